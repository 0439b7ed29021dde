"""One off-line session, from the user's choices to the checked result.

``optimize``, each job of ``batch`` (on local processes or Dask) and the design studies call
:func:`offline`: the choices resolved once (:func:`desdemona.runs.session.offline`: the path cued,
the workers fitted, whole or windowed chosen), then solved as chosen (:func:`solve`): the whole path
(:func:`desdemona.cueing.offline.optimize`), in windows (:func:`desdemona.cueing.windows.optimize_windowed`),
or with the thesis' own method (:func:`desdemona.cueing.offline.thesis_result`). The command line
resolves first (:func:`resolve`) to tell the user the problem's size before the solve.
"""

from __future__ import annotations

from desdemona.machine.model import Model
from desdemona.profiles import DesiredPath
from desdemona.runs import session
from desdemona.runs.session import ChoiceError, Choices, Session

#: The starts of a session unless told (:attr:`desdemona.cueing.offline.OptimizeOptions.starts`).
STARTS = 4


def resolve(path: DesiredPath, model: Model, choices: Choices = Choices(), method: str = "auto", perception=None,
            workers: int | None = None, starts: int = STARTS) -> Session:
    """The off-line session of ``path`` on ``model``: method "thesis" (:func:`session.thesis`, on one
    process), else the solver ("auto", "ipopt", "fatrop") of :func:`session.offline`, on ``workers``
    processes (None: fitted to the cores, the starts and the memory)."""
    if starts < 1 or (workers is not None and workers < 1):
        raise ChoiceError("--starts and --workers must be at least 1")
    if method == "thesis":
        return session.thesis(path, model, choices)
    return session.offline(path, model, choices, method, perception, workers, starts)


def solve(resolved: Session, starts: int = STARTS, seed: int = 0, refine: bool = False, progress=None,
          announce=None):
    """The checked result (:class:`desdemona.cueing.offline.Result`) of a resolved off-line session:
    whole or in its windows, on its workers. progress : optional ``progress(done, total, best_cost)``
    told after each start; announce : optional ``announce(index, count, start, end)`` told as each
    window begins. Raises :class:`~desdemona.check.simulate.LimitViolation` where no trajectory keeps
    every limit."""
    from desdemona.cueing.offline import OptimizeOptions, optimize, thesis_result
    from desdemona.cueing.windows import optimize_windowed

    path, model, problem = resolved.path, resolved.model, resolved.options
    if resolved.method == "thesis":
        from desdemona.baselines.thesis import ThesisOptions

        return thesis_result(path, model, ThesisOptions(h_u=problem.h_u, starts=starts, seed=seed))
    options = OptimizeOptions(problem, starts=starts, seed=seed, workers=resolved.workers, refine=refine)
    if resolved.window is None:
        return optimize(path, model, options, progress=progress)
    return optimize_windowed(path, model, options, resolved.window, progress=progress, announce=announce)


def offline(path: DesiredPath, model: Model, choices: Choices = Choices(), *, method: str = "auto", perception=None,
            workers: int | None = None, starts: int = STARTS, seed: int = 0, refine: bool = False, progress=None,
            announce=None):
    """The checked result of an off-line session: :func:`resolve`, then :func:`solve`."""
    return solve(resolve(path, model, choices, method, perception, workers, starts), starts, seed, refine, progress,
                 announce)

"""A recording of any length, off-line: solved in overlapping windows, checked as a whole.

A whole-recording solve holds every interval in memory at once (about 1 GB for ten minutes on
``yaw-track-cabin``) and its time per iteration grows with the length. In windows, each window is an
off-line problem of its own (:func:`desdemona.cueing.offline.optimize`, its starts and check); it keeps its
plan up to where the next window starts, ``overlap`` before its end, and the next window starts
exactly from that state (positions, rates and accelerations). So the part kept never depends on how
a window ends, every window but the last ends stoppable (every state can still brake to rest within
the position limits, the on-line end condition of chapter 7), and memory is bounded by the window,
not the recording. The stitched plan is re-checked as a whole against every limit
(:func:`desdemona.check.simulate.check`); a violation is an error, as for any result. Its limit prices
are the windows' over the parts they keep (:func:`desdemona.cueing.prices.combined`).

Every window but the last poses, for every recording, the same problem with another path and another
start: its fatrop solver is kept in the cache (``OptimizeOptions.stored``), so that only a machine's
first windowed run pays its set-up. The last is as long as what is left, and builds its own.

``choose(duration, model, options, asked)`` decides: the window asked for (refused with the length
that would do where it is shorter than the machine needs to stop twice over, or longer than the
memory allows), else windows of :data:`DEFAULT_WINDOW` above :data:`WHOLE_UP_TO` seconds.
"""

from __future__ import annotations

import math
import time
from dataclasses import replace

import numpy as np

from desdemona.check.simulate import LimitViolation, check, evaluate_plan, fine_grid
from desdemona.cueing import prices, sizing
from desdemona.cueing.offline import OptimizeOptions, Result, optimize, settled, spin_following
from desdemona.cueing.transcription import Solution
from desdemona.machine.model import Model
from desdemona.profiles import DesiredPath

#: Recordings up to this long [s] are solved whole by default, longer ones in windows
#: (docs/benchmarks/windows.md).
WHOLE_UP_TO = 150.0

#: The default window [s]: the shortest that holds two overlaps on the default machine. Against 60 s the
#: ten-minute sortie on ``full`` converged in every window instead of stopping at the iteration cap in
#: three, in less time; the corpus' windowed cases as good or better (docs/benchmarks/windows-of-30-s.md).
DEFAULT_WINDOW = 30.0

#: The shortest overlap [s]: the part of a window solved but not kept.
MIN_OVERLAP = 10.0

#: Starts of every window after the first, at most: the window before, continued (a warm start near
#: the optimum, which the first window's starts already chose among), and the first smart guess.
LATER_STARTS = 2


class WindowError(ValueError):
    """A window length that cannot work; the message says which length would."""


def stopping_time(model: Model, braking: float = 0.5) -> float:
    """The longest time [s] a joint needs to come to rest from its velocity limit, braking at
    ``braking`` x its acceleration limit (the stoppable condition's), the ramp at the jerk limit
    counted."""
    lim = model.limits
    a = braking * lim.acceleration
    ramp = a / lim.jerk if lim.smooth else 0.0
    return float(np.max(lim.velocity / a + ramp))


def overlap(model: Model) -> float:
    """The overlap of two windows [s]: at least the time the machine needs to stop, twice over."""
    return max(MIN_OVERLAP, math.ceil(2.0 * stopping_time(model)))


def choose(path: DesiredPath, model: Model, options, asked: float | None, workers: int = 1,
           whole_up_to: float = WHOLE_UP_TO) -> float | None:
    """The window [s] for ``path`` (None: solve it whole). ``asked``: the user's ``--window`` (0: whole,
    None: the default, windows above ``whole_up_to`` seconds; with a perception model the default is
    whole). Raises :class:`WindowError` for a window that cannot work."""
    if asked is not None and asked <= 0:
        return None
    if options.perception is not None:
        if asked is None:
            return None
        _refuse_perception()
    shortest = 2 * overlap(model)
    if asked is None:
        if path.duration <= whole_up_to:
            return None
        asked = max(DEFAULT_WINDOW, shortest)
    if asked >= path.duration:
        return None
    if asked < shortest:
        raise WindowError(f"--window {asked:g}: shorter than the machine needs. On {model.config.name} a joint "
                          f"takes up to {stopping_time(model):.1f} s to stop, each window overlaps the next by "
                          f"{overlap(model):g} s; use --window {shortest:g} or more")
    size = sizing.estimate(part(path, 0.0, asked), model.config, options, workers, model.limits.smooth)
    if not size.fits:
        fitting = asked * (size.available - sizing.BASE_BYTES) / (size.memory - sizing.BASE_BYTES)
        if fitting >= shortest:
            advice = f"use --window {math.floor(fitting):g} or less"
        else:  # the finest --h-u at which the window asked fits
            coarser = next((h for h in sizing.H_U_STEPS if h > options.h_u and sizing.estimate(
                part(path, 0.0, asked), model.config, replace(options, h_u=h), workers, model.limits.smooth).fits), None)
            advice = (f"no window fits (the shortest that works is {shortest:g} s); use "
                      + (f"--h-u {coarser:g} or more" if coarser is not None else "a larger --h-u"))
        raise WindowError(f"--window {asked:g}: {size.intervals:,} control intervals in a window need "
                          f"{sizing.memory_words(size)}; {advice}")
    return float(asked)


def _refuse_perception():
    raise WindowError("--perception needs the whole path in one solve (its filters' state is not carried "
                      "from window to window): drop --window, or give --window 0")


def part(path: DesiredPath, start: float, end: float) -> DesiredPath:
    """The desired path on [start, end], its time from 0: its own samples inside, the ends
    interpolated."""
    inside = path.t[(path.t > start) & (path.t < end)]
    t = np.r_[start, inside, end]
    S_d = path.sample(t) if path.S_d is not None else None
    modulus = path.sample_modulus(t) if path.modulus is not None else None
    return replace(path, t=t - start, S_d=S_d, modulus=modulus)


def _windows(intervals: int, window: int, keep: int) -> list[int]:
    """The first interval of each window of ``window`` intervals over ``intervals``: each starts ``keep``
    after the one before; the last reaches the end (and is shorter where less is left)."""
    firsts = [*range(0, intervals - window, keep)]
    return [*firsts, firsts[-1] + keep if firsts else 0]


def optimize_windowed(path: DesiredPath, model: Model, options: OptimizeOptions, window: float,
                      progress=None, announce=None) -> Result:
    """:func:`~desdemona.cueing.offline.optimize` in windows of ``window`` seconds (see the module's
    docstring). ``announce(index, count, start, end)`` is told as each window begins; ``progress`` is
    passed on to each window's solve. Raises :class:`LimitViolation` when the stitched plan breaks a
    limit."""
    wall = time.perf_counter()
    problem = options.problem
    if problem.perception is not None:
        _refuse_perception()
    path = model.config.cue_path(path)
    h_u = problem.h_u
    size = int(round(window / h_u))
    firsts = _windows(int(round(path.duration / h_u)), size, int(round((window - overlap(model)) / h_u)))
    pieces, reports, state, guess, priced = [], [], None, None, []
    for index, first in enumerate(firsts):
        last = index == len(firsts) - 1
        start, end = first * h_u, path.duration if last else (first + size) * h_u
        if announce is not None:
            announce(index + 1, len(firsts), start, end)
        window_path = part(path, start, end)
        settings = problem if last else replace(problem, final="none", stoppable=True)
        if state is not None:
            settings = replace(settings, initial="given", initial_state=state)
        starts = options.starts if state is None else min(options.starts, LATER_STARTS)
        stored = not last or int(round((end - start) / h_u)) == size  # a problem later runs pose again
        result = optimize(window_path, model, replace(options, problem=settings, starts=starts, stored=stored),
                          progress=progress, first=guess)
        reports += [replace(r, guess=f"window {index + 1}/{len(firsts)}: {r.guess}") for r in result.starts]
        sol = result.solution
        if last:
            pieces.append((start, sol, len(sol.u)))
            priced.append((result.prices, start, math.inf, result.path.duration))
            break
        k = firsts[index + 1] - first  # the node where the next window starts
        pieces.append((start, sol, k))
        priced.append((result.prices, start, float(sol.t_nodes[k] - sol.t_nodes[0]), result.path.duration))
        n = model.n
        x = sol.x[k]
        state = (x[:n].copy(), x[n:2 * n].copy()) + ((x[2 * n:3 * n].copy(),) if sol.smooth else ())
        guess = _continued(sol, k)
    return replace(_stitched(path, model, options, pieces, reports, wall),
                   prices=prices.combined(model, priced, 0.0, path.duration))


def _continued(sol: Solution, k: int):
    """The next window's first guess: this window's accelerations after node k, then the yaw following
    the held force from the rate this window ends at (:func:`~desdemona.cueing.offline.spin_following`, without
    its floor: the arm may slow down where the force asks for no turn), every joint with a travel
    brought to rest from the state this window ends at (:func:`~desdemona.cueing.offline.settled`), the other
    joints' accelerations held at zero."""
    n = sol.u.shape[1]
    rest = sol.accelerations[k:]
    end_rate, end_acceleration = sol.x[-1, n:2 * n], sol.x[-1, 2 * n:3 * n] if sol.smooth else np.zeros(n)

    def guess(problem):
        done = min(len(rest), problem.N)
        yaw = end_rate[0]
        u = spin_following(problem, 1.0 if yaw >= 0 else -1.0, floor=0.0, start=done, rate0=yaw)
        u = settled(problem, end_rate, end_acceleration, u, done)
        u[:done] = rest[:done]
        return [("the window before, continued",
                 *problem.guess(sol.x[k, :n], sol.x[k, n:2 * n], u, sol.x[k, 2 * n:3 * n] if sol.smooth else None))]
    return guess


def _stitched(path: DesiredPath, model: Model, options: OptimizeOptions, pieces, reports, wall: float) -> Result:
    """One result of the windows' kept parts, checked as a whole."""
    t, x, u = [], [], []
    for start, sol, k in pieces:
        t.append(start + sol.t_nodes[:k])
        x.append(sol.x[:k])
        u.append(sol.u[:k])
    start, sol, k = pieces[-1]
    t.append([start + sol.t_nodes[-1]])
    x.append(sol.x[-1:])
    chosen = [p[1] for p in pieces]
    whole = Solution(t_nodes=np.concatenate(t), x=np.vstack(x), u=np.vstack(u),
                     cost=float(sum(s.cost for s in chosen)), status=sol.status,
                     success=all(s.success for s in chosen), iterations=sum(s.iterations for s in chosen),
                     solve_time=sum(s.solve_time for s in chosen), smooth=sol.smooth)
    problem = options.problem
    h_sub = problem.h_u / problem.substeps
    weights = problem.weights if problem.weights is not None else path.weights
    result_check, _ = check(model, path, whole.plan, h_sub, weights=weights)
    if not result_check.passed:
        raise LimitViolation(result_check, "the windows' stitched trajectory")
    trajectory = evaluate_plan(model, path, whole.plan, fine_grid(whole.t_nodes, h_sub))
    timings = {"build": 0.0, "solve": sum(r.solve_time for r in reports), "wall": time.perf_counter() - wall,
               "windows": len(pieces)}
    return Result(path=path, model=model, options=options, method=problem.solver, solution=whole,
                  trajectory=trajectory, check=result_check, starts=tuple(reports), timings=timings)


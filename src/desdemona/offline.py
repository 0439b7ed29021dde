"""Off-line optimal motion cueing: initial guesses, multi-start, refinement, checked result (chapter 5).

``optimize(path, config, params, options) -> Result``: builds the problem of :mod:`desdemona.problem`,
solves it from several initial guesses (in parallel processes when asked), re-checks every solution
independently (:mod:`desdemona.simulate`) and returns the best one that keeps every limit. The problem
is non-convex with many local optima (thesis 4.5, 5.8): zero motion is a stationary point (at zero yaw
rate the centripetal terms have no gradient), so the guesses start the yaw turning, as the thesis'
smart guesses of table 5.2 do, and seeded random starts widen the search.
"""

from __future__ import annotations

import multiprocessing
import time
from dataclasses import dataclass, field, replace

import numpy as np

from desdemona import baselines, guard, sizing
from desdemona.configs import Configuration, get_configuration
from desdemona.model import Model
from desdemona.params import MachineParams, default_params
from desdemona.problem import CueingProblem, ProblemOptions, Solution
from desdemona.profiles import DesiredPath
from desdemona.simulate import LimitCheck, LimitViolation, Trajectory, check, evaluate, integrate


@dataclass(frozen=True)
class OptimizeOptions:
    """Options of :func:`optimize`.

    problem : how the problem is posed and solved (:class:`ProblemOptions`).
    starts : number of initial guesses: the smart guesses first, then seeded random ones.
    seed : seed of the random guesses (results are reproducible for a given seed).
    workers : parallel processes for the starts (1: in this process).
    refine : solve with the simplified dynamics first, then refine with the full dynamics (5.7).
    """

    problem: ProblemOptions = field(default_factory=ProblemOptions)
    starts: int = 4
    seed: int = 0
    workers: int = 1
    refine: bool = False

    def __post_init__(self):
        if self.starts < 1 or self.workers < 1:
            raise ValueError("starts and workers must be >= 1")


@dataclass(frozen=True)
class StartReport:
    """One start of a multi-start: where it began and where it ended."""

    guess: str
    status: str
    success: bool
    iterations: int
    solve_time: float
    cost: float
    rms: float
    worst_use: float
    passed: bool


@dataclass(frozen=True, eq=False)
class Result:
    """A checked off-line solution.

    solution : the chosen start's nodes, controls and solver statistics.
    trajectory : the motion on the optimiser's sub-step grid (for files and figures).
    check : the independent fine-grid check (every limit <= 1 + 1e-6, RMS errors).
    starts : every start's report; timings : build, solve and wall times [s].
    """

    path: DesiredPath
    config: Configuration
    params: MachineParams
    options: OptimizeOptions
    method: str
    solution: Solution
    trajectory: Trajectory
    check: LimitCheck
    starts: tuple[StartReport, ...]
    timings: dict

    @property
    def converged(self) -> bool:
        """The chosen start's solver reported success (not stopped at its iteration cap or otherwise)."""
        return bool(self.solution.success)


# ----------------------------------------------------------------------------------------------
# initial guesses


def initial_guesses(problem: CueingProblem, count: int, seed: int) -> list[tuple[str, np.ndarray, np.ndarray]]:
    """``count`` guesses (name, node states (N + 1, nx), controls (N, n)): smart ones, then random."""
    model, N, n = problem.model, problem.N, problem.model.n
    lim = model.limits
    guesses = []

    def add(name, q0, qd0, u=None):
        u = np.zeros((N, n)) if u is None else u
        guesses.append((name, problem.states_from(np.asarray(q0, float), np.asarray(qd0, float), u), u))

    free = model.config.free
    if model.config.modulus_cost:
        t, q1, q1d, q1dd = baselines.classical_dfs(problem.path, model, times=problem.t_nodes)
        add("classical-loop", q1[:1], q1d[:1], q1dd[:-1, None])
        add("spinning", [0.0], [0.5 * lim["velocity"][0]])
    else:
        # Thesis table 5.2: the yaw turning, the track out, or both; the track on the side where the
        # centripetal specific force points along the mean demanded f_y. The "not turning" row gets a
        # slow turn: at exactly zero yaw rate the centripetal terms have no gradient (a stationary
        # point where the solver stalls).
        track = free.index(1) if 1 in free else None
        demand = float(np.mean(problem.path.S_d[:, 4]))
        side = -1.0 if demand >= 0 else 1.0
        spin = 0.5 * lim["velocity"][0]
        rows = [("smart: yaw turning", 0.0, spin, 0.0),
                ("smart: track out", 0.5, 0.1 * spin, 0.0),
                ("smart: yaw turning, track in", 0.1, spin, -0.3)]
        for name, q2, q1d, q2d in rows:
            q0, qd0 = np.zeros(n), np.zeros(n)
            qd0[0] = q1d
            if track is not None:
                q0[track] = side * q2 * lim["position_max"][track]
                qd0[track] = -side * q2d * lim["velocity"][track]
            add(name, q0, qd0)
    rng = np.random.default_rng(seed)
    lo = np.where(np.isfinite(lim["position_min"]), 0.5 * lim["position_min"], -np.pi)
    hi = np.where(np.isfinite(lim["position_max"]), 0.5 * lim["position_max"], np.pi)
    while len(guesses) < count:
        u = rng.uniform(-0.2, 0.2, size=(N, n)) * lim["acceleration"]
        add(f"random {len(guesses)}", rng.uniform(lo, hi), rng.uniform(-0.5, 0.5, size=n) * lim["velocity"], u)
    return guesses[:count]


# ----------------------------------------------------------------------------------------------
# solving


def _problems(params: MachineParams, config: Configuration, path: DesiredPath, options: OptimizeOptions):
    full = CueingProblem(Model(params, config), path, options.problem, solves=options.starts)
    rough = (CueingProblem(Model(params.simplified(), config), path, options.problem, solves=options.starts)
             if options.refine else None)
    return full, rough


def _solve_one(full: CueingProblem, rough: CueingProblem | None, x, u) -> Solution:
    if rough is not None:
        first = rough.solve(x, u)
        return full.solve(first.x, first.u, warm=first)
    return full.solve(x, u)


_WORKER: dict = {}


def _worker_solve(guesses):
    # Forked workers inherit the problems built by the parent (see optimize): no rebuild per process.
    full, rough = _WORKER["problems"]
    return [(name, _solve_one(full, rough, x, u)) for name, x, u in guesses]


def optimize(path: DesiredPath, config: str | Configuration = "yaw-track-cabin",
             params: MachineParams | None = None, options: OptimizeOptions = OptimizeOptions(),
             progress=None) -> Result:
    """The best checked joint trajectory for a desired path (thesis chapters 3-7, off-line).

    progress : optional callable ``progress(done, total, best_cost)`` told after each start.
    Raises :class:`LimitViolation` when no start yields a trajectory within every limit, and
    :class:`~desdemona.sizing.TooLarge` before building a problem that would not fit in memory.
    """
    wall = time.perf_counter()
    params = default_params() if params is None else params
    config = get_configuration(config)
    sizing.check_fits(path, config, options.problem, options.workers)
    build = time.perf_counter()
    full, rough = _problems(params, config, path, options)
    build = time.perf_counter() - build
    guesses = initial_guesses(full, options.starts, options.seed)
    solved = []

    def done(item):
        solved.append(item)
        if progress is not None:
            progress(len(solved), len(guesses), min(sol.cost for _, sol in solved))

    if options.workers > 1 and len(guesses) > 1:
        _WORKER["problems"] = (full, rough)
        context = multiprocessing.get_context("fork")
        # leaving the block terminates the workers, also when the parent is interrupted
        try:
            with context.Pool(min(options.workers, len(guesses)), initializer=guard.worker_signals) as pool:
                for part in pool.imap_unordered(_worker_solve, [[g] for g in guesses]):
                    done(part[0])
        finally:
            _WORKER.clear()
        order = {name: i for i, (name, _, _) in enumerate(guesses)}
        solved.sort(key=lambda item: order[item[0]])
    else:
        for name, x, u in guesses:
            done((name, _solve_one(full, rough, x, u)))
    candidates, reports = [], []
    for name, sol in solved:
        result_check, _ = _check(full, sol)
        reports.append(StartReport(name, sol.status, sol.success, sol.iterations, sol.solve_time, sol.cost,
                                   result_check.rms, result_check.worst_use, result_check.passed))
        candidates.append((result_check, sol))
    passed = [(c, s) for c, s in candidates if c.passed]
    if not passed:
        # A limit bulged between the optimiser's sub-steps: back off further and re-solve the best start.
        best_check, best = min(candidates, key=lambda cs: cs[0].worst_use)
        problem_options = options.problem
        for _ in range(2):
            problem_options = replace(problem_options, margin=max(10 * problem_options.margin, 1e-3))
            retry = CueingProblem(full.model, path, replace(problem_options, expand=False))
            sol = retry.solve(best.x, best.u, warm=best)
            best_check, _ = _check(retry, sol)
            reports.append(StartReport(f"retry, margin {problem_options.margin:g}", sol.status, sol.success,
                                       sol.iterations, sol.solve_time, sol.cost, best_check.rms,
                                       best_check.worst_use, best_check.passed))
            if best_check.passed:
                passed = [(best_check, sol)]
                break
        else:
            raise LimitViolation(best_check, "every start's trajectory")
    chosen_check, chosen = min(passed, key=lambda cs: cs[0].rms)
    times = full.sub_times()
    t = np.r_[times[:, :-1].ravel(), full.t_nodes[-1]]
    q, qd, qdd = integrate(chosen.t_nodes, chosen.q0, chosen.qd0, chosen.u, t)
    trajectory = evaluate(full.model, path, t, q, qd, qdd, options.problem.perception)
    timings = {"build": build, "solve": sum(r.solve_time for r in reports),
               "wall": time.perf_counter() - wall}
    return Result(path=path, config=config, params=params, options=options, method=options.problem.solver,
                  solution=chosen, trajectory=trajectory, check=chosen_check, starts=tuple(reports),
                  timings=timings)


def _check(problem: CueingProblem, sol: Solution) -> tuple[LimitCheck, Trajectory]:
    return check(problem.model, problem.path, sol.t_nodes, sol.q0, sol.qd0, sol.u, problem.h_sub,
                 weights=problem.weights, perception=problem.options.perception)


def thesis_result(path: DesiredPath, config: str | Configuration = "yaw-track",
                  params: MachineParams | None = None, options=None) -> Result:
    """The thesis' own method (:func:`desdemona.baselines.optimize_thesis`), checked and packaged like ours.

    Its best start that keeps every limit on the fine grid is returned; :class:`LimitViolation` if none.
    """
    options = baselines.ThesisOptions() if options is None else options
    wall = time.perf_counter()
    params = default_params() if params is None else params
    config = get_configuration(config)
    problem, runs = baselines.optimize_thesis(path, config, params, options)
    step = float(np.min(np.diff(path.t)))
    reports, candidates = [], []
    for k, run in enumerate(runs):
        result_check, _ = check(problem.model, path, run.t_nodes, run.q0, run.qd0, run.u, step)
        reports.append(StartReport(f"random {k}", run.message, result_check.passed, run.iterations,
                                   run.solve_time, run.cost, result_check.rms, result_check.worst_use,
                                   result_check.passed))
        candidates.append((result_check, run))
    passed = [(c, r) for c, r in candidates if c.passed]
    if not passed:
        raise LimitViolation(min(candidates, key=lambda cr: cr[0].worst_use)[0], "the thesis method's trajectory")
    chosen_check, run = min(passed, key=lambda cr: cr[0].rms)
    q, qd, _ = integrate(run.t_nodes, run.q0, run.qd0, run.u, run.t_nodes)
    solution = Solution(t_nodes=run.t_nodes, x=np.hstack([q, qd]), u=run.u, cost=run.cost, status=run.message,
                        success=True, iterations=run.iterations, solve_time=run.solve_time)
    t = path.t[path.t <= run.t_nodes[-1] + 1e-12]
    q, qd, qdd = integrate(run.t_nodes, run.q0, run.qd0, run.u, t)
    trajectory = evaluate(problem.model, path, t, q, qd, qdd)
    timings = {"build": 0.0, "solve": sum(r.solve_time for r in runs), "wall": time.perf_counter() - wall}
    return Result(path=path, config=config, params=params, options=options, method="thesis",
                  solution=solution, trajectory=trajectory, check=chosen_check, starts=tuple(reports),
                  timings=timings)

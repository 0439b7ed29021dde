"""Off-line optimal motion cueing: initial guesses, multi-start, refinement, checked result (chapter 5).

``optimize(path, model, options) -> Result``: builds the problem of :mod:`desdemona.cueing.formulation`,
solves it from several initial guesses (in parallel processes when asked), re-checks every solution
independently (:mod:`desdemona.check.simulate`) and returns the best one that keeps every limit (among the
starts that converged, where any did: a converged start is a verified local optimum, an iterate
stopped at the cap is not; the others stay in the result's reports). The problem
is non-convex with many local optima (thesis 4.5, 5.8): zero motion is a stationary point (at zero yaw
rate the centripetal terms have no gradient), so the guesses start the yaw turning, as the thesis'
smart guesses of table 5.2 do, and seeded random starts widen the search.
"""

from __future__ import annotations

import functools
import multiprocessing
import time
from dataclasses import dataclass, field, replace

import numpy as np

from desdemona.baselines import thesis
from desdemona.baselines.classical import classical_dfs
from desdemona.check import metrics
from desdemona.check.simulate import LimitCheck, LimitViolation, Trajectory, check, evaluate_plan, trajectory_dataframe
from desdemona.cueing import sizing
from desdemona.cueing.formulation import ProblemOptions
from desdemona.cueing.prices import LimitPrices, limit_prices
from desdemona.cueing.transcription import MAP_THREADS, CueingProblem, Solution
from desdemona.machine.model import Model
from desdemona.machine.plan import Plan, braked, start_acceleration, start_state
from desdemona.profiles import DesiredPath
from desdemona.support import guard

#: The share of the yaw's rate limit the random starts' spin-up turns at, at least (thesis table 5.2:
#: half).
SPIN_SHARE = 0.5
#: The share of the yaw's rate limit the smart guesses' spin-up turns at, at least: enough to leave
#: the stationary point of no turn (no gradient of the centripetal terms at zero yaw rate).
SPIN_FLOOR = 0.3


#: The most starts a run takes. Each start is a whole solve (about a second for the quick start warm,
#: minutes for a long path on ``full``) and every guess is made before the first solve, so a run of a
#: million starts never ends; a wider search is better split into runs with other seeds, each of
#: which is checked and written.
MAX_STARTS = 100


@dataclass(frozen=True)
class OptimizeOptions:
    """Options of :func:`optimize`.

    problem : how the problem is posed and solved (:class:`ProblemOptions`).
    starts : number of initial guesses: the smart guesses first, then seeded random ones.
    seed : seed of the random guesses (results are reproducible for a given seed).
    workers : parallel processes for the starts (1: in this process).
    refine : solve with the simplified dynamics first, then refine with the full dynamics (5.7).
    stored : keep fatrop's solver in the cache for later runs (``CueingProblem(stored=True)``: the
    windows of a recording, :mod:`desdemona.cueing.windows`); None: where its set-up is long (a long
    whole path, ``transcription.STORED_FROM``).
    """

    problem: ProblemOptions = field(default_factory=ProblemOptions)
    starts: int = 4
    seed: int = 0
    workers: int = 1
    refine: bool = False
    stored: bool | None = None

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

    model : the machine and configuration it was computed for;
    solution : the chosen start's nodes, controls and solver statistics.
    trajectory : the motion on the optimiser's sub-step grid (for files and figures).
    check : the independent fine-grid check (every limit <= 1 + 1e-6, RMS errors).
    starts : every start's report; timings : build, solve and wall times [s].
    prices : what each limit costs the felt error (:mod:`desdemona.cueing.prices`), from the chosen
    solve's multipliers (a windowed result: combined from its windows'); None for the thesis' method.
    """

    path: DesiredPath
    model: Model
    options: OptimizeOptions
    method: str
    solution: Solution
    trajectory: Trajectory
    check: LimitCheck
    starts: tuple[StartReport, ...]
    timings: dict
    prices: LimitPrices | None = None

    @property
    def plan(self) -> Plan:
        """The chosen joint plan (grid, initial state, accelerations)."""
        return self.solution.plan

    @property
    def converged(self) -> bool:
        """The chosen start's solver reported success (not stopped at its iteration cap or otherwise)."""
        return bool(self.solution.success)

    @functools.cached_property
    def quality(self) -> metrics.Metrics:
        """What the occupant feels and the machine does (:mod:`desdemona.check.metrics`), through the
        problem's perception model or, without one, the thesis' model."""
        perception = self.options.problem.perception if isinstance(self.options, OptimizeOptions) else None
        return metrics.of_trajectory(self.trajectory, self.model.config.joint_names, perception)

    def to_dataframe(self):
        """The trajectory as a pandas DataFrame indexed by time (needs pandas: ``pip install
        'desdemona[dataframe]'``); the columns of ``trajectory.csv``."""
        return trajectory_dataframe(self.trajectory, self.model.config)


# ----------------------------------------------------------------------------------------------
# initial guesses


def initial_guesses(problem: CueingProblem, count: int, seed: int) -> list[tuple[str, np.ndarray, np.ndarray]]:
    """``count`` guesses (name, node states (N + 1, nx), controls (N, n)): smart ones, then random."""
    model, N, n = problem.model, problem.N, problem.model.n
    lim = model.limits
    guesses = []

    def add(name, q0, qd0, u=None):
        u = np.zeros((N, n)) if u is None else u
        guesses.append((name, *problem.guess(np.asarray(q0, float), np.asarray(qd0, float), u, a0)))

    a0 = None if problem.options.initial == "free" else start_acceleration(problem.options.initial_state, n)

    fixed = problem.options.initial != "free"  # the start is fixed (at rest, or given)
    random_rate = spin_share(problem) if fixed else None
    if fixed:
        guesses += _guesses_from_start(problem, spin_share(problem, SPIN_FLOOR))
    elif model.config.takes_modulus:
        classical = classical_dfs(problem.path, model, times=problem.t_nodes)
        add("classical-loop", classical.q0, classical.qd0, classical.u)
        spinning = np.zeros(n)
        spinning[0] = 0.5 * lim.velocity[0]
        add("spinning", np.zeros(n), spinning)
    else:
        # Thesis table 5.2: the yaw turning, the track out, or both; the track on the side where the
        # centripetal specific force points along the mean demanded f_y. The "not turning" row gets a
        # slow turn: at exactly zero yaw rate the centripetal terms have no gradient (a stationary
        # point where the solver stalls).
        track = model.config.track
        demand = float(np.mean(problem.path.S_d[:, 4]))
        side = -1.0 if demand >= 0 else 1.0
        spin = 0.5 * lim.velocity[0]
        rows = [("smart: yaw turning", 0.0, spin, 0.0),
                ("smart: track out", 0.5, 0.1 * spin, 0.0),
                ("smart: yaw turning, track in", 0.1, spin, -0.3)]
        for name, q2, q1d, q2d in rows:
            q0, qd0 = np.zeros(n), np.zeros(n)
            qd0[0] = q1d
            if track is not None:
                q0[track] = side * q2 * lim.position_max[track]
                qd0[track] = -side * q2d * lim.velocity[track]
            add(name, q0, qd0)
    rng = np.random.default_rng(seed)
    lo = np.where(np.isfinite(lim.position_min), 0.5 * lim.position_min, -np.pi)
    hi = np.where(np.isfinite(lim.position_max), 0.5 * lim.position_max, np.pi)
    while len(guesses) < count:
        u = rng.uniform(-0.2, 0.2, size=(N, n)) * lim.acceleration
        q0, qd0 = rng.uniform(lo, hi), rng.uniform(-0.5, 0.5, size=n) * lim.velocity
        if fixed:  # only the accelerations are random, on top of the spin-up
            q0, qd0, u = *_start(problem), _spin_up(problem, 1.0, random_rate) + u
        add(f"random {len(guesses)}", q0, qd0, u)
    return guesses[:count]


def _start(problem: CueingProblem) -> tuple[np.ndarray, np.ndarray]:
    """The fixed initial state of a problem that starts at rest (position 0) or at a given state."""
    o = problem.options
    return start_state(o.initial_state if o.initial == "given" else None, problem.model.n)


def _spin_up(problem: CueingProblem, direction: float, rate: float = SPIN_SHARE, accel: float = 0.8) -> np.ndarray:
    """(N, n) accelerations that turn the yaw up from the start to ``rate`` times its rate limit at
    ``accel`` times its acceleration limit, in ``direction`` (+1 or -1), hold it, and brake it again
    over the last intervals when the problem ends at rest.

    Zero motion is a stationary point (no gradient of the centripetal terms at zero yaw rate), so a
    guess that starts at rest must leave it by itself: this is the thesis' "yaw turning" guess of
    table 5.2 for a session that starts, and ends, still.
    """
    lim, N, h = problem.model.limits, problem.N, problem.options.h_u
    u = np.zeros((N, problem.model.n))
    a = accel * lim.acceleration[0]
    k = min(N // 2, max(1, round(rate * lim.velocity[0] / (a * h))))
    u[:k, 0] = direction * a
    if problem.options.final != "none":
        u[N - k:, 0] = -direction * a
    return u


def spin_share(problem: CueingProblem, floor: float = SPIN_SHARE) -> float:
    """The share of the yaw's rate limit that a spun-up random guess turns at (and by which the smart
    guesses from a fixed start put the track half out or at its end): the rate whose centripetal force
    at the cabin's largest radius gives the median of the desired modulus held
    (:func:`desdemona.cueing.sizing.held_modulus`), within [``floor``, 1].

    A guess that turns at another rate than the path's sustained force asks has to be brought
    to it by the solver over every interval of the path, one at a time: the arm's acceleration limit
    blocks each step, too slow a spin on the F-16 turn on ``full``, too fast a one on the 747
    take-off (docs/benchmarks/spin-of-the-guesses.md).
    """
    held = float(np.median(sizing.held_modulus(problem.path)))
    return float(np.clip(_held_share(problem.model, held), floor, 1.0))


def _held_share(model: Model, held):
    """The share of the yaw's rate limit whose centripetal force at the cabin's largest radius gives
    the specific force ``held`` [m/s^2] (g and a horizontal force): unclipped, per value; zero where the
    configuration has no radius to turn the cabin at."""
    radius = max(abs(r) for r in sizing.radii(model))
    if radius <= 0.0:  # no centripetal force to give
        return np.zeros_like(np.asarray(held, dtype=float))
    horizontal = np.sqrt(np.maximum(np.asarray(held, dtype=float) ** 2 - float(model.params.gravity) ** 2, 0.0))
    return np.sqrt(horizontal / radius) / model.limits.velocity[0]


def spin_following(problem: CueingProblem, direction: float, floor: float = SPIN_FLOOR, accel: float = 0.8,
                   start: int = 0, rate0: float | None = None) -> np.ndarray:
    """(N, n) accelerations that turn the yaw in ``direction`` at the rate :func:`spin_share`'s rule
    gives the desired modulus held at each node (within [``floor``, 1] of the limit), as near as
    ``accel`` times its acceleration limit lets it follow: changed ahead of time where the force
    will ask (a pass backwards), from the start's rate (a pass forwards), and braked to rest at the
    end when the problem ends at rest. A path whose sustained force changes (a sortie's turns and
    straight stretches) is then not left to the solver to spin up and down node by node against the
    arm's limits (docs/benchmarks/spin-of-the-guesses.md). From node ``start`` on, at the rate
    ``rate0`` there (default: the problem's start), and zero before it."""
    model, h, N = problem.model, problem.steps, problem.N
    lim, u = model.limits, np.zeros((N, problem.model.n))
    if not model.config.turns_arm:
        return u
    held = np.interp(problem.t_nodes, problem.path.t, sizing.held_modulus(problem.path))
    rate = direction * lim.velocity[0] * np.clip(_held_share(model, held), floor, 1.0)
    step = accel * lim.acceleration[0] * h
    if problem.options.final != "none":
        rate[-1] = 0.0
    for k in range(N - 1, start - 1, -1):
        rate[k] = np.clip(rate[k], rate[k + 1] - step[k], rate[k + 1] + step[k])
    rate[start] = _start(problem)[1][0] if rate0 is None else rate0
    for k in range(start + 1, N + 1):
        rate[k] = np.clip(rate[k], rate[k - 1] - step[k - 1], rate[k - 1] + step[k - 1])
    u[start:, 0] = np.diff(rate[start:]) / h[start:]
    return u


def _guesses_from_start(problem: CueingProblem, rate: float) -> list[tuple[str, np.ndarray, np.ndarray]]:
    """Guesses for a fixed start (at rest, or given): the yaw turning either way at the rate the held
    force asks for node by node (:func:`spin_following`), and, where there is a track and the start's
    position is free, with the track out on the side where the centripetal specific force points along
    the mean demanded f_y: half its travel out, or at its end where the median held force asks for more
    than half the yaw's rate limit (``rate``, :func:`spin_share`; the radius it takes)."""
    model, guesses = problem.model, []
    q0, qd0 = _start(problem)
    a0 = start_acceleration(problem.options.initial_state, model.n)
    track = model.config.track
    origin = "from rest" if not (np.any(qd0) or np.any(a0)) else "from the start"  # a later window's moves
    rows = [(f"{origin}: yaw spun up", 0.0, 1.0), (f"{origin}: yaw spun up the other way", 0.0, -1.0)]
    if track is not None and problem.options.initial == "rest" and problem.path.S_d is not None:
        side = -1.0 if float(np.mean(problem.path.S_d[:, 4])) >= 0 else 1.0
        out = 0.5 if rate <= SPIN_SHARE else 1.0
        rows.insert(1, ("from rest: yaw spun up, track out", side * out * model.limits.position_max[track], 1.0))
    for name, track_position, direction in rows:
        start = q0.copy()
        if track is not None and track_position:
            start[track] = track_position
        x, u = problem.guess(start, qd0, settled(problem, qd0, a0, spin_following(problem, direction)), a0)
        guesses.append((name, x, u))
    return guesses


def settled(problem: CueingProblem, qd, a, accelerations, first: int = 0) -> np.ndarray:
    """``accelerations`` (N, n) of a guess with every joint that has a travel (finite position limits)
    brought to rest from node ``first`` on, from rates ``qd`` and accelerations ``a`` there, braking
    at the plans' ``braking`` share of the acceleration limit (:func:`desdemona.machine.plan.braked`). A guess
    from a moving start (a window after the first) would otherwise carry the start's rates on at zero
    acceleration into the end of the travel, where :meth:`CueingProblem.guess` clips its positions and
    leaves its gaps open; a joint that turns freely (the yaw, the gimbals of ``full`` and ``dfs``)
    keeps its rate, which a steady turn needs (docs/benchmarks/later-windows-guesses-brought-to-rest.md)."""
    lim, u = problem.model.limits, np.array(accelerations, dtype=float)
    joints = np.isfinite(lim.position_min) | np.isfinite(lim.position_max)
    if not joints.any():
        return u
    u[first:, joints] = braked(np.asarray(qd)[joints], np.asarray(a)[joints], problem.steps[first:],
                               problem.options.braking * lim.acceleration[joints], lim.jerk[joints] if lim.smooth else None)
    return u


# ----------------------------------------------------------------------------------------------
# solving


def _problems(model: Model, path: DesiredPath, options: OptimizeOptions):
    # in parallel starts each process takes a core: the stage functions on one thread each
    threads = 1 if options.workers > 1 and options.starts > 1 else MAP_THREADS
    full = CueingProblem(model, path, options.problem, solves=options.starts, stored=options.stored, threads=threads)
    rough = (CueingProblem(Model(model.params.simplified(), model.config), path, options.problem,
                           solves=options.starts, stored=options.stored, threads=threads) if options.refine else None)
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


def _solve_in_workers(full, rough, guesses, workers: int, done) -> None:
    """Each guess solved in a forked worker process (which inherits the problems built here: no
    rebuild per process), ``done((name, solution))`` told as each ends."""
    _WORKER["problems"] = (full, rough)
    context = multiprocessing.get_context("fork")
    # leaving the block terminates the workers, also when the parent is interrupted
    try:
        with context.Pool(min(workers, len(guesses)), initializer=guard.worker_signals) as pool:
            for part in pool.imap_unordered(_worker_solve, [[g] for g in guesses]):
                done(part[0])
            guard.finish(pool)
    finally:
        _WORKER.clear()


def optimize(path: DesiredPath, model: Model, options: OptimizeOptions = OptimizeOptions(),
             progress=None, first=None) -> Result:
    """The best checked joint trajectory for a desired path (thesis chapters 3-7, off-line).

    model : the machine and configuration, e.g. ``Model(default_params(), "yaw-track-cabin")``;
    progress : optional callable ``progress(done, total, best_cost)`` told once the problem is built
    (done 0, best_cost inf) and after each start;
    first : optional callable ``first(problem) -> guesses`` of the guesses to try before the usual
    ones (a window's: the window before, continued), within ``options.starts``.
    Raises :class:`LimitViolation` when no start yields a trajectory within every limit, and
    :class:`~desdemona.cueing.sizing.TooLarge` before building a problem that would not fit in memory.
    """
    wall = time.perf_counter()
    path = model.config.cue_path(path)
    sizing.check_fits(path, model.config, options.problem, options.workers, model.limits.smooth)
    build = time.perf_counter()
    full, rough = _problems(model, path, options)
    build = time.perf_counter() - build
    guesses = [] if first is None else first(full)[:options.starts]
    guesses += initial_guesses(full, options.starts - len(guesses), options.seed) if options.starts > len(guesses) else []
    solved = []
    if progress is not None:
        progress(0, len(guesses), np.inf)

    def done(item):
        solved.append(item)
        if progress is not None:
            progress(len(solved), len(guesses), min(sol.cost for _, sol in solved))

    if options.workers > 1 and len(guesses) > 1:
        _solve_in_workers(full, rough, guesses, options.workers, done)
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
    solved_by = dict.fromkeys(map(id, (s for _, s in candidates)), full)  # the problem each solution is of
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
                passed, solved_by[id(sol)] = [(best_check, sol)], retry
                break
        else:
            raise LimitViolation(best_check, "every start's trajectory")
    converged = [(c, s) for c, s in passed if s.success]
    chosen_check, chosen = min(converged or passed, key=lambda cs: cs[0].rms)
    times = full.sub_times()
    t = np.r_[times[:, :-1].ravel(), full.t_nodes[-1]]
    trajectory = evaluate_plan(model, path, chosen.plan, t, options.problem.perception)
    pricing = time.perf_counter()
    prices = limit_prices(solved_by[id(chosen)], chosen)
    timings = {"build": build, "solve": sum(r.solve_time for r in reports),
               "prices": time.perf_counter() - pricing, "wall": time.perf_counter() - wall}
    return Result(path=path, model=model, options=options, method=options.problem.solver,
                  solution=chosen, trajectory=trajectory, check=chosen_check, starts=tuple(reports),
                  timings=timings, prices=prices)


def _check(problem: CueingProblem, sol: Solution) -> tuple[LimitCheck, Trajectory]:
    return check(problem.model, problem.path, sol.plan, problem.h_sub, weights=problem.weights,
                 perception=problem.options.perception)


def thesis_result(path: DesiredPath, model: Model, options: thesis.ThesisOptions | None = None) -> Result:
    """The thesis' own method (:func:`desdemona.baselines.thesis.optimize_thesis`), checked and packaged like ours.

    Its best start that keeps every limit on the fine grid is returned; :class:`LimitViolation` if none.
    """
    options = thesis.ThesisOptions() if options is None else options
    wall = time.perf_counter()
    problem, runs = thesis.optimize_thesis(path, model, options)
    step = float(np.min(np.diff(path.t)))
    reports, candidates = [], []
    for k, run in enumerate(runs):
        result_check, _ = check(model, path, run.plan, step)
        reports.append(StartReport(f"random {k}", run.message, result_check.passed, run.iterations,
                                   run.solve_time, run.cost, result_check.rms, result_check.worst_use,
                                   result_check.passed))
        candidates.append((result_check, run))
    passed = [(c, r) for c, r in candidates if c.passed]
    if not passed:
        raise LimitViolation(min(candidates, key=lambda cr: cr[0].worst_use)[0], "the thesis method's trajectory")
    chosen_check, run = min(passed, key=lambda cr: cr[0].rms)
    plan = run.plan
    solution = Solution(t_nodes=plan.t_nodes, x=plan.states(), u=plan.u, cost=run.cost, status=run.message,
                        success=True, iterations=run.iterations, solve_time=run.solve_time)
    trajectory = evaluate_plan(model, path, plan, path.t[path.t <= plan.t_nodes[-1] + 1e-12])
    timings = {"build": 0.0, "solve": sum(r.solve_time for r in runs), "wall": time.perf_counter() - wall}
    return Result(path=path, model=model, options=options, method="thesis", solution=solution,
                  trajectory=trajectory, check=chosen_check, starts=tuple(reports), timings=timings)

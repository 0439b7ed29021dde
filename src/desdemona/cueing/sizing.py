"""What a run will need and what it can reach, known before any work: problem size, time and unreachable targets.

:func:`estimate` counts the control intervals and NLP variables of an off-line problem and its memory,
from figures measured per control interval; :func:`check_fits` refuses a problem that would not fit in
the memory this machine has available, saying what to change, instead of a ``std::bad_alloc`` after
minutes; :func:`estimate_online` and :func:`check_fits_online` do the same for an on-line run.
:func:`check_time` and :func:`check_time_online` do it for the run's time, from figures measured per
interval and iteration and per cycle: a run estimated above :func:`time_limit` (20 times its path,
``--max-time`` to allow more) is refused with the ``--h-u`` or ``--step`` that fits, instead of hours. :func:`unreachable` finds the parts of a desired path that no trajectory of the configuration
can give, by construction: a modulus below g on ``dfs`` (with the cabin aligned the modulus is
sqrt((R qdd)^2 + (R qd^2)^2 + g^2) >= g, thesis 7.2) and a specific force beyond what the machine can
hold steadily (the centripetal force at the largest radius and the fastest yaw rate its motors can hold).
"""

from __future__ import annotations

import math
import os
from dataclasses import dataclass

import numpy as np

from desdemona.cueing.formulation import ProblemOptions
from desdemona.machine.configs import Configuration
from desdemona.machine.model import Model
from desdemona.occupant.perception import THRESHOLDS
from desdemona.profiles import DesiredPath

# Peak resident memory per control interval [bytes] at the default two sub-steps, measured on this
# project's 2-core reference machine (CasADi 3.7, IPOPT with MUMPS) as the slope of ru_maxrss between
# 400 and 1,600 intervals of the cosine path (dfs: its modulus), h_u = 0.05 s:
# dfs 22.4 kB, yaw-track 40.6 kB, yaw-track-cabin 67.8 kB, full 213 kB; with the thesis' perception model
# on full, 1.6x that (341 kB). The cost of a stage grows with its sub-step points (substeps + 1).
BYTES_PER_INTERVAL = {1: 22.4e3, 2: 40.6e3, 3: 67.8e3, 6: 213e3}  # by number of free joints
PERCEPTION_FACTOR = 1.6
BASE_BYTES = 250e6  # Python, NumPy, SciPy, CasADi and the path itself
SAFETY = 2.0  # MUMPS may enlarge its workspace when it re-factorises; the test path converged in 3 iterations
STEADY_WINDOW = 1.0  # [s] a target held at least this long is "steady"


class TooLarge(ValueError):
    """The problem would not fit in memory: the message gives its size and what to change."""


@dataclass(frozen=True)
class Size:
    """intervals : control intervals N; variables : NLP decision variables; memory : estimated peak
    resident memory of the whole run [bytes]; available : memory available on this machine [bytes]."""

    intervals: int
    variables: int
    memory: float
    available: float

    @property
    def fits(self) -> bool:
        return self.memory <= self.available


def available_memory() -> float:
    """Memory available to a new process [bytes]: MemAvailable of /proc/meminfo, else the free pages."""
    try:
        with open("/proc/meminfo") as fh:
            for line in fh:
                if line.startswith("MemAvailable:"):
                    return float(line.split()[1]) * 1024.0
    except OSError:
        pass
    try:
        return float(os.sysconf("SC_AVPHYS_PAGES") * os.sysconf("SC_PAGE_SIZE"))
    except (ValueError, OSError, AttributeError):
        return math.inf


def _per_interval(n: int, options: ProblemOptions) -> float:
    known = sorted(BYTES_PER_INTERVAL)
    per = BYTES_PER_INTERVAL[min((k for k in known if k >= n), default=known[-1])]
    per *= (options.substeps + 1) / 3.0
    return per * (PERCEPTION_FACTOR if options.perception else 1.0)


def estimate(path: DesiredPath, config: Configuration, options: ProblemOptions, workers: int = 1,
             smooth: bool = True) -> Size:
    """The size of the off-line problem of ``path`` on ``config`` solved with ``options`` by ``workers``
    processes (each holds its own solver); ``smooth``: the machine limits jerk (the accelerations are
    states too)."""
    intervals = max(1, int(round(path.duration / options.h_u)))
    n = config.n
    nx = (3 if smooth else 2) * n + (9 if options.perception else 0)  # perception filters: at most 9 states (canals, otoliths)
    variables = intervals * (nx + n) + nx
    memory = BASE_BYTES + SAFETY * intervals * _per_interval(n, options) * max(1, workers)
    return Size(intervals, variables, memory, available_memory())


def check_fits(path: DesiredPath, config: Configuration, options: ProblemOptions, workers: int = 1,
               smooth: bool = True) -> Size:
    """:func:`estimate`, raising :class:`TooLarge` when the problem would not fit in memory."""
    size = estimate(path, config, options, workers, smooth)
    if size.fits:
        return size
    per_interval = (size.memory - BASE_BYTES) / size.intervals
    fitting = max(1.0, (size.available - BASE_BYTES) / per_interval)
    h_u = path.duration / fitting
    seconds = fitting * options.h_u
    shorter = f", or a path shorter than {seconds:.0f} s" if seconds >= 1.0 else ""
    raise TooLarge(
        f"{path.name} on {config.name}: {size.intervals:,} control intervals ({path.duration:g} s at --h-u "
        f"{options.h_u:g} s), {size.variables:,} variables, {memory_words(size)}. Use --h-u {_round_up(h_u)} or "
        f"more{shorter}" + (", or fewer --workers" if workers > 1 else ""))


def memory_words(size: Size) -> str:
    """How much memory a run needs against what is available, in words a reader takes in at once."""
    available = f"{size.available / 1e9:.1f} GB are available"
    if size.memory > 1000 * size.available:
        return f"more than 1,000 times the memory of this machine ({available})"
    return f"about {size.memory / 1e9:.1f} GB of memory; {available}"


# The on-line controller's peak resident memory, measured on the reference machine with dfs-catapult
# on dfs (4 free joints; ru_maxrss): 193 MB with 36 plan intervals and 600 closed-loop steps, 293 MB
# with 100 and 600, 303 MB with 96 and 2,400: about 1.6 MB per interval of the plan (its problem and
# solver) and 9 kB per closed-loop step (the run, its check on a 10x finer grid).
ONLINE_BYTES_PER_INTERVAL = 1.6e6 / 4  # per free joint
ONLINE_BYTES_PER_STEP = 9e3
ONLINE_STEPS = (0.001, 0.002, 0.005, 0.01, 0.02, 0.05, 0.1, 0.2)  # the --step values suggested


def estimate_online(path: DesiredPath, config: Configuration, mpc) -> Size:
    """The size of an on-line run of ``path`` on ``config`` with the :class:`~desdemona.control.mpc.MPCOptions`
    ``mpc``: ``intervals`` of one plan, ``variables`` of one plan's problem, and the run's memory."""
    intervals = len(mpc.grid())
    steps = max(1, int(round(path.duration / mpc.step)))
    n = config.n
    memory = BASE_BYTES + SAFETY * (intervals * ONLINE_BYTES_PER_INTERVAL * n + steps * ONLINE_BYTES_PER_STEP)
    return Size(intervals, intervals * 4 * n, memory, available_memory())


def check_fits_online(path: DesiredPath, config: Configuration, mpc) -> Size:
    """:func:`estimate_online`, raising :class:`TooLarge` when the run would not fit in memory, with the
    smallest ``--step`` of :data:`ONLINE_STEPS` that would."""
    import dataclasses

    size = estimate_online(path, config, mpc)
    if size.fits:
        return size
    fitting = next((s for s in ONLINE_STEPS if s > mpc.step and 2 * s <= mpc.horizon and estimate_online(
        path, config, dataclasses.replace(mpc, step=s, replan=None, tail_step=mpc.tail_step and max(mpc.tail_step, s))
    ).fits), None)
    advice = f"Use --step {fitting:g} or more" if fitting is not None else "Use a larger --step or a shorter --horizon"
    raise TooLarge(
        f"{path.name} on-line on {config.name}: {size.intervals:,} intervals in each plan (--step {mpc.step:g} s "
        f"over {mpc.length:g} s), {int(round(path.duration / mpc.step)):,} closed-loop steps, {memory_words(size)}. "
        f"{advice}")


def _round_up(x: float) -> str:
    digits = 10 ** math.floor(math.log10(x))
    return f"{math.ceil(x / digits) * digits:g}"


def radii(model: Model) -> list[float]:
    """The cabin's distances from the yaw axis [m] that the configuration can hold: the track's two
    ends where it moves (0 where it has no bounds), else its fixed position."""
    config, lim = model.config, model.limits
    if config.moves_track:
        k = config.track
        return [r for r in (lim.position_min[k], lim.position_max[k]) if math.isfinite(r)] or [0.0]
    return [config.held_track]


def held_modulus(path: DesiredPath) -> np.ndarray:
    """The desired modulus |f_d| [m/s^2] averaged over :data:`STEADY_WINDOW` s around each sample: what
    a target asks for as long as it is held."""
    return _moving_mean(path.t, path.M_d, STEADY_WINDOW)


def steady_modulus_limit(model: Model) -> float:
    """The largest specific force [m/s^2] the configuration can hold for as long as wanted: the cabin at
    the largest radius the track allows, turning at the fastest yaw rate at which every joint's
    velocity, force and power limit holds (no acceleration: nothing else is steady)."""
    config, lim = model.config, model.limits
    best = float(model.params.gravity)
    for radius in radii(model):
        q, still = np.zeros(model.n), np.zeros(model.n)
        if config.moves_track:
            q[config.track] = radius

        def state(rate):
            qd = np.zeros(model.n)
            qd[0] = rate
            return qd

        def holds(rate):
            tau = model.tau(q, state(rate), still)
            return np.all(np.abs(tau) <= lim.effort) and np.all(np.abs(tau * state(rate)) <= lim.power)

        low, high = 0.0, float(lim.velocity[0])
        if holds(high):
            low = high
        for _ in range(0 if low == high else 40):  # bisection: the limits bind monotonically in the rate
            mid = 0.5 * (low + high)
            low, high = (mid, high) if holds(mid) else (low, mid)
        best = max(best, float(np.linalg.norm(model.f_cabin(q, state(low), still))))
    return best


def unreachable(path: DesiredPath, model: Model) -> dict:
    """Parts of the desired path no trajectory of ``model``'s configuration can give, by construction.

    Returns {"below_g": ..., "above_steady_limit": ...}, each None or {"share_of_time": fraction of the
    path's duration, "worst_m_s2": the most extreme desired modulus, "limit_m_s2": the bound}. Where the
    heave is held (``dfs``) every sample below g counts; elsewhere (the heave can drop for a moment) and for the upper
    bound, the desired modulus averaged over :data:`STEADY_WINDOW` seconds. A modulus below g by no
    more than the vertical force's perception threshold (0.28 m/s^2) is not counted: no one feels it
    (a logged rest reads standard gravity, 9.80665, and the sensor's noise around it).
    """
    g = float(model.params.gravity)
    t = path.t
    M = path.M_d
    steady = held_modulus(path)
    low = (M if not model.config.moves_heave else steady) < g - THRESHOLDS[5]  # without the heave: always
    limit = steady_modulus_limit(model)
    high = steady > limit * (1.0 + 1e-6)
    return {"below_g": _share(t, M, low, g, np.min), "above_steady_limit": _share(t, M, high, limit, np.max)}


def describe(report: dict) -> str:
    """One phrase for the printed line, empty when everything is reachable."""
    words = []
    for key, text in (("below_g", "below g"), ("above_steady_limit", "above the steady limit")):
        part = report.get(key)
        if part:
            words.append(f"{100 * part['share_of_time']:.1f}% of the time {text} {part['limit_m_s2']:.3g} m/s^2 "
                         f"(worst {part['worst_m_s2']:.3g})")
    return "; unreachable target: " + ", ".join(words) if words else ""


def _moving_mean(t: np.ndarray, values: np.ndarray, window: float) -> np.ndarray:
    """Mean of ``values`` over the window of ``window`` s centred on each sample (trapezoid rule)."""
    cumulative = np.concatenate([[0.0], np.cumsum(0.5 * (values[1:] + values[:-1]) * np.diff(t))])
    lo, hi = np.maximum(t - window / 2, t[0]), np.minimum(t + window / 2, t[-1])
    span = np.maximum(hi - lo, 1e-12)
    mean = (np.interp(hi, t, cumulative) - np.interp(lo, t, cumulative)) / span
    return np.where(hi - lo > 1e-12, mean, values)


def _share(t, M, mask, bound, extreme) -> dict | None:
    if not np.any(mask):
        return None
    weights = np.gradient(t)  # the time each sample stands for
    return {"share_of_time": float(np.sum(weights[mask]) / np.sum(weights)), "worst_m_s2": float(extreme(M[mask])),
            "limit_m_s2": bound}


# ----------------------------------------------------------------------------------------------
# time: a run's estimated seconds, from figures measured per interval and per cycle

#: A run may take this many times its path's duration (and at least :data:`MIN_TIME_LIMIT`) unless
#: the user allows more (``--max-time``).
TIME_FACTOR = 20.0
MIN_TIME_LIMIT = 60.0
# Off-line, per control interval, free joint and solver iteration [s], measured on the reference
# machine with the compiled stages (docs/benchmarks/fatrop-on-blasfeo-for-the-processor.md): fatrop on
# `full`, the F-16 turn's 1,100 intervals at 77 ms an iteration; IPOPT on `full`, the catapult's 160
# at 24 ms. A start is taken to need ITERATIONS (the corpus' hard cases: 150-500, the cap 500);
# fatrop's set-up grows with the square of a solve's intervals (12 s at 1,140, 40 s at 1,880);
# BASE_SECONDS: imports, the check, the figures.
SECONDS_PER_INTERVAL = {"fatrop": 12e-6, "ipopt": 25e-6}
ITERATIONS = 300
SETUP_PER_INTERVAL_SQUARED = 1e-5
BASE_SECONDS = 10.0
# On-line, per interval of a plan [s], by free joints (the next listed at or above): one cycle's
# computation with its real-time iteration, `dfs` at 100 Hz (56 intervals, p99 5.6 ms, the QP alone
# 1.2-1.4 ms), `full` at 50 Hz (46, median 8.7 ms); a plan solved by IPOPT (--replan) NLP_FACTOR times
# that (7 ms for 50 intervals of one joint against 0.6 ms); and per closed-loop step the plant, the
# predictor and the check. Figures of a quiet machine: one that shares its cores takes longer.
SECONDS_PER_PLAN_INTERVAL = {4: 60e-6, 6: 200e-6}
NLP_FACTOR = 6.0
SECONDS_PER_STEP = 5e-4
H_U_STEPS = (0.001, 0.002, 0.005, 0.01, 0.02, 0.05, 0.1, 0.2, 0.5)  # the --h-u values suggested


class TooLong(ValueError):
    """The run would take longer than its limit: the message gives the estimate and what to change."""


def time_limit(path: DesiredPath, max_time: float | None = None) -> float:
    """The seconds a run of ``path`` may take: ``max_time`` where given, else :data:`TIME_FACTOR` times
    its duration, at least :data:`MIN_TIME_LIMIT`. Raises :class:`TooLong` for a ``max_time`` that is
    not a positive number of seconds."""
    if max_time is not None and not (max_time > 0 and math.isfinite(max_time)):
        raise TooLong(f"--max-time {max_time:g}: must be a positive number of seconds")
    return max_time if max_time is not None else max(TIME_FACTOR * path.duration, MIN_TIME_LIMIT)


def estimate_time(path: DesiredPath, config: Configuration, h_u: float, solver: str, starts: int = 1,
                  workers: int = 1, window: float | None = None) -> float:
    """The seconds an off-line run of ``path`` on ``config`` at the control step ``h_u`` takes with
    ``solver`` ("ipopt" or "fatrop"), ``starts`` on ``workers`` processes, whole or in windows of
    ``window`` s: the starts' iterations over every interval, and fatrop's set-up per solve."""
    intervals = path.duration / h_u
    per_solve = intervals if window is None else min(intervals, window / h_u)
    rounds = math.ceil(starts / max(1, min(workers, starts)))
    seconds = rounds * ITERATIONS * intervals * config.n * SECONDS_PER_INTERVAL[solver]
    if solver == "fatrop":
        seconds += SETUP_PER_INTERVAL_SQUARED * per_solve * intervals
    return BASE_SECONDS + seconds


def check_time(path: DesiredPath, config: Configuration, h_u: float, solver: str, starts: int = 1,
               workers: int = 1, window: float | None = None, max_time: float | None = None) -> float:
    """:func:`estimate_time`, raising :class:`TooLong` above :func:`time_limit`, with the smallest
    ``--h-u`` of :data:`H_U_STEPS` that fits."""
    seconds, limit = estimate_time(path, config, h_u, solver, starts, workers, window), time_limit(path, max_time)
    if seconds <= limit:
        return seconds
    fitting = next((h for h in H_U_STEPS if h_u < h <= path.duration and estimate_time(
        path, config, h, solver, starts, workers, window) <= limit), None)
    advice = f"Use --h-u {fitting:g} or more" if fitting is not None else "Use a larger --h-u or a shorter path"
    raise TooLong(f"{path.name} on {config.name}: {round(path.duration / h_u):,} control intervals "
                  f"({path.duration:g} s at --h-u {h_u:g} s), {starts} start{'s' if starts > 1 else ''}: "
                  f"{time_words(seconds, limit, max_time)}. {advice}, fewer --starts, or --max-time "
                  f"{_seconds_up(seconds)} to allow it")


def estimate_time_online(path: DesiredPath, config: Configuration, mpc) -> float:
    """The seconds an on-line run of ``path`` on ``config`` with the
    :class:`~desdemona.control.mpc.MPCOptions` ``mpc`` takes: a plan every re-plan period, each over
    the plan's intervals, and the closed loop's steps."""
    steps = path.duration / mpc.step
    known = sorted(SECONDS_PER_PLAN_INTERVAL)
    per_interval = SECONDS_PER_PLAN_INTERVAL[min((k for k in known if k >= config.n), default=known[-1])]
    plan = len(mpc.grid()) * per_interval * (1.0 if mpc.replan_steps == 1 else NLP_FACTOR)
    return BASE_SECONDS + steps / mpc.replan_steps * plan + steps * SECONDS_PER_STEP


def check_time_online(path: DesiredPath, config: Configuration, mpc, max_time: float | None = None) -> float:
    """:func:`estimate_time_online`, raising :class:`TooLong` above :func:`time_limit`, with the
    smallest ``--step`` of :data:`ONLINE_STEPS` that fits."""
    import dataclasses

    seconds, limit = estimate_time_online(path, config, mpc), time_limit(path, max_time)
    if seconds <= limit:
        return seconds
    fitting = next((s for s in ONLINE_STEPS if s > mpc.step and 2 * s <= mpc.horizon and estimate_time_online(
        path, config, dataclasses.replace(mpc, step=s, replan=None, tail_step=mpc.tail_step and max(mpc.tail_step, s))
    ) <= limit), None)
    advice = f"Use --step {fitting:g} or more" if fitting is not None else "Use a larger --step"
    raise TooLong(f"{path.name} on-line on {config.name}: {round(path.duration / mpc.step):,} closed-loop "
                  f"steps (--step {mpc.step:g} s over {path.duration:g} s), {len(mpc.grid()):,} intervals in "
                  f"each plan: {time_words(seconds, limit, max_time)}. {advice}, or --max-time "
                  f"{_seconds_up(seconds)} to allow it")


def time_words(seconds: float, limit: float, max_time: float | None) -> str:
    """An estimate against its limit, in words."""
    allowed = (f"--max-time {max_time:g} s" if max_time is not None else
               f"the limit of {limit:.0f} s ({TIME_FACTOR:g} times the path, at least {MIN_TIME_LIMIT:g} s)")
    return f"about {duration_words(seconds)} estimated, above {allowed}"


def _seconds_up(seconds: float) -> str:
    """``seconds`` rounded up to one significant digit, as a whole number."""
    return f"{float(_round_up(max(seconds, 1.0))):.0f}"


def duration_words(seconds: float) -> str:
    """``seconds`` as a person reads them: 45 s, 12 min, 3.2 h."""
    if seconds < 120.0:
        return f"{seconds:.0f} s"
    if seconds < 7200.0:
        return f"{seconds / 60:.0f} min"
    return f"{seconds / 3600:.1f} h"

"""Plant integration and the independent limit check.

Whatever an optimiser or controller returns is re-simulated here, independently of how it was
computed: its :class:`~desdemona.machine.plan.Plan` is evaluated with NumPy on a grid ``fine`` times finer
than the optimiser's, every limit of eq. 3.3-3.5 is evaluated on that grid, and S (and the perceived S) is
compared with S_d there. A trajectory that uses more than 1 + 1e-6 of any limit is an error
(:class:`LimitViolation`), never a result.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from desdemona.machine.model import Model
from desdemona.machine.params import JOINT_NAMES
from desdemona.machine.plan import Plan, State
from desdemona.occupant.perception import VestibularModel
from desdemona.profiles import CHANNELS, DesiredPath

TOLERANCE = 1e-6
LIMIT_NAMES = ("position", "velocity", "acceleration", "jerk", "effort", "power")


class LimitViolation(RuntimeError):
    """A trajectory exceeds a limit of the machine; carries the :class:`LimitCheck`."""

    def __init__(self, check: "LimitCheck", what: str = "trajectory"):
        self.check = check
        super().__init__(f"{what} violates the machine's limits: {check.describe_violations()}")


@dataclass(frozen=True, eq=False)
class Trajectory:
    """A joint trajectory with everything felt and demanded along it, on a time grid.

    t : (K,) [s]; q, qd, qdd, tau, power : (K, n) of the free joints; S, S_d : (K, 6);
    S_perc, S_d_perc : (K, 6) perceived paths where a perception model was used, else None;
    M, M_d : (K,) modulus of the specific force and its desired value (eq. 7.1, 7.2).
    """

    t: np.ndarray
    q: np.ndarray
    qd: np.ndarray
    qdd: np.ndarray
    tau: np.ndarray
    power: np.ndarray
    S: np.ndarray
    S_d: np.ndarray | None
    M: np.ndarray
    M_d: np.ndarray
    S_perc: np.ndarray | None = None
    S_d_perc: np.ndarray | None = None


@dataclass(frozen=True, eq=False)
class LimitCheck:
    """Worst use of every limit (1 = at the limit) and the fine-grid errors of a trajectory.

    use : {limit name: (n,) worst use per free joint}; worst : {limit name: worst over joints};
    rms : weighted RMS of S - S_d (eq. 5.1 with Q), or of M - M_d for a modulus path;
    rms_channels : (6,) RMS per channel of S - S_d (None for a modulus path);
    rms_perceived : weighted RMS of the perceived difference, where perception was on;
    rms_modulus : RMS of M - M_d; step : the fine grid's step [s].
    """

    use: dict
    worst: dict
    rms: float
    rms_channels: np.ndarray | None
    rms_perceived: float | None
    rms_modulus: float
    step: float
    joint_names: tuple[str, ...] = field(default=())

    @property
    def passed(self) -> bool:
        return all(v <= 1.0 + TOLERANCE for v in self.worst.values())

    @property
    def worst_use(self) -> float:
        return max(self.worst.values())

    def describe_violations(self) -> str:
        parts = []
        for name in LIMIT_NAMES:
            for k, value in enumerate(self.use[name]):
                if value > 1.0 + TOLERANCE:
                    joint = self.joint_names[k] if self.joint_names else f"joint {k}"
                    parts.append(f"{name} of {joint} at {value:.6g} x its limit")
        return "; ".join(parts) if parts else "none"


def fine_grid(t_nodes, step: float) -> np.ndarray:
    """Times from t_nodes[0] to t_nodes[-1] at ``step`` or finer, containing every node."""
    pieces = []
    for a, b in zip(t_nodes[:-1], t_nodes[1:]):
        count = max(1, int(np.ceil((b - a) / step - 1e-9)))
        pieces.append(np.linspace(a, b, count, endpoint=False))
    return np.concatenate(pieces + [np.asarray(t_nodes[-1:])])


def evaluate(model: Model, path: DesiredPath, t, q, qd, qdd, perception: VestibularModel | None = None) -> Trajectory:
    """Everything along a trajectory of the free joints: torques, power, S, and what S_d asks there.

    perception : a vestibular model through which S and S_d are also perceived (full paths only).
    """
    S = model.S(q, qd, qdd)
    tau = model.tau(q, qd, qdd)
    M = np.linalg.norm(S[:, 3:], axis=1)
    S_d = path.sample(t) if path.S_d is not None else None
    S_perc = S_d_perc = None
    if perception is not None and S_d is not None:
        # t is uniform away from the last point; the filters hold each sample over one step
        step = float(np.median(np.diff(t)))
        S_perc = perception.perceive(S, step)
        S_d_perc = perception.perceive(S_d, step)
    return Trajectory(t=np.asarray(t, float), q=q, qd=qd, qdd=qdd, tau=tau, power=tau * qd, S=S, S_d=S_d,
                      M=M, M_d=path.sample_modulus(t), S_perc=S_perc, S_d_perc=S_d_perc)


def evaluate_plan(model: Model, path: DesiredPath, plan: Plan, times,
                  perception: VestibularModel | None = None) -> Trajectory:
    """:func:`evaluate` along a plan at ``times`` (K,) [s]."""
    return evaluate(model, path, times, *plan.at(times), perception)


def limit_use(model: Model, traj: Trajectory) -> dict[str, np.ndarray]:
    """Worst use of each limit per free joint over a trajectory (1 = at the limit)."""
    lim = model.limits
    bounds = {"position": (lim.position_min, lim.position_max), "velocity": lim.velocity,
              "acceleration": lim.acceleration, "effort": lim.effort, "power": lim.power}
    values = {"q": traj.q, "qd": traj.qd, "qdd": traj.qdd, "tau": traj.tau, "power": traj.power}
    return {kind: np.max(use, axis=0) for kind, use in uses_over_time(values, bounds).items()}


#: The limit each trajectory quantity has: trajectory.csv's prefix -> the limit's name.
LIMITED = {"q": "position", "qd": "velocity", "qdd": "acceleration", "tau": "effort", "power": "power"}


def uses_over_time(values: dict, bounds: dict) -> dict[str, np.ndarray]:
    """The use of each limit at every sample, 1 = at the limit: ``values`` maps the prefixes of
    :data:`LIMITED` to arrays (K, n), ``bounds`` the limits' names to their (n,) limits, the position's
    as (lower, upper) (infinite, or absent, where a joint has none). Returns {limit: (K, n)} for every
    limit given both."""
    uses = {}
    for key, kind in LIMITED.items():
        if key not in values or kind not in bounds:
            continue
        if kind == "position":
            lo, hi = (np.asarray(b, dtype=float) for b in bounds[kind])
            bounded = np.isfinite(lo) & np.isfinite(hi)
            mid = 0.5 * (np.where(bounded, lo, 0.0) + np.where(bounded, hi, 0.0))
            half = np.where(bounded, 0.5 * (np.where(bounded, hi, 1.0) - np.where(bounded, lo, -1.0)), np.inf)
            uses[kind] = np.abs(values[key] - mid) / half
        else:
            uses[kind] = np.abs(values[key]) / bounds[kind]
    return uses


def jerk_use(model: Model, plan: Plan, step: float) -> np.ndarray:
    """Worst use of the jerk limit per free joint (n,) over a plan, on a grid of ``step`` [s].

    Inside an interval the jerk is the plan's own, constant; a step of the acceleration at a node is a
    jerk without bound, counted as the jerk that would make that step within one ``step`` of the check's
    grid; so is the first acceleration of a plan that starts at rest (a machine at rest does not
    accelerate). Zero where the machine has no jerk limit.
    """
    limit = model.limits.jerk
    if not np.any(np.isfinite(limit)):
        return np.zeros(plan.n)
    jumps = plan.acceleration_jumps()
    if not np.any(plan.qd0):
        jumps = np.vstack([plan.u[:1], jumps])
    jumps = np.abs(jumps) / step
    worst = np.max(np.abs(plan.jerk), axis=0, initial=0.0)
    worst = np.maximum(worst, np.max(jumps, axis=0, initial=0.0))
    return np.where(np.isfinite(limit), worst / limit, 0.0)


def check(model: Model, path: DesiredPath, plan: Plan, step: float, fine: int = 10,
          weights=None, perception: VestibularModel | None = None) -> tuple[LimitCheck, Trajectory]:
    """The independent check: re-integrate a plan on a grid ``fine`` times finer than ``step``.

    Every limit of every free joint is measured there, the jerk included (:func:`jerk_use`).

    step : the optimiser's finest grid (its sub-step) [s]; weights : diagonal of Q, default the path's.
    Returns the check and the fine-grid trajectory.
    """
    path = model.config.cue_path(path)
    traj = evaluate_plan(model, path, plan, fine_grid(plan.t_nodes, step / fine), perception)
    use = limit_use(model, traj)
    use["jerk"] = jerk_use(model, plan, step / fine)
    rms_modulus = float(np.sqrt(np.mean((traj.M - traj.M_d) ** 2)))
    w = np.asarray(weights if weights is not None else path.weights, float)
    rms_channels = rms_perceived = None
    if model.config.modulus_cost or traj.S_d is None:
        rms = rms_modulus
    else:
        diff = traj.S - traj.S_d
        rms_channels = np.sqrt(np.mean(diff**2, axis=0))
        rms = float(np.sqrt(np.mean(diff**2 @ w)))
        if traj.S_perc is not None:
            rms_perceived = float(np.sqrt(np.mean((traj.S_perc - traj.S_d_perc) ** 2 @ w)))
    result = LimitCheck(use=use, worst={k: float(v.max()) for k, v in use.items()}, rms=rms,
                        rms_channels=rms_channels, rms_perceived=rms_perceived, rms_modulus=rms_modulus,
                        step=step / fine, joint_names=model.config.joint_names)
    return result, traj


@dataclass(frozen=True, eq=False)
class ClosedLoop:
    """A closed-loop run: the plan the plant executed, and per control cycle its start time [s], the
    source of its commands, the compute time [s] and the reason for any fallback."""

    plan: Plan
    cycle_times: np.ndarray
    sources: tuple[str, ...]
    compute_times: np.ndarray
    reasons: tuple[str, ...] = field(default=())


def closed_loop(controller, path: DesiredPath, predictor, q0=None, qd0=None,
                duration: float | None = None) -> ClosedLoop:
    """Run a controller against the plant: each cycle's commands are applied one step each and
    integrated exactly (the same model, as the machine's servos follow it).

    controller : has ``step((q, qd, qdd), preview) -> command`` with ``command.sequence`` (r, n) the
        accelerations at the start of each step, ``command.jerk`` (r, n) their rates of change over it,
        ``.source``, ``.compute_time``, ``.reason``, and ``options`` with ``step``, ``horizon``,
        ``period`` (T_c = r steps) and ``delay`` (e.g. :class:`desdemona.control.mpc.MPC`);
        predictor : ``predictor(path, now, horizon) -> preview``, e.g.
        :func:`desdemona.control.predictors.predictor` (name). Every cycle's compute time is recorded.

    The plant starts at (q0, qd0) with zero acceleration and applies what it is told: a command whose
    acceleration does not start where the last one ended is a step of acceleration, which the
    independent check reports on a machine with jerk limits.

    With ``delay`` (thesis 7.1, figure 7.2) the plan computed in the cycle that starts at t is applied
    from t + T_c: the controller is given the state predicted for then (the commands of the running
    cycle applied to the state at t) and the preview from t + T_c as predicted at t. The first plan is
    computed in the cycle before the session starts (recorded at t = -T_c), from the start state and
    the preview from t = 0, as a controller that is running when the session begins would have it.
    """
    o = controller.options
    h, n, r = o.step, controller.model.n, o.replan_steps
    steps = int(math.floor((duration or path.duration) / h + 1e-9))
    state = State(np.zeros(n) if q0 is None else np.asarray(q0, float).copy(),
                  np.zeros(n) if qd0 is None else np.asarray(qd0, float).copy(), np.zeros(n))
    start_q, start_qd = state.q.copy(), state.qd.copy()
    u, jerks, starts, sources, times, reasons = [], [], [], [], [], []
    pending = (np.zeros((r, n)), np.zeros((r, n)))  # with delay: the commands of the running cycle

    def record(now, command):
        starts.append(now)
        sources.append(command.source)
        times.append(command.compute_time)
        reasons.append(command.reason)

    if o.delay:  # the first plan: computed in the cycle before the session, from its known start
        command = controller.step(state, predictor(path, 0.0, o.horizon))
        record(-o.period, command)
        pending = (command.sequence, command.jerks)
    for k in range(0, steps, r):
        now = k * h
        if o.delay:
            ahead = state
            for qdd, jerk in zip(*pending):
                ahead = ahead.advance(qdd, h, jerk)
            command = controller.step(ahead, _later(predictor(path, now, o.horizon + o.period), o.period))
            (sequence, jerk_sequence), pending = pending, (command.sequence, command.jerks)
        else:
            command = controller.step(state, predictor(path, now, o.horizon))
            sequence, jerk_sequence = command.sequence, command.jerks
        record(now, command)
        for qdd, jerk in list(zip(sequence, jerk_sequence))[:steps - k]:
            u.append(qdd)
            jerks.append(jerk)
            state = state.advance(qdd, h, jerk)
    return ClosedLoop(Plan(np.arange(len(u) + 1) * h, start_q, start_qd, np.array(u), np.array(jerks)),
                      np.array(starts), tuple(sources), np.array(times), tuple(reasons))


def _later(preview, offset: float):
    """The part of a preview from ``offset`` [s] on, with its time counted from there."""
    if isinstance(preview, DesiredPath):
        keep = preview.t >= offset - 1e-12
        return DesiredPath(preview.name, preview.t[keep] - offset,
                           None if preview.S_d is None else preview.S_d[keep], preview.weights,
                           preview.description, None if preview.modulus is None else preview.modulus[keep])
    t, values = (np.asarray(v, dtype=float) for v in preview)
    keep = t >= offset - 1e-12
    return t[keep] - offset, values[keep]


# ----------------------------------------------------------------------------------------------
# a trajectory as a table

def trajectory_table(traj: Trajectory, config) -> tuple[list[str], np.ndarray]:
    """Column names and values (K, columns) of trajectory.csv.

    config : the result's :class:`~desdemona.machine.configs.Configuration`. Positions, rates and accelerations
    are given for all six joints, the held ones at their fixed positions and at rest, so that the file
    drives the whole machine; torques and power for the free joints (a held joint's brake is not a
    motor limit, section 5.5).
    """
    names, columns = ["t"], [traj.t[:, None]]
    for label, values, held in (("q", traj.q, "position"), ("qd", traj.qd, "zero"), ("qdd", traj.qdd, "zero")):
        names += [f"{label}_{j}" for j in JOINT_NAMES]
        columns.append(config.expand(values, held))
    for label, values in (("tau", traj.tau), ("power", traj.power)):
        names += [f"{label}_{j}" for j in config.joint_names]
        columns.append(values)
    names += list(CHANNELS)
    columns.append(traj.S)
    if traj.S_d is not None:
        names += [f"{c}_d" for c in CHANNELS]
        columns.append(traj.S_d)
    names += ["M", "M_d"]
    columns += [traj.M[:, None], traj.M_d[:, None]]
    if traj.S_perc is not None:
        names += [f"{c}_perc" for c in CHANNELS] + [f"{c}_d_perc" for c in CHANNELS]
        columns += [traj.S_perc, traj.S_d_perc]
    return names, np.hstack(columns)


def trajectory_dataframe(traj: Trajectory, config):
    """A pandas DataFrame of a trajectory with the columns of trajectory.csv, indexed by t [s].

    pandas is an optional extra (``pip install 'desdemona[dataframe]'``), not a dependency.
    """
    try:
        import pandas
    except ImportError:
        raise ImportError("a DataFrame needs pandas: pip install 'desdemona[dataframe]'") from None
    names, table = trajectory_table(traj, config)
    return pandas.DataFrame(table[:, 1:], index=pandas.Index(table[:, 0], name="t"), columns=names[1:])

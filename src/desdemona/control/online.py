"""A whole on-line session as a value: the controller against the plant, checked, beside the classical loop.

:func:`run` closes the loop of :class:`desdemona.control.mpc.MPC` against the plant
(:func:`desdemona.check.simulate.closed_loop`) over a desired path the controller sees only through a
predictor (:mod:`desdemona.control.predictors`), from the start :class:`OnlineOptions` says; checks the run
independently; and runs beside it what a simulator runs today (the classical loop of 7.4.2 on dfs, a
classical washout elsewhere, :mod:`desdemona.baselines.classical`) from the same state (:class:`OnlineResult`).
The ``online`` command, the benchmarks and the tests all call it (the command through
:func:`desdemona.runs.session.online`).
"""

from __future__ import annotations

import functools
from dataclasses import dataclass
from typing import Literal

import numpy as np

from desdemona.baselines.classical import classical_dfs, steady_start
from desdemona.baselines.washout import classical_washout
from desdemona.check import metrics
from desdemona.check.simulate import (
    ClosedLoop,
    LimitCheck,
    LimitViolation,
    Trajectory,
    check,
    closed_loop,
    evaluate_plan,
    trajectory_dataframe,
)
from desdemona.control import predictors
from desdemona.control.mpc import MPC, MPCOptions
from desdemona.control.predictors import predictor
from desdemona.machine.kinematics import gimbal_twin, wrapped
from desdemona.machine.model import Model
from desdemona.machine.plan import Plan, start_state
from desdemona.profiles import DesiredPath
from desdemona.profiles.forecast import Forecast

#: The session's starts (:class:`OnlineOptions`), the first the default.
INITIAL_CHOICES = ("rest", "home", "steady", "given")


@dataclass(frozen=True)
class OnlineOptions:
    """Options of :func:`run`: the controller's (:class:`MPCOptions`), the predictor's name
    (:data:`desdemona.control.predictors.PREDICTORS`) and, for ``route``, its ``reference`` recording, for
    ``forecast`` the vehicle's ``forecast`` (None in a live session, whose host sends it), and the
    machine's state when the session starts: ``initial``

    - "rest" (the default): still, where the first plan wants the machine: the positions are chosen with
      the first plan before the session (:meth:`MPC.place`), as the off-line problem's ``rest`` chooses
      them, and the machine is moved there beforehand; on the configurations whose cabin follows the
      force (``dfs``), and with a perception model, at home;
    - "home": still, every joint at its centre;
    - "steady": in steady state with the path's first sample (:func:`desdemona.baselines.classical.steady_start`):
      on ``dfs`` the arm already turning, elsewhere the cabin tilted to it; the classical washout then
      starts trimmed too;
    - "given": ``initial_state`` = (q0, qd0) of the free joints (a given ``initial_state`` alone means
      "given").

    The classical baseline starts from the same state as the MPC (its gimbals, if still, on the branch
    of the same cabin attitude that the loop steers from: :func:`_loop_start`)."""

    mpc: MPCOptions = MPCOptions()
    predictor: str = "perfect"  # a name of predictors.PREDICTORS
    initial_state: tuple | None = None
    reference: DesiredPath | None = None
    initial: Literal["rest", "home", "steady", "given"] | None = None
    forecast: Forecast | None = None

    def __post_init__(self):
        # a forecast may come later, from a live session's host
        predictors.check(self.predictor, None, self.reference is not None, self.forecast is not None)
        if self.initial is None:
            object.__setattr__(self, "initial", "rest" if self.initial_state is None else "given")
        if self.initial not in INITIAL_CHOICES:
            raise ValueError(f"initial = {self.initial!r}: must be one of {', '.join(INITIAL_CHOICES)}")
        if (self.initial == "given") != (self.initial_state is not None):
            raise ValueError("initial 'given' and initial_state go together")

    def start(self, path: DesiredPath, model: Model) -> tuple[np.ndarray, np.ndarray]:
        """(q0, qd0) of the model's free joints when the session on ``path`` starts, before
        :meth:`MPC.place` places a "rest" start (at home until then)."""
        if self.initial == "steady":
            return steady_start(model.config.cue_path(path), model)
        return start_state(self.initial_state, model.n)


@dataclass(frozen=True, eq=False)
class OnlineResult:
    """A checked closed-loop run of the MPC against the plant, with the classical loop beside it.

    loop : the plan the plant executed and the per-cycle records (source, compute time, reason);
    deadline : the compute budget per cycle [s]; trajectory : the motion on the control grid;
    check : the independent fine-grid check of the run (it passed: a run that does not is an error);
    baseline, baseline_check : what a simulator runs today, on the same grid from the same state, and
    its check: the classical loop of 7.4.2 on ``dfs``, the classical washout
    (:func:`desdemona.baselines.classical.classical_washout`) on the other configurations.
    """

    path: DesiredPath
    model: Model
    options: OnlineOptions
    loop: ClosedLoop
    deadline: float
    trajectory: Trajectory
    check: LimitCheck
    baseline: Trajectory | None = None
    baseline_check: LimitCheck | None = None

    @property
    def plan(self) -> Plan:
        return self.loop.plan

    @functools.cached_property
    def quality(self) -> metrics.Metrics:
        """What the occupant feels and the machine does (:mod:`desdemona.check.metrics`)."""
        return metrics.of_trajectory(self.trajectory, self.model.config.joint_names, self.options.mpc.perception)

    @functools.cached_property
    def baseline_quality(self) -> metrics.Metrics | None:
        """The same metrics for the classical loop, where there is one."""
        if self.baseline is None:
            return None
        return metrics.of_trajectory(self.baseline, self.model.config.joint_names, self.options.mpc.perception)

    def to_dataframe(self):
        """The trajectory as a pandas DataFrame indexed by time (needs pandas)."""
        return trajectory_dataframe(self.trajectory, self.model.config)


def run(path: DesiredPath, model: Model, options: OnlineOptions = OnlineOptions(), progress=None) -> OnlineResult:
    """Run the MPC in closed loop over a whole desired path and check the result (thesis chapter 7).

    The controller sees the path only through the predictor; each command is held for one step and
    integrated exactly. The machine starts as ``options`` say (by default at rest, where the first
    plan wants it, :meth:`MPC.place`; see :class:`OnlineOptions`), and the classical loop (``dfs``)
    or washout (the others) runs beside it from the same state as the baseline. Raises :class:`LimitViolation` if the run breaks a limit on the independent check's fine
    grid. progress : optional ``progress(now)`` told as each cycle begins, ``now`` [s] on the path.
    """
    path = model.config.cue_path(path)
    reference = None if options.reference is None else model.config.cue_path(options.reference)
    forecast = None if options.forecast is None else options.forecast.map(model.config.cue_path)
    q0, qd0 = options.start(path, model)
    controller = MPC(model, options.mpc, weights=path.weights)

    def fresh():  # a fresh predictor: hold and route keep state from call to call
        made = predictor(options.predictor, reference, forecast)
        if progress is None:
            return made

        def told(seen, now, horizon):  # each cycle asks for its preview once
            progress(now)
            return made(seen, now, horizon)

        return told

    if options.initial == "rest":  # a fresh predictor's first preview: no state is kept
        q0, qd0 = controller.place((q0, qd0), fresh()(path, 0.0, options.mpc.horizon))
    loop = closed_loop(controller, path, fresh(), q0=q0, qd0=qd0)
    return judge(path, model, options, loop, controller.deadline)


def _loop_start(model: Model, q0, qd0) -> np.ndarray:
    """Where the classical loop starts: the MPC's start, with a still outer gimbal turned past 90 deg
    (a start placed on the gimbals' other branch of the cabin's attitude) put on the branch the loop
    steers from, :func:`~desdemona.machine.kinematics.gimbal_twin`: the same pose and S. The loop steers its
    gimbal angles from home, and from the other branch it turned the cabin through half a turn
    (b737-steady-turn on full: felt direction 88 deg, felt force RMS 3.85 against 1.48)."""
    if model.config.gimbals is None:
        return q0
    gimbals = list(model.config.gimbals)  # the outer gimbal first
    if np.any(np.asarray(qd0)[gimbals] != 0.0) or abs(wrapped(q0[gimbals[0]])) <= np.pi / 2:
        return q0
    twin = model.config.select(gimbal_twin(model.config.expand(q0)))
    limits = model.limits
    return twin if np.all((twin >= limits.position_min) & (twin <= limits.position_max)) else q0


def judge(path: DesiredPath, model: Model, options: OnlineOptions, loop: ClosedLoop, deadline: float) -> OnlineResult:
    """A closed-loop session as a checked :class:`OnlineResult`: the plan the machine executed
    (``loop``, from its start) checked independently on the fine grid, and the classical loop run
    beside it on the same path from the same start (:func:`_loop_start`). :func:`run` and the
    real-time service (:mod:`desdemona.service.serve`) judge their sessions with it. Raises
    :class:`LimitViolation` if the plan breaks a limit."""
    step = options.mpc.step
    path = model.config.cue_path(path)
    q0, qd0 = loop.plan.q0, loop.plan.qd0
    # judged with the weights the controller minimised, and perceived through its perception model, as
    # an off-line result is (desdemona.runs.session)
    weights, perception = options.mpc.weights, options.mpc.perception
    result, _ = check(model, path, loop.plan, step=step, weights=weights, perception=perception)
    if not result.passed:
        raise LimitViolation(result, "the closed-loop trajectory")
    nodes = loop.plan.t_nodes
    start = (_loop_start(model, q0, qd0), qd0)
    if model.config.takes_modulus:
        classical = classical_dfs(path, model, times=nodes, state=start)
    else:
        classical = classical_washout(path, model, times=nodes, state=start, trimmed=options.initial == "steady")
    baseline_check, _ = check(model, path, classical, step=step, weights=weights, perception=perception)
    baseline = evaluate_plan(model, path, classical, nodes, perception)
    return OnlineResult(path=path, model=model, options=options, loop=loop, deadline=deadline,
                        trajectory=evaluate_plan(model, path, loop.plan, nodes, perception), check=result,
                        baseline=baseline, baseline_check=baseline_check)

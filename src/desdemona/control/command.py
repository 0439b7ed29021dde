"""What one cycle of the on-line controller returns (:class:`Command`), and the horizon a session uses
by default (:func:`default_horizon`): values that :mod:`desdemona.control.mpc` produces and the
closed loop, the service and the reports read; what one of its solves gives (:class:`_Solved`)."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Literal, NamedTuple

import numpy as np

from desdemona.occupant.perception import VestibularModel


@dataclass(frozen=True)
class Command:
    """What one cycle returns: the joint accelerations of its steps, and why.

    sequence : (r, n) accelerations at the start of each step, r = ``options.replan_steps``;
    source : "mpc" (this cycle's plan), "shifted" (the previous plan), "brake" (no plan left);
    compute_time [s] of the cycle; reason : why a fallback was used ("" for "mpc");
    jerk : (r, n) the accelerations' rate of change over each step (None: held constant).
    """

    sequence: np.ndarray
    source: Literal["mpc", "shifted", "brake"]
    compute_time: float
    reason: str = ""
    jerk: np.ndarray | None = None

    @property
    def jerks(self) -> np.ndarray:
        """(r, n) jerks of the steps (zeros where the accelerations are held)."""
        return np.zeros_like(self.sequence) if self.jerk is None else self.jerk

    @property
    def qdd(self) -> np.ndarray:
        """(n,) the first step's accelerations."""
        return self.sequence[0]


def default_horizon(config) -> float:
    """The horizon a session uses when none is given [s]: 2 s where only the yaw and the gimbals
    move (dfs), 4 s where the track does, whose position must be planned further ahead than the cue
    (docs/benchmarks/default-horizon.md). A session's plans reach at least this far whatever the horizon
    (``MPCOptions.reach``)."""
    return 4.0 if config.moves_track else 2.0


class _Solved(NamedTuple):
    """What one solve of :class:`MPC` gives: the plan (accelerations, jerks) per interval, whether the
    solver succeeded, its time [s], the start's positions and (IPOPT only) the cost."""

    plan: tuple[np.ndarray, np.ndarray]
    success: bool
    elapsed: float
    start: np.ndarray
    cost: float | None


@dataclass(frozen=True)
class MPCOptions:
    """What the controller plans and how (thesis chapter 7).

    horizon : T_h [s], how far the preview reaches; step : h [s], the grid of the plan (its
    accelerations are held this long); replan : T_c [s], the period at which a new plan is computed,
    a whole number of steps (default: every step); delay : simulate the computation time as the thesis
    does (7.1, figure 7.2): the plan computed during [t, t + T_c] from the state at t is applied from
    t + T_c, so it starts from the state predicted there; deadline : compute budget per plan [s]
    (default: T_c); substeps, regularisation, margin, weights, spin_weight, jerk_weight, wall, rotation_band,
    rotation_ceiling (the felt rotation beyond so many thresholds weighs more): as in
    :class:`~desdemona.cueing.formulation.ProblemOptions` (jerk_weight None:
    :func:`~desdemona.cueing.formulation.default_jerk_weight` on-line); braking : fraction of the acceleration
    limit assumed for stopping; method : "rti" (real-time iteration: one Gauss-Newton QP per plan,
    linearised at the shifted previous plan, solved by CasADi's ``qp_solver`` plugin), "nlp" (IPOPT
    to convergence, warm-started, at most ``max_iter`` iterations) or "auto" (see
    :attr:`plan_method`); perception : minimise the perceived difference through this vestibular model
    (chapter 6): the controller then carries the filter states of what the person has felt and of
    what they should have felt from step to step; null_weight : the weight of the gimbals' rates that
    turn the cabin not at all, near the inner gimbal's lock (:attr:`~desdemona.cueing.formulation.ProblemOptions.null_weight`;
    None: its on-line default with the real-time iteration, where the spin was found, and 0 with IPOPT,
    whose thesis-timing rows of ``benchmarks/online.py`` it moved by up to 12 %, docs/benchmarks/gimbals-lock.md);
    spin_up : fraction of the yaw's acceleration limit with which a still yaw is seeded (:meth:`MPC._leave_rest`), 0: off.

    rti_step : the share of each real-time iteration's QP step taken from the previous plan
    (:class:`~desdemona.cueing.realtime_iteration.RealTimeIteration`; 1 from a fresh seed); None: 0.5 where the cabin
    turns about the vertical but cannot tilt (``yaw-track-cabin``), else 1. The Gauss-Newton model
    leaves out the curvature of large residuals: where a sustained force is out of reach, turning the
    small force the arm can hold towards it overshoots, and one full step a cycle swings the plan from
    one side of the optimum to the other, cycle after cycle. A cabin that tilts reaches most sustained
    forces with gravity; there (``full``), as on ``dfs`` and ``yaw-track``, the plan hardly swings,
    and half steps lagged a fast target or led the plan, now and then, to a QP without a solution
    (docs/benchmarks/damped-real-time-iteration.md).

    tail_step : the plan's step [s] beyond the first ``fine`` seconds of the horizon (None: ``step``
    throughout), twice as long beyond ``far`` seconds (None: ``tail_step`` to the end; "auto":
    :data:`desdemona.control.mpc.FAR` where the cabin tilts, as on ``full``, else to the end): what the plan does in a second
    matters only through where it leaves the machine, and it is re-planned long before then
    (docs/benchmarks/coarse-tail-of-the-plan.md). On ``yaw-track-cabin``, whose cycle is short anyway, the damped
    iteration swung the yaw of a steady turn with the doubled tail (1.17 reversals a second against 0.04).
    fine_step : the plan's step [s] over the first ``fine`` seconds after the first re-plan period and
    one step more, rounded to whole steps (None: ``step``): at 100 Hz (``step`` 0.01) a 2 s plan has 37
    intervals instead of 56, the felt force within 1 % on the corpus (docs/benchmarks/fine-part-of-the-plan.md).

    reach : how far each plan looks [s], at least ``horizon`` (None: the horizon). Beyond the horizon,
    where nothing is known, the desired path is taken as held at its last previewed value: an end cost
    (eq. 3.8's K) that prices where the plan leaves the machine by what holding the path would cost from
    there; a short horizon needs it where the machine takes longer than the horizon to get where a cue
    wants it (docs/benchmarks/reach-beyond-the-horizon.md). The thesis takes K = 0 for the dfs (7.3). A session reaches
    at least :func:`default_horizon` (:func:`desdemona.runs.session.online`).
    """

    horizon: float = 2.0
    step: float = 0.02
    replan: float | None = None
    delay: bool = False
    deadline: float | None = None
    substeps: int = 1
    regularisation: float = 1e-4
    margin: float = 1e-3
    braking: float = 0.5
    weights: tuple[float, ...] | None = None
    max_iter: int = 100
    method: Literal["auto", "rti", "nlp"] = "auto"
    qp_solver: str = "hpipm"
    perception: VestibularModel | None = None
    spin_up: float = 0.2
    rti_step: float | None = None
    tail_step: float | None = 0.1
    fine: float = 0.4
    fine_step: float | None = 0.02
    far: float | Literal["auto"] | None = "auto"
    jerk_weight: float | None = None
    reach: float | None = None
    rotation_band: float | None = None
    rotation_ceiling: float | None = None
    null_weight: float | None = None
    wall: float = 0.0
    spin_weight: float = 0.0
    head_movement_weight: float = 0.0  # as ProblemOptions'

    def __post_init__(self):
        if self.method not in ("auto", "rti", "nlp"):
            raise ValueError(f"method {self.method!r}: one of auto, rti, nlp")
        if not (self.step > 0 and self.horizon >= 2 * self.step):
            raise ValueError(f"need step > 0 and horizon >= 2 steps, got step {self.step}, horizon {self.horizon}")
        r = self.period / self.step
        if not (abs(r - round(r)) < 1e-9 and 1 <= round(r) and self.period <= self.horizon - self.step):
            raise ValueError(f"replan = {self.replan}: the re-plan period must be a whole number of steps "
                             f"({self.step:g} s) and shorter than the horizon ({self.horizon:g} s)")
        if self.rti_step is not None and not 0.0 < self.rti_step <= 1.0:
            raise ValueError(f"rti_step = {self.rti_step}: the share of the QP's step, in (0, 1]")
        if self.far not in ("auto", None) and not (isinstance(self.far, (int, float)) and self.far >= 0.0):
            raise ValueError(f"far = {self.far!r}: where the tail's intervals double [s], at least 0, "
                             f"or 'auto' or None")
        if self.reach is not None and not self.reach >= self.horizon:
            raise ValueError(f"reach = {self.reach}: must be at least the horizon ({self.horizon:g} s)")

    @property
    def length(self) -> float:
        """How far each plan looks [s]: the reach, or the horizon."""
        return self.horizon if self.reach is None else self.reach

    @property
    def period(self) -> float:
        """T_c [s]: the time between two plans."""
        return self.step if self.replan is None else self.replan

    @property
    def plan_method(self) -> str:
        """The method each plan is solved by: ``method``, or for "auto" the real-time iteration when a
        plan is made every step and IPOPT to convergence when the re-plan period spans several steps.

        One Gauss-Newton QP per plan is enough when plans follow each other step by step, each
        linearised at the last; with a long period the plan moves far between two QPs, and the thesis
        uses its T_c to solve to convergence (7.5) (docs/benchmarks/plan-method-real-time-iteration-or-ipopt.md)."""
        if self.method != "auto":
            return self.method
        return "rti" if self.replan_steps == 1 else "nlp"

    @property
    def replan_steps(self) -> int:
        """Steps of a plan applied before the next plan takes over."""
        return int(round(self.period / self.step))

    def grid(self) -> np.ndarray:
        """The plan's interval lengths [s] over its :attr:`length`, each a whole number of steps:
        ``step`` over the re-plan period and one step more, then ``fine_step`` to ``fine`` seconds, then
        ``tail_step`` rounded to whole steps, from ``far`` seconds on twice that (the last interval
        shorter where the plan ends; "auto" as None here: the controller resolves it for its
        configuration, :class:`MPC`); uniform with a perception model whose channels are of higher
        order than one (:attr:`~desdemona.occupant.perception.VestibularModel.diagonal`). The 4 s plans of ``full``
        have 46 intervals instead of 56 with ``tail_step`` to the end: the QP's work falls, the felt force
        stays within 1 % on the built-in paths and moves either way on real ones (docs/benchmarks/coarse-tail-of-the-plan.md)."""
        total = int(round(self.length / self.step))
        block = 1 if self.tail_step is None else int(round(self.tail_step / self.step))
        if block <= 1 or (self.perception is not None and not self.perception.diagonal):
            return np.full(total, self.step)
        first = min(total, self.replan_steps + 1)
        fine = min(total, max(int(round(self.fine / self.step)), first))
        far = total if self.far in (None, "auto") else int(round(self.far / self.step))
        fine_block = 1 if self.fine_step is None else max(1, int(round(self.fine_step / self.step)))
        sizes, start = [1] * first, first
        while start < total:
            size = fine_block if start < fine else (block if start < far else 2 * block)
            sizes.append(min(size, (fine if start < fine else total) - start))
            start += sizes[-1]
        return self.step * np.array(sizes, dtype=float)

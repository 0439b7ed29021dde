"""The optimal cueing problem: its cost and limits, one control interval at a time (thesis 3.4, 4.1, 4.2, chapters 5-7).

Find joint accelerations qdd(t) of the free joints such that the path S felt in the cabin follows the
desired S_d::

    min  1/T int_0^T (S - S_d)^T Q (S - S_d) dt  +  rho/T int_0^T sum_i (qdd_i / qdd_max,i)^2 dt
    s.t. every limit of eq. 3.3-3.5 / 4.2 on the free joints,

or, for the ``dfs`` configuration, the modulus error (M - M_d)^2 of eq. 7.3; with a perception model
(chapter 6) the error is taken between the *perceived* S and S_d.

Transcription (:mod:`desdemona.cueing.transcription`, :mod:`desdemona.cueing.assembly`): direct multiple shooting on a
control grid h_u (thesis 4.2, 5.3). On a machine with jerk limits (every built-in one but the thesis' toy
set) the states are (q, qd, qdd) of the free joints and the controls their jerks j, held constant per
interval: the accelerations are continuous and piecewise linear, and |j| <= j_max holds everywhere. Without
jerk limits (the thesis' setting) the states are (q, qd) and the controls qdd, held constant per interval.
Either way the state equation is a chain of integrators, whose solution over an interval is exact in closed
form, q(t) = q_k + qd_k t + qdd_k t^2 / 2 + j_k t^3 / 6. The gap constraints are therefore *linear* and
exact: no integration error at all, the nonlinearity sits where it belongs, in S and in the torque and power
limits (tau from inverse dynamics, eq. A.26). We chose multiple shooting over collocation because of this:
collocation would add variables to approximate a trajectory that is known exactly. With a perception model
the filter states join (q, qd) and advance by the exact zero-order-hold discretisation of
:mod:`desdemona.occupant.perception` on each sub-step.

Each control interval is divided into ``substeps`` sub-steps (by default the sample step of S_d). The
cost is integrated on them (trapezoid rule on the one-sided values inside the interval, so the jump of
S where qdd jumps is respected) and every limit is enforced on them: positions (quadratic in t) at each
sub-step point, backed off by qdd_max h^2 / 8, which bounds the bulge between two points, so position
limits hold for all t; accelerations are linear in t (or constant), so bounds at the nodes hold for all
t; velocities are quadratic in t (or linear), and their bounds at the nodes are backed off by
j_max h_u^2 / 8, the bulge of such a parabola; jerks are bounds on the controls; torques and power are enforced at every sub-step point with a small relative back-off
(``margin``), and the independent check of :mod:`desdemona.check.simulate` verifies them on a 10x finer grid.

Regularisation ``rho``: a full-scale joint acceleration held for the whole path costs rho (m/s^2)^2,
equivalent to an RMS error of sqrt(rho); the default 1e-4 (0.01 m/s^2, well below the 0.17 m/s^2
perception threshold) never trades a felt cue for effort, but removes the flat directions of the
cost (joints that do not change S in the weighted channels), which makes the Hessian regular and the
optimum unique. With jerk limits the jerk has a weight of its own against its limit
(``ProblemOptions.jerk_weight``), so that a plan does not swing its accelerations where the cue gains
little from it. A session adds a smooth wall before the position limits (``ProblemOptions.wall``).
"""

from __future__ import annotations

import itertools
import math
from dataclasses import dataclass
from typing import Literal

import casadi as ca
import numpy as np

from desdemona.machine.kinematics import gimbal_null_rate
from desdemona.machine.model import Model
from desdemona.machine.plan import STOP_EPS, STOP_LAG, advance, settled_rate, settled_rates, stopping_reach
from desdemona.occupant.perception import VestibularModel
from desdemona.profiles import DesiredPath

#: How much more a felt rotation beyond :attr:`ProblemOptions.rotation_band` (``rotation_ceiling``)
#: weighs, on top of its weight: this many times it (docs/benchmarks/felt-rotation-band.md, docs/benchmarks/felt-rotation-ceiling.md).
BAND_WEIGHT = 9.0
CEILING_WEIGHT = 100.0
#: On-line on ``dfs``, the weight of the gimbals' motion that turns the cabin not at all near the inner
#: gimbal's lock (:attr:`ProblemOptions.null_weight`, docs/benchmarks/gimbals-lock.md).
NULL_WEIGHT = 0.1
#: The most entries of the linear map through which a controller perceives its horizon
#: (:meth:`Formulation.perceive`): 16 MB; a longer horizon is perceived step by step.
PERCEPTION_MAP_SIZE = 2_000_000
#: The off-line cost's wall before each position limit (:attr:`ProblemOptions.wall`): its width, as a
#: share of the joint's travel, and what it costs at the limit, as a felt error [m/s^2].
WALL_WIDTH, WALL = 0.005, 1.0


@dataclass(frozen=True)
class ProblemOptions:
    """How to pose and solve the cueing problem. The measurements behind the defaults are in
    docs/benchmarks/index.md#design-decisions-and-the-measurements, one page each (cited
    below).

    h_u : control step [s] (thesis h_qdd, section 5.3).
    steps : the intervals' lengths [s] where the grid is not uniform (an on-line horizon fine near now
        and coarse further on), None for ``h_u`` throughout; with a perception model only where its
        channels are of first order at most (:attr:`~desdemona.occupant.perception.VestibularModel.diagonal`),
        whose discretisation has a closed form in the step.
    substeps : sub-steps per control interval for cost and limits. Two are enough where S_d is smooth
        on the scale of h_u (docs/benchmarks/sub-steps.md).
    initial : "free" (optimised, section 5.2), "rest" (at rest, position free; on ``dfs`` at home, the
        cabin level) or "given" (``initial_state``).
    initial_state : (q0, qd0) of the free joints when initial == "given".
    final : "none", "rest" (qd = 0 at the end) or "centre" (at rest with the track and heave centred).
    perception : None, or the vestibular model (:mod:`desdemona.occupant.perception`) through which the
        difference is perceived.
    weights : diagonal of Q (6,), None for the path's own.
    regularisation : rho, see the module docstring.
    margin : relative back-off of torque and power limits inside the optimiser.
    solver : "ipopt" or "fatrop"; max_iter, tol : solver stopping criteria.
    initial_filter : with perception, the filters start in the steady state of the first S ("steady",
        off-line) or in a state the caller fixes through the bounds of x0 ("given", on-line).
    stoppable : every planned state must be able to brake to rest within the position limits at
        ``braking`` times the acceleration limit (the on-line end condition of chapter 7, here at every
        node so that any shifted plan ends stoppable too).
    brake_step : the step [s] of a controller's brake that takes over from a plan (on-line): the
        stopping rows then also carry the brake's lag (:func:`~desdemona.machine.plan.stopping_reach`'s
        ``lag``, :data:`~desdemona.machine.plan.STOP_LAG` x A h^2), so that a plan that keeps them passes the
        controller's check (:func:`~desdemona.machine.plan.stopping_extent`). None: no lag (off-line).
    expand : evaluate the NLP as one flat SX graph (fast to evaluate, slow to build); None chooses:
        flat when the problem will be solved EXPAND_SOLVES times or more and is below EXPAND_LIMIT.
    limit_curvature : put the second derivatives of the torque and power limits into IPOPT's Hessian.
        They are almost all of the Hessian's operations on ``full`` and change neither the optimum nor,
        measured, the iteration count: None leaves them out of IPOPT's on more than three joints
        (docs/benchmarks/limit-curvature.md); fatrop keeps them (without, it takes up to twice the iterations on
        ``full``). Every other term (cost, gaps, positions, braking) stays exact.
    jerk_weight : the rho of the jerk, against j_max (with jerk limits): a plan that used the whole
        jerk limit all the time would pay as much as sqrt(rho) m/s^2 of RMS error. It keeps the joints
        from reversing their accelerations where the cue gains little from it. None:
        :func:`default_jerk_weight`.
    unweighted : weight of the channels of S that Q leaves at zero, in the cost only (RMS figures keep
        Q). With it, joints that move only unweighted channels (on ``full``, the gimbals turning the
        cabin about the felt force) stop being flat directions of the cost. None: 0.003 on
        configurations of more than three joints, 0 otherwise; on-line (``parametric``) 0.01: one QP
        per cycle, linearised at the last plan, suffers more from flat directions (docs/benchmarks/unweighted-channels.md).
    compile : evaluate the stages' functions compiled to machine code, kept in a cache on disk
        (:mod:`desdemona.cueing.compiled`; the results are the same, about six times faster to evaluate).
        None: where the interpreted evaluation would take long (``COMPILE_WORK``) or the library is
        already cached; with fatrop always, the NLP's functions too. Never with ``expand``, nor on-line.
    gauss_newton_first : IPOPT starts with the cost's Gauss-Newton Hessian (2 J_r^T J_r, positive
        semi-definite; the constraints keep their curvature) and, at a rough tolerance, finishes with
        the exact Hessian from where it got (its multipliers kept). Far from the optimum the exact
        Hessian of the ``dfs`` modulus cost is indefinite, and its corrected steps crawl; near it
        Gauss-Newton converges only linearly where the target is out of reach. None: on the
        configurations that follow the modulus, `dfs` and `dfs-yaw` (docs/benchmarks/gauss-newton-first.md).
    wall : a smooth wall in the cost over the last ``WALL_WIDTH`` of each bounded joint's travel at
        either end: ``wall * (depth / width)^2`` [m/s^2], weighed like a felt error of weight 1, so
        ``wall`` at the limit itself. The limit stays a constraint; the wall keeps the optimum off it.
        With the jerk as the control a position limit is a third-order state constraint, which an
        optimum meets at isolated touch points rather than along an arc; on real recordings the
        track grazed its end there and IPOPT's dual infeasibility stayed at that one node for hundreds
        of iterations (docs/benchmarks/wall-before-the-position-limits.md). 0 (the default): none, the thesis'
        formulation; a session (:func:`desdemona.runs.session.offline`, :func:`desdemona.runs.session.online`)
        takes ``WALL``: on-line, a track parked against its end dithered there without it.
    rotation_band : with a perception model, a felt rotation beyond this many perception thresholds of
        its canal channel (either way) costs :data:`BAND_WEIGHT` times its weight more, on the excess: a
        plan may use a rotation the occupant hardly feels (the arm's slow spin-up, a tilt below the
        threshold) and pays steeply for one they would (docs/benchmarks/felt-rotation-band.md). None: no band.
        ``rotation_ceiling``, the same with :data:`CEILING_WEIGHT` on top: the arm spins up no faster
        than felt as that much rotation (docs/benchmarks/felt-rotation-ceiling.md).
    null_weight : where the three gimbals are free, the weight of their rates that turn the cabin not at
        all: at the inner gimbal's lock (q5 = +-90 deg) the outer gimbal and the cabin turning against
        each other (:func:`~desdemona.machine.kinematics.gimbal_null_rate`), a motion no channel of S sees. Without it a controller's
        plans let that motion run up to the joints' rate limit (the outer gimbal at 180 deg/s and
        6 kW on a recorded sortie on ``dfs``). None: :data:`NULL_WEIGHT` on-line (``parametric``) on the
        configurations whose cabin follows the force (``dfs``), else 0 (docs/benchmarks/gimbals-lock.md).
    spin_weight : with a perception model, the weight of the spin about the occupant's vertical as it is
        (against none), as a share of its channel's: a steady spin the canals no longer feel still costs
        (docs/benchmarks/a-steady-spin-of-the-cabin-on-dfs.md). 0: none; a session takes :data:`~desdemona.runs.session.SPIN_WEIGHT` on ``dfs``.
    """

    h_u: float = 0.05
    substeps: int = 2
    initial: Literal["free", "rest", "given"] = "free"
    initial_state: tuple | None = None
    final: Literal["none", "rest", "centre"] = "none"
    perception: VestibularModel | None = None
    weights: tuple[float, ...] | None = None
    regularisation: float = 1e-4
    margin: float = 1e-3
    solver: Literal["ipopt", "fatrop"] = "ipopt"
    max_iter: int = 500
    tol: float = 1e-8
    expand: bool | None = None
    stoppable: bool = False
    braking: float = 0.5
    brake_step: float | None = None
    initial_filter: Literal["steady", "given"] = "steady"
    limit_curvature: bool | None = None
    unweighted: float | None = None
    jerk_weight: float | None = None
    steps: tuple[float, ...] | None = None
    compile: bool | None = None
    gauss_newton_first: bool | None = None
    wall: float = 0.0
    rotation_band: float | None = None
    rotation_ceiling: float | None = None
    null_weight: float | None = None
    spin_weight: float = 0.0
    head_movement_weight: float = 0.0  # on the cabin's angular velocity in space, where a head may move (occupant.coriolis)

    def __post_init__(self):
        if not (math.isfinite(self.h_u) and self.h_u > 0):
            raise ValueError(f"h_u = {self.h_u!r}: the control step must be a positive number of seconds")
        if self.brake_step is not None and not (math.isfinite(self.brake_step) and self.brake_step > 0):
            raise ValueError(f"brake_step = {self.brake_step!r}: a positive number of seconds, or None")
        if self.substeps < 1:
            raise ValueError(f"substeps = {self.substeps!r}: must be >= 1")
        for name, value, allowed in (("initial", self.initial, ("free", "rest", "given")),
                                     ("final", self.final, ("none", "rest", "centre")),
                                     ("solver", self.solver, ("ipopt", "fatrop"))):
            if value not in allowed:
                raise ValueError(f"{name} = {value!r}: must be one of {', '.join(allowed)}")
        if self.steps is not None and not all(math.isfinite(h) and h > 0 for h in self.steps):
            raise ValueError("steps: every interval must last a positive number of seconds")
        if (self.steps is not None and self.perception is not None and not self.perception.diagonal
                and max(self.steps) - min(self.steps) > 1e-12):
            raise ValueError(f"steps: perception model {self.perception.name!r} has channels of higher order "
                             f"than one and needs a uniform grid")
        if self.initial == "given" and self.initial_state is None:
            raise ValueError("initial = 'given' needs initial_state = (q0, qd0)")
        for name in ("wall", "spin_weight", "head_movement_weight", "unweighted", "null_weight", "rotation_band", "rotation_ceiling"):
            value = getattr(self, name)  # the last four: None for none
            if (value is not None or name in ("wall", "spin_weight", "head_movement_weight")) and not (math.isfinite(value) and value >= 0):
                raise ValueError(f"{name} = {value!r}: must be a number >= 0")
            if name.startswith("rotation") and value is not None and self.perception is None:
                raise ValueError(f"{name} = {value!r}: needs a perception model (it is on the felt rotation)")
        if self.spin_weight and self.perception is None:
            raise ValueError(f"spin_weight = {self.spin_weight!r}: needs a perception model (without one the "
                             f"rotation is weighed as it is)")
        if not (self.regularisation >= 0 and 0 <= self.margin < 0.5):
            raise ValueError("regularisation must be >= 0 and margin in [0, 0.5)")


def default_jerk_weight(config, online: bool = False) -> float:
    """The jerk's weight (:attr:`ProblemOptions.jerk_weight`) unless a session sets it: 1, and on a
    configuration whose cabin follows the force (``dfs``) 5 off-line and 3 on-line. There the arm and
    gimbals swing the force's direction and would reverse their accelerations often for little cue;
    a controller that sees only its horizon pays for every hesitation, so it is weighted less than
    the off-line plan, which sees the whole path (docs/benchmarks/off-line-jerk-weight.md, docs/benchmarks/on-line-jerk-weight.md)."""
    if not config.aligned:
        return 1.0
    return 3.0 if online else 5.0


@dataclass(frozen=True, eq=False)
class Family:
    """One family of path constraints of a stage: lower <= expression <= upper, elementwise."""

    name: str
    expression: ca.SX
    lower: np.ndarray
    upper: np.ndarray


class Formulation:
    """The cueing problem of one model, desired path and set of options, as functions of one control
    interval (the stage) and the data each interval takes; :class:`desdemona.cueing.transcription.CueingProblem`
    transcribes it into an NLP and solves it."""

    def __init__(self, model: Model, path: DesiredPath, options: ProblemOptions = ProblemOptions(),
                 parametric: bool = False):
        self.parametric = parametric
        path = model.config.cue_path(path)
        self.model, self.path, self.options = model, path, options
        self.modulus = model.config.modulus_cost
        if not self.modulus and path.S_d is None:
            raise ValueError(f"configuration {model.config.name!r} needs a full path S_d; "
                             f"path {path.name!r} gives only the modulus")
        if self.modulus and options.perception is not None:
            raise ValueError("a perception model applies to the full path S, not to the dfs modulus")
        h_u = options.h_u
        if options.steps is None:
            self.N = max(1, int(round(path.duration / h_u)))
            self.steps = np.full(self.N, h_u)
        else:
            self.steps = np.asarray(options.steps, dtype=float)
            self.N = len(self.steps)
        self.t_nodes = path.t[0] + np.r_[0.0, np.cumsum(self.steps)]
        self.m = options.substeps
        self.h_sub = float(self.steps.max()) / self.m  # the longest sub-step: what back-offs allow for
        # The sub-step points, as fractions of an interval. With continuous accelerations an interval's
        # end is the next one's start, with the same S, torques and power: the stages leave it out (a
        # third of the work with two sub-steps), and an off-line problem costs and limits its last
        # node in a terminal stage of its own. Without jerk limits the acceleration jumps at the
        # nodes, and each interval keeps its own end.
        self.smooth = model.limits.smooth
        self.fractions = np.arange(self.m + (0 if self.smooth else 1)) / self.m
        self.terminal_stage = self.smooth and not parametric
        self.weights = np.array(options.weights if options.weights is not None else path.weights, float)
        large = model.n > 3  # see ProblemOptions.limit_curvature and .unweighted
        floor = options.unweighted if options.unweighted is not None else (
            (0.01 if parametric else 0.003) if large else 0.0)
        self.cost_weights = np.where(self.weights > 0, self.weights, floor)
        self.limit_curvature = options.limit_curvature if options.limit_curvature is not None else not (
            large and options.solver == "ipopt")
        self.jerk_weight = options.jerk_weight if options.jerk_weight is not None else default_jerk_weight(
            model.config, online=parametric)
        self.null_weight = options.null_weight if options.null_weight is not None else (
            NULL_WEIGHT if parametric and model.config.aligned else 0.0)
        self.vestibular = options.perception
        # the filters over the first interval's sub-steps (a controller's cycle); on a grid that varies
        # the stages discretise them for their own step (VestibularModel.casadi_discrete)
        self.filter = self.vestibular.discretize(float(self.steps[0]) / self.m) if self.vestibular else None
        self.uniform = bool(np.ptp(self.steps) <= 1e-12)
        self.nz = self.vestibular.n_states if self.vestibular else 0
        self._perceive_map = None  # built on the first call of perceive
        n = model.n
        self.n_motion = (3 if self.smooth else 2) * n  # (q, qd[, qdd]) lead the state, filters follow
        self.nx, self.nu = self.n_motion + self.nz, n
        self.stage, self.residual, self.families = self._stage_functions()
        self.terminal = self._terminal_function()

    # ------------------------------------------------------------------------------------------
    # data on the sub-step grid

    def sub_times(self) -> np.ndarray:
        """(N, P) absolute times of every interval's sub-step points (P = m + 1, or m without the end)."""
        return self.t_nodes[:-1, None] + self.steps[:, None] * self.fractions[None, :]

    def stage_data(self) -> np.ndarray:
        """(nd, N) what each interval's stage function takes (:meth:`with_steps`)."""
        times = self.sub_times()
        if self.modulus:
            return self.with_steps(self.path.sample_modulus(times).T)  # (P, N)
        S_d = self.path.sample(times.ravel()).reshape(self.N, len(self.fractions), 6)
        if self.vestibular is None:
            return self.with_steps(S_d.reshape(self.N, -1).T)  # column k: S_d at the points of interval k
        # perceived desired path, from the steady state of its first sample, held over each sub-step
        y_d = self.perceive(S_d[:, :self.m, :].reshape(-1, 6))[0]
        return self.with_steps(y_d.reshape(self.N, -1).T)

    def perceive(self, S, z0=None) -> tuple[np.ndarray, np.ndarray]:
        """Through the perception model, S (N m, 6) held over each sub-step of the grid in turn:
        the perceived path (N m, 6) and the filter states (N m + 1, nz), from ``z0`` (default the
        steady state of S[0]). A controller's horizon, perceived anew every cycle, goes through one
        linear map built on the first call (:meth:`_perception_map`, up to :data:`PERCEPTION_MAP_SIZE`
        entries); otherwise a grid that varies is taken a run of equal intervals at a time."""
        S = np.asarray(S, dtype=float)
        z = self.filter.steady_state(S[0]) if z0 is None else np.asarray(z0, dtype=float)
        rows = self.N * self.m
        if self.parametric and (rows + 1) * self.nz * (self.nz + 6 * rows) <= PERCEPTION_MAP_SIZE:
            if self._perceive_map is None:
                self._perceive_map = self._perception_map()
            states = (self._perceive_map @ np.concatenate([z, S.ravel()])).reshape(-1, self.nz)
            return states[:-1] @ self.filter.C.T + S @ self.filter.D.T, states
        outputs, states, start = [], [z[None, :]], 0
        for step, run in itertools.groupby(self.steps.tolist()):
            stop = start + self.m * len(list(run))
            y, x = self.vestibular.discretize(step / self.m).simulate(S[start:stop], states[-1][-1])
            outputs.append(y)
            states.append(x[1:])
            start = stop
        return np.vstack(outputs), np.vstack(states)

    def _perception_map(self) -> np.ndarray:
        """((N m + 1) nz, nz + 6 N m) the filter states of :meth:`perceive` as one linear map of
        (z0, S flattened by rows): a controller perceives each cycle's horizon in one product."""
        nz, rows = self.nz, self.N * self.m
        M = np.zeros(((rows + 1) * nz, nz + 6 * rows))
        M[:nz, :nz] = np.eye(nz)
        k = 0
        for step in self.steps:
            system = self.vestibular.discretize(float(step) / self.m)
            for _ in range(self.m):
                M[(k + 1) * nz:(k + 2) * nz] = system.Ad @ M[k * nz:(k + 1) * nz]
                M[(k + 1) * nz:(k + 2) * nz, nz + 6 * k:nz + 6 * (k + 1)] += system.Bd
                k += 1
        return M

    @property
    def n_head(self) -> int:
        """Rows of a stage's data before its desired values (:meth:`with_steps`)."""
        return 3 if self.modulus else 9

    def with_steps(self, values) -> np.ndarray:
        """(n_head + nd, N) the stages' data: the intervals' lengths, their first points' weights,
        1 / T and the square roots of the weights of S (not for a modulus), above the desired values
        (nd, N). What depends on the path is data, so that the stage functions depend only on the
        machine, the configuration and the options, and a compiled library serves every path
        (:mod:`desdemona.cueing.compiled`).

        The first point's weight scales the first sub-step point's share h_k / m of the cost. Where the
        stages leave their ends out, an off-line problem makes the sum over the stages and the terminal stage the
        trapezoid rule on the whole grid: a node between intervals of lengths h_(k-1) and h_k weighs
        (h_(k-1) + h_k) / (2 m), the first one h_0 / (2 m). On-line the first point is the fixed
        present, and the left-point rule is kept (weights 1).
        """
        first = np.ones(self.N)
        if self.terminal_stage:
            first[0] = 0.5
            first[1:] = 0.5 * (self.steps[:-1] + self.steps[1:]) / self.steps[1:]
        head = [self.steps, first, np.full(self.N, 1.0 / self.path.duration)]
        if not self.modulus:
            head += list(np.repeat(np.sqrt(self.cost_weights)[:, None], self.N, axis=1))
        return np.vstack([np.vstack(head), values])

    # ------------------------------------------------------------------------------------------
    # the stage: one control interval

    @property
    def n_path(self) -> int:
        """Path constraints per stage: the rows of every family."""
        return sum(f.expression.numel() for f in self.families)

    def _stage_functions(self) -> tuple[ca.Function, ca.Function, list[Family]]:
        """One control interval: ``stage(x, u, d) -> (x_next, L, g)`` (the next node state, the stage
        cost and the path constraints), ``residual(x, u, d) -> r`` (the cost is sum(r^2)) and the
        constraint families that make up g, in order.

        The motion at the sub-step points is exact (:func:`desdemona.machine.plan.advance`); there the cue
        (S, or the modulus against its desired value) and the torques are evaluated once, and shared by
        the cost (:meth:`_residuals`) and the constraint families (:meth:`_families`).
        """
        n = self.model.n
        x, u = ca.SX.sym("x", self.nx), ca.SX.sym("u", self.nu)
        q, qd = x[:n], x[n:2 * n]
        a, jerk = (x[2 * n:3 * n], u) if self.smooth else (u, None)
        points = len(self.fractions)
        nd = points if self.modulus else (self.m * 6 if self.vestibular else points * 6)
        data = ca.SX.sym("d", self.n_head + nd)  # see with_steps
        h_u, d = data[0], data[self.n_head:]
        q_next, qd_next = advance(q, qd, a, h_u, jerk)
        positions, values, efforts, powers, motions = [], [], [], [], []
        for j, fraction in enumerate(self.fractions):
            tj = fraction * h_u
            qj, qdj = advance(q, qd, a, tj, jerk)
            aj = a + jerk * tj if self.smooth else a
            value, effort, power = self._at_point(qj, qdj, aj)
            values.append(value - d[j] if self.modulus else value)
            efforts.append(effort)
            powers.append(power)
            positions.append(qj)
            motions.append((qj, qdj, aj))
        residuals, z_next = self._residuals(values, a, jerk, x[self.n_motion:], data, positions)
        null = gimbal_null_rate(q, qd, self.model.config.gimbals)
        if null is not None and self.null_weight > 0:
            residuals.append(ca.sqrt(self.null_weight * h_u * data[2]) * null)
        residuals += [ca.sqrt(self.options.head_movement_weight * h_u * data[2] / points) * self.model.functions["S"](*m)[:3] for m in motions if self.options.head_movement_weight]
        r = ca.vertcat(*residuals)
        residual = ca.Function("stage_residual", [x, u, data], [r], ["x", "u", "d"], ["r"])
        a_next = a + jerk * h_u if self.smooth else None
        families = self._families(positions, efforts, powers, q_next, qd_next, a_next)
        g = ca.vertcat(*[f.expression for f in families])
        x_next = ca.vertcat(q_next, qd_next, *([a_next] if self.smooth else []), z_next)
        stage = ca.Function("stage", [x, u, data], [x_next, ca.sumsqr(r), g], ["x", "u", "d"], ["x_next", "L", "g"])
        return stage, residual, families

    def _terminal_function(self) -> ca.Function | None:
        """The last node of an off-line problem whose stages leave their ends out (:attr:`fractions`):
        ``terminal(x, d) -> (L, g)``, its share h / (2 m) of the trapezoid rule and its torques and powers
        within their limits, ``d`` from :meth:`terminal_data`. With a perception model the zero-order hold
        ends with the last interval, and the node is only limited. None where the stages keep their ends."""
        if not self.terminal_stage:
            return None
        n, x, d = self.model.n, ca.SX.sym("x", self.nx), ca.SX.sym("d", self.terminal_data().size)
        value, effort, power = self._at_point(x[:n], x[n:2 * n], x[2 * n:3 * n])
        weight = 1.0 if self.modulus else ca.DM(np.sqrt(self.cost_weights))
        residual = ca.SX(0, 1) if self.vestibular is not None else d[0] * weight * (value - d[1:])
        return ca.Function("terminal", [x, d], [ca.sumsqr(residual), ca.vertcat(effort, power)], ["x", "d"], ["L", "g"])

    def terminal_data(self) -> np.ndarray:
        """What the terminal stage takes of the path: its share of the trapezoid rule, then the desired
        value at the end (the modulus, or S; nothing with a perception model)."""
        share, end = math.sqrt(0.5 * self.steps[-1] / (self.m * self.path.duration)), self.t_nodes[-1:]
        desired = [] if self.vestibular is not None else (self.path.sample_modulus if self.modulus else self.path.sample)(end)[0]
        return np.r_[share, desired]

    def _at_point(self, q, qd, a) -> tuple[ca.SX, ca.SX, ca.SX]:
        """At one point of the motion: the cue (S, or the modulus M), and the torques and powers
        over their limits less ``margin``."""
        fn, lim, margin = self.model.functions, self.model.limits, 1.0 - self.options.margin
        tau = fn["tau"](q, qd, a)
        value = fn["modulus"](q, qd, a) if self.modulus else fn["S"](q, qd, a)
        return value, tau / ca.DM(lim.effort * margin), tau * qd / ca.DM(lim.power * margin)

    def _residuals(self, values, a, jerk, z, data, positions) -> tuple[list, ca.SX]:
        """The stage's cost as squared residuals, and the filter states at its end.

        values, positions : per sub-step point, S (full paths) or M - M_d (modulus paths), and the
        joints' positions (for the wall, :attr:`ProblemOptions.wall`). A sum of squared
        residuals (trapezoid rule, or zero-order hold with perception), so that a Gauss-Newton
        Hessian can be formed from the same definition (see :mod:`desdemona.control.online`). ``data``:
        the stage's, :meth:`with_steps`.
        """
        m, points, lim, o = self.m, len(self.fractions), self.model.limits, self.options
        h_u, first, inv_T, root_w, d = data[0], data[1], data[2], data[3:self.n_head], data[self.n_head:]
        # times the interval's length h_u: the trapezoid rule with the end, or the points up to the
        # end, the first one weighed by ``first``
        trapezoid = [1.0 / m] * points
        if points == m + 1:
            trapezoid[0] = trapezoid[-1] = 0.5 / m
        else:
            trapezoid[0] = first / m
        if self.modulus:
            residuals = [ca.sqrt(trapezoid[j] * h_u * inv_T) * values[j] for j in range(points)]
        elif self.vestibular is None:
            residuals = [ca.sqrt(trapezoid[j] * h_u * inv_T) * root_w * (values[j] - d[6 * j: 6 * j + 6])
                         for j in range(points)]
        else:
            A, B = ((ca.DM(self.filter.Ad), ca.DM(self.filter.Bd)) if self.uniform
                    else self.vestibular.casadi_discrete(h_u / m))
            C, D = ca.DM(self.filter.C), ca.DM(self.filter.D)
            residuals = []
            bands = [(ca.DM(band * np.asarray(self.vestibular.thresholds[:3])), weight) for band, weight in
                     ((o.rotation_band, BAND_WEIGHT), (o.rotation_ceiling, CEILING_WEIGHT)) if band is not None]
            for j in range(m):  # zero-order hold of S over each sub-step
                error = C @ z + D @ values[j] - d[6 * j: 6 * j + 6]  # felt less what should be felt
                residuals.append(ca.sqrt(h_u / m * inv_T) * root_w * error)
                for width, weight in bands:  # the felt rotation's error beyond the band (the ceiling), again
                    beyond = ca.fmax(error[:3] - width, 0.0) + ca.fmin(error[:3] + width, 0.0)
                    residuals.append(ca.sqrt(weight * h_u / m * inv_T) * root_w[:3] * beyond)
                if o.spin_weight > 0:  # the spin about the occupant's vertical as it is, felt or not
                    residuals.append(ca.sqrt(o.spin_weight * h_u / m * inv_T) * root_w[2] * values[j][2])
                z = A @ z + B @ values[j]
        if o.wall > 0 and lim.bounded:
            residuals += [ca.sqrt(trapezoid[j] * h_u * inv_T) * self._wall(positions[j], o.wall) for j in range(points)]
        rho = o.regularisation * h_u * inv_T
        residuals.append(ca.sqrt(rho) * a / ca.DM(lim.acceleration))
        if jerk is not None:
            rho_j = self.jerk_weight * h_u * inv_T
            residuals.append(ca.sqrt(rho_j) * jerk / ca.DM(lim.jerk))
        return residuals, z

    def _wall(self, q, wall: float) -> ca.SX:
        """The residual of the wall before the position limits (:attr:`ProblemOptions.wall`) at one
        point: ``wall * (depth / width)^2`` per bounded joint, zero short of the wall."""
        lim = self.model.limits
        bounded = lim.bounded
        low, high = lim.position_min[bounded], lim.position_max[bounded]
        width = WALL_WIDTH * (high - low)
        depth = ca.fmax(0, q[bounded] - ca.DM(high - width)) + ca.fmax(0, ca.DM(low + width) - q[bounded])
        return wall * (depth / ca.DM(width)) ** 2

    def _families(self, positions, efforts, powers, q_next, qd_next, a_next=None) -> list[Family]:
        """The path constraints of one interval, family by family, each with its own bounds.

        position : bounded joints at the inner sub-step points, backed off by the bulge of a parabola
            between two points (qdd_max h^2 / 8), so they hold for all t (nodes are variable bounds);
        stopping : with ``stoppable``, where each bounded joint comes to rest braking at ``braking``
            times its acceleration limit from the interval's end (the on-line end condition, chapter 7);
            with jerk limits how far up and down the stop reaches (:func:`stopping_reach`: the
            acceleration at the end and the ramps count);
        rate : with ``stoppable`` and jerk limits, the rate each joint ends at when its acceleration
            is taken to zero at the jerk limit, qd + a |a| / 2J, within the velocity limits (the brake
            can then keep them); off-line as two convex rows (:func:`~desdemona.machine.plan.settled_rates`);
        effort, power : |tau| and |tau qd| over their limits (less ``margin``) at every sub-step point.
        Velocity and acceleration limits are bounds on the variables (linear and constant in t).
        """
        lim, o = self.model.limits, self.options
        bounded = lim.bounded
        qmin, qmax = (bound[bounded] for bound in self.position_bounds())
        families = []
        inner = [qj[bounded] for qj in positions[1:self.m]] if bounded else []
        if inner:
            families.append(Family("position", ca.vertcat(*inner), np.tile(qmin, len(inner)),
                                   np.tile(qmax, len(inner))))
        if o.stoppable and bounded:
            q_end, qd_end = q_next[bounded], qd_next[bounded]
            if self.smooth:
                A, J = ca.DM(lim.acceleration[bounded]), ca.DM(lim.jerk[bounded])
                a_end, B, lag = a_next[bounded], o.braking * A, ca.DM(self._stop_lag(bounded)) if o.brake_step else None
                up = q_end + stopping_reach(qd_end, a_end, B, J, lag=lag)
                down = q_end - stopping_reach(-qd_end, -a_end, B, J, lag=lag)
                inf = np.full(len(bounded), np.inf)
                families.append(Family("stopping", ca.vertcat(up, down), np.r_[-inf, qmin], np.r_[qmax, inf]))
            else:
                brake = ca.DM(2.0 * o.braking * lim.acceleration[bounded])
                families.append(Family("stopping", q_end + qd_end * ca.sqrt(qd_end**2 + 1e-8) / brake, qmin, qmax))
        if o.stoppable and self.smooth:  # on-line one row a joint: the QP's Hessian has no limit curvature
            J, V = ca.DM(lim.jerk), lim.velocity
            families.append(Family("rate", settled_rate(qd_next, a_next, J, eps=STOP_EPS), -V, V) if self.parametric else
                            Family("rate", ca.vertcat(*settled_rates(qd_next, a_next, J)), np.r_[-np.inf * V, -V], np.r_[V, np.inf * V]))
        for name, rows in (("effort", efforts), ("power", powers)):
            expression = ca.vertcat(*rows)
            families.append(Family(name, expression, -np.ones(expression.numel()), np.ones(expression.numel())))
        return families

    def position_bounds(self, h_sub=None) -> tuple[np.ndarray, np.ndarray]:
        """(n,) lower and upper position bounds, backed off by the largest bulge of a parabola between
        two sub-step points h_sub apart (default the longest), qdd_max h_sub^2 / 8 (unbounded joints
        stay infinite); (K, n) each for sub-steps h_sub of shape (K, 1)."""
        lim = self.model.limits
        backoff = lim.acceleration * (self.h_sub if h_sub is None else h_sub)**2 / 8.0
        return (lim.position_min + np.where(np.isfinite(lim.position_min), backoff, 0.0),
                lim.position_max - np.where(np.isfinite(lim.position_max), backoff, 0.0))

    def _stop_lag(self, joints):
        """The brake's lag [m] the stopping rows of ``joints`` carry (:attr:`ProblemOptions.brake_step`), or None."""
        h = self.options.brake_step
        return None if h is None else STOP_LAG * self.model.limits.acceleration[joints] * h * h

    def stop_overreach(self, q0, qd0, a0, qmin, qmax) -> tuple[np.ndarray, np.ndarray, np.ndarray] | None:
        """Where a start's own stop (:func:`stopping_reach` at ``braking``) lies beyond the stopping
        rows' bounds ``qmin``, ``qmax`` (n,) but within the travel: (lower, upper, ramp), the bounds
        reaching out to it and the time [s] until the acceleration can have passed the braking, |a0 ±
        B| / J, after which harder braking pulls the stop back in; None where no start lies so (or
        there are no such rows). A one-QP plan keeps the rows to first order and can leave a state a
        fraction of a millimetre beyond them, and along the strongest ramp a stop's reach stays where
        it is: no plan from that state keeps the rows at once (the catapult on ``full`` fell back 7
        cycles running). Along the ramp the smoothed reach (W+ of :func:`stopping_reach`) rises by
        sqrt(eps) / 2 a second: the bounds reach that much further, over the ramp and one second more."""
        lim, o = self.model.limits, self.options
        if not (o.stoppable and self.smooth and lim.bounded):
            return None
        B, J, lag = o.braking * lim.acceleration, lim.jerk, self._stop_lag(slice(None))
        up, down = q0 + stopping_reach(qd0, a0, B, J, lag=lag), q0 - stopping_reach(-qd0, -a0, B, J, lag=lag)
        over, under = (up > qmax) & (up <= lim.position_max), (down < qmin) & (down >= lim.position_min)
        if not (over.any() or under.any()):
            return None
        ramp = np.where(over, np.maximum(a0 + B, 0.0), np.where(under, np.maximum(B - a0, 0.0), -np.inf)) / lim.jerk
        drift = 0.5 * STOP_EPS**0.5 * (np.maximum(ramp, 0.0) + 1.0)  # the smoothed reach's rise along the ramp
        return (np.where(under, np.maximum(down - drift, lim.position_min), qmin),
                np.where(over, np.minimum(up + drift, lim.position_max), qmax), ramp)

"""The cueing problem transcribed and solved: variables, bounds, the NLP, its exact derivatives and
its solvers (thesis 4.2, 5.3; chapter 7 for the parametric, on-line form).

:class:`desdemona.cueing.formulation.Formulation` states the problem one control interval at a time. Here it
becomes an NLP by direct multiple shooting: the decision vector in stage order x0, u0, x1, u1, ...,
xN (what fatrop's structure detection expects), the gaps between intervals (linear and exact, the
motion being a chain of integrators), the path constraints of each stage, the bounds of the
variables, and the exact Jacobian and Hessian assembled stage by stage (:mod:`desdemona.cueing.assembly`).
:class:`CueingProblem` solves it off-line from a guess: IPOPT with the desired path as constants,
fatrop with the path as the NLP's parameter p, so that problems of as many intervals (the windows of
a long recording) share one solver (:data:`FATROP_SOLVERS`). A parametric problem (the path as p,
each cycle's preview) is solved from a fixed start by an on-line controller, either to convergence or by one
real-time iteration (:class:`desdemona.cueing.realtime_iteration.RealTimeIteration`): :meth:`CueingProblem.start_bounds`,
:meth:`CueingProblem.solve_from` and :meth:`CueingProblem.plan_of` are all a controller needs to
know of the layout.
"""

from __future__ import annotations

import hashlib
import time
from dataclasses import dataclass, field
from typing import NamedTuple

import casadi as ca
import numpy as np

from desdemona.cueing import assembly, blasfeo, compiled
from desdemona.cueing.formulation import Formulation, ProblemOptions
from desdemona.machine.model import Model
from desdemona.machine.plan import Plan, node_states, ramp, start_acceleration, start_state
from desdemona.profiles import DesiredPath
from desdemona.support import guard

# A flat SX graph evaluates ~4x faster than the mapped MX one but takes ~20 us per scalar operation
# of the stages to build (measured: 3.2 s for the 8 s catapult on yaw-track-cabin, 0.1 s for the 5 s
# cosine): it pays from about five solves of the same problem on, and only while it stays this small.
EXPAND_LIMIT = 400_000
EXPAND_SOLVES = 5
MAP_MODE, MAP_THREADS = assembly.MAP_MODE, assembly.MAP_THREADS
# The mapped stage functions compiled for IPOPT (desdemona.cueing.compiled), and the work (stages times the
# instructions of a stage's Jacobian) from which compiling pays by itself: on `full` a stage's Jacobian
# has about 36,000 instructions; the catapult's 160 stages of it took 27 ms per iteration interpreted
# and 5 ms compiled. The stage itself stays interpreted: IPOPT's interface differentiates f and g.
COMPILED = ("hess", "jac", "grad")
COMPILE_WORK = 2_000_000
# With fatrop every stage function is compiled, at -O1 with fused multiply-adds where the processor has
# them: the F-16 turn's 1,100 stage Hessians on `full` take 25 ms (28 without them);
# docs/benchmarks/fatrop-on-blasfeo-for-the-processor.md.
FATROP_COMPILED = ("stage", "jac", "jac0", "grad", "hess", "hess0", "terminal", "terminal_jac", "terminal_grad",
                   "terminal_hess")
FATROP_FLAGS = ("-O1", "-fPIC", "-shared", *compiled.processor_flags())
# fatrop solvers built in this process, by their compiled NLP and options: the windows of a long path
# share one (CasADi's fatrop set-up takes 15 s at 1,140 intervals on `full`, growing with their square).
FATROP_SOLVERS: dict[str, ca.Function] = {}
FATROP_KEPT = 2
#: A whole path's fatrop solver is kept in the cache from this many intervals on (30 s at the default
#: step): the F-16 turn's 1,100 on `full` took 10.7 s to build with its set-up, 1.3 s loaded; at 160
#: the set-up takes a fraction of a second (it grows with the square of the intervals).
STORED_FROM = 600
# MUMPS' fill-reducing ordering: approximate minimum degree with quasi-dense rows (QAMD); IPOPT's time
# per iteration against MUMPS' own choice: 24 against 36 ms on the catapult on full (docs/benchmarks/mumps-ordering.md).
MUMPS_ORDERING = 6

#: With ``ProblemOptions.gauss_newton_first``: the Gauss-Newton phase stops at this tolerance or after
#: this many iterations, and the exact phase starts from there with IPOPT's warm start
#: (docs/benchmarks/gauss-newton-first.md).
GAUSS_NEWTON_TOL, GAUSS_NEWTON_ITER = 1e-3, 30
WARM_START = {"warm_start_init_point": "yes", "mu_init": 1e-6, "warm_start_bound_push": 1e-9,
              "warm_start_bound_frac": 1e-9, "warm_start_slack_bound_push": 1e-9,
              "warm_start_slack_bound_frac": 1e-9, "warm_start_mult_bound_push": 1e-9}
FATROP_STATUS = {0: "Solve_Succeeded", 1: "Maximum_Iterations_Exceeded"}  # its return codes, in IPOPT's words


@dataclass(frozen=True)
class Solution:
    """What one solve returns: the free joints' initial state and piecewise-constant accelerations.

    t_nodes : (N + 1,) control grid [s]; x : (N + 1, nx) states at the nodes (q, qd, filter states);
    u : (N, n) joint accelerations per interval; cost : objective value; status, success, iterations,
    solve_time [s] of the solver itself; lam_g, lam_x : multipliers, for warm starts.
    """

    t_nodes: np.ndarray
    x: np.ndarray
    u: np.ndarray
    cost: float
    status: str
    success: bool
    iterations: int
    solve_time: float
    lam_g: np.ndarray = field(repr=False, default=None)
    lam_x: np.ndarray = field(repr=False, default=None)
    smooth: bool = False

    @property
    def n(self) -> int:
        return self.u.shape[1]

    @property
    def accelerations(self) -> np.ndarray:
        """(N, n) the joints' accelerations at the start of each interval."""
        return self.x[:-1, 2 * self.n: 3 * self.n] if self.smooth else self.u

    @property
    def q0(self) -> np.ndarray:
        return self.x[0, : self.n]

    @property
    def qd0(self) -> np.ndarray:
        return self.x[0, self.n: 2 * self.n]

    @property
    def plan(self) -> Plan:
        """The joints' plan: this solution's grid, initial state, accelerations and jerks."""
        return Plan(self.t_nodes, self.q0, self.qd0, self.accelerations, self.u if self.smooth else None)


class Bounds(NamedTuple):
    """The bounds of one solve: on the variables (lbx, ubx) and on the constraints (lbg, ubg)."""

    lbx: np.ndarray
    ubx: np.ndarray
    lbg: np.ndarray
    ubg: np.ndarray


class CueingProblem(Formulation):
    """The NLP of a :class:`~desdemona.cueing.formulation.Formulation`; built once, solved from many guesses.

    solves : how often it will be solved (a flat graph pays from :data:`EXPAND_SOLVES` on);
    parametric : the desired path is a parameter (an on-line controller's problem, solved each cycle
    on a new preview), not a constant;
    stored : with fatrop, keep its solver in the cache for later runs and take it from there
    (:func:`desdemona.cueing.compiled.store_solver`: a window of a recording poses the same problem for
    every recording, a whole path for every path of as many intervals); None: where its set-up is long
    (:data:`STORED_FROM` intervals or more).
    threads : the threads the stage functions are mapped on (1 in a worker process of a multi-start,
    whose processes already take the cores).
    """

    def __init__(self, model: Model, path: DesiredPath, options: ProblemOptions = ProblemOptions(),
                 solves: int = 1, parametric: bool = False, stored: bool | None = False, threads: int = MAP_THREADS):
        super().__init__(model, path, options, parametric)
        self.solves = solves
        self.stored = self.N >= STORED_FROM if stored is None else stored
        self.threads = threads
        self.monitor = None  # the solver's guard.SolveMonitor, where it has one
        self._build_nlp()

    def _build_nlp(self) -> None:
        N, nx, nu = self.N, self.nx, self.nu
        nw = nx + nu
        w = ca.MX.sym("w", N * nw + nx)  # stage order x0, u0, x1, u1, ..., xN (fatrop)
        XU = ca.reshape(w[: N * nw], nw, N)
        X, U = XU[:nx, :], XU[nx:, :]
        X_next = ca.horzcat(X[:, 1:], w[N * nw:])
        # The desired values are a parameter p (columns per stage) for an MPC, and for fatrop off-line,
        # whose compiled NLP is then the same for every path of as many intervals (FATROP_SOLVERS);
        # constants for IPOPT off-line.
        nd, n_end = self.stage.size1_in(2), 0 if self.terminal is None else self.terminal.size1_in(1)
        self.path_parameter = self.parametric or self.options.solver == "fatrop"
        if self.path_parameter:
            p = ca.MX.sym("p", nd * N + n_end)
            data, data_end = ca.reshape(p[:nd * N], nd, N), p[nd * N:]
        else:
            p, data = ca.MX(0, 1), ca.DM(self.stage_data())
            data_end = None if self.terminal is None else ca.DM(self.terminal_data())
        self.p = None if self.parametric or not self.path_parameter else np.r_[
            self.stage_data().ravel(order="F"), [] if self.terminal is None else self.terminal_data()]
        # With perception, the filters start in the steady state of the first S: the person has sat
        # still before the run, and the optimiser may not choose what they felt before t = 0.
        initial = self.initial_constraint()(X[:, 0], U[:, 0])
        self.n_initial = initial.numel()
        self.expanded = self._expand()
        o = self.options  # Gauss-Newton first: IPOPT off-line, on the derivatives assembled here
        self.gauss_newton_first = ((o.gauss_newton_first if o.gauss_newton_first is not None
                                    else self.model.config.takes_modulus)
                                   and o.solver == "ipopt" and not self.parametric and not self.expanded)
        stage = assembly.stage_functions(self)
        self.compiled = self._compile(stage)
        # f and g on two threads too, unless the graph is flattened (on-line and small problems)
        serial = self.parametric or self.expanded
        x_next, L, g = stage["stage"].map(N, "serial" if serial else MAP_MODE, 1 if serial else self.threads)(X, U, data)
        G = ca.vertcat(X_next - x_next, g)  # per stage: gap, then path constraints
        g_all = ca.vertcat(G[:nx, 0], initial, G[nx:, 0], ca.vec(G[:, 1:]))
        f = ca.sum2(L)
        self.n_terminal = 0
        if self.terminal is not None:
            L_end, g_end = stage["terminal"](w[N * nw:], data_end)
            f, g_all = f + L_end, ca.vertcat(g_all, g_end)
            self.n_terminal = g_end.numel()
        self.nlp = {"x": w, "f": f, "g": g_all}
        if self.path_parameter:
            self.nlp["p"] = p
        stage_eq = [True] * nx + [False] * self.n_path
        self.equality = (stage_eq[:nx] + [True] * self.n_initial + stage_eq[nx:] + stage_eq * (N - 1)
                         + [False] * self.n_terminal)
        self.derivatives = assembly.derivatives(self, w, p, XU, data, data_end, stage)
        self.gauss_newton_hessian = self.derivatives.pop("hess_gn", None)
        self._bounds()
        self.solver = self._solver()

    def initial_constraint(self) -> ca.Function:
        """``initial(x0, u0) -> residual``: with perception, the filters in the steady state of the first S."""
        x, u = ca.SX.sym("x", self.nx), ca.SX.sym("u", self.nu)
        residual = ca.SX(0, 1)
        if self.nz and self.options.initial_filter == "steady":
            n = self.model.n
            a = x[2 * n:3 * n] if self.smooth else u
            residual = x[self.n_motion:] - ca.DM(self.filter.steady_gain()) @ self.model.functions["S"](x[:n], x[n:2 * n], a)
        return ca.Function("initial", [x, u], [residual])

    def _expand(self) -> bool:
        """Whether to evaluate the NLP as one flat SX graph (``ProblemOptions.expand``)."""
        if self.options.expand is not None:
            return self.options.expand
        return self.N * self.stage.n_instructions() <= EXPAND_LIMIT and self.solves >= EXPAND_SOLVES

    def _compile(self, stage: dict[str, ca.Function]) -> bool:
        """Replace the mapped stage functions by compiled ones where ``ProblemOptions.compile`` asks
        for it (:mod:`desdemona.cueing.compiled`); whether they were."""
        wanted = self.options.compile
        if self.expanded or self.parametric or wanted is False:
            return False  # a flat graph cannot hold compiled code; on-line problems are flattened too
        fatrop = self.options.solver == "fatrop"  # it differentiates nothing: every stage function compiled
        keys = [k for k in (FATROP_COMPILED if fatrop else (*COMPILED, "hess_gn")) if k in stage]
        functions = [stage[k] for k in keys]
        if wanted is None and not fatrop and self.N * stage["jac"].n_instructions() < COMPILE_WORK \
                and not compiled.is_cached(functions):
            return False
        self.stage_library = compiled.build(functions, FATROP_FLAGS if fatrop else compiled.FLAGS)
        if self.stage_library is None:
            return False
        stage.update((k, ca.external(stage[k].name(), str(self.stage_library))) for k in keys)
        return True

    def _bounds(self) -> None:
        n, N, nx, o = self.model.n, self.N, self.nx, self.options
        lim = self.model.limits
        # Between nodes a rate is a parabola and a position bulges between sub-step points: each node
        # backs off by the largest bulge of the intervals beside it, so a plan's fine first steps may
        # come nearer a limit than its coarse tail (one back-off by the tail's bulge held an arm 0.15 %
        # under its rate limit on-line, and the heave on `full` 25 mm inside its travel).
        h = self.node_steps()[:, None]
        self._node_positions = self.position_bounds(h / self.m)  # (N + 1, n) each
        self._inner_positions = self.position_bounds(self.steps[:, None] / self.m)  # (N, n) each
        qmin, qmax = self._node_positions
        free = np.full((N + 1, self.nz), np.inf)
        if self.smooth:
            velocity = lim.velocity - lim.jerk * h**2 / 8.0  # (N + 1, n)
            x_lo = np.hstack([qmin, -velocity, np.broadcast_to(-lim.acceleration, qmin.shape), -free])
            x_hi = np.hstack([qmax, velocity, np.broadcast_to(lim.acceleration, qmax.shape), free])
            control = lim.jerk
        else:
            velocity = np.broadcast_to(lim.velocity, qmin.shape)
            x_lo, x_hi = np.hstack([qmin, -velocity, -free]), np.hstack([qmax, velocity, free])
            control = lim.acceleration
        lbx = np.r_[np.hstack([x_lo[:N], np.tile(-control, (N, 1))]).ravel(), x_lo[N]]
        ubx = np.r_[np.hstack([x_hi[:N], np.tile(control, (N, 1))]).ravel(), x_hi[N]]
        last = slice(N * (nx + self.nu), N * (nx + self.nu) + nx)
        moving = slice(n, self.n_motion)  # rates (and accelerations): zero at rest
        if o.initial in ("rest", "given"):
            lbx[moving] = ubx[moving] = 0.0
        if o.initial == "rest" and self.model.config.aligned:
            # the cabin follows the force from home, level: the gimbals' start is not free (three
            # angles give the same level cabin, some near gimbal lock), and so is the arm's, by symmetry
            lbx[:n] = ubx[:n] = 0.0
        elif o.initial in ("rest", "free") and self._arm_symmetric():
            # Nothing depends on the arm's angle (gravity is along its axis), so a free start of it
            # is a flat direction of the whole problem: IPOPT drifted it to 1e13 rad on real data,
            # where round-off alone left the gaps unsatisfiable and the solve stalled.
            lbx[0] = ubx[0] = 0.0
        if o.initial == "given":
            q0, qd0 = start_state(o.initial_state, n)
            lbx[:n] = ubx[:n] = q0
            lbx[n:2 * n] = ubx[n:2 * n] = qd0
            if self.smooth:
                lbx[2 * n:3 * n] = ubx[2 * n:3 * n] = start_acceleration(o.initial_state, n)
        if o.final in ("rest", "centre"):
            lo, hi = lbx[last], ubx[last]  # views into lbx, ubx
            lo[moving] = hi[moving] = 0.0
            if o.final == "centre":
                prismatic = np.flatnonzero(self.model.prismatic)
                lo[prismatic] = hi[prismatic] = 0.0
        self.lbx, self.ubx = lbx, ubx
        self.lbg, self.ubg = self._constraint_bounds(None)
        if o.initial == "given":
            self.lbx, self.ubx, self.lbg, self.ubg = self.bounds_from(start_state(o.initial_state, n)[0])

    def node_steps(self) -> np.ndarray:
        """(N + 1,) the longer of the two intervals beside each node (the first and last: their one)."""
        h = self.steps
        return np.r_[h[0], np.maximum(h[:-1], h[1:]), h[-1]]

    def _constraint_bounds(self, widen=None) -> tuple[np.ndarray, np.ndarray]:
        """(lbg, ubg): per stage the gaps (equalities), then the families in the order of the stage's
        g. The position rows of a stage back off by its own sub-steps' bulge, the stopping rows by
        that of the node they start from (:meth:`_bounds`). ``widen`` = (lower, upper, stages): the
        position and stopping families of the first ``stages[j]`` stages take bound j at least that
        far out (:meth:`bounds_from`)."""
        nx, N, bounded = self.nx, self.N, self.model.limits.bounded
        rows_lo, rows_hi = [], []
        for k in range(N):
            lower, upper = [np.zeros(nx)], [np.zeros(nx)]
            for f in self.families:
                lo, hi = f.lower, f.upper
                if f.name in ("position", "stopping"):
                    bounds, row = (self._inner_positions, k) if f.name == "position" else (self._node_positions, k + 1)
                    count = lo.size // len(bounded)
                    lo, hi = (np.tile(side[row][bounded], count) for side in bounds)
                    if widen is not None:
                        wide = k < widen[2][bounded]
                        lo = np.minimum(lo, np.tile(np.where(wide, widen[0][bounded], lo[:len(bounded)]), count))
                        hi = np.maximum(hi, np.tile(np.where(wide, widen[1][bounded], hi[:len(bounded)]), count))
                    # a side the family leaves open stays open (the stopping rows: how far up, how far down)
                    lo, hi = np.where(np.isneginf(f.lower), -np.inf, lo), np.where(np.isposinf(f.upper), np.inf, hi)
                lower.append(lo)
                upper.append(hi)
            rows_lo.append(np.concatenate(lower))
            rows_hi.append(np.concatenate(upper))
        terminal = np.ones(self.n_terminal)  # torques and powers over their limits at the last node
        initial = np.zeros(self.n_initial)
        return (np.r_[rows_lo[0][:nx], initial, rows_lo[0][nx:], *rows_lo[1:], -terminal],
                np.r_[rows_hi[0][:nx], initial, rows_hi[0][nx:], *rows_hi[1:], terminal])

    def _arm_symmetric(self) -> bool:
        """Whether the arm (q1) is free and without position limits: then the problem is the same
        whatever its angle, and the start fixes it at 0."""
        config, lim = self.model.config, self.model.limits
        return bool(config.turns_arm and not np.isfinite(lim.position_min[0])
                    and not np.isfinite(lim.position_max[0]))

    def bounds_from(self, q0, qd0=None, a0=None) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
        """(lbx, ubx, lbg, ubg) for a plan that starts at the positions q0 (n,) (with the rates qd0 and
        accelerations a0 where given).

        The optimiser keeps positions a bulge (qdd_max h^2 / 8) inside their limits, so that the
        parabola between two points stays inside too. A start in that band (at rest at the end of a
        joint's travel, say) could then not plan at all: it cannot move the first millimetre within
        one step's jerk, and an on-line controller would brake for ever. Where q0 lies in the band,
        the bounds of that joint (nodes, position and stopping rows) reach out to q0 over the time a
        jerk-limited start from rest needs to cross the band, and one interval more; after that the
        plan is inside, as everywhere. The bounds unchanged where q0 lies inside. A start in the band
        moving outwards, whose stopping point lies beyond the start, is still infeasible: no plan
        from it keeps the stopping condition. A start whose own stop lies just beyond the stopping
        rows (:meth:`~desdemona.cueing.formulation.Formulation.stop_overreach`) has the position and stopping
        rows reach out to it until its acceleration can have passed the braking, and one interval more."""
        q0 = np.asarray(q0, dtype=float)
        qmin, qmax = self.position_bounds()
        lower, upper = np.minimum(qmin, q0), np.maximum(qmax, q0)
        t = self.t_nodes - self.t_nodes[0]
        over = None if qd0 is None else self.stop_overreach(q0, qd0, a0, *(side[1] for side in self._node_positions))
        rows = None if over is None else (over[0], over[1], np.searchsorted(t, over[2], side="right") + 1)
        below, above = lower < qmin, upper > qmax
        if below.any() or above.any():
            lim = self.model.limits
            band = np.maximum(np.nan_to_num(qmin) - np.nan_to_num(lower), np.nan_to_num(upper) - np.nan_to_num(qmax))
            crossing = np.cbrt(6.0 * band / lim.jerk) if self.smooth else np.sqrt(2.0 * band / lim.acceleration)
            stages = np.searchsorted(t, crossing, side="right") + 1  # intervals started before it is crossed, and one more
            # the fine first nodes back off less (:meth:`_bounds`): where each node it would widen already
            # reaches q0 (a joint held at the end of its travel through the fine steps), nothing changes
            within = np.arange(1, self.N + 1)[:, None] <= stages
            node_lo, node_hi = (side[1:] for side in self._node_positions)
            below = below & np.any(within & (node_lo > lower), axis=0)
            above = above & np.any(within & (node_hi < upper), axis=0)
        if not (below.any() or above.any()):
            return (self.lbx, self.ubx, *self._constraint_bounds(rows)) if rows else (self.lbx, self.ubx, self.lbg, self.ubg)
        n, nw = self.model.n, self.nx + self.nu
        lbx, ubx = self.lbx.copy(), self.ubx.copy()
        last = self.N if self.options.final == "none" else self.N - 1  # a fixed end stays fixed
        for k in range(1, last + 1):  # the start node is the start
            wide = k <= stages
            lo, hi = lbx[k * nw:k * nw + n], ubx[k * nw:k * nw + n]  # views
            lo[:] = np.where(wide & below, np.minimum(lo, lower), lo)
            hi[:] = np.where(wide & above, np.maximum(hi, upper), hi)
        if rows:
            lower, upper, stages = np.minimum(lower, rows[0]), np.maximum(upper, rows[1]), np.maximum(stages, rows[2])
        return (lbx, ubx, *self._constraint_bounds((lower, upper, stages)))

    def _solver(self) -> ca.Function:
        o = self.options
        if o.solver == "ipopt":
            if not self.parametric:  # off-line solves are long: stoppable by Ctrl-C, and reported on
                self.monitor = guard.SolveMonitor(self.nlp["x"].numel(), self.nlp["g"].numel())
            if self.gauss_newton_first:
                self.first_solver = self._ipopt({"tol": GAUSS_NEWTON_TOL, "max_iter": GAUSS_NEWTON_ITER},
                                                hess_lag=self.gauss_newton_hessian)
                return self._ipopt(WARM_START)
            return self._ipopt({})
        opts = {"structure_detection": "auto", "equality": self.equality, "print_time": False, "expand": self.expanded,
                "calc_lam_x": False, "calc_lam_p": False,  # fatrop's own multipliers (compiled.oracle)
                "fatrop": {"print_level": 0, "max_iter": o.max_iter, "tol": o.tol}}
        # on linear algebra built for this processor, where it can be (desdemona.cueing.blasfeo); an off-line
        # run does not wait for its first build where optimised code is built later (compiled.OPTIMISED),
        # an on-line controller's does (its QPs are timed)
        blasfeo.load(wait=self.parametric or compiled.OPTIMISED != "later")
        if not self.compiled:
            return ca.nlpsol("cueing", "fatrop", self.nlp, opts)
        # the NLP with the derivatives assembled here, compiled, for fatrop to find by name; one solver
        # for every problem whose compiled NLP is the same (the path is its parameter)
        source = compiled.c_source(compiled.oracle(self.nlp, self.derivatives), "assembly.c")
        key = hashlib.sha256(f"{ca.__version__}{source}{self.stage_library}{opts}".encode()).hexdigest()
        if key in FATROP_SOLVERS:
            return FATROP_SOLVERS[key]
        solver = compiled.stored_solver(key) if self.stored else None
        if solver is None:
            kept = compiled.solver_files(key)[1] if self.stored and compiled.writable() else None
            if (oracle := compiled.linked(source, self.stage_library, "nlp", kept)) is None:
                raise RuntimeError("the NLP's functions for fatrop did not compile (the warning says why); "
                                   "solve with IPOPT, or with ProblemOptions(compile=False)")
            solver = ca.nlpsol("cueing", "fatrop", oracle, opts)
            if kept is not None:
                compiled.store_solver(key, solver)
        while len(FATROP_SOLVERS) >= FATROP_KEPT:
            FATROP_SOLVERS.pop(next(iter(FATROP_SOLVERS)))
        FATROP_SOLVERS[key] = solver
        return solver

    def _ipopt(self, settings: dict, **derivatives) -> ca.Function:
        """An IPOPT solver of the NLP with the stage-assembled derivatives (``derivatives`` replacing
        some) and ``settings`` over the defaults."""
        o = self.options
        opts = {"ipopt": {"print_level": 0, "max_iter": o.max_iter, "tol": o.tol,
                          "sb": "yes", "mu_strategy": "adaptive",
                          "linear_solver": "mumps", "mumps_pivot_order": MUMPS_ORDERING, **settings},
                "print_time": False, "expand": self.expanded}
        if not self.expanded:  # a flat graph differentiates well by itself
            opts.update(self.derivatives, **derivatives)
        if self.monitor is not None:
            opts["iteration_callback"] = self.monitor
        return ca.nlpsol("cueing", "ipopt", self.nlp, opts)

    # ------------------------------------------------------------------------------------------

    def pack(self, x: np.ndarray, u: np.ndarray) -> np.ndarray:
        """Decision vector from node states (N + 1, nx) and controls (N, nu)."""
        return np.r_[np.hstack([x[:-1], u]).ravel(), x[-1]]

    def unpack(self, w) -> tuple[np.ndarray, np.ndarray]:
        w = np.asarray(w, dtype=float).ravel()
        N, nx, nu = self.N, self.nx, self.nu
        XU = w[: N * (nx + nu)].reshape(N, nx + nu)
        return np.vstack([XU[:, :nx], w[N * (nx + nu):]]), XU[:, nx:]

    def guess(self, q0, qd0, accelerations, a0=None, clip: bool = True, filters=None) -> tuple[np.ndarray, np.ndarray]:
        """Node states (N + 1, nx) and controls (N, nu) of a guess: the joints following
        ``accelerations`` (N, n), one per interval, from (q0, qd0) (with jerk limits: ramped from
        ``a0``, default the first, at most at j_max, :func:`desdemona.machine.plan.ramp`), clipped to the
        limits with ``clip``; filter states at ``filters`` (the state a controller carries), else at the
        steady state of the first S."""
        lim, h = self.model.limits, self.steps[:, None]
        accelerations = np.asarray(accelerations, dtype=float)
        if self.smooth:
            starts, u = ramp(accelerations, h, a0, lim.jerk)
            a = np.vstack([starts, starts[-1] + u[-1] * h[-1]])
        else:
            starts, u, a = accelerations, accelerations, np.zeros((self.N + 1, 0))
        q, qd = node_states(q0, qd0, starts, h, u if self.smooth else None)
        if clip:
            qd = np.clip(qd, -lim.velocity, lim.velocity)
            q = np.clip(q, lim.position_min, lim.position_max)
        x = np.hstack([q, qd, a])
        if self.nz:  # a controller's carried state, else the steady state of the first S
            z = filters if filters is not None else self.filter.steady_state(self.model.S(q0, qd0, starts[0]))
            x = np.hstack([x, np.broadcast_to(z, (self.N + 1, self.nz))])
        return x, u

    def solve(self, x_guess: np.ndarray, u_guess: np.ndarray, warm: Solution | None = None) -> Solution:
        """Solve from a guess of node states (N + 1, nx) and controls (N, nu), optionally warm-started
        with the multipliers of an earlier solution of a problem of the same shape."""
        args = {"x0": self.pack(x_guess, u_guess), "lbx": self.lbx, "ubx": self.ubx,
                "lbg": self.lbg, "ubg": self.ubg}
        if self.p is not None:
            args["p"] = self.p
        if warm is not None and warm.lam_g is not None and self.options.solver == "ipopt":
            args.update(lam_g0=warm.lam_g, lam_x0=warm.lam_x)
        start, iterations = time.perf_counter(), 0
        with guard.solving(self.monitor):  # raises guard.Interrupted after a stop was asked for
            if self.gauss_newton_first:
                first = self.first_solver(**args)
                iterations = int(self.first_solver.stats()["iter_count"])
                args.update(x0=first["x"], lam_g0=first["lam_g"], lam_x0=first["lam_x"])
            sol = self.solver(**args)
        elapsed = time.perf_counter() - start
        stats = self.solver.stats()
        x, u = self.unpack(sol["x"])
        status = stats.get("return_status", stats.get("unified_return_status", "unknown"))
        if isinstance(status, int):
            status = FATROP_STATUS.get(status, f"fatrop_return_code_{status}")
        return Solution(t_nodes=self.t_nodes.copy(), x=x, u=u, cost=float(sol["f"]), status=status,
                        success=bool(stats["success"]), iterations=iterations + int(stats.get("iter_count", -1)),
                        solve_time=elapsed, lam_g=np.asarray(sol["lam_g"]).ravel(),
                        lam_x=np.asarray(sol["lam_x"]).ravel(), smooth=self.smooth)

    # ------------------------------------------------------------------------------------------
    # a controller's solves: a parametric problem from a fixed start

    def start_bounds(self, q, qd, a=None, z=None, positions=None) -> Bounds:
        """The bounds of a plan that starts at the positions ``q`` (or, with ``positions`` = (lower,
        upper), anywhere within them), the rates ``qd``, with jerk limits the accelerations ``a``, and
        with a perception model the filter states ``z``: "fix the start". The rest of the plan is
        bounded as :meth:`bounds_from` ``q`` has it."""
        n = self.model.n
        lbx, ubx, lbg, ubg = self.bounds_from(q, qd, np.zeros(n) if a is None else a)
        lbx, ubx = lbx.copy(), ubx.copy()
        lbx[:n], ubx[:n] = (q, q) if positions is None else positions
        lbx[n:2 * n], ubx[n:2 * n] = qd, qd
        if self.smooth:
            lbx[2 * n:3 * n], ubx[2 * n:3 * n] = a, a
        if self.nz:
            lbx[self.n_motion:self.nx], ubx[self.n_motion:self.nx] = z, z
        return Bounds(lbx, ubx, lbg, ubg)

    def keep_rate_sign(self, bounds: Bounds, joint: int, first: int, sign: float) -> None:
        """Keep free joint ``joint``'s rate at the nodes from ``first`` on of the sign of ``sign``
        (>= 0: not below zero; < 0: not above), in ``bounds`` in place."""
        nw = self.nx + self.nu
        rates = slice(first * nw + self.model.n + joint, len(bounds.lbx), nw)
        if sign >= 0.0:
            bounds.lbx[rates] = np.maximum(bounds.lbx[rates], 0.0)
        else:
            bounds.ubx[rates] = np.minimum(bounds.ubx[rates], 0.0)

    def solve_from(self, x, controls, bounds: Bounds, data, rti=None,
                   share: float = 1.0):
        """Solve the parametric problem from the guess (node states ``x``, ``controls``) within
        ``bounds`` for the stages' ``data`` (:meth:`with_steps`): by one real-time iteration with
        ``rti`` (a :class:`~desdemona.cueing.realtime_iteration.RealTimeIteration`, taking ``share`` of
        its step), else by the solver to convergence. Returns (w, success,
        cost), the cost None for a real-time iteration."""
        p = np.asarray(data).ravel(order="F")
        w = self.pack(x, controls)
        if rti is not None:
            w, success = rti(w, p, bounds, share)
            return w, success, None
        sol = self.solver(x0=w, lbx=bounds.lbx, ubx=bounds.ubx, lbg=bounds.lbg, ubg=bounds.ubg, p=p)
        return sol["x"], bool(self.solver.stats()["success"]), float(sol["f"])

    def plan_of(self, w) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """(q0, accelerations, jerks) of a decision vector: the start's positions (n,), and per
        interval the accelerations at its start and its jerks (N, n) (zero without jerk limits)."""
        x, controls = self.unpack(w)
        n = self.model.n
        if self.smooth:
            return x[0, :n], x[:-1, 2 * n:3 * n], controls
        return x[0, :n], controls, np.zeros_like(controls)

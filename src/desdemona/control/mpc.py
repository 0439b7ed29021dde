"""The on-line cueing controller: a model predictive controller with a safe fallback (thesis chapter 7).

With a pilot in the loop the desired path is known only a horizon T_h ahead. :class:`MPC` is built
once and stepped every re-plan period T_c (a whole number of plan steps h; by default T_c = h):
``step(state, preview) -> Command``, the accelerations of the coming period. Each step solves the
problem of :mod:`desdemona.cueing.formulation` over the horizon (eq. 3.8) from the measured state (or, with the
thesis' computation delay, the state predicted for when the plan takes over, figure 7.2),
warm-started from the previous plan shifted by one period, with every limit hard and every planned state
*stoppable* (each track and heave position can still brake to rest within its limits: the end
condition of chapter 7, section 3.4's K, imposed at every node so that any remainder of a plan ends
stoppable too). The solve itself, and the layout of its variables, belong to
:mod:`desdemona.cueing.transcription`.

Fallback, in order, whenever the solver fails, misses its deadline or is given an unusable preview:
the next step of the previous plan, for at most ``SHIFT_MAX``; then a braking command. Every command, whatever
its source, is checked against every limit over the coming step before it is returned; a braking
command is scaled down until it passes. The controller never returns a command that violates a limit.

The measurements behind the defaults are in docs/benchmarks/index.md#design-decisions-and-the-measurements
(one page each, cited below); the predictors that turn what is known now into the preview are in
:mod:`desdemona.control.predictors`; a whole closed-loop session is :func:`desdemona.control.online.run`.
"""

from __future__ import annotations

import dataclasses
import time

import numpy as np

from desdemona.baselines.classical import still_home
from desdemona.check.simulate import TOLERANCE
from desdemona.control.command import Command, MPCOptions, _Solved, default_horizon  # noqa: F401 -- re-exported
from desdemona.cueing.formulation import ProblemOptions
from desdemona.cueing.realtime_iteration import RealTimeIteration
from desdemona.cueing.transcription import CueingProblem
from desdemona.machine.model import Model
from desdemona.machine.plan import (REST_RATE, Plan, State, advance, braking_jerk, homing_rate, settled_rate,
                                    stopping_extent)
from desdemona.occupant.perception import THRESHOLDS
from desdemona.profiles import ALIGNED_WEIGHTS, DesiredPath, above_g, at_least_g, vertical_force
from desdemona.support.symbolic import call

#: How long [s] a fallback follows the last plan before it brakes, at most; the next plan then starts from a
#: fresh seed (a plan's far part is no command to follow open-loop for seconds: docs/benchmarks/fallback-to-the-last-plan.md).
SHIFT_MAX = 2.0
#: Where the plan's tail doubles [s] on a configuration whose cabin tilts (``MPCOptions.far`` "auto"): beyond
#: it a 4 s plan on ``full`` has intervals of 0.2 s, 46 intervals in all instead of 56 (docs/benchmarks/coarse-tail-of-the-plan.md).
FAR = 2.0
#: How long [s] the brake holds the machine where it stopped before it brings it home (:meth:`MPC.homing`):
#: a gap in the plans keeps the pose the next plan starts from; an outage that lasts goes home.
HOMING_AFTER = 2.0


#: The least a placed start must save of the first plan's cost (a mean square felt error, (m/s^2)^2) to be
#: taken: 1e-4 is an RMS of 0.01 m/s^2, a seventeenth of the smallest force threshold. Less is a place the
#: plan does not feel (the track under a held 1 g), set by the solver's last digits (docs/benchmarks/placed-start.md).
PLACE_SAVING = 1e-4


class MPC:
    """The model predictive cueing controller, built once for a model and options, then stepped."""

    def __init__(self, model: Model, options: MPCOptions = MPCOptions(), weights=None):
        if options.far == "auto":  # where the tail doubles: where the cabin tilts (MPCOptions.tail_step)
            options = dataclasses.replace(options, far=FAR if model.config.tilts_cabin else None)
        self.model, self.options = model, options
        self.deadline = options.deadline if options.deadline is not None else options.period
        self.rti_step = options.rti_step or (0.5 if model.config.turns_cabin_only else 1.0)
        steps = options.grid()
        t = np.r_[0.0, np.cumsum(steps)]
        # A placeholder path fixes the problem's shape; the preview arrives as its parameter each step.
        placeholder = DesiredPath("preview", t, None if model.config.modulus_cost else np.zeros((len(t), 6)),
                                  weights=weights or (ALIGNED_WEIGHTS if model.config.aligned else (1.0,) * 6),
                                  modulus=np.zeros(len(t)) if model.config.modulus_cost else None)
        mine = {f.name for f in dataclasses.fields(options)}  # the fields both have: the same name, the same meaning
        shared = {f.name: getattr(options, f.name) for f in dataclasses.fields(ProblemOptions) if f.name in mine}
        shared["null_weight"] = options.null_weight if options.null_weight is not None or options.plan_method == "rti" else 0.0
        problem_options = ProblemOptions(h_u=options.step, initial="given", initial_state=(np.zeros(model.n),
            np.zeros(model.n)), tol=1e-6, stoppable=True, brake_step=options.step, initial_filter="given",
            steps=None if np.all(steps == options.step) else tuple(steps), **shared)
        self.problem = CueingProblem(model, placeholder, problem_options, solves=1000, parametric=True)
        if self.problem.nz:  # the horizon's perception map is built now, not in the session's first cycle
            self.problem.perceive(np.zeros((self.problem.N * self.problem.m, 6)))
        self.limits, self._limit_use = model.limits, model.step_limit_use(options.step)
        self.z = self.z_d = self._z_d_next = self._z_d_path = None  # filter states of the felt and the desired path, the desired one step on
        self._rti = RealTimeIteration(self.problem, options.qp_solver) if options.plan_method == "rti" else None
        self.smooth = self.problem.smooth
        self.plan: tuple[np.ndarray, np.ndarray] | None = None  # the last plan per step: accelerations, jerks
        self._counts = np.rint(self.problem.steps / options.step).astype(int)  # steps per interval
        # each step's time since its interval's start, (steps, 1)
        self._offsets = (np.concatenate([np.arange(c) for c in self._counts]) * options.step)[:, None]
        self.plan_age = self.braked = 0  # steps since the last plan began; steps braked in a row
        self.present = None  # the last preview's present value
        # the last step's stage data and whether it seeded a still arm to turn; what prepare() linearised for
        self._last_data, self._turning, self._prepared = None, True, None
        self.timings = dict.fromkeys(("preview", "qp_data", "qp", "check"), 0.0)  # the last step's phases [s]

    def step(self, state, preview) -> Command:
        """The commands of the coming cycle from the state (q, qd[, qdd]) and the preview of S_d.

        state : where the plan starts: the measured state (positions, rates and, on a machine with
            jerk limits, accelerations; zero where not given), or with ``delay`` the state predicted for
            when the plan takes over; preview : a :class:`DesiredPath` starting there, or raw arrays
            ``(t, values)`` with t (K,) [s] from there and values (K, 6) of S_d or (K,) of M_d for
            ``dfs`` (as a predictor may deliver them, NaN included: such a preview is not used).
        """
        start = time.perf_counter()
        q, qd = (np.asarray(v, dtype=float).reshape(self.model.n) for v in state[:2])
        a = np.asarray(state[2], dtype=float).reshape(self.model.n) if len(state) > 2 else np.zeros_like(q)
        if not self.smooth:
            a = np.zeros_like(q)  # the acceleration is a command, not a state
        now = State(q, qd, a)
        if self.problem.nz and self.z is None:  # the person has sat still before the run
            self.z = self.problem.filter.steady_state(self.model.S(q, qd, a))
        t, values = self._preview_arrays(preview)
        reason = self._preview_problem(t, values)
        self._z_d_next = None
        plan = None
        if not reason:
            self.present = values[0].copy() if values.ndim == 2 else None  # S_d now: the brake's home (homing)
            turning = not self.model.config.takes_modulus or above_g(values, THRESHOLDS[5])  # _leave_rest's
            begun = time.perf_counter()
            self._last_data, self._turning = self._data(t, values), turning
            self.timings["preview"] = time.perf_counter() - begun
            plan, success, elapsed, *_ = self._solve(q, qd, a, self._last_data, turning=turning)
            plan = self._per_step(*plan)
            if not success:
                reason, plan = "solver failed", None
            elif elapsed > self.deadline:
                reason, plan = f"deadline missed ({elapsed * 1e3:.1f} ms > {self.deadline * 1e3:.1f} ms)", None
        r, checked = self.options.replan_steps, time.perf_counter()
        if plan is not None and self._safe_sequence(now, plan[0][:r], plan[1][:r]):
            self.plan, self.plan_age, self.braked = plan, 0, 0
            command = Command(plan[0][:r].copy(), "mpc", time.perf_counter() - start, jerk=plan[1][:r].copy())
        else:
            reason = reason or "plan fails the limit check"
            command = self._fallback(now, reason, start)
        self.timings["check"] = time.perf_counter() - checked
        if self.problem.nz:
            self._advance_filters(now, command)
        return command

    def follow(self, state) -> Command | None:
        """The coming cycle's commands where nothing new came since the last (a host slower than the
        cycle, :mod:`desdemona.service.serve`): the last plan's next step from ``state``, as it was
        planned, without a QP. The real-time iteration's next step would linearise at that plan and
        solve on the same preview again; following it leaves the processor free for the host's next
        message, which the service then answers at once (docs/benchmarks/real-time-service.md). The
        step is checked as every command is (:meth:`_safe_sequence`), and the felt and desired filter
        states are carried over it as after a plan. None where there is no plan to follow (none yet, too
        old, or past the horizon's part of equal steps, over which the desired filter's states are
        known), or where its next step fails the check: the cycle then plans as always (:meth:`step`)."""
        start = time.perf_counter()
        r, most = self.options.replan_steps, round(SHIFT_MAX / self.options.step)
        if self.plan is None or self.plan_age + 2 * r > min(len(self.plan[0]), most):
            return None
        q, qd = (np.asarray(v, dtype=float).reshape(self.model.n) for v in state[:2])
        a = np.asarray(state[2], dtype=float).reshape(self.model.n) if self.smooth else np.zeros_like(q)
        now = State(q, qd, a)
        prob, age = self.problem, self.plan_age + r
        z_d_next = None
        if prob.nz:
            sub = prob.m * (age + r)  # the desired filter's state after the step followed
            if self._z_d_path is None or age + r > np.argmin(np.r_[self._counts, 0] == 1) or sub >= len(self._z_d_path):
                return None
            z_d_next = self._z_d_path[sub]
        window = slice(age, age + r)
        sequence, jerks = self.plan[0][window], self.plan[1][window]
        if not self._safe_sequence(now, sequence, jerks):
            return None
        self.plan_age = age
        command = Command(sequence.copy(), "shifted", time.perf_counter() - start, "nothing new since the last plan", jerks.copy())
        self.timings = dict.fromkeys(self.timings, 0.0) | {"check": command.compute_time}
        if prob.nz:
            self._z_d_next = z_d_next
            self._advance_filters(now, command)
        return command

    def place(self, state, preview) -> tuple[np.ndarray, np.ndarray]:
        """Before a session that starts at rest: where the machine should stand. The first plan is
        solved to convergence (IPOPT, at most ``max_iter`` iterations) from ``state`` = (q, qd) on
        ``preview`` (as :meth:`step` takes it), then again with the start's positions free within
        their limits (the arm's angle aside: with gravity along its axis it changes nothing felt), at
        rest, as the off-line problem's ``initial="rest"`` has them, from the first plan. A controller
        has this time before the session, and the machine is moved to the placed start beforehand; the
        placed plan is the one the first real-time iteration is linearised at (docs/benchmarks/placed-start.md).

        Returns the start (q0, qd0). Nothing is placed, and the controller is left as it was, on a
        configuration whose cabin follows the force (it starts level at home, as off-line), with a
        perception model whose felt state at rest depends on where the machine stands (otoliths with
        states: the choice would change what was felt before the run), or where a solve fails or the
        placed plan saves less than :data:`PLACE_SAVING`.
        """
        q, qd = (np.asarray(v, dtype=float).reshape(self.model.n) for v in state[:2])
        a = np.zeros_like(q)
        t, values = self._preview_arrays(preview)
        prob = self.problem
        # at rest nothing turns, and only filters of the force would remember where the machine stood
        felt_at_rest = prob.nz and np.any(prob.filter.steady_gain()[:, 3:] != 0.0)
        if self.model.config.aligned or felt_at_rest or self._preview_problem(t, values):
            return q, qd
        if prob.nz:
            self.z = prob.filter.steady_state(self.model.S(q, np.zeros_like(q), a))
        data = self._data(t, values)
        first = self._solve(q, qd, a, data, method="nlp")
        if not first.success:
            return q, qd
        # the seed of the placed solve: a plan taking over at the first step is one period younger than the last cycle's
        self.plan, self.plan_age = self._per_step(*first.plan), -self.options.replan_steps
        placed = self._solve(q, qd, a, data, method="nlp", place=True)
        if placed.success and first.cost - placed.cost > PLACE_SAVING:
            self.plan = self._per_step(*placed.plan)
            return self._within_a_turn(placed.start), np.zeros_like(qd)
        self.plan, self.plan_age = None, 0
        return q, qd

    def forget(self) -> None:
        """Drop the last plan: the machine was moved by something else (parked by the real-time
        service while the host was quiet), so the next cycle plans afresh from where it stands."""
        self.plan, self.plan_age, self._prepared = None, 0, None

    def _within_a_turn(self, q) -> np.ndarray:
        """``q`` with each joint that has no position limit (a gimbal that turns freely) taken within
        half a turn of home, [-pi, pi): the same attitude, so the same plan, but a start the machine
        reaches quickly."""
        lim = self.limits
        free = ~(np.isfinite(lim.position_min) | np.isfinite(lim.position_max))
        return np.where(free, np.remainder(q + np.pi, 2.0 * np.pi) - np.pi, q)

    def _advance_filters(self, state: State, command) -> None:
        """Carry the felt filter state over the cycle just commanded, and the desired one with it."""
        prob = self.problem
        s = np.arange(prob.m)[:, None] / prob.m * self.options.step
        for qdd, jerk in zip(command.sequence, command.jerks):
            S = self.model.S(*advance(state.q, state.qd, qdd, s, jerk), qdd + jerk * s)
            for row in S:
                self.z = prob.filter.Ad @ self.z + prob.filter.Bd @ row
            state = state.advance(qdd, self.options.step, jerk)
        # without a usable preview the desired state is unknown: restart from the next preview's steady state
        self.z_d = self._z_d_next

    def _preview_arrays(self, preview):
        """(t, values) of a preview, as the problem takes them: S_d, or the modulus M_d on a modulus
        configuration, a modulus turned into the force along the occupant's vertical on one whose cabin
        follows the force.

        On those configurations (``dfs``, ``dfs-yaw``: no heave, the head at the gimbals' centre) the
        felt force is never weaker than g, and a desired force below g is planned for as g in its
        direction, the nearest the machine can do: chased as it is, one QP per cycle linearised at the
        last plan meets residuals its Gauss-Newton model does not see and turned the cabin over
        (docs/benchmarks/modulus-below-g-on-line.md). The run is judged against the path as it is."""
        if isinstance(preview, DesiredPath):
            preview = self.model.config.cue_path(preview)
            t, values = preview.t, preview.M_d if self.model.config.modulus_cost else preview.S_d
        else:
            t, values = preview
            values = None if values is None else np.asarray(values, dtype=float)
            if values is not None and values.ndim == 1 and self.model.config.aligned:
                values = vertical_force(values)  # a modulus, for a cabin that follows the force
        if values is not None and self.model.config.takes_modulus:
            values = at_least_g(values)
        return np.asarray(t, dtype=float), values

    def _preview_problem(self, t, values) -> str:
        shape = (len(t),) if self.model.config.modulus_cost else (len(t), 6)
        if values is None or values.shape != shape:
            return "preview misses the channels this configuration needs"
        if not (np.all(np.isfinite(values)) and np.all(np.isfinite(t))):
            return "preview has NaN or inf"
        if len(t) < 2 or np.any(np.diff(t) <= 0):
            return "preview time does not increase"
        if t[-1] < self.options.horizon - 1e-9:
            return f"preview covers {t[-1]:.3g} s of the {self.options.horizon:g} s horizon"
        return ""

    def _data(self, t, values) -> np.ndarray:
        prob = self.problem
        times = prob.sub_times()  # relative to now: the placeholder starts at 0
        # a plan that reaches past the preview takes its last value as held there (np.interp does)
        if self.model.config.modulus_cost:
            return prob.with_steps(np.interp(times, t, values).T)
        S_d = np.column_stack([np.interp(times.ravel(), t, values[:, i]) for i in range(6)])
        if prob.nz == 0:
            return prob.with_steps(S_d.reshape(prob.N, -1).T)
        # perceived desired path over the horizon, from the desired filter state carried so far
        held = S_d.reshape(prob.N, len(prob.fractions), 6)[:, :prob.m, :].reshape(-1, 6)
        if self.z_d is None:
            self.z_d = prob.filter.steady_state(held[0])
        y_d, states = prob.perceive(held, self.z_d)
        self._z_d_next = states[prob.m * self.options.replan_steps]  # after this cycle's sub-steps
        self._z_d_path = states  # and after the next ones, for a cycle that follows the plan (follow)
        return prob.with_steps(y_d.reshape(prob.N, -1).T)

    def _solve(self, q, qd, a, data, method: str | None = None, place: bool = False, turning: bool = True):
        """One warm-started solve from (q, qd, a) by ``method`` (default the options'); with ``place``
        the start's positions are free within their limits (``q`` is then only the guess's start);
        ``turning``: the preview asks for what a turning arm gives (:meth:`_leave_rest`). Returns a :class:`_Solved`."""
        prob, method = self.problem, method or self.options.plan_method
        share = self.rti_step if self.plan is not None else 1.0  # the whole step from a fresh seed
        begun = time.perf_counter()
        if method == "rti" and not place and self._prepared == self._key(q, qd, a, turning) and self._rti.ready:
            start = time.perf_counter()
            w, success, cost = *self._rti.feedback(np.asarray(data).ravel(order="F"), share), None
        else:
            x, controls, bounds = self._linearisation(q, qd, a, turning, method, place)
            start = time.perf_counter()
            w, success, cost = prob.solve_from(x, controls, bounds, data, self._rti if method == "rti" else None, share)
        self._prepared, elapsed = None, time.perf_counter() - start
        if self._rti is not None:  # the cycle's phases [s]: linearising and the QP's data, the QP solver
            self.timings.update(qp_data=start - begun + self._rti.timings["qp_data"], qp=self._rti.timings["qp"])
        q0, accelerations, jerks = prob.plan_of(w)
        return _Solved((accelerations, jerks), success, elapsed, q0, cost)

    def _linearisation(self, q, qd, a, turning: bool, method: str, place: bool = False):
        """The guess (node states, controls) a solve starts from, and the bounds of its start: the
        previous plan shifted by a period (with a spin-up where the arm is still and ``turning``)."""
        prob = self.problem
        u = self._shifted_plan(prob) if self.plan is not None else np.zeros((prob.N, self.model.n))
        u = self._leave_rest(qd, u) if turning else u
        # RTI: a consistent point, not clipped
        x, controls = prob.guess(q, qd, u, a, clip=method != "rti", filters=self.z if prob.nz else None)
        bounds = prob.start_bounds(q, qd, a, self.z, positions=self._placing(q) if place else None)
        if self.model.config.takes_modulus:
            self._one_way(qd, a, bounds)
        return x, controls, bounds

    def prepare(self, state) -> None:
        """The preparation phase of the real-time iteration, between two cycles: the next cycle's QP
        linearised at the plan shifted by a period from ``state`` (where the command just sent leaves the
        machine), so that :meth:`step` from that state, on the next preview, only feeds the preview in
        and solves (Diehl's real-time iteration; the same step to round-off). A step from any other
        state, after :meth:`forget`, or where the preview changes whether the arm is seeded to turn,
        linearises afresh. Nothing is prepared before a first plan, or with IPOPT."""
        if self._rti is None or self.plan is None or self._last_data is None:
            return
        q, qd = (np.asarray(v, dtype=float).reshape(self.model.n) for v in state[:2])
        a = np.asarray(state[2], dtype=float).reshape(self.model.n) if self.smooth else np.zeros_like(q)
        x, controls, bounds = self._linearisation(q, qd, a, self._turning, "rti")
        self._rti.prepare(self.problem.pack(x, controls), np.asarray(self._last_data).ravel(order="F"), bounds)
        self._prepared = self._key(q, qd, a, self._turning)

    def _key(self, q, qd, a, turning) -> tuple:
        """What a prepared QP was linearised for: the start, the plan shifted and its age, the felt
        filter state and whether the arm is seeded to turn."""
        return (q.tobytes(), qd.tobytes(), a.tobytes(), id(self.plan), self.plan_age, turning,
                None if self.z is None else self.z.tobytes())

    def _placing(self, q) -> tuple[np.ndarray, np.ndarray]:
        """Bounds on the start's positions when it is placed: each joint within its limits, except
        the arm, which stays at ``q``: with gravity along its axis its angle changes nothing felt."""
        lower, upper = self.problem.position_bounds()
        if self.model.config.turns_arm:
            k = self.model.config.yaw
            lower[k] = upper[k] = q[k]
        return lower, upper

    def _one_way(self, qd, a, bounds) -> None:
        """Keep the arm turning the way it turns (forwards from rest) over the plan: bounds on the
        yaw's rate, from the first node at which its acceleration can have been brought to zero (|a| /
        jerk limit after now), in the direction of the rate it then has at the soonest, qd + a |a| / (2
        jerk limit): a plan that must still cross zero rate is not made infeasible.

        The modulus cues of ``dfs`` and ``dfs-yaw`` are the same for either direction of turning
        ("without influencing the optimization results, q1' can be assumed positive", 7.4.2), so the
        cue has a mirror image of every plan, and a plan linearised on a slowing arm can slide into
        the mirror: through zero rate (where the modulus is only g) and up the other way, instead of
        speeding up again (docs/benchmarks/one-way-arm-on-dfs.md).
        """
        prob, k = self.problem, self.model.config.yaw
        jerk = self.limits.jerk[k] if self.smooth else np.inf
        settle = abs(a[k]) / jerk
        rate = settled_rate(qd[k], a[k], jerk)
        first = max(1, int(np.searchsorted(prob.t_nodes - prob.t_nodes[0], settle - 1e-12)))
        prob.keep_rate_sign(bounds, k, first, 1.0 if rate >= 0.0 else -1.0)

    def _per_step(self, accelerations, jerks) -> tuple[np.ndarray, np.ndarray]:
        """A plan's (accelerations, jerks) per interval as the same plan per step (the grid's intervals
        are whole numbers of steps): each step starts where the ramp of its interval is."""
        jerks = np.repeat(jerks, self._counts, axis=0)
        return np.repeat(accelerations, self._counts, axis=0) + jerks * self._offsets, jerks

    def _shifted_plan(self, prob: CueingProblem) -> np.ndarray:
        """(N, n) the previous plan's accelerations from now on, on the problem's grid: at each
        interval's end with jerk limits (what the ramp of :meth:`CueingProblem.guess` aims at), at its
        start without; held at the last value past the plan's end, within the limits."""
        accelerations, jerks = self.plan
        times = np.arange(len(accelerations) + 1) * self.options.step
        previous = Plan(times, np.zeros(self.model.n), np.zeros(self.model.n), accelerations, jerks)
        now = (self.plan_age + self.options.replan_steps) * self.options.step
        times = now + (prob.t_nodes[1:] if self.smooth else prob.t_nodes[:-1])
        at = previous.accelerations_at(np.minimum(times, prob.t_nodes[-1]))
        return np.clip(at, -self.limits.acceleration, self.limits.acceleration)

    def _leave_rest(self, qd, u) -> np.ndarray:
        """The seed ``u`` (N, n), with a spin-up of the yaw where it would otherwise stay still.

        Zero yaw rate is a stationary point of the cue: the centripetal terms and the modulus have no gradient
        there, so a solve linearised at a still yaw returns a still yaw forever, and a run from rest never turns the
        arm. Where the yaw's fastest rate over the seed is below ``REST_RATE``, the seed's yaw acceleration is drawn
        towards ``options.spin_up`` times its limit (in the direction it already turns), the more the stiller it is:
        the linearisation then sees what turning would give, and the solve decides whether to turn
        (docs/benchmarks/spin-up-from-rest.md). Drawn by degrees, not switched: a seed switched to a spin-up whenever a slow turn dipped below the
        threshold kicked every joint each time (docs/benchmarks/damped-real-time-iteration.md). Not seeded where the preview asks for
        a modulus of g or less (:meth:`_solve`'s ``turning``, docs/benchmarks/a-steady-spin-of-the-cabin-on-dfs.md).
        """
        if not self.model.config.turns_arm or self.options.spin_up == 0.0:
            return u
        k = self.model.config.yaw
        rates = qd[k] + np.cumsum(u[:, k] * self.problem.steps)
        stillness = 1.0 - float(np.max(np.abs(rates))) / REST_RATE
        if stillness <= 0.0:
            return u
        u = u.copy()
        spin = (1.0 if qd[k] >= 0 else -1.0) * self.options.spin_up * self.limits.acceleration[k]
        u[:, k] += stillness * (spin - u[:, k])
        return u

    def _safe(self, q, qd, qdd, jerk) -> bool:
        """Every limit over the coming step with this command, to the independent check's tolerance."""
        return float(np.max(call(self._limit_use, q, qd, qdd, jerk))) <= 1.0 + TOLERANCE

    def _safe_sequence(self, state: State, sequence, jerks) -> bool:
        """:meth:`_safe` for every step of a sequence of accelerations and jerks, from ``state`` on; with
        jerk limits each step must start at the acceleration the last one ended with, and :meth:`brake`
        must be able to stop the state it leaves within the travel (:func:`~desdemona.machine.plan.stopping_extent`)
        and the velocity limits (qd + a |a| / 2J): a one-QP plan keeps its own such rows to first order."""
        lim = self.limits
        for qdd, jerk in zip(sequence, jerks):
            jumps = self.smooth and np.any(np.abs(qdd - state.a) > TOLERANCE * lim.acceleration)
            if jumps or not self._safe(state.q, state.qd, qdd, jerk):
                return False
            state = state.advance(qdd, self.options.step, jerk)
        if not self.smooth:  # a constant deceleration: the plans' own stopping rows suffice
            return True
        low, high = stopping_extent(state.q, state.qd, state.a, lim.acceleration, lim.jerk, self.options.step)
        settles = np.abs(settled_rate(state.qd, state.a, lim.jerk)) <= lim.velocity * (1.0 + TOLERANCE)
        return bool(np.all((high <= lim.position_max) & (low >= lim.position_min) & settles))

    def _fallback(self, state: State, reason: str, start: float) -> Command:
        r, most = self.options.replan_steps, round(SHIFT_MAX / self.options.step)
        if self.plan is not None and self.plan_age + 2 * r <= min(len(self.plan[0]), most):
            self.plan_age += r
            window = slice(self.plan_age, self.plan_age + r)
            sequence, jerks = self.plan[0][window], self.plan[1][window]
            if self._safe_sequence(state, sequence, jerks):
                return Command(sequence.copy(), "shifted", time.perf_counter() - start, reason, jerks.copy())
        self.plan, sequence, jerks = None, [], []  # a fresh seed for the next plan
        self.braked += r
        for _ in range(r):
            qdd, jerk = self.brake(*state)
            sequence.append(qdd)
            jerks.append(jerk)
            state = state.advance(qdd, self.options.step, jerk)
        return Command(np.array(sequence), "brake", time.perf_counter() - start, reason, np.array(jerks))

    def brake(self, q, qd, a=None) -> tuple[np.ndarray, np.ndarray]:
        """The step's (acceleration, jerk) towards rest, and after :data:`HOMING_AFTER` of braking in a
        row towards home (:meth:`homing`), that keeps every limit over the step: with jerk limits
        :func:`~desdemona.machine.plan.braking_jerk`, without them the strongest change of rate (at most
        ``braking`` x the acceleration limit); scaled down until safe."""
        lim, h, zero = self.limits, self.options.step, np.zeros_like(qd)
        most, a = self.options.braking * lim.acceleration, zero if a is None else np.asarray(a, dtype=float)
        goal = self.homing(q, qd) if self.braked * h >= HOMING_AFTER else zero  # a lasting outage
        full = braking_jerk(q, qd, a, h, lim, self.options.braking, goal) if self.smooth else np.clip((goal - qd) / h, -most, most)
        commands = [(a, s * full) if self.smooth else (s * full, zero) for s in (1.0, 0.75, 0.5, 0.25, 0.1, 0.0)]
        for qdd, jerk in commands:
            if self._safe(q, qd, qdd, jerk):
                return qdd, jerk
        # the last resort (the independent check reports any excess): the whole jerk, or holding
        return commands[0] if self.smooth else commands[-1]

    def homing(self, q, qd) -> np.ndarray:
        """The rates that take a braked machine home (:func:`~desdemona.machine.plan.homing_rate`): where a still
        machine cues the last present force best (:func:`~desdemona.baselines.classical.still_home`)."""
        force = None if self.present is None else self.present[3:]
        home = still_home(q, self.model, force)
        return homing_rate(q, qd, home, np.isin(np.arange(len(q)), self.limits.bounded), self.model.config.yaw)

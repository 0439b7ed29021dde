"""The baselines to beat: the classical dynamic-flight-simulator loop and the thesis' own optimiser.

- :func:`classical_dfs`: the control loop that dynamic flight simulators use for the central yaw
  (thesis 7.4.2, figure 7.4): the yaw rate that would give the desired modulus in steady rotation,
  qd1_ref = sqrt(sqrt(M_d^2 - g^2) / R) (the inversion of eq. 7.7 without yaw acceleration), tracked by
  a rate- and acceleration-limited first-order loop. Its result (a :class:`~desdemona.plan.Plan`) gives
  the thesis' M_org.
- :func:`optimize_thesis`: the numerical method of chapters 4-5, reproduced on purpose as it was:
  unknowns qdd per control interval (and optionally the initial state, 5.2), Runge-Kutta integration
  on the step h_itr, the cost as a sum over the samples of S_d (eq. 4.1, 4.3), limits as barrier terms
  in the cost (quadratic, eq. B.13 / 4.7, or the 'if' barrier of eq. 5.2), a trust-region
  least-squares solver with finite-difference Jacobian (scipy ``least_squares``), an iteration cap and
  the stop on a small change of the cost (5.4), and seeded random multi-start (4.7).
"""

from __future__ import annotations

import math
import time
from dataclasses import dataclass
from typing import Literal

import numpy as np
import scipy.optimize
import scipy.signal

from desdemona.model import Model
from desdemona.plan import Plan, advance
from desdemona.profiles import DesiredPath

DFS_RADIUS = 4.0  # |q2| of the dfs configuration [m]


def classical_dfs(path: DesiredPath, model: Model, times=None, gain: float = 10.0, state=None) -> Plan:
    """The classical yaw loop of figure 7.4 on the dfs configuration.

    path : desired modulus M_d (from its S_d or given); model : a dfs Model (its limits are respected:
    yaw rate, acceleration, torque and power); times : grid to run the loop on (default the path's);
    gain : bandwidth of the rate loop [1/s]; state : the yaw's (q0, qd0) at the start, by default
    turning at the reference rate of the first sample (as an off-line guess).
    Returns the yaw's plan on ``times``.
    """
    t = path.t if times is None else np.asarray(times, dtype=float)
    M_d = path.sample_modulus(t)
    g = model.params.gravity
    radius = abs(model.config.fixed[1]) if model.config.modulus_cost else DFS_RADIUS
    lim = model.limits
    reference = np.sqrt(np.sqrt(np.maximum(M_d**2 - g**2, 0.0)) / radius)
    reference = np.minimum(reference, lim.velocity[0])
    inertia = float(model.mass_matrix(np.zeros(1))[0, 0])  # yaw inertia: constant in dfs
    u = np.zeros(len(t) - 1)
    q0, rate0 = (np.zeros(1), reference[0]) if state is None else (np.reshape(state[0], 1), float(state[1][0]))
    rate = rate0
    for k in range(len(t) - 1):
        h = t[k + 1] - t[k]
        # the most acceleration that torque and power allow at this rate (tau = I qdd for dfs)
        a_max = min(lim.acceleration[0], lim.effort[0] / inertia,
                    lim.power[0] / (inertia * max(abs(rate), 1e-9)))
        # rate command: do not overshoot the reference within one step, nor the rate limit
        a = np.clip(gain * (reference[k + 1] - rate), -a_max, a_max)
        a = np.clip(a, (-lim.velocity[0] - rate) / h, (lim.velocity[0] - rate) / h)
        u[k] = a
        rate = rate + a * h
    return Plan(t, q0, [rate0], u[:, None])


@dataclass(frozen=True)
class Washout:
    """Settings of the classical washout (:func:`classical_washout`), after Reid & Nahon's classical
    algorithm; assumptions chosen for Desdemona's 8 m track and 2 m heave, not the thesis'.

    omega_hp, zeta_hp : second-order high-pass of the specific force sent to the track and heave
    [rad/s, -]; omega_centre, zeta_centre : the spring that washes them back to the centre;
    omega_lp, zeta_lp : second-order low-pass of f_x, f_y for tilt coordination; tilt_rate : the
    largest tilt rate [rad/s], at the perception threshold so that the tilt is not felt as rotation;
    omega_rot : first-order high-pass of the angular velocity [rad/s]; gain : scale of S_d - rest.
    The defaults had the lowest mean RMS of a small grid (omega_hp 0.5-1.5, omega_centre 0.2-0.5, gain
    0.5-1) over the catapult, car lap, cosine and double pulse on yaw-track and full.
    """

    omega_hp: float = 0.5
    zeta_hp: float = 0.7
    omega_centre: float = 0.5
    zeta_centre: float = 1.0
    omega_lp: float = 2.0
    zeta_lp: float = 0.7
    tilt_rate: float = math.radians(3.0)
    omega_rot: float = 0.5
    gain: float = 0.5


def _filtered(numerator, denominator, u, dt) -> np.ndarray:
    """The response of a continuous SISO filter to ``u`` (K,) sampled at ``dt``, inputs held (ZOH),
    from a zero state."""
    b, a, _ = scipy.signal.cont2discrete((numerator, denominator), dt, method="zoh")
    return scipy.signal.lfilter(np.ravel(b), a, u)


def classical_washout(path: DesiredPath, model: Model, times=None, settings: Washout = Washout(),
                      state=None) -> Plan:
    """The classical washout a motion simulator runs today, on the yaw-track, yaw-track-cabin and
    full configurations (Reid & Nahon's classical algorithm, with tilt coordination where the cabin
    can tilt).

    - Translational: f_y (track) and f_z - g (heave) through a second-order high-pass, plus a spring
      that washes the joint back to its centre.
    - Tilt coordination (full): the low-passed f_x and f_y held by tilting the cabin (q6 pitch: f_x
      = -g sin q6; q4 roll: f_y = g sin q4), at most ``tilt_rate``, below the rotation threshold.
    - Rotational: omega_z through a first-order high-pass as the yaw's rate (omega_x, omega_y the same
      on the gimbals where they are free).

    Every command then passes the limits: acceleration, a braking distance to the position limits,
    and torque, power and rate over the step (:meth:`Model.step_limit_use`), scaled down until it does.
    Returns the free joints' plan on ``times`` (default: the path's grid), from ``state`` (rest).
    """
    o = settings
    t = path.t if times is None else np.asarray(times, dtype=float)
    dt = float(np.min(np.diff(t)))
    S_d = path.sample(t)
    g = model.params.gravity
    rest = np.array([0.0, 0.0, 0.0, 0.0, 0.0, g])
    S_d = rest + o.gain * (S_d - rest)
    free, lim = model.config.free, model.limits
    hp2 = ([1.0, 0.0, 0.0], [1.0, 2 * o.zeta_hp * o.omega_hp, o.omega_hp**2])
    lp2 = ([o.omega_lp**2], [1.0, 2 * o.zeta_lp * o.omega_lp, o.omega_lp**2])
    hp1 = ([1.0, 0.0], [1.0, o.omega_rot])
    # per free joint: what it follows
    target_acc = np.zeros((len(t), model.n))  # translational: high-passed specific force
    target_rate = np.zeros((len(t), model.n))  # rotational: high-passed angular velocity
    target_angle = np.full((len(t), model.n), np.nan)  # tilt coordination
    for k, joint in enumerate(free):
        if joint == 1:
            target_acc[:, k] = _filtered(*hp2, S_d[:, 4], dt)
        elif joint == 2:
            target_acc[:, k] = _filtered(*hp2, S_d[:, 5] - g, dt)
        elif joint in (0, 4) and (joint == 0 or 0 not in free):
            target_rate[:, k] = _filtered(*hp1, S_d[:, 2], dt)
        elif joint == 3:
            target_rate[:, k] = _filtered(*hp1, S_d[:, 0], dt)
            target_angle[:, k] = np.arcsin(np.clip(_filtered(*lp2, S_d[:, 4], dt) / g, -0.5, 0.5))
        elif joint == 5:
            target_rate[:, k] = _filtered(*hp1, S_d[:, 1], dt)
            target_angle[:, k] = -np.arcsin(np.clip(_filtered(*lp2, S_d[:, 3], dt) / g, -0.5, 0.5))
    prismatic = np.array([model.params.joints[j].kind == "prismatic" for j in free])
    tilt = ~np.isnan(target_angle[0])
    use = model.step_limit_use(dt)
    q, qd = (np.zeros(model.n), np.zeros(model.n)) if state is None else (np.array(state[0], float),
                                                                          np.array(state[1], float))
    q0, qd0 = q.copy(), qd.copy()
    u = np.zeros((len(t) - 1, model.n))
    wc, zc = o.omega_centre, o.zeta_centre
    for k in range(len(t) - 1):
        a = np.where(prismatic, target_acc[k] - wc**2 * q - 2 * zc * wc * qd, (target_rate[k] - qd) / 0.1)
        if tilt.any():  # follow the tilt angle with the rate below the threshold
            rate = np.clip((np.nan_to_num(target_angle[k]) - q) * 2.0, -o.tilt_rate, o.tilt_rate) + target_rate[k]
            a = np.where(tilt, (rate - qd) / 0.1, a)
        a = np.clip(a, -lim.acceleration, lim.acceleration)
        # room to brake before a position limit at half the acceleration limit
        for i in lim.bounded:
            brake = 0.5 * lim.acceleration[i]
            room_hi = np.sqrt(2 * brake * max(lim.position_max[i] - q[i], 0.0))
            room_lo = -np.sqrt(2 * brake * max(q[i] - lim.position_min[i], 0.0))
            a[i] = np.clip(a[i], (room_lo - qd[i]) / dt, (room_hi - qd[i]) / dt)
        a = np.clip(a, -lim.acceleration, lim.acceleration)
        for scale in (1.0, 0.75, 0.5, 0.25, 0.0):
            if float(np.max(np.asarray(use(q, qd, scale * a)))) <= 1.0:
                break
        u[k] = scale * a
        q, qd = advance(q, qd, u[k], dt)
    return Plan(t, q0, qd0, u)


@dataclass(frozen=True)
class ThesisOptions:
    """The thesis method's settings (chapters 4-5).

    h_u : control step [s]; h_itr : Runge-Kutta step [s]; h_S : step of the cost samples [s], None for
    the path's own samples (the thesis: h_S = 0.1 s, h_itr = 0.05 s, section 5.3); barrier : "quadratic" (eq. B.13 with
    a, b, c of 4.7) or "if" (eq. 5.2, starting at ``onset`` of each limit); barrier_weight : weight of
    the 'if' barrier per sample; optimize_initial : include q(0), qd(0) in the unknowns (5.2);
    max_iter : iteration cap (40 in 4.7); min_cost_change : stop when the cost changes less (0.1 in
    5.4); starts, seed : seeded random multi-start.
    """

    h_u: float = 0.1
    h_itr: float = 0.05
    h_S: float | None = 0.1
    barrier: Literal["quadratic", "if"] = "if"
    barrier_weight: float = 100.0
    onset: float = 3.7 / 4.0
    quadratic: tuple[float, float, float] = (0.1, 1e-3, 1e-5)
    optimize_initial: bool = True
    max_iter: int = 40
    min_cost_change: float = 0.1
    starts: int = 1
    seed: int = 0


@dataclass(frozen=True)
class ThesisRun:
    """One start of the thesis method."""

    plan: Plan
    cost: float
    iterations: int
    evaluations: int
    solve_time: float
    message: str


class ThesisProblem:
    """The residual vector of eq. 4.3/4.4 plus barriers, for a model and a desired path."""

    def __init__(self, model: Model, path: DesiredPath, options: ThesisOptions):
        self.model, self.path, self.options = model, path, options
        self.N = max(1, int(round(path.duration / options.h_u)))
        self.t_nodes = path.t[0] + options.h_u * np.arange(self.N + 1)
        # cost samples every h_S (5.3), on the path's own grid when h_S is None
        end = min(self.t_nodes[-1], path.t[-1])
        self.samples = (path.t[path.t <= end + 1e-12] if options.h_S is None
                        else path.t[0] + options.h_S * np.arange(int(round((end - path.t[0]) / options.h_S)) + 1))
        self.weights = np.sqrt(np.asarray(path.weights, float))
        # Runge-Kutta on h_itr, then states at the samples (5.3): the step fits the control grid
        self.steps = max(1, int(math.ceil(options.h_u / options.h_itr - 1e-9)))

    def unpack(self, z):
        n = self.model.n
        if self.options.optimize_initial:
            return z[:n], z[n:2 * n], z[2 * n:].reshape(self.N, n)
        return np.zeros(n), np.zeros(n), z.reshape(self.N, n)

    def pack(self, q0, qd0, u):
        u = np.asarray(u, float).ravel()
        return np.r_[q0, qd0, u] if self.options.optimize_initial else u

    def states(self, q0, qd0, u):
        """States at the cost samples: Runge-Kutta on h_itr, then from the last node to each sample.

        For the double integrator with qdd held, the classical RK4 step reduces algebraically to
        q+ = q + h qd + h^2 qdd / 2, qd+ = qd + h qdd (its stages are k1 = (qd, u), k2 = k3 =
        (qd + h u / 2, u), k4 = (qd + h u, u)); it is applied here to all steps at once with
        cumulative sums, the same numbers as stepping, without Python-loop overhead. The step is
        written out in the RK4 reduction's own order of operations rather than through
        :func:`desdemona.plan.advance`: the method differentiates by finite differences, which turn a
        change of round-off into a different run (measured: 22 instead of 24 iterations on 4.7), and
        this baseline must reproduce its published figures to the bit.
        """
        h = self.options.h_u / self.steps
        steps = np.repeat(u, self.steps, axis=0)
        qd_all = np.vstack([qd0, qd0 + np.cumsum(h * steps, axis=0)])
        q_all = np.vstack([q0, q0 + np.cumsum(h * qd_all[:-1] + 0.5 * h * h * steps, axis=0)])
        q_nodes, qd_nodes = q_all[:: self.steps], qd_all[:: self.steps]
        k = np.clip(np.searchsorted(self.t_nodes, self.samples, side="right") - 1, 0, self.N - 1)
        q, qd = advance(q_nodes[k], qd_nodes[k], u[k], (self.samples - self.t_nodes[k])[:, None])
        return q, qd, u[k]

    def residuals(self, z) -> np.ndarray:
        q0, qd0, u = self.unpack(z)
        q, qd, qdd = self.states(q0, qd0, u)
        model, lim, o = self.model, self.model.limits, self.options
        S = model.S(q, qd, qdd)
        tau = model.tau(q, qd, qdd)
        if model.config.modulus_cost:
            error = (np.linalg.norm(S[:, 3:], axis=1) - self.path.sample_modulus(self.samples))[:, None]
        else:
            error = (S - self.path.sample(self.samples)) * self.weights
        parts = [error.ravel()]
        if o.barrier == "quadratic":
            a, b, c = o.quadratic
            prismatic = np.array([model.params.joints[i].kind == "prismatic" for i in model.config.free])
            parts.append((math.sqrt(a) * q[:, prismatic]).ravel())
            parts.append((np.where(prismatic, math.sqrt(c), math.sqrt(b)) * tau).ravel())
        else:
            bounded = np.isfinite(lim.position_max)
            for value, limit in ((q[:, bounded], lim.position_max[bounded]), (qd, lim.velocity),
                                 (qdd, lim.acceleration), (tau, lim.effort),
                                 (tau * qd, lim.power)):
                x = value / limit
                over = np.abs(x) > o.onset
                parts.append((math.sqrt(o.barrier_weight) * np.where(over, x**2 - o.onset**2, 0.0)).ravel())
        return np.concatenate(parts)

    def random_start(self, rng: np.random.Generator) -> np.ndarray:
        lim = self.model.limits
        lo = np.where(np.isfinite(lim.position_min), 0.5 * lim.position_min, -np.pi)
        hi = np.where(np.isfinite(lim.position_max), 0.5 * lim.position_max, np.pi)
        n = self.model.n
        q0 = rng.uniform(lo, hi)
        qd0 = rng.uniform(-0.5, 0.5, n) * lim.velocity
        u = rng.uniform(-0.2, 0.2, (self.N, n)) * lim.acceleration
        return self.pack(q0, qd0, u)

    def solve(self, z0) -> ThesisRun:
        o = self.options
        history, why = [], []

        def stop(intermediate_result):
            # 5.4: stop when the cost (with barriers) changes by less than min_cost_change
            history.append(2.0 * intermediate_result.cost)
            if len(history) >= o.max_iter:
                why.append(f"iteration cap ({o.max_iter})")
                raise StopIteration
            if len(history) > 1 and abs(history[-2] - history[-1]) < o.min_cost_change:
                why.append(f"cost change below {o.min_cost_change:g} (5.4)")
                raise StopIteration

        start = time.perf_counter()
        result = scipy.optimize.least_squares(self.residuals, z0, jac="2-point", method="trf",
                                              callback=stop, max_nfev=50 * o.max_iter)
        elapsed = time.perf_counter() - start
        q0, qd0, u = self.unpack(result.x)
        if not o.optimize_initial:
            q0, qd0 = np.zeros(self.model.n), np.zeros(self.model.n)
        message = f"stopped: {why[0]}" if why else str(result.message)
        return ThesisRun(Plan(self.t_nodes.copy(), q0, qd0, u), float(2.0 * result.cost), len(history),
                         int(result.nfev), elapsed, message)


def optimize_thesis(path: DesiredPath, model: Model, options: ThesisOptions = ThesisOptions()):
    """Run the thesis method from ``options.starts`` seeded random starts; every run, best first by cost.

    The runs are not checked here: the caller checks them with :func:`desdemona.simulate.check`, as it
    does ours, because barrier terms do not guarantee the limits.
    """
    problem = ThesisProblem(model, path, options)
    rng = np.random.default_rng(options.seed)
    runs = [problem.solve(problem.random_start(rng)) for _ in range(options.starts)]
    return problem, sorted(runs, key=lambda r: r.cost)

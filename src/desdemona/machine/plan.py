"""A joint plan: piecewise-linear (or piecewise-constant) accelerations from an initial state (thesis 4.2, 5.3).

Every optimiser and controller of desdemona commands the free joints' accelerations over the intervals
of a control grid: on interval k the acceleration starts at ``u[k]`` and changes at the constant jerk
``jerk[k]``. Between two nodes the motion is then the exact triple integral::

    q(t_k + s) = q_k + qd_k s + u_k s^2 / 2 + j_k s^3 / 6,    qd(t_k + s) = qd_k + u_k s + j_k s^2 / 2,
    qdd(t_k + s) = u_k + j_k s.

On a machine with jerk limits the accelerations are continuous, u[k + 1] = u[k] + jerk[k] h_k, and the
jerk is bounded everywhere; without them (the thesis' setting, section 5.3) jerk is zero and the
accelerations are held constant per interval, stepping at the nodes.

:func:`advance` is the one place this formula lives (:meth:`State.advance` carries a whole state with it); it takes floats, NumPy arrays and CasADi symbols
alike, so the optimisers' transcription, the MPC's limit check, the plant simulation and the
independent check all use the same definition. :class:`Plan` is the value every off-line result,
closed-loop run and baseline returns: the grid, the initial state and the accelerations, evaluated at
any time with :meth:`Plan.at`.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import NamedTuple

import numpy as np


def advance(q, qd, qdd, s, jerk=None):
    """Position and rate after ``s`` seconds from acceleration ``qdd`` changing at ``jerk`` (held
    constant where ``jerk`` is None): the exact integral.

    q, qd, qdd, jerk : (n,) or broadcastable arrays [rad | m, /s, /s^2, /s^3], or CasADi expressions;
    s [s]. Returns (q + qd s + qdd s^2 / 2 + jerk s^3 / 6, qd + qdd s + jerk s^2 / 2).
    """
    if jerk is None:
        return q + qd * s + 0.5 * qdd * s * s, qd + qdd * s
    return q + qd * s + 0.5 * qdd * s * s + jerk * (s * s * s / 6.0), qd + qdd * s + 0.5 * jerk * s * s


class State(NamedTuple):
    """The free joints' motion at one instant: positions q, rates qd and accelerations a, (n,) each
    (a tuple, as :meth:`desdemona.control.mpc.MPC.step` takes a measured state)."""

    q: np.ndarray
    qd: np.ndarray
    a: np.ndarray

    def advance(self, qdd, h: float, jerk) -> State:
        """The state ``h`` seconds on, the acceleration starting at ``qdd`` and changing at ``jerk``
        (:func:`advance`; the acceleration then is qdd + jerk h)."""
        q, qd = advance(self.q, self.qd, qdd, h, jerk)
        return State(q, qd, qdd + jerk * h)


def node_states(q0, qd0, u, h, jerk=None) -> tuple[np.ndarray, np.ndarray]:
    """Positions and rates (N + 1, n) at the nodes of accelerations ``u`` (N, n) starting each
    interval of ``h`` [s] (a scalar, or (N, 1) steps), changing at ``jerk`` (N, n) or held where it is
    None, from (q0, qd0): the intervals' :func:`advance` summed up."""
    u = np.asarray(u, dtype=float)
    jerk = np.zeros_like(u) if jerk is None else np.asarray(jerk, dtype=float)
    _, dqd = advance(0.0, 0.0, u, h, jerk)
    qd = np.vstack([qd0, qd0 + np.cumsum(dqd, axis=0)])
    steps, _ = advance(0.0, qd[:-1], u, h, jerk)
    return np.vstack([q0, q0 + np.cumsum(steps, axis=0)]), qd


def ramp(accelerations, h, a0=None, jerk_max=None) -> tuple[np.ndarray, np.ndarray]:
    """Continuous accelerations that follow ``accelerations`` (N, n), one target per interval of ``h``
    [s]: each interval ramps from where the last one ended towards its target at a jerk of at most
    ``jerk_max`` (n,) (exactly onto it where the limit allows). Returns the interval-start
    accelerations (N, n) and jerks (N, n) of a :class:`Plan`; a0 : (n,) the acceleration at the start
    (default the first target, reached at once); h may also be (N,) or (N, 1) steps."""
    targets = np.asarray(accelerations, dtype=float)
    N, n = targets.shape
    steps = np.broadcast_to(np.asarray(h, dtype=float).reshape(-1), (N,)).tolist()
    a = (targets[0] if a0 is None else np.broadcast_to(np.asarray(a0, dtype=float), (n,))).tolist()
    limits = np.broadcast_to(np.inf if jerk_max is None else np.asarray(jerk_max, dtype=float), (n,)).tolist()
    starts, jerks = [], []
    # one joint at a time in Python floats: a controller builds its guess this way every cycle, and a
    # loop over the intervals in NumPy took 0.4 ms of it for 56 intervals (now 0.07 ms, the same bits)
    for column, a_i, limit in zip(targets.T.tolist(), a, limits):
        starts.append(row_starts := [])
        jerks.append(row_jerks := [])
        for target, step in zip(column, steps):
            jerk = (target - a_i) / step
            jerk = limit if jerk > limit else (-limit if jerk < -limit else jerk)
            row_starts.append(a_i)
            row_jerks.append(jerk)
            a_i += jerk * step
    starts, jerks = np.array(starts, dtype=float).reshape(n, N).T, np.array(jerks, dtype=float).reshape(n, N).T
    return starts, jerks


def start_state(state, n: int) -> tuple[np.ndarray, np.ndarray]:
    """(q0, qd0), each (n,), from ``state`` = (positions, rates) of n joints, or rest at the centre
    (zeros) where ``state`` is None. A clear error unless both are n finite numbers."""
    if state is None:
        return np.zeros(n), np.zeros(n)
    q0, qd0 = (np.asarray(v, dtype=float).reshape(-1) for v in state[:2])
    if q0.shape != (n,) or qd0.shape != (n,) or not (np.all(np.isfinite(q0)) and np.all(np.isfinite(qd0))):
        raise ValueError(f"an initial state needs {n} finite positions and {n} finite rates, one per free joint")
    return q0, qd0


def start_acceleration(state, n: int) -> np.ndarray:
    """(n,) accelerations of a start ``state`` = (positions, rates[, accelerations]) of n joints: its
    third entry where it has one, else zero (a machine at rest, or moving steadily)."""
    if state is None or len(state) < 3:
        return np.zeros(n)
    a0 = np.asarray(state[2], dtype=float).reshape(-1)
    if a0.shape != (n,) or not np.all(np.isfinite(a0)):
        raise ValueError(f"an initial state's accelerations must be {n} finite numbers, one per free joint")
    return a0


@dataclass(frozen=True, eq=False)
class Plan:
    """Accelerations ``u`` at the start of each interval of ``t_nodes``, changing at ``jerk`` over it,
    from the state (q0, qd0).

    t_nodes : (N + 1,) control grid [s]; q0, qd0 : (n,) initial positions and rates of the free joints;
    u : (N, n) joint accelerations at t_nodes[k]; jerk : (N, n) their constant rate of change until
    t_nodes[k + 1], or None for accelerations held constant over each interval (zero jerk).
    """

    t_nodes: np.ndarray
    q0: np.ndarray
    qd0: np.ndarray
    u: np.ndarray
    jerk: np.ndarray | None = None

    def __post_init__(self):
        if self.jerk is None:
            object.__setattr__(self, "jerk", np.zeros_like(np.asarray(self.u, dtype=float)))
        for name in ("t_nodes", "q0", "qd0", "u", "jerk"):
            object.__setattr__(self, name, np.asarray(getattr(self, name), dtype=float))
        if self.u.ndim != 2 or len(self.t_nodes) != len(self.u) + 1 or self.jerk.shape != self.u.shape:
            raise ValueError(f"a plan needs (N + 1,) nodes and (N, n) accelerations and jerks, got "
                             f"{self.t_nodes.shape}, {self.u.shape} and {self.jerk.shape}")

    @property
    def n(self) -> int:
        """Number of joints."""
        return self.u.shape[1]

    @property
    def duration(self) -> float:
        return float(self.t_nodes[-1] - self.t_nodes[0])

    def nodes(self) -> tuple[np.ndarray, np.ndarray]:
        """Positions and rates (N + 1, n) at the nodes, accumulated exactly."""
        return node_states(self.q0, self.qd0, self.u, np.diff(self.t_nodes)[:, None], self.jerk)

    def acceleration_jumps(self) -> np.ndarray:
        """(N - 1, n) steps of the acceleration at the inner nodes: the next interval's start minus
        where this one ends (zero for a plan with continuous accelerations)."""
        ends = self.u + self.jerk * np.diff(self.t_nodes)[:, None]
        return self.u[1:] - ends[:-1]

    def at(self, times) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Positions, rates and accelerations (K, n) at ``times`` (K,) [s].

        Each time belongs to the interval that starts at or before it (the last node to the last
        interval); it is reached from that interval's node state.
        """
        q_nodes, qd_nodes = self.nodes()
        k, s = self._intervals(times)
        q, qd = advance(q_nodes[k], qd_nodes[k], self.u[k], s, self.jerk[k])
        return q, qd, self.u[k] + self.jerk[k] * s

    def accelerations_at(self, times) -> np.ndarray:
        """The accelerations (K, n) of :meth:`at`, without integrating the positions and rates (a
        controller reads its last plan so every cycle)."""
        k, s = self._intervals(times)
        return self.u[k] + self.jerk[k] * s

    def _intervals(self, times) -> tuple[np.ndarray, np.ndarray]:
        """Per time (K,): the interval it belongs to (the one that starts at or before it, the last
        node to the last interval) and the time since that interval's start (K, 1)."""
        times = np.asarray(times, dtype=float)
        k = np.clip(np.searchsorted(self.t_nodes, times, side="right") - 1, 0, len(self.u) - 1)
        return k, (times - self.t_nodes[k])[:, None]

    def states(self) -> np.ndarray:
        """Node states (N + 1, 2n): positions then rates."""
        return np.hstack(self.nodes())


def stopping_jerk(qd, a, h: float, A, J) -> np.ndarray:
    """Per joint the jerk of the coming step [/s^3] of a stop as quick as the limits allow: the
    acceleration turned against the motion at up to the jerk limit ``J``, held at ``A``, and turned back
    to zero so that the rate reaches zero as the acceleration does. Of the jerks in [-J, J] it takes the
    one that brakes most while the rate, were the acceleration then taken to zero at ``J``, does not
    pass zero, and the acceleration stays within ``A`` (qd, a, A, J: (n,) per joint; h [s]).

    In closed form: with u and b the rate and acceleration along the motion and c = b + k h the
    acceleration the step leaves, the rate left after the step and the ramp is u + b h / 2 + c h / 2 +
    c |c| / 2J, increasing in c; it is zero at c = 2R / (h / 2 + sqrt(h^2 / 4 + 2 |R| / J)), R = -(u +
    b h / 2). The jerk is raised by a few units of round-off where that root leaves the rate a hair
    below zero.
    """
    qd, a = np.asarray(qd, dtype=float), np.asarray(a, dtype=float)
    J = np.asarray(J, dtype=float) * np.ones_like(qd)
    s = np.where(qd != 0.0, np.sign(qd), -np.sign(a))  # the direction of motion
    u, b = s * qd, s * a  # rate and acceleration along it

    def left(k):  # the rate left along it after the step and a ramp of the acceleration to zero
        return settled_rate(u + b * h + 0.5 * k * h * h, b + k * h, J)

    R = -(u + 0.5 * b * h)
    k = (2.0 * R / (0.5 * h + np.sqrt(0.25 * h * h + 2.0 * np.abs(R) / J)) - b) / h
    bump = 4.0 * np.finfo(float).eps * (np.abs(k) + J)
    for _ in range(8):
        short = (left(k) < 0.0) & (k < J)
        if not short.any():
            break
        k, bump = np.where(short, k + bump, k), 2.0 * bump
    k = np.maximum(k, (-A - b) / h)  # the acceleration no further than A against the motion
    return s * np.clip(k, -J, J)  # -J where even the strongest ramp leaves the rate along the motion


def braked(qd, a, h, A, J=None) -> np.ndarray:
    """(N, n) accelerations, one at the end of each interval of ``h`` (N,) [s], of joints brought to rest
    from rates ``qd`` and accelerations ``a`` (n,) as quickly as the acceleration ``A`` and the jerk
    ``J`` (n,) allow (:func:`stopping_jerk` each interval), then held at rest: a guess that does not
    carry a start's motion on into the position limits. Without ``J`` (no jerk limits) the
    accelerations are held over each interval, as such a plan's are."""
    qd, a = np.array(qd, dtype=float), np.array(a, dtype=float)
    out = np.empty((len(h), len(qd)))
    for k, step in enumerate(np.asarray(h, dtype=float).reshape(-1)):
        if not (qd.any() or a.any()):  # at rest (a start at rest: every guess of a whole solve)
            out[k:] = 0.0
            break
        if J is None:
            out[k] = -np.sign(qd) * np.minimum(A, np.abs(qd) / step)
            qd += out[k] * step
            continue
        jerk = stopping_jerk(qd, a, step, A, J)
        qd += a * step + 0.5 * jerk * step * step
        a += jerk * step
        out[k] = a
    return out


def braking_jerk(q, qd, a, h: float, limits, braking: float, rate=0.0) -> np.ndarray:
    """Per joint the jerk of one step of a brake towards the rate ``rate`` (default rest) [/s^3]: the
    acceleration turned from ``a`` at most at the jerk limit J towards (rate - qd) / T, at most
    ``braking`` x the acceleration limit A, with T = 2 braking A / J + h the time the jerk limit needs
    to build that deceleration up and lose it again (the rate then settles without overshoot). Where
    the travel ahead of a joint is shorter than that approach covers, it stops as quickly as its limits
    allow (:func:`stopping_jerk`). ``limits``: the machine's :class:`~desdemona.machine.configs.Limits`."""
    A, J = limits.acceleration, limits.jerk
    T = 2.0 * braking * A / J + h
    target = np.clip((rate - qd) / T, -braking * A, braking * A)
    full = np.clip((target - a) / h, -J, J)
    ahead = np.where(qd > 0, limits.position_max - q, q - limits.position_min)  # inf without an end
    short = ahead < np.abs(qd) * (T + (np.abs(a) + A) / J + h)
    return np.where(short, stopping_jerk(qd, a, h, A, J), full)


#: How fast a braked machine goes home once its arm is still (:func:`homing_rate`): a turning joint at
#: 1 deg/s (three in line at most 3 deg/s, the canals' threshold of roll), the track and heave at 0.03
#: m/s, each slowing in proportion to the way left within the last HOMING_TIME [s] of it, so that it
#: settles without overshoot (0.5 deg/s^2 and 0.015 m/s^2 at most). The brake reaches the rate within
#: its T (0.27 s): 0.11 m/s^2 on the track, under the otoliths' threshold of 0.17
#: (docs/benchmarks/return-home-in-an-outage.md).
HOMING_RATE, HOMING_TIME = (np.radians(1.0), 0.03), 2.0

#: Below this rate [rad/s] the arm counts as still (0.01 m/s^2 of centripetal force at 4 m).
REST_RATE = 0.05


def homing_rate(q, qd, home, linear, arm: int | None) -> np.ndarray:
    """(n,) the rates that take a braked machine ``home`` (n,) slowly, once its arm (joint ``arm`` of
    q, None where it is held) is still, below :data:`REST_RATE`: each joint with a home (not NaN) at
    :data:`HOMING_RATE` (the second of the pair where ``linear``, (n,) bool: the track and heave),
    and within :data:`HOMING_TIME` of home at the way left over that time, -clip(e / HOMING_TIME,
    -rate, rate) with e = q - home. Zero while the arm turns: a cabin tilted into its centripetal
    force stays so. :func:`desdemona.baselines.classical.still_home` says where home is."""
    q, home = np.asarray(q, dtype=float), np.asarray(home, dtype=float)
    if arm is not None and abs(qd[arm]) >= REST_RATE:
        return np.zeros_like(q)
    rate = np.where(linear, HOMING_RATE[1], HOMING_RATE[0])
    return -np.clip(np.nan_to_num(q - home) / HOMING_TIME, -rate, rate)


def stopping_time(qd, a, A, J) -> np.ndarray:
    """Per joint the shortest time [s] to rest from rate ``qd`` and acceleration ``a`` with the
    acceleration within ``A`` and the jerk within ``J`` (continuous time): with b the acceleration along
    the motion and w = |qd| + b^2 / 2J the rate the stop starts from once the acceleration has been
    taken to zero, b / J + w / A + A / J, or b / J + 2 sqrt(w / J) where the stop never reaches A."""
    qd, a = np.asarray(qd, dtype=float), np.asarray(a, dtype=float)
    b = np.where(qd != 0.0, np.sign(qd) * a, -np.abs(a))
    w = np.abs(qd) + b**2 / (2.0 * J)
    return b / J + np.where(w >= A**2 / J, w / A + A / J, 2.0 * np.sqrt(w / J))


def settled_rate(qd, a, J, eps: float = 0.0):
    """The rate a joint has once its acceleration ``a`` is taken to zero at the jerk limit ``J``,
    qd + a |a| / 2J (floats, NumPy arrays or CasADi expressions; ``eps`` > 0 smooths |a| for a
    solver: sqrt(a^2 + eps))."""
    return qd + a * (a * a + eps) ** 0.5 / (2.0 * J)


#: The travel a stop is given beyond :func:`stopping_extent`'s reach, at most, as a share of A h^2 (A
#: the acceleration limit, h the control step): the brake acts in whole steps, a step behind the ideal
#: ramp; 1/2 (1 mm on the track at 20 ms) covers the most a scan of rates and accelerations found it
#: late (0.65 mm). Never more than the reach itself: a joint at rest at its end stays stoppable.
STOP_LAG = 0.5


#: The smoothing of the plans' stopping reach and rate (|x| as sqrt(x^2 + eps), [m^2/s^2]).
STOP_EPS = 1e-8


def settled_rates(qd, a, J, eps: float = STOP_EPS):
    """The highest and the lowest rate a joint can settle at (:func:`settled_rate`), as two convex
    functions of (qd, a) for a solver that takes the limits' curvature: qd + a+^2 / 2J and
    qd - a-^2 / 2J, a+ and a- the acceleration's positive and negative parts (smoothed as
    (x + sqrt(x^2 + eps)) / 2, never below them). Within the velocity limits, ``highest <= V`` and
    ``lowest >= -V`` keep the same states as ``|settled_rate| <= V``: where the acceleration falls,
    the rate only falls. ``settled_rate``'s own a |a| is concave where a < 0: with it active (the
    arm held at its rate limit for a sustained force) the Lagrangian took its negative curvature
    (docs/benchmarks/where-the-sorties-steps-are-cut-and-the.md)."""
    def plus(x):
        return 0.5 * (x + (x * x + eps) ** 0.5)
    return qd + plus(a) ** 2 / (2.0 * J), qd - plus(-a) ** 2 / (2.0 * J)


def stopping_reach(qd, a, B, J, eps: float = STOP_EPS, lag=None):
    """Per joint how far up (towards its upper end) a jerk-limited stop from rate ``qd`` and
    acceleration ``a`` reaches, braking at ``B`` (floats, NumPy arrays or CasADi expressions); how far
    down is ``-stopping_reach(-qd, -a, B, J)``.

    Taking the acceleration to zero at the jerk limit J leaves the rate W = qd + a^2 / 2J (with ``a``
    against the motion: the state lies on a braking ramp that left zero acceleration at that rate
    |a| / J ago). The stop from that zero-acceleration point ramps to -B, holds it and ramps back to
    rest, W^2 / 2B + W B / 2J (exact where the ramp reaches B, above the triangle where it does not);
    with the stretch between that point and now, either way the reach is

        W a / J - a^3 / 6J^2 + W^2 / 2B + W B / 2J,     W = qd + a^2 / 2J,

    a polynomial in (qd, a): smooth where the acceleration changes sign, where a stop that first takes
    the acceleration to zero has a kink (a solver stalls on it). With W below zero the motion never
    turns upwards and W is taken as zero, smoothly: W+ = (W + sqrt(W^2 + eps) - sqrt(eps)) / 2, zero
    at rest; the reach is then at most the turning point the ramp left behind, |a|^3 / 6J^2.
    ``tests/test_jerk.py`` checks it against the brake of :class:`~desdemona.control.mpc.MPC`.

    lag : with it [m, per joint], the reach r plus the travel :func:`stopping_extent` gives a brake
    that acts in whole steps, min(r, lag), bounded smoothly from above by the harmonic mean
    2 r+ lag / (r+ + lag) (r+ the reach's positive part, smoothed as W is): zero at rest, so that a
    joint at rest at its end can still be planned from, and never short of the check's."""
    def plus(x):  # the positive part of x, smoothly, zero at zero
        return 0.5 * (x + (x * x + eps) ** 0.5 - eps**0.5)

    w = plus(qd + a * a / (2.0 * J))
    r = w * a / J - a * a * a / (6.0 * J * J) + w * w / (2.0 * B) + w * B / (2.0 * J)
    if lag is None:
        return r
    positive = plus(r)
    return r + 2.0 * positive * lag / (positive + lag)


def stopping_extent(q, qd, a, A, J, h):
    """(lowest, highest) positions per joint that a stop from (q, qd, a) at the limits (acceleration
    A, jerk J) can reach, with :data:`STOP_LAG` for a brake that acts every ``h`` seconds: the check
    behind the controller's fallback (:meth:`desdemona.control.mpc.MPC.brake` stops as quickly as that near
    an end). Each side braking at the most its ramp reaches, min(A, sqrt(W J)) (the triangle where it
    does not reach A), so that no stop is judged longer than it is; a side the motion does not turn
    towards is not reached (where :func:`stopping_reach` counts the turning point the ramp left
    behind)."""
    late = STOP_LAG * A * h**2

    def reach(v, acc):
        w = np.maximum(v + acc * acc / (2.0 * J), 0.0)
        r = stopping_reach(v, acc, np.clip(np.sqrt(w * J), 1e-9, A), J, eps=0.0)
        # only a motion that goes that way reaches further (a ramp away from an end leaves it behind)
        r = np.where(np.where(acc >= 0.0, w > 0.0, v > 0.0), r, 0.0)
        return r + np.clip(r, 0.0, late)

    return q - reach(-qd, -a), q + reach(qd, a)

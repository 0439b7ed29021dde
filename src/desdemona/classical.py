"""The classical motion-cueing loops simulators run today: the baselines an optimal result must beat.

- :func:`classical_dfs`: the control loop that dynamic flight simulators use for the central yaw
  (thesis 7.4.2, figure 7.4): the yaw rate that would give the desired modulus in steady rotation,
  qd1_ref = sqrt(sqrt(M_d^2 - g^2) / R) (the inversion of eq. 7.7 without yaw acceleration), tracked by
  a rate- and acceleration-limited first-order loop; on ``dfs`` the gimbals follow the force's
  direction. Its result (a :class:`~desdemona.plan.Plan`) gives the thesis' M_org.
- :func:`~desdemona.washout.classical_washout` (in :mod:`desdemona.washout`, found here too): the
  classical washout (Reid & Nahon) on the other configurations, with the arm's sustained force.

Both run step by step on a time grid and never look ahead. On a machine with jerk limits each joint's
acceleration is continuous and ramps towards its command at most at the jerk limit (:class:`_Follower`),
braking in time before rate and position limits; every step then passes the guard of
:meth:`~desdemona.model.Model.step_limit_use`, its commands scaled down until it does. Without jerk
limits (the thesis' toy set) the accelerations step, as in the thesis.

The thesis' own optimiser, the other baseline, is :mod:`desdemona.thesis`.
"""

from __future__ import annotations

import math

import numpy as np

from desdemona._casadi import call
from desdemona.kinematics import gimbal_alignment, wrapped
from desdemona.model import Model
from desdemona.plan import Plan, State, advance, start_acceleration, start_state
from desdemona.profiles import DesiredPath

DFS_RADIUS = 4.0  # |q2| of the dfs configurations [m]

#: Bandwidth [rad/s] of the gimbals' critically damped angle followers in :func:`classical_dfs`, per
#: gimbal: outer (q4), inner (q5), cabin (q6).
GIMBAL_BANDWIDTH = {3: 5.0, 4: 5.0, 5: 1.5}

#: The largest tilt of tilt coordination: sin(30 deg), so the cabin's tilt gives at most g / 2 of
#: sustained horizontal force.
MAX_TILT_SINE = 0.5


def tilt_angles(f_x, f_y, g: float, limit: float = MAX_TILT_SINE) -> tuple:
    """The outer gimbal (q4, roll) and cabin gimbal (q6, pitch) angles [rad] at which gravity is felt
    as the horizontal specific forces f_y = g sin q4 and f_x = -g sin q6 (tilt coordination), each
    sine within ``limit``; arrays or numbers."""
    return (np.arcsin(np.clip(np.asarray(f_y) / g, -limit, limit)),
            -np.arcsin(np.clip(np.asarray(f_x) / g, -limit, limit)))


#: Time constant [s] of the washout's rate loops (rotations and tilt).
RATE_LOOP = 0.1

#: Share of the acceleration limit a bounded joint brakes with before its position limit: the rest is
#: room for the guard's scaling and for the commands.
BRAKE = 0.5

#: Longest piece of a step [s] that the guard checks at once (at its ends and middle).
GUARD_PIECE = 0.025

#: The guard's scales of the commands, tried in turn until a step passes (the last: no command).
SCALES = (1.0, 0.75, 0.5, 0.25, 0.0)


# ---------------------------------------------------------------------------------------------------
# A limited follower: one step of commanded accelerations made safe, with or without jerk limits


def _rate_zeros(v, u, j):
    """The two times s where v + u s + j s^2 / 2 = 0 (NaN or inf where there is none), computed
    without cancellation (j may be zero)."""
    disc = u * u - 2.0 * j * v
    sq = np.sqrt(np.where(disc >= 0.0, disc, np.nan))
    w = -0.5 * (u + np.copysign(sq, u))
    return w / (0.5 * j), v / w


def _braking_peak(q, v, a, J, B):
    """The highest position a joint reaches while it brakes from (q, v, a): its acceleration ramped at
    the jerk limit J down to -B (or held where it is already below), then held until it stops. With
    J = inf the acceleration steps to -B at once."""
    Bm = np.maximum(B, -a)
    finite = np.isfinite(J)
    Jf = np.where(finite, J, 1.0)
    t1 = (a + Bm) / Jf  # the ramp to -Bm
    disc = a * a + 2.0 * Jf * v
    tr = (a + np.sqrt(np.maximum(disc, 0.0))) / Jf  # the rate falls through zero during the ramp
    q_tr, _ = advance(q, v, a, tr, -Jf)
    ramp_peak = np.where((disc < 0.0) | (tr <= 0.0), q, np.maximum(q, q_tr))
    q1, v1 = advance(q, v, a, t1, -Jf)
    hold_peak = np.maximum(q, q1 + np.maximum(v1, 0.0) ** 2 / (2.0 * Bm))
    finite_peak = np.where(tr <= t1, ramp_peak, hold_peak)
    return np.where(finite, finite_peak, q + np.maximum(v, 0.0) ** 2 / (2.0 * Bm))


def _peaks(q, v, u, j, h, J, B):
    """Highest rate and position of joints (arrays) over a step of ``h`` from (q, v) with acceleration
    u changing at j, and after it: the rate while the acceleration comes back to zero at the jerk limit
    J, the position while the joint brakes (:func:`_braking_peak`)."""
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        q1, v1 = advance(q, v, u, h, j)
        a1 = u + j * h
        s = np.where(j < 0.0, -u / j, -1.0)  # where the rate peaks inside the step
        rate = np.maximum(v, v1)
        rate = np.where((s > 0.0) & (s < h), np.maximum(rate, v - u * u / (2.0 * j)), rate)
        # after the step the acceleration returns to zero in whole steps of constant jerk: at J, and
        # up to one step more (h a / 2 of rate, h v of way), room that lets a follower on the edge
        # stay on it smoothly instead of jerking across zero
        late = np.where(np.isfinite(J), h, 0.0)
        rate = np.maximum(rate, v1 + np.maximum(a1, 0.0) ** 2 / (2.0 * J) + 0.5 * late * np.maximum(a1, 0.0))
        position = np.maximum(q, q1)
        for s in _rate_zeros(v, u, j):
            inside = (s > 0.0) & (s < h)
            position = np.where(inside, np.maximum(position, advance(q, v, u, np.where(inside, s, 0.0), j)[0]),
                                position)
        position = np.maximum(position, _braking_peak(q1, v1, a1, J, B) + late * np.maximum(v1, 0.0))
    return rate, position


def _largest(bad, lo, hi, rounds: int = 5, points: int = 32):
    """Per element, the largest x in [lo, hi] with bad(x) False, where bad(hi) is True and bad is
    monotone (lo where even lo is bad): ``rounds`` of ``points`` trials at once, each round narrowing
    the interval ``points`` times (bad takes arrays of trials (points - 1, n))."""
    good, worse = lo.copy(), hi.copy()
    fractions = np.linspace(0.0, 1.0, points + 1)[1:-1, None]
    columns = np.arange(len(good))
    for _ in range(rounds):
        trials = good + (worse - good) * fractions
        b = bad(trials)
        first = np.where(b.any(axis=0), np.argmax(b, axis=0), len(fractions))  # the first bad trial
        good = np.where(first > 0, trials[np.maximum(first - 1, 0), columns], good)
        worse = np.where(first < len(fractions), trials[np.minimum(first, len(fractions) - 1), columns], worse)
    return good


class _Follower:
    """Each step's acceleration commands of some joints, made safe.

    On a machine with jerk limits (``limits.smooth``) a step starts at the acceleration where the last
    one ended and changes at a jerk x within the limit, towards the command (reached at the end of the
    step where the jerk allows); without them it holds an acceleration x (the thesis' setting: the
    accelerations step). Either way x stays where every joint can still stop in time: its rate within
    the limit over the step and while the acceleration comes back to zero at the jerk limit, a bounded
    joint's position within its range over the step and while it brakes at ``BRAKE`` x the
    acceleration limit, its acceleration ramped there at the jerk limit.

    idx : the joints (indices of the free joints) this follower moves.
    """

    def __init__(self, model: Model, idx):
        lim = model.limits
        self.idx = np.asarray(idx, dtype=int)
        self.smooth = lim.smooth
        take = lambda x: np.asarray(x, dtype=float)[self.idx]
        self.J = take(lim.jerk) if self.smooth else np.full(len(self.idx), np.inf)
        self.A, self.V = take(lim.acceleration), take(lim.velocity)
        self.qmin, self.qmax = take(lim.position_min), take(lim.position_max)
        self.B = BRAKE * self.A

    def motion(self, a, x):
        """(acceleration at the start, jerk) of the step x from acceleration a."""
        return (a, x) if self.smooth else (x, np.zeros_like(x))

    def step(self, q, qd, a, h, command, accel=None):
        """(u, jerk) of the joints over a step of ``h`` from (q, qd, a) towards the acceleration
        ``command``, the acceleration within ``accel`` (default the limit)."""
        q, qd, a, command = (np.asarray(x, dtype=float)[self.idx] for x in (q, qd, a, command))
        A = self.A if accel is None else np.minimum(self.A, np.asarray(accel, dtype=float))
        if self.smooth:  # a beyond A (its bound shrank) goes back at the full jerk
            lo = np.minimum(np.maximum(-self.J, (-A - a) / h), self.J)
            hi = np.maximum(np.minimum(self.J, (A - a) / h), lo)
            x = (command - a) / h
        else:
            lo, hi, x = -A, A, command
        x = np.clip(x, lo, hi)
        # braking ramps no faster than one step can take the acceleration across its range, so that a
        # step of constant jerk can follow them (steps longer than A / J)
        J = np.minimum(self.J, self.A / h) if self.smooth else self.J
        B, V = self.B, self.V

        def over(y):
            u, j = self.motion(a, y)
            rate, position = _peaks(q, qd, u, j, h, J, B)
            return (rate > V) | (position > self.qmax)

        def under(y):
            u, j = self.motion(a, y)
            rate, position = _peaks(-q, -qd, -u, -j, h, J, B)
            return (rate > V) | (position > -self.qmin)

        # a joint without position limits whose rate cannot reach its limit with any x: nothing to do
        reach = np.abs(a) + np.where(np.isfinite(J), J * h, np.abs(x))
        with np.errstate(invalid="ignore"):
            far = np.abs(qd) + h * reach + np.nan_to_num(reach**2 / (2.0 * J)) + 0.5 * h * reach
        if np.all(far < V) and not np.any(np.isfinite(self.qmax) | np.isfinite(self.qmin)):
            return self.motion(a, x)
        # both edges at once (the usual case: neither is reached)
        u, j = self.motion(a, x)
        rate, position = _peaks(np.r_[q, -q], np.r_[qd, -qd], np.r_[u, -u], np.r_[j, -j], h, np.r_[J, J],
                                np.r_[B, B])
        n = len(q)
        high = (rate[:n] > V) | (position[:n] > self.qmax)
        if high.any():
            x = np.where(high, _largest(over, np.minimum(lo, x), x), x)
        low = (rate[n:] > V) | (position[n:] > -self.qmin)
        if high.any() or low.any():
            low = under(x)
        if low.any():
            x = np.where(low, -_largest(lambda y: under(-y), -np.maximum(hi, x), -x), x)
        return self.motion(a, x)


class _Guard:
    """The guard a controller applies before it commands (:meth:`Model.step_limit_use`: every limit at
    the ends and the middle of a step), on pieces of a step of at most :data:`GUARD_PIECE`."""

    def __init__(self, model: Model):
        self.model, self.functions = model, {}

    def passes(self, q, qd, u, jerk, h: float) -> bool:
        pieces = max(1, int(math.ceil(h / GUARD_PIECE - 1e-9)))
        piece = h / pieces
        key = round(piece, 12)
        if key not in self.functions:
            self.functions[key] = self.model.step_limit_use(piece)
        use = self.functions[key]
        for i in range(pieces):
            s = i * piece
            qs, qds = advance(q, qd, u, s, jerk)
            if float(np.max(call(use, qs, qds, u + jerk * s, jerk))) > 1.0 + 1e-9:
                return False
        return True

    def first(self, q, qd, h: float, steps):
        """The first of ``steps`` (an iterable of (u, jerk) candidates, the boldest first) that passes,
        else the last."""
        for u, jerk in steps:
            if self.passes(q, qd, u, jerk, h):
                break
        return u, jerk


def _rate_command(error, gain, J):
    """The acceleration that closes a rate error at ``gain`` [1/s], shaped so that a follower limited
    to the jerk J can keep to it and ends the error without overshoot: gain x error up to where
    following that line would need more than J (|error| = J / gain^2), beyond it the curve along which
    the acceleration falls at exactly J as the error closes, sqrt(2 J |error| - (J / gain)^2)
    (tangent to the line there)."""
    error = np.asarray(error, dtype=float)
    with np.errstate(invalid="ignore", over="ignore"):
        corner = J / gain**2
        curve = np.sqrt(np.maximum(2.0 * J * np.abs(error) - (J / gain) ** 2, 0.0))
        size = np.where(np.isfinite(J) & (np.abs(error) > corner), curve, gain * np.abs(error))
    return np.sign(error) * size


# ---------------------------------------------------------------------------------------------------
# The classical dynamic-flight-simulator loop


def _check_dfs(model: Model, what: str) -> None:
    config = model.config
    if config.free[:1] != (0,) or not set(config.free[1:]) <= {3, 4, 5}:
        raise ValueError(f"{what} is for the yaw and the gimbals (dfs, dfs-yaw), not "
                         f"{config.name}'s {', '.join(config.joint_names)}")


def _rate_reference(M_d, model: Model) -> np.ndarray:
    """The yaw rate [rad/s] that gives the modulus M_d in steady rotation (7.4.2), within its limit."""
    radius = abs(model.config.fixed[1]) or DFS_RADIUS
    g = model.params.gravity
    rate = np.sqrt(np.sqrt(np.maximum(np.asarray(M_d, dtype=float) ** 2 - g**2, 0.0)) / radius)
    return np.minimum(rate, model.limits.velocity[0])


def _gimbal_targets(model: Model, q1, qd1, qdd1) -> np.ndarray:
    """The gimbals' alignment angles (K, n - 1) for the yaw's states (K,): the outer and cabin gimbal
    of :func:`~desdemona.kinematics.gimbal_alignment`, the inner gimbal at 0 (the gimbals at zero: f in
    the arm frame)."""
    n, joint_of = model.n, model.config.free
    zero = np.zeros((len(q1), n - 1))
    f = model.f_cabin(np.c_[q1, zero], np.c_[qd1, zero], np.c_[qdd1, zero])
    outer, cabin = gimbal_alignment(f)
    return np.stack([{3: outer, 4: np.zeros(len(q1)), 5: cabin}[joint_of[i]] for i in range(1, n)], axis=1)


def still_home(q, model: Model, force=None) -> np.ndarray:
    """(n,) where a still machine cues the specific force ``force`` (3,) [m/s^2] best, nearest the free
    joints' positions ``q``; NaN where a joint has no home to go to (the fallback's brake brings the
    machine there, :func:`desdemona.plan.homing_rate`):

    - the arm: none (nothing feels its angle at rest);
    - the track and heave: their centres;
    - the inner gimbal q5 (the cabin's yaw while it is level): its nearest half turn, at which the
      outer gimbal q4 and the cabin q6 tilt the cabin about its own x and y (at a quarter turn both
      would tilt it about one axis, H = Rx(q4) Rz(q5) Ry(q6));
    - q4 and q6: tilt coordination of ``force`` (:func:`tilt_angles`, as :func:`steady_start` tilts;
      level where ``force`` is None or the cabin follows the force, ``dfs``), q4's sign turned with a
      half turn of q5, plus the nearest whole turn; none where that lies more than a quarter turn
      away: the way there may lead through a cabin upside down.
    """
    free, lim, q = model.config.free, model.limits, np.asarray(q, dtype=float)
    home = np.full(len(q), np.nan)
    home[lim.bounded] = 0.5 * (lim.position_min + lim.position_max)[lim.bounded]
    roll = pitch = psi = 0.0
    if force is not None and not model.config.takes_modulus:
        roll, pitch = tilt_angles(force[0], force[1], model.params.gravity)
    if 4 in free:
        k = free.index(4)
        home[k] = psi = math.pi * round(q[k] / math.pi)
    for joint, angle in ((3, math.cos(psi) * roll), (5, pitch)):
        if joint in free:
            k = free.index(joint)
            nearest = angle + 2.0 * math.pi * round((q[k] - angle) / (2.0 * math.pi))
            home[k] = nearest if abs(q[k] - nearest) <= 0.5 * math.pi else np.nan
    return home


def steady_start(path: DesiredPath, model: Model) -> tuple[np.ndarray, np.ndarray]:
    """(q0, qd0) of the free joints for a session that begins in steady state with the path's first
    sample, as a simulator is trimmed before its run.

    - ``dfs``, ``dfs-yaw``: the arm turning at the rate that gives the path's first modulus (7.4.2),
      the gimbals still at the angles that put the felt force along the occupant's vertical. A
      centrifuge spins up before its run; the thesis' on-line catapult (7.5.1) starts from such a
      state, its pulses on a constant 1.5 g.
    - the others: at rest, with the cabin tilted (where its outer gimbal q4 and cabin gimbal q6 are
      free) by tilt coordination of the first desired specific force (:func:`tilt_angles`, the
      classical washout's rule, here on the whole force: at most 30 deg, f_y = g sin q4, f_x = -g
      sin q6); at rest at home where no gimbal can tilt (``yaw-track``, ``yaw-track-cabin``) or the
      first force is vertical.
    """
    n, free = model.n, model.config.free
    q, qd = np.zeros(n), np.zeros(n)
    if model.config.takes_modulus:
        _check_dfs(model, "a steady start")
        rate = float(_rate_reference(path.sample_modulus([path.t[0]]), model)[0])
        qd[0] = rate
        if n > 1:
            q[1:] = _gimbal_targets(model, np.zeros(1), np.array([rate]), np.zeros(1))[0]
        return q, qd
    f = path.sample([path.t[0]])[0]
    roll, pitch = tilt_angles(f[3], f[4], model.params.gravity)
    for joint, angle in ((3, roll), (5, pitch)):
        if joint in free:
            q[free.index(joint)] = float(angle)
    return q, qd


def classical_dfs(path: DesiredPath, model: Model, times=None, gain: float = 10.0, state=None) -> Plan:
    """The classical loop of figure 7.4 on ``dfs-yaw`` (the yaw) or ``dfs`` (the yaw and the gimbals).

    - Yaw: the rate that would give the desired modulus in steady rotation, qd1_ref = sqrt(sqrt(M_d^2
      - g^2) / R) (7.4.2), tracked by a first-order rate loop of bandwidth ``gain``, its acceleration
      within the limits of acceleration, torque and power. On a machine with jerk limits the
      acceleration follows the loop's command at most at the jerk limit, and the command is no larger
      than the jerk limit can bring back to zero before the rate reaches the reference (or the rate
      limit): the rate does not overshoot.
    - Gimbals (``dfs``): what a simulator does today: they follow, they do not plan ahead. The specific
      force in the arm frame comes from the yaw's state (with the head at the gimbal centre it does not
      depend on the gimbals: ``f_cabin`` with the gimbals at zero), and
      :func:`~desdemona.kinematics.gimbal_alignment` gives the outer and cabin gimbal angles that put it
      along the occupant's vertical (the inner gimbal's target is 0). Over each step the targets are
      taken at the yaw's start, middle and end; the parabola through them gives the target's angle, rate
      and acceleration now, and each gimbal's jerk comes from a critically damped third-order loop (a
      triple pole at :data:`GIMBAL_BANDWIDTH`; the jerk is the input of a jerk-limited joint), then
      within the jerk, acceleration and rate limits. The yaw steps its tangential acceleration faster
      than the cabin gimbal can turn (about 10 deg within the yaw's 0.25 s ramp), so the cabin pitch
      lags and the felt force leaves the occupant's vertical by several degrees in transients; a lower
      bandwidth on the cabin gimbal keeps its overshoot down.

    Every step then passes the guard (:meth:`Model.step_limit_use`), its commands scaled down until it
    does. path : desired modulus M_d (from its S_d or given); model : a ``dfs`` or ``dfs-yaw`` Model;
    times : the grid to run the loop on (default the path's); gain : the rate loop's bandwidth [1/s];
    state : (q0, qd0[, qdd0]) of the free joints at the start, by default :func:`steady_start` (as an
    off-line guess); the accelerations start at zero (or at qdd0).
    Returns the free joints' plan on ``times``: continuous accelerations on a machine with jerk limits.
    """
    _check_dfs(model, "the classical loop of 7.4.2")
    t = path.t if times is None else np.asarray(times, dtype=float)
    n, lim = model.n, model.limits
    reference = _rate_reference(path.sample_modulus(t), model)
    gimbals = np.arange(1, n)
    q, qd = steady_start(path, model) if state is None else start_state(state, n)
    a = start_acceleration(state, n)
    q0, qd0 = q.copy(), qd.copy()
    yaw, gimbal = _Follower(model, [0]), _Follower(model, gimbals)
    guard = _Guard(model)
    u, jerk = np.zeros((len(t) - 1, n)), np.zeros((len(t) - 1, n))
    w = np.array([GIMBAL_BANDWIDTH[j] for j in model.config.free[1:]])
    for k in range(len(t) - 1):
        h = float(t[k + 1] - t[k])
        # yaw: the rate loop, its acceleration within what torque and power allow at this rate
        inertia = float(model.mass_matrix(q)[0, 0])
        rate = abs(qd[0]) + abs(a[0]) * h
        accel = [min(lim.effort[0] / inertia, lim.power[0] / (inertia * max(rate, 1e-9)))]
        command = np.zeros(n)
        command[0] = np.clip(_rate_command(reference[k] - qd[0], gain, yaw.J[0]), -accel[0], accel[0])
        bold = yaw.step(q, qd, a, h, command, accel)
        if n > 1:
            # the gimbals' targets along the yaw's step (start, middle, end) and the parabola through
            # them: the target's angle, rate and acceleration now, fed to a third-order loop (a triple
            # pole at the bandwidth) that sets the gimbals' jerk
            s = np.array([0.0, 0.5, 1.0]) * h
            yaw_q, yaw_qd = advance(q[0], qd[0], bold[0][0], s, bold[1][0])
            ref = _gimbal_targets(model, yaw_q, yaw_qd, bold[0][0] + bold[1][0] * s)
            ref_rate = (4.0 * ref[1] - 3.0 * ref[0] - ref[2]) / h
            ref_accel = 4.0 * (ref[2] - 2.0 * ref[1] + ref[0]) / (h * h)
            error = wrapped(ref[0] - q[gimbals])
            jerk_command = (w**3 * error + 3.0 * w**2 * (ref_rate - qd[gimbals])
                            + 3.0 * w * (ref_accel - a[gimbals]))
            command[gimbals] = a[gimbals] + h * jerk_command

        def candidate(scale):
            yaw_step = bold if scale == 1.0 else yaw.step(q, qd, a, h, scale * command, accel)
            if n == 1:
                return yaw_step
            gimbal_step = gimbal.step(q, qd, a, h, scale * command)
            return np.r_[yaw_step[0], gimbal_step[0]], np.r_[yaw_step[1], gimbal_step[1]]

        u[k], jerk[k] = guard.first(q, qd, h, (candidate(scale) for scale in SCALES))
        q, qd, a = State(q, qd, a).advance(u[k], h, jerk[k])
    return Plan(t, q0, qd0, u, jerk)


def __getattr__(name: str):
    """The classical washout lives in :mod:`desdemona.washout` (it builds on this module's followers);
    ``from desdemona.classical import classical_washout`` still finds it."""
    if name in ("Washout", "WASHOUT", "classical_washout"):
        from desdemona import washout

        return getattr(washout, name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")

"""The classical motion-cueing loops simulators run today: the baselines an optimal result must beat.

- :func:`classical_dfs`: the control loop that dynamic flight simulators use for the central yaw
  (thesis 7.4.2, figure 7.4): the yaw rate that would give the desired modulus in steady rotation,
  qd1_ref = sqrt(sqrt(M_d^2 - g^2) / R) (the inversion of eq. 7.7 without yaw acceleration), tracked by
  a rate- and acceleration-limited first-order loop; on ``dfs`` the gimbals follow the force's
  direction. Its result (a :class:`~desdemona.machine.plan.Plan`) gives the thesis' M_org.
- :func:`~desdemona.baselines.washout.classical_washout` (in :mod:`desdemona.baselines.washout`): the
  classical washout (Reid & Nahon) on the other configurations, with the arm's sustained force.

Both run step by step on a time grid and never look ahead, each step made safe by the follower and
guard they share (:mod:`desdemona.baselines.followers`).

The thesis' own optimiser, the other baseline, is :mod:`desdemona.baselines.thesis`.
"""

from __future__ import annotations

import math

import numpy as np

from desdemona.baselines.followers import SCALES, Follower, Guard, rate_command, tilt_angles
from desdemona.machine.kinematics import gimbal_alignment, wrapped
from desdemona.machine.model import Model
from desdemona.machine.plan import Plan, State, advance, start_acceleration, start_state
from desdemona.profiles import DesiredPath
from desdemona.support.symbolic import call

DFS_RADIUS = 4.0  # |q2| of the dfs configurations [m]

#: Bandwidth [rad/s] of the gimbals' critically damped angle followers in :func:`classical_dfs`, per
#: gimbal: outer (q4), inner (q5), cabin (q6), by joint name.
GIMBAL_BANDWIDTH = {"outer_gimbal": 5.0, "inner_gimbal": 5.0, "cabin": 1.5}

# ---------------------------------------------------------------------------------------------------
# The classical dynamic-flight-simulator loop


def _check_dfs(model: Model, what: str) -> None:
    config = model.config
    if not config.yaw_and_gimbals:
        raise ValueError(f"{what} is for the yaw and the gimbals (dfs, dfs-yaw), not "
                         f"{config.name}'s {', '.join(config.joint_names)}")


def _rate_reference(M_d, model: Model) -> np.ndarray:
    """The yaw rate [rad/s] that gives the modulus M_d in steady rotation (7.4.2), within its limit."""
    radius = abs(model.config.held_track) or DFS_RADIUS
    g = model.params.gravity
    rate = np.sqrt(np.sqrt(np.maximum(np.asarray(M_d, dtype=float) ** 2 - g**2, 0.0)) / radius)
    return np.minimum(rate, model.limits.velocity[0])


def _gimbal_targets(model: Model, q1, qd1, qdd1) -> np.ndarray:
    """The gimbals' alignment angles (K, n - 1) for the yaw's states (K,): the outer and cabin gimbal
    of :func:`~desdemona.machine.kinematics.gimbal_alignment`, the inner gimbal at 0 (the gimbals at zero: f in
    the arm frame)."""
    n = model.n
    zero = np.zeros((len(q1), n - 1))
    f = model.f_cabin(np.c_[q1, zero], np.c_[qd1, zero], np.c_[qdd1, zero])
    outer, cabin = gimbal_alignment(f)
    target = {"outer_gimbal": outer, "inner_gimbal": np.zeros(len(q1)), "cabin": cabin}
    return np.stack([target[joint] for joint in model.config.joint_names[1:]], axis=1)


def still_home(q, model: Model, force=None) -> np.ndarray:
    """(n,) where a still machine cues the specific force ``force`` (3,) [m/s^2] best, nearest the free
    joints' positions ``q``; NaN where a joint has no home to go to (the fallback's brake brings the
    machine there, :func:`desdemona.machine.plan.homing_rate`):

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
    config, lim, q = model.config, model.limits, np.asarray(q, dtype=float)
    home = np.full(len(q), np.nan)
    b = lim.bounded  # the centres of the bounded joints only: -inf + inf of the others is not a number
    home[b] = 0.5 * (lim.position_min[b] + lim.position_max[b])
    roll = pitch = psi = 0.0
    if force is not None and not model.config.takes_modulus:
        roll, pitch = tilt_angles(force[0], force[1], model.params.gravity)
    if config.inner_gimbal is not None:
        k = config.inner_gimbal
        home[k] = psi = math.pi * round(q[k] / math.pi)
    for k, angle in ((config.outer_gimbal, math.cos(psi) * roll), (config.cabin_gimbal, pitch)):
        if k is not None:
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
    n, config = model.n, model.config
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
    for k, angle in ((config.outer_gimbal, roll), (config.cabin_gimbal, pitch)):
        if k is not None:
            q[k] = float(angle)
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
      :func:`~desdemona.machine.kinematics.gimbal_alignment` gives the outer and cabin gimbal angles that put it
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
    yaw, gimbal = Follower(model, [0]), Follower(model, gimbals)
    guard = Guard(model)
    u, jerk = np.zeros((len(t) - 1, n)), np.zeros((len(t) - 1, n))
    w = np.array([GIMBAL_BANDWIDTH[joint] for joint in model.config.joint_names[1:]])
    for k in range(len(t) - 1):
        h = float(t[k + 1] - t[k])
        # yaw: the rate loop, its acceleration within what torque and power allow at this rate
        inertia = float(model.mass_matrix(q)[0, 0])
        rate = abs(qd[0]) + abs(a[0]) * h
        accel = [min(lim.effort[0] / inertia, lim.power[0] / (inertia * max(rate, 1e-9)))]
        command = np.zeros(n)
        command[0] = np.clip(rate_command(reference[k] - qd[0], gain, yaw.J[0]), -accel[0], accel[0])
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

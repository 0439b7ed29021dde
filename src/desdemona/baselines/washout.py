"""The classical washout (Reid & Nahon's classical algorithm) on ``yaw-track``, ``yaw-track-cabin`` and
``full``, and where the machine can point it, the arm's sustained force as a centrifuge makes it.

The washout's filters give the onsets: the track and the heave follow the high-passed specific force and
are washed back to their centres; the cabin tilts to hold low-passed horizontal force with gravity (tilt
coordination); the yaw and the gimbals follow the high-passed angular velocity. A washout alone can hold
no sustained force beyond what a 30 deg tilt makes of gravity.

With ``Washout.arm`` the arm holds it, as the dfs loop of 7.4.2 does
(:func:`~desdemona.baselines.classical.classical_dfs`): where the force needs more than ``arm_min`` the cabin
rides out to ``radius`` from the yaw axis (and keeps to its side of it), the arm turns at the rate that
makes the low-passed force's modulus in steady rotation, qd1_ref = sqrt(sqrt(|f|^2 - g^2) / R) on
``full`` (eq. 7.7 without the yaw acceleration) and sqrt(|f_xy| / R) on ``yaw-track-cabin`` (the cabin
stays level there), beyond ``arm_min``, its rate ramped at ``arm_accel`` so that its onset stays
gentle; and the cabin turns the arm's force (the centripetal and tangential terms and gravity, eq. 7.7)
onto the desired direction: by the smallest rotation of the gimbals on ``full`` (the rotation that
takes the desired direction to the arm's force; with the arm still, this is tilt coordination), by the
cabin's yaw q5 on ``yaw-track-cabin``. The high-passed force is then sent to the track and the heave
as the cabin's orientation turns it into the arm frame. Every command passes the same followers and
guard as the dfs loop (:class:`~desdemona.baselines.classical.Follower`, :class:`~desdemona.baselines.classical.Guard`):
every limit holds.

The per-configuration settings (:func:`tuned`) are the tuned baseline.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
import scipy.linalg
import scipy.signal

from desdemona.baselines.followers import MAX_TILT_SINE, RATE_LOOP, SCALES, Follower, Guard, rate_command, tilt_angles
from desdemona.machine.model import Model
from desdemona.machine.plan import Plan, State, start_acceleration, start_state
from desdemona.profiles import DesiredPath

#: Natural frequency [rad/s] of the critically damped moves of the track's centre to the arm's radius and
#: back.
CENTRE_MOVE = 0.3

#: Horizontal force [m/s^2] below which its direction is not worth turning the cabin for (about three
#: times the lateral otolith threshold, 0.17 m/s^2); the yaw-track-cabin cabin blends to home below it.
POINT_FORCE = 0.5

#: Share of the yaw's rate limit the arm's sustained rate may use: the rest is room for the onsets.
ARM_RATE_SHARE = 0.9


@dataclass(frozen=True)
class Washout:
    """Settings of the classical washout (:func:`classical_washout`), after Reid & Nahon's classical
    algorithm; assumptions chosen for Desdemona's 8 m track and 2 m heave, not the thesis'.

    omega_hp, zeta_hp : second-order high-pass of the specific force sent to the track and heave
    [rad/s, -]; omega_centre, zeta_centre : the spring that washes them back to the centre;
    omega_lp, zeta_lp : second-order low-pass of f_x, f_y for tilt coordination; tilt_rate : the
    largest tilt rate [rad/s], at the perception threshold so that the tilt is not felt as rotation;
    tilt_limit : sine of the largest tilt; omega_rot : first-order high-pass of the angular velocity
    [rad/s]; gain : scale of S_d - rest for the washout's filters.
    arm : the arm holds the sustained force (``yaw-track-cabin`` and ``full``; see the module's notes),
    at full scale; radius : the cabin's distance from the yaw axis meanwhile [m] (the track's centre);
    omega_arm : second-order low-pass (damping zeta_lp) of the force the arm holds [rad/s]; arm_accel :
    the ramp of the arm's sustained rate [rad/s^2]; arm_min : the force the arm leaves to the washout
    [m/s^2]: it holds only what the force needs beyond it, since a small force costs the most turning
    (the arm's rate goes with its square root). With the arm, the cabin points the whole low-passed
    force (omega_lp, unscaled), tilted at most by tilt_limit, and tilt_rate bounds the correction
    beyond the pointing's own rate.
    The defaults are the untuned washout of before (a small grid over four built-in paths); the tuned
    ones are each configuration's (:func:`tuned`).
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
    tilt_limit: float = MAX_TILT_SINE
    arm: bool = False
    radius: float = 3.0
    omega_arm: float = 0.3
    arm_accel: float = 0.1
    arm_min: float = 0.0


def tuned(config) -> Washout:
    """The washout a configuration runs beside the MPC: its tuned settings (the configuration's
    ``washout`` data, found by ``nice -n 10 python benchmarks/tune_classical.py`` on 2026-12-02, a
    coordinate search of the felt force on the corpus and the built-in paths,
    docs/benchmarks/classical-washout-tuned.md: mean felt force RMS 0.96x the untuned on
    yaw-track-cabin, 0.80x on full), else :class:`Washout` ()."""
    return Washout(**dict(config.washout))


def _filtered(numerator, denominator, u, dt, steady: bool = False) -> np.ndarray:
    """The response of a continuous SISO filter to ``u`` (K,) sampled at ``dt``, inputs held (ZOH),
    from a zero state, or from the steady state of the first input (``steady``)."""
    b, a, _ = scipy.signal.cont2discrete((numerator, denominator), dt, method="zoh")
    b = np.ravel(b)
    if not steady:
        return scipy.signal.lfilter(b, a, u)
    return scipy.signal.lfilter(b, a, u, zi=scipy.signal.lfilter_zi(b, a) * u[0])[0]


def _filters(o: Washout) -> dict[str, tuple]:
    """The washout's filters as (numerator, denominator): hp2 (force), lp2 (tilt), hp1 (rotation),
    lp_arm (the arm's force)."""
    return {"hp2": ([1.0, 0.0, 0.0], [1.0, 2 * o.zeta_hp * o.omega_hp, o.omega_hp**2]),
            "lp2": ([o.omega_lp**2], [1.0, 2 * o.zeta_lp * o.omega_lp, o.omega_lp**2]),
            "hp1": ([1.0, 0.0], [1.0, o.omega_rot]),
            "lp_arm": ([o.omega_arm**2], [1.0, 2 * o.zeta_lp * o.omega_arm, o.omega_arm**2])}


def _arm_ramp(reference, turn, t, accel: float, start: float) -> tuple[np.ndarray, np.ndarray]:
    """The arm's sustained rate (K,) [rad/s], signed, and its rate of change (K,): the magnitude ramps
    towards ``reference`` (K,) at most at ``accel``; it starts (from a still arm) the way ``turn``
    (K,) says, the desired yaw's sign, so that a turn is felt the way the vehicle turns, and keeps
    that way until it stops."""
    rate = np.zeros(len(t))
    w, sign = abs(start), math.copysign(1.0, start) if start else 1.0
    for k in range(len(t)):
        if w == 0.0 and turn[k] != 0.0:
            sign = math.copysign(1.0, turn[k])
        rate[k] = sign * w
        if k + 1 < len(t):
            h = t[k + 1] - t[k]
            w += float(np.clip(reference[k] - w, -accel * h, accel * h))
    change = np.r_[np.diff(rate) / np.diff(t), 0.0]
    return rate, change


def _rotation_between(d, f) -> np.ndarray:
    """The smallest rotations R (K, 3, 3) with R d = f for unit vectors d, f (K, 3), neither pair
    opposite: R = I + [v]x + [v]x^2 / (1 + d.f), v = d x f."""
    v = np.cross(d, f)
    c = np.sum(d * f, axis=1)
    V = np.zeros((len(d), 3, 3))
    V[:, 0, 1], V[:, 0, 2], V[:, 1, 2] = -v[:, 2], v[:, 1], -v[:, 0]
    V -= np.transpose(V, (0, 2, 1))
    return np.eye(3) + V + V @ V / (1.0 + c)[:, None, None]


def _gimbal_angles(R) -> np.ndarray:
    """Outer, inner and cabin gimbal angles (K, 3) [rad] of R = Rx(q4) Rz(q5) Ry(q6) (K, 3, 3), each
    unwrapped along K."""
    angles = np.stack([np.arctan2(R[:, 2, 1], R[:, 1, 1]), np.arcsin(np.clip(-R[:, 0, 1], -1.0, 1.0)),
                       np.arctan2(R[:, 0, 2], R[:, 0, 0])], axis=1)
    return np.unwrap(angles, axis=0)


def _centre_move(t, goal, start: float) -> np.ndarray:
    """Position, rate and acceleration (K, 3) of a centre that follows ``goal`` (K,) [m] from ``start``
    at rest, critically damped at :data:`CENTRE_MOVE` (exact for goals held over each step)."""
    w = CENTRE_MOVE
    A = np.array([[0.0, 1.0], [-w * w, -2.0 * w]])
    x, out, steps = np.array([start, 0.0]), np.zeros((len(t), 3)), {}
    for k in range(len(t)):
        out[k] = x[0], x[1], w * w * (goal[k] - x[0]) - 2.0 * w * x[1]
        if k + 1 < len(t):
            h = round(float(t[k + 1] - t[k]), 12)
            if h not in steps:
                steps[h] = scipy.linalg.expm(A * h)
            rest = np.array([goal[k], 0.0])
            x = rest + steps[h] @ (x - rest)
    return out


def _arm_plan(path: DesiredPath, model: Model, t, o: Washout, q0, qd0, trimmed: bool) -> dict:
    """What the joints follow while the arm holds the sustained force: the arm's sustained rate (K,),
    the cabin's orientation R (K, 3, 3) that points the arm's force (the arm frame's axes in it), its
    gimbal angles (K, 3) (q4, q5, q6) and the track's centre (K,) with its rate and acceleration."""
    dt, g, config = float(np.min(np.diff(t))), model.params.gravity, model.config
    S_d = path.sample(t)
    f = S_d[:, 3:]
    filters = _filters(o)
    F = np.column_stack([_filtered(*filters["lp2"], f[:, i], dt, trimmed) for i in range(3)])
    held = np.column_stack([_filtered(*filters["lp_arm"], f[:, i], dt, trimmed) for i in range(3)])
    turn = _filtered(*filters["lp_arm"], S_d[:, 2], dt, trimmed)
    full = config.tilts_cabin
    side = -1.0 if q0[config.track] <= 0.0 else 1.0  # the track's side the cabin rides on
    radius = o.radius
    if full:
        need = np.sqrt(np.maximum(np.sum(held**2, axis=1) - g**2, 0.0))
    else:
        need = np.hypot(held[:, 0], held[:, 1])
    reference = np.minimum(np.sqrt(np.maximum(need - o.arm_min, 0.0) / radius),
                           ARM_RATE_SHARE * model.limits.velocity[0])
    rate, change = _arm_ramp(reference, turn, t, o.arm_accel, qd0[0])
    # the cabin rides out to the radius while the arm holds force, and back to the centre after
    engaged = (reference > 0.0) | (rate != 0.0)
    centre = _centre_move(t, np.where(engaged, side * radius, 0.0), q0[config.track])
    # the arm frame's force at the cabin (eq. 7.7, the track at the centre): tangential, centripetal
    # and gravity
    f_arm = np.column_stack([-centre[:, 0] * change, -centre[:, 0] * rate**2, np.full(len(t), g)])
    if full:  # the desired direction, tilted at most by the tilt limit from the cabin's vertical
        horizontal = F[:, :2] / np.maximum(np.linalg.norm(F, axis=1), g)[:, None]
        size = np.linalg.norm(horizontal, axis=1)
        horizontal *= (np.minimum(size, o.tilt_limit) / np.maximum(size, 1e-12))[:, None]
        d = np.column_stack([horizontal, np.sqrt(1.0 - np.sum(horizontal**2, axis=1))])
        R = _rotation_between(d, f_arm / np.linalg.norm(f_arm, axis=1)[:, None])
        angles = _gimbal_angles(R)
    else:  # the cabin's yaw turns the arm's horizontal force onto the desired one, where both are felt
        weight = (np.minimum(np.hypot(F[:, 0], F[:, 1]) / POINT_FORCE, 1.0)
                  * np.minimum(np.hypot(f_arm[:, 0], f_arm[:, 1]) / POINT_FORCE, 1.0))
        turn_by = np.arctan2(f_arm[:, 1], f_arm[:, 0]) - np.arctan2(F[:, 1], F[:, 0])
        yaw = np.unwrap(np.arctan2(weight * np.sin(turn_by), 1.0 - weight + weight * np.cos(turn_by)))
        yaw += 2.0 * np.pi * np.round((q0[config.inner_gimbal] - yaw[0]) / (2.0 * np.pi))
        c, s = np.cos(yaw), np.sin(yaw)
        R = np.zeros((len(t), 3, 3))
        R[:, 0, 0], R[:, 0, 1], R[:, 1, 0], R[:, 1, 1], R[:, 2, 2] = c, -s, s, c, 1.0
        angles = np.column_stack([np.zeros(len(t)), yaw, np.zeros(len(t))])
    return {"rate": rate, "R": R, "angles": angles, "centre": centre, "side": side,
            "engaged": engaged | (np.maximum.accumulate(engaged) & (np.abs(centre[:, 0]) > 0.01))}


def _targets(path: DesiredPath, model: Model, t, o: Washout, state, trimmed: bool) -> dict:
    """Per free joint what it follows (each (K, n)): ``acc`` the translational joints' acceleration,
    ``rate`` the rotational joints' rate, ``angle`` the tilting joints' angle (NaN where none), and
    ``centre`` (K, n, 3) the position, rate and acceleration of the centre the springs wash back to;
    ``side`` the side of the yaw axis the track keeps to (-1, +1; 0: either) while ``engaged`` (K,), the
    arm holding force or the cabin out at its radius."""
    dt, g, config, n = float(np.min(np.diff(t))), model.params.gravity, model.config, model.n
    rest = np.array([0.0, 0.0, 0.0, 0.0, 0.0, g])
    S_d = rest + o.gain * (path.sample(t) - rest)
    filters = _filters(o)
    hp2, lp2, hp1 = filters["hp2"], filters["lp2"], filters["hp1"]
    acc, rate = np.zeros((len(t), n)), np.zeros((len(t), n))
    angle, centre = np.full((len(t), n), np.nan), np.zeros((len(t), n, 3))
    arm = o.arm and config.turns_arm and config.moves_track and config.inner_gimbal is not None
    if arm:
        q0, qd0 = start_state(state, n)
        plan = _arm_plan(path, model, t, o, q0, qd0, trimmed)
        hp = np.column_stack([_filtered(*hp2, S_d[:, 3 + i] - rest[3 + i], dt, trimmed) for i in range(3)])
        in_arm = np.einsum("kij,kj->ki", plan["R"], hp)  # the high-passed force in the arm frame
        for k, axis in ((config.track, 1), (config.heave, 2)):  # the arm frame's y and z
            if k is not None:
                acc[:, k] = in_arm[:, axis]
        centre[:, config.track] = plan["centre"]
        rate[:, config.yaw] = plan["rate"] + _filtered(*hp1, S_d[:, 2], dt, trimmed)
        # each gimbal's angle (q4, q5, q6) and the rotation it also cues (omega_x, none, omega_y)
        for i, (k, channel) in enumerate(((config.outer_gimbal, 0), (config.inner_gimbal, None),
                                          (config.cabin_gimbal, 1))):
            if k is not None:
                angle[:, k] = plan["angles"][:, i]
                rate[:, k] = np.r_[np.diff(angle[:, k]) / np.diff(t), 0.0]
                if channel is not None:
                    rate[:, k] += _filtered(*hp1, S_d[:, channel], dt, trimmed)
        return {"acc": acc, "rate": rate, "angle": angle, "centre": centre, "side": plan["side"],
                "engaged": plan["engaged"]}
    if config.track is not None:
        acc[:, config.track] = _filtered(*hp2, S_d[:, 4], dt, trimmed)
    if config.heave is not None:
        acc[:, config.heave] = _filtered(*hp2, S_d[:, 5] - g, dt, trimmed)
    turning = config.yaw if config.turns_arm else config.inner_gimbal  # omega_z: the arm, else the cabin
    if turning is not None:
        rate[:, turning] = _filtered(*hp1, S_d[:, 2], dt, trimmed)
    if config.outer_gimbal is not None:
        k = config.outer_gimbal
        rate[:, k] = _filtered(*hp1, S_d[:, 0], dt, trimmed)
        angle[:, k] = tilt_angles(0.0, _filtered(*lp2, S_d[:, 4], dt, trimmed), g, o.tilt_limit)[0]
    if config.cabin_gimbal is not None:
        k = config.cabin_gimbal
        rate[:, k] = _filtered(*hp1, S_d[:, 1], dt, trimmed)
        angle[:, k] = tilt_angles(_filtered(*lp2, S_d[:, 3], dt, trimmed), 0.0, g, o.tilt_limit)[1]
    return {"acc": acc, "rate": rate, "angle": angle, "centre": centre, "side": 0.0}


def classical_washout(path: DesiredPath, model: Model, times=None, settings: Washout | None = None,
                      state=None, trimmed: bool = False) -> Plan:
    """The classical washout a motion simulator runs today, on the yaw-track, yaw-track-cabin and
    full configurations (Reid & Nahon's classical algorithm, with tilt coordination where the cabin
    can tilt, and the arm's sustained force where ``settings.arm`` and the cabin can point it).

    - Translational: f_y (track) and f_z - g (heave) through a second-order high-pass, plus a spring
      that washes the joint back to its centre (with the arm: the high-passed force turned into the
      arm frame by the cabin's orientation, the track's centre at the radius while the arm holds force).
    - Tilt coordination (full): the low-passed f_x and f_y held by tilting the cabin (q6 pitch: f_x
      = -g sin q6; q4 roll: f_y = g sin q4), at most ``tilt_rate``, below the rotation threshold.
      With the arm the gimbals turn its force onto the desired direction (see the module's notes),
      following the target's own rate plus a correction of at most ``tilt_rate``.
    - Rotational: omega_z through a first-order high-pass as the yaw's rate (omega_x, omega_y the same
      on the gimbals where they are free), added to the arm's sustained rate.

    The rate loops' commands are no larger than the jerk limit can end without overshoot. Every command
    then passes the limits (:class:`~desdemona.baselines.classical.Follower`): on a machine with jerk limits the
    acceleration ramps from where it was (zero at the start) towards the command at most at the jerk
    limit; rate and position stay where the joint can still stop, a bounded joint braking at
    :data:`~desdemona.baselines.classical.BRAKE` x its acceleration limit with the ramp there counted; then
    torque, power and the rest over the step (:meth:`Model.step_limit_use`), the command (and so the
    jerk) scaled down until it passes. Without jerk limits the accelerations step, as before.
    Returns the free joints' plan on ``times`` (default: the path's grid), from ``state`` =
    (q0, qd0[, qdd0]) (default rest). ``settings``: default the configuration's, :func:`tuned`.
    ``trimmed``: the filters start in the steady state of the first sample, as for a session that begins trimmed to it
    (:func:`~desdemona.baselines.classical.steady_start`); else from zero, as if the path had been at rest
    before t = 0.
    """
    o = tuned(model.config) if settings is None else settings
    t = path.t if times is None else np.asarray(times, dtype=float)
    lim = model.limits
    target = _targets(path, model, t, o, state, trimmed)
    prismatic = model.prismatic
    tilt = ~np.isnan(target["angle"][0])
    q, qd = start_state(state, model.n)
    a = start_acceleration(state, model.n)
    q0, qd0 = q.copy(), qd.copy()
    follower = Follower(model, np.arange(model.n))
    side, track = target["side"], model.config.track or 0
    bounds = follower.qmin.copy(), follower.qmax.copy()
    u, jerk = np.zeros((len(t) - 1, model.n)), np.zeros((len(t) - 1, model.n))
    wc, zc = o.omega_centre, o.zeta_centre
    guard = Guard(model)
    for k in range(len(t) - 1):
        h = float(t[k + 1] - t[k])
        c = target["centre"][k]
        spring = c[:, 2] - wc**2 * (q - c[:, 0]) - 2 * zc * wc * (qd - c[:, 1])
        command = np.where(prismatic, target["acc"][k] + spring,
                           rate_command(target["rate"][k] - qd, 1.0 / RATE_LOOP, follower.J))
        if tilt.any():  # follow the tilt angle with the rate below the threshold
            rate = (np.clip((np.nan_to_num(target["angle"][k]) - q) * 2.0, -o.tilt_rate, o.tilt_rate)
                    + target["rate"][k])
            command = np.where(tilt, rate_command(rate - qd, 1.0 / RATE_LOOP, follower.J), command)
        command = np.clip(command, -lim.acceleration, lim.acceleration)
        if side:  # while the arm holds force the cabin keeps to its side of the yaw axis
            lo, hi = bounds[0][track], bounds[1][track]
            if target["engaged"][k]:
                lo, hi = (max(lo, min(q[track], 0.0)), hi) if side > 0 else (lo, min(hi, max(q[track], 0.0)))
            follower.qmin[track], follower.qmax[track] = lo, hi
        u[k], jerk[k] = guard.first(q, qd, h, (follower.step(q, qd, a, h, s * command) for s in SCALES))
        q, qd, a = State(q, qd, a).advance(u[k], h, jerk[k])
    return Plan(t, q0, qd0, u, jerk)


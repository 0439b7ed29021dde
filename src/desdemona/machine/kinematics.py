"""Forward kinematics of Desdemona and the path S the person in the cabin feels (appendix A.1-A.3).

The chain of eq. A.7, world (frame 0) to cabin (frame 6)::

    H_world_cabin = Rz(q1) T(0, q2, 0) T(0, 0, q3) Rx(q4) Rz(q5) Ry(q6)

World z points up; gravity is g_vec = (0, 0, -g). The path is ``S = (omega_cabin, f_cabin)`` (eq. 3.2,
A.10): the cabin's angular velocity and the specific force ``f = a - g_vec`` at the head, both in cabin
coordinates, so a cabin at rest and level feels f_cabin = (0, 0, +g) (eq. A.19, B.5).

The functions here are expressions of the full six-joint chain. They accept floats, NumPy arrays
(one state ``(6,)`` or many ``(N, 6)``) and CasADi SX/MX symbols alike; :class:`desdemona.machine.model.Model`
restricts them to the free joints of a configuration.
"""

from __future__ import annotations

import functools

import casadi as ca
import numpy as np

from desdemona.support.symbolic import call

N_JOINTS = 6
# (kind, axis) of each joint in its parent's frame, eq. A.7 / A.8; axis 0, 1, 2 = x, y, z.
JOINT_AXES: tuple[tuple[str, int], ...] = (
    ("revolute", 2), ("prismatic", 1), ("prismatic", 2), ("revolute", 0), ("revolute", 2), ("revolute", 1))


def rotation(axis: int, angle):
    """3x3 rotation about the x (0), y (1) or z (2) axis by ``angle`` [rad] (eq. A.2-A.4).

    Works on floats (returns a NumPy array) and CasADi symbols (returns the same type).
    """
    symbolic = isinstance(angle, (ca.SX, ca.MX, ca.DM))
    c, s = (ca.cos(angle), ca.sin(angle)) if symbolic else (np.cos(angle), np.sin(angle))
    rows = {0: ((1, 0, 0), (0, c, -s), (0, s, c)),
            1: ((c, 0, s), (0, 1, 0), (-s, 0, c)),
            2: ((c, -s, 0), (s, c, 0), (0, 0, 1))}[axis]
    if symbolic:
        return ca.vertcat(*[ca.horzcat(*row) for row in rows])
    return np.array(rows, dtype=float)


def frames(q) -> list[tuple]:
    """World rotation and origin of frames 1..6 along the chain of eq. A.7.

    q : (6,) joint positions [rad | m], floats or CasADi symbols.
    Returns six pairs ``(R_world_i (3, 3), p_world_i (3,))``.
    """
    symbolic = isinstance(q, (ca.SX, ca.MX))
    R = ca.DM.eye(3) if symbolic else np.eye(3)
    p = ca.DM.zeros(3) if symbolic else np.zeros(3)
    out = []
    for i, (kind, axis) in enumerate(JOINT_AXES):
        if kind == "revolute":
            R = R @ rotation(axis, q[i])
        else:
            p = p + R[:, axis] * q[i]
        out.append((R, p))
    return out


def cabin_pose(q):
    """(4, 4) homogeneous transform H_world_cabin (eq. A.1, A.7). q : (6,) [rad | m]."""
    R, p = frames(q)[-1]
    if isinstance(R, (ca.SX, ca.MX, ca.DM)):
        return ca.vertcat(ca.horzcat(R, p), ca.DM([[0, 0, 0, 1]]))
    return np.block([[R, p.reshape(3, 1)], [np.zeros((1, 3)), np.ones((1, 1))]])


def body_motion(q, qd, qdd=None, gravity: float = 0.0) -> list[dict]:
    """Motion of frames 1..6, each in its own coordinates, by the forward recursion of Newton-Euler.

    Returns per frame a dict with ``omega`` (angular velocity [rad/s]), ``v`` (velocity of the origin
    [m/s]), and where ``qdd`` is given ``alpha`` (angular acceleration [rad/s^2]) and ``a`` (classical
    acceleration of the origin [m/s^2]); ``up`` is g times the world z axis [m/s^2] in that frame.
    All are world-relative quantities expressed in the frame's own axes (the twist T_i^{i,0} of eq. A.12).

    Working in local axes keeps the expressions free of the world rotation: a yaw angle never appears
    in the yaw-track model, as in eq. B.2-B.5. q, qd, qdd : (6,) CasADi expressions.
    """
    zero = ca.DM.zeros(3)
    omega, v, up = zero, zero, ca.DM([0.0, 0.0, gravity])
    alpha, a = zero, zero
    out = []
    for i, (kind, axis) in enumerate(JOINT_AXES):
        e = ca.DM.zeros(3)
        e[axis] = 1.0
        if kind == "revolute":
            Rt = rotation(axis, q[i]).T  # parent axes -> this frame's axes
            omega_parent = Rt @ omega
            omega = omega_parent + e * qd[i]
            v, up = Rt @ v, Rt @ up
            if qdd is not None:
                alpha = Rt @ alpha + e * qdd[i] + ca.cross(omega_parent, e * qd[i])
                a = Rt @ a
        else:
            p = e * q[i]  # the origin slides along the axis; the axes stay
            if qdd is not None:
                a = (a + ca.cross(alpha, p) + ca.cross(omega, ca.cross(omega, p))
                     + 2.0 * ca.cross(omega, e * qd[i]) + e * qdd[i])
            v = v + ca.cross(omega, p) + e * qd[i]
        out.append({"omega": omega, "v": v, "alpha": alpha, "a": a, "up": up})
    return out


def gimbal_alignment(f):
    """Outer and cabin gimbal angles (q4, q6) that align the cabin's +z with a specific force.

    The dynamic-flight-simulator use of chapter 7: the gimbals turn the cabin so that the person feels
    the whole specific force "down" into the seat; only its modulus (eq. 7.2) is then a cue.
    f : (3,) specific force in the arm frame (after q1, q2, q3) [m/s^2], with inner gimbal q5 = 0.
    Returns (q4, q6) [rad] such that Ry(q6)^T Rx(q4)^T f = (0, 0, |f|).
    """
    if isinstance(f, (ca.SX, ca.MX)):
        return ca.atan2(-f[1], f[2]), ca.atan2(f[0], ca.sqrt(f[1] ** 2 + f[2] ** 2))
    f = np.asarray(f, dtype=float)
    return np.arctan2(-f[..., 1], f[..., 2]), np.arctan2(f[..., 0], np.hypot(f[..., 1], f[..., 2]))


def wrapped(angle):
    """``angle`` [rad] wrapped to [-pi, pi); arrays or numbers."""
    return np.mod(np.asarray(angle, dtype=float) + np.pi, 2.0 * np.pi) - np.pi


#: The outer gimbal, inner gimbal and cabin in the full joint vector: Rx(q4) Rz(q5) Ry(q6) (eq. A.7).
GIMBALS = (3, 4, 5)


def gimbal_twin(q) -> np.ndarray:
    """The same joint positions with the gimbals on their other branch of the same cabin attitude:
    Rx(a) Rz(b) Ry(c) = Rx(a + pi) Rz(pi - b) Ry(c + pi), each angle wrapped to [-pi, pi).

    q : (6,) [rad | m]. At rest the two are the same state for the occupant: the same pose, the same S.
    """
    twin = np.array(q, dtype=float)
    a, b, c = twin[list(GIMBALS)]
    twin[list(GIMBALS)] = wrapped([a + np.pi, np.pi - b, c + np.pi])
    return twin


def path_expression(q, qd, qdd, gravity: float, head_offset) -> ca.SX:
    """S = (omega_cabin, f_cabin) as a CasADi expression (eq. 3.2, A.10-A.19).

    q, qd, qdd : (6,) expressions of the joints (held joints constant). The head's acceleration is the
    cabin origin's plus the rigid-body terms of the head offset r: a + alpha x r + omega x (omega x r);
    the specific force adds g times the world's up axis seen from the cabin (eq. A.19).
    """
    cabin = body_motion(q, qd, qdd, gravity)[-1]
    r = ca.DM(head_offset)
    omega = cabin["omega"]
    a_head = cabin["a"] + ca.cross(cabin["alpha"], r) + ca.cross(omega, ca.cross(omega, r))
    return ca.vertcat(omega, a_head + cabin["up"])


@functools.lru_cache(maxsize=None)
def path_function(gravity: float = 9.81, head_offset: tuple[float, float, float] = (0.0, 0.0, 0.0)) -> ca.Function:
    """CasADi Function ``S(q, qd, qdd) -> (6,)`` of the full chain; see :func:`path_expression`."""
    q, qd, qdd = (ca.SX.sym(name, N_JOINTS) for name in ("q", "qd", "qdd"))
    S = path_expression(q, qd, qdd, gravity, head_offset)
    return ca.Function("S", [q, qd, qdd], [S], ["q", "qd", "qdd"], ["S"])


def S(q, qd, qdd, gravity: float = 9.81, head_offset: tuple[float, float, float] = (0.0, 0.0, 0.0)):
    """The path ``S = (omega_cabin, f_cabin)`` of the full chain (eq. 3.2, A.10).

    q, qd, qdd : (6,) or (N, 6) joint positions [rad | m], rates and accelerations, or CasADi symbols.
    Returns (6,) or (N, 6): cabin angular velocity [rad/s] and specific force at the head [m/s^2], both
    in cabin coordinates.
    """
    return call(path_function(float(gravity), tuple(float(x) for x in head_offset)), q, qd, qdd)


def gimbal_null_rate(q, qd, gimbals) -> ca.SX | None:
    """The part of the outer gimbal's and the cabin's rates that turns the cabin not at all, weighed by
    how near the inner gimbal is to its lock: c^2 (qd4 - c qd6) / 2, where c = -sin q5 is the cosine
    between the outer gimbal's axis and the cabin's (consecutive axes of the chain are perpendicular,
    appendix A). At the lock (c = +-1) the two axes line up and qd4 = -c qd6 turns the cabin by
    nothing; away from it (c = 0) the term vanishes. ``gimbals``: the (outer, inner, cabin) gimbals'
    indices into q and qd (:attr:`~desdemona.machine.configs.Configuration.gimbals`); None (the result
    too) unless all three are free."""
    if gimbals is None:
        return None
    outer, inner, cabin = gimbals
    c = -ca.sin(q[inner])
    return c ** 2 * (qd[outer] - c * qd[cabin]) / 2

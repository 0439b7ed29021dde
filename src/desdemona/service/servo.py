"""The joints of the motion-system stand-in (``desdemona machine``): each joint's servo, and the brake of
its own safety layer.

**The servo.** A drive follows its reference ``r(t)`` (position, rate, acceleration of the cubic a
setpoint commands) a transport delay ``d`` late, with the rate and the acceleration fed forward and a
critically damped position loop of bandwidth ``omega`` [rad/s] for what is not: the joint's motion is
``y(t) = r(t - d) + e(t)`` with the error obeying ``e'' + 2 omega e' + omega^2 e = 0``. A reference
that is continuous is then followed exactly, the delay late; a reference that jumps (a setpoint
re-anchored on the measured machine, the start of a motion) leaves an error that decays as

    e(s) = (e0 + (e0' + omega e0) s) exp(-omega s)

(s after the jump), whose derivatives are in closed form (:func:`decay`): the motion made is exact,
not integrated, and its acceleration and jerk are known everywhere.

**The brake.** The stand-in's own stop (no setpoint in time, a fault, an emergency stop) starts from
where the joints are (position, rate and acceleration of the motion made: no jump) and turns each
acceleration against its motion at the jerk limit, holds it at the acceleration limit and turns it back
so that rate and acceleration reach zero together: the fastest stop the limits allow
(:func:`desdemona.machine.plan.stopping_jerk`, one jerk per :data:`BRAKE_STEP`), then holds still.

Every function takes (n,) arrays per joint, SI units, and returns new arrays (no state is mutated
but the :class:`Joints`' own).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from desdemona.machine.plan import advance, stopping_jerk, stopping_time

#: The brake's step [s]: one jerk per step, as the stand-in's drive would update its own ramp.
BRAKE_STEP = 0.001
#: Defaults of the servo (``desdemona machine --delay --bandwidth --noise``): a transport delay of 10
#: ms (a fieldbus cycle and the drive's own cycle, a few ms each); a position loop of 5 Hz (a large
#: drive's, well under its mechanics' resonances; with the rate and acceleration fed forward it only
#: corrects what they do not carry); measurement noise of 1e-5 [rad | m] (an encoder's resolution)
#: and 1e-4 [rad/s | m/s] (a rate differenced over a millisecond and filtered), one standard deviation.
DELAY, BANDWIDTH_HZ, NOISE = 0.010, 5.0, (1e-5, 1e-4)


def decay(e0, ed0, omega: float, s):
    """The error of a critically damped loop ``s`` [s] (K, 1) after it was ``e0``, ``ed0`` (n,): its
    position, rate, acceleration and jerk, each (K, n)."""
    c1 = ed0 + omega * e0
    x = np.exp(-omega * s)
    base = e0 + c1 * s
    return (base * x, (c1 - omega * base) * x, (-2.0 * omega * c1 + omega**2 * base) * x,
            (3.0 * omega**2 * c1 - omega**3 * base) * x)


@dataclass(frozen=True)
class JointLimits:
    """Every joint's limits (6,) from the machine's parameters: position_min/max [rad | m] (inf where
    unbounded), velocity, acceleration, jerk (finite: a machine without jerk limits brakes as if its
    jerk were :data:`UNLIMITED_JERK` times its acceleration)."""

    position_min: np.ndarray
    position_max: np.ndarray
    velocity: np.ndarray
    acceleration: np.ndarray
    jerk: np.ndarray

    @classmethod
    def of(cls, params) -> JointLimits:
        jerk = np.asarray(params.jerk_max, dtype=float)
        acceleration = np.asarray(params.acceleration_max, dtype=float)
        jerk = np.where(np.isfinite(jerk), jerk, UNLIMITED_JERK * acceleration)
        return cls(np.asarray(params.position_min, float), np.asarray(params.position_max, float),
                   np.asarray(params.velocity_max, float), acceleration, jerk)

    def stopping_time(self, qd, a) -> float:
        """The longest of the joints' shortest stops [s] from rates ``qd`` and accelerations ``a``."""
        return float(np.max(stopping_time(qd, a, self.acceleration, self.jerk)))


#: Without jerk limits the brake ramps its acceleration within 1/UNLIMITED_JERK s.
UNLIMITED_JERK = 100.0


class Joints:
    """The six joints of the stand-in: their reference (the drive's target, in one of two modes: the
    setpoints' cubic, given per instant, or the stand-in's own brake) and the servo's error after the
    reference's last jump.

    reference : (q, qd, a) (6,) each, at ``t`` [s, the stand-in's clock]; error : (e, e') (6,) at
    ``jumped`` [s]; braking : the brake is the reference.
    """

    def __init__(self, home, limits: JointLimits, omega: float):
        home = np.asarray(home, dtype=float)
        self.limits, self.omega = limits, omega
        self.t = 0.0
        self.reference = (home.copy(), np.zeros(6), np.zeros(6))
        self.jerk = np.zeros(6)
        self.error = (np.zeros(6), np.zeros(6))
        self.jumped = 0.0
        self.braking = False

    def motion(self, t):
        """The motion made at times ``t`` (K,) at or after the reference's time, the reference's jerk
        held from its time: position, rate, acceleration, jerk (K, 6) each."""
        s = np.asarray(t, dtype=float)[:, None] - self.t
        q, qd, a = self.reference
        rq, rqd = advance(q, qd, a, s, self.jerk)
        ra = a + self.jerk * s
        e, ed, edd, eddd = decay(*self.error, self.omega, np.asarray(t, dtype=float)[:, None] - self.jumped)
        return rq + e, rqd + ed, ra + edd, self.jerk + eddd

    def now(self, t: float):
        """Position, rate, acceleration and jerk (6,) each of the motion made at ``t``."""
        return tuple(x[0] for x in self.motion([t]))

    def follow(self, t: float, q, qd, a, jerk) -> None:
        """From ``t`` on the reference is (q, qd, a) changing at ``jerk`` (the setpoints' cubic, the
        delay already applied). The servo's error is taken afresh there: where the reference goes on
        as it went, the error's decay goes on unchanged (it depends only on the error and its rate);
        where it jumps, the error takes the jump."""
        y, yd, _, _ = self.now(t)
        q, qd = np.asarray(q, dtype=float), np.asarray(qd, dtype=float)
        self.error, self.jumped = (y - q, yd - qd), t
        self.t, self.reference = t, (q, qd, np.asarray(a, dtype=float))
        self.jerk, self.braking = np.asarray(jerk, dtype=float), False

    def place(self, t: float, q, qd, a) -> None:
        """The joints are at (q, qd, a) (6,) each at ``t``, moving on at that acceleration, and the
        servo's reference with them (no error)."""
        self.follow(t, q, qd, a, np.zeros(6))
        self.error = (np.zeros(6), np.zeros(6))

    def brake(self, t: float) -> None:
        """From ``t`` the reference is the brake, starting where the joints are (no jump)."""
        y, yd, ydd, _ = self.now(t)
        self.t, self.reference, self.jerk = t, (y, yd, ydd), np.zeros(6)
        self.error, self.jumped, self.braking = (np.zeros(6), np.zeros(6)), t, True

    def hold(self, t: float) -> None:
        """From ``t`` the reference holds still where it is."""
        q, _, _ = self.reference_at(t)
        self.follow(t, q, np.zeros(6), np.zeros(6), np.zeros(6))

    def reference_at(self, t: float):
        """The reference's position, rate and acceleration (6,) at ``t``."""
        s = t - self.t
        q, qd, a = self.reference
        rq, rqd = advance(q, qd, a, s, self.jerk)
        return rq, rqd, a + self.jerk * s

    def brake_to(self, t: float) -> bool:
        """Carry the brake on to ``t`` [s], one jerk per :data:`BRAKE_STEP`; True once every joint is at
        rest (rate and acceleration within a step's jerk of zero; then held)."""
        lim, h = self.limits, BRAKE_STEP
        while self.t + h <= t + 1e-12:
            q, qd, a = self.reference
            if np.all(np.abs(qd) <= lim.jerk * h * h / 4) and np.all(np.abs(a) <= lim.jerk * h / 4):
                self.hold(self.t)
                return True
            jerk = stopping_jerk(qd, a, h, lim.acceleration, lim.jerk)
            q, qd = advance(q, qd, a, h, jerk)
            self.reference, self.t = (q, qd, a + jerk * h), self.t + h
            self.error, self.jumped = (np.zeros(6), np.zeros(6)), self.t
        return False

    def at_rest(self, t: float, rate: float = 1e-6) -> bool:
        """The motion made at ``t`` is still (every rate below ``rate``, the reference at rest)."""
        _, yd, _, _ = self.now(t)
        return not self.braking and bool(np.all(np.abs(yd) <= rate) and np.all(self.reference[1] == 0.0))

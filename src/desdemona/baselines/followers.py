"""The parts the classical loops share (:mod:`.classical`'s `dfs` loop and :mod:`.washout`): tilt
coordination, and the limited follower and guard that make one step of commanded accelerations safe.

On a machine with jerk limits each joint's acceleration is continuous and ramps towards its command at
most at the jerk limit (:class:`Follower`), braking in time before rate and position limits; every
step then passes the guard of :meth:`~desdemona.machine.model.Model.step_limit_use` (:class:`Guard`),
its commands scaled down until it does. Without jerk limits (the thesis' toy set) the accelerations
step, as in the thesis.
"""

from __future__ import annotations

import math

import numpy as np

from desdemona.machine.model import Model
from desdemona.machine.plan import advance
from desdemona.support.symbolic import call

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


class Follower:
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


class Guard:
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


def rate_command(error, gain, J):
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

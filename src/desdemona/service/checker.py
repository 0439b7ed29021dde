"""The motion-system stand-in's own check (``desdemona machine``): every setpoint against every limit,
the held joints and the previous setpoint; and the motion the joints actually made.

A real motion system does not trust its controller: its own guard refuses a command that would take a
joint beyond its range, rate, acceleration, jerk, torque or power, that moves a joint which should be
held, or that jumps from where the machine is. Neither the service's controller nor its own guard is
used here; only the model's limits, the exact motion of :func:`desdemona.machine.plan.advance` and the
model's torques.

- every free joint over the whole cycle a setpoint commands, not only at its start: the motion inside
  the cycle is the exact cubic, evaluated on :data:`POINTS` points of the cycle and at the instants
  where a position or a rate turns: position within [position_min, position_max], ``|rate| <=
  velocity``, ``|acceleration| <= acceleration``, ``|jerk| <= jerk``, ``|torque| <= effort`` and
  ``|torque * rate| <= power``, each with the relative tolerance of the independent check
  (:data:`desdemona.check.simulate.TOLERANCE`);
- every held joint at its held position (``config.held``) and at rest (``held``);
- continuity (``continuity``): a setpoint that follows the previous one (the next sequence number)
  starts where the previous one's cycle ends, within :data:`CONTINUITY` of its scale plus
  :data:`ABSOLUTE`; or, re-anchored on the measured machine (protocol version 2), within
  :data:`REANCHOR` cycles at the rate limit (position) and at the acceleration limit (rate), its
  acceleration continuous: counted as a re-anchor, not a violation;
- the motion made (:meth:`Checker.made`): every joint's position, rate, acceleration and jerk at every
  step of the stand-in's servos, and the free joints' torque and power at every State sample, against
  the same limits with :data:`MADE_TOLERANCE` (kinds ``made position`` ...).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from desdemona.check.simulate import TOLERANCE
from desdemona.machine.model import Model
from desdemona.machine.params import JOINT_NAMES
from desdemona.machine.plan import advance
from desdemona.service import protocol

#: Points of each cycle at which the motion is evaluated (both ends included), besides the instants
#: where a position or a rate turns.
POINTS = 11
#: Continuity and rest: relative tolerance (of the limit, or of the position's scale) ...
CONTINUITY = 1e-6
#: ... plus this absolute one.
ABSOLUTE = 1e-9
#: A re-anchored setpoint starts within this many cycles at the rate limit (position) and at the
#: acceleration limit (rate) of where the previous one ends: the service's own tracking tolerance
#: (a larger error is a fault there, and it parks).
REANCHOR = 2.0
#: The motion made may pass a limit by this share of it: the servo's loop corrects round-off and an
#: error's decay, and adds a hair to a motion commanded at the limit (2.5e-6 of the cabin's jerk limit
#: was seen) -- a measured motion is judged with a tolerance, as a drive's own trip levels are.
MADE_TOLERANCE = 1e-3
#: ... and its jerk by this share: a re-anchored or bridged reference leaves the servo an error whose
#: decay adds to a jerk commanded at its limit (1.2 % seen on a loaded computer's session; 2.1 % on the
#: cabin as a session resumed after a drive fault and its reset, from a start measured with noise). A
#: trip level on a measured jerk, not a limit of the setpoints: they are checked without it.
MADE_JERK_TOLERANCE = 0.05
#: The limits measured per free joint, in the order of ``violations.csv``'s ``what``.
LIMIT_KINDS = ("position", "rate", "acceleration", "jerk", "effort", "power")
#: The same, of the motion made.
MADE_KINDS = tuple(f"made {k}" for k in LIMIT_KINDS)
KINDS = LIMIT_KINDS + ("held", "continuity") + MADE_KINDS


@dataclass(frozen=True)
class Violation:
    """One limit a setpoint breaks: ``what`` (:data:`KINDS`) of ``joint`` (a name of
    :data:`JOINT_NAMES`), the worst ``value`` and the ``limit`` it crosses (for ``held`` and
    ``continuity``: the value expected); ``time`` [s since bound] and ``sequence`` of the setpoint;
    ``detail`` where in the cycle, or which quantity and its tolerance."""

    time: float
    sequence: int
    joint: str
    what: str
    value: float
    limit: float
    detail: str = ""


class Checker:
    """The machine's own guard for one model: :meth:`check` a setpoint against the limits, the held
    joints and the previous setpoint."""

    def __init__(self, model: Model):
        self.model = model
        self.select, self.expand = model.config.select, model.config.expand
        self.held = model.config.held
        self.names = list(model.config.joint_names)
        lim = model.limits
        self.lo, self.hi = np.asarray(lim.position_min, float), np.asarray(lim.position_max, float)
        self.bounded = np.isfinite(self.lo) & np.isfinite(self.hi)
        self.mid = np.where(self.bounded, 0.5 * (np.where(self.bounded, self.lo, 0) + np.where(self.bounded, self.hi, 0)), 0.0)
        self.half = np.where(self.bounded, 0.5 * (np.where(self.bounded, self.hi, 1) - np.where(self.bounded, self.lo, -1)), np.inf)
        self.velocity, self.acceleration = np.asarray(lim.velocity, float), np.asarray(lim.acceleration, float)
        self.jerk, self.effort, self.power = (np.asarray(x, float) for x in (lim.jerk, lim.effort, lim.power))
        self.smooth = bool(lim.smooth)
        self.tau = model.functions["tau"]
        p = model.params
        # scales of the held joints' tolerances (every joint's limits, from the parameters)
        span = p.position_max - p.position_min
        self.held_scale = {"position": np.where(np.isfinite(span), span, 1.0), "rate": p.velocity_max,
                           "acceleration": p.acceleration_max, "jerk": p.jerk_max}
        # continuity: a position's scale is its range, or a second at the rate limit where unbounded
        self.position_scale = np.where(self.bounded, self.hi - self.lo, self.velocity)
        self.reanchored = 0  # setpoints re-anchored on the measured machine
        self.largest_reanchor = np.zeros(2 * model.n)  # positions, then rates
        # the motion made: every joint's limits (the held ones must stay still within them too)
        self.every = {"position": (p.position_min, p.position_max), "rate": p.velocity_max,
                      "acceleration": p.acceleration_max, "jerk": p.jerk_max}

    def _times(self, q, qd, a, j, step: float) -> np.ndarray:
        """Instants of the cycle to evaluate: :data:`POINTS` evenly, and where an acceleration would
        turn a rate (a + j s = 0) or a rate a position (qd + a s + j s^2 / 2 = 0)."""
        with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
            root = np.sqrt(a * a - 2.0 * j * qd)  # NaN where the rate never reaches zero
            s = np.concatenate([np.linspace(0.0, step, POINTS), -a / j, (-a + root) / j, (-a - root) / j,
                                np.where(j == 0, -qd / a, np.nan)])
        return np.unique(s[np.isfinite(s) & (s >= 0.0) & (s <= step)])

    def check(self, sp: protocol.Setpoint, previous: protocol.Setpoint | None, t: float, where=None):
        """Violations of setpoint ``sp`` (received at ``t``) and the use of each limit {kind: (n,)};
        ``previous`` : the setpoint it follows, or None where continuity is not checked; ``where`` :
        (positions, rates) (6,) of the joints as they are when it came, or None: a setpoint that starts
        there is re-anchored on the machine (its acceleration free: the machine's is not measured)."""
        out: list[Violation] = []
        q, qd, a, j = (self.select(x) for x in (sp.position, sp.rate, sp.acceleration, sp.jerk))
        s = self._times(q, qd, a, j, sp.step)[:, None]
        qs, qds = advance(q, qd, a, s, j)
        accs = a + j * s
        tau = np.asarray(self.tau(qs.T, qds.T, accs.T)).T.reshape(qs.shape)
        pw = tau * qds
        use = {"position": np.abs(qs - self.mid) / self.half, "rate": np.abs(qds) / self.velocity,
               "acceleration": np.abs(accs) / self.acceleration,
               "jerk": np.broadcast_to(np.abs(j) / self.jerk, qs.shape),
               "effort": np.abs(tau) / self.effort, "power": np.abs(pw) / self.power}
        values = {"position": qs, "rate": qds, "acceleration": accs, "jerk": np.broadcast_to(j, qs.shape),
                  "effort": tau, "power": pw}
        limits = {"rate": self.velocity, "acceleration": self.acceleration, "jerk": self.jerk,
                  "effort": self.effort, "power": self.power}
        worst = {}
        for kind in LIMIT_KINDS:
            u = use[kind]
            worst[kind] = np.max(u, axis=0)
            for k in np.flatnonzero(worst[kind] > 1.0 + TOLERANCE):
                row = int(np.argmax(u[:, k]))
                value = float(values[kind][row, k])
                if kind == "position":
                    limit = float(self.hi[k] if value > self.mid[k] else self.lo[k])
                else:
                    limit = float(limits[kind][k])
                out.append(Violation(t, sp.sequence, self.names[k], kind, value, limit,
                                     f"{float(s[row, 0]):.6g} s into the cycle of {sp.step:.6g} s"))
        for i, position in self.held.items():
            for what, value, target in (("position", sp.position[i], position), ("rate", sp.rate[i], 0.0),
                                        ("acceleration", sp.acceleration[i], 0.0), ("jerk", sp.jerk[i], 0.0)):
                scale = self.held_scale[what][i]
                tol = ABSOLUTE + (CONTINUITY * scale if math.isfinite(scale) else 0.0)
                if abs(value - target) > tol:
                    out.append(Violation(t, sp.sequence, JOINT_NAMES[i], "held", float(value), float(target),
                                         f"{what} of a held joint: {float(value):.9g}, held at {target:.9g}"))
        if previous is not None:
            out += self._continuity(sp, previous, t, where)
        return out, worst

    def _continuity(self, sp, prev, t, where=None) -> list[Violation]:
        pq, pqd, pa, pj = (self.select(x) for x in (prev.position, prev.rate, prev.acceleration, prev.jerk))
        eq, eqd = advance(pq, pqd, pa, prev.step, pj)
        ea = pa + pj * prev.step
        checks = [("position", eq, self.select(sp.position), self.position_scale),
                  ("rate", eqd, self.select(sp.rate), self.velocity)]
        if self.smooth:
            checks.append(("acceleration", ea, self.select(sp.acceleration), self.acceleration))
        lim = (self.velocity, self.acceleration)
        if all(np.all(np.abs(got - expected) <= REANCHOR * sp.step * scale)
               for (_, expected, got, _), scale in zip(checks[:2], lim)) and (
                len(checks) < 3 or np.all(np.abs(checks[2][2] - checks[2][1]) <= ABSOLUTE + CONTINUITY * checks[2][3])):
            jumps = [np.abs(got - expected) for _, expected, got, _ in checks[:2]]
            if any(np.any(j > ABSOLUTE + CONTINUITY * c[3]) for j, c in zip(jumps, checks)):
                self.reanchored += 1
                self.largest_reanchor = np.maximum(self.largest_reanchor, np.concatenate(jumps))
            return []
        if where is not None and all(
                np.all(np.abs(got - self.select(at)) <= REANCHOR * sp.step * scale)
                for (_, _, got, _), at, scale in zip(checks[:2], where, lim)):
            self.reanchored += 1  # started where the machine measurably is (after a stop of its own)
            return []
        out = []
        for what, expected, got, scale in checks:
            tol = ABSOLUTE + CONTINUITY * scale
            for k in np.flatnonzero(np.abs(got - expected) > tol):
                out.append(Violation(t, sp.sequence, self.names[k], "continuity", float(got[k]), float(expected[k]),
                                     f"{what} {got[k]:.9g} where the previous cycle (sequence {prev.sequence}) "
                                     f"ends at {expected[k]:.9g}, tolerance {tol[k]:.3g}"))
        return out


    def made(self, t: float, sequence: int, q, qd, qdd, jerk) -> tuple[list[Violation], dict]:
        """Violations of the motion made, (K, 6) positions, rates, accelerations and jerks at K instants
        (the last one at ``t``, the State's time); the free joints' torque and power at the last one.
        Returns the violations (kind ``made ...``, ``sequence`` the setpoint being followed) and the use
        of each limit {kind: (6,)} (torque and power: of the free joints, others 0)."""
        lo, hi = (np.asarray(x, float) for x in self.every["position"])
        bounded = np.isfinite(lo) & np.isfinite(hi)
        low, high = np.where(bounded, lo, -1.0), np.where(bounded, hi, 1.0)
        mid = np.where(bounded, 0.5 * (low + high), 0.0)
        half = np.where(bounded, 0.5 * (high - low), np.inf)
        q_free, qd_free, qdd_free = self.select(q[-1]), self.select(qd[-1]), self.select(qdd[-1])
        tau = np.asarray(self.tau(q_free, qd_free, qdd_free), dtype=float).reshape(-1)
        effort = self.expand(np.abs(tau) / self.effort, "zero")
        power = self.expand(np.abs(tau * qd_free) / self.power, "zero")
        use = {"position": np.max(np.abs(q - mid) / half, axis=0),
               "rate": np.max(np.abs(qd) / self.every["rate"], axis=0),
               "acceleration": np.max(np.abs(qdd) / self.every["acceleration"], axis=0),
               "jerk": np.max(np.abs(jerk) / self.every["jerk"], axis=0), "effort": effort, "power": power}
        values = {"position": q, "rate": qd, "acceleration": qdd, "jerk": jerk}
        out = []
        for kind, per_joint in use.items():
            for i in np.flatnonzero(per_joint > 1.0 + (MADE_JERK_TOLERANCE if kind == "jerk" else MADE_TOLERANCE)):
                if kind in values:
                    column = values[kind][:, i]
                    value = float(column[np.argmax(np.abs(column - (mid[i] if kind == "position" else 0.0)))])
                    limit = (float(hi[i] if value > mid[i] else lo[i]) if kind == "position"
                             else float(self.every[kind][i]))
                else:  # a free joint's torque or power (a held joint's use is 0)
                    torque = self.expand(tau, "zero")[i]
                    value = float(torque if kind == "effort" else torque * qd[-1, i])
                    limit = float(self.expand(self.effort if kind == "effort" else self.power, "zero")[i])
                out.append(Violation(t, sequence, JOINT_NAMES[i], f"made {kind}", value, limit,
                                     "the motion the joints made"))
        return out, use

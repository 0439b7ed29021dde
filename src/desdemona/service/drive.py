"""The motion-system stand-in's own supervision (``desdemona machine``): which reference its joints'
servos follow, independently of the service.

- **Following.** The first setpoint (or the first after the machine came to rest on its own) anchors
  the setpoints' time line to the stand-in's clock: cycle ``c`` is *due* at ``c + anchor``. The drive
  runs that time line ``timeout`` cycles behind (a queue: a setpoint a little late is still in time)
  and a transport delay ``delay`` later: at time T its reference is the cubic of the setpoint whose
  cycle holds ``T - anchor - lead``, lead = timeout x step + delay.
- **No setpoint in time** (the queue ran dry: no valid setpoint for the timeout): it brakes every joint
  at once from where it is, the fastest stop the limits allow (:meth:`Joints.brake`), then holds
  (``braking`` -> ``stopped``). It never resumes while moving; at rest it follows again a setpoint that
  starts where it stands, at rest (:data:`START`).
- **A fault** (``--fault AT:JOINT``, a drive fault injected ``AT`` seconds after the first setpoint)
  and an **emergency stop** (a Command, or SIGUSR1): the same fastest stop; then it refuses motion
  until a reset (a Command) at rest.
- A setpoint whose status is ``fault`` (the service's own check failed): not followed; it brakes.

Every change is an :class:`Event` with its time, kept in :attr:`Drive.events`.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from desdemona.machine.params import JOINT_NAMES
from desdemona.machine.plan import advance
from desdemona.service import protocol
from desdemona.service.servo import JointLimits, Joints

#: A setpoint starts where the machine stands (to follow from rest) within this share of a cycle at
#: the rate limit (position) and at the acceleration limit (rate).
START = 0.1
#: The motion made is moved on and sampled (for its check) every SAMPLE seconds.
SAMPLE = 0.002
#: Still: every rate and acceleration within this share of its limit (round-off of a stop at rest).
STILL = 1e-6


@dataclass(frozen=True)
class Event:
    """Something the stand-in did or met at ``time`` [s, its clock]: ``what`` (a status it entered, a
    command, a fault, a timing fault, a refused setpoint) and a ``detail``."""

    time: float
    what: str
    detail: str = ""


@dataclass(frozen=True)
class Stop:
    """One stop of the stand-in's own: ``why``, from ``start`` [s] with the longest shortest stop the
    limits allow from there, ``bound`` [s]; ``rest``: when every joint was at rest (None: not yet)."""

    why: str
    start: float
    bound: float
    rest: float | None = None


@dataclass
class Drive:
    """The supervision of one stand-in: ``joints`` (the servos), ``timeout`` [cycles], ``delay`` [s].
    :meth:`setpoint`, :meth:`command`, :meth:`fault` and :meth:`emergency` take what comes;
    :meth:`run_to` moves the joints on in time."""

    joints: Joints
    timeout: int
    delay: float
    status: str = "ready"
    fault_code: str = "none"
    fault_joint: int | None = None
    anchor: float | None = None
    step: float | None = None
    queue: list = field(default_factory=list)
    applied: protocol.Setpoint | None = None
    events: list = field(default_factory=list)
    stops: list = field(default_factory=list)
    ended_moving: bool = False
    bridged: protocol.Setpoint | None = None

    @classmethod
    def of(cls, model, timeout: int, delay: float, bandwidth_hz: float) -> Drive:
        home = model.config.expand(np.zeros(model.n))
        return cls(Joints(home, JointLimits.of(model.params), 2.0 * np.pi * bandwidth_hz), timeout, delay)

    @property
    def lead(self) -> float:
        return self.timeout * self.step + self.delay

    def drive_time(self, t: float) -> float:
        """Where on the setpoints' time line the reference is at ``t`` (the stand-in's clock)."""
        return t - self.anchor - self.lead

    def due(self, sp: protocol.Setpoint) -> float | None:
        """When ``sp``'s cycle is due on the stand-in's clock (None before the time line is anchored)."""
        return None if self.anchor is None else sp.cycle_time + self.anchor

    def _event(self, t: float, what: str, detail: str = "") -> None:
        self.events.append(Event(t, what, detail))

    def _enter(self, t: float, status: str, detail: str = "") -> None:
        if status != self.status:
            self.status = status
            self._event(t, status, detail)

    def setpoint(self, sp: protocol.Setpoint, t: float) -> str:
        """Take setpoint ``sp`` arrived at ``t``: "" if it is queued to be followed, else why not."""
        if refusal := self.setpoint_refusal():
            return refusal
        if sp.status == "fault":
            self._stop(t, "braking", "the service reported a fault: not followed, braking")
            return "refused: the service reported a fault"
        if self.status in ("ready", "stopped"):
            return self._start(sp, t)
        if self.drive_time(t) > sp.cycle_time + sp.step:
            return "refused: its cycle is over"
        self.queue.append(sp)
        return ""

    def _start(self, sp: protocol.Setpoint, t: float) -> str:
        lim = self.joints.limits
        y, _, _, _ = self.joints.now(t)
        tol_q, tol_qd = START * lim.velocity * sp.step, START * lim.acceleration * sp.step
        if np.any(np.abs(sp.position - y) > tol_q) or np.any(np.abs(sp.rate) > tol_qd):
            worst = int(np.argmax(np.abs(sp.position - y) / tol_q))
            return (f"refused: does not start where the machine stands ({JOINT_NAMES[worst]} at "
                    f"{y[worst]:.6g}, the setpoint {sp.position[worst]:.6g})")
        self.anchor, self.step, self.queue, self.applied = t - sp.cycle_time, sp.step, [sp], None
        self._enter(t, "following", f"from setpoint {sp.sequence}")
        return ""

    def command(self, action: str, t: float) -> None:
        """An operator's command: emergency stop or reset (the others are the service's)."""
        self._event(t, f"command {action}")
        if action == "emergency stop":
            self.emergency(t, "a Command")
        elif action == "reset":
            if self.status not in ("fault", "e-stop"):
                self._event(t, "reset ignored", f"nothing to reset ({self.status})")
            elif self.joints.braking:
                self._event(t, "reset refused", "still braking")
            else:
                self.fault_code, self.fault_joint, self.queue, self.applied = "none", None, [], None
                self._enter(t, "ready", "reset")

    def over_limit(self, t: float, why: str) -> str:
        """A setpoint over a limit of the machine (its own check, :mod:`desdemona.service.checker`):
        never followed; the drive brakes on its own as for a lost stream, then takes a new motion
        that starts where it stands."""
        if self.status != "following":
            return self.setpoint_refusal() or f"refused: over a limit ({why})"
        self._stop(t, "braking", f"a setpoint over a limit ({why}): not followed, braking")
        return f"refused: over a limit ({why})"

    def setpoint_refusal(self) -> str:
        """Why a setpoint is refused in the drive's present status ("" if it is not)."""
        if self.status in ("fault", "e-stop"):
            return f"refused: {self.status} (a reset is needed)"
        return "refused: braking on its own" if self.status == "braking" else ""

    def emergency(self, t: float, source: str) -> None:
        """An emergency stop: the fastest stop, then no motion until a reset."""
        self._stop(t, "e-stop", f"emergency stop ({source})")

    def fault(self, t: float, joint: int) -> None:
        """A drive fault on ``joint``: reported, the fastest stop, no motion until a reset."""
        self.fault_code, self.fault_joint = "drive", joint
        self._stop(t, "fault", f"drive fault on {JOINT_NAMES[joint]}")

    def _stop(self, t: float, status: str, why: str) -> None:
        moving = not self.joints.at_rest(t)
        if moving and not self.joints.braking:
            _, qd, a, _ = self.joints.now(t)
            self.joints.brake(t)
            self.stops.append(Stop(why, t, self.joints.limits.stopping_time(qd, a)))
        elif not moving:
            self.joints.hold(t)
        self.queue = []
        self._enter(t, status, why)

    def run_to(self, t0: float, t1: float) -> list[tuple]:
        """Move the joints on from ``t0`` to ``t1`` [s] in steps of :data:`SAMPLE` (the brake within
        them in its own :data:`~desdemona.service.servo.BRAKE_STEP`); the motion made at each step's
        end: [(t, q, qd, qdd, jerk), ...]."""
        samples = []
        count = max(1, round((t1 - t0) / SAMPLE))
        for i in range(1, count + 1):
            t = t0 + (t1 - t0) * i / count
            self._step(t)
            samples.append((t, *self.joints.now(t)))
        return samples

    def _step(self, t: float) -> None:
        if self.joints.braking:
            if self.joints.brake_to(t):
                self._rested(t)
            return
        if self.status != "following" or self.anchor is None:
            return
        tau = self.drive_time(t)
        while self.queue and self.queue[0].cycle_time + self.queue[0].step <= tau and len(self.queue) > 1 \
                and self.queue[1].cycle_time <= tau:
            self.queue.pop(0)
        sp = self.queue[0] if self.queue else None
        if sp is not None and tau < sp.cycle_time and self.applied is None:
            return  # the first cycle is not due on the drive yet: it holds where it stands
        if sp is not None and sp.cycle_time + sp.step < tau and len(self.queue) > 1:
            # a cycle lost between two that came: bridged by the next one's cubic taken back to it
            # (continuous where that one starts; at the lost cycle's start it differs from where the
            # last one ended by the cycles' difference of jerk, a third-order step the servo takes)
            if self.queue[1] is not self.bridged:
                self.bridged = self.queue[1]
                self._event(t, "bridged", f"setpoints {sp.sequence + 1}-{self.queue[1].sequence - 1} lost: "
                                          f"followed {self.queue[1].sequence} from {tau - self.queue[1].cycle_time:.4f} s")
            sp = self.queue[1]
        if sp is None or not (sp.cycle_time - self.timeout * sp.step <= tau <= sp.cycle_time + sp.step + 1e-9) or (
                tau < sp.cycle_time and sp is not self.bridged):
            last = self.applied
            # judged, and braked from, where the last cycle ended (not its cubic run on beyond it)
            end = t if last is None else last.cycle_time + last.step + self.anchor + self.lead
            self._starved(min(t, max(end, self.joints.t)))
            if self.joints.braking and self.joints.brake_to(t):
                self._rested(t)
            return
        if sp is self.applied and not self.joints.braking:
            return  # the same cubic goes on: the reference carries it exactly
        s = tau - sp.cycle_time
        q, qd = advance_setpoint(sp, s)
        self.joints.follow(t, q, qd, sp.acceleration + sp.jerk * s, sp.jerk)
        self.applied = sp

    def _starved(self, t: float) -> None:
        # moving: the commanded motion where it ended (a servo still settling a small error is not)
        lim = self.joints.limits
        _, qd, a = self.joints.reference_at(t)
        moving = np.any(np.abs(qd) > STILL * lim.velocity) or np.any(np.abs(a) > STILL * lim.acceleration)
        if moving:
            self.ended_moving = True
            self._stop(t, "braking", "no setpoint in time while moving: braking on its own")
        else:
            self.joints.hold(t)
            self._enter(t, "stopped", "no setpoint in time, at rest: holding")

    def _rested(self, t: float) -> None:
        if self.stops and self.stops[-1].rest is None:
            last = self.stops[-1]
            self.stops[-1] = Stop(last.why, last.start, last.bound, t)
        self._event(t, "at rest")
        if self.status == "braking":
            self._enter(t, "stopped", "at rest after braking on its own")

    def applied_time(self, t: float) -> float:
        """Where on the setpoints' time line the joints' reference was at ``t`` (0 before any)."""
        if self.applied is None or self.anchor is None:
            return 0.0
        if self.status == "following":
            return self.drive_time(t)
        return self.applied.cycle_time + self.applied.step


def advance_setpoint(sp: protocol.Setpoint, s: float):
    """Position and rate (6,) of setpoint ``sp``'s cubic ``s`` [s] into its cycle."""
    return advance(np.asarray(sp.position), np.asarray(sp.rate), np.asarray(sp.acceleration), s, np.asarray(sp.jerk))

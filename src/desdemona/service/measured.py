"""What the service knows of the machine it drives: the motion system's State messages (protocol
version 2), checked, and the tracking error they show.

The tracking error compares like with like: a State says which point of the commanded motion its
joints were following when measured (``applied_time`` on the setpoints' time line, every transport
delay and queue of the motion system included), so the error is the measured position and rate less
the commanded ones at that point. Carried forward to a cycle's time with the commands in flight, the
machine is expected where the commanded motion is then, plus that error.

Tolerances, from the limits (per free joint, the session's step h):

- **fault**: a position error beyond the way the joint covers in :data:`CYCLES` cycles at its rate
  limit, or a rate error beyond what it gains in as many cycles at its acceleration limit: the machine
  is not doing what it was told (the stand-in's own re-anchor allowance is the same);
- **re-anchor**: beyond :data:`BAND` of those the service plans from the measured machine rather than
  from its own command (below it, the error is a measurement's noise, and the reference stays
  continuous for the servos' feed-forward).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from desdemona.machine.plan import advance
from desdemona.service import protocol
from desdemona.service.drops import Drops
from desdemona.service.signing import Incoming

#: The fault tolerance in cycles at the rate limit (position) and at the acceleration limit (rate).
CYCLES = 2.0
#: The share of the fault tolerance beyond which the plan starts from the measured machine.
BAND = 0.05
#: The motion system's statuses in which it does not follow the service.
STOPPED_ON_ITS_OWN = ("braking", "fault", "e-stop")
#: The statuses of a motion system at rest on its own, ready to follow a setpoint that starts where
#: it stands.
HOLDING_ON_ITS_OWN = ("stopped", "ready")
#: After the machine stopped on its own, it must follow the service's own hold this long [s] before
#: the service plans motion again. The hold starts where the machine was measured, a measurement's
#: noise off where it stands: the servo takes that step, and its error rings out with a jerk of about
#: 2 omega^3 times the step (a 5 Hz loop: 0.6 rad/s^3 for 1e-5 rad, a tenth of the cabin's jerk
#: limit). At rest that jerk is harmless; added to a plan that starts at its jerk limit it went over
#: (the hour's soak, docs/benchmarks/soak.md). A quarter of a second leaves a hundredth of it for a
#: 5 Hz loop, and the plan then starts on the reference the machine already follows.
SETTLE = 0.25


@dataclass(frozen=True)
class Tracking:
    """The newest State carried to a cycle: ``error`` (e_q, e_qd) of the free joints (n,) each, the
    largest use of the fault tolerance ``use`` (1 = at it), and the State's ``status``."""

    error: tuple[np.ndarray, np.ndarray]
    use: float
    status: str
    state: protocol.MachineState


class MachineLink:
    """The States of the motion system at ``address`` (the service's ``--send``), for ``model`` at the
    session's step ``h`` [s]: :meth:`take` a datagram; :meth:`tracking` of the newest State against the
    commanded motion; ``lost_after`` [s] without a State (once they came) is a loss. With ``key`` only
    signed States are taken; a new session of the motion system is its restart (its sequence counted
    afresh, the old session's States never taken again); drops are counted by reason
    (:class:`~desdemona.service.drops.Drops`, ``on_drop(line)`` at most once a second per reason of
    ``clock``)."""

    def __init__(self, model, h: float, address: tuple[str, int], lost_after: float, key: bytes | None = None,
                 on_drop=None, clock=None):
        self.select = model.config.select
        lim = model.limits
        self.tolerance = (CYCLES * h * np.asarray(lim.velocity, float), CYCLES * h * np.asarray(lim.acceleration, float))
        self.address, self.lost_after = address, lost_after
        self.newest: protocol.MachineState | None = None
        self.session = None  # the motion system's session (a new one: it restarted)
        self.past: set = set()  # its sessions before
        self.arrived: float | None = None
        self.received = 0
        self.incoming = Incoming(key)
        self.drops = Drops(on_drop) if clock is None else Drops(on_drop, clock)

    @property
    def dropped(self):
        """reason -> datagrams dropped (:data:`~desdemona.service.protocol.REASONS`)."""
        return self.drops.counts

    def take(self, data: bytes, sender, now: float) -> str:
        """A datagram that came to the service's sending socket: "" if it is a valid State of the
        machine (kept as the newest), else the reason it was dropped (counted)."""
        why = self._check(data, sender)
        if why:
            self.drops(*why)
            return why[0]
        self.received += 1
        self.arrived = now
        return ""

    def _check(self, data: bytes, sender) -> tuple[str, str] | None:
        if tuple(sender[:2]) != tuple(self.address):
            return "sender", f"a datagram from {sender[0]}:{sender[1]}, the machine is {self.address[0]}:" \
                             f"{self.address[1]}"
        try:
            frame = self.incoming.read(data)
        except protocol.ProtocolError as exc:
            return exc.reason, f"state: {exc}"
        message = frame.message
        if not isinstance(message, protocol.MachineState):
            return "kind", f"a {type(message).__name__} from the machine's address"
        if frame.session in self.past:
            return "sender", f"a State of the machine's session {frame.session}, replaced by a newer one"
        if (self.newest is not None and frame.session == self.session
                and message.sequence <= self.newest.sequence):
            return "stale", f"state sequence {message.sequence} after {self.newest.sequence}"
        if self.newest is not None and frame.session != self.session:
            self.past.add(self.session)  # the motion system restarted
        self.newest, self.session = message, frame.session
        return None

    def lost(self, now: float) -> bool:
        """States came, and none for ``lost_after`` seconds."""
        return self.arrived is not None and now - self.arrived > self.lost_after

    def tracking(self, commanded) -> Tracking | None:
        """The newest State against ``commanded(t) -> (q, qd)`` of the free joints on the setpoints'
        time line (None where it has no motion there); None before any State."""
        state = self.newest
        if state is None:
            return None
        at = commanded(state.applied_time) if state.applied is not None else None
        if at is None:
            zero = np.zeros_like(self.tolerance[0])
            return Tracking((zero, zero), 0.0, state.status, state)
        e_q = self.select(state.position) - at[0]
        e_qd = self.select(state.rate) - at[1]
        use = float(max(np.max(np.abs(e_q) / self.tolerance[0]), np.max(np.abs(e_qd) / self.tolerance[1])))
        return Tracking((e_q, e_qd), use, state.status, state)

    def measured(self, now: float) -> tuple[np.ndarray, np.ndarray]:
        """The newest State's free joints' positions and rates, carried to ``now`` (the service's
        clock) at those rates (the machine's own stop is not known here: its acceleration is not
        measured); a rate within the noise band (:data:`BAND` of the tolerance) is taken as rest."""
        q, qd = self.select(self.newest.position), self.select(self.newest.rate)
        qd = np.where(np.abs(qd) <= BAND * self.tolerance[1], 0.0, qd)
        return q + qd * max(now - self.arrived, 0.0), qd


def commanded_at(starts, u, jerks, h: float):
    """``commanded(t)`` of cycles starting at k h from ``starts`` [(q, qd, a), ...] with accelerations
    ``u`` and jerks: the free joints' (q, qd) at t (None outside the cycles commanded, or before those
    still in memory: :class:`~desdemona.service.spill.Spilled`)."""
    def at(t: float):
        k = int(np.floor(t / h + 1e-9))
        if k < 0 or k >= len(u):
            return None
        s = min(max(t - k * h, 0.0), h)
        try:
            (q, qd, _), acceleration, jerk = starts[k], u[k], jerks[k]
        except IndexError:  # a State about a setpoint of long ago: nothing to judge it on
            return None
        return advance(q, qd, acceleration, s, jerk)
    return at

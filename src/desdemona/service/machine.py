"""A stand-in for the motion system (``desdemona machine``): it receives the service's setpoints over
UDP, moves a model of the machine's joints with them, reports what they do, and has its own safety
layer, independent of the service.

- **Its joints** (:mod:`desdemona.service.servo`): each joint's servo follows the setpoints' cubic a
  transport delay late (``delay``), with a position loop of ``bandwidth_hz`` for what the fed-forward
  rate and acceleration do not carry; measurement noise on what it reports.
- **Its supervision** (:mod:`desdemona.service.drive`): no setpoint in time (it runs the setpoints' time
  line ``timeout`` cycles behind) -> it brakes every joint to rest on its own, the fastest stop the
  limits allow, then holds; an emergency stop (a Command from the ``operator`` host, or SIGUSR1; a
  first SIGINT or SIGTERM too, after which it ends once at rest) -> the same stop, then no motion until
  a reset Command; ``fault`` = (seconds after the first setpoint, joint) -> a drive fault on that joint,
  reported, the same stop, no motion until a reset; a setpoint over a limit (its check, below) -> never
  followed: the same stop, as for no setpoint in time.
- **Its State** (protocol version 2): every joint's measured position and rate, its status, a fault
  and its joint, the setpoint followed and where on its time line, ``state_rate`` times a second, to the
  address the setpoints come from (setpoints from any other address are dropped).
- **Its check** (:mod:`desdemona.service.checker`): every setpoint against every limit over its whole
  cycle, held joints, continuity (or a re-anchor on the measured machine); the motion the joints made,
  at every step of the servos; and **when** each setpoint came: later than ``late`` cycles after it was
  due, a gap between arrivals longer than the timeout while moving, or a burst (:data:`BURST`
  setpoints within a quarter of a cycle) is a timing fault. A stream that ends while the machine moves
  (it had to brake on its own) is never a pass.

It stops ``idle`` seconds after the last datagram once the machine is at rest, after ``duration``
seconds, or at rest after a SIGINT/SIGTERM (a second one: at once). Its folder holds, each appended
and flushed as it goes (a killed stand-in leaves them up to the last sample):

- ``setpoints.csv``: one row per setpoint checked: receive time [s since the socket was bound],
  sequence, the sender's time, status, source, answers, cycle_time, step, then per joint of
  :data:`desdemona.machine.params.JOINT_NAMES` its position, rate, acceleration and jerk;
- ``motion.csv``: the motion made, one row per State sent: time, status, fault, fault joint, the
  setpoint followed (sequence) and where on its time line, then per joint the measured position and
  rate (as the State says: with the noise) and the acceleration;
- ``violations.csv``: one row per violation: time, sequence, joint, what (position, rate, acceleration,
  jerk, effort, power, held, continuity; ``made ...`` of the motion made), value, limit, detail;
- ``events.csv``: every status it entered, command, fault, timing fault and refused setpoint, with its
  time and a detail;
- ``summary.json`` (written at the start, and whole at the end): counts (received, dropped by reason,
  refused by reason, gaps, violations by kind, timing faults by kind), the worst use of every limit by
  the setpoints and by the motion made, its own stops (why, when, the shortest stop the limits allowed,
  when at rest), whether the stream ended while moving, and why it stopped.

:func:`exit_code` is the command's exit status: 1 unless it passed (no violation, no timing fault, no
stream that ended while moving), 0 otherwise.
"""

from __future__ import annotations

import json
import math
import signal
import socket
import threading
import time
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from desdemona.machine.model import Model
from desdemona.machine.params import JOINT_NAMES
from desdemona.service import pacing, protocol
from desdemona.service.checker import (ABSOLUTE, CONTINUITY, KINDS, LIMIT_KINDS, MADE_KINDS, POINTS, REANCHOR,
                                       Checker, Violation)
from desdemona.service.drive import Drive, Event
from desdemona.service.drops import Drops
from desdemona.service.machinelog import (FILES, MAX_KEPT, WRITTEN_BY, Files, number, record, summary, violation,
                                          write_summary)
from desdemona.service.servo import BANDWIDTH_HZ, DELAY, NOISE
from desdemona.service.signing import Incoming, Outgoing
from desdemona.support import guard

__all__ = ["ABSOLUTE", "CONTINUITY", "FILES", "KINDS", "LIMIT_KINDS", "MADE_KINDS", "POINTS", "REANCHOR", "Checker",
           "MachineOptions", "Report", "Violation", "drop_reason", "exit_code", "parse_fault", "prepare", "run",
           "summary"]

#: Every receive waits at most this long [s], so the loop notices ``idle``, ``duration`` and signals.
RECEIVE_TIMEOUT = 0.05
#: The largest datagram read (a longer one is cut by the kernel, and refused as a wrong length).
MAX_DATAGRAM = 65536
#: A burst: this many setpoints arriving within a quarter of a cycle.
BURST = 3
TIMING = ("late", "gap", "burst")



@dataclass(frozen=True)
class MachineOptions:
    """The stand-in's servo and supervision: ``delay`` [s] transport delay, ``bandwidth_hz`` of the
    position loop, ``noise`` (position [rad | m], rate [rad/s | m/s]) one standard deviation, seeded by
    ``seed``; ``state_rate`` [Hz] of its State messages (and of ``motion.csv``); ``timeout`` [cycles]
    it runs behind the setpoints' time line (no setpoint for that long: it brakes); ``late``
    [cycles] after its cycle was due a setpoint counts as late; ``fault``: (seconds after the first
    setpoint, joint index) of an injected drive fault, or None; ``operator``: the host whose Commands
    it takes; ``state_outage``: (seconds after the first setpoint, length [s]) in which it sends no
    State (a test of the service's loss of them), or None; ``key``: the shared key its datagrams are
    signed with and every datagram it takes must be (:mod:`desdemona.service.signing`), or None."""

    delay: float = DELAY
    bandwidth_hz: float = BANDWIDTH_HZ
    noise: tuple[float, float] = NOISE
    state_rate: float = 100.0
    timeout: int = 3
    late: float = 1.5
    fault: tuple[float, int] | None = None
    operator: str = "127.0.0.1"
    seed: int = 0
    state_outage: tuple[float, float] | None = None
    key: bytes | None = field(default=None, repr=False)

    def __post_init__(self):
        for name, value, low in (("--delay", self.delay, 0.0), ("--late", self.late, 0.0),
                                 ("--noise", min(self.noise), 0.0)):
            if not (math.isfinite(value) and value >= low):
                raise ValueError(f"{name} {value!r}: a number >= {low:g}")
        for name, value in (("--bandwidth", self.bandwidth_hz), ("--state-rate", self.state_rate)):
            if not (math.isfinite(value) and value > 0):
                raise ValueError(f"{name} {value!r}: a positive number")
        if not (isinstance(self.timeout, int) and self.timeout >= 1):
            raise ValueError(f"--timeout {self.timeout!r}: a whole number of cycles, at least 1")


def parse_fault(text: str) -> tuple[float, int]:
    """(seconds, joint index) of ``--fault AT:JOINT`` (JOINT a name of :data:`JOINT_NAMES` or 0-5);
    ValueError naming the problem."""
    at, sep, joint = text.partition(":")
    try:
        seconds = float(at)
    except ValueError:
        seconds = math.nan
    if not sep or not (math.isfinite(seconds) and seconds >= 0):
        raise ValueError(f"--fault {text!r}: give AT:JOINT, seconds after the first setpoint and a joint, "
                         f"e.g. 3.5:yaw")
    if joint in JOINT_NAMES:
        return seconds, JOINT_NAMES.index(joint)
    if joint.isdigit() and int(joint) < 6:
        return seconds, int(joint)
    raise ValueError(f"--fault {text!r}: the joint is one of {', '.join(JOINT_NAMES)} (or 0-5)")


@dataclass
class Report:
    """What the machine received, did and found.

    received : setpoints checked; datagrams : all datagrams read; dropped : {reason: count} of those
    never checked (one of :data:`desdemona.service.protocol.REASONS`: not valid, from an unexpected
    sender, out of order, unsigned, forged or replayed with a key), drop_samples : {reason: the first
    datagrams' details}; refused : {reason:
    count} of setpoints checked but not followed (a fault, braking, not where the machine stands);
    gaps : sequence gaps, missing : sequence numbers skipped in all; violations : the first
    :data:`MAX_KEPT`; counts : {kind: count} of all violations (:data:`KINDS`); worst : {limit: worst
    use} of the setpoints over the free joints (1 = at the limit), worst_joint : {limit: joint};
    made, made_joint : the same of the motion made; timing : {late, gap, burst: count}, latest : the
    latest a setpoint came after it was due [s]; reanchored : setpoints re-anchored on the measured
    machine; events, stops : of the :class:`~desdemona.service.drive.Drive`; ended_moving : the
    setpoints ended while the machine moved; states : State messages sent; statuses, sources : {name:
    count}; first_cycle_time, last_cycle_time : of the setpoints checked; stopped : "idle", "duration"
    or "interrupted (SIGINT)"...; elapsed [s]; out : the folder written; address : the socket bound.
    """

    out: Path
    address: tuple[str, int] = ("", 0)
    received: int = 0
    datagrams: int = 0
    dropped: dict = field(default_factory=dict)
    drop_samples: dict = field(default_factory=dict)
    refused: dict = field(default_factory=dict)
    gaps: int = 0
    missing: int = 0
    violations: list = field(default_factory=list)
    counts: dict = field(default_factory=lambda: {k: 0 for k in KINDS})
    worst: dict = field(default_factory=lambda: {k: 0.0 for k in LIMIT_KINDS})
    worst_joint: dict = field(default_factory=dict)
    made: dict = field(default_factory=lambda: {k: 0.0 for k in LIMIT_KINDS})
    made_joint: dict = field(default_factory=dict)
    timing: dict = field(default_factory=lambda: {k: 0 for k in TIMING})
    latest: float = 0.0
    reanchored: int = 0
    events: list = field(default_factory=list)
    stops: list = field(default_factory=list)
    ended_moving: bool = False
    states: int = 0
    statuses: dict = field(default_factory=dict)
    sources: dict = field(default_factory=dict)
    first_cycle_time: float | None = None
    last_cycle_time: float | None = None
    stopped: str = ""
    elapsed: float = 0.0

    @property
    def passed(self) -> bool:
        """No violation, no timing fault, and the setpoints did not end while the machine moved."""
        return not any(self.counts.values()) and not any(self.timing.values()) and not self.ended_moving

    @property
    def violation_count(self) -> int:
        return sum(self.counts.values())

    def describe(self) -> str:
        """A few lines for the terminal."""
        def listed(d):
            return ", ".join(f"{k} {v}" for k, v in sorted(d.items()) if v) or "none"

        def uses(worst, joints):
            return ", ".join(f"{k} {v:.3g}" + (f" ({joints[k]})" if k in joints else "") for k, v in worst.items())

        stops = "; ".join(f"{s.why} at {s.start:.3f} s: at rest after {s.rest - s.start:.3f} s (shortest "
                          f"{s.bound:.3f} s)" if s.rest is not None else f"{s.why} at {s.start:.3f} s: still moving"
                          for s in self.stops) or "none"
        verdict = "PASSED" if self.passed else "FAILED" + (
            " (the setpoints ended while the machine moved: it braked on its own)" if self.ended_moving else "")
        return (f"machine: {self.received} setpoints checked, {self.datagrams} datagrams, {self.states} states "
                f"sent, stopped: {self.stopped}\n"
                f"  dropped: {listed(self.dropped)}; refused: {listed(self.refused)}; sequence gaps: {self.gaps} "
                f"({self.missing} missing); re-anchored: {self.reanchored}\n"
                f"  violations: {listed(self.counts)}\n"
                f"  timing faults: {listed(self.timing)} (latest {1e3 * self.latest:.1f} ms after due)\n"
                f"  worst use of the limits, setpoints: {uses(self.worst, self.worst_joint)}\n"
                f"  worst use of the limits, motion made: {uses(self.made, self.made_joint)}\n"
                f"  its own stops: {stops}\n"
                f"  {verdict}; written to {self.out}")


def exit_code(report: Report) -> int:
    """The command's exit status: 0 if the machine passed (:attr:`Report.passed`), 1 otherwise."""
    return 0 if report.passed else 1


def drop_reason(error: protocol.ProtocolError) -> str:
    """The reason (a key of :attr:`Report.dropped`, one of :data:`protocol.REASONS`) for a datagram
    :func:`protocol.read` refused."""
    return error.reason


def _is_own(folder: Path) -> bool:
    """An earlier output of this command: its summary.json says so."""
    try:
        return json.loads((folder / "summary.json").read_text()).get("written_by") == WRITTEN_BY
    except (OSError, ValueError, AttributeError):
        return False


def prepare(out: str | Path) -> Path:
    """The output folder, created; ValueError naming it where it exists, is not empty and is not an
    earlier output of this command (whose files are then replaced)."""
    out = Path(out)
    if out.exists() and not out.is_dir():
        raise ValueError(f"{out}: exists and is not a folder")
    if out.is_dir() and any(out.iterdir()) and not _is_own(out):
        raise ValueError(f"{out}: a folder that is not empty and not an earlier output of desdemona machine; "
                         f"give a new or empty folder")
    out.mkdir(parents=True, exist_ok=True)
    return out






class _StandIn:
    """One run's state: the drive, the check, the service's address, what came when."""

    def __init__(self, model: Model, options: MachineOptions, sock, report: Report, files: Files):
        self.model, self.options, self.sock, self.report, self.files = model, options, sock, report, files
        self.drive = Drive.of(model, options.timeout, options.delay, options.bandwidth_hz)
        self.checker = Checker(model)
        self.rng = np.random.default_rng(options.seed)
        self.previous: protocol.Setpoint | None = None
        self.incoming, self.outgoing = Incoming(options.key), Outgoing(options.key)
        self.drops = Drops()
        self.service = None  # where the setpoints come from, and the States go
        self.commands: dict = {}  # the last command sequence per sender
        self.first_arrival: float | None = None
        self.last_arrival: float | None = None
        self.arrivals: list[float] = []  # of setpoints, for bursts
        self.in_burst = False
        self.written_events = 0
        self.faulted = False
        self.button = False  # the emergency stop's button (SIGUSR1), acted on at the next tick

    def drop(self, reason: str, detail: str = "") -> None:
        self.drops(reason, detail)
        self.report.dropped[reason] = self.drops.counts[reason]
        self.report.drop_samples = self.drops.sample()

    def datagram(self, data: bytes, sender, t: float) -> None:
        self.report.datagrams += 1
        self.last_arrival = t
        try:
            frame = self.incoming.read(data)
        except protocol.ProtocolError as error:
            return self.drop(error.reason, str(error))
        message, who = frame.message, (*sender[:2], frame.session)
        if isinstance(message, protocol.Setpoint):
            return self.setpoint(message, sender, t)
        if isinstance(message, protocol.Command):
            if sender[0] != self.options.operator:
                return self.drop("sender", f"a command from {sender[0]}, the operator is {self.options.operator}")
            if message.sequence <= self.commands.get(who, -1):
                return self.drop("stale", f"command sequence {message.sequence}")
            self.commands[who] = message.sequence
            return self.drive.command(message.action, t)
        self.drop("kind", f"a {type(message).__name__} from {sender[0]}:{sender[1]}")

    def setpoint(self, sp: protocol.Setpoint, sender, t: float) -> None:
        report, previous = self.report, self.previous
        if self.service is None:
            self.service = sender
        elif sender != self.service:
            return self.drop("sender", f"a setpoint from {sender[0]}:{sender[1]}, the service is "
                                       f"{self.service[0]}:{self.service[1]}")
        if previous is not None and sp.sequence <= previous.sequence:
            return self.drop("stale", f"setpoint sequence {sp.sequence} after {previous.sequence}")
        follows = previous is not None and sp.sequence == previous.sequence + 1
        # continuity matters for a motion the drive follows on: not for setpoints it refuses (stopped on
        # its own) or takes afresh from where it stands
        continued = follows and self.drive.status == "following"
        if previous is not None and not follows:
            report.gaps += 1
            report.missing += sp.sequence - previous.sequence - 1
        where = self.drive.joints.now(t)[:2]
        violations, use = self.checker.check(sp, previous if continued else None, t, where)
        report.reanchored = self.checker.reanchored
        self._timing(sp, t)
        self.first_arrival = t if self.first_arrival is None else self.first_arrival
        # its own safety layer: a setpoint over a limit is never followed (the drive brakes instead)
        refused = (self.drive.over_limit(t, f"{violations[0].joint} {violations[0].what}")
                   if violations else self.drive.setpoint(sp, t))
        if refused:
            reason = refused.split(" (")[0]
            report.refused[reason] = report.refused.get(reason, 0) + 1
            if report.refused[reason] == 1:  # the first of each reason
                self.drive.events.append(Event(t, "setpoint refused", f"{sp.sequence}: {refused}"))
        record(report, self.checker, sp, t, violations, use, self.files)
        self.previous = sp

    def _timing(self, sp: protocol.Setpoint, t: float) -> None:
        """When ``sp`` came: late after it was due, a gap while moving, a burst."""
        report, drive, step = self.report, self.drive, sp.step
        due = drive.due(sp) if drive.status == "following" else None
        if due is not None:
            late = t - due
            report.latest = max(report.latest, late)
            if late > self.options.late * step:
                self._timing_fault(t, "late", f"setpoint {sp.sequence} came {1e3 * late:.1f} ms after it was due")
        if (self.arrivals and drive.status == "following" and t - self.arrivals[-1] > drive.timeout * step
                and not drive.joints.at_rest(t)):
            self._timing_fault(t, "gap", f"{1e3 * (t - self.arrivals[-1]):.1f} ms without a setpoint while moving")
        self.arrivals = [a for a in self.arrivals[-(BURST - 1):] if t - a <= step / 4] + [t]
        if len(self.arrivals) >= BURST and not self.in_burst:
            self._timing_fault(t, "burst", f"{len(self.arrivals)} setpoints within {1e3 * step / 4:.1f} ms")
        self.in_burst = len(self.arrivals) >= BURST

    def _timing_fault(self, t: float, kind: str, detail: str) -> None:
        self.report.timing[kind] += 1
        if self.report.timing[kind] <= MAX_KEPT:
            self.drive.events.append(Event(t, f"timing: {kind}", detail))

    def tick(self, t0: float, t1: float) -> None:
        """Move the joints from ``t0`` to ``t1``, check the motion made, write it, send the State."""
        if self.button:
            self.button = False
            self.drive.emergency(t0, "SIGUSR1")
        fault = self.options.fault
        if fault is not None and not self.faulted and self.first_arrival is not None \
                and t1 >= self.first_arrival + fault[0]:
            self.faulted = True
            self.drive.fault(t1, fault[1])
        samples = self.drive.run_to(t0, t1)
        _, q, qd, qdd, jerk = (np.array(x) for x in zip(*samples))
        applied = self.drive.applied
        violations, use = self.checker.made(t1, -1 if applied is None else applied.sequence, q, qd, qdd, jerk)
        self._record_made(violations, use)
        noisy_q = q[-1] + self.rng.normal(0.0, self.options.noise[0], 6)
        noisy_qd = qd[-1] + self.rng.normal(0.0, self.options.noise[1], 6)
        drive = self.drive
        state = protocol.MachineState(self.report.states + 1, t1, drive.status, drive.fault_code, drive.fault_joint,
                                      None if applied is None else applied.sequence, drive.applied_time(t1),
                                      noisy_q, noisy_qd)
        row = [number(t1), state.status, state.fault, "" if state.fault_joint is None else state.fault_joint,
               "" if state.applied is None else state.applied, number(state.applied_time)]
        for i in range(6):
            row += [number(noisy_q[i]), number(noisy_qd[i]), number(qdd[-1, i])]
        self.files.write("motion.csv", row)
        outage = self.options.state_outage
        silent = (outage is not None and self.first_arrival is not None
                  and 0.0 <= t1 - self.first_arrival - outage[0] < outage[1])
        if self.service is not None and not silent:
            try:
                self.sock.sendto(self.outgoing.pack(state), self.service)
                self.report.states += 1
            except OSError as exc:
                self.drop("socket", f"state not sent: {exc}")
        for event in drive.events[self.written_events:]:
            self.files.write("events.csv", [number(event.time), event.what, event.detail])
        self.written_events = len(drive.events)
        self.report.events, self.report.stops = drive.events, drive.stops
        self.report.ended_moving = drive.ended_moving
        self.files.flush()

    def _record_made(self, violations, use) -> None:
        report = self.report
        for kind, per_joint in use.items():
            k = int(np.argmax(per_joint))
            if per_joint[k] > report.made[kind]:
                report.made[kind], report.made_joint[kind] = float(per_joint[k]), JOINT_NAMES[k]
        for v in violations:
            violation(report, v, self.files)

    def at_rest(self, t: float) -> bool:
        return not self.drive.joints.braking and self.drive.joints.at_rest(t, rate=1e-3)



def run(model: Model, listen: tuple[str, int], out: str | Path, idle: float = 2.0,
        duration: float | None = None, ready=None, options: MachineOptions = MachineOptions()) -> Report:
    """Receive setpoints on UDP ``listen`` = (host, port), move the joints with them and check
    everything (see the module), writing ``out`` as it goes. Stops ``idle`` seconds after the last
    datagram (once one came) with the machine at rest, after ``duration`` seconds if given, or at rest
    after SIGINT/SIGTERM (at once after a second); returns the :class:`Report`. SIGUSR1 is an
    emergency stop. ``ready()`` is called once the socket is bound. ValueError for a folder it must not
    write into, or an ``idle`` that is not positive.
    """
    if not (idle > 0):
        raise ValueError(f"idle {idle!r}: must be a positive number of seconds")
    sock = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
    try:
        try:
            sock.setsockopt(socket.SOL_SOCKET, socket.SO_RCVBUF, 4 << 20)
        except OSError:
            pass
        sock.bind(listen)  # before the folder: a port in use leaves nothing behind
        pacing.stamped(sock)
        out = prepare(out)
        report = Report(out=out)
        report.address = sock.getsockname()[:2]
        report.stopped = "running"
        write_summary(report, model)  # marks the folder as this command's from the start
        files = Files(out)
        stand_in = _StandIn(model, options, sock, report, files)
        stops: list[int] = []
        started = time.monotonic()
        try:
            with guard.handled_here(stops.append), _emergency_signal(stand_in, started):
                if ready is not None:
                    ready()
                _loop(stand_in, stops, started, idle, duration)
        finally:
            # what it has is written whole, not cut by a further signal (held back until it is)
            with guard.deferred():
                report.elapsed = time.monotonic() - started
                files.close()
                write_summary(report, model)
    finally:
        sock.close()
    return report


def _loop(stand_in: _StandIn, stops: list, started: float, idle: float, duration: float | None) -> None:
    """Ticks at the State rate; between them, every datagram as it comes. Sets ``report.stopped``."""
    report, period = stand_in.report, 1.0 / stand_in.options.state_rate
    k, last = 1, 0.0
    while True:
        now = time.monotonic() - started
        if duration is not None and now >= duration:
            report.stopped = "duration"
            return
        if stops:
            if len(stops) == 1 and not stand_in.at_rest(now) and stand_in.drive.status != "e-stop":
                stand_in.drive.emergency(now, f"{signal.Signals(stops[0]).name} to the stand-in")
            if len(stops) > 1 or stand_in.at_rest(now):
                report.stopped = f"interrupted ({signal.Signals(stops[0]).name})"
                return
        quiet = stand_in.last_arrival is not None and now - stand_in.last_arrival >= idle
        if quiet and stand_in.at_rest(now):
            report.stopped = "idle"
            return
        tick = k * period
        while (now := time.monotonic() - started) < tick:
            stand_in.sock.settimeout(min(tick - now, RECEIVE_TIMEOUT))
            try:
                data, sender, age = pacing.received(stand_in.sock, MAX_DATAGRAM)
            except (TimeoutError, BlockingIOError, InterruptedError):
                continue
            # timed from when it came (the kernel's stamp), not from when this process next ran: a
            # motion system's controller reads its link in real time, the stand-in may be held up
            stand_in.datagram(data, sender, time.monotonic() - started - age)
        stand_in.tick(last, now)
        last, k = now, max(k + 1, int(now / period) + 1)


class _emergency_signal:
    """Within the block SIGUSR1 presses the emergency stop's button (main thread only)."""

    def __init__(self, stand_in: _StandIn, started: float):
        self.stand_in, self.started, self.saved = stand_in, started, None

    def __enter__(self):
        if threading.current_thread() is threading.main_thread():
            self.saved = signal.signal(signal.SIGUSR1, lambda *_: setattr(self.stand_in, "button", True))

    def __exit__(self, *exc):
        if self.saved is not None:
            signal.signal(signal.SIGUSR1, self.saved)

"""A stand-in for the motion system (``desdemona machine``): it receives the service's setpoints over
UDP and checks every one of them on its own.

A real motion system does not trust its controller: its own guard refuses a command that would take a
joint beyond its range, rate, acceleration, jerk, torque or power, that moves a joint which should be
held, or that jumps from where the machine is. This stand-in plays that part on one computer, so that
``desdemona serve`` can be tested end to end without the machine: whatever the service sends is
measured here, independently of how the service computed it (neither its controller nor its own
guard is used; only the model's limits, the exact motion of :func:`desdemona.machine.plan.advance` and the
model's torques).

What is checked, for every setpoint (:func:`check_setpoint`):

- every free joint over the whole cycle the setpoint commands, not only at its start: the motion
  inside the cycle is the exact cubic of :func:`~desdemona.machine.plan.advance` from the setpoint's position,
  rate, acceleration and jerk, evaluated on :data:`POINTS` points of the cycle and at the instants
  where a position or a rate turns (so that position, rate and acceleration are checked exactly):
  position within [position_min, position_max], ``|rate| <= velocity``, ``|acceleration| <=
  acceleration``, ``|jerk| <= jerk``, ``|torque| <= effort`` and ``|torque * rate| <= power``, each with
  the relative tolerance of the independent check (:data:`desdemona.check.simulate.TOLERANCE`);
- every held joint at its held position (``config.held``) and at rest:
  rate, acceleration and jerk zero (``held``);
- continuity (``continuity``): a setpoint that follows the previous one (the next sequence number)
  starts where the previous one's cycle ends, the previous one advanced by its ``step`` with its
  acceleration and jerk: position, rate, and where the machine limits jerk, acceleration, each within
  :data:`CONTINUITY` of its scale plus :data:`ABSOLUTE`. After a sequence gap (a datagram lost or
  dropped) only the limits are checked, and the gap is counted;
- sequence numbers strictly increase: a duplicate or an older one is dropped and counted, as is any
  datagram that is not a valid setpoint (:func:`desdemona.service.protocol.unpack`): such datagrams are
  never checked as setpoints.

It stops when no datagram has arrived for ``idle`` seconds after the first one, after ``duration``
seconds if given, or on Ctrl-C / SIGTERM; it then writes what it has into its folder (each file whole,
written beside its place and renamed into it; ``summary.json`` last):

- ``setpoints.csv``: one row per setpoint checked: receive time [s since the socket was bound],
  sequence, the sender's time, status, source, answers, cycle_time, step, then per joint of
  :data:`desdemona.machine.params.JOINT_NAMES` its position, rate, acceleration and jerk;
- ``violations.csv``: one row per violation: time, sequence, joint, what (position, rate,
  acceleration, jerk, effort, power, held, continuity), value, limit, and a detail (where in the cycle,
  or which quantity). For a limit, value is the worst over the cycle and limit the bound it crosses;
  for ``held`` and ``continuity``, value is what the setpoint says and limit what it should say (the
  held position or zero; where the previous cycle ends), the quantity and tolerance in the detail;
- ``summary.json``: counts (received, dropped by reason, gaps, violations by kind), the worst use of
  every limit (1 = at the limit) and its joint, the first and last cycle time, the statuses and sources
  seen, and why it stopped.

:func:`exit_code` is the command's exit status: 1 if any violation, 0 otherwise.
"""

from __future__ import annotations

import csv
import io
import json
import math
import os
import socket
import time
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from desdemona._version import __version__
from desdemona.check.simulate import TOLERANCE
from desdemona.machine.model import Model
from desdemona.machine.params import JOINT_NAMES
from desdemona.machine.plan import advance
from desdemona.service import protocol
from desdemona.support import guard
from desdemona.support.files import beside

#: Points of each cycle at which the motion is evaluated (both ends included), besides the instants
#: where a position or a rate turns.
POINTS = 11
#: Continuity and rest: relative tolerance (of the limit, or of the position's scale) ...
CONTINUITY = 1e-6
#: ... plus this absolute one.
ABSOLUTE = 1e-9
#: Every receive waits at most this long [s], so the loop notices ``idle``, ``duration`` and signals.
RECEIVE_TIMEOUT = 0.05
#: The largest datagram read (a longer one is cut by the kernel, and refused as a wrong length).
MAX_DATAGRAM = 65536
#: Violations kept in the :class:`Report` (all are counted and written to ``violations.csv``).
MAX_KEPT = 1000
#: The limits measured per free joint, in the order of ``violations.csv``'s ``what``.
LIMIT_KINDS = ("position", "rate", "acceleration", "jerk", "effort", "power")
KINDS = LIMIT_KINDS + ("held", "continuity")
FILES = ("setpoints.csv", "violations.csv", "summary.json")
WRITTEN_BY = "desdemona machine"

SETPOINT_COLUMNS = (("time", "sequence", "sent", "status", "source", "answers", "cycle_time", "step")
                    + tuple(f"{name}_{q}" for name in JOINT_NAMES
                            for q in ("position", "rate", "acceleration", "jerk")))
VIOLATION_COLUMNS = ("time", "sequence", "joint", "what", "value", "limit", "detail")


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


@dataclass
class Report:
    """What the machine received and found.

    received : setpoints checked; datagrams : all datagrams read; dropped : {reason: count} of those
    never checked (:func:`drop_reason`); gaps : sequence gaps (continuity not checked across them),
    missing : sequence numbers skipped in all; violations : the first :data:`MAX_KEPT`;
    counts : {kind: count} of all violations; worst : {limit: worst use} over the free joints
    (1 = at the limit), worst_joint : {limit: joint name}; statuses, sources : {name: count};
    first_cycle_time, last_cycle_time : of the setpoints checked; stopped : "idle", "duration" or
    "interrupted (SIGINT)"...; elapsed [s]; out : the folder written; address : the socket bound.
    """

    out: Path
    address: tuple[str, int] = ("", 0)
    received: int = 0
    datagrams: int = 0
    dropped: dict = field(default_factory=dict)
    gaps: int = 0
    missing: int = 0
    violations: list = field(default_factory=list)
    counts: dict = field(default_factory=dict)
    worst: dict = field(default_factory=lambda: {k: 0.0 for k in LIMIT_KINDS})
    worst_joint: dict = field(default_factory=dict)
    statuses: dict = field(default_factory=dict)
    sources: dict = field(default_factory=dict)
    first_cycle_time: float | None = None
    last_cycle_time: float | None = None
    stopped: str = ""
    elapsed: float = 0.0

    @property
    def passed(self) -> bool:
        """No violation at all."""
        return not any(self.counts.values())

    @property
    def violation_count(self) -> int:
        return sum(self.counts.values())

    def describe(self) -> str:
        """A few lines for the terminal."""
        dropped = ", ".join(f"{k} {v}" for k, v in sorted(self.dropped.items())) or "none"
        kinds = ", ".join(f"{k} {v}" for k, v in self.counts.items() if v) or "none"
        worst = ", ".join(f"{k} {v:.3g}" + (f" ({self.worst_joint[k]})" if k in self.worst_joint else "")
                          for k, v in self.worst.items())
        return (f"machine: {self.received} setpoints checked, {self.datagrams} datagrams, stopped: {self.stopped}\n"
                f"  dropped: {dropped}; sequence gaps: {self.gaps} ({self.missing} missing)\n"
                f"  violations: {kinds}\n"
                f"  worst use of the limits: {worst}\n"
                f"  {'PASSED' if self.passed else 'FAILED'}; written to {self.out}")


def exit_code(report: Report) -> int:
    """The command's exit status: 1 if the machine saw any violation, 0 otherwise."""
    return 0 if report.passed else 1


def drop_reason(error: protocol.ProtocolError) -> str:
    """A short reason (the key of :attr:`Report.dropped`) for a datagram :func:`protocol.unpack` refused."""
    text = str(error)
    for words, reason in (("truncated", "truncated"), ("magic", "wrong magic"), ("protocol version", "version"),
                          ("unknown message kind", "unknown kind"), ("not a finite number", "not finite"),
                          ("absurd", "absurd value"), ("setpoint of", "wrong length"),
                          ("setpoint with", "malformed"), ("motion", "not a setpoint")):
        if words in text:
            return reason
    return "invalid"


class Checker:
    """The machine's own guard for one model: :meth:`check` a setpoint against the limits, the held
    joints and the previous setpoint."""

    def __init__(self, model: Model):
        self.model = model
        self.select = model.config.select
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

    def _times(self, q, qd, a, j, step: float) -> np.ndarray:
        """Instants of the cycle to evaluate: :data:`POINTS` evenly, and where an acceleration would
        turn a rate (a + j s = 0) or a rate a position (qd + a s + j s^2 / 2 = 0)."""
        with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
            root = np.sqrt(a * a - 2.0 * j * qd)  # NaN where the rate never reaches zero
            s = np.concatenate([np.linspace(0.0, step, POINTS), -a / j, (-a + root) / j, (-a - root) / j,
                                np.where(j == 0, -qd / a, np.nan)])
        return np.unique(s[np.isfinite(s) & (s >= 0.0) & (s <= step)])

    def check(self, sp: protocol.Setpoint, previous: protocol.Setpoint | None, t: float):
        """Violations of setpoint ``sp`` (received at ``t``) and the use of each limit {kind: (n,)};
        ``previous`` : the setpoint it follows, or None where continuity is not checked."""
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
            out += self._continuity(sp, previous, t)
        return out, worst

    def _continuity(self, sp, prev, t) -> list[Violation]:
        pq, pqd, pa, pj = (self.select(x) for x in (prev.position, prev.rate, prev.acceleration, prev.jerk))
        eq, eqd = advance(pq, pqd, pa, prev.step, pj)
        ea = pa + pj * prev.step
        checks = [("position", eq, self.select(sp.position), self.position_scale),
                  ("rate", eqd, self.select(sp.rate), self.velocity)]
        if self.smooth:
            checks.append(("acceleration", ea, self.select(sp.acceleration), self.acceleration))
        out = []
        for what, expected, got, scale in checks:
            tol = ABSOLUTE + CONTINUITY * scale
            for k in np.flatnonzero(np.abs(got - expected) > tol):
                out.append(Violation(t, sp.sequence, self.names[k], "continuity", float(got[k]), float(expected[k]),
                                     f"{what} {got[k]:.9g} where the previous cycle (sequence {prev.sequence}) "
                                     f"ends at {expected[k]:.9g}, tolerance {tol[k]:.3g}"))
        return out


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


def _number(x: float) -> str:
    return repr(float(x))


def run(model: Model, listen: tuple[str, int], out: str | Path, idle: float = 2.0,
        duration: float | None = None, ready=None) -> Report:
    """Receive setpoints on UDP ``listen`` = (host, port), check each (:class:`Checker`), and write
    ``out`` (see the module). Stops ``idle`` seconds after the last datagram (once one came), after
    ``duration`` seconds if given, or on KeyboardInterrupt / :class:`desdemona.support.guard.Interrupted`; then
    writes what it has and returns the :class:`Report`. ``ready()`` is called once the socket is bound.
    ValueError for a folder it must not write into, or an ``idle`` that is not positive.
    """
    if not (idle > 0):
        raise ValueError(f"idle {idle!r}: must be a positive number of seconds")
    checker = Checker(model)
    sock = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
    try:
        try:
            sock.setsockopt(socket.SOL_SOCKET, socket.SO_RCVBUF, 4 << 20)
        except OSError:
            pass
        sock.bind(listen)  # before the folder: a port in use leaves nothing behind
        out = prepare(out)
        report = Report(out=out, counts={k: 0 for k in KINDS})
        report.address = sock.getsockname()[:2]
        with (beside(out / "setpoints.csv") as setpoints_tmp, beside(out / "violations.csv") as violations_tmp,
              open(setpoints_tmp, "w", newline="") as sfile, open(violations_tmp, "w", newline="") as vfile):
            srows, vrows = csv.writer(sfile), csv.writer(vfile)
            srows.writerow(SETPOINT_COLUMNS)
            vrows.writerow(VIOLATION_COLUMNS)
            started = time.monotonic()
            if ready is not None:
                ready()
            try:
                _receive(sock, checker, report, srows, vrows, started, idle, duration)
            except (KeyboardInterrupt, guard.Interrupted) as stop:
                report.stopped = f"interrupted ({getattr(stop, 'name', 'SIGINT')})"
            # what it has is written whole, not cut by a further signal (held back until it is)
            with guard.deferred():
                report.elapsed = time.monotonic() - started
                sfile.close()
                vfile.close()
                os.replace(setpoints_tmp, out / "setpoints.csv")
                os.replace(violations_tmp, out / "violations.csv")
                _write_summary(report, model)  # the last: it marks the folder as this command's
    finally:
        sock.close()
    return report


def _receive(sock, checker: Checker, report: Report, srows, vrows, started: float, idle: float,
             duration: float | None) -> None:
    """The receive loop: every wait bounded by :data:`RECEIVE_TIMEOUT`; sets ``report.stopped``."""
    previous: protocol.Setpoint | None = None
    last_arrival: float | None = None
    while True:
        now = time.monotonic()
        if duration is not None and now - started >= duration:
            report.stopped = "duration"
            return
        if last_arrival is not None and now - last_arrival >= idle:
            report.stopped = "idle"
            return
        wait = RECEIVE_TIMEOUT
        if duration is not None:
            wait = min(wait, max(duration - (now - started), 1e-3))
        sock.settimeout(wait)
        try:
            data, _ = sock.recvfrom(MAX_DATAGRAM)
        except (TimeoutError, BlockingIOError, InterruptedError):
            continue
        last_arrival = time.monotonic()
        t = last_arrival - started
        report.datagrams += 1
        try:
            message = protocol.unpack(data)
        except protocol.ProtocolError as error:
            _drop(report, drop_reason(error))
            continue
        if not isinstance(message, protocol.Setpoint):
            _drop(report, "not a setpoint")
            continue
        if previous is not None and message.sequence <= previous.sequence:
            _drop(report, "duplicate" if message.sequence == previous.sequence else "out of order")
            continue
        follows = previous is not None and message.sequence == previous.sequence + 1
        if previous is not None and not follows:
            report.gaps += 1
            report.missing += message.sequence - previous.sequence - 1
        violations, use = checker.check(message, previous if follows else None, t)
        _record(report, checker, message, t, violations, use, srows, vrows)
        previous = message


def _drop(report: Report, reason: str) -> None:
    report.dropped[reason] = report.dropped.get(reason, 0) + 1


def _record(report: Report, checker: Checker, sp: protocol.Setpoint, t: float, violations, use, srows, vrows):
    report.received += 1
    report.statuses[sp.status] = report.statuses.get(sp.status, 0) + 1
    report.sources[sp.source] = report.sources.get(sp.source, 0) + 1
    if report.first_cycle_time is None:
        report.first_cycle_time = sp.cycle_time
    report.last_cycle_time = sp.cycle_time
    for kind, per_joint in use.items():
        k = int(np.argmax(per_joint))
        if per_joint[k] > report.worst[kind]:
            report.worst[kind] = float(per_joint[k])
            report.worst_joint[kind] = checker.names[k]
    row = [_number(t), sp.sequence, _number(sp.time), sp.status, sp.source,
           "" if sp.answers is None else sp.answers, _number(sp.cycle_time), _number(sp.step)]
    for i in range(6):
        row += [_number(sp.position[i]), _number(sp.rate[i]), _number(sp.acceleration[i]), _number(sp.jerk[i])]
    srows.writerow(row)
    for v in violations:
        report.counts[v.what] += 1
        if len(report.violations) < MAX_KEPT:
            report.violations.append(v)
        vrows.writerow([_number(v.time), v.sequence, v.joint, v.what, _number(v.value), _number(v.limit), v.detail])


def summary(report: Report, model: Model) -> dict:
    """The contents of ``summary.json``."""
    def finite(x):
        return x if x is None or math.isfinite(x) else str(x)

    return {
        "written_by": WRITTEN_BY, "version": __version__, "passed": report.passed,
        "config": model.config.name, "params": model.params.name, "free": list(model.config.joint_names),
        "listen": list(report.address), "stopped": report.stopped, "elapsed": report.elapsed,
        "datagrams": report.datagrams, "received": report.received, "dropped": dict(sorted(report.dropped.items())),
        "gaps": report.gaps, "missing": report.missing,
        "violations": dict(report.counts), "violation_count": report.violation_count,
        "worst_use": {k: finite(v) for k, v in report.worst.items()}, "worst_joint": dict(report.worst_joint),
        "first_cycle_time": report.first_cycle_time, "last_cycle_time": report.last_cycle_time,
        "statuses": dict(report.statuses), "sources": dict(report.sources),
        "tolerance": TOLERANCE, "continuity_tolerance": {"relative": CONTINUITY, "absolute": ABSOLUTE},
    }


def _write_summary(report: Report, model: Model) -> None:
    target = report.out / "summary.json"
    with beside(target) as tmp:
        text = io.StringIO()
        json.dump(summary(report, model), text, indent=2)
        tmp.write_text(text.getvalue() + "\n")
        os.replace(tmp, target)

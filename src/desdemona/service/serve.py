"""``desdemona serve``: a session of the on-line controller driven by a simulator host, in real time.

Every cycle of the session's step h (``--rate`` = 1 / h) the service takes the newest valid motion
message of the host, turns what it has received into a preview with the session's predictor (as
``desdemona online`` does: :mod:`desdemona.control.predictors`; ``forecast`` reads the host's own forecast
block), runs :class:`desdemona.control.mpc.MPC` from the machine's state within the cycle's deadline (with
its fallbacks: the previous plan, then braking), checks the command against every limit over the
cycle (:meth:`Model.step_limit_use`, on its own, after the controller's own check), and sends the
setpoint of the cycle (:mod:`desdemona.service.protocol`). The machine's state advances by the
command exactly: the setpoints are a continuous jerk-limited motion, cycle after cycle.

Timing: cycle k belongs to the machine's time k h. It starts when a new host message arrives within
half a cycle of that time (so a host that sends at the session's rate is answered at once: the
end-to-end latency is the compute time); one stale before the window opened waits for the host's next
where it is due in time. A cycle with nothing new (a host slower than the service) follows the last
plan's next step without a QP (:meth:`desdemona.control.mpc.MPC.follow`), at the window's end where
the host's next message is due in the window, else as it opens, away from when the next message comes
(:func:`desdemona.service.pacing.begins`).

- **Starting**: until the first host message the machine stands still at home (status ``starting``).
- **Watchdog**: without a valid host message for ``timeout`` cycles the machine is parked: braked to
  rest within every limit (``parking``), then held (``parked``); when valid messages return, the
  controller plans afresh from where it stands (``running``).
- **Bad datagrams** (not this protocol, NaN, absurd values, the wrong channels, out of order or
  repeated, from another sender than the host, unsigned, forged or replayed with a key): dropped and
  counted by one of the protocol's fixed reasons, never used (:mod:`desdemona.service.inbox`).
- **Stop**: SIGINT or SIGTERM parks the machine and then ends the session; a second one ends it at
  once after one braking command.

:func:`serve` returns a :class:`Served` session, which :func:`result` judges like an on-line run
(:func:`desdemona.control.online.judge`: the independent check and the classical loop beside it) and
:func:`write` writes as ``desdemona online`` writes its folder, with the service's columns in
``cycles.csv``.
"""

from __future__ import annotations

import math
import socket
import time
from collections import Counter
from dataclasses import dataclass, field

import numpy as np

from desdemona.check.simulate import TOLERANCE, ClosedLoop
from desdemona.control import predictors
from desdemona.control.mpc import MPC
from desdemona.control.online import OnlineOptions, OnlineResult, judge
from desdemona.control.predictors import predictor
from desdemona.machine.model import Model
from desdemona.machine.params import JOINT_NAMES
from desdemona.machine.plan import Plan, State, stopping_jerk
from desdemona.profiles import DesiredPath, ProfileError
from desdemona.service import pacing, protocol
from desdemona.service.inbox import Inbox
from desdemona.service.measured import (
    BAND,
    HOLDING_ON_ITS_OWN,
    SETTLE,
    STOPPED_ON_ITS_OWN,
    MachineLink,
    commanded_at,
)
from desdemona.service.sessionlog import TIMED, describe, events_table, session_table, summary
from desdemona.service.spill import Spilled

__all__ = ["ServeOptions", "Served", "default_channels", "describe", "events_table", "result", "serve",
           "session_table", "summary"]
from desdemona.support import guard
from desdemona.support.symbolic import call

#: Where the controller's command sources are named in the log: what the protocol calls them.
SOURCE_NAMES = {"mpc": "plan", "shifted": "previous plan", "brake": "brake"}


def default_channels(config) -> int:
    """What a host sends by default: the modulus (1) on the configurations that take it, else S (6)."""
    return 1 if config.takes_modulus else 6


def _host_path(t, values, description: str = "") -> DesiredPath:
    """Motion received from the host, (K,) times and (K, 1) moduli or (K, 6) S, as a desired path."""
    if values.shape[1] == 1:
        return DesiredPath("host", t, None, description=description, modulus=values[:, 0])
    return DesiredPath("host", t, values, description=description)


@dataclass(frozen=True)
class ServeOptions:
    """listen, send : (host, port) of the host's messages and of the machine; channels : what the host
    sends, 6 (S) or 1 (the modulus; None: 1 on the configurations that take it, else 6); timeout : cycles without
    a valid host message before the machine is parked; duration : end the session after this many
    seconds (None: run until stopped); quiet_end : end it once parked with no host message for this
    many seconds, after the first one came (None: never); history : seconds of received motion the
    predictor is given; operator : the host whose Commands it takes; state_lost : seconds without a
    State from the machine (once they came) before it parks."""

    listen: tuple[str, int]
    send: tuple[str, int]
    channels: int | None = None
    timeout: int = 5
    duration: float | None = None
    quiet_end: float | None = None
    history: float = 10.0
    operator: str = "127.0.0.1"
    state_lost: float = 0.5
    key: bytes | None = field(default=None, repr=False)

    def __post_init__(self):
        if self.channels not in (None, 1, 6):
            raise ValueError(f"--channels {self.channels}: 6 (S) or 1 (the modulus)")
        if not (isinstance(self.timeout, int) and self.timeout >= 1):
            raise ValueError(f"--timeout {self.timeout}: a whole number of cycles, at least 1")
        for name, value in (("--duration", self.duration), ("--quiet-end", self.quiet_end),
                            ("--state-lost", self.state_lost)):
            if value is not None and not (math.isfinite(value) and value > 0):
                raise ValueError(f"{name} {value:g}: a positive number of seconds")


@dataclass
class Served:
    """What a session did: the plan the machine executed from rest at home (:class:`ClosedLoop`), per
    cycle the service's record (:attr:`columns`), the motion received (times on the session's clock:
    the host's time plus ``offset``, the session's time at which the host's first message arrived less
    its time) and the datagrams dropped by reason; ``stopped_by``: the signal that ended it, or None."""

    loop: ClosedLoop
    columns: dict[str, np.ndarray]
    received_t: np.ndarray
    received: np.ndarray
    dropped: Counter = field(default_factory=Counter)
    drop_samples: dict = field(default_factory=dict)  # reason -> the first datagrams' details
    stopped_by: int | None = None
    deadline: float = 0.0
    offset: float = 0.0  # the session's time [s] of the host's time 0
    events: list = field(default_factory=list)  # (time [s, the session's clock], what, detail)
    states: int = 0  # State messages of the machine taken
    reanchored: int = 0  # cycles planned from the measured machine
    breaks: list = field(default_factory=list)  # cycles whose state was set from the machine after a fault

    def span(self) -> tuple[int, int]:
        """(k0, k1): the cycles the session followed the host, from the first that answered a host
        message to the last that did (one past it): what it is judged on, without the wait before the
        host came and the parking after it had gone."""
        running = np.flatnonzero(self.columns["status"] == "running")
        if len(running) == 0:
            raise ProfileError("the session never followed the host (no valid host message was answered): "
                               "nothing to judge")
        k0, k1 = int(running[0]), int(running[-1]) + 1
        # the plan is one continuous motion up to where the session planned afresh from the measured
        # machine after a fault of it: judged up to there
        later = [k for k in self.breaks if k > k0]
        return k0, min([k1, *later])

    def judged(self, model: Model) -> tuple[DesiredPath, ClosedLoop]:
        """The motion received and the machine's plan over :meth:`span`, the time from its start: the
        desired path (held at the first message's value until it came) and the loop from the state the
        machine had there."""
        k0, k1 = self.span()
        plan = self.loop.plan
        t0 = plan.t_nodes[k0]
        q, qd, _ = plan.at([t0])
        cropped = Plan(plan.t_nodes[k0:k1 + 1] - t0, q[0], qd[0], plan.u[k0:k1], plan.jerk[k0:k1])
        loop = ClosedLoop(cropped, self.loop.cycle_times[k0:k1] - t0, self.loop.sources[k0:k1],
                          self.loop.compute_times[k0:k1], self.loop.reasons[k0:k1])
        t, values = self.received_t - t0, self.received
        if t[0] > 0.0:
            t, values = np.r_[0.0, t], np.vstack([values[:1], values])
        return model.config.cue_path(_host_path(t, values, "received from the host")), loop


class _Preview:
    """The session's predictor over what the host has sent (``forecast``: the host's own block)."""

    def __init__(self, name: str, model: Model, horizon: float, reference: DesiredPath | None, history: float):
        self.name, self.model, self.horizon = name, model, horizon
        self.history = min(history, predictors.PREDICTORS[name].looks_back or history)  # what it reads
        self.predict = None if name == "forecast" else predictor(name, reference)

    def held(self, values):
        """A host's motion ``values`` (one message's) held over the horizon, as the controller takes a
        preview."""
        held = np.repeat(np.atleast_2d(values), 2, axis=0)
        return np.array([0.0, self.horizon]), held[:, 0] if held.shape[1] == 1 else held

    def __call__(self, inbox: Inbox):
        message = inbox.newest
        if self.name == "forecast":
            if message.forecast is None:
                return None  # the controller falls back as on any unusable preview
            t = np.r_[0.0, message.forecast_step * np.arange(1, len(message.forecast) + 1)]
            values = np.vstack([message.values, message.forecast])
            if t[-1] < self.horizon:  # held beyond the forecast's end
                t, values = np.r_[t, self.horizon], np.vstack([values, values[-1:]])
            return t, values[:, 0] if values.shape[1] == 1 else values
        t, values = inbox.recent(self.history)
        if len(t) < 2:  # one sample: held
            return self.held(values[0])
        return self.predict(self.model.config.cue_path(_host_path(t, values)), float(t[-1]), self.horizon)


def listening(address: tuple[str, int]) -> socket.socket:
    """A UDP socket bound to ``address``, for the host's datagrams; OSError where the port is taken."""
    sock = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
    try:
        sock.bind(address)
    except OSError:
        sock.close()
        raise
    return sock


def _discard_queued(sock: socket.socket) -> int:
    """Read and drop what waits in ``sock``: the datagrams that came before the session began, stale by
    then (the controller takes seconds to build); how many."""
    sock.setblocking(False)
    count = 0
    while True:
        try:
            sock.recv(65536)
        except (BlockingIOError, InterruptedError):
            return count
        except OSError:
            pass
        count += 1


def serve(model: Model, options: OnlineOptions, serving: ServeOptions, clock=time.monotonic, ready=None,
          on_drop=None, inbound: socket.socket | None = None, log=None, console=None, record=None) -> Served:
    """Run a session (see the module's docstring) until ``serving.duration``, ``serving.quiet_end`` or
    a stop signal; returns what it did. The controller's options are ``options.mpc`` (a plan every
    step: the session's step is the cycle); its predictor ``options.predictor``
    (one that may run live, :data:`desdemona.control.predictors.PREDICTORS`). ``ready(early)``, if given,
    is called once the service listens, with the number of host datagrams that came before (counted as
    dropped); ``on_drop(line)`` when datagrams are dropped, at most once a second per reason.
    ``inbound``: the host's socket (:func:`listening`), bound before the controller is built, so that
    a port in use is said at once and what a host sends meanwhile is counted; None: bound to
    ``serving.listen``. ``log``, if given, a :class:`~desdemona.service.sessionlog.LiveLog` that gets
    every cycle as it ends; ``console``, a :class:`~desdemona.service.console.Console` handed each cycle
    as it ends, whose operators' commands are taken as Command datagrams are; ``record``, the folder
    where the session's record writes its older blocks (:mod:`~desdemona.service.spill`: the session's
    results; None: the system's temporary folder)."""
    mpc = options.mpc
    predictors.check(options.predictor, True, options.reference is not None, options.forecast is not None)
    if mpc.replan_steps != 1:
        raise ValueError("a live session plans every cycle: no --replan")
    h = mpc.step
    controller = MPC(model, mpc, weights=mpc.weights)
    channels = serving.channels or default_channels(model.config)
    if channels == 1 and not model.config.takes_modulus:
        raise ValueError(f"configuration {model.config.name!r} needs the six channels of S, not the modulus")
    preview = _Preview(options.predictor, model, mpc.horizon, options.reference, serving.history)
    guard_use = model.step_limit_use(h)
    stops: list[int] = []
    with inbound or listening(serving.listen) as inbound, \
            socket.socket(socket.AF_INET, socket.SOCK_DGRAM) as outbound, \
            guard.handled_here(stops.append), pacing.collected() as collect:
        early = _discard_queued(inbound)
        if ready is not None:
            ready(early)
        link = MachineLink(model, h, serving.send, serving.state_lost, key=serving.key, on_drop=on_drop, clock=clock)
        inbox = Inbox(inbound, channels, clock, serving.timeout * h, on_drop, machine=(outbound, link),
                      operator=serving.operator, early=early, key=serving.key, record=record)
        session = _Session(model, controller, h, guard_use, record)
        start = clock()
        k = 0
        while True:
            opens, closes = start + (k - 0.5) * h, start + (k + 0.5) * h
            # stopping, the cycles keep their times; else each starts as a new host message comes
            inbox.wait(start + k * h, np.inf) if stops else inbox.wait(closes, opens)
            began, cpu, session.timings, session.followed = clock(), time.thread_time(), None, False
            _operate(session, inbox, console, outbound, serving.send, k * h, began - start)
            alive = inbox.arrived is not None and began - inbox.arrived <= serving.timeout * h
            machine = session.observe(link, k * h, began)
            if stops:
                session.park(stop=True, hard=len(stops) > 1)
            elif machine or (session.paused and session.held is None):
                session.park(reason=machine or f"operator: {session.paused}")
            elif session.paused:  # the operator's pause: the present cue held, the host not followed
                session.run(preview.held(session.held), 0.0, None)
                session.reason = session.reason or "operator: pause (the cue held)"
            elif alive:  # with nothing new since the last cycle, the last plan's next step where it can
                if inbox.fresh or not session.follow():
                    session.run(*pacing.timed(preview, inbox), inbox.newest.sequence)
            elif inbox.newest is None:
                session.hold("starting")
            else:
                session.park()
            answered = inbox.fresh and alive and not (stops or machine or session.paused)
            inbox.fresh = inbox.fresh and not answered
            sending, setpoint = clock(), session.setpoint(k, began - start, inbox.newest.sequence if answered else None)
            _send(outbound, setpoint, serving.send, inbox)
            sent = clock()
            session.record(k, compute=sent - began, age=np.nan if inbox.arrived is None else began - inbox.arrived,
                           latency=sent - inbox.arrived if answered else np.nan, timed=(sent - sending, cpu))
            _log(log, console, session, inbox, link, model.config)
            collect()  # the garbage of the cycle's objects, after its send (pacing.Collector)
            k += 1
            quiet = inbox.arrived is not None and clock() - inbox.arrived > (serving.quiet_end or np.inf)
            if ((stops and (session.status == "parked" or len(stops) > 1))
                    or (serving.duration is not None and k * h >= serving.duration)
                    or (quiet and session.status == "parked")):
                break
    return _served(session, inbox, link, start, stops, controller.deadline)


def _served(session: _Session, inbox: Inbox, link: MachineLink, start: float, stops, deadline: float) -> Served:
    """What the session did, its record read back (and its temporary files closed: spill)."""
    offset = inbox.arrivals.head - start - inbox.t.head if inbox.t else 0.0
    served = Served(loop=session.loop(), columns=session.columns(), received_t=np.asarray(inbox.t) + offset,
                    received=np.asarray(inbox.values).reshape(len(inbox.t), inbox.channels),
                    dropped=inbox.dropped + link.dropped, drop_samples={**link.drops.sample(), **inbox.drops.sample()},
                    stopped_by=stops[0] if stops else None, deadline=deadline, offset=offset,
                    events=session.events, states=link.received, reanchored=session.reanchored, breaks=session.breaks)
    for record in (session.rows, session.u, session.jerks, inbox.t, inbox.values, inbox.arrivals):
        record.close()
    return served


def _operate(session: _Session, inbox: Inbox, console, outbound: socket.socket, to, t: float, now: float) -> None:
    """The operators' commands that came (as Command datagrams, or from the console), acted on and
    logged at the cycle's time ``t``; an emergency stop and a reset passed on to the motion system."""
    commands = inbox.commands + (console.commands() if console is not None else [])
    for _, action, *who in commands:
        session.operator(action, t, *who, present=None if inbox.newest is None else inbox.newest.values)
        if action in ("emergency stop", "reset"):  # the motion system's own: passed on
            _send(outbound, protocol.Command(len(session.events), now, action), to, inbox)
    inbox.commands = []


def _log(log, console, session: _Session, inbox: Inbox, link: MachineLink, config) -> None:
    """The cycle just recorded, into the session's log as it goes (commanded and measured beside, what
    the host asked) and handed to the console (each where given)."""
    state = link.newest
    if log is not None:
        measured = None if state is None else (config.select(state.position), config.select(state.rate),
                                               state.applied_time)
        desired = session.held if session.paused and session.held is not None else (
            None if inbox.newest is None else inbox.newest.values)
        log.cycle(session.rows[-1], (*session.starts[-1][:2], session.u[-1]), measured, session.events, desired)
    if console is not None:
        console.publish(session, inbox, link)


def _send(sock: socket.socket, message, to, inbox: Inbox) -> None:
    try:
        sock.sendto(inbox.outgoing.pack(message), to)
    except OSError as exc:  # the machine's port: nothing to do but count it
        inbox.drops("socket", f"{type(message).__name__.lower()} not sent: {exc.strerror or exc}")


class _Session:
    """The machine's state and the commands of the cycles, as the service drives it."""

    def __init__(self, model: Model, controller: MPC, h: float, guard_use, record=None):
        self.model, self.controller, self.h, self.guard_use = model, controller, h, guard_use
        n = model.n
        self.state = State(np.zeros(n), np.zeros(n), np.zeros(n))
        self.status, self.source, self.reason = "starting", "park", ""
        self.command = (np.zeros(n), np.zeros(n))
        # the cycles' rows and commands, at flat memory (spill: older blocks on a temporary file)
        self.rows, self.u, self.jerks = (Spilled(directory=record) for _ in range(3))
        self.was_parked = False
        self.settle = None  # the second cycle's jerks of coming to rest
        self.starts = Spilled(keep=False)  # each cycle's starting state, for the tracking error: the recent ones
        self.paused: str | None = None  # an operator's pause, park or emergency stop, until resume or reset
        self.held = None  # the host's motion a pause holds
        self.events: list[tuple[float, str, str]] = []
        self.machine_fault = ""  # why the machine is parked on what it measurably does ("": it is not)
        self.own_stop = False  # the machine stopped on its own: it must follow the service's hold first
        self.holding_since: float | None = None  # when it was first seen following that hold
        self.trusted_from = 1  # the first setpoint sequence a State's tracking error is judged on
        self.reanchored = 0
        self.tracking = np.nan  # the use of the tracking tolerance this cycle (1 = a fault)
        self.machine_status = ""
        self.told: set[str] = set()
        self.breaks: list[int] = []
        self.timings, self.guarded = None, 0.0  # this cycle's phases where it planned [s]; the service's check's
        self.followed = False  # this cycle followed the last plan (follow)

    def run(self, preview, preview_time: float, sequence: int) -> None:
        if self.was_parked:  # the machine was moved by the watchdog: plan afresh from here
            self.controller.forget()
            self.was_parked, self.settle = False, None
        command = self.controller.step(self.state, preview if preview is not None else (np.zeros(1), None))
        self.command = (command.sequence[0], command.jerks[0])
        self.status, self.source, self.reason = "running", SOURCE_NAMES[command.source], command.reason
        self._guard()
        self.timings = {**self.controller.timings, "service_preview": preview_time, "guard": self.guarded}

    def follow(self) -> bool:
        """A cycle with no new host message: the last plan's next step (:meth:`MPC.follow`), no QP, so
        that the host's next message, coming while this cycle would have solved, is answered at once;
        False where the controller has none to follow (the cycle then plans on the message it has)."""
        command = None if self.was_parked else self.controller.follow(self.state)
        if command is None:
            return False
        self.command = (command.sequence[0], command.jerks[0])
        self.status, self.source, self.reason = "running", SOURCE_NAMES[command.source], command.reason
        self._guard()
        self.timings, self.followed = None, True
        return True

    def event(self, t: float, what: str, detail: str = "") -> None:
        self.events.append((t, what, detail))

    def operator(self, action: str, t: float, who: str = "", present=None) -> None:
        """An operator's Command: pause (the host's last message's motion, ``present``, held: planned on
        until resume, the host no longer followed; as park where the session is
        not following the host), park (the machine brought to rest and held; the
        controller then plans afresh), resume, emergency stop (parked until a reset), reset; ``who``
        sent it (the console's client)."""
        self.event(t, f"command {action}", who)
        if action == "pause" and self.paused is not None:
            return  # parked or stopped: a pause does not move it again
        if action in ("pause", "park", "emergency stop"):
            # a pause holds the cue of a session that follows the host; a parked machine stays at rest
            self.held = present if action == "pause" and self.status == "running" else None
            self.paused = action
            if action == "park":
                self.controller.forget()
        elif (action, self.paused) in (("resume", "pause"), ("resume", "park"), ("reset", "emergency stop")):
            self.paused = None

    def observe(self, link: MachineLink, t: float, now: float) -> str:
        """Take the newest State of the machine ``link`` at the cycle's time ``t`` [s] (``now`` on the
        clock): why the machine must be parked on what it measurably does ("" if it need not); the
        state the cycle plans from is the measured machine carried forward where it is off the
        command beyond the noise (:data:`~desdemona.service.measured.BAND`)."""
        if link.newest is None:
            if t > 1.0 and "no state" not in self.told:
                self.told.add("no state")
                self.event(t, "no State from the machine", "planning on its own command (as protocol version 1)")
            return ""
        if link.lost(now):
            return self._machine(t, f"no State from the machine for more than {link.lost_after:g} s")
        commanded = commanded_at(self.starts, self.u, self.jerks, self.h)
        tracking = link.tracking(lambda tau: commanded(tau) if link.newest.applied is not None
                                 and link.newest.applied >= self.trusted_from else None)
        self.tracking, self.machine_status = tracking.use, tracking.status
        st = tracking.state
        if tracking.status in STOPPED_ON_ITS_OWN or (tracking.status == "stopped" and self.status != "parked"
                                                       and not self.machine_fault):
            joint = "" if st.fault_joint is None else f" on {JOINT_NAMES[st.fault_joint]}"
            fault = "" if st.fault == "none" else f" ({st.fault} fault{joint})"
            return self._machine(t, f"the machine is {tracking.status}{fault}", measured=link.measured(now))
        if tracking.use > 1.0:
            return self._machine(t, f"tracking error {tracking.use:.2f} x its tolerance", error=tracking.error)
        if self.machine_fault:
            if self.status != "parked" or not self._holding(link, t, now):  # no more re-anchoring
                return self.machine_fault
            self.event(t, "machine back", f"{tracking.status}: planning afresh from where it stands")
            self.machine_fault, self.own_stop, self.holding_since = "", False, None
        elif tracking.use > BAND:
            self._carry(tracking.error)
            self.reanchored += 1
        return ""

    def _holding(self, link: MachineLink, t: float, now: float) -> bool:
        """The parked service may plan again: at once where the machine did not stop on its own, else
        once it has followed the service's hold for :data:`~desdemona.service.measured.SETTLE` s. While
        it holds on its own, the hold is moved to where it is measured, so that it starts to follow."""
        st = link.newest
        if not self.own_stop:
            return True
        if st.status == "following" and st.applied is not None and st.applied >= self.trusted_from:
            self.holding_since = t if self.holding_since is None else self.holding_since
            return t - self.holding_since >= SETTLE - 1e-9
        self.holding_since = None
        if st.status in HOLDING_ON_ITS_OWN:
            q, _ = link.measured(now)
            self.state = State(q, np.zeros_like(q), np.zeros_like(q))
            self.trusted_from = len(self.rows) + 1  # the hold it is to follow is this one or a later one
        return False

    def _machine(self, t: float, why: str, measured=None, error=None) -> str:
        """Park on what the machine measurably does: from ``measured`` (q, qd) where it stopped on its
        own, from the command plus the tracking ``error`` where it drifted off; logged once per reason."""
        if why != self.machine_fault:
            self.event(t, "machine fault", why)
            self.controller.forget()
            self.breaks.append(len(self.rows))
        self.machine_fault = why
        if measured is not None:
            q, qd = measured
            self.state, self.settle, self.own_stop = State(q, qd, np.zeros_like(q)), None, True
            self.trusted_from = len(self.rows) + 1  # the setpoints from now on start where the machine is
        elif error is not None:
            self._carry(error)
        return why

    def _carry(self, error) -> None:
        q, qd, a = self.state
        self.state, self.settle = State(q + error[0], qd + error[1], a), None
        # the States of the setpoints already sent still measure this error against the line before
        # the carry: judged again, it would be carried again, cycle after cycle (a runaway)
        self.trusted_from = len(self.rows) + 1

    def park(self, stop: bool = False, hard: bool = False, reason: str = "") -> None:
        """Stop the machine as quickly as its limits allow (:func:`stopping_jerk`: each joint braking at
        its acceleration limit, reached and left at its jerk limit; at a lower acceleration where the
        cycle's check of every limit asks for it, and as :meth:`MPC.brake` where none passes), and, once
        nearly still, come to rest exactly in two cycles; then hold."""
        q, qd, a = self.state
        lim, h = self.model.limits, self.h
        near = np.all(np.abs(qd) <= lim.jerk * h**2 / 4) and np.all(np.abs(a) <= lim.jerk * h / 4)
        self.status = "parking"
        if self.settle is not None:  # the second cycle of coming to rest
            self.command, self.settle = (a.copy(), self.settle), None
        elif near and not hard:
            if np.all(np.abs(qd) < 1e-12) and np.all(np.abs(a) < 1e-12):
                self.state = State(q, np.zeros_like(qd), np.zeros_like(a))  # still: round-off left behind
                self.command, self.status = (np.zeros_like(qd), np.zeros_like(qd)), "parked"
            else:  # the jerks that take rate and acceleration to zero at the end of the next cycle
                self.command = (a.copy(), -qd / h**2 - 1.5 * a / h)
                self.settle = qd / h**2 + 0.5 * a / h
        else:
            for share in (1.0, 0.75, 0.5, 0.25):
                self.command = (a.copy(), stopping_jerk(qd, a, h, share * lim.acceleration, lim.jerk))
                if self._use() <= 1.0 + TOLERANCE:
                    break
            else:
                self.command = self.controller.brake(q, qd, a)
        self.source, self.reason = "park", reason or ("stop" if stop else "no host message")
        self.was_parked = True
        self._guard()

    def hold(self, status: str) -> None:
        self.command, self.status, self.source, self.reason = (np.zeros(self.model.n),) * 2, status, "park", ""

    def _use(self) -> float:
        """The largest use of any limit over the cycle with the command (1 = at a limit)."""
        return float(np.max(call(self.guard_use, *self.state[:2], *self.command)))

    def _guard(self) -> None:
        """The service's own check of the cycle's command over the cycle (every limit, position to
        jerk); a command that fails it is a fault (the controller's own check should never let one
        through), reported as such in the setpoint and the log."""
        began = time.perf_counter()
        use = self._use()
        self.guarded = time.perf_counter() - began
        if use > 1.0 + TOLERANCE:
            self.status, self.reason = "fault", f"limit use {use:.4f} over the cycle"

    def setpoint(self, k: int, now: float, answers: int | None) -> protocol.Setpoint:
        config = self.model.config
        q, qd, a = self.state
        qdd, jerk = self.command
        return protocol.Setpoint(k + 1, now, self.status, self.source, answers, k * self.h, self.h, config.expand(q),
                                 config.expand(qd, "zero"), config.expand(qdd, "zero"), config.expand(jerk, "zero"))

    def record(self, k: int, compute: float, age: float, latency: float, timed=(np.nan, 0.0)) -> None:
        """The cycle's row, and the state its command leaves the machine in; ``timed`` = (the send's time
        [s], the thread's processor time at the cycle's start): its phases, then the next cycle's QP
        prepared from that state where it planned (:func:`desdemona.service.pacing.close`)."""
        qdd, jerk = self.command
        self.starts.append(self.state)
        self.u.append(qdd)
        self.jerks.append(jerk)
        self.rows.append({"t": k * self.h, "compute_time_s": compute, "message_age_s": age, "latency_s": latency,
                          "command": self.source, "status": self.status, "reason": self.reason,
                          "tracking_use": self.tracking, "machine": self.machine_status})
        self.state = self.state.advance(qdd, self.h, jerk)
        pacing.close(self.rows[-1], self.timings, *timed, self.controller.prepare, self.state, self.followed)

    def loop(self) -> ClosedLoop:
        n, rows = self.model.n, list(self.rows)
        plan = Plan(np.arange(len(self.u) + 1) * self.h, np.zeros(n), np.zeros(n), self.u.array().reshape(-1, n),
                    self.jerks.array().reshape(-1, n))
        sources = tuple({"plan": "mpc", "previous plan": "shifted"}.get(r["command"], "brake") for r in rows)
        return ClosedLoop(plan, np.array([r["t"] for r in rows]), sources,
                          np.array([r["compute_time_s"] for r in rows]), tuple(r["reason"] for r in rows))

    def columns(self) -> dict[str, np.ndarray]:
        rows = list(self.rows)
        return {key: np.array([r[key] for r in rows])
                for key in (*TIMED, "message_age_s", "latency_s", "command", "status", "tracking_use", "machine")}


def result(served: Served, model: Model, options: OnlineOptions) -> OnlineResult:
    """The session judged as an on-line run (:func:`desdemona.control.online.judge`) over the span it followed
    the host (:meth:`Served.judged`), against the motion the host sent, with the classical loop run
    beside it over the same span from the same state; :class:`~desdemona.check.simulate.LimitViolation` if
    the machine's motion broke a limit."""
    path, loop = served.judged(model)
    return judge(path, model, options, loop, served.deadline)

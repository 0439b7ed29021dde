"""Hosts for one computer: programs that send the vehicle's motion to ``desdemona serve`` over UDP as a
simulator host would (``docs/protocol.md``, :class:`~desdemona.service.protocol.Motion` messages).

- :func:`replay` (``desdemona host replay PATH --to HOST:PORT``) sends a desired path (a CSV file or a
  built-in profile) in real time, one message per sample. It is for a session on one computer: the
  service, this host and a stand-in for the motion system (``desdemona machine``), and for tests and
  benchmarks of the service: ``drop`` loses a share of the datagrams at random, ``outage`` goes quiet
  for a while (the service's watchdog must park the machine), ``speed`` replays faster or slower.
- :func:`jsbsim` (``desdemona host jsbsim SCRIPT --to HOST:PORT``) flies a JSBSim script in real time
  and sends what its pilot feels, as the import does (:mod:`desdemona.profiles.jsbsim`): a stand-in for
  a simulator host whose vehicle model runs while the service cues it.

Both can attach a forecast to each message: the next ``forecast`` seconds of the motion at a fixed step.
Both forecasts are perfect: the recording's own next samples (:func:`replay`), or the same deterministic
flight computed ahead of what is sent (:func:`jsbsim`) -- a test of the service with the best forecast
a host could give, not a model of one a real simulator could make.

Each message's ``sequence`` counts every sample, sent or not: a datagram withheld by ``drop`` or
``outage`` leaves a gap in the sequence the receiver sees, as a lost one would. Both hosts send only to
the address given, sleep until each send time (no busy waiting), end with the path or the flight, and
stop at once on Ctrl-C (``KeyboardInterrupt``, or :class:`desdemona.support.guard.Interrupted` inside the
command line's ``interruptible()``).
"""

from __future__ import annotations

import bisect
import math
import os
import socket
import tempfile
import time
from pathlib import Path

import numpy as np

from desdemona.profiles import convert
from desdemona.profiles import jsbsim as _flights
from desdemona.profiles.path import DesiredPath, G, ProfileError
from desdemona.service import protocol
from desdemona.service.signing import Outgoing
from desdemona.support import guard

#: The largest payload of a UDP datagram over IPv4 [bytes]: a forecast must fit in one message.
MAX_DATAGRAM = 65507


def _check_common(speed: float, forecast: float, start_sequence: int, drop: float, outage) -> None:
    if not (math.isfinite(speed) and speed > 0):
        raise ValueError(f"speed {speed!r}: must be a positive number (1 = real time)")
    if not (math.isfinite(forecast) and forecast >= 0):
        raise ValueError(f"forecast {forecast!r}: must be a number of seconds >= 0")
    if not (isinstance(start_sequence, (int, np.integer)) and 0 <= start_sequence <= 0xFFFFFFFF):
        raise ValueError(f"start_sequence {start_sequence!r}: must be an integer in 0 ... 2^32 - 1")
    if not (0.0 <= drop <= 1.0):
        raise ValueError(f"drop {drop!r}: must be a share between 0 and 1")
    if outage is not None:
        begin, length = (float(x) for x in outage)
        if not (math.isfinite(begin) and math.isfinite(length) and length >= 0):
            raise ValueError(f"outage {outage!r}: give (start, length) in seconds, length >= 0")


def _forecast_samples(forecast: float, step: float, channels: int) -> int:
    """The number of forecast samples of ``forecast`` seconds at ``step``; ValueError if the message
    would not fit in one datagram (or exceeds the protocol's limit)."""
    if forecast <= 0:
        return 0
    n = max(1, round(forecast / step))
    fixed = protocol.HEADER.size + protocol.MOTION.size + protocol.TRAILERS
    size = fixed + 8 * channels * (1 + n)
    if n > protocol.MAX_FORECAST or size > MAX_DATAGRAM:
        most = min(protocol.MAX_FORECAST, (MAX_DATAGRAM - fixed) // (8 * channels) - 1)
        raise ValueError(f"a forecast of {forecast:g} s at a step of {step:g} s is {n} samples: a message of "
                         f"{size} bytes; at most {most} samples ({most * step:.4g} s) fit in one datagram")
    return n


class _Sender:
    """Sends Motion messages to one address on a real-time schedule: the message of vehicle time
    ``offset`` [s after the first message] is due ``offset / speed`` seconds after the first one was."""

    def __init__(self, to: tuple[str, int], speed: float, start_sequence: int, drop: float, outage, seed: int,
                 clock, sleep, key: bytes | None = None):
        host, port = to
        family, kind, proto, _, address = socket.getaddrinfo(host, int(port), type=socket.SOCK_DGRAM)[0]
        self.socket = socket.socket(family, kind, proto)
        self.address = address
        self.speed, self.drop, self.clock, self.sleep = float(speed), float(drop), clock, sleep
        self.outage = None if outage is None else (float(outage[0]), float(outage[0]) + float(outage[1]))
        self.random = np.random.default_rng(seed)
        self.outgoing = Outgoing(key)  # a session of its own; signed with a key
        self.sequence = int(start_sequence)
        self.first_sequence = self.sequence
        self.started: float | None = None
        self.counts = {"sent": 0, "dropped": 0, "outage": 0}
        self.late = 0.0  # the latest a message went out after its time [s]
        self.last = None  # wall time of the last send

    def close(self) -> None:
        self.socket.close()

    def send(self, offset: float, time_: float, values, forecast=None, step: float = 0.0) -> None:
        """Wait for the message's time, then send it unless it is withheld (``drop``, ``outage``).
        ``offset``: vehicle time since the first message [s]; ``time_``: the message's time field."""
        now = self.clock()
        if self.started is None:
            self.started = now
        due = self.started + offset / self.speed
        while now < due:
            self.sleep(due - now)  # interrupted by a signal: its handler raises here (Ctrl-C)
            now = self.clock()
        guard.check()
        self.late = max(self.late, now - due)
        if self.sequence > 0xFFFFFFFF:
            raise ValueError("the sequence number passed 2^32 - 1: give a lower start_sequence")
        sequence, self.sequence = self.sequence, self.sequence + 1
        withheld = self.drop > 0 and self.random.random() < self.drop
        if self.outage is not None and self.outage[0] <= time_ < self.outage[1]:
            self.counts["outage"] += 1
        elif withheld:
            self.counts["dropped"] += 1
        else:
            message = protocol.Motion(sequence, float(time_), np.asarray(values, dtype=float),
                                      None if forecast is None or len(forecast) == 0 else forecast,
                                      step if forecast is not None and len(forecast) else 0.0)
            self.socket.sendto(self.outgoing.pack(message), self.address)
            self.counts["sent"] += 1
            self.last = now

    def result(self) -> dict:
        messages = self.sequence - self.first_sequence
        duration = 0.0 if self.started is None else self.clock() - self.started
        return {**self.counts, "messages": messages, "first_sequence": self.first_sequence,
                "last_sequence": self.sequence - 1 if messages else None, "duration": duration,
                "late": self.late}


def replay(path: DesiredPath, to: tuple[str, int], speed: float = 1.0, forecast: float = 0.0,
           start_sequence: int = 1, drop: float = 0.0, outage: tuple[float, float] | None = None,
           seed: int = 0, modulus: bool = False, clock=time.monotonic, sleep=time.sleep,
           key: bytes | None = None) -> dict:
    """Send ``path`` to ``to`` = (host, port) in real time: one Motion message per sample.

    Sample k goes out (t_k - t_0) / ``speed`` seconds after the first, with the message time t_k (the
    path's own clock) and the path's channels: the six of S (wx, wy, wz, fx, fy, fz) or, for a
    modulus-only path or with ``modulus``, the modulus M. A message late by more than a step (a busy
    computer) is sent late, not skipped; ``late`` in the result says by how much at most.

    forecast : seconds of the recording after each sample to attach, at the path's sample step (its
        median step; a non-uniform grid is interpolated): the true future, what a perfect forecast
        would send. Near the path's end the forecast is cut where the recording ends (fewer samples).
    start_sequence : the first message's sequence number; each sample takes the next one, sent or not.
    drop : the share of messages withheld at random (a generator seeded with ``seed``).
    outage : (start, length) [s of the path's time]: the messages of start <= t_k < start + length are
        withheld (the host going quiet).
    clock, sleep : the wall clock [s] and the way to wait (for tests).
    key : the shared key every message is signed with (:mod:`desdemona.service.signing`), or None.

    Returns ``sent``, ``dropped`` (by ``drop``), ``outage`` (withheld by it), ``messages`` (all samples),
    ``first_sequence``, ``last_sequence``, ``duration`` [s of wall time from the first message's time
    to the end] and ``late`` [s]. ValueError for arguments out of range.
    """
    _check_common(speed, forecast, start_sequence, drop, outage)
    t = path.t
    if start_sequence + len(t) - 1 > 0xFFFFFFFF:
        raise ValueError(f"start_sequence {start_sequence}: {len(t)} messages would pass 2^32 - 1")
    X = path.M_d[:, None] if (modulus or path.S_d is None) else path.S_d
    step = float(np.median(np.diff(t)))
    n = _forecast_samples(forecast, step, X.shape[1])
    uniform = np.allclose(np.diff(t), step, rtol=1e-6, atol=1e-9)
    sender = _Sender(to, speed, start_sequence, drop, outage, seed, clock, sleep, key)
    try:
        for k in range(len(t)):
            ahead = None
            if n:
                if uniform:
                    ahead = X[k + 1: k + 1 + n]
                else:
                    times = t[k] + step * np.arange(1, n + 1)
                    times = times[times <= t[-1] + 1e-9 * step]
                    ahead = np.column_stack([np.interp(times, t, X[:, i]) for i in range(X.shape[1])])
            sender.send(t[k] - t[0], t[k], X[k], ahead, step)
        return sender.result()
    finally:
        sender.close()


class _Flight:
    """A JSBSim run stepped on demand, its samples (after every step) kept from where they are still
    needed: time, body rates (p, q, r) [rad/s], pilot-station specific force (body axes) [m/s^2]."""

    def __init__(self, fdm, jsbsim, end: float | None):
        self.fdm, self.jsbsim, self.end = fdm, jsbsim, end
        manager = fdm.get_property_manager()
        self.props = [manager.get_node(name) for name in _flights.RATES + _flights.FORCE]
        self.trim_node = manager.get_node(_flights.TRIMMED)
        self.t: list[float] = []
        self.rows: list[list[float]] = []
        self.trimmed: list[bool] = []
        self.ended: str | None = None  # why no more samples come: the script's end, ``end``, a crash

    def advance(self, until: float) -> None:
        """Step the model until its last sample is at or after ``until`` [s of sim time] (or it ends)."""
        while self.ended is None and (not self.t or self.t[-1] < until):
            try:
                running = self.fdm.run()
            except self.jsbsim.BaseError as exc:
                at = f" at t = {self.t[-1]:.2f} s" if self.t else ""
                raise ProfileError(f"JSBSim{at}: {type(exc).__name__}: {' '.join(str(exc).split())}") from None
            if not running:
                self.ended = "the script's end"
                break
            t = self.fdm.get_sim_time()
            if self.t and t < self.t[-1] - 0.5 * self.fdm.get_delta_t():  # as the import: the first run only
                self.ended = (f"the script's clock going back at {self.t[-1]:.4g} s to run again (a series of "
                              f"runs): its first run only")
                break
            values = [node.get_double_value() for node in self.props]
            row = values[:3] + [v * G for v in values[3:]]
            force = math.sqrt(sum(v * v for v in row[3:]))
            if not all(math.isfinite(v) for v in row) or force > convert.CRASH_G * G:
                self.ended = (f"the flight crashed or diverged at t = {t:.2f} s (a specific force above "
                              f"{convert.CRASH_G:g} g or not a number)")
                break
            if self.t and t <= self.t[-1]:  # a trim may repeat a time: keep its last sample
                self.t.pop(), self.rows.pop(), self.trimmed.pop()
            self.t.append(t)
            self.rows.append(row)
            self.trimmed.append(self.trim_node is not None and self.trim_node.get_double_value() > 0.5)
            if self.end is not None and t > self.end:
                self.ended = "its end"
                break

    def cabin(self, times) -> np.ndarray:
        """(len(times), 6) S in the cabin frame at ``times`` [s of sim time], linearly interpolated
        between JSBSim's steps (every time within the samples kept)."""
        times = np.asarray(times, dtype=float)
        lo = max(bisect.bisect_right(self.t, float(times[0])) - 1, 0)
        hi = min(bisect.bisect_left(self.t, float(times[-1])) + 1, len(self.t))
        t = np.asarray(self.t[lo:hi])
        raw = np.asarray(self.rows[lo:hi])
        body = np.column_stack([np.interp(times, t, raw[:, i]) for i in range(6)])
        return np.column_stack([convert.turn_to_cabin(body[:, :3], convert.R_CABIN_BODY),
                                convert.turn_to_cabin(body[:, 3:], convert.R_CABIN_BODY)])

    def forget(self, before: float) -> None:
        """Drop the samples no longer needed (all but one before ``before``), now and then."""
        i = bisect.bisect_right(self.t, before) - 1
        if i > 1000:
            del self.t[:i], self.rows[:i], self.trimmed[:i]

    def default_start(self, script: Path, aircraft: str) -> tuple[float, str]:
        """The import's default start (:func:`desdemona.profiles.jsbsim.default_start`), from the first
        seconds of the run: the model is run (as fast as it computes) until a trim completes or until
        the settling rule's window has passed. A trim later than that window is not waited for."""
        horizon = _flights.SETTLE_WITHIN + _flights.SETTLE_SECONDS + 0.1
        while self.ended is None and not (self.trimmed and self.trimmed[-1]):
            self.advance((self.t[-1] if self.t else 0.0) + 1e-9)
            if self.t and self.t[-1] - self.t[0] > horizon:
                break
        if len(self.t) < 2:
            raise ProfileError(f"JSBSim script {script}: ran no time")
        raw = np.asarray(self.rows)
        flight = _flights.Flight(script, aircraft, self.jsbsim.__version__, np.asarray(self.t), raw[:, :3],
                                 raw[:, 3:], np.zeros((len(raw), 2)), np.asarray(self.trimmed))
        return _flights.default_start(flight)


def jsbsim(script: str | Path, to: tuple[str, int], speed: float = 1.0, forecast: float = 0.0,
           rate: float = _flights.DEFAULT_RATE, start: float | None = None, end: float | None = None,
           start_sequence: int = 1, drop: float = 0.0, outage: tuple[float, float] | None = None,
           seed: int = 0, modulus: bool = False, clock=time.monotonic, sleep=time.sleep,
           key: bytes | None = None) -> dict:
    """Fly a JSBSim script (a shipped one by name, or a file) in real time and send what its pilot
    feels to ``to`` = (host, port), ``rate`` messages per second of sim time.

    The motion is the import's (:func:`desdemona.profiles.from_jsbsim`): the pilot station's specific
    force (:data:`~desdemona.profiles.jsbsim.FORCE`, in g, times G) and the body rates
    (:data:`~desdemona.profiles.jsbsim.RATES`), turned into the cabin frame by
    :data:`desdemona.profiles.convert.R_CABIN_BODY`; with ``modulus``, the modulus |f| alone. Unlike the
    import, which filters the whole flight forwards and backwards, a live host cannot look at the
    future to filter: each message holds JSBSim's samples (after each of its 120 Hz steps) linearly
    interpolated at the message's time, without an anti-alias filter (motion cues lie far below either
    rate).

    start, end : [s of sim time] as the import's ``--start``/``--end``. The model runs as fast as it
        computes up to ``start``, then in real time. ``start`` None: the import's default start
        (after the script's trim, else after the start-up transient), looked for in the run's first
        ~10.6 s (a trim later than that is not waited for). A message's time is the sim time minus the
        start: t = 0 at the start, as in an imported path.
    forecast : seconds of the flight's future to attach to each message, at 1 / ``rate``. JSBSim cannot
        reliably copy a running model to fly it ahead with the controls held (the state of its flight
        control system and of the script's events is not exposed as a whole), so the forecast is the
        true future of this same, deterministic flight: the model is kept ``forecast`` seconds of sim
        time ahead of what is sent and the samples in between go into the message. It is what a perfect
        forecast would send, not what a real host could predict. Near the flight's end it is cut short.
    speed, start_sequence, drop, outage, seed, clock, sleep, key : as for :func:`replay` (``outage`` in
        the message's time, from the start).

    The flight ends with the script, at ``end``, or where the model crashes or diverges (a specific
    force above :data:`.convert.CRASH_G` g or not a number: nothing from there is sent). Returns the
    counts of :func:`replay` and ``script``, ``aircraft``, ``start`` [s of sim time], ``start_reason``
    and ``ended`` (why the flight stopped). Raises :class:`ProfileError` when jsbsim is not installed
    (with the install hint), for an unknown script, one that cannot be loaded or run, or a ``start``
    past the flight's end; ValueError for arguments out of range.
    """
    _check_common(speed, forecast, start_sequence, drop, outage)
    rate = float(rate)
    if not (math.isfinite(rate) and rate > 0):
        raise ValueError(f"rate {rate!r}: must be a positive number of messages per second")
    if start is not None and end is not None and not end > start:
        raise ValueError(f"start {start:g} and end {end:g}: the end must be after the start")
    step = 1.0 / rate
    n = _forecast_samples(forecast, step, 1 if modulus else 6)
    lib = _flights._jsbsim()  # ProfileError with the install hint without the jsbsim package
    path, root, aircraft, init = _flights.script_setup(script)
    with tempfile.TemporaryDirectory() as tmp:
        log = os.path.join(tmp, "jsbsim.log")
        with _flights._quiet(log):  # JSBSim's banner and the script's notify events: into the log
            flight = _Flight(_open(lib, root, path, init, tmp), lib, end)
            if start is None:
                lo, why = flight.default_start(path, aircraft)
            else:
                flight.advance(float(start))
                if not flight.t or flight.t[-1] < start:
                    last = flight.t[-1] if flight.t else 0.0
                    raise ProfileError(f"JSBSim script {path.stem}: start {start:g} s is past its end at "
                                       f"{last:.4g} s ({flight.ended})")
                lo, why = float(start), "as given"
            if end is not None and not end > lo:
                raise ProfileError(f"JSBSim script {path.stem}: it starts at {lo:.4g} s ({why}), after the "
                                   f"end {end:g} s; give a later end or a start")
            sender = _Sender(to, speed, start_sequence, drop, outage, seed, clock, sleep, key)
            try:
                _stream(flight, sender, lo, step, n, end, modulus)
                result = sender.result()
            finally:
                sender.close()
    ended = flight.ended or "its end"
    if end is not None and flight.ended in (None, "its end"):
        ended = f"the end {end:g} s"
    return {**result, "script": path.stem, "aircraft": aircraft, "start": lo, "start_reason": why,
            "ended": ended}


def _open(lib, root: Path, path: Path, init: str, tmp: str):
    """A JSBSim model with the script loaded and its initial conditions run; its output files go to
    ``tmp``. :class:`ProfileError` where JSBSim cannot load or run it."""
    try:
        fdm = lib.FGFDMExec(str(root))
        fdm.set_debug_level(0)
        fdm.set_output_path(tmp)  # a script's <output> files go here, not into JSBSim's folder
        loaded = fdm.load_script(str(path), 0.0, init) if init else fdm.load_script(str(path))
        if loaded:
            fdm.disable_output()
            fdm.run_ic()
    except (lib.BaseError, OSError) as exc:
        raise ProfileError(f"JSBSim script {path}: cannot be run: {type(exc).__name__}: "
                           f"{' '.join(str(exc).split())}") from None
    if not loaded:
        raise ProfileError(f"JSBSim script {path}: cannot be run: JSBSim could not load it")
    return fdm


def _stream(flight, sender, lo: float, step: float, n: int, end: float | None, modulus: bool) -> None:
    """Send the flight from sim time ``lo`` every ``step`` until its end (or ``end``), each message with
    the next ``n`` samples as its forecast, the model kept that far ahead."""
    k = 0
    while True:
        ts = lo + k * step
        if end is not None and ts > end + 1e-9:
            return
        flight.advance(ts + n * step)
        if not flight.t or flight.t[-1] < ts - 1e-9:
            return
        last = flight.t[-1] if end is None else min(flight.t[-1], end)
        times = ts + step * np.arange(0, n + 1)
        times = times[times <= last + 1e-9]
        S = flight.cabin(times)
        X = np.linalg.norm(S[:, 3:], axis=1)[:, None] if modulus else S
        sender.send(k * step, k * step, X[0], X[1:] if n else None, step)
        flight.forget(ts)
        k += 1

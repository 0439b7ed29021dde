"""Bridges from a flight simulator's own UDP output to ``desdemona serve``: the simulator's packets in,
checked Motion messages out (``docs/protocol.md``).

``desdemona host flightgear`` (:mod:`.flightgear`) and ``desdemona host xplane`` (:mod:`.xplane`) each
decode their simulator's packets into a :class:`Sample` (body rates, the specific force at the pilot,
the attitude, where the aircraft is); this module turns samples into the cabin frame (DESIGN.md,
"Vehicle data in"), checks them live and forwards them to ``serve``.

Why a bridge beside ``serve`` rather than inside it: ``serve`` stays one protocol and one real-time
loop, tested with the replay and JSBSim hosts alone, whatever simulator drives it; each simulator's
packets, versions and conventions are decoded and checked in one module of its own, testable without
the service; and the bridge can run on the simulator's computer while ``serve`` runs beside the
machine. The cost is one more datagram on loopback (tens of microseconds, measured by ``delay``).

The live check (:class:`Bridge`):

- **Before anything is forwarded** the stream must look like a vehicle: the first still second
  (rates below 1 deg/s, a steady force: at rest or in level flight) must read +1 g up, with the
  world's up taken from the simulator's attitude; the magnitudes must be in SI (rates held above
  10 rad/s, a force that reads like g). The checks and their messages are the import's
  (:func:`.csvfile.check_units`, :func:`.convert.check_convention`); a mistake refuses the session
  (:class:`ProfileError`, naming it) and nothing is sent.
- **While forwarding**, a stream that turns implausible stops the forwarding, with the reason:
  not a number, beyond any vehicle's motion, a crash (above 20 g), rates held above 10 rad/s, a
  frozen simulator (nothing changed for half a second: paused), a reset (the simulator's clock going
  back, or the aircraft moved further than its speed allows). ``serve`` then hears nothing and parks
  the machine after its timeout. When the stream runs again, its first seconds are checked afresh.
"""

from __future__ import annotations

import math
import socket
import time
from collections import Counter
from dataclasses import dataclass

import numpy as np

from desdemona.profiles import convert, csvfile
from desdemona.profiles.path import G, MAX_ANGULAR_VELOCITY, MAX_SPECIFIC_FORCE, DesiredPath, ProfileError
from desdemona.service import protocol
from desdemona.service.signing import Outgoing
from desdemona.support import guard

#: [s] the stream the start check reads: a still second within it (:data:`.convert.STILL_SECONDS`)
START_SECONDS = 2.0
#: [s] a simulator whose motion has not changed this long is frozen (paused, stopped)
FROZEN_SECONDS = 0.5
#: A move between two packets longer than this many times the distance the speed allows, plus
#: :data:`JUMP_MARGIN` [m], is a reset or a jump (a new position), not flight.
JUMP_SPEED_FACTOR = 3.0
JUMP_MARGIN = 50.0
#: [s] no packet this long while forwarding: the simulator stopped sending (said once; ``serve``'s own
#: watchdog parks the machine after its timeout, whatever the bridge says)
QUIET_SECONDS = 1.0
#: The WGS 84 ellipsoid: the aircraft's place as a point (the jump check), from latitude and longitude.
_A, _E2 = 6378137.0, 6.69437999014e-3


class DecodeError(ValueError):
    """A packet that is not the simulator's format (counted by its message, never used)."""


@dataclass(frozen=True)
class Sample:
    """One packet of a simulator, decoded.

    omega_body : (3,) p, q, r [rad/s], body axes x forward, y right, z down;
    f_body : (3,) specific force [m/s^2] at the pilot (where the simulator gives it), body axes;
    attitude : (phi, theta) bank and pitch [rad] (the world's up in the cabin frame);
    position : (3,) [m] earth-centred, earth-fixed (:func:`ecef`); speed : [m/s] over the ground;
    sim_time : the simulator's clock [s], None where its packets carry none;
    state : what changes from packet to packet while the simulation runs (the frozen check).
    """

    omega_body: np.ndarray
    f_body: np.ndarray
    attitude: tuple[float, float]
    position: np.ndarray
    speed: float
    sim_time: float | None
    state: tuple

    def cabin(self) -> np.ndarray:
        """(6,) S = (omega_cabin, f_cabin) (DESIGN.md, "Vehicle data in": wx = q, wy = p, wz = -r)."""
        R = convert.R_CABIN_BODY
        return np.concatenate([R @ np.asarray(self.omega_body, float), R @ np.asarray(self.f_body, float)])

    def up_cabin(self) -> np.ndarray:
        """(3,) the world's up in the cabin frame (:func:`.convert.up_from_attitude`)."""
        return convert.up_from_attitude(*self.attitude)


def ecef(lat: float, lon: float, alt: float) -> np.ndarray:
    """(3,) [m] the earth-centred, earth-fixed point of geodetic ``lat``, ``lon`` [rad] and ``alt`` [m]
    above the WGS 84 ellipsoid."""
    n = _A / math.sqrt(1.0 - _E2 * math.sin(lat) ** 2)
    return np.array([(n + alt) * math.cos(lat) * math.cos(lon), (n + alt) * math.cos(lat) * math.sin(lon),
                     (n * (1.0 - _E2) + alt) * math.sin(lat)])


def body_rates(phi: float, theta: float, phidot: float, thetadot: float, psidot: float) -> np.ndarray:
    """(3,) body rates p, q, r [rad/s] from the Euler angles' rates (z-y-x, bank ``phi``, pitch ``theta``
    [rad]): ``p = phidot - psidot sin theta``, ``q = thetadot cos phi + psidot sin phi cos theta``,
    ``r = -thetadot sin phi + psidot cos phi cos theta`` (exact: Stevens & Lewis eq. 1.4-4)."""
    sp, cp, st, ct = math.sin(phi), math.cos(phi), math.sin(theta), math.cos(theta)
    return np.array([phidot - psidot * st, thetadot * cp + psidot * sp * ct, -thetadot * sp + psidot * cp * ct])


def check_start(t, S, up, fixes: tuple[str, str, str, str], name: str) -> bool:
    """The start check on a window of the stream: ``t`` (N,) [s], ``S`` (N, 6) in the cabin frame,
    ``up`` (N, 3) the world's up in the cabin frame. True where it passes; False where the window holds
    no still second yet (keep waiting: a manoeuvre); :class:`ProfileError` naming the likely mistake.
    ``fixes``: what mends a force in g, rates in deg/s, a force in g read as m/s^2, the reverse, in
    the words of the simulator's settings; ``name`` the stream in a message."""
    t, X = convert.uniform_grid(np.asarray(t, float) - float(t[0]), np.column_stack([S, up]))
    S, up = X[:, :6], X[:, 6:]
    csvfile.check_units(DesiredPath(name, t, S), lambda k: name if k is None else f"{name} at {t[k]:.2f} s",
                        fixes[:2])
    still = convert.find_still(t, S[:, :3], S[:, 3:])
    if still is None:
        if _rates_in_degrees(t, S):
            raise ProfileError(f"{name}: read as deg/s the rates are still, the force steady, and they swing "
                               f"about zero as no turn does: the rates are in deg/s, not rad/s? {fixes[1]}")
        return False
    inside = (t >= still.t0) & (t <= still.t1)
    try:
        convert.check_convention(still, "the simulator's body axes x forward, y right, z down", up=up[inside].mean(axis=0),
                                 unit_fixes=(f" {fixes[2]}", f" {fixes[3]}"))
    except ProfileError as exc:
        raise ProfileError(f"{name}: {exc}") from None
    return True


def _rates_in_degrees(t, S) -> bool:
    """Where the window is nowhere still: whether it would be with the rates read as deg/s, and the rates
    there swing about zero (their mean below their spread): turbulence in level flight written in
    deg/s. A steady turn's rates are as steady, but about their mean: no mistake, a manoeuvre."""
    still = convert.find_still(t, np.radians(S[:, :3]), S[:, 3:])
    if still is None:
        return False
    omega = S[(t >= still.t0) & (t <= still.t1), :3]
    mean = omega.mean(axis=0)
    return float(np.linalg.norm(mean)) < float(np.sqrt(np.mean(np.sum((omega - mean) ** 2, axis=1))))


class Watch:
    """The checks of a forwarded stream, sample by sample: :meth:`problem` says what is implausible."""

    def __init__(self):
        self.last: tuple[float, Sample] | None = None
        self.changed = None  # when the state last changed [s]
        self.fast_since = None  # since when |omega| is above csvfile.MAX_SUSTAINED_RATE [s]

    def frozen(self, now: float, sample: Sample) -> bool:
        """True once the sample's state has not changed for :data:`FROZEN_SECONDS`."""
        if self.last is None or self.last[1].state != sample.state or self.changed is None:
            self.changed = now
        return now - self.changed >= FROZEN_SECONDS

    def problem(self, now: float, sample: Sample, S: np.ndarray) -> str | None:
        """Why the stream is no vehicle's motion at ``now`` [s], or None (and the sample is kept)."""
        previous, frozen = self.last, self.frozen(now, sample)
        self.last = (now, sample)
        rate, force = float(np.linalg.norm(S[:3])), float(np.linalg.norm(S[3:]))
        if not np.all(np.isfinite(S)):
            return "not a number in the motion"
        if rate > MAX_ANGULAR_VELOCITY or force > MAX_SPECIFIC_FORCE:
            return (f"|omega| = {rate:.4g} rad/s, |f| = {force:.4g} m/s^2: beyond any vehicle's motion "
                    f"(wrong units?)")
        if force > convert.CRASH_G * G:
            return f"|f| = {force / G:.3g} g, above {convert.CRASH_G:g} g: a crash or ground impact"
        self.fast_since = None if rate <= csvfile.MAX_SUSTAINED_RATE else (self.fast_since or now)
        if self.fast_since is not None and now - self.fast_since >= csvfile.SUSTAINED_FOR:
            return f"|omega| above {csvfile.MAX_SUSTAINED_RATE:g} rad/s for {now - self.fast_since:.3g} s: rates in deg/s?"
        if frozen:
            return f"frozen: the simulator's motion has not changed for {FROZEN_SECONDS:g} s (paused?)"
        if previous is None:
            return None
        return _jump(now - previous[0], previous[1], sample)


def _jump(dt: float, before: Sample, after: Sample) -> str | None:
    """A reset between two samples ``dt`` [s] apart: the simulator's clock going back, or a move further
    than the speed allows."""
    if before.sim_time is not None and after.sim_time is not None and after.sim_time < before.sim_time:
        return f"a reset: the simulator's clock went back from {before.sim_time:.3f} s to {after.sim_time:.3f} s"
    moved = float(np.linalg.norm(after.position - before.position))
    allowed = JUMP_SPEED_FACTOR * max(before.speed, after.speed) * max(dt, 0.0) + JUMP_MARGIN
    if moved > allowed:
        return (f"a reset or a jump: the aircraft moved {moved:.4g} m in {dt:.3g} s at "
                f"{max(before.speed, after.speed):.4g} m/s")
    return None


class Bridge:
    """Checked forwarding of a simulator's samples to ``serve``, one Motion message per sample.

    States: ``waiting`` (collecting the stream's first :data:`START_SECONDS` while it runs), ``forwarding``,
    and back to ``waiting`` when the stream turns implausible. ``say(text)`` reports each change; ``key``:
    the shared key its messages are signed with, or None."""

    def __init__(self, sock: socket.socket, to: tuple[str, int], name: str, fixes: tuple[str, str, str, str],
                 modulus: bool = False, say=None, clock=time.monotonic, key: bytes | None = None):
        self.sock, self.to, self.name, self.fixes, self.modulus = sock, to, name, fixes, modulus
        self.outgoing = Outgoing(key)  # a session of its own; signed with a key
        self.say = say or (lambda text: None)
        self.clock = clock
        self.begun = clock()
        self.window: list[tuple[float, np.ndarray, np.ndarray]] = []
        self.watch = Watch()
        self.forwarding = False
        self.sequence = 1
        self.last_time = -math.inf
        self.counts: Counter = Counter()
        self.stops: list[tuple[float, str]] = []
        self.starts: list[float] = []
        self.delays: list[float] = []

    def take(self, sample: Sample, arrived: float) -> None:
        """One decoded sample that arrived at ``arrived`` [s, the bridge's clock]."""
        self.counts["samples"] += 1
        if self.counts["samples"] == 1:
            self.say("the first packet came: waiting until the motion runs and its first still second passes "
                     "the start check")
        S = sample.cabin()
        if self.forwarding:
            problem = self.watch.problem(arrived, sample, S)
            if problem is None:
                self._forward(S, arrived)
            else:
                self._stop(arrived, problem)
            return
        self._wait(sample, S, arrived)

    def quiet(self, now: float) -> None:
        """Nothing came for a while: past :data:`QUIET_SECONDS` while forwarding, say so (the simulator
        stopped or went away) and check the stream afresh when it comes back."""
        if self.forwarding and self.watch.last is not None and now - self.watch.last[0] >= QUIET_SECONDS:
            self._stop(now, f"no packet for {now - self.watch.last[0]:.2f} s: the simulator stopped sending")

    def _stop(self, now: float, problem: str) -> None:
        self.forwarding = False
        self.window = []
        self.stops.append((now - self.begun, problem))
        self.say(f"stopped forwarding at {now - self.begun:.2f} s: {problem}; the service parks the "
                 f"machine when it hears nothing; waiting for the stream to run and pass the start check")

    def _wait(self, sample: Sample, S: np.ndarray, arrived: float) -> None:
        """Collect the stream while it runs; start forwarding once its first seconds pass the check."""
        finite = bool(np.all(np.isfinite(S)))
        self.counts["not a number"] += not finite
        if self.watch.frozen(arrived, sample) or not finite:
            self.window = []  # placeholders until the simulation runs (FlightGear's first packets), a pause
            self.watch.last = (arrived, sample)
            return
        if self.watch.last is not None and _jump(arrived - self.watch.last[0], self.watch.last[1], sample):
            self.window = []  # the simulator repositioned: its first seconds begin here
        self.watch.last = (arrived, sample)
        self.window.append((arrived, S, sample.up_cabin()))
        if arrived - self.window[0][0] < START_SECONDS or len(self.window) < 10:
            return
        t = np.array([w[0] for w in self.window])
        if check_start(t, np.array([w[1] for w in self.window]), np.array([w[2] for w in self.window]),
                       self.fixes, self.name):
            self.forwarding = True
            self.watch = Watch()
            self.watch.last = (arrived, sample)
            self.starts.append(arrived - self.begun)
            self.say(f"the stream reads +1 g up where still ({len(self.window)} packets in "
                     f"{t[-1] - t[0]:.2f} s): forwarding to {self.to[0]}:{self.to[1]}")
            self.window = []
            return
        self.window = [w for w in self.window if w[0] >= arrived - START_SECONDS]  # slide on: a manoeuvre

    def _forward(self, S: np.ndarray, arrived: float) -> None:
        t = arrived - self.begun
        if t <= self.last_time:
            return
        values = np.array([np.linalg.norm(S[3:])]) if self.modulus else S
        data = self.outgoing.pack(protocol.Motion(self.sequence, t, values))
        self.sock.sendto(data, self.to)
        self.delays.append(self.clock() - arrived)
        self.sequence += 1
        self.last_time = t
        self.counts["forwarded"] += 1

    def result(self) -> dict:
        """Counts, the starts and stops [s of the bridge's clock] and the bridge's own delay (packet
        received -> Motion sent) [s], median and 99th percentile."""
        delay = np.array(self.delays) if self.delays else np.array([np.nan])
        return {**self.counts, "starts": self.starts, "stops": self.stops, "last_sequence": self.sequence - 1,
                "delay_median": float(np.median(delay)), "delay_p99": float(np.percentile(delay, 99)),
                "duration": self.clock() - self.begun}


def run(sock: socket.socket, decode, bridge: Bridge, wait: float, duration: float | None = None,
        idle=None) -> dict:
    """Receive the simulator's packets on ``sock`` (bound by the caller) and hand each decoded one to
    ``bridge``, until ``duration`` [s] (None: until stopped) or Ctrl-C. ``wait`` [s]: the longest the
    stream may take to pass the start check; ProfileError beyond it, saying what came. ``idle()`` is
    called when nothing came for a fifth of a second (X-Plane: subscribe again). Ctrl-C ends it with
    the result, ``stopped_by`` the exit code it asks for (130, 143)."""
    sock.settimeout(0.2)
    try:
        _receive(sock, decode, bridge, wait, duration, idle)
    except (guard.Interrupted, KeyboardInterrupt) as stop:  # Ctrl-C: the session's end, with its report
        return {**bridge.result(), "stopped_by": getattr(stop, "code", 130)}
    return bridge.result()


def _receive(sock: socket.socket, decode, bridge: Bridge, wait: float, duration: float | None, idle) -> None:
    while duration is None or bridge.clock() - bridge.begun < duration:
        guard.check()
        if not bridge.starts and bridge.clock() - bridge.begun > wait:
            raise ProfileError(_never_started(bridge, wait))
        try:
            data = sock.recv(65536)
        except TimeoutError:
            bridge.quiet(bridge.clock())
            if idle is not None:
                idle()
            continue
        arrived = bridge.clock()
        bridge.counts["packets"] += 1
        try:
            sample = decode(data)
        except DecodeError as exc:
            bridge.counts[f"dropped: {exc}"] += 1
            continue
        if sample is not None:
            bridge.take(sample, arrived)


def _never_started(bridge: Bridge, wait: float) -> str:
    counts = bridge.counts
    if not counts["packets"]:
        return f"{bridge.name}: no packet came in {wait:g} s: is the simulator sending to this address?"
    if not counts["samples"]:
        dropped = "; ".join(f"{k[len('dropped: '):]} ({v})" for k, v in counts.items() if k.startswith("dropped"))
        return f"{bridge.name}: {counts['packets']} packets in {wait:g} s, none of its format: {dropped}"
    if counts["not a number"]:
        return (f"{bridge.name}: {counts['not a number']} of its {counts['samples']} samples in {wait:g} s hold "
                f"NaN or inf: no motion to forward")
    if bridge.watch.frozen(bridge.clock(), bridge.watch.last[1]):
        return (f"{bridge.name}: {counts['samples']} packets in {wait:g} s, but its motion never changed: "
                f"the simulation is paused or not yet running")
    return (f"{bridge.name}: no still second in {wait:g} s (rates below 1 deg/s, a steady force): the start "
            f"check reads the stream at rest or in level flight; fly level for a few seconds")

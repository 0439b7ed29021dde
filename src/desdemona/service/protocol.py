"""The service's datagrams, version 2 (``docs/protocol.md``): what a host sends, what the machine gets,
what the machine reports and what an operator commands.

Every datagram is little-endian and begins with the same 20-byte header (:data:`HEADER`): the magic
word ``DSDM`` (0x4D445344 read as a little-endian uint32), the protocol version (uint16), the kind of
message (uint8), the flags (uint8: which trailers follow the message), the sender's sequence number
(uint32) and the sender's time [s] (float64).

Two trailers may follow a message, in this order (``docs/protocol.md``, section 2):

- the **session** block (flag :data:`FLAG_SESSION`): a uint32 the sender draws at random when it starts,
  so that a receiver tells a restarted sender (a new session) from a stale datagram (an old sequence
  number of the same session);
- the **signature** (flag :data:`FLAG_SIGNED`, only with a session): a 48-bit timestamp in 10 us units
  since 2015-01-01 (as MAVLink 2 signs its frames) and the first :data:`TAG_BYTES` bytes of the
  HMAC-SHA256 of everything before the tag under a shared key (:func:`tag`).

- :class:`Motion` (kind 1, host -> service): the vehicle's motion at the pilot's head: the six channels
  of S (wx, wy, wz [rad/s], fx, fy, fz [m/s^2], cabin axes) or, for ``dfs``, the modulus M [m/s^2];
  optionally a forecast block: n samples of the same channels at a fixed step, the first one step
  after the message's time.
- :class:`Setpoint` (kind 2, service -> machine): for every joint of the machine, in the order of
  :data:`desdemona.machine.params.JOINT_NAMES`, the position, rate, acceleration and jerk of the cycle that
  starts at ``cycle_time`` and lasts ``step``; the session's status; the command's source; and the
  sequence number of the host message the command answers.
- :class:`MachineState` (kind 3, machine -> service): every joint's measured position and rate, the
  motion system's own status (:data:`MACHINE_STATUSES`), a fault's code and joint, and the setpoint
  (sequence, and the time on the setpoints' time line) its joints were following when measured.
- :class:`Command` (kind 4, operator -> service or machine): pause, park, resume, emergency stop,
  reset (:data:`ACTIONS`).

Version 1 had only the first two; a datagram of another version is refused with a message that
names both versions (no guessing at a layout). :func:`read` refuses anything else with a
:class:`ProtocolError` that names the problem and carries one of the fixed :data:`REASONS`; a receiver
drops and counts such datagrams by that reason.
"""

from __future__ import annotations

import hashlib
import hmac
import math
import struct
from dataclasses import dataclass

import numpy as np

MAGIC = 0x4D445344  # the bytes b"DSDM"
VERSION = 2
KIND_MOTION, KIND_SETPOINT, KIND_STATE, KIND_COMMAND = 1, 2, 3, 4

#: magic, version, kind, flags, sequence, sender's time
HEADER = struct.Struct("<IHBBId")
#: Flags: a session block follows the message; a signature follows the session block.
FLAG_SESSION, FLAG_SIGNED = 0x01, 0x02
#: The session block: the sender's session identifier (random, drawn when it starts)
SESSION = struct.Struct("<I")
#: Bytes of the HMAC-SHA256 kept in a signature: 128 bits, out of reach of guessing at any rate a
#: network carries (MAVLink keeps 48 to save radio bandwidth; here 10 more bytes cost nothing).
TAG_BYTES = 16
#: The signature: a 48-bit timestamp (10 us units since 2015-01-01 00:00 UTC), then the tag
SIGNATURE_BYTES = 6 + TAG_BYTES
#: The most the trailers add to a message [bytes]
TRAILERS = 4 + SIGNATURE_BYTES
#: The key's length [bytes] (64 hex digits, as ``openssl rand -hex 32`` writes them)
KEY_BYTES = 32
#: channels (6 or 1), forecast samples n, forecast step [s]; then (1 + n) x channels float64
MOTION = struct.Struct("<HHd")
#: status, source, joints (6), a reserved byte, the answered sequence, the cycle's time and step [s];
#: then per joint position, rate, acceleration, jerk (float64)
SETPOINT = struct.Struct("<BBBBIdd")
#: status, fault code, fault joint, joints (6), the applied setpoint's sequence and the time on the
#: setpoints' time line the joints followed [s]; then per joint measured position and rate (float64)
STATE = struct.Struct("<BBBBId")
#: action, then three reserved bytes (0)
COMMAND = struct.Struct("<BBH")
JOINTS = 6
NO_JOINT = 0xFF  # a fault of no particular joint
NO_ANSWER = 0xFFFFFFFF  # a setpoint that answers no host message (starting, parking, parked)

#: The session's status in a setpoint.
STATUSES = ("starting", "running", "parking", "parked", "fault")
#: Where a setpoint's command comes from: this cycle's plan, the previous plan, a braking command when
#: no plan is left, the watchdog's or a stop's parking.
SOURCES = ("plan", "previous plan", "brake", "park")

#: The motion system's own status in a state message: ready (at rest, holding, takes a setpoint that
#: starts where it stands), following the setpoints, braking on its own (no setpoint in time), stopped
#: (at rest after braking on its own), fault (braked; refuses motion until a reset), e-stop (an
#: emergency stop: the fastest stop; refuses motion until a reset).
MACHINE_STATUSES = ("ready", "following", "braking", "stopped", "fault", "e-stop")
#: A fault's code: none, a joint's drive reported a fault, the motion made broke a limit.
FAULTS = ("none", "drive", "limit")
#: An operator's command: pause (hold the present cue until resume), park, resume, emergency stop, reset (the
#: motion system's fault or emergency stop cleared, at rest).
ACTIONS = ("pause", "park", "resume", "emergency stop", "reset")

#: Values beyond these are not a vehicle's motion (as :mod:`desdemona.profiles` refuses files).
MAX_RATE = 50.0  # rad/s
MAX_FORCE = 100.0 * 9.81  # m/s^2
MAX_FORECAST = 10_000
MAX_JOINT_VALUE = 1e6


#: Why a receiver drops a datagram: a fixed, small set (docs/protocol.md, section 7), so that counts
#: keyed by it stay few whatever comes; the offending value goes into a sample, never into the key.
REASONS = {
    "truncated": "shorter than its header, message or trailers",
    "magic": "not this protocol (the magic word)",
    "version": "another version of the protocol",
    "flags": "unknown flags, or a signature without a session",
    "kind": "a kind of message this receiver does not take",
    "length": "a length other than its header and counts give",
    "malformed": "a count, status, code or step out of its range",
    "not finite": "a number that is NaN or infinite",
    "absurd": "a value beyond any vehicle's or machine's motion (wrong units?)",
    "channels": "channels other than the session takes",
    "unsigned": "not signed, and this receiver has a key",
    "signed": "signed, and this receiver has no key",
    "forged": "a signature that does not match (forged or altered)",
    "replayed": "a signature's timestamp not newer than its session's last (replayed)",
    "stale": "a sequence number or time at or below the last taken (out of order or repeated)",
    "sender": "from a sender it does not take this kind from (another address, port or session)",
    "early": "came before the receiver was ready",
    "socket": "a socket error, or a message that could not be sent",
}


class ProtocolError(ValueError):
    """A datagram that is not a valid message of this protocol; the message says what is wrong,
    ``reason`` (one of :data:`REASONS`) why it is dropped."""

    def __init__(self, text: str, reason: str):
        super().__init__(text)
        if reason not in REASONS:
            raise KeyError(f"not a drop reason: {reason!r}")
        self.reason = reason


@dataclass(frozen=True)
class Motion:
    """Host -> service: ``values`` (6,) of S or (1,) of M at ``time`` [s, the host's clock], and an
    optional ``forecast`` (n, channels) at ``forecast_step`` [s] after ``time``."""

    sequence: int
    time: float
    values: np.ndarray
    forecast: np.ndarray | None = None
    forecast_step: float = 0.0

    @property
    def channels(self) -> int:
        return len(self.values)


@dataclass(frozen=True)
class Setpoint:
    """Service -> machine: per joint (6,) ``position``, ``rate``, ``acceleration`` and ``jerk`` of the
    cycle from ``cycle_time`` [s, the service's clock] lasting ``step`` [s]; ``status`` and ``source``
    (:data:`STATUSES`, :data:`SOURCES`); ``answers``: the host sequence it answers, or None."""

    sequence: int
    time: float
    status: str
    source: str
    answers: int | None
    cycle_time: float
    step: float
    position: np.ndarray
    rate: np.ndarray
    acceleration: np.ndarray
    jerk: np.ndarray


@dataclass(frozen=True)
class MachineState:
    """Machine -> service: per joint (6,) measured ``position`` and ``rate`` at ``time`` [s, the
    machine's clock]; ``status`` (:data:`MACHINE_STATUSES`); ``fault`` (:data:`FAULTS`) and
    ``fault_joint`` (0-5, None: none in particular); ``applied``: the sequence of the setpoint its joints
    were following (None: none yet), and ``applied_time`` [s] the time on the setpoints' time line
    (``cycle_time`` + the time into that cycle) they were following when measured."""

    sequence: int
    time: float
    status: str
    fault: str
    fault_joint: int | None
    applied: int | None
    applied_time: float
    position: np.ndarray
    rate: np.ndarray


@dataclass(frozen=True)
class Command:
    """Operator -> service or machine: ``action`` (:data:`ACTIONS`) at ``time`` [s, the sender's clock]."""

    sequence: int
    time: float
    action: str


Message = Motion | Setpoint | MachineState | Command


@dataclass(frozen=True)
class Frame:
    """A datagram read (:func:`read`): its ``message``; the sender's ``session`` identifier (None: no
    session block); a signature's ``timestamp`` [10 us since 2015-01-01] (None: not signed)."""

    message: Message
    session: int | None = None
    timestamp: int | None = None


def tag(key: bytes, signed: bytes) -> bytes:
    """The signature's tag of the bytes ``signed`` (the header, message, session block and timestamp):
    the first :data:`TAG_BYTES` of their HMAC-SHA256 under ``key``."""
    return hmac.new(key, signed, hashlib.sha256).digest()[:TAG_BYTES]


def pack(message: Message, session: int | None = None, key: bytes | None = None, timestamp: int = 0) -> bytes:
    """The datagram of a message (:class:`ProtocolError` where it could not be read back); with a
    ``session`` identifier (uint32) its session block, and with a ``key`` too its signature at
    ``timestamp`` (48 bits, 10 us units since 2015-01-01)."""
    if key is not None and session is None:
        raise ValueError("a signed message carries its sender's session")
    flags = (0 if session is None else FLAG_SESSION) | (0 if key is None else FLAG_SIGNED)
    data = _pack_message(message, flags)
    if session is not None:
        data += SESSION.pack(session & 0xFFFFFFFF)
    if key is not None:
        if not 0 <= timestamp < 1 << 48:
            raise ValueError(f"timestamp {timestamp}: 48 bits")
        data += timestamp.to_bytes(6, "little")
        data += tag(key, data)
    return data


def _pack_message(message: Message, flags: int) -> bytes:
    def header(kind):
        return HEADER.pack(MAGIC, VERSION, kind, flags, message.sequence & 0xFFFFFFFF, float(message.time))

    if isinstance(message, Motion):
        values = np.asarray(message.values, dtype="<f8").ravel()
        forecast = np.zeros((0, len(values))) if message.forecast is None else np.asarray(message.forecast, "<f8")
        _check_motion(len(values), values, forecast, message.forecast_step)
        return (header(KIND_MOTION) + MOTION.pack(len(values), len(forecast), float(message.forecast_step))
                + values.tobytes() + forecast.astype("<f8").tobytes())
    if isinstance(message, Setpoint):
        body = SETPOINT.pack(STATUSES.index(message.status), SOURCES.index(message.source), JOINTS, 0,
                             NO_ANSWER if message.answers is None else message.answers, float(message.cycle_time),
                             float(message.step))
        table = np.column_stack([message.position, message.rate, message.acceleration, message.jerk])
        return header(KIND_SETPOINT) + body + np.asarray(table, dtype="<f8").reshape(JOINTS, 4).tobytes()
    if isinstance(message, MachineState):
        body = STATE.pack(MACHINE_STATUSES.index(message.status), FAULTS.index(message.fault),
                          NO_JOINT if message.fault_joint is None else message.fault_joint, JOINTS,
                          NO_ANSWER if message.applied is None else message.applied, float(message.applied_time))
        table = np.column_stack([message.position, message.rate])
        return header(KIND_STATE) + body + np.asarray(table, dtype="<f8").reshape(JOINTS, 2).tobytes()
    if isinstance(message, Command):
        return header(KIND_COMMAND) + COMMAND.pack(ACTIONS.index(message.action), 0, 0)
    raise TypeError(f"not a message: {type(message).__name__}")


def unpack(data: bytes) -> Message:
    """The message of an unsigned datagram (:func:`read` without a key)."""
    return read(data).message


def read(data: bytes, key: bytes | None = None) -> Frame:
    """The message of a datagram and its trailers; :class:`ProtocolError` naming what is wrong (magic,
    version, flags, kind, length, a value that is not finite or is beyond a vehicle's motion, a
    malformed forecast) and why it is dropped (:data:`REASONS`). With a ``key`` only a datagram signed
    with it is read (its tag checked before its message); without one a signed datagram is refused.
    Whether a signature's timestamp is new is the receiver's to judge (:mod:`desdemona.service.signing`)."""
    if len(data) < HEADER.size:
        raise ProtocolError(f"truncated: {len(data)} bytes, shorter than the {HEADER.size}-byte header", "truncated")
    magic, version, kind, flags, sequence, time = HEADER.unpack_from(data)
    if magic != MAGIC:
        raise ProtocolError(f"wrong magic word 0x{magic:08X}", "magic")
    if version != VERSION:
        raise ProtocolError(f"protocol version {version}: this is version {VERSION} (docs/protocol.md); "
                            f"sender and receiver must run the same version", "version")
    if flags & ~(FLAG_SESSION | FLAG_SIGNED) or flags == FLAG_SIGNED:
        raise ProtocolError(f"flags 0x{flags:02X}: only a session (0x01) and a signature after it (0x02)", "flags")
    trailer = (SESSION.size if flags & FLAG_SESSION else 0) + (SIGNATURE_BYTES if flags & FLAG_SIGNED else 0)
    end = len(data) - trailer
    if end < HEADER.size:
        raise ProtocolError(f"truncated: {len(data)} bytes, too short for the header and its trailers", "truncated")
    timestamp = None
    if key is None and flags & FLAG_SIGNED:
        raise ProtocolError("a signed datagram, and this receiver has no key (--key)", "signed")
    if key is not None:
        if not flags & FLAG_SIGNED:
            raise ProtocolError("an unsigned datagram, and this receiver takes signed ones only (--key)", "unsigned")
        if not hmac.compare_digest(tag(key, data[:-TAG_BYTES]), data[-TAG_BYTES:]):
            raise ProtocolError("a signature that does not match the key: forged or altered", "forged")
        timestamp = int.from_bytes(data[end + SESSION.size:end + SESSION.size + 6], "little")
    session = SESSION.unpack_from(data, end)[0] if flags & FLAG_SESSION else None
    if not math.isfinite(time):
        raise ProtocolError("the sender's time is not a finite number", "not finite")
    body = data[:end]
    if kind == KIND_MOTION:
        message = _unpack_motion(body, sequence, time)
    elif kind == KIND_SETPOINT:
        message = _unpack_setpoint(body, sequence, time)
    elif kind == KIND_STATE:
        message = _unpack_state(body, sequence, time)
    elif kind == KIND_COMMAND:
        message = _unpack_command(body, sequence, time)
    else:
        raise ProtocolError(f"unknown message kind {kind}", "kind")
    return Frame(message, session, timestamp)


def _unpack_motion(data: bytes, sequence: int, time: float) -> Motion:
    if len(data) < HEADER.size + MOTION.size:
        raise ProtocolError(f"truncated motion message: {len(data)} bytes", "truncated")
    channels, n, step = MOTION.unpack_from(data, HEADER.size)
    if channels not in (1, 6):
        raise ProtocolError(f"motion with {channels} channels: 6 (S) or 1 (the modulus M)", "malformed")
    expected = HEADER.size + MOTION.size + 8 * channels * (1 + n)
    if len(data) != expected:
        raise ProtocolError(f"motion message of {len(data)} bytes, {expected} expected for {channels} channels "
                            f"and {n} forecast samples", "length")
    numbers = np.frombuffer(data, dtype="<f8", offset=HEADER.size + MOTION.size).astype(float)
    values, forecast = numbers[:channels], numbers[channels:].reshape(n, channels)
    _check_motion(channels, values, forecast, step)
    return Motion(sequence, time, values, forecast if n else None, step if n else 0.0)


def _check_motion(channels: int, values, forecast, step: float) -> None:
    for what, block in (("values", values[None, :]), ("forecast", forecast)):
        if block.size == 0:
            continue
        if not np.all(np.isfinite(block)):
            raise ProtocolError(f"motion {what} hold NaN or inf", "not finite")
        force = block if channels == 1 else block[:, 3:]
        if np.any(np.abs(force) > MAX_FORCE) or (channels == 6 and np.any(np.abs(block[:, :3]) > MAX_RATE)):
            raise ProtocolError(f"motion {what} beyond a vehicle's motion (|f| up to {MAX_FORCE:g} m/s^2, "
                                f"|omega| up to {MAX_RATE:g} rad/s): wrong units?", "absurd")
        if channels == 1 and np.any(block < 0):
            raise ProtocolError(f"a modulus below zero in the motion {what}", "absurd")
    if len(forecast) > MAX_FORECAST:
        raise ProtocolError(f"a forecast of {len(forecast)} samples, at most {MAX_FORECAST}", "malformed")
    if len(forecast) and not (math.isfinite(step) and step > 0):
        raise ProtocolError(f"forecast step {step!r}: must be a positive number of seconds", "malformed")


def _unpack_setpoint(data: bytes, sequence: int, time: float) -> Setpoint:
    expected = HEADER.size + SETPOINT.size + 8 * 4 * JOINTS
    if len(data) != expected:
        raise ProtocolError(f"setpoint of {len(data)} bytes, {expected} expected", "length")
    status, source, joints, _, answers, cycle_time, step = SETPOINT.unpack_from(data, HEADER.size)
    if joints != JOINTS or status >= len(STATUSES) or source >= len(SOURCES):
        raise ProtocolError(f"setpoint with {joints} joints, status {status}, source {source}", "malformed")
    table = np.frombuffer(data, dtype="<f8", offset=HEADER.size + SETPOINT.size).astype(float).reshape(JOINTS, 4)
    if not (np.all(np.isfinite(table)) and math.isfinite(cycle_time) and math.isfinite(step)):
        raise ProtocolError("setpoint with a value that is not a finite number", "not finite")
    if not step > 0:
        raise ProtocolError(f"setpoint with a step {step!r} that is not positive", "malformed")
    if np.any(np.abs(table) > MAX_JOINT_VALUE):
        raise ProtocolError("setpoint with an absurd joint value", "absurd")
    return Setpoint(sequence, time, STATUSES[status], SOURCES[source], None if answers == NO_ANSWER else answers,
                    cycle_time, step, *table.T)


def _unpack_state(data: bytes, sequence: int, time: float) -> MachineState:
    expected = HEADER.size + STATE.size + 8 * 2 * JOINTS
    if len(data) != expected:
        raise ProtocolError(f"state of {len(data)} bytes, {expected} expected", "length")
    status, fault, joint, joints, applied, applied_time = STATE.unpack_from(data, HEADER.size)
    if (joints != JOINTS or status >= len(MACHINE_STATUSES) or fault >= len(FAULTS)
            or not (joint < JOINTS or joint == NO_JOINT)):
        raise ProtocolError(f"state with {joints} joints, status {status}, fault {fault}, joint {joint}",
                            "malformed")
    table = np.frombuffer(data, dtype="<f8", offset=HEADER.size + STATE.size).astype(float).reshape(JOINTS, 2)
    if not (np.all(np.isfinite(table)) and math.isfinite(applied_time)):
        raise ProtocolError("state with a value that is not a finite number", "not finite")
    if np.any(np.abs(table) > MAX_JOINT_VALUE):
        raise ProtocolError("state with an absurd joint value", "absurd")
    return MachineState(sequence, time, MACHINE_STATUSES[status], FAULTS[fault], None if joint == NO_JOINT else joint,
                        None if applied == NO_ANSWER else applied, applied_time, *table.T)


def _unpack_command(data: bytes, sequence: int, time: float) -> Command:
    expected = HEADER.size + COMMAND.size
    if len(data) != expected:
        raise ProtocolError(f"command of {len(data)} bytes, {expected} expected", "length")
    action, _, _ = COMMAND.unpack_from(data, HEADER.size)
    if action >= len(ACTIONS):
        raise ProtocolError(f"command with action {action}", "malformed")
    return Command(sequence, time, ACTIONS[action])


def address(text: str, option: str = "address") -> tuple[str, int]:
    """(host, port) of ``HOST:PORT`` (IPv4, e.g. ``127.0.0.1:5500``); ValueError naming ``option`` and
    the problem."""
    host, sep, port = text.rpartition(":")
    if not sep or not host or ":" in host or host.startswith("["):
        raise ValueError(f"{option} {text!r}: give an IPv4 HOST:PORT, e.g. 127.0.0.1:5500")
    try:
        number = int(port)
    except ValueError:
        raise ValueError(f"{option} {text!r}: the port must be a number") from None
    if not 0 < number < 65536:
        raise ValueError(f"{option} {text!r}: the port must be between 1 and 65535")
    return host, number

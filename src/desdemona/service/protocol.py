"""The service's datagrams, version 2 (``docs/protocol.md``): what a host sends, what the machine gets,
what the machine reports and what an operator commands.

Every datagram is little-endian and begins with the same 20-byte header (:data:`HEADER`): the magic
word ``DSDM`` (0x4D445344 read as a little-endian uint32), the protocol version (uint16), the kind of
message (uint16), the sender's sequence number (uint32) and the sender's time [s] (float64).

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
names both versions (no guessing at a layout). :func:`unpack` refuses anything else with a :class:`ProtocolError` that names the problem; a
receiver drops and counts such datagrams.
"""

from __future__ import annotations

import math
import struct
from dataclasses import dataclass

import numpy as np

MAGIC = 0x4D445344  # the bytes b"DSDM"
VERSION = 2
KIND_MOTION, KIND_SETPOINT, KIND_STATE, KIND_COMMAND = 1, 2, 3, 4

#: magic, version, kind, sequence, sender's time
HEADER = struct.Struct("<IHHId")
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
#: An operator's command: pause (park and hold until resume), park, resume, emergency stop, reset (the
#: motion system's fault or emergency stop cleared, at rest).
ACTIONS = ("pause", "park", "resume", "emergency stop", "reset")

#: Values beyond these are not a vehicle's motion (as :mod:`desdemona.profiles` refuses files).
MAX_RATE = 50.0  # rad/s
MAX_FORCE = 100.0 * 9.81  # m/s^2
MAX_FORECAST = 10_000
MAX_JOINT_VALUE = 1e6


class ProtocolError(ValueError):
    """A datagram that is not a valid message of this protocol; the message says what is wrong."""


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


def pack(message: Message) -> bytes:
    """The datagram of a message (:class:`ProtocolError` where it could not be read back)."""
    if isinstance(message, Motion):
        values = np.asarray(message.values, dtype="<f8").ravel()
        forecast = np.zeros((0, len(values))) if message.forecast is None else np.asarray(message.forecast, "<f8")
        _check_motion(len(values), values, forecast, message.forecast_step)
        head = HEADER.pack(MAGIC, VERSION, KIND_MOTION, message.sequence & 0xFFFFFFFF, float(message.time))
        return (head + MOTION.pack(len(values), len(forecast), float(message.forecast_step)) + values.tobytes()
                + forecast.astype("<f8").tobytes())
    if isinstance(message, Setpoint):
        head = HEADER.pack(MAGIC, VERSION, KIND_SETPOINT, message.sequence & 0xFFFFFFFF, float(message.time))
        body = SETPOINT.pack(STATUSES.index(message.status), SOURCES.index(message.source), JOINTS, 0,
                             NO_ANSWER if message.answers is None else message.answers, float(message.cycle_time),
                             float(message.step))
        table = np.column_stack([message.position, message.rate, message.acceleration, message.jerk])
        return head + body + np.asarray(table, dtype="<f8").reshape(JOINTS, 4).tobytes()
    if isinstance(message, MachineState):
        head = HEADER.pack(MAGIC, VERSION, KIND_STATE, message.sequence & 0xFFFFFFFF, float(message.time))
        body = STATE.pack(MACHINE_STATUSES.index(message.status), FAULTS.index(message.fault),
                          NO_JOINT if message.fault_joint is None else message.fault_joint, JOINTS,
                          NO_ANSWER if message.applied is None else message.applied, float(message.applied_time))
        table = np.column_stack([message.position, message.rate])
        return head + body + np.asarray(table, dtype="<f8").reshape(JOINTS, 2).tobytes()
    if isinstance(message, Command):
        head = HEADER.pack(MAGIC, VERSION, KIND_COMMAND, message.sequence & 0xFFFFFFFF, float(message.time))
        return head + COMMAND.pack(ACTIONS.index(message.action), 0, 0)
    raise TypeError(f"not a message: {type(message).__name__}")


def unpack(data: bytes) -> Message:
    """The message of a datagram; :class:`ProtocolError` naming what is wrong (magic, version, kind,
    length, a value that is not finite or is beyond a vehicle's motion, a malformed forecast)."""
    if len(data) < HEADER.size:
        raise ProtocolError(f"truncated: {len(data)} bytes, shorter than the {HEADER.size}-byte header")
    magic, version, kind, sequence, time = HEADER.unpack_from(data)
    if magic != MAGIC:
        raise ProtocolError(f"wrong magic word 0x{magic:08X}")
    if version != VERSION:
        raise ProtocolError(f"protocol version {version}: this is version {VERSION} (docs/protocol.md); "
                            f"sender and receiver must run the same version")
    if not math.isfinite(time):
        raise ProtocolError("the sender's time is not a finite number")
    if kind == KIND_MOTION:
        return _unpack_motion(data, sequence, time)
    if kind == KIND_SETPOINT:
        return _unpack_setpoint(data, sequence, time)
    if kind == KIND_STATE:
        return _unpack_state(data, sequence, time)
    if kind == KIND_COMMAND:
        return _unpack_command(data, sequence, time)
    raise ProtocolError(f"unknown message kind {kind}")


def _unpack_motion(data: bytes, sequence: int, time: float) -> Motion:
    if len(data) < HEADER.size + MOTION.size:
        raise ProtocolError(f"truncated motion message: {len(data)} bytes")
    channels, n, step = MOTION.unpack_from(data, HEADER.size)
    if channels not in (1, 6):
        raise ProtocolError(f"motion with {channels} channels: 6 (S) or 1 (the modulus M)")
    expected = HEADER.size + MOTION.size + 8 * channels * (1 + n)
    if len(data) != expected:
        raise ProtocolError(f"motion message of {len(data)} bytes, {expected} expected for {channels} channels "
                            f"and {n} forecast samples")
    numbers = np.frombuffer(data, dtype="<f8", offset=HEADER.size + MOTION.size).astype(float)
    values, forecast = numbers[:channels], numbers[channels:].reshape(n, channels)
    _check_motion(channels, values, forecast, step)
    return Motion(sequence, time, values, forecast if n else None, step if n else 0.0)


def _check_motion(channels: int, values, forecast, step: float) -> None:
    for what, block in (("values", values[None, :]), ("forecast", forecast)):
        if block.size == 0:
            continue
        if not np.all(np.isfinite(block)):
            raise ProtocolError(f"motion {what} hold NaN or inf")
        force = block if channels == 1 else block[:, 3:]
        if np.any(np.abs(force) > MAX_FORCE) or (channels == 6 and np.any(np.abs(block[:, :3]) > MAX_RATE)):
            raise ProtocolError(f"motion {what} beyond a vehicle's motion (|f| up to {MAX_FORCE:g} m/s^2, "
                                f"|omega| up to {MAX_RATE:g} rad/s): wrong units?")
        if channels == 1 and np.any(block < 0):
            raise ProtocolError(f"a modulus below zero in the motion {what}")
    if len(forecast) > MAX_FORECAST:
        raise ProtocolError(f"a forecast of {len(forecast)} samples, at most {MAX_FORECAST}")
    if len(forecast) and not (math.isfinite(step) and step > 0):
        raise ProtocolError(f"forecast step {step!r}: must be a positive number of seconds")


def _unpack_setpoint(data: bytes, sequence: int, time: float) -> Setpoint:
    expected = HEADER.size + SETPOINT.size + 8 * 4 * JOINTS
    if len(data) != expected:
        raise ProtocolError(f"setpoint of {len(data)} bytes, {expected} expected")
    status, source, joints, _, answers, cycle_time, step = SETPOINT.unpack_from(data, HEADER.size)
    if joints != JOINTS or status >= len(STATUSES) or source >= len(SOURCES):
        raise ProtocolError(f"setpoint with {joints} joints, status {status}, source {source}")
    table = np.frombuffer(data, dtype="<f8", offset=HEADER.size + SETPOINT.size).astype(float).reshape(JOINTS, 4)
    if not (np.all(np.isfinite(table)) and math.isfinite(cycle_time) and math.isfinite(step) and step > 0):
        raise ProtocolError("setpoint with a value that is not a finite number, or a step that is not positive")
    if np.any(np.abs(table) > MAX_JOINT_VALUE):
        raise ProtocolError("setpoint with an absurd joint value")
    return Setpoint(sequence, time, STATUSES[status], SOURCES[source], None if answers == NO_ANSWER else answers,
                    cycle_time, step, *table.T)


def _unpack_state(data: bytes, sequence: int, time: float) -> MachineState:
    expected = HEADER.size + STATE.size + 8 * 2 * JOINTS
    if len(data) != expected:
        raise ProtocolError(f"state of {len(data)} bytes, {expected} expected")
    status, fault, joint, joints, applied, applied_time = STATE.unpack_from(data, HEADER.size)
    if (joints != JOINTS or status >= len(MACHINE_STATUSES) or fault >= len(FAULTS)
            or not (joint < JOINTS or joint == NO_JOINT)):
        raise ProtocolError(f"state with {joints} joints, status {status}, fault {fault}, joint {joint}")
    table = np.frombuffer(data, dtype="<f8", offset=HEADER.size + STATE.size).astype(float).reshape(JOINTS, 2)
    if not (np.all(np.isfinite(table)) and math.isfinite(applied_time)):
        raise ProtocolError("state with a value that is not a finite number")
    if np.any(np.abs(table) > MAX_JOINT_VALUE):
        raise ProtocolError("state with an absurd joint value")
    return MachineState(sequence, time, MACHINE_STATUSES[status], FAULTS[fault], None if joint == NO_JOINT else joint,
                        None if applied == NO_ANSWER else applied, applied_time, *table.T)


def _unpack_command(data: bytes, sequence: int, time: float) -> Command:
    expected = HEADER.size + COMMAND.size
    if len(data) != expected:
        raise ProtocolError(f"command of {len(data)} bytes, {expected} expected")
    action, _, _ = COMMAND.unpack_from(data, HEADER.size)
    if action >= len(ACTIONS):
        raise ProtocolError(f"command with action {action}")
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

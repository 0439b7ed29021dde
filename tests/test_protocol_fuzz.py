"""Fuzzing the protocol's readers (hypothesis): random and mutated datagrams of every kind (lengths,
counts, NaN and infinities, huge values, wrong versions, magics, kinds and flags, signatures made
with the wrong key or altered) never raise anything but a :class:`ProtocolError` carrying one of the
fixed reasons out of :func:`protocol.read`, and never anything at all out of the service's inbox:
each datagram is either taken as a valid message or dropped and counted by one of those reasons.
Derandomized (the same examples every run), about 10,000 of them in all."""

import math
import socket
import struct

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from desdemona.service import protocol, signing
from desdemona.service.inbox import Inbox

KEY, WRONG = bytes(range(32)), bytes(range(1, 33))
NOW = 1.8e9  # [s, Unix time] the signatures' clock


def fuzz(examples: int):
    """Derandomized (the same examples every run, nothing stored), no deadline: a loaded CI runner."""
    return settings(derandomize=True, database=None, deadline=None, max_examples=examples,
                    suppress_health_check=list(HealthCheck))

#: Numbers a sender might put anywhere: ordinary, at and beyond the limits, not finite, subnormal.
numbers = st.one_of(st.floats(-20.0, 20.0), st.sampled_from([0.0, -0.0, 9.81, 49.9, 50.1, 980.0, 982.0, 1e6, 1.1e6,
                                                             -1e300, 5e-324, math.nan, math.inf, -math.inf]),
                    st.floats(allow_nan=True, allow_infinity=True))


@st.composite
def messages(draw):
    kind = draw(st.sampled_from(["motion", "setpoint", "state", "command"]))
    sequence, time = draw(st.integers(0, 0xFFFFFFFF)), draw(st.floats(-1e3, 1e3))
    if kind == "motion":
        channels, n = draw(st.sampled_from([1, 6])), draw(st.integers(0, 3))
        values = np.array(draw(st.lists(st.floats(0.0, 20.0), min_size=channels, max_size=channels)))
        forecast = np.full((n, channels), 9.81) if n else None
        return protocol.Motion(sequence, time, values, forecast, 0.01 if n else 0.0)
    six = np.array(draw(st.lists(st.floats(-10.0, 10.0), min_size=6, max_size=6)))
    if kind == "setpoint":
        return protocol.Setpoint(sequence, time, draw(st.sampled_from(protocol.STATUSES)),
                                 draw(st.sampled_from(protocol.SOURCES)), draw(st.none() | st.integers(0, 1000)),
                                 time, 0.02, six, six, six, six)
    if kind == "state":
        return protocol.MachineState(sequence, time, draw(st.sampled_from(protocol.MACHINE_STATUSES)),
                                     draw(st.sampled_from(protocol.FAULTS)), draw(st.none() | st.integers(0, 5)),
                                     draw(st.none() | st.integers(0, 1000)), time, six, six)
    return protocol.Command(sequence, time, draw(st.sampled_from(protocol.ACTIONS)))


@st.composite
def framed(draw):
    """A valid datagram: unsigned, with a session, or signed with the key or the wrong one."""
    message = draw(messages())
    how = draw(st.sampled_from(["plain", "session", "signed", "wrong key"]))
    session = None if how == "plain" else draw(st.integers(0, 0xFFFFFFFF))
    key = {"signed": KEY, "wrong key": WRONG}.get(how)
    return protocol.pack(message, session, key, draw(st.integers(0, (1 << 48) - 1)) if key else 0)


#: Header fields and counts worth setting to odd values: (offset, struct format)
FIELDS = [(0, "<I"), (4, "<H"), (6, "<B"), (7, "<B"), (8, "<I"), (12, "<d"), (20, "<H"), (22, "<H"), (24, "<d"),
          (20, "<B"), (21, "<B"), (22, "<B"), (23, "<B"), (24, "<I"), (28, "<d"), (32, "<d"), (36, "<d"), (44, "<d")]


@st.composite
def mutated(draw):
    """A valid datagram changed: bytes flipped, cut or added, a field or number set to an odd value."""
    data = bytearray(draw(framed()))
    for _ in range(draw(st.integers(1, 3))):
        what = draw(st.sampled_from(["flip", "cut", "add", "field", "number"]))
        if what == "flip" and data:
            data[draw(st.integers(0, len(data) - 1))] ^= 1 << draw(st.integers(0, 7))
        elif what == "cut":
            del data[draw(st.integers(0, len(data))):]
        elif what == "add":
            data += draw(st.binary(min_size=1, max_size=40))
        elif what == "field":
            offset, fmt = draw(st.sampled_from(FIELDS))
            if offset + struct.calcsize(fmt) <= len(data):
                value = draw(numbers) if fmt == "<d" else draw(st.integers(0, (1 << (8 * struct.calcsize(fmt))) - 1))
                struct.pack_into(fmt, data, offset, value)
        elif len(data) >= 28:  # a float64 anywhere in the message, aligned as its numbers are
            offset = 20 + 4 * draw(st.integers(0, (len(data) - 28) // 4))
            struct.pack_into("<d", data, offset, draw(numbers))
    return bytes(data)


datagrams = st.one_of(framed(), mutated(), mutated(), st.binary(max_size=300))


def _read(data: bytes, key):
    """The frame, or the reason it is refused: anything but a ProtocolError fails the test."""
    try:
        return protocol.read(data, key)
    except protocol.ProtocolError as exc:
        assert exc.reason in protocol.REASONS
        return exc.reason


@fuzz(5000)
@given(datagrams)
def test_reading_any_datagram_gives_a_valid_message_or_a_fixed_reason(data):
    for key in (None, KEY):
        frame = _read(data, key)
        if isinstance(frame, protocol.Frame):  # taken: a message that packs back to itself
            message = frame.message
            again = protocol.read(protocol.pack(message, frame.session, key, frame.timestamp or 0), key).message
            assert type(again) is type(message) and again.sequence == message.sequence
            for name in message.__dataclass_fields__:
                value = getattr(message, name)
                if isinstance(value, np.ndarray):
                    assert np.all(np.isfinite(value)) and np.array_equal(value, getattr(again, name))


@fuzz(3500)
@given(messages(), st.integers(0, 0xFFFFFFFF), st.integers(0, (1 << 48) - 1), st.integers(0, 10**6),
       st.integers(0, 7), st.integers(0, 3))
def test_a_signed_datagram_changed_anywhere_is_never_taken(message, session, stamp, where, bit, cut):
    data = protocol.pack(message, session, KEY, stamp)
    frame = protocol.read(data, KEY)
    assert (frame.session, frame.timestamp) == (session, stamp)
    changed = bytearray(data)
    changed[where % len(data)] ^= 1 << bit
    for altered in (bytes(changed), data[:len(data) - cut - 1], data + bytes(cut + 1)):
        assert _read(altered, KEY) in protocol.REASONS  # a reason, never a message


@pytest.fixture(scope="module")
def sock():
    with socket.socket(socket.AF_INET, socket.SOCK_DGRAM) as s:
        s.bind(("127.0.0.1", 0))
        yield s


@fuzz(1500)
@given(st.lists(st.tuples(datagrams, st.sampled_from([("127.0.0.1", 40001), ("127.0.0.1", 40002),
                                                      ("10.0.0.9", 40001)])), min_size=1, max_size=8),
       st.booleans(), st.sampled_from([1, 6]))
def test_the_inbox_takes_or_drops_every_datagram_and_raises_nothing(sock, stream, keyed, channels):
    inbox = Inbox(sock, channels, clock=lambda: 0.0, lost_after=0.1, key=KEY if keyed else None)
    inbox.incoming.clock = lambda: NOW
    for k, (data, sender) in enumerate(stream):
        inbox.take(data, 0.03 * k, sender)
    taken = len(inbox.t) + len(inbox.commands)
    assert taken + sum(inbox.dropped.values()) == len(stream)
    assert set(inbox.dropped) <= set(protocol.REASONS)
    assert all(np.all(np.isfinite(v)) and len(v) == channels for v in inbox.values)
    assert np.all(np.diff(inbox.t) > 0)

"""docs/protocol.md is the whole contract: every worked example's bytes, as the document prints them,
are what :func:`desdemona.service.protocol.pack` makes of the message its text describes, and read back
to that message; State and Command datagrams that are not valid are refused, naming why."""

import re
import struct
from pathlib import Path

import numpy as np
import pytest

from desdemona.service import protocol

DOCUMENT = Path(__file__).resolve().parents[1] / "docs" / "protocol.md"

#: The messages section 10 describes, in its order.
EXAMPLES = [
    protocol.Motion(7, 1.25, np.array([0, 0, 0.1, 0.5, -2.0, 9.81])),
    protocol.Motion(8, 1.26, np.array([9.81]), np.array([[9.9], [10.0]]), 0.01),
    protocol.Setpoint(42, 0.8412, "running", "plan", 83, 0.82, 0.02, np.array([1.0, -4.0, 0, 0.02, 0, -0.01]),
                      np.array([0.5, 0, 0, 0.1, 0, 0]), np.array([0.25, 0, 0, 0, 0, 0]),
                      np.array([-1.0, 0, 0, 0, 0, 0])),
    protocol.MachineState(100, 2.0, "following", "none", None, 42, 0.83, np.array([1.0049, -4.0, 0, 0.021, 0, -0.01]),
                          np.array([0.5025, 0, 0, 0.1, 0, 0])),
    protocol.MachineState(101, 2.01, "fault", "drive", 3, 42, 0.84, np.array([1.0099, -4.0, 0, 0.022, 0, -0.01]),
                          np.array([0.5, 0, 0, 0.1, 0, 0])),
    protocol.Command(5, 12.5, "emergency stop"),
    protocol.Command(5, 12.5, "emergency stop"),
]
#: How each example is framed: (session, key, timestamp); the last one signed as the document says.
FRAMING = [(None, None, 0)] * 6 + [(0x12345678, bytes(range(32)), 37_657_440_000_000)]


def document_examples() -> list[bytes]:
    """The bytes of every hex block of the worked examples' section, in order."""
    text = DOCUMENT.read_text()
    section = text[text.index("## 10. Worked examples"):text.index("## 11.")]
    blocks = re.findall(r"```\n((?:[0-9a-f]{4}  [0-9a-f ]+\n)+)```", section)
    out = []
    for block in blocks:
        data = bytearray()
        for offset, line in enumerate(block.strip().splitlines()):
            address, _, hexes = line.partition("  ")
            assert int(address, 16) == 16 * offset, line
            data += bytes.fromhex(hexes)
        out.append(bytes(data))
    return out


def same(a, b) -> bool:
    if type(a) is not type(b):
        return False
    for name in a.__dataclass_fields__:
        x, y = getattr(a, name), getattr(b, name)
        if isinstance(x, np.ndarray) or isinstance(y, np.ndarray):
            if x is None or y is None or not np.array_equal(np.asarray(x, float), np.asarray(y, float)):
                return False
        elif x != y:
            return False
    return True


def test_every_example_of_the_document_is_what_pack_makes():
    found = document_examples()
    assert len(found) == len(EXAMPLES)
    for message, (session, key, stamp), data in zip(EXAMPLES, FRAMING, found):
        assert protocol.pack(message, session, key, stamp) == data, type(message).__name__
        frame = protocol.read(data, key)
        assert same(frame.message, message) and frame.session == session and (frame.timestamp or 0) == stamp


def test_the_signed_example_s_timestamp_is_the_time_the_document_gives():
    import calendar

    from desdemona.service import signing

    assert signing.timestamp(calendar.timegm((2026, 12, 7, 12, 0, 0))) == FRAMING[-1][2]


def test_the_document_lists_the_drop_reasons_the_code_has():
    text = DOCUMENT.read_text()
    table = text[text.index("### Drop reasons"):text.index("## 8.")]
    assert re.findall(r"^\| `([a-z ]+)` \|", table, re.M) == list(protocol.REASONS)


def test_the_document_states_the_lengths_the_code_makes():
    text = DOCUMENT.read_text()
    for kind, size in (("Setpoint", 236), ("State", 132), ("Command", 24)):
        assert f"Length: **{size} bytes**" in text, kind
    assert protocol.HEADER.size + protocol.STATE.size + 96 == 132
    assert protocol.HEADER.size + protocol.COMMAND.size == 24
    assert f"| 4      | 2    | uint16  | version  | `{protocol.VERSION}` |" in text


STATE = EXAMPLES[3]


def _with(data: bytes, offset: int, fmt: str, value) -> bytes:
    out = bytearray(data)
    struct.pack_into(fmt, out, offset, value)
    return bytes(out)


@pytest.mark.parametrize("data, words", [
    (protocol.pack(STATE)[:-1], "state of 131 bytes"),
    (protocol.pack(STATE) + b"\0", "state of 133 bytes"),
    (_with(protocol.pack(STATE), 36, "<d", float("nan")), "not a finite number"),
    (_with(protocol.pack(STATE), 28, "<d", float("inf")), "not a finite number"),
    (_with(protocol.pack(STATE), 44, "<d", 1e9), "absurd"),
    (_with(protocol.pack(STATE), 20, "<B", 6), "status 6"),
    (_with(protocol.pack(STATE), 21, "<B", 3), "fault 3"),
    (_with(protocol.pack(STATE), 22, "<B", 6), "joint 6"),
    (_with(protocol.pack(STATE), 4, "<H", 1), "protocol version 1: this is version 2"),
    (_with(protocol.pack(EXAMPLES[5]), 20, "<B", 5), "action 5"),
    (protocol.pack(EXAMPLES[5])[:22], "command of 22 bytes"),
    (_with(protocol.pack(EXAMPLES[5]), 12, "<d", float("nan")), "time is not a finite"),
], ids=["short", "long", "nan-position", "inf-time", "absurd", "status", "fault", "joint", "version-1",
        "action", "short-command", "nan-command"])
def test_bad_state_and_command_datagrams_are_refused(data, words):
    with pytest.raises(protocol.ProtocolError, match=re.escape(words)):
        protocol.unpack(data)

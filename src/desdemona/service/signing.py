"""Who may speak to the machine: the shared key, the session and signature a sender puts on each of
its datagrams, and a receiver's judgement of them (``docs/protocol.md``, sections 2 and 7).

- A **key** (:func:`load_key`) is 32 bytes written as 64 hex digits in a file only its owner may read,
  as ``openssl rand -hex 32 > FILE; chmod 600 FILE`` makes it.
- A sender (:class:`Outgoing`) draws a random **session** identifier when it starts and puts it on
  every datagram, so a receiver knows a restarted sender by its header rather than by a sequence
  number that went back; with a key it **signs** each datagram: a timestamp (10 us units since
  2015-01-01, strictly increasing) and the HMAC-SHA256 tag of everything before it (as MAVLink 2's
  message signing, with an HMAC and 16 bytes of tag).
- A receiver (:class:`Incoming`) with a key reads signed datagrams only, checks the tag, and keeps
  the newest timestamp of each session: one at or below it is replayed; a session it has not seen
  must be no older than :data:`REPLAY_WINDOW` behind its clock or the newest it has seen (an old
  recording played to a receiver started since).
"""

from __future__ import annotations

import os
import secrets
import stat
import time
from pathlib import Path

from desdemona.service import protocol

#: 2015-01-01 00:00:00 UTC, the origin of the signatures' timestamps [s since 1970, Unix time]
EPOCH = 1_420_070_400
#: The timestamp's unit [s]
TICK = 1e-5
#: A session first seen with a timestamp more than this behind the receiver's newest is replayed [s]
REPLAY_WINDOW = 60.0


def load_key(path: str | Path) -> bytes:
    """The 32 bytes of a key file (64 hex digits, blanks around them ignored); :class:`ValueError`
    naming the file where it is missing, malformed, or readable or writable by others than its owner."""
    path = Path(path)
    try:
        mode = path.stat().st_mode
        text = path.read_text(encoding="ascii", errors="replace").strip()
    except OSError as exc:
        raise ValueError(f"--key {path}: {exc.strerror or exc}") from None
    if os.name == "posix" and mode & (stat.S_IRWXG | stat.S_IRWXO):
        raise ValueError(f"--key {path}: others than its owner may read or change it (mode {stat.S_IMODE(mode):03o}): "
                         f"chmod 600 {path}")
    try:
        key = bytes.fromhex(text)
    except ValueError:
        key = b""
    if len(text) != 2 * protocol.KEY_BYTES or len(key) != protocol.KEY_BYTES:
        raise ValueError(f"--key {path}: not a key: give {2 * protocol.KEY_BYTES} hex digits, as "
                         f"'openssl rand -hex 32 > {path}' writes them")
    return key


def timestamp(unix_time: float) -> int:
    """A signature's timestamp of ``unix_time`` [s since 1970]: 10 us units since 2015-01-01."""
    return max(int((unix_time - EPOCH) / TICK), 0)


class Outgoing:
    """What a sender puts on its datagrams: its ``session`` (random, drawn here) and, with a ``key``,
    a signature whose timestamp comes from ``clock`` [s, Unix time] and always increases."""

    def __init__(self, key: bytes | None = None, session: int | None = None, clock=time.time):
        self.key, self.clock = key, clock
        self.session = secrets.randbits(32) if session is None else session
        self.last = -1

    def pack(self, message: protocol.Message) -> bytes:
        if self.key is None:
            return protocol.pack(message, self.session)
        self.last = max(timestamp(self.clock()), self.last + 1)
        return protocol.pack(message, self.session, self.key, self.last)


class Incoming:
    """A receiver's reading of datagrams: with a ``key`` only signed ones, each newer than the last
    of its session (``clock`` [s, Unix time] for a session not seen before)."""

    def __init__(self, key: bytes | None = None, clock=time.time):
        self.key, self.clock = key, clock
        self.newest: dict[int, int] = {}  # session -> its newest timestamp taken
        self.latest = 0  # the newest timestamp taken of any session

    def read(self, data: bytes) -> protocol.Frame:
        """The frame of a datagram (:func:`protocol.read`); :class:`protocol.ProtocolError` with its
        reason where it is not valid, not signed with the key, or replayed."""
        frame = protocol.read(data, self.key)
        if self.key is None:
            return frame
        stamp, session = frame.timestamp, frame.session
        last = self.newest.get(session)
        if last is not None and stamp <= last:
            raise protocol.ProtocolError(f"timestamp {stamp} at or below its session's last {last}", "replayed")
        if last is None:
            floor = max(self.latest, timestamp(self.clock())) - int(REPLAY_WINDOW / TICK)
            if stamp < floor:
                raise protocol.ProtocolError(f"a new session's timestamp {stamp} more than {REPLAY_WINDOW:g} s old",
                                             "replayed")
        self.newest[session] = stamp
        self.latest = max(self.latest, stamp)
        return frame

"""What comes to the service (``desdemona serve``): the host's Motion, the operator's Commands and the
machine's States, read without blocking, checked, and dropped by one of the protocol's fixed reasons
(:class:`~desdemona.service.drops.Drops`) where they are not to be taken.

**Who may move the machine.** With a key (:mod:`desdemona.service.signing`) only datagrams signed with
it are read, each newer than the last of its session. Whatever the key, motion is taken from one host
at a time, the **host**: the sender (address, port and session) of the first valid Motion. Another
sender's Motion is dropped while the host is alive (a valid message within ``lost_after`` seconds);
once the host is lost, the next valid Motion from anyone makes its sender the host. A host that
restarts says so by a new session in its header (``docs/protocol.md``, section 2): from the host's
address and port (or, with a key, from anywhere: the signature vouches for it) it is taken at once,
its sequence counted afresh and its times continuing from where the old session left off. A sequence
number or time at or below the last taken of the same session is stale, however long the host was
silent: a restart is never guessed from a number going back.
"""

from __future__ import annotations

import selectors
import socket

import numpy as np

from desdemona.service import pacing, protocol
from desdemona.service.drops import Drops
from desdemona.service.signing import Incoming, Outgoing
from desdemona.service.spill import Spilled

#: Replaced sessions remembered (their late datagrams are never taken as a restart)
RETIRED = 64
#: The least time [s] between the last message of one session and the first of the next, on the
#: session's clock (two datagrams read at the same clock reading stay in order)
GAP = 1e-6


class Inbox:
    """The host's datagrams on ``sock``: checked, the newest valid Motion kept (``newest``, arrived
    at ``arrived`` on ``clock``), the motion received so far (``t`` on the host's clock continued
    across restarts, ``values``, ``arrivals``) for the predictor and the log. ``lost_after`` [s]
    without a valid Motion and the host is lost; ``on_drop(line)`` is told of drops, at most once a
    second per reason; ``machine`` = (the sending socket, its
    :class:`~desdemona.service.measured.MachineLink`): the States that come back to it; Commands are
    taken from the host ``operator`` only; ``early``: datagrams dropped before the session began;
    ``key``: the shared key (None: unsigned datagrams only), which :attr:`outgoing` signs the
    service's own datagrams with; ``record``: the folder of the motion's older blocks
    (:class:`~desdemona.service.spill.Spilled`; None: the system's temporary folder)."""

    def __init__(self, sock: socket.socket, channels: int, clock, lost_after: float = np.inf, on_drop=None,
                 machine=None, operator: str = "127.0.0.1", early: int = 0, key: bytes | None = None, record=None):
        self.sock, self.channels, self.clock = pacing.stamped(sock), channels, clock
        self.lost_after = lost_after
        self.drops = Drops(on_drop, clock)
        if early:
            self.drops.counts["early"] = early
        self.incoming = Incoming(key)
        self.outgoing = Outgoing(key)  # the service's own datagrams: its session, signed with the same key
        self.shift = 0.0  # added to a returning host's times
        self.selector = selectors.DefaultSelector()
        self.selector.register(sock, selectors.EVENT_READ)
        self.machine, self.operator = machine, operator
        if machine is not None:
            machine[0].setblocking(False)
            self.selector.register(machine[0], selectors.EVENT_READ)
        self.commands: list[tuple[float, str]] = []  # (arrived, action) not yet acted on
        self.last_command: dict = {}  # (address, port, session) -> its last sequence
        self.host = None  # (address, port, session) of the host
        self.stamp = None  # the signature's timestamp of the host's newest message (with a key)
        self.retired: dict = {}  # the hosts' sessions replaced by newer ones (the newest RETIRED)
        self.newest: protocol.Motion | None = None
        self.arrived = None  # clock time the newest message arrived
        self.fresh = False  # a message came since the last cycle took one
        # every message's, at flat memory: the older ones in a temporary file in the folder ``record``
        self.t, self.values, self.arrivals = (Spilled(directory=record) for _ in range(3))

    @property
    def dropped(self):
        """reason -> datagrams dropped."""
        return self.drops.counts

    def wait(self, until: float, opens: float) -> None:
        """Read what comes until the cycle whose window is [``opens``, ``until``] (clock) starts
        (:func:`~desdemona.service.pacing.begins`): as the window opens, or as a new message comes in
        it, or as it closes."""
        while True:
            self.drain()
            now = self.clock()
            begins = min(pacing.begins(self.arrivals, self.fresh, opens, until), until)
            if now >= begins:
                return
            self.selector.select(begins - now)

    def drain(self) -> None:
        if self.machine is not None:
            sock, link = self.machine
            for data, sender, _ in _datagrams(sock, self.drops):
                link.take(data, sender, self.clock())
        for data, sender, age in _datagrams(self.sock, self.drops):  # timed from the kernel's receive
            self.take(data, self.clock() - age, sender)

    def take(self, data: bytes, arrived: float, sender=("", 0)) -> None:
        """One datagram from ``sender`` = (address, port), arrived at ``arrived`` (clock)."""
        try:
            frame = self.incoming.read(data)
        except protocol.ProtocolError as exc:
            return self.drops.error(exc)
        message, who = frame.message, (*sender[:2], frame.session)
        if isinstance(message, protocol.Command):
            return self._command(message, who, arrived)
        if not isinstance(message, protocol.Motion):
            return self.drops("kind", f"a {type(message).__name__} from {sender[0]}:{sender[1]}")
        if message.channels != self.channels:
            return self.drops("channels", f"{message.channels} channels, the session takes {self.channels} "
                                          f"(--channels)")
        if who != self.host:
            why = self._other(who, frame.timestamp, arrived)
            if why:
                return self.drops(*why)
            if self.newest is not None:  # a new host, or the host restarted: its times continue the old
                self.shift = self.t[-1] + max(arrived - self.arrived, GAP) - message.time
                self.retired[self.host] = None
                while len(self.retired) > RETIRED:
                    del self.retired[next(iter(self.retired))]
            self.host, self.newest = who, None
        elif message.sequence <= self.newest.sequence or message.time + self.shift <= self.t[-1]:
            return self.drops("stale", f"sequence {message.sequence} after {self.newest.sequence}, time "
                                       f"{message.time!r}")
        self.newest, self.arrived, self.fresh, self.stamp = message, arrived, True, frame.timestamp
        self.t.append(message.time + self.shift)
        self.values.append(message.values)
        self.arrivals.append(arrived)

    def _other(self, who, stamp: int | None, arrived: float) -> tuple[str, str] | None:
        """Why a Motion of ``who`` (address, port, session), not the host, is not taken as the host's
        restart or as the new host (None: it is). A session once replaced is never taken again."""
        if who in self.retired:
            return "sender", f"session {who[2]} of {who[0]}:{who[1]} was replaced by a newer one"
        if self.host is None or arrived - self.arrived > self.lost_after:
            return None
        signed = self.incoming.key is not None
        if (signed and stamp > self.stamp) or (not signed and who[:2] == self.host[:2]):
            return None  # the host restarted: a new session, vouched for by the key or from its port
        return "sender", (f"motion from {who[0]}:{who[1]} (session {who[2]}) while the host {self.host[0]}:"
                          f"{self.host[1]} is alive")

    def _command(self, message: protocol.Command, who, arrived: float) -> None:
        if who[0] != self.operator:
            return self.drops("sender", f"a command from {who[0]}, the operator is {self.operator} (--operator)")
        if message.sequence <= self.last_command.get(who, -1):
            return self.drops("stale", f"command sequence {message.sequence}")
        self.last_command[who] = message.sequence
        self.commands.append((arrived, message.action))

    def recent(self, seconds: float) -> tuple[np.ndarray, np.ndarray]:
        """(t, values) of the motion of the last ``seconds`` (host time), at most what is in memory (the
        last :data:`~desdemona.service.spill.BLOCK` messages or more)."""
        start = self.t.after(self.t[-1] - seconds)  # the times increase: 0.1 ms less a cycle than a scan
        return np.asarray(self.t[start:]), np.asarray(self.values[start:])


def _datagrams(sock: socket.socket, drops: Drops):
    """The datagrams waiting on a non-blocking ``sock``: (data, sender, age [s] since received) each."""
    return pacing.datagrams(sock, lambda exc: drops("socket", str(exc)))

"""``desdemona host xplane``: X-Plane's datarefs subscribed over UDP (RREF), checked Motion messages to
``serve`` out (:mod:`.bridge`).

The bridge asks X-Plane (10.40 and later, 11, 12) for the datarefs it needs, by name, at a rate: an
``RREF`` request per dataref to X-Plane's port (49000 unless changed in its Network settings), and
X-Plane answers to the address the requests came from, every frame up to that rate. No Data Output
row needs ticking, and a dataref's unit is fixed by its name: X-Plane 12 changed the units and order of
the Data Output row 16 (angular velocities, deg/s P, Q, R) from X-Plane 11's (rad/s Q, P, R); the
datarefs ``Prad``, ``Qrad``, ``Rrad`` are rad/s in both.

The request (X-Plane's "Exchanging Data with X-Plane" document): ``"RREF\\0"``, then int32 frequency
[per second] (0 stops it), int32 index (the client's number for the dataref), char[400] the dataref's
name, zero-padded: 413 bytes, little-endian. The answer: ``"RREF"``, one byte, then (int32 index,
float32 value) pairs, 8 bytes each.

What is read: the body rates p, q, r (``sim/flightmodel/position/Prad``, ``Qrad``, ``Rrad``, rad/s);
the load factors (``sim/flightmodel/forces/g_axil``, ``g_side``, ``g_nrml``, in g at the centre of
gravity: X-Plane has no pilot-station load): the specific force in body axes is
``(g_axil, g_side, -g_nrml) x 9.80665`` m/s^2 (the signs of ArduPilot's X-Plane connector; ``g_nrml``
reads +1 in level flight); the bank and pitch (``phi``, ``theta``, deg); where the aircraft is
(``latitude``, ``longitude`` deg, ``elevation`` m) and its velocity (``local_vx/vy/vz``, m/s); the
flight's clock (``sim/time/total_flight_time_sec``: it stops while paused and restarts at a new flight).
"""

from __future__ import annotations

import math
import socket
import struct

import numpy as np

from desdemona.profiles.log import STANDARD_GRAVITY
from desdemona.service import bridge as _bridge

#: The datarefs, in the order of their index in the requests.
DATAREFS = (
    "sim/time/total_flight_time_sec",
    "sim/flightmodel/position/Prad", "sim/flightmodel/position/Qrad", "sim/flightmodel/position/Rrad",
    "sim/flightmodel/forces/g_axil", "sim/flightmodel/forces/g_side", "sim/flightmodel/forces/g_nrml",
    "sim/flightmodel/position/phi", "sim/flightmodel/position/theta",
    "sim/flightmodel/position/latitude", "sim/flightmodel/position/longitude",
    "sim/flightmodel/position/elevation",
    "sim/flightmodel/position/local_vx", "sim/flightmodel/position/local_vy", "sim/flightmodel/position/local_vz",
)
REQUEST = struct.Struct("<5sii400s")
PAIR = struct.Struct("<if")
NAME = "X-Plane's RREF stream"
FIXES = ("the g-load datarefs are in g and turned into m/s^2 here: is another program answering?",
         "the Prad/Qrad/Rrad datarefs are rad/s: is another program answering?",
         "(the g-load datarefs: another program answering?)",
         "(the g-load datarefs: another program answering?)")


def request(index: int, rate: int) -> bytes:
    """The RREF request for dataref ``DATAREFS[index]`` at ``rate`` answers a second (0: stop)."""
    return REQUEST.pack(b"RREF\0", int(rate), int(index), DATAREFS[index].encode())


class Decoder:
    """``decoder(packet) -> Sample | None``: X-Plane's RREF answers, merged (one answer may hold some
    of the datarefs); a sample once every dataref has a value and the answer holds the clock."""

    def __init__(self):
        self.values: dict[int, float] = {}

    def __call__(self, data: bytes) -> _bridge.Sample | None:
        if len(data) < 5 or data[:4] != b"RREF" or (len(data) - 5) % PAIR.size:
            raise _bridge.DecodeError(f"not an RREF answer ({len(data)} bytes, {data[:4]!r})")
        fresh = dict(PAIR.iter_unpack(data[5:]))
        self.values.update({k: float(v) for k, v in fresh.items() if 0 <= k < len(DATAREFS)})
        if len(self.values) < len(DATAREFS) or 0 not in fresh:
            return None
        return sample([self.values[k] for k in range(len(DATAREFS))])


def sample(v) -> _bridge.Sample:
    """A :class:`.bridge.Sample` of the dataref values ``v`` in the order of :data:`DATAREFS`."""
    clock, p, q, r, axial, side, normal, phi, theta, lat, lon, elevation, vx, vy, vz = v
    f_body = STANDARD_GRAVITY * np.array([axial, side, -normal])
    return _bridge.Sample(np.array([p, q, r]), f_body, (math.radians(phi), math.radians(theta)),
                          _bridge.ecef(math.radians(lat), math.radians(lon), elevation),
                          float(np.linalg.norm([vx, vy, vz])), clock, tuple(v))


def run(xplane: tuple[str, int], listen: tuple[str, int], to: tuple[str, int], rate: int = 60,
        modulus: bool = False, wait: float = 120.0, duration: float | None = None, say=None,
        key: bytes | None = None) -> dict:
    """Subscribe to :data:`DATAREFS` at ``rate`` answers a second from the X-Plane at ``xplane`` (host,
    port), receiving on ``listen``, and forward the checked motion to ``serve`` at ``to`` until
    ``duration`` [s] or Ctrl-C (:func:`.bridge.run`: ``wait``, the result); ``key``: the shared key
    its messages are signed with. The subscriptions are sent again while nothing comes (X-Plane
    started after the bridge) and cancelled at the end."""
    with socket.socket(socket.AF_INET, socket.SOCK_DGRAM) as sock:
        sock.bind(listen)

        def subscribe(every: int = int(rate)) -> None:
            for k in range(len(DATAREFS)):
                sock.sendto(request(k, every), xplane)

        link = _bridge.Bridge(sock, to, NAME, FIXES, modulus=modulus, say=say, key=key)
        subscribe()
        try:
            return _bridge.run(sock, Decoder(), link, wait, duration, idle=subscribe)
        finally:
            subscribe(0)

"""``desdemona host flightgear``: FlightGear's native FDM packets in, checked Motion messages to ``serve``
out (:mod:`.bridge`).

FlightGear sends its flight dynamics state once a frame with
``fgfs --native-fdm=socket,out,RATE,127.0.0.1,PORT,udp --max-fps=RATE`` (at most one packet a frame:
the output rate is the frame rate). The packet is FlightGear's ``FGNetFDM``, version 24: 408 bytes,
big-endian, decoded with ``flightgear-python`` (its ``fdm_v24`` layout, the library the project uses
for FlightGear's protocols: ``pip install 'desdemona[flightgear]'``). Of it the bridge reads:

- the specific force at the pilot's station ``A_X/Y/Z_pilot`` [ft/s^2], body axes x forward, y right,
  z down (level flight reads z = -32.2);
- the Euler angles ``phi``, ``theta`` and their rates ``phidot``, ``thetadot``, ``psidot`` [rad, rad/s]:
  FlightGear sends Euler-angle rates, not body rates, turned here exactly into p, q, r with the
  attitude (:func:`.bridge.body_rates`);
- where the aircraft is (``lat``, ``lon`` [rad], ``alt`` [m]) and its speed (``v_north/east/down``
  [ft/s]): the jump check.

The packet carries no simulation time with sub-second resolution (``cur_time`` is Unix seconds):
the bridge's own clock times the samples, and a paused FlightGear shows as packets that do not change.
"""

from __future__ import annotations

import socket

import numpy as np

from desdemona.profiles.path import ProfileError
from desdemona.service import bridge as _bridge

#: Feet to metres (exact, international foot).
FT = 0.3048
#: FlightGear's native FDM version this bridge reads, and its length [bytes].
VERSION, LENGTH = 24, 408
NAME = "FlightGear's native FDM stream"
#: What mends each unit mistake (:func:`.bridge.check_start`): FlightGear's units are fixed by its packet.
FIXES = ("the native FDM is in ft/s^2: is another program sending to this port?",
         "the native FDM's rates are rad/s: is another program sending to this port?",
         "(the native FDM is in ft/s^2: another program on this port?)",
         "(the native FDM is in ft/s^2: another program on this port?)")


def _layout():
    try:
        from flightgear_python import fdm_v24
    except ImportError:
        raise ProfileError("host flightgear needs flightgear-python: pip install 'desdemona[flightgear]'") from None
    return fdm_v24.fdm_struct


def decoder():
    """``decode(packet) -> Sample``: a native FDM v24 packet decoded (DecodeError for anything else)."""
    layout = _layout().compile()  # construct's compiled parser: 60 us a packet against 250 us
    import construct

    def decode(data: bytes) -> _bridge.Sample:
        if len(data) != LENGTH:
            raise _bridge.DecodeError(f"{len(data)} bytes, not a native FDM v{VERSION} packet ({LENGTH})")
        try:
            fdm = layout.parse(data)
        except construct.ConstructError:
            raise _bridge.DecodeError(f"not a native FDM v{VERSION} packet (version "
                                      f"{int.from_bytes(data[:4], 'big')})") from None
        return sample(fdm)

    return decode


def sample(fdm) -> _bridge.Sample:
    """A :class:`.bridge.Sample` of a parsed native FDM packet (``flightgear_python``'s container)."""
    phi, theta = float(fdm.phi_rad), float(fdm.theta_rad)
    omega = _bridge.body_rates(phi, theta, fdm.phidot_rad_per_s, fdm.thetadot_rad_per_s, fdm.psidot_rad_per_s)
    f_body = FT * np.array([fdm.A_X_pilot_ft_per_s_per_s, fdm.A_Y_pilot_ft_per_s_per_s, fdm.A_Z_pilot_ft_per_s_per_s])
    velocity = FT * np.array([fdm.v_north_ft_per_s, fdm.v_east_ft_per_s, fdm.v_down_ft_per_s])
    state = (fdm.lon_rad, fdm.lat_rad, fdm.alt_m, fdm.phi_rad, fdm.theta_rad, fdm.psi_rad,
             fdm.A_X_pilot_ft_per_s_per_s, fdm.A_Y_pilot_ft_per_s_per_s, fdm.A_Z_pilot_ft_per_s_per_s)
    return _bridge.Sample(omega, f_body, (phi, theta), _bridge.ecef(fdm.lat_rad, fdm.lon_rad, fdm.alt_m),
                          float(np.linalg.norm(velocity)), None, state)


def run(listen: tuple[str, int], to: tuple[str, int], modulus: bool = False, wait: float = 120.0,
        duration: float | None = None, say=None,
        key: bytes | None = None) -> dict:
    """Read FlightGear's native FDM packets on ``listen`` (host, port) and forward the checked motion
    to ``serve`` at ``to`` until ``duration`` [s] or Ctrl-C (:func:`.bridge.run`: ``wait``, the result);
    ``key``: the shared key its messages are signed with."""
    decode = decoder()
    with socket.socket(socket.AF_INET, socket.SOCK_DGRAM) as sock:
        sock.bind(listen)
        link = _bridge.Bridge(sock, to, NAME, FIXES, modulus=modulus, say=say, key=key)
        return _bridge.run(sock, decode, link, wait, duration)

"""The simulator bridges (desdemona.service.bridge, .flightgear, .xplane): packets made by an independent
encoder decode to the motion they hold, the live check refuses the usual mistakes, and the bridges
forward on loopback only what passed it.

FlightGear's packets are built with flightgear-python's own packer (``fdm_v24.fdm_struct.build``);
X-Plane's from its documented layout, written out here. Every socket is bound on 127.0.0.1 and has a
timeout; every loopback run lasts a few seconds at most."""

import math
import socket
import struct
import threading
import time

import numpy as np
import pytest

from desdemona.cli import main
from desdemona.profiles.path import G, ProfileError
from desdemona.service import bridge, xplane
from tests.test_service_hosts import Receiver

fdm_v24 = pytest.importorskip("flightgear_python.fdm_v24", reason="host flightgear needs flightgear-python")
from desdemona.service import flightgear  # noqa: E402

FT = 0.3048
G0 = 9.80665


def fdm_packet(phi=0.0, theta=0.0, psi=0.0, phidot=0.0, thetadot=0.0, psidot=0.0, accel_ft=(0.0, 0.0, -G / FT),
               lat=1.1, lon=-0.39, alt=1000.0, v_north_ft=150.0, version=24) -> bytes:
    """A native FDM packet built by flightgear-python's packer (its v24 layout)."""
    four = [0.0] * 4
    fields = dict(version=24, _padding=b"\0" * 4, lon_rad=lon, lat_rad=lat, alt_m=alt, agl_m=alt, phi_rad=phi,
                  theta_rad=theta, psi_rad=psi, alpha_rad=0.0, beta_rad=0.0, phidot_rad_per_s=phidot,
                  thetadot_rad_per_s=thetadot, psidot_rad_per_s=psidot, vcas=80.0, climb_rate_ft_per_s=0.0,
                  v_north_ft_per_s=v_north_ft, v_east_ft_per_s=0.0, v_down_ft_per_s=0.0, v_body_u=v_north_ft,
                  v_body_v=0.0, v_body_w=0.0, A_X_pilot_ft_per_s_per_s=accel_ft[0],
                  A_Y_pilot_ft_per_s_per_s=accel_ft[1], A_Z_pilot_ft_per_s_per_s=accel_ft[2], stall_warning=0.0,
                  slip_deg=0.0, num_engines=1, eng_state=["running"] * 4, rpm=four, fuel_flow_gal_per_hr=four,
                  fuel_px_psi=four, egt_deg_F=four, cht_deg_F=four, mp_osi=four, tit=four, oil_temp_deg_F=four,
                  oil_px_psi=four, num_tanks=1, fuel_quantity=four, num_wheels=3, wow=[0] * 3, gear_pos=[0.0] * 3,
                  gear_steer=[0.0] * 3, gear_compression=[0.0] * 3, cur_time_s=0, warp_s=0, visibility_m=1e4,
                  elevator=0.0, elevator_trim_tab=0.0, left_flap=0.0, right_flap=0.0, left_aileron=0.0,
                  right_aileron=0.0, rudder=0.0, nose_wheel=0.0, speedbrake=0.0, spoilers=0.0)
    data = fdm_v24.fdm_struct.build(fields)
    return data if version == 24 else struct.pack(">I", version) + data[4:]


def rref_answer(pairs: dict[int, float]) -> bytes:
    """X-Plane's answer to RREF subscriptions as its UDP document lays it out: the bytes "RREF", one
    byte (a comma), then per dataref its int32 index and float32 value, little-endian."""
    return b"RREF," + b"".join(struct.pack("<i", k) + struct.pack("<f", v) for k, v in pairs.items())


def xplane_values(clock=10.0, pqr=(0.0, 0.0, 0.0), g=(0.0, 0.0, 1.0), phi=0.0, theta=0.0, lat=64.0, lon=-22.6,
                  elevation=900.0, v=(0.0, 0.0, -50.0)) -> dict[int, float]:
    """Dataref index -> value, in the order of xplane.DATAREFS (X-Plane's units: s, rad/s, g, deg, m, m/s)."""
    return dict(enumerate([clock, *pqr, *g, phi, theta, lat, lon, elevation, *v]))


def euler_rates(phi, theta, p, q, r):
    """The Euler angles' rates of body rates p, q, r (z-y-x): the kinematic equation solved for them,
    written independently of bridge.body_rates."""
    phidot = p + (q * math.sin(phi) + r * math.cos(phi)) * math.tan(theta)
    thetadot = q * math.cos(phi) - r * math.sin(phi)
    psidot = (q * math.sin(phi) + r * math.cos(phi)) / math.cos(theta)
    return phidot, thetadot, psidot


# -- FlightGear's packets ------------------------------------------------------------------------------

def test_flightgear_level_flight_is_one_g_up_in_the_cabin():
    s = flightgear.decoder()(fdm_packet(accel_ft=(0.0, 0.0, -32.174)))
    S = s.cabin()
    np.testing.assert_allclose(S, [0, 0, 0, 0, 0, 32.174 * FT], atol=1e-5)
    assert S[5] == pytest.approx(G0, abs=1e-4)
    np.testing.assert_allclose(s.up_cabin(), [0, 0, 1], atol=1e-12)


def test_flightgear_axes_and_feet():
    """Body x forward, y right, z down to cabin x right, y forward, z up; ft/s^2 to m/s^2."""
    S = flightgear.decoder()(fdm_packet(accel_ft=(10.0, -5.0, -30.0))).cabin()
    np.testing.assert_allclose(S[3:], [-5.0 * FT, 10.0 * FT, 30.0 * FT], rtol=1e-6)


def test_flightgear_steady_right_turn_has_wz_below_zero():
    """A coordinated right turn, bank 30 deg, heading rate w: p = 0, q = w sin(phi), r = w cos(phi)."""
    phi, w = math.radians(30.0), 0.1
    S = flightgear.decoder()(fdm_packet(phi=phi, psidot=w)).cabin()
    np.testing.assert_allclose(S[:3], [w * math.sin(phi), 0.0, -w * math.cos(phi)], atol=1e-7)


def test_flightgear_euler_rates_become_the_body_rates():
    """Seeded attitudes and body rates: the Euler rates FlightGear would send turn back into them."""
    rng = np.random.default_rng(75)
    for _ in range(50):
        phi, theta = rng.uniform(-math.pi, math.pi), rng.uniform(-1.3, 1.3)
        pqr = rng.uniform(-2.0, 2.0, 3)
        packet = fdm_packet(phi=phi, theta=theta, psi=rng.uniform(0, 6), **dict(zip(
            ("phidot", "thetadot", "psidot"), euler_rates(phi, theta, *pqr))))
        s = flightgear.decoder()(packet)
        np.testing.assert_allclose(s.omega_body, pqr, rtol=2e-5, atol=2e-5 / math.cos(theta))  # float32 on the wire


@pytest.mark.parametrize("data, says", [(b"\0" * 100, "100 bytes"), (None, "version 25")])
def test_flightgear_refuses_other_packets(data, says):
    with pytest.raises(bridge.DecodeError, match=says):
        flightgear.decoder()(data if data is not None else fdm_packet(version=25))


# -- X-Plane's packets ---------------------------------------------------------------------------------

def test_xplane_request_has_the_documented_layout():
    data = xplane.request(2, 60)
    assert len(data) == 413 and data[:5] == b"RREF\0"
    assert struct.unpack_from("<ii", data, 5) == (60, 2)
    assert data[13:].rstrip(b"\0") == b"sim/flightmodel/position/Qrad" and len(data[13:]) == 400


def test_xplane_level_flight_and_a_right_turn():
    decode = xplane.Decoder()
    S = decode(rref_answer(xplane_values())).cabin()
    np.testing.assert_allclose(S, [0, 0, 0, 0, 0, G0], atol=1e-6)
    phi, w = math.radians(30.0), 0.1
    s = decode(rref_answer(xplane_values(clock=10.1, pqr=(0.0, w * math.sin(phi), w * math.cos(phi)),
                                         g=(0.0, 0.0, 1 / math.cos(phi)), phi=30.0)))
    S = s.cabin()
    np.testing.assert_allclose(S[:3], [w * math.sin(phi), 0.0, -w * math.cos(phi)], rtol=1e-6)
    assert S[5] == pytest.approx(G0 / math.cos(phi), rel=1e-6) and s.sim_time == pytest.approx(10.1)
    np.testing.assert_allclose(s.up_cabin(), [-0.5, 0.0, math.cos(phi)], atol=1e-6)


def test_xplane_answers_are_merged_and_need_the_clock():
    decode = xplane.Decoder()
    values = xplane_values()
    assert decode(rref_answer({k: v for k, v in values.items() if k < 8})) is None
    assert decode(rref_answer({k: v for k, v in values.items() if k >= 8})) is None  # no clock in it
    assert decode(rref_answer({0: 10.2})).sim_time == pytest.approx(10.2)
    with pytest.raises(bridge.DecodeError, match="not an RREF"):
        decode(b"DATA*" + bytes(36))


# -- the start check and the watch ---------------------------------------------------------------------

def level_stream(seconds=3.0, rate=60.0, seed=1):
    """t, S (cabin), up: a level flight with a little turbulence."""
    rng = np.random.default_rng(seed)
    t = np.arange(0.0, seconds, 1.0 / rate)
    S = np.zeros((len(t), 6))
    S[:, :3] = rng.normal(0, 0.004, (len(t), 3))
    S[:, 3:] = [0.0, 0.0, G] + rng.normal(0, 0.05, (len(t), 3))
    return t, S, np.tile([0.0, 0.0, 1.0], (len(t), 1))


def test_start_check_passes_level_flight():
    assert bridge.check_start(*level_stream(), flightgear.FIXES, "stream")


@pytest.mark.parametrize("mistake, says", [
    ("deg/s", "rates are in deg/s"),
    ("g", "reads like g"),
    ("z down", "the force points down"),
    ("ft/s^2", "9.81 g"),
])
def test_start_check_names_the_mistake(mistake, says):
    t, S, up = level_stream()
    if mistake == "deg/s":
        S[:, :3] = np.degrees(S[:, :3])
    elif mistake == "g":
        S[:, 3:] /= G
    elif mistake == "z down":
        S[:, 5] *= -1
    else:
        S[:, 3:] *= G
    with pytest.raises(ProfileError, match=says):
        bridge.check_start(t, S, up, xplane.FIXES, "stream")


def test_start_check_waits_through_a_manoeuvre():
    t, S, up = level_stream()
    S[:, 2] = 0.3  # a steady turn: not still, no mistake either
    assert bridge.check_start(t, S, up, flightgear.FIXES, "stream") is False


def xp_sample(clock=10.0, **kwargs):
    return xplane.sample([xplane_values(clock=clock, **kwargs)[k] for k in range(len(xplane.DATAREFS))])


def test_watch_sees_a_pause_a_reset_a_jump_and_a_crash():
    watch = bridge.Watch()
    assert watch.problem(0.0, xp_sample(10.0), xp_sample(10.0).cabin()) is None
    assert watch.problem(0.3, xp_sample(10.0), xp_sample(10.0).cabin()) is None  # a repeat is no pause yet
    assert "frozen" in watch.problem(0.6, xp_sample(10.0), xp_sample(10.0).cabin())
    watch = bridge.Watch()
    watch.problem(0.0, xp_sample(10.0), xp_sample(10.0).cabin())
    assert "clock went back" in watch.problem(0.02, xp_sample(0.0), xp_sample(0.0).cabin())
    watch = bridge.Watch()
    watch.problem(0.0, xp_sample(10.0), xp_sample(10.0).cabin())
    moved = xp_sample(10.02, lat=64.01)  # 1.1 km in 20 ms at 50 m/s
    assert "moved" in watch.problem(0.02, moved, moved.cabin())
    crash = xp_sample(10.04, g=(0.0, 0.0, 25.0))
    assert "crash" in bridge.Watch().problem(0.0, crash, crash.cabin())


def test_watch_sees_rates_held_in_deg_s():
    watch = bridge.Watch()
    fast = [xp_sample(10.0 + k / 60, pqr=(0.0, 0.0, 12.0)) for k in range(70)]
    said = [watch.problem(k / 60, s, s.cabin()) for k, s in enumerate(fast)]
    assert said[:60] == [None] * 60 and "deg/s" in said[-1]


# -- bridges on loopback -------------------------------------------------------------------------------

def free_port() -> int:
    with socket.socket(socket.AF_INET, socket.SOCK_DGRAM) as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def send_at(packets, to, rate: float, sock=None) -> threading.Thread:
    """A fake simulator: ``packets`` sent to ``to`` at ``rate`` a second, from a thread."""
    own = sock is None
    sock = sock or socket.socket(socket.AF_INET, socket.SOCK_DGRAM)

    def run():
        begun = time.monotonic()
        for k, data in enumerate(packets):
            time.sleep(max(0.0, begun + k / rate - time.monotonic()))
            sock.sendto(data, to)
        if own:
            sock.close()

    thread = threading.Thread(target=run, daemon=True)
    thread.start()
    return thread


pytestmark_realtime = pytest.mark.realtime


@pytestmark_realtime
def test_flightgear_bridge_forwards_after_the_start_check_and_stops_on_a_pause():
    """0.5 s of placeholders (not forwarded), 3 s of level flight climbing at 1 m a packet, then the same
    packet for a second (paused): forwarding starts 2 s into the flight and stops half a second into
    the pause; what was forwarded is the flight, in order."""
    port, rate = free_port(), 100.0
    placeholder = [fdm_packet(alt=0.0, v_north_ft=0.0)] * 50
    flight = [fdm_packet(alt=1000.0 + k * 0.3, accel_ft=(0.0, 0.0, -32.2 - 0.1 * math.sin(k / 7)))
              for k in range(300)]
    pause = [flight[-1]] * 100
    said = []
    with Receiver() as rx:
        send_at(placeholder + flight + pause, ("127.0.0.1", port), rate)
        result = flightgear.run(("127.0.0.1", port), rx.to, wait=5.0, duration=4.7, say=said.append)
    got = [m for _, m in rx.got]
    assert len(result["starts"]) == 1 and 2.4 < result["starts"][0] < 2.9  # 0.5 s placeholders + 2 s checked
    assert len(result["stops"]) == 1 and "frozen" in result["stops"][0][1] and 3.9 < result["stops"][0][0] < 4.3
    assert result["forwarded"] == len(got) and 100 < len(got) < 200
    assert [m.sequence for m in got] == list(range(1, len(got) + 1))
    assert all(np.diff([m.time for m in got]) > 0)
    fz = np.array([m.values[5] for m in got])
    assert np.all(np.abs(fz - 32.2 * FT) < 0.1 * FT + 1e-6)
    assert any("forwarding to" in s for s in said) and any("stopped forwarding" in s for s in said)
    assert result["delay_p99"] < 0.01


class FakeXPlane:
    """X-Plane's UDP port on 127.0.0.1: takes RREF requests, answers the requester with ``answers``."""

    def __init__(self, answers, rate: float):
        self.socket = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
        self.socket.bind(("127.0.0.1", 0))
        self.socket.settimeout(3.0)
        self.address = self.socket.getsockname()
        self.requests: list[tuple[int, int, bytes]] = []
        self.answers, self.rate = answers, rate

    def leftover(self) -> None:
        """The requests that came after the answers began (a cancellation), then close."""
        self.socket.settimeout(0.2)
        try:
            while True:
                self.requests.append(struct.unpack_from("<5sii400s", self.socket.recv(1024))[1:])
        except TimeoutError:
            pass
        self.socket.close()

    def serve(self):
        data, client = self.socket.recvfrom(1024)
        first = struct.unpack_from("<5sii400s", data)
        self.requests.append(first[1:])
        self.socket.settimeout(0.01)
        while True:  # the rest of the subscription
            try:
                data, _ = self.socket.recvfrom(1024)
            except TimeoutError:
                break
            self.requests.append(struct.unpack_from("<5sii400s", data)[1:])
        return send_at(self.answers, client, self.rate, sock=self.socket)


@pytestmark_realtime
def test_xplane_bridge_subscribes_and_forwards_the_modulus():
    answers = [rref_answer(xplane_values(clock=5.0 + k / 100, elevation=900.0 + k * 0.5)) for k in range(300)]
    fake = FakeXPlane(answers, 100.0)
    listen = ("127.0.0.1", free_port())
    with Receiver() as rx:
        runner = threading.Thread(target=lambda: fake.serve().join(5), daemon=True)
        runner.start()
        result = xplane.run(fake.address, listen, rx.to, rate=50, modulus=True, wait=5.0, duration=3.3)
        runner.join(5)
    fake.leftover()
    subscribed = {index: name.rstrip(b"\0").decode() for rate, index, name in fake.requests if rate == 50}
    assert subscribed == dict(enumerate(xplane.DATAREFS))
    assert any(rate == 0 for rate, _, _ in fake.requests)  # cancelled at the end
    got = [m for _, m in rx.got]
    assert result["starts"] and len(got) == result["forwarded"] > 50
    assert all(m.channels == 1 for m in got)
    np.testing.assert_allclose([m.values[0] for m in got], G0, rtol=1e-6)


@pytestmark_realtime
def test_xplane_stream_in_the_wrong_units_never_starts(capsys):
    """g_nrml sent in m/s^2 (a program answering for X-Plane in the wrong units): exit 2, one line naming
    it, nothing forwarded."""
    answers = [rref_answer(xplane_values(clock=5.0 + k / 100, g=(0.0, 0.0, G0))) for k in range(300)]
    fake = FakeXPlane(answers, 100.0)
    with Receiver() as rx:
        runner = threading.Thread(target=lambda: fake.serve().join(5), daemon=True)
        runner.start()
        code = main(["host", "xplane", "--xplane", f"127.0.0.1:{fake.address[1]}", "--listen",
                     f"127.0.0.1:{free_port()}", "--to", f"127.0.0.1:{rx.to[1]}", "--wait", "3.5"])
        runner.join(5)
    fake.socket.close()
    err = capsys.readouterr().err.strip().splitlines()
    assert code == 2 and not rx.got
    assert err[-1].startswith("desdemona: error: X-Plane's RREF stream: ") and "9.81 g" in err[-1]
    assert "Traceback" not in "".join(err)


@pytestmark_realtime
def test_a_frozen_simulator_never_starts():
    port = free_port()
    packets = [fdm_packet()] * 150
    with Receiver() as rx:
        send_at(packets, ("127.0.0.1", port), 100.0)
        with pytest.raises(ProfileError, match="never changed: the simulation is paused"):
            flightgear.run(("127.0.0.1", port), rx.to, wait=1.2)
    assert not rx.got


def test_a_silent_simulator_stops_the_forwarding_once():
    """Forwarding, then no packet for a second: said once; the next packets are checked afresh."""
    with socket.socket(socket.AF_INET, socket.SOCK_DGRAM) as sock:
        link = bridge.Bridge(sock, ("127.0.0.1", 9), "stream", xplane.FIXES, say=lambda text: None)
        link.forwarding, link.watch.last = True, (10.0, xp_sample(10.0))
        link.quiet(10.5)
        assert link.forwarding and not link.stops
        link.quiet(11.2)
        link.quiet(12.0)
        assert not link.forwarding and len(link.stops) == 1 and "no packet for 1.2" in link.stops[0][1]


@pytestmark_realtime
def test_a_stream_of_nan_never_starts_and_says_so():
    port = free_port()
    packets = [fdm_packet(alt=1000.0 + k, accel_ft=(0.0, 0.0, float("nan"))) for k in range(150)]
    with Receiver() as rx:
        send_at(packets, ("127.0.0.1", port), 100.0)
        with pytest.raises(ProfileError, match="hold NaN or inf"):
            flightgear.run(("127.0.0.1", port), rx.to, wait=1.2)
    assert not rx.got


@pytestmark_realtime
def test_ctrl_c_ends_the_bridge_with_its_report():
    """Ctrl-C is how a session through a bridge ends: the counts are printed, the exit code is 130."""
    import signal
    import subprocess
    import sys

    port = free_port()
    proc = subprocess.Popen([sys.executable, "-m", "desdemona", "host", "flightgear", "--listen",
                             f"127.0.0.1:{port}", "--to", "127.0.0.1:9", "--wait", "30"],
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    sim = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
    send = threading.Thread(target=lambda: [(sim.sendto(fdm_packet(), ("127.0.0.1", port)), time.sleep(0.1))
                                            for _ in range(100) if proc.poll() is None], daemon=True)
    try:
        assert "reading FlightGear's native FDM" in proc.stderr.readline()
        send.start()  # a packet every 0.1 s until it reads
        assert "the first packet came" in proc.stderr.readline()
        proc.send_signal(signal.SIGINT)
        out, _ = proc.communicate(timeout=10)
        send.join(timeout=1)
    finally:
        sim.close()
        if proc.poll() is None:
            proc.kill()
            proc.wait()
    assert proc.returncode == 128 + signal.SIGINT and out.startswith("forwarded 0 of ")

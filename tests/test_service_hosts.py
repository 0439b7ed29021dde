"""The hosts (desdemona.service.hosts): what they send over loopback UDP, when, and what they withhold.

Every socket here is bound on 127.0.0.1 and has a timeout; every host run is a second or less."""

import signal
import socket
import subprocess
import sys
import textwrap
import threading
import time

import numpy as np
import pytest

from desdemona import profiles
from desdemona.profiles.path import G, ProfileError
from desdemona.service import hosts, protocol

# These tests time what they watch (a real-time loop, a prompt stop): the README runs them alone.
pytestmark = pytest.mark.realtime


class Receiver:
    """A UDP socket on 127.0.0.1 that a thread reads while a host sends: (wall time, message) pairs."""

    def __init__(self):
        self.socket = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
        self.socket.setsockopt(socket.SOL_SOCKET, socket.SO_RCVBUF, 4 << 20)
        self.socket.bind(("127.0.0.1", 0))
        self.socket.settimeout(0.05)
        self.to = self.socket.getsockname()
        self.got: list[tuple[float, protocol.Motion]] = []
        self.stop = threading.Event()
        self.thread = threading.Thread(target=self._read, daemon=True)

    def _read(self):
        while not self.stop.is_set():
            try:
                data = self.socket.recv(65536)
            except TimeoutError:
                continue
            except OSError:
                return
            self.got.append((time.monotonic(), protocol.unpack(data)))

    def __enter__(self):
        self.thread.start()
        return self

    def __exit__(self, *exc):
        time.sleep(0.1)  # the last datagrams in flight
        self.stop.set()
        self.thread.join(timeout=2)
        self.socket.close()

    @property
    def messages(self) -> list[protocol.Motion]:
        return [m for _, m in self.got]


class FakeClock:
    """A clock that only ``sleep`` moves: a host's schedule without waiting for it."""

    def __init__(self):
        self.now = 100.0
        self.sleeps: list[float] = []

    def clock(self):
        return self.now

    def sleep(self, seconds):
        self.sleeps.append(seconds)
        self.now += seconds


def short_cosine():
    return profiles.cosine(duration=1.5)  # 151 samples at 0.01 s


def test_replay_sends_every_sample_in_order_in_real_time():
    path = short_cosine()
    with Receiver() as rx:
        begun = time.monotonic()
        result = hosts.replay(path, rx.to, speed=4.0)
    got = rx.messages
    assert [m.sequence for m in got] == list(range(1, len(path.t) + 1))
    np.testing.assert_array_equal([m.time for m in got], path.t)
    np.testing.assert_array_equal(np.array([m.values for m in got]), path.S_d)
    assert all(m.forecast is None and m.channels == 6 for m in got)
    assert result["sent"] == result["messages"] == len(path.t) and result["dropped"] == result["outage"] == 0
    assert (result["first_sequence"], result["last_sequence"]) == (1, len(path.t))
    # real time at speed 4: 1.5 s of path in 0.375 s, each sample near its time after the first
    assert 0.37 <= result["duration"] < 0.8
    arrival = np.array([w for w, _ in rx.got]) - begun
    lag = arrival - path.t / 4.0
    assert np.median(np.abs(lag - lag[0])) < 0.02 and np.max(lag - lag[0]) < 0.2
    assert np.all(arrival[1:] - arrival[0] >= path.t[1:] / 4.0 - 0.02)  # never early


def test_replay_sleeps_until_each_send_time():
    """The schedule: sample k at t_k / speed after the first, reached by sleeping (no busy wait)."""
    path = short_cosine()
    fake = FakeClock()
    with Receiver() as rx:
        result = hosts.replay(path, rx.to, speed=2.0, clock=fake.clock, sleep=fake.sleep)
    assert len(fake.sleeps) == len(path.t) - 1
    np.testing.assert_allclose(fake.sleeps, 0.005, rtol=1e-6)
    assert result["duration"] == pytest.approx(0.75) and result["late"] == 0.0
    assert len(rx.messages) == len(path.t)


def test_replay_drop_withholds_a_seeded_share():
    path = short_cosine()
    runs = []
    for _ in range(2):
        fake = FakeClock()
        with Receiver() as rx:
            result = hosts.replay(path, rx.to, drop=0.3, seed=7, start_sequence=1000, clock=fake.clock,
                                  sleep=fake.sleep)
        runs.append([m.sequence for m in rx.messages])
        assert result["sent"] == len(rx.messages) and result["sent"] + result["dropped"] == len(path.t)
        assert 0.15 < result["dropped"] / len(path.t) < 0.45
        # every message received carries its own sample: a gap in the sequence for each one withheld
        for m in rx.messages:
            k = m.sequence - 1000
            assert m.time == path.t[k] and np.array_equal(m.values, path.S_d[k])
    assert runs[0] == runs[1]  # the same seed, the same datagrams
    assert runs[0] == sorted(runs[0])


def test_replay_outage_goes_quiet_for_its_span():
    path = short_cosine()
    fake = FakeClock()
    with Receiver() as rx:
        result = hosts.replay(path, rx.to, outage=(0.5, 0.3), clock=fake.clock, sleep=fake.sleep)
    quiet = (path.t >= 0.5) & (path.t < 0.8)
    assert result["outage"] == np.count_nonzero(quiet) == 30
    assert [m.sequence for m in rx.messages] == [k + 1 for k in np.flatnonzero(~quiet)]
    assert result["duration"] == pytest.approx(1.5)  # the schedule runs on through the outage


def test_replay_forecast_is_the_recordings_next_samples():
    path = short_cosine()
    fake = FakeClock()
    with Receiver() as rx:
        hosts.replay(path, rx.to, forecast=0.2, clock=fake.clock, sleep=fake.sleep)
    got = rx.messages
    assert len(got) == len(path.t)
    for k, m in enumerate(got):
        if k == len(path.t) - 1:
            assert m.forecast is None  # nothing left of the recording
            continue
        assert m.forecast_step == pytest.approx(0.01)
        np.testing.assert_array_equal(m.forecast, path.S_d[k + 1: k + 21])  # cut at the recording's end
    assert len(got[0].forecast) == 20 and len(got[-2].forecast) == 1


def test_replay_modulus_path_sends_one_channel():
    path = profiles.modulus_version(short_cosine())
    fake = FakeClock()
    with Receiver() as rx:
        hosts.replay(path, rx.to, forecast=0.05, clock=fake.clock, sleep=fake.sleep)
    got = rx.messages
    assert all(m.channels == 1 for m in got)
    np.testing.assert_array_equal([m.values[0] for m in got], path.M_d)
    np.testing.assert_array_equal(got[0].forecast[:, 0], path.M_d[1:6])
    fake = FakeClock()
    with Receiver() as rx:  # a full path sent as its modulus on request
        hosts.replay(short_cosine(), rx.to, modulus=True, clock=fake.clock, sleep=fake.sleep)
    np.testing.assert_allclose([m.values[0] for m in rx.messages], path.M_d)


@pytest.mark.parametrize("kwargs", [{"speed": 0.0}, {"speed": float("nan")}, {"forecast": -1.0},
                                    {"drop": 1.5}, {"outage": (1.0, -1.0)}, {"start_sequence": -1},
                                    {"forecast": 20.0}, {"start_sequence": 2**32 - 100}])  # 2000 samples: no datagram holds them
def test_replay_refuses_arguments_out_of_range(kwargs):
    with pytest.raises(ValueError):
        hosts.replay(short_cosine(), ("127.0.0.1", 9), **kwargs)


def test_replay_stops_promptly_on_ctrl_c():
    """SIGINT during a 20 s replay inside the command line's guard: the process ends at once (130)."""
    with socket.socket(socket.AF_INET, socket.SOCK_DGRAM) as rx:
        rx.bind(("127.0.0.1", 0))
        rx.settimeout(20)
        port = rx.getsockname()[1]
        script = textwrap.dedent(f"""
            from desdemona.support import guard
            from desdemona import profiles
            from desdemona.service import hosts
            try:
                with guard.interruptible():
                    hosts.replay(profiles.cosine(duration=20.0), ("127.0.0.1", {port}))
            except guard.Interrupted as stop:
                raise SystemExit(stop.code)
            """)
        proc = subprocess.Popen([sys.executable, "-c", script], stdout=subprocess.PIPE, stderr=subprocess.PIPE)
        try:
            rx.recv(65536)  # it runs: the first sample has arrived
            time.sleep(0.2)
            proc.send_signal(signal.SIGINT)
            sent = time.monotonic()
            proc.wait(timeout=5)
            assert time.monotonic() - sent < 1.0
        finally:
            if proc.poll() is None:
                proc.kill()
                proc.wait()
    assert proc.returncode == 128 + signal.SIGINT


def test_jsbsim_without_the_package_says_how_to_install(monkeypatch):
    monkeypatch.setitem(sys.modules, "jsbsim", None)  # import jsbsim raises ImportError
    with pytest.raises(ProfileError, match="pip install"):
        hosts.jsbsim("737_cruise", ("127.0.0.1", 9))


def test_jsbsim_unknown_script_is_refused():
    pytest.importorskip("jsbsim", reason="the jsbsim host needs the optional jsbsim package")
    with pytest.raises(ProfileError, match="neither a file nor a shipped script"):
        hosts.jsbsim("no_such_script", ("127.0.0.1", 9))


@pytest.fixture(scope="module")
def jsbsim_flight():
    pytest.importorskip("jsbsim", reason="the jsbsim host needs the optional jsbsim package")
    with Receiver() as rx:
        result = hosts.jsbsim("737_cruise", rx.to, speed=10.0, forecast=0.3, end=7.5)
    return result, rx.messages


def test_jsbsim_host_sends_level_flight(jsbsim_flight):
    """737_cruise: trimmed at 5.1 s in level cruise; 7.5 s of sim time, from the trim, at 10x."""
    result, got = jsbsim_flight
    assert result["start_reason"] == "after the script's trim" and 5.0 < result["start"] < 5.2
    assert result["ended"] == "the end 7.5 s" and result["aircraft"] == "737"
    n = int(np.floor((7.5 - result["start"]) * 100 + 1e-6)) + 1
    assert result["sent"] == len(got) == n
    assert [m.sequence for m in got] == list(range(1, n + 1))
    np.testing.assert_allclose([m.time for m in got], np.arange(n) * 0.01, atol=1e-12)
    S = np.array([m.values for m in got])
    assert np.all(np.abs(np.linalg.norm(S[:, 3:], axis=1) - G) < 0.3)  # level flight: about 1 g
    assert np.all(S[:, 5] > 9.0)  # felt up in the cabin frame (z up)
    assert np.all(np.abs(S[:, :3]) < 0.05)
    assert 0.2 < result["duration"] < 0.5  # 2.4 s of flight at 10x


def test_jsbsim_host_matches_the_import(jsbsim_flight):
    """The same channels and conversion as ``import jsbsim`` (which also filters: small differences)."""
    _, got = jsbsim_flight
    path, _ = profiles.from_jsbsim("737_cruise", end=7.5)
    S = np.array([m.values for m in got])
    k = min(len(S), len(path.t))
    np.testing.assert_allclose(S[:k], path.S_d[:k], atol=0.02)


def test_jsbsim_forecast_is_the_flights_true_future(jsbsim_flight):
    _, got = jsbsim_flight
    values = np.array([m.values for m in got])
    for k, m in enumerate(got[:-1]):
        assert m.forecast_step == pytest.approx(0.01)
        ahead = values[k + 1: k + 31]  # 0.3 s at 100 Hz, cut at the flight's end
        assert m.forecast.shape == ahead.shape
        np.testing.assert_allclose(m.forecast, ahead, rtol=1e-9, atol=1e-9)
    assert got[-1].forecast is None

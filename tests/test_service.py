"""The real-time service (desdemona.service.serve) on the loopback address: a session end to end, the
watchdog, bad datagrams, and a stop that parks the machine. Every loop is bounded in count and time."""

import json
import os
import signal
import socket
import subprocess
import sys
import threading
import time
from collections import Counter

import numpy as np
import pytest

from desdemona import Model, profiles
from desdemona.runs import session
from desdemona.service import machine, protocol, serve, spill

# These tests time what they watch (a real-time loop, a prompt stop): the README runs them alone.
pytestmark = pytest.mark.realtime

LOOPBACK = "127.0.0.1"


def _free_port() -> int:
    with socket.socket(socket.AF_INET, socket.SOCK_DGRAM) as s:
        s.bind((LOOPBACK, 0))
        return s.getsockname()[1]


class _Machine:
    """A receiver of setpoints on the loopback address, in a thread that ends by itself."""

    def __init__(self, seconds: float):
        self.sock = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
        self.sock.bind((LOOPBACK, 0))
        self.sock.settimeout(0.05)
        self.address = self.sock.getsockname()
        self.setpoints = []
        self.seconds = seconds
        self.end = None  # until the service is ready (from_now): its start-up may take longer than the session
        self.thread = threading.Thread(target=self._run, daemon=True)
        self.thread.start()

    def _run(self):
        while self.end is None or time.monotonic() < self.end:
            try:
                self.setpoints.append(protocol.unpack(self.sock.recv(4096)))
            except socket.timeout:
                continue
        self.sock.close()

    def from_now(self):
        """Listen ``seconds`` from now: from the moment the service is ready, whose start-up (its first
        plan) a slow machine stretches, rather than from this stand-in's creation."""
        self.end = time.monotonic() + self.seconds

    def join(self):
        """Once the service has ended: what is still on its way arrives within a moment."""
        self.end = min(self.end, time.monotonic() + 0.2)
        self.thread.join(timeout=2.0)


def _send(port: int, messages, at, extra=(), go: threading.Event | None = None):
    """Send ``messages`` (datagrams) at the clock offsets ``at`` [s] from now (or from ``go`` being
    set), in a thread; ``extra``: (offset, datagram) pairs sent too."""
    def run():
        if go is not None and not go.wait(timeout=30):
            return
        with socket.socket(socket.AF_INET, socket.SOCK_DGRAM) as s:
            start = time.monotonic()
            for when, data in sorted([*zip(at, messages), *extra], key=lambda x: x[0]):
                delay = start + when - time.monotonic()
                if delay > 0:
                    time.sleep(delay)
                s.sendto(data, (LOOPBACK, port))
    thread = threading.Thread(target=run, daemon=True)
    thread.start()
    return thread


def _motion(path, until: float, delay: float = 0.2, skip=None, session=None):
    """The datagrams of ``path``'s modulus up to ``until`` [s], each at its time after ``delay``, with
    the host's ``session`` if given."""
    keep = path.t <= until
    if skip is not None:
        keep &= ~((path.t >= skip[0]) & (path.t < skip[1]))
    data = [protocol.pack(protocol.Motion(k + 1, float(t), np.array([m])), session)
            for k, (t, m) in enumerate(zip(path.t, path.M_d)) if keep[k]]
    return data, delay + path.t[keep]


def _session(duration: float, predictor: str = "hold", **kwargs):
    model = Model(config="dfs")
    options = session.live(model, channels=1, rate=50.0, span=duration, horizon=1.0, predictor=predictor).options
    port = _free_port()
    stand_in = _Machine(duration + 3.0)
    serving = serve.ServeOptions(listen=(LOOPBACK, port), send=stand_in.address, channels=1, duration=duration,
                                 **kwargs)
    return model, options, port, stand_in, serving


def _serve(duration: float, data, at, extra=(), predictor: str = "hold", **serving):
    """A session of ``duration`` [s] on dfs at 50 Hz, the host sending ``data`` at ``at`` once it listens."""
    model, options, port, stand_in, serving = _session(duration, predictor, **serving)
    go = threading.Event()
    host = _send(port, data, at, extra, go=go)
    def ready(early):
        assert early == 0  # the host sends only once the service is ready
        stand_in.from_now()
        go.set()

    served = serve.serve(model, options, serving, ready=ready)
    host.join(timeout=5)
    stand_in.join()
    return model, options, served, stand_in


def _continuous(setpoints, model) -> None:
    """The setpoints as the motion system's own guard sees them (the stand-in's checker, independent of
    the service): consecutive, one continuous motion, every limit kept over every cycle."""
    assert [s.sequence for s in setpoints] == list(range(1, len(setpoints) + 1))
    checker = machine.Checker(model)
    for previous, setpoint in zip([None, *setpoints], setpoints):
        violations, _ = checker.check(setpoint, previous, setpoint.time)
        assert not violations, violations


@pytest.mark.parametrize("block", [None, 32])
def test_a_short_session_end_to_end(block, monkeypatch):
    """The host sends 2 s of the dfs catapult's modulus at its rate; the machine follows and is parked
    when the host stops; the setpoints are one continuous motion
    within the limits, each answering the newest message at once; the session judged like an on-line
    run keeps every limit. With the record written out every 32 rows (desdemona.service.spill), the
    session read back is the one sent: the plan's accelerations those of the setpoints, every message."""
    if block is not None:
        monkeypatch.setattr(spill, "BLOCK", block)
    data, at = _motion(profiles.get_profile("dfs-catapult"), 2.0)
    model, options, served, stand_in = _serve(3.5, data, at)
    sent = np.array([model.config.select(s.acceleration) for s in stand_in.setpoints])
    np.testing.assert_array_equal(served.loop.plan.u, sent)
    statuses = list(served.columns["status"])
    assert "running" in statuses and statuses[-1] in ("parking", "parked")
    assert statuses.index("parking") > statuses.index("running")
    assert len(served.received_t) == len(data) and not served.dropped
    assert len(stand_in.setpoints) == len(statuses)
    _continuous(stand_in.setpoints, model)
    answered = [s.answers for s in stand_in.setpoints if s.answers is not None]
    running = statuses.count("running")  # the host sends at 100 Hz, the session runs at 50 Hz
    assert answered == sorted(answered) and len(answered) >= 0.8 * running
    latency = served.columns["latency_s"]
    assert np.all(latency[np.isfinite(latency)] < 0.5)  # answered within the cycle it came in, not later
    result = serve.result(served, model, options)
    assert result.check.passed and result.check.rms > 0


def test_the_watchdog_parks_the_machine_and_a_returning_host_resumes_it():
    data, at = _motion(profiles.get_profile("dfs-catapult"), 2.5, skip=(0.8, 1.6))  # 0.8 s of silence: 40 cycles
    model, options, served, stand_in = _serve(3.0, data, at, timeout=5)
    statuses = list(served.columns["status"])
    first_park = statuses.index("parking")
    assert "running" in statuses[:first_park] and "running" in statuses[first_park:]
    commands = Counter(served.columns["command"][first_park:])
    assert commands["park"] >= 5 and commands["plan"] > 0
    _continuous(stand_in.setpoints, model)
    assert serve.result(served, model, options).check.passed


def test_bad_datagrams_are_dropped_and_counted_never_used():
    good = protocol.Motion(1, 0.0, np.array([9.81]))
    wrong_magic = bytearray(protocol.pack(good))
    wrong_magic[0] ^= 0xFF
    nan = bytearray(protocol.pack(protocol.Motion(2, 0.01, np.array([9.81]))))
    nan[-8:] = np.array([np.nan]).tobytes()
    six = protocol.pack(protocol.Motion(3, 0.02, np.r_[0, 0, 0, 0, 0, 9.81]))  # dfs is served the modulus
    bad = [(0.05, b"hello"), (0.06, bytes(wrong_magic)), (0.07, bytes(nan)), (0.08, six),
           (0.09, protocol.pack(good)[:-4]), (0.1, b"\x00" * 300)]
    later = [protocol.pack(protocol.Motion(k, 0.02 * k, np.array([9.81 + 0.1 * k]))) for k in range(1, 30)]
    repeated = [(0.4, later[3]), (0.41, later[0])]  # a repeated and an older sequence
    model, options, served, stand_in = _serve(1.5, later, 0.1 + 0.02 * np.arange(1, 30), extra=bad + repeated)
    assert len(served.received_t) == len(later)  # only the good ones, each once
    np.testing.assert_allclose(served.received[:, 0], [9.81 + 0.1 * k for k in range(1, 30)])
    assert sum(served.dropped.values()) == len(bad) + len(repeated)
    assert served.dropped["stale"] == 2 and served.dropped["channels"] == 1
    assert set(served.dropped) <= set(protocol.REASONS)


def _serve_process(tmp_path):
    """``desdemona serve`` on dfs as its own process, a stand-in receiving, once the service listens."""
    port, out = _free_port(), tmp_path / "served"
    stand_in = _Machine(20.0)
    stand_in.from_now()
    proc = subprocess.Popen([sys.executable, "-m", "desdemona", "serve", "--config", "dfs", "--listen",
                             f"{LOOPBACK}:{port}", "--send", f"{LOOPBACK}:{stand_in.address[1]}", "--out", str(out),
                             "--horizon", "1", "--duration", "15", "--no-view"],
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    assert "serving dfs at 50 Hz" in proc.stderr.readline()  # the service is up
    return port, out, stand_in, proc


@pytest.mark.skipif(sys.platform == "win32", reason="POSIX signals")
def test_sigint_parks_the_machine_writes_the_session_and_exits_130(tmp_path):
    port, out, stand_in, proc = _serve_process(tmp_path)
    try:
        path = profiles.get_profile("dfs-catapult")
        data, at = _motion(path, 6.0, delay=0.0)
        host = _send(port, data, at)
        deadline = time.monotonic() + 10
        while time.monotonic() < deadline and not any(s.status == "running" and np.any(s.rate != 0)
                                                      for s in stand_in.setpoints):
            time.sleep(0.05)
        time.sleep(0.5)
        os.kill(proc.pid, signal.SIGINT)
        stdout, stderr = proc.communicate(timeout=30)
    finally:
        if proc.poll() is None:
            proc.kill()
    host.join(timeout=10)
    assert proc.returncode == 130, stderr
    assert "the machine was parked" in stderr and "written to" in stdout
    summary = json.loads((out / "summary.json").read_text())
    assert summary["service"]["stopped_by"] == "SIGINT"
    rows = (out / "cycles.csv").read_text().splitlines()  # the cycles it followed the host
    assert rows[0].split(",")[-6:] == ["message_age_s", "latency_s", "command", "status", "tracking_use", "machine"]
    assert rows[-1].split(",")[-4:-2] == ["plan", "running"]
    assert rows[-1].endswith(",nan,")  # this stand-in sends no State: no tracking error, no machine status
    events = (out / "events.csv").read_text()
    assert "no State from the machine" in events and summary["service"]["machine_states"] == 0
    session = (out / "session.csv").read_text().splitlines()  # every cycle, the parking too
    assert session[-1].split(",")[1:3] == ["parked", "park"]
    assert summary["service"]["judged_span_s"][1] < float(session[-1].split(",")[0])
    last = stand_in.setpoints[-1]
    assert last.status == "parked" and not np.any(last.rate) and not np.any(last.acceleration)
    _continuous(stand_in.setpoints, Model(config="dfs"))


def test_parking_stops_each_joint_as_quickly_as_its_limits_allow():
    """From the arm spinning near its rate limit and the gimbals moving, the stop brakes at the
    acceleration limit, ramped at the jerk limit, and is nearly still within a few cycles of the
    shortest stop the limits allow (continuous time); no limit is exceeded on the way."""
    from desdemona.machine.plan import State, stopping_jerk, stopping_time

    lim, h = Model(config="dfs").limits, 0.02
    state = State(np.zeros(4), np.array([2.5, -1.0, 0.5, 2.0]), np.array([0.3, 0.5, -1.0, 0.0]))
    bound = np.max(stopping_time(state.qd, state.a, lim.acceleration, lim.jerk))
    for k in range(int(2 * bound / h)):
        jerk = stopping_jerk(state.qd, state.a, h, lim.acceleration, lim.jerk)
        assert np.all(np.abs(jerk) <= lim.jerk + 1e-12)
        state = state.advance(state.a, h, jerk)
        assert np.all(np.abs(state.a) <= lim.acceleration + 1e-12) and np.all(np.abs(state.qd) <= lim.velocity)
        if np.all(np.abs(state.qd) <= lim.jerk * h**2 / 4) and np.all(np.abs(state.a) <= lim.jerk * h / 4):
            break
    assert (k + 1) * h <= bound + 3 * h


@pytest.mark.skipif(sys.platform == "win32", reason="POSIX signals")
def test_a_second_sigint_stops_at_once_after_one_braking_command(tmp_path):
    """The first Ctrl-C starts parking the spinning machine; a second one ends the service after one
    more braking command, long before the machine could be at rest."""
    port, out, stand_in, proc = _serve_process(tmp_path)
    try:
        data, at = _motion(profiles.get_profile("dfs-catapult"), 8.0, delay=0.0)
        host = _send(port, data, at)
        deadline = time.monotonic() + 10
        while time.monotonic() < deadline and not any(s.status == "running" and abs(s.rate[0]) > 0.2
                                                      for s in stand_in.setpoints):
            time.sleep(0.05)
        os.kill(proc.pid, signal.SIGINT)
        time.sleep(0.1)
        os.kill(proc.pid, signal.SIGINT)
        proc.communicate(timeout=30)
    finally:
        if proc.poll() is None:
            proc.kill()
    host.join(timeout=10)
    stand_in.join()
    assert proc.returncode == 130
    last = stand_in.setpoints[-1]
    assert last.status == "parking", [(s.status, round(s.rate[0], 3)) for s in stand_in.setpoints[-5:]]
    assert abs(last.rate[0]) > 0.05  # still turning: it did not wait to park
    _continuous(stand_in.setpoints, Model(config="dfs"))


def test_the_forecast_predictor_plans_on_the_hosts_own_forecast():
    """A host that sends the next second with each message (here the true future): every plan is made
    on it (no fallback for want of a preview), and the session follows the path better than with the
    present value held."""
    path = profiles.get_profile("dfs-catapult")
    keep = path.t <= 5.0  # the launch's pulse comes at about 4 s
    step = float(path.t[1] - path.t[0])
    M = np.where(keep, path.M_d, path.M_d[keep][-1])  # the host's motion ends at 5 s, held after
    data = []
    for k in np.flatnonzero(keep):
        ahead = M[k + 1:k + 1 + int(round(1.0 / step))]
        data.append(protocol.pack(protocol.Motion(k + 1, float(path.t[k]), np.array([path.M_d[k]]),
                                                  ahead[:, None], step)))
    at = 0.2 + path.t[keep]
    model, options, forecast, _ = _serve(5.5, data, at, predictor="forecast")
    running = forecast.columns["status"] == "running"
    assert running.sum() > 100 and not any("preview" in r for r in forecast.loop.reasons)
    plain = [protocol.pack(protocol.Motion(k + 1, float(path.t[k]), np.array([path.M_d[k]])))
             for k in np.flatnonzero(keep)]
    _, hold_options, held, _ = _serve(5.5, plain, at)
    assert serve.result(forecast, model, options).check.rms < serve.result(held, model, hold_options).check.rms


def test_a_host_restarted_after_the_timeout_is_taken_back():
    """A host that starts again (a new session) from sequence 1 and time 0 after the watchdog parked the
    machine is the host back: followed again, its times continuing from where it left off."""
    path = profiles.get_profile("dfs-catapult")
    first, at_first = _motion(path, 0.8, session=1)
    again, at_again = _motion(path, 0.8, delay=1.6, session=2)  # sequence and time from the start
    model, options, served, _ = _serve(3.0, first + again, np.r_[at_first, at_again], timeout=5)
    statuses = list(served.columns["status"])
    parked = statuses.index("parking")
    assert "running" in statuses[parked:] and not served.dropped
    assert np.all(np.diff(served.received_t) > 0) and len(served.received_t) == len(first) + len(again)


def test_the_readme_s_three_commands_together(tmp_path):
    """machine, serve and host replay as three processes, as the README runs them: the stand-in checks
    every setpoint and passes, the session is written and judged, and each command says what it did."""
    machine_port, serve_port = _free_port(), _free_port()
    short = tmp_path / "short.csv"
    path = profiles.get_profile("dfs-catapult")
    keep = path.t <= 2.0
    profiles.write_csv(short, profiles.DesiredPath("short", path.t[keep], None, modulus=path.M_d[keep]))
    run = [sys.executable, "-m", "desdemona"]
    stand_in = subprocess.Popen([*run, "machine", "--config", "dfs", "--listen", f"{LOOPBACK}:{machine_port}",
                                 "--out", str(tmp_path / "machine-log"), "--idle", "2", "--duration", "30"],
                                stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    server = subprocess.Popen([*run, "serve", "--config", "dfs", "--listen", f"{LOOPBACK}:{serve_port}",
                               "--send", f"{LOOPBACK}:{machine_port}", "--out", str(tmp_path / "session"),
                               "--horizon", "1", "--quiet-end", "0.5", "--duration", "30", "--no-view"],
                              stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    try:
        assert "serving dfs at 50 Hz" in server.stderr.readline()
        host = subprocess.run([*run, "host", "replay", str(short), "--to", f"{LOOPBACK}:{serve_port}"],
                              capture_output=True, text=True, timeout=30)
        served, _ = server.communicate(timeout=30)
        checked, _ = stand_in.communicate(timeout=30)
    finally:
        for proc in (stand_in, server):
            if proc.poll() is None:
                proc.kill()
    assert host.returncode == 0 and f"sent {keep.sum()} messages" in host.stdout
    assert server.returncode == 0 and "served" in served and "written to" in served
    assert stand_in.returncode == 0 and "PASSED" in checked, checked
    summary = json.loads((tmp_path / "session" / "summary.json").read_text())
    assert summary["service"]["received"] == keep.sum() and summary["metrics"]["limits_kept"]
    assert json.loads((tmp_path / "machine-log" / "summary.json").read_text())["received"] > 50

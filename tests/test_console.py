"""The operator's console (desdemona.service.console): who may connect (the token rule), what a cycle
hands it (references, nothing computed), what a frame shows (the felt force of eq. 3.2, the canals'
felt rotation as the metrics compute it, the use of each limit), the stream's refusals; and, in
headless chromium (skipped where selenium, chromium or chromedriver is missing), a real ``serve`` with
the stand-in and a replay host on 127.0.0.1: the page's live pose is the session's log, its park
button parks the stand-in within the braking time, no console error, no request but to its own host,
and the page says when the service stops. Every wait is bounded."""

from __future__ import annotations

import csv
import json
import os
import socket
import subprocess
import sys
import time
import urllib.error
import urllib.request
from collections import Counter
from pathlib import Path
from types import SimpleNamespace
from urllib.parse import urlsplit

import numpy as np
import pytest

from desdemona import Model, profiles
from desdemona.check import metrics
from desdemona.machine import kinematics
from desdemona.machine.params import JOINT_NAMES
from desdemona.machine.plan import State, stopping_time
from desdemona.service import console, protocol

pytest.importorskip("websockets")

LOOPBACK = "127.0.0.1"
H = 0.02


@pytest.fixture(scope="module")
def model():
    return Model(config="dfs")


# ---- who may connect ----

def test_loopback_needs_no_token_any_other_address_a_new_one(tmp_path):
    assert console.access_token("127.0.0.1") is None
    assert console.access_token("127.0.0.5") is None and console.access_token("localhost") is None
    made = {console.access_token("0.0.0.0") for _ in range(3)}
    assert len(made) == 3 and all(len(t) >= 40 for t in made)  # 32 random bytes each, never the same


def test_a_token_file_is_read_only_when_only_its_owner_may_read_it(tmp_path):
    good = tmp_path / "token"
    good.write_text("a1b2c3d4e5f6a7b8c9d0e1f2a3b4c5d6\n")
    good.chmod(0o600)
    assert console.access_token("0.0.0.0", good) == "a1b2c3d4e5f6a7b8c9d0e1f2a3b4c5d6"
    assert console.access_token("127.0.0.1", good) == "a1b2c3d4e5f6a7b8c9d0e1f2a3b4c5d6"  # asked for: used
    good.chmod(0o640)
    with pytest.raises(console.ConsoleError, match="others may read it.*chmod 600"):
        console.access_token("0.0.0.0", good)
    short = tmp_path / "short"
    short.write_text("abc\n")
    short.chmod(0o600)
    with pytest.raises(console.ConsoleError, match="at least 16"):
        console.access_token("0.0.0.0", short)
    with pytest.raises(console.ConsoleError, match="No such file"):
        console.access_token("0.0.0.0", tmp_path / "absent")


# ---- what a cycle hands over, what a frame shows ----

def _cycle(model, k, rng, host=None, machine=None):
    """A session's state after cycle k as serve's loop holds it (the attributes publish reads)."""
    n = model.n
    state = State(rng.uniform(-1, 1, n), rng.uniform(-1, 1, n), rng.uniform(-0.5, 0.5, n))
    row = {"t": k * H, "status": "running", "command": "plan", "reason": "", "latency_s": 0.004,
           "compute_time_s": 0.003, "message_age_s": 0.001, "machine": "following", "tracking_use": 0.1}
    session = SimpleNamespace(rows=[row], starts=[state], command=(state[2], np.zeros(n)), paused=None)
    inbox = SimpleNamespace(newest=host, t=[0.0] * k, dropped=Counter({"x": 2}))
    link = SimpleNamespace(newest=machine, dropped=Counter({"y": 1}))
    return session, inbox, link


def test_a_cycle_hands_over_references_and_the_frames_compute_the_felt_motion(model):
    """publish appends a tuple of the cycle's own objects (nothing copied or computed); the frames made
    from them give S of eq. 3.2 at the head, and the canals' felt rotation run over every cycle, batch
    after batch, equals metrics.felt_rotation over the whole session."""
    rng = np.random.default_rng(3)
    live = console.Console(model, H, (LOOPBACK, 0))
    host = protocol.Motion(7, 1.5, np.array([12.0]))
    cycles = [_cycle(model, k, rng, host=host) for k in range(40)]
    for session, inbox, link in cycles:
        live.publish(session, inbox, link)
    snap = live.snapshots[0]
    assert snap.state is cycles[0][0].starts[-1] and snap.row is cycles[0][0].rows[-1] and snap.host is host
    assert snap.dropped == 3 and snap.received == 0
    frames = console.Frames(model, H)
    snaps = list(live.snapshots)
    made = [frames.frame(snaps[i:i + 7]) for i in range(0, 40, 7)]  # as the console's thread takes them
    S = np.array([np.asarray(model.S(s.state[0], s.state[1], s.command[0]), float).ravel() for s in snaps])
    assert np.allclose(made[-1]["f"], S[-1, 3:], rtol=0, atol=1e-12)
    assert np.allclose(made[-1]["omega"], S[-1, :3], rtol=0, atol=1e-12)
    assert made[-1]["f_d"] == [0.0, 0.0, 12.0]  # the modulus: along the occupant's z
    felt = np.degrees(np.abs(metrics.felt_rotation(S, None, H, frames.vestibular)))
    assert np.allclose(made[-1]["rotation_deg_s"], felt[-1], rtol=1e-9, atol=1e-9)
    direction = np.degrees(metrics.direction_error(S[-1:, 3:], None)[0])
    assert made[-1]["direction_deg"] == pytest.approx(direction, abs=1e-9)
    assert made[-1]["q"] == dict(zip(JOINT_NAMES, model.config.expand(snaps[-1].state[0]).tolist()))
    json.dumps(made[-1], allow_nan=False)  # plain JSON: no NaN or infinity reaches the page


def test_the_use_of_a_limit_is_one_at_the_limit(model):
    lim = model.limits
    n = model.n
    snap = console.Snapshot(0.0, State(np.zeros(n), lim.velocity * np.r_[1.0, np.zeros(n - 1)], np.zeros(n)),
                            (np.r_[0.0, 0.5 * lim.acceleration[1:]], np.zeros(n)), {}, None, None, None, 0, 0)
    use = console.Frames(model, H).use(snap)
    assert use["yaw"] == {"use": pytest.approx(1.0), "kind": "velocity"}
    assert use["cabin"]["kind"] in ("acceleration", "effort", "power") and use["cabin"]["use"] >= 0.5 - 1e-12


def test_without_a_token_only_a_loopback_name_reaches_the_console(model):
    """A site's name made to resolve to this computer (DNS rebinding) does not reach the page nor the
    stream of a console without a token."""
    from websockets.exceptions import InvalidStatus
    from websockets.sync.client import connect

    with console.Console(model, H, (LOOPBACK, 0)) as live:
        port = live.address[1]
        request = urllib.request.Request(f"http://{LOOPBACK}:{port}/", headers={"Host": f"evil.example:{port}"})
        with pytest.raises(urllib.error.HTTPError, match="403"):
            urllib.request.urlopen(request, timeout=5)
        with socket.create_connection((LOOPBACK, port), timeout=5) as sock, pytest.raises(InvalidStatus, match="403"):
            connect(f"ws://evil.example:{port}/stream", sock=sock, origin=f"http://evil.example:{port}",
                    open_timeout=5).close()
        for host in (f"{LOOPBACK}:{port}", f"localhost:{port}"):
            request = urllib.request.Request(f"http://{LOOPBACK}:{port}/", headers={"Host": host})
            with urllib.request.urlopen(request, timeout=5) as page:
                assert page.status == 200


def test_the_stream_needs_the_token_and_this_host_s_page_and_takes_only_known_commands(model):
    """With a token: the page and the stream are refused without it; a stream opened from another
    site's page is refused; a command is queued with who sent it; an unknown one is refused."""
    from websockets.exceptions import InvalidStatus
    from websockets.sync.client import connect

    with console.Console(model, H, (LOOPBACK, 0), token="s3cret-token-of-the-test") as live:
        host, port = live.address
        with pytest.raises(urllib.error.HTTPError, match="403"):
            urllib.request.urlopen(f"http://{host}:{port}/", timeout=5)
        with urllib.request.urlopen(live.url, timeout=5) as page:
            assert page.status == 200 and "connect-src 'self'" in page.headers["Content-Security-Policy"]
        stream = f"ws://{host}:{port}/stream"
        with pytest.raises(InvalidStatus, match="403"):
            connect(stream, open_timeout=5).close()
        with pytest.raises(InvalidStatus, match="403"):
            connect(stream + "?token=s3cret-token-of-the-test", origin="http://elsewhere.example",
                    open_timeout=5).close()
        with connect(stream + "?token=s3cret-token-of-the-test", origin=f"http://{host}:{port}",
                     open_timeout=5) as ws:
            ws.send(json.dumps({"command": "park"}))
            assert json.loads(ws.recv(timeout=5)) == {"accepted": "park"}
            ws.send(json.dumps({"command": "launch"}))
            assert "unknown command" in json.loads(ws.recv(timeout=5))["refused"]
            local = ws.local_address
        (arrived, action, who), = live.commands()
        assert action == "park" and who == f"console {local[0]}:{local[1]}" and arrived <= time.monotonic()
        assert live.commands() == []


# ---- in a real browser, beside a real session ----

def _free_port(kind=socket.SOCK_DGRAM) -> int:
    with socket.socket(socket.AF_INET, kind) as s:
        s.bind((LOOPBACK, 0))
        return s.getsockname()[1]


def _rows(path: Path) -> list[dict]:
    with open(path, newline="") as fh:
        return list(csv.DictReader(fh))


@pytest.fixture(scope="module")
def browser():
    from desdemona.results import view

    try:
        driver = view.headless_browser(900, 600, network=True)
    except view.NoBrowser as exc:
        pytest.skip(str(exc))
    yield driver
    driver.quit()


def _until(condition, seconds: float, what: str, browser=None):
    end = time.monotonic() + seconds
    while time.monotonic() < end:
        value = condition()
        if value:
            return value
        time.sleep(0.05)
    page = "" if browser is None else browser.execute_script(
        "const s = window.consoleState; return JSON.stringify([s.frames, s.closed, s.ended, s.frame && s.frame.t, "
        "s.frame && s.frame.status, s.frame && s.frame.received])")
    raise AssertionError(f"not within {seconds} s: {what} {page}")


@pytest.mark.realtime
def test_the_console_shows_the_session_and_parks_the_machine(browser, model, tmp_path):
    machine_port, serve_port, console_port = _free_port(), _free_port(), _free_port(socket.SOCK_STREAM)
    path = profiles.get_profile("dfs-catapult")
    keep = path.t <= 3.5
    short = tmp_path / "short.csv"
    profiles.write_csv(short, profiles.DesiredPath("short", path.t[keep], None, modulus=path.M_d[keep]))
    run = [sys.executable, "-m", "desdemona"]
    env = {**os.environ, "PYTHONUNBUFFERED": "1"}
    stand_in = subprocess.Popen([*run, "machine", "--config", "dfs", "--listen", f"{LOOPBACK}:{machine_port}",
                                 "--out", str(tmp_path / "machine"), "--idle", "2", "--duration", "60"],
                                stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, env=env)
    server = subprocess.Popen([*run, "serve", "--config", "dfs", "--listen", f"{LOOPBACK}:{serve_port}",
                               "--send", f"{LOOPBACK}:{machine_port}", "--out", str(tmp_path / "session"),
                               "--horizon", "1", "--quiet-end", "0.5", "--duration", "60", "--no-view",
                               "--console", f"{LOOPBACK}:{console_port}"],
                              stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, env=env)
    host = None
    try:
        said = server.stderr.readline()
        assert f"console at http://{LOOPBACK}:{console_port}/ (loopback: no token)" in said, said
        for _ in range(10):  # a line that it compiles may come before the one that it is ready
            said = server.stderr.readline()
            if "serving" in said or not said:
                break
        assert "serving dfs at 50 Hz" in said, said
        browser.get(f"http://{LOOPBACK}:{console_port}/")
        _until(lambda: browser.execute_script("return !!(window.consoleState && window.consoleState.connected)"),
               60, "the page connected")
        host = subprocess.Popen([*run, "host", "replay", str(short), "--to", f"{LOOPBACK}:{serve_port}"],
                                stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
        newest = "return window.consoleState.frame || {}"
        started = _until(lambda: browser.execute_script(newest).get("status") == "running"
                         and browser.execute_script(newest)["t"], 30, "the session running", browser)
        _until(lambda: browser.execute_script(newest)["t"] > started + 1.5, 10, "1.5 s of the host's motion")
        # what is drawn is the frame: the cabin of eq. A.7 at the frame's joints
        frame, drawn = browser.execute_script("const s = window.consoleState; return [s.frame, s.cabinMatrix()]")
        q = [frame["q"][j] for j in JOINT_NAMES]
        assert np.allclose(np.reshape(drawn, (4, 4)), kinematics.cabin_pose(q), atol=1e-9)
        browser.find_element("id", "park").click()
        assert browser.execute_script("return window.consoleState.frame.paused") is None  # not before confirmed
        browser.find_element("id", "yes").click()
        _until(lambda: browser.execute_script("return window.consoleState.frame.status") == "parked", 15, "parked")
        host.communicate(timeout=30)
        _until(lambda: browser.execute_script("return window.consoleState.ended"), 60, "the page told of the end", browser)
        banner = browser.find_element("id", "banner").text
        assert "The session is over: the session ended" in banner
        assert all(b.get_attribute("disabled") for b in browser.find_elements("css selector", "header button"))
        shown = browser.execute_script("return window.consoleState.drawn")
        server.communicate(timeout=60)
        checked, _ = stand_in.communicate(timeout=30)
    finally:
        for proc in (host, server, stand_in):
            if proc is not None and proc.poll() is None:
                proc.kill()
    assert server.returncode == 0
    # the page's live pose at sampled times is the session's log
    rows = {round(float(r["t"]) / H): r for r in _rows(tmp_path / "session" / "session.csv")}
    compared = 0
    for frame in shown[:: max(1, len(shown) // 25)]:
        row = rows[round(frame["t"] / H)]
        assert abs(float(row["t"]) - frame["t"]) < 1e-6
        for j in model.config.joint_names:
            assert abs(frame["q"][j] - float(row[f"commanded_{j}_position"])) <= 1e-6, (frame["t"], j)
            if frame["measured"] is not None:
                assert abs(frame["measured"][j] - float(row[f"measured_{j}_position"])) <= 1e-6
        compared += 1
    assert compared >= 10
    # the park: logged with its time and who sent it, and the machine at rest within the braking time
    events = _rows(tmp_path / "session" / "events.csv")
    (park,) = [e for e in events if e["what"] == "command park"]
    assert park["detail"].startswith(f"console {LOOPBACK}:")
    t_park = float(park["t"])
    setpoints = _rows(tmp_path / "machine" / "setpoints.csv")
    at = next(s for s in setpoints if float(s["cycle_time"]) >= t_park - 1e-9)
    lim, free = model.limits, model.config.joint_names
    qd = np.array([float(at[f"{j}_rate"]) for j in free])
    a = np.array([float(at[f"{j}_acceleration"]) for j in free])
    braking = float(np.max(stopping_time(qd, a, lim.acceleration, lim.jerk)))
    assert np.max(np.abs(qd)) > 0.1  # it was moving
    parked = next(float(s["cycle_time"]) for s in setpoints if s["status"] == "parked"
                  and float(s["cycle_time"]) > t_park)
    assert parked - t_park <= braking + 3 * H, (parked - t_park, braking)  # the stop and two settling cycles
    motion = _rows(tmp_path / "machine" / "motion.csv")
    after = [m for m in motion if m["applied_time"] not in ("", "nan") and float(m["applied_time"]) >= parked + H]
    assert after and max(abs(float(m[f"{j}_rate"])) for m in after for j in free) < 2e-3  # still, within the noise
    # its own check of every setpoint and of the motion made (its timing faults are the loaded machine's)
    assert json.loads((tmp_path / "machine" / "summary.json").read_text())["violation_count"] == 0, checked
    # no console error, no request but to its own host
    assert [e for e in browser.get_log("browser") if e["level"] == "SEVERE"] == []
    hosts = set()
    for entry in browser.get_log("performance"):
        message = json.loads(entry["message"])["message"]
        if message["method"] in ("Network.requestWillBeSent", "Network.webSocketCreated"):
            url = message["params"].get("request", {}).get("url") or message["params"].get("url")
            hosts.add(urlsplit(url).netloc)
    assert hosts == {f"{LOOPBACK}:{console_port}"}, hosts



def test_serve_says_a_bad_console_in_one_line_and_exits_2(tmp_path, capsys):
    """A token file others may read, a port in use: one line naming the option, exit 2, before the
    session (nothing but the claimed folder's log is begun)."""
    from desdemona.cli import main

    token = tmp_path / "token"
    token.write_text("a1b2c3d4e5f6a7b8c9d0e1f2a3b4c5d6\n")
    token.chmod(0o644)
    serving = ["serve", "--config", "dfs", "--listen", f"{LOOPBACK}:{_free_port()}", "--send",
               f"{LOOPBACK}:{_free_port()}", "--duration", "1"]
    assert main([*serving, "--out", str(tmp_path / "a"), "--console", "0.0.0.0:8765", "--console-token", str(token)]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "--console-token" in err and "chmod 600" in err, err
    with socket.socket(socket.AF_INET, socket.SOCK_STREAM) as taken:
        taken.bind((LOOPBACK, 0))
        taken.listen()
        assert main([*serving, "--out", str(tmp_path / "b"), "--console", f"{LOOPBACK}:{taken.getsockname()[1]}"]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "--console" in err and "in use" in err, err

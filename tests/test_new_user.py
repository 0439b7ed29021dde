"""What a new user met (issue 73): bad input is one line and exit 2, no minute passes in silence, a
log is imported without ringing and with its rate unit checked by physics, round-off reads as 0, and the
small faults of the commands' words and figures."""

import argparse
import json
import math
import re
import socket
import time
import warnings

import numpy as np
import pytest

from desdemona import profiles
from desdemona.baselines.classical import still_home
from desdemona.check import metrics
from desdemona.cli import main, options
from desdemona.machine.model import Model
from desdemona.profiles import convert
from desdemona.profiles.log import STANDARD_GRAVITY
from desdemona.results import compare, figures, report
from desdemona.service import serve
from desdemona.support import guard

QUICK = ["cosine", "--config", "yaw-track", "--h-u", "0.1", "--starts", "1", "--no-view"]


def _one_line(err: str) -> str:
    assert err.count("\n") == 1 and "Traceback" not in err, err
    return err


# ---- 1. one line, exit 2, at once --------------------------------------------------------------------

@pytest.mark.parametrize("argv, words", [
    pytest.param(["optimize", "dfs-catapult", "--config", "dfs", "--method", "thesis"], "gives only the modulus",
                 id="thesis-on-a-modulus"),
    pytest.param(["optimize", *QUICK, "--seed", "-1"], "--seed -1", id="negative-seed"),
    pytest.param(["optimize", *QUICK[:-3], "--starts", "1000000"], "at most 100: each start is a whole solve",
                 id="starts-bounded-optimize"),  # before: ran until killed, 16 GB of guesses
    pytest.param(["batch", "cosine", "--configs", "yaw-track", "--starts", "1000000"], "at most 100",
                 id="starts-bounded-batch"),
    pytest.param(["optimize", *QUICK, "--out", ""], "--out '': give a name", id="empty-out"),
    pytest.param(["profiles", "catapult", "--csv", ""], "--csv '': give a name", id="empty-csv"),
])
def test_bad_input_is_one_line_and_exit_2_at_once(tmp_path, capsys, argv, words):
    out = [] if "--out" in argv or "--csv" in argv else ["--out", str(tmp_path / "r")]
    begin = time.perf_counter()
    assert main([*argv, *out]) == 2
    assert time.perf_counter() - begin < 5.0
    assert words in _one_line(capsys.readouterr().err)
    assert list(tmp_path.iterdir()) == []


def _closed_port() -> int:
    with socket.socket(socket.AF_INET, socket.SOCK_STREAM) as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]  # closed again: nothing listens there


def test_an_unreachable_dask_scheduler_is_one_line_within_5_s(tmp_path, capsys):
    """Before: a 30 s wait and a 54-line traceback."""
    begin = time.perf_counter()
    argv = ["batch", "catapult", "car-lap", "--configs", "full", "--out", str(tmp_path / "r"),
            "--dask", f"tcp://127.0.0.1:{_closed_port()}"]
    assert main(argv) == 2
    assert time.perf_counter() - begin < 5.0
    assert "no Dask scheduler there" in _one_line(capsys.readouterr().err)
    assert list(tmp_path.iterdir()) == []


# ---- 2. no silent minutes --------------------------------------------------------------------------

def test_a_long_compile_is_told_and_the_clock_speaks_within_every_period(capsys):
    """A step that says nothing (compiling into the cache) is told as it begins and ends with its
    time, and the command's clock names it at least every ``every`` seconds meanwhile; its time adds
    to what the command prints apart from the solve."""
    from desdemona.cli import progress

    before = guard.compile_seconds()
    with progress.Progress("solving", every=0.4, tty=False) as told, guard.reporting(None, tell=told.say):
        with guard.lasting("compiling the test", ", once, into the cache"):
            time.sleep(1.7)
    lines = capsys.readouterr().err.splitlines()
    assert lines[0] == "desdemona: compiling the test, once, into the cache"
    assert lines[-1].startswith("desdemona: compiling the test: 1.")
    assert len([line for line in lines if "compiling the test (" in line and "s so far" in line]) >= 3
    assert guard.compile_seconds() - before >= 1.7


def test_optimize_prints_the_compile_apart_from_the_solve(tmp_path, monkeypatch, capsys):
    from desdemona.cueing import offline

    real = offline._problems

    def compiling_first(*args, **kwargs):  # as a fresh cache does, as the problem is built
        with guard.lasting("compiling (a stand-in)"):
            time.sleep(1.0)
        return real(*args, **kwargs)

    monkeypatch.setattr(offline, "_problems", compiling_first)
    begin = time.perf_counter()
    assert main(["optimize", *QUICK, "--out", str(tmp_path / "r")]) == 0
    wall = time.perf_counter() - begin
    line = capsys.readouterr().out.splitlines()[0]
    solve, compiled = (float(x) for x in re.search(r", ([\d.]+) s \(and ([\d.]+) s compiling\)", line).groups())
    assert compiled >= 1.0 and solve < wall - 1.0


def test_online_shows_its_progress(tmp_path, monkeypatch, capsys):
    """On a terminal one line drawn over itself; otherwise a line every EVERY seconds."""
    from desdemona.cli import progress

    with progress.OnlineProgress(10.0, tty=True) as told:
        told.cycle(2.5)
    assert "\r  on-line: 2.5 of 10.0 s of the path" in capsys.readouterr().err
    monkeypatch.setattr(progress, "EVERY", 0.3)
    assert main(["online", "cosine", "--config", "yaw-track", "--step", "0.1", "--horizon", "1",
                 "--out", str(tmp_path / "r"), "--no-view"]) == 0
    assert "desdemona: on-line: " in capsys.readouterr().err


# ---- 3. import log without ringing -----------------------------------------------------------------

def _write_log(file, t, f_g, w=None):
    """A log in the default layout (t, ax, ay, az in g, p, q, r in rad/s; forward, right, down)."""
    w = np.zeros_like(f_g) if w is None else w
    with open(file, "w") as out:
        out.write("t,ax,ay,az,p,q,r\n")
        for row in np.column_stack([t, f_g, w]):
            out.write(",".join(repr(float(x)) for x in row) + "\n")
    return file


def test_a_step_at_the_logs_own_rate_stays_a_step(tmp_path, capsys):
    """A 0.3 g step at 100 Hz, imported at 100 Hz: before, through a zero-phase Butterworth, it read
    +8.6 % over the step, dipped before it and wrote values like -3e-123."""
    t = np.arange(0.0, 10.0, 0.01)
    f = np.column_stack([np.where(t >= 5.0, 0.3, 0.0), np.zeros_like(t), -np.ones_like(t)])
    log = _write_log(tmp_path / "step.csv", t, f)
    assert main(["import", "log", str(log), "--accel-unit", "g", "--rate-unit", "rad/s",
                 "--out", str(tmp_path / "p.csv")]) == 0
    path = profiles.load(tmp_path / "p.csv")
    fy, step = path.S_d[:, 4], 0.3 * STANDARD_GRAVITY
    assert np.all(np.diff(fy) >= -0.01 * step) and fy.min() >= -0.01 * step and fy.max() <= 1.01 * step
    tiny = np.abs(path.S_d[(path.S_d != 0.0)])
    assert tiny.min() >= 1e-12
    assert "no anti-alias filter" in (tmp_path / "p.csv").read_text()


def test_a_lower_rate_still_removes_what_would_alias(tmp_path):
    """A 40 Hz tone in a 200 Hz log imported at 50 Hz (Nyquist 25 Hz) would fold to 10 Hz: it is gone;
    a 2 Hz tone beside it is kept (the filter's gain is 0.99 there)."""
    t = np.arange(0.0, 12.0, 0.005)
    moving = t >= 3.0
    slow, fast = 0.1 * np.sin(2 * np.pi * 2.0 * t) * moving, 0.1 * np.sin(2 * np.pi * 40.0 * t) * moving
    for name, tone in (("slow", slow), ("fast", fast)):
        f = np.column_stack([tone, np.zeros_like(t), -np.ones_like(t)])
        log = _write_log(tmp_path / f"{name}.csv", t, f)
        assert main(["import", "log", str(log), "--accel-unit", "g", "--rate-unit", "rad/s", "--rate", "50",
                     "--out", str(tmp_path / f"{name}-p.csv")]) == 0
    kept = profiles.load(tmp_path / "slow-p.csv").S_d[:, 4] / STANDARD_GRAVITY
    gone = profiles.load(tmp_path / "fast-p.csv").S_d[:, 4] / STANDARD_GRAVITY
    inside = (np.arange(len(gone)) / 50.0 > 4.0) & (np.arange(len(gone)) / 50.0 < 11.0)
    assert np.std(gone[inside]) < 0.01 * np.std(fast[moving])
    assert np.std(kept[inside]) > 0.95 * np.std(slow[moving])
    assert np.all(convert.gaussian_lowpass(np.zeros((50, 1)), 200.0, 50.0) == 0.0)  # 0 stays exactly 0
    np.testing.assert_allclose(convert.gaussian_lowpass(np.full((50, 1), 9.81), 200.0, 50.0), 9.81, rtol=1e-14)


# ---- 4. the rate unit by gyro against gravity ---------------------------------------------------------

def _tilting(file, deg_s: float, unit: str, seconds: float = 20.0):
    """A sensor still for 2 s, rolling at ``deg_s`` about its x axis for ``seconds``, still again: its
    accelerometer sees gravity turn (forward, right, down axes; in g), its gyro logged in ``unit``."""
    t = np.arange(0.0, seconds + 4.0, 0.01)
    rate = np.where((t >= 2.0) & (t < 2.0 + seconds), math.radians(deg_s), 0.0)
    angle = np.cumsum(rate) * 0.01
    f = np.column_stack([np.zeros_like(t), -np.sin(angle), -np.cos(angle)])
    w = np.column_stack([rate, np.zeros_like(t), np.zeros_like(t)]) * (180.0 / math.pi if unit == "deg/s" else 1.0)
    return _write_log(file, t, f, w)


@pytest.mark.parametrize("deg_s", [1.0, 9.0, 30.0])
def test_rates_in_deg_s_declared_rad_s_are_refused_at_any_rate(tmp_path, capsys, deg_s):
    log = _tilting(tmp_path / "log.csv", deg_s, "deg/s")
    argv = ["import", "log", str(log), "--accel-unit", "g", "--out", str(tmp_path / "p.csv")]
    assert main(argv + ["--rate-unit", "rad/s"]) == 2
    err = _one_line(capsys.readouterr().err)
    assert "57.3 times as fast" in err and "--rate-unit deg/s" in err
    assert not (tmp_path / "p.csv").exists()
    assert main(argv + ["--rate-unit", "deg/s"]) == 0


def test_the_rate_check_passes_real_motion_in_its_unit():
    """Every built-in path and a yaw alone (gravity's direction does not turn: nothing to tell) pass;
    the factor read is 1 where the log tilts, 1/57.3 for its rates in deg/s taken for rad/s."""
    from desdemona.profiles import turns

    for name in profiles.PROFILES:
        path = profiles.get_profile(name)
        if path.S_d is not None:
            assert turns.rate_unit_problem(path.t, path.S_d[:, :3], path.S_d[:, 3:], "rad/s") is None, name
    t = np.arange(0.0, 20.0, 0.01)
    spin = np.column_stack([np.zeros_like(t), np.zeros_like(t), np.full_like(t, 9.0)])  # 9 "rad/s" of yaw
    still = np.tile([0.0, 0.0, 9.81], (len(t), 1))
    assert turns.turn_ratio(t, spin, still) is None
    angle = 0.5 * t
    roll = np.column_stack([np.full_like(t, 0.5), np.zeros_like(t), np.zeros_like(t)])
    f = 9.81 * np.column_stack([np.zeros_like(t), np.sin(angle), np.cos(angle)])
    assert turns.turn_ratio(t, roll, f)[0] == pytest.approx(1.0, rel=0.02)
    assert turns.turn_ratio(t, roll * 180 / math.pi, f)[0] == pytest.approx(math.pi / 180, rel=0.02)


# ---- 5. a path's time shift ---------------------------------------------------------------------------

def test_a_path_whose_time_starts_later_is_said_and_kept(tmp_path, capsys):
    path = profiles.get_profile("cosine")
    rows = np.column_stack([path.t + 5.0, path.S_d])
    file = tmp_path / "late.csv"
    file.write_text("t,wx,wy,wz,fx,fy,fz\n" + "\n".join(",".join(repr(float(x)) for x in r) for r in rows) + "\n")
    assert main(["optimize", str(file), *QUICK[1:], "--out", str(tmp_path / "r")]) == 0
    err = capsys.readouterr().err
    assert "late.csv: its time starts at 5 s, read as t = 0" in err
    summary = json.loads((tmp_path / "r" / "summary.json").read_text())
    assert summary["time_origin_s"] == 5.0 and "its time from 5 s as t = 0" in summary["path"]["description"]


# ---- 6. the service: ready, early datagrams, a port in use -------------------------------------------

def test_serve_refuses_a_port_in_use_before_building_anything(tmp_path, monkeypatch, capsys):
    built = []
    monkeypatch.setattr(serve, "MPC", lambda *a, **k: built.append(1))
    with socket.socket(socket.AF_INET, socket.SOCK_DGRAM) as taken:
        taken.bind(("127.0.0.1", 0))
        port = taken.getsockname()[1]
        assert main(["serve", "--config", "dfs", "--listen", f"127.0.0.1:{port}", "--send", "127.0.0.1:9",
                     "--out", str(tmp_path / "s"), "--no-view"]) == 2
    assert f"--listen 127.0.0.1:{port}" in _one_line(capsys.readouterr().err) and not built


def test_serve_says_it_is_ready_and_how_many_datagrams_came_before(tmp_path, monkeypatch, capsys):
    """A host started with serve (the README's ``&``) sends while the controller is built: the socket
    is bound first, so the datagrams wait there, and the ready line counts them."""
    from desdemona.service import protocol

    real = serve.listening

    def host_started_early(address):
        sock = real(address)
        with socket.socket(socket.AF_INET, socket.SOCK_DGRAM) as host:
            for k in range(5):
                host.sendto(protocol.pack(protocol.Motion(k + 1, 0.01 * k, np.array([9.81]))), address)
        return sock

    monkeypatch.setattr(serve, "listening", host_started_early)
    with socket.socket(socket.AF_INET, socket.SOCK_DGRAM) as probe:
        probe.bind(("127.0.0.1", 0))
        port = probe.getsockname()[1]
    main(["serve", "--config", "dfs", "--listen", f"127.0.0.1:{port}", "--send", "127.0.0.1:9",
          "--duration", "0.2", "--out", str(tmp_path / "s"), "--no-view"])
    ready = [line for line in capsys.readouterr().err.splitlines() if ", ready:" in line]
    assert len(ready) == 1 and "serving dfs at 50 Hz, ready" in ready[0]
    assert "5 host datagrams came before it was ready" in ready[0]


# ---- 7. round-off and small faults -----------------------------------------------------------------------

def test_round_off_is_printed_as_0_and_written_as_computed(tmp_path, capsys):
    """The cosine on yaw-track has no rotation to cue: its false rotation is round-off (1e-25 deg/s)."""
    assert main(["optimize", *QUICK, "--out", str(tmp_path / "r")]) == 0
    out = capsys.readouterr().out
    assert "peak false rotation 0 deg/s" in out and "e-2" not in out
    quality = json.loads((tmp_path / "r" / "summary.json").read_text())["quality"]
    written = quality["channels"]["peak_false_cue"]["wz"]
    assert 0.0 < abs(written) < metrics.ROUND_OFF  # summary.json as computed, for the tools that read it
    table = compare.table(compare.load_results([tmp_path / "r", tmp_path / "r"]))
    assert "e-1" not in table and "e-2" not in table
    assert metrics.shown(1.505e-16) == 0.0 and metrics.shown(-0.2) == -0.2 and metrics.shown(None) is None


def test_the_model_table_keeps_its_columns_for_long_joint_names(capsys):
    assert main(["model", "--config", "full"]) == 0
    lines = capsys.readouterr().out.splitlines()
    header = next(line for line in lines if "position" in line and "joint" in line)
    rows = [line for line in lines if line.strip().startswith("* q")]
    assert len(rows) == 6
    for row in rows:  # every value ends where its column's title ends
        assert row[:header.index("position") + len("position")].endswith(("unbounded", "m", "deg")), row
        assert row[header.index("position") + len("position")] == " "


def test_reading_a_folder_that_is_missing_or_empty_is_one_plain_line(tmp_path, capsys):
    (tmp_path / "empty").mkdir()
    for argv in (["plot", str(tmp_path / "nope")], ["view", str(tmp_path / "nope")],
                 ["compare", str(tmp_path / "empty")], ["plot", str(tmp_path / "empty")]):
        assert main(argv) == 2
        err = _one_line(capsys.readouterr().err)
        assert "Errno" not in err and ("no such folder" in err or "has no summary.json" in err)


def test_an_empty_folder_is_a_new_one_for_every_command(tmp_path, capsys):
    """The README's one rule: without --overwrite, a command writes into a new or empty folder."""
    (tmp_path / "r").mkdir()
    assert main(["optimize", *QUICK, "--out", str(tmp_path / "r")]) == 0
    assert report.is_result_folder(tmp_path / "r")
    (tmp_path / "c").mkdir()
    assert main(["compare", str(tmp_path / "r"), "--out", str(tmp_path / "c")]) == 0
    assert main(["optimize", *QUICK, "--out", str(tmp_path / "r")]) == 2  # not empty now
    assert "already exists" in capsys.readouterr().err


def _commands(parser, prefix=""):
    """(name, parser) of every command and subcommand."""
    for action in parser._actions:
        if isinstance(action, argparse._SubParsersAction):
            for name, sub in action.choices.items():
                yield f"{prefix}{name}", sub
                yield from _commands(sub, f"{prefix}{name} ")


def test_every_positional_argument_and_the_batch_starts_are_explained():
    commands = dict(_commands(options.build_parser()))
    for name, sub in commands.items():
        for action in sub._actions:
            if not action.option_strings and not isinstance(action, argparse._SubParsersAction):
                assert action.help, f"{name} {action.metavar}"
    assert {"plot", "batch", "host replay"} <= set(commands)
    starts = next(a for a in commands["batch"]._actions if "--starts" in a.option_strings)
    assert "default: 2" in starts.help and "optimize's 4" in starts.help


def test_a_still_home_of_unbounded_joints_computes_without_warnings():
    model = Model(config="full")
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        home = still_home(np.zeros(6), model)
    assert home[1] == 0.0 and home[2] == 0.0  # the track and heave: their centres


def test_every_joint_label_fits_its_axes(tmp_path):
    """Before, "outer_gimbal (held) [deg]" ran past its axes on a configuration that holds it."""
    assert main(["optimize", "cosine", "--config", "yaw-track-cabin", "--h-u", "0.2", "--starts", "1", "--no-view",
                 "--out", str(tmp_path / "r")]) == 0
    traj, summary = report.load(tmp_path / "r")
    fig = figures._joints_figure(traj, summary)
    fig.tight_layout()
    from matplotlib.backends.backend_agg import FigureCanvasAgg

    renderer = FigureCanvasAgg(fig).get_renderer()
    for ax in fig.axes:
        label, box = ax.yaxis.label.get_window_extent(renderer), ax.get_window_extent(renderer)
        assert label.y0 >= box.y0 - 1 and label.y1 <= box.y1 + 1, ax.get_ylabel()

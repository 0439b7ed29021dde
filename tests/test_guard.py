"""Safe with the user's files and time: --overwrite, interrupts, runaway inputs, progress, exit codes."""

import csv
import functools
import json
import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest

import desdemona
from desdemona import cli, profiles
from desdemona.cli import commands, main
from desdemona.cueing import formulation as problem
from desdemona.results import report
from desdemona.support import guard

SHORT = ["cosine", "--config", "yaw-track", "--h-u", "0.1", "--starts", "1"]


def _optimize(out, *extra):
    return main(["optimize", *SHORT, "--out", str(out), *extra])


def test_overwrite_replaces_only_a_result_folder(tmp_path, monkeypatch, capsys):
    monkeypatch.chdir(tmp_path)
    data = tmp_path / "data"
    data.mkdir()
    (data / "keep.txt").write_text("the user's")
    (tmp_path / "notes.txt").write_text("also the user's")
    for out in ("data", "notes.txt", ".", ".."):
        assert _optimize(out, "--overwrite") == 2, out
        err = capsys.readouterr().err
        assert err.count("\n") == 1 and "--overwrite replaces only a desdemona result folder" in err
    assert (data / "keep.txt").read_text() == "the user's"
    assert (tmp_path / "notes.txt").read_text() == "also the user's"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["data", "notes.txt"]  # no temporary left over
    # an earlier result is replaced, but not once the user has put a file of theirs in it
    assert _optimize("run") == 0 and _optimize("run", "--overwrite") == 0
    assert json.loads((tmp_path / "run" / "summary.json").read_text())["format"] == "desdemona result"
    (tmp_path / "run" / "mine.txt").write_text("x")
    assert _optimize("run", "--overwrite") == 2 and (tmp_path / "run" / "mine.txt").exists()


def test_overwrite_never_replaces_the_folder_of_the_input(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    assert _optimize("run") == 0
    profiles.write_csv(tmp_path / "run" / "trajectory.csv", profiles.cosine(duration=1.0))  # looks like ours
    assert main(["optimize", "run/trajectory.csv", "--config", "yaw-track", "--h-u", "0.1", "--starts", "1",
                 "--out", "run", "--overwrite"]) == 2


def test_result_folder_respects_the_umask_and_names_its_columns(tmp_path):
    old = os.umask(0o022)
    try:
        assert _optimize(tmp_path / "run") == 0
    finally:
        os.umask(old)
    assert (tmp_path / "run").stat().st_mode & 0o777 == 0o755
    with open(tmp_path / "run" / "trajectory.csv") as fh:
        rows = csv.DictReader(line for line in fh if not line.startswith("#"))
        first = next(rows)
    assert float(first["t"]) == 0.0 and "q_track" in first and "fy_d" in first
    traj, _ = report.load(tmp_path / "run")
    assert traj.q.shape[1] == 2
    # folders of earlier versions, with the names in a comment, still load
    lines = (tmp_path / "run" / "trajectory.csv").read_text().splitlines()
    (tmp_path / "run" / "trajectory.csv").write_text("\n".join([lines[0], "# " + lines[1], *lines[2:]]) + "\n")
    assert (report.load(tmp_path / "run")[0].q == traj.q).all()


@pytest.mark.realtime
@pytest.mark.parametrize("method", ["ipopt", "fatrop"])
def test_sigint_inside_the_solver_stops_the_run(tmp_path, method):
    """Acceptance: SIGINT 2 s into the car lap on full ends the process within 5 s, exit 130, nothing
    written: inside IPOPT, and with fatrop (its default there) wherever it is, compiling or solving."""
    env = dict(os.environ, PYTHONPATH=str(Path(desdemona.__file__).resolve().parent.parent))
    out = tmp_path / "lap"
    start = time.perf_counter()
    proc = subprocess.Popen([sys.executable, "-m", "desdemona", "optimize", "car-lap", "--config", "full",
                             "--method", method, "--starts", "2", "--out", str(out)], env=env,
                            stderr=subprocess.PIPE, text=True)
    # its first line says the command has started (on a loaded machine Python's imports alone may take 2 s)
    assert "700 control intervals" in proc.stderr.readline()
    time.sleep(max(0.0, 2.0 - (time.perf_counter() - start)))
    proc.send_signal(signal.SIGINT)
    sent = time.perf_counter()
    try:
        err = proc.stderr.read()
        proc.wait(timeout=5.0)
    finally:
        proc.kill()
    assert time.perf_counter() - sent < 5.0
    assert proc.returncode == 130, err
    assert err.strip().splitlines()[-1] == "desdemona: interrupted (SIGINT): stopped, no partial result written"
    assert list(tmp_path.iterdir()) == []


@pytest.mark.realtime
def test_millisecond_time_column_is_refused_at_once(tmp_path, capsys):
    path = tmp_path / "ms.csv"
    path.write_text("t,wx,wy,wz,fx,fy,fz\n" + "".join(f"{500 * k},0,0,0,0,1,9.81\n" for k in range(61)))
    start = time.perf_counter()
    assert main(["optimize", str(path), "--config", "full", "--out", str(tmp_path / "r")]) == 2
    assert time.perf_counter() - start < 2.0
    assert "column 't' looks like milliseconds" in capsys.readouterr().err


def test_batch_with_one_bad_csv_stops_before_any_job(tmp_path, capsys):
    good, bad = tmp_path / "good.csv", tmp_path / "bad.csv"
    profiles.write_csv(good, profiles.cosine(duration=1.0))
    bad.write_text(good.read_text().replace("0.5,", "nan,", 1))
    out = tmp_path / "runs"
    assert main(["batch", str(good), str(bad), "cosine", "--configs", "yaw-track", "--out", str(out),
                 "--h-u", "0.1", "--starts", "1"]) == 2
    err = capsys.readouterr().err
    assert "bad.csv: line" in err and "not a finite number" in err and err.count("\n") == 1
    assert not out.exists()
    # a modulus-only path on a configuration that needs the full path: also before any job
    (tmp_path / "m.csv").write_text("t,M\n0,9.81\n1,12\n")
    assert main(["batch", str(tmp_path / "m.csv"), "--configs", "dfs", "yaw-track", "--out", str(out)]) == 2
    assert not out.exists()


def test_progress_lines_when_stderr_is_not_a_terminal(tmp_path, monkeypatch, capsys):
    """A line when the run starts, per start (elapsed time, best cost) and, inside a long solve, every
    PROGRESS_EVERY s; --quiet silences them. (By hand: the README's car lap on full, 3 min, prints a line
    every 10 s.)"""
    monkeypatch.setattr(commands, "PROGRESS_EVERY", 0.0)
    # the lines inside a solve come from this process: one worker (starts in parallel workers report
    # as each ends)
    assert main(["optimize", "cosine", "--config", "yaw-track", "--h-u", "0.1", "--starts", "2", "--workers", "1",
                 "--out", str(tmp_path / "a")]) == 0
    err = capsys.readouterr().err
    assert "50 control intervals" in err
    assert "start 1/2 done" in err and "start 2/2 done" in err and "best cost so far" in err
    assert "solving: iteration 1," in err
    assert "ends about" in err.splitlines()[0] and "start 1/2 done" in err and ", ends about " in err
    assert _optimize(tmp_path / "b", "--quiet") == 0
    assert capsys.readouterr().err == ""


def test_the_clock_says_solving_once_the_problem_is_built(tmp_path, capsys):
    """The clock's line names the work in hand: "building the problem" until the problem is built,
    then the starts being solved (a 30 s start in a worker was told as building for its whole time),
    and a window keeps its window's name. No line is said for the built problem itself."""
    from desdemona import Model
    from desdemona.cli.progress import OfflineProgress
    from desdemona.cueing.offline import OptimizeOptions, optimize

    told = []
    with OfflineProgress(2, None, None, None, tty=True) as progress:
        assert progress.doing == "building the problem"

        def tell(done, total, best):
            told.append((done, progress.doing))
            progress.start_done(done, total, best)
        optimize(profiles.load("cosine"), Model(config="yaw-track"),
                 OptimizeOptions(problem.ProblemOptions(h_u=0.1), starts=2), progress=tell)
        assert told[:2] == [(0, "building the problem"), (1, "solving: 0 of 2 starts done")]
        progress.window(3, 7, 30.0, 60.0)
        progress.start_done(0, 2, float("inf"))
        assert progress.doing == "window 3/7"
    assert "0/2" not in capsys.readouterr().err


def test_a_ctrl_c_while_the_table_of_commands_is_built_exits_130_in_one_line(monkeypatch, capsys):
    """Found by the suite under load: a Ctrl-C 0.6 s into `optimize` came while argparse built the
    commands, before any handler, and ended in a traceback (exit -2)."""
    def interrupted():
        raise KeyboardInterrupt
    monkeypatch.setattr(cli, "build_parser", interrupted)
    assert main(["profiles"]) == 130
    err = capsys.readouterr().err
    assert err.startswith("desdemona: interrupted") and err.count("\n") == 1


def test_iteration_cap_is_reported_as_not_converged(tmp_path, monkeypatch, capsys):
    monkeypatch.setattr(problem, "ProblemOptions", functools.partial(problem.ProblemOptions, max_iter=3))
    assert _optimize(tmp_path / "r") == cli.EXIT_NOT_CONVERGED
    assert "solver Maximum_Iterations_Exceeded (NOT CONVERGED)" in capsys.readouterr().out
    solver = json.loads((tmp_path / "r" / "summary.json").read_text())["solver"]
    assert solver["converged"] is False and solver["status"] == "Maximum_Iterations_Exceeded"


def test_unreachable_target_is_reported_not_refused(tmp_path, capsys):
    path = tmp_path / "low.csv"
    path.write_text("t,M\n0,9.81\n1,7\n2,7\n3,9.81\n")
    assert main(["optimize", str(path), "--config", "dfs", "--h-u", "0.1", "--starts", "1",
                 "--out", str(tmp_path / "r")]) == 0
    assert "of the time below g 9.81 m/s^2 (worst 7)" in capsys.readouterr().out
    below = json.loads((tmp_path / "r" / "summary.json").read_text())["unreachable"]["below_g"]
    assert below["worst_m_s2"] == 7.0 and below["share_of_time"] == 0.5  # two of four equal samples


def test_exit_codes_are_documented(capsys):
    assert main(["--help"]) == 0
    out = capsys.readouterr().out
    for code in ("0 ", "2 ", "3 ", "4 ", "130"):
        assert f"\n  {code}" in out


def test_fatrop_status_in_words(tmp_path):
    """fatrop's return code in IPOPT's words, and its linear algebra (desdemona.cueing.blasfeo) in the summary."""
    from desdemona import Model
    from desdemona.cueing import blasfeo
    from desdemona.cueing.offline import OptimizeOptions, optimize

    result = optimize(profiles.cosine(duration=1.0), Model(config="yaw-track"),
                      options=OptimizeOptions(problem.ProblemOptions(h_u=0.1, solver="fatrop"), starts=1))
    assert result.solution.status == "Solve_Succeeded" and result.converged
    summary = json.loads((report.write(result, tmp_path / "run", view=False) / "summary.json").read_text())
    assert summary["solver"]["linear_algebra"] == blasfeo.status() is not None


def _guarded(tmp_path, body: str) -> subprocess.Popen:
    """A process that runs ``body`` inside guard.interruptible() and exits as the command line does."""
    script = tmp_path / "guarded.py"
    script.write_text(
        "import sys\nimport numpy as np\nfrom desdemona.support import guard\n"
        "a = np.random.default_rng(0).random((2500, 2500))\n"
        "print('ready', flush=True)\n"
        "try:\n    with guard.interruptible():\n" + "".join(f"        {line}\n" for line in body.splitlines())
        + "except guard.Interrupted as exc:\n    sys.exit(exc.code)\n")
    proc = subprocess.Popen([sys.executable, str(script)], stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    assert proc.stdout.readline().strip() == "ready"
    return proc


@pytest.mark.realtime
def test_sigint_inside_compiled_code_that_never_returns_ends_the_process_within_two_seconds(tmp_path):
    """One long call into compiled code (an eigen-decomposition of 10 s or more here) keeps Python's
    handler from running; the watchdog ends the process GRACE seconds after the signal."""
    proc = _guarded(tmp_path, "np.linalg.eigvals(a)\nprint('finished', flush=True)")
    time.sleep(0.5)
    sent = time.perf_counter()
    proc.send_signal(signal.SIGINT)
    out, err = proc.communicate(timeout=60)
    assert proc.returncode == 130 and "finished" not in out
    assert time.perf_counter() - sent < guard.GRACE + 1.0
    assert err.strip() == "desdemona: interrupted (SIGINT): stopped, no partial result written"


@pytest.mark.realtime
def test_the_watchdog_waits_for_a_block_that_holds_signals_back(tmp_path):
    """A signal inside guard.deferred() (renaming a result into place) is delivered when it ends, by the
    main thread, however long the block takes: the watchdog does not cut it in two."""
    # the signals are held back inside the block, so its Python loop is one piece: longer than GRACE
    proc = _guarded(tmp_path, "import time\nwith guard.deferred():\n    start = time.perf_counter()\n"
                              f"    while time.perf_counter() - start < {guard.GRACE + 1.0}:\n"
                              "        np.linalg.eigvals(a[:300, :300])\n"
                              "    print('block done', flush=True)\nprint('after', flush=True)")
    time.sleep(0.3)
    proc.send_signal(signal.SIGINT)
    out, _ = proc.communicate(timeout=60)
    assert proc.returncode == 130
    assert out.split() == ["block", "done"]


def test_the_end_is_estimated_from_the_pace_or_the_estimate():
    """10 s for half of the work: 10 s more; nothing done yet after 10 s of an estimated 100: 90 more."""

    def seconds_ahead(end: str) -> float:
        now = time.localtime()
        hours, minutes, seconds = map(int, end.split(":"))
        return ((hours - now.tm_hour) * 3600 + (minutes - now.tm_min) * 60 + seconds - now.tm_sec) % 86400

    assert 8 <= seconds_ahead(guard.estimated_end(time.perf_counter() - 10.0, 1, 2)) <= 12
    assert 88 <= seconds_ahead(guard.estimated_end(time.perf_counter() - 10.0, 0, 2, estimate=100.0)) <= 92


def test_an_online_run_tells_its_estimate_and_end(capsys):
    """An on-line run estimated longer than the clock's period says so as it starts, with its end; as
    it runs, what it does names the end at its pace."""
    from desdemona.cli.progress import OnlineProgress

    with OnlineProgress(12.0, tty=False, estimate=600.0) as progress:
        progress.cycle(3.0)
        assert progress.doing.startswith("on-line: 3.0 of 12.0 s of the path, ends about ")
    assert "desdemona: on-line: about 10 min (ends about " in capsys.readouterr().err
    with OnlineProgress(12.0, tty=False, estimate=5.0):
        pass
    assert capsys.readouterr().err == ""  # a short run: no line

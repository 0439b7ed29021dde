"""Never lose the user's work: concurrent runs, batch and compare folders, runaway sizes,
tracebacks and unclear messages, each as a new user meets it on the command line."""

import csv
import json
import os
import shutil
import signal
import subprocess
import sys
import time
from pathlib import Path

import numpy as np
import pytest

import desdemona
from desdemona import profiles
from desdemona.cli import main
from desdemona.control import online
from desdemona.cueing import sizing
from desdemona.results import figures, report

QUICK = ["cosine", "--config", "yaw-track", "--h-u", "0.1", "--starts", "1"]
BATCH = ["--configs", "yaw-track", "--h-u", "0.5", "--starts", "1", "--processes", "1"]
ENV = dict(os.environ, PYTHONPATH=str(Path(desdemona.__file__).resolve().parent.parent))


def _optimize(out, *extra):
    return main(["optimize", *QUICK, "--out", str(out), *extra])


def _command(*args):
    """The ``desdemona`` command as a user runs it (the console script, else ``python -m``)."""
    script = shutil.which("desdemona")
    return [script, *args] if script else [sys.executable, "-m", "desdemona", *args]


@pytest.fixture(scope="module")
def result_folder(tmp_path_factory):
    out = tmp_path_factory.mktemp("result") / "run"
    assert _optimize(out) == 0
    return out


@pytest.fixture(scope="module")
def batch_folder(tmp_path_factory):
    out = tmp_path_factory.mktemp("batch") / "runs"
    assert main(["batch", "cosine", *BATCH, "--out", str(out)]) == 0
    return out


# ---- row 1: two runs on the same --out ---------------------------------------------------------------

def test_a_second_run_on_the_same_folder_is_refused_naming_the_first(tmp_path, capsys):
    out = tmp_path / "same"
    first = subprocess.Popen(_command("optimize", *QUICK, "--out", str(out), "--quiet"), env=ENV,
                             stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    try:
        lock = report.lock_path(out)
        deadline = time.monotonic() + 30.0
        while not lock.exists() and first.poll() is None and time.monotonic() < deadline:
            time.sleep(0.01)
        assert lock.exists(), "the first run holds no lock on its folder"
        assert _optimize(out) == 2
        err = capsys.readouterr().err
        assert f"process {first.pid}" in err and "another desdemona run is writing it" in err
        assert err.count("\n") == 1
        first.communicate(timeout=60)
    finally:
        first.kill()
    assert first.returncode == 0
    assert json.loads((out / "summary.json").read_text())["command"].startswith("desdemona optimize")
    assert not lock.exists()  # released at its end


def test_a_lock_left_by_a_run_that_has_ended_is_taken_over(tmp_path):
    ended = subprocess.run([sys.executable, "-c", "import os; print(os.getpid())"], capture_output=True, text=True)
    out = tmp_path / "r"
    report.lock_path(out).write_text(f"{ended.stdout.strip()}\ndesdemona optimize killed\n")
    assert _optimize(out) == 0
    assert not report.lock_path(out).exists()


# ---- row 2: a folder created at --out while the figures are drawn -----------------------------------

@pytest.mark.parametrize("earlier", [False, True])
def test_a_folder_that_appears_while_the_run_writes_is_never_removed(tmp_path, monkeypatch, capsys, earlier):
    out = tmp_path / "r"
    if earlier:
        assert _optimize(out) == 0
    draw = figures.draw_result

    def draw_while_the_user_works(traj, summary, folder):
        if earlier:
            (out / "notes.txt").write_text("the user's")  # into the earlier result, during the run
        else:
            out.mkdir()
            (out / "notes.txt").write_text("the user's")
        return draw(traj, summary, folder)

    monkeypatch.setattr(figures, "draw_result", draw_while_the_user_works)
    assert _optimize(out, *(["--overwrite"] if earlier else [])) == 2
    assert "nothing written" in capsys.readouterr().err
    assert (out / "notes.txt").read_text() == "the user's"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["r"]  # no temporary or lock left over


# ---- rows 3, 7, 11: batch ----------------------------------------------------------------------------

def test_batch_replaces_only_what_it_wrote_and_only_with_overwrite(batch_folder, tmp_path, capsys):
    job = batch_folder / "cosine--yaw-track" / "summary.json"
    written = job.stat().st_mtime_ns
    assert main(["batch", "cosine", *BATCH, "--out", str(batch_folder)]) == 2
    assert "already exists" in capsys.readouterr().err and job.stat().st_mtime_ns == written
    # the user's own batch.csv (or any file of theirs) is never replaced, not even with --overwrite
    mine = tmp_path / "mine"
    mine.mkdir()
    (mine / "batch.csv").write_text("my,own,table\n")
    for extra in ([], ["--overwrite"]):
        assert main(["batch", "cosine", *BATCH, "--out", str(mine), *extra]) == 2
        assert "mine" in capsys.readouterr().err
    assert (mine / "batch.csv").read_text() == "my,own,table\n" and len(list(mine.iterdir())) == 1


def test_batch_overwrite_replaces_an_earlier_batch(batch_folder, capsys):
    out = batch_folder
    assert main(["batch", "cosine", *BATCH, "--out", str(out), "--overwrite"]) == 0
    rows = list(csv.DictReader(open(out / "batch.csv")))
    assert [r["status"] for r in rows] == ["ok"]
    table = capsys.readouterr().out
    assert "[deg/s]" in table and "[m/s^2]" in table  # row 12: the table's units
    assert "e-" not in table.split("\n")[2].split()[5]  # row 12: no false rotation of 1e-20 deg/s


def test_batch_into_a_file_or_an_unwritable_folder_is_one_line(tmp_path, monkeypatch, capsys):
    (tmp_path / "FILE").write_text("x")
    assert main(["batch", "cosine", *BATCH, "--out", str(tmp_path / "FILE")]) == 2
    err = capsys.readouterr().err
    assert "FILE: is not a folder" in err and err.count("\n") == 1
    locked = tmp_path / "locked"
    locked.mkdir()
    real_access = os.access
    monkeypatch.setattr(os, "access", lambda p, mode, **kw: False if Path(p) == locked else real_access(p, mode))
    assert main(["batch", "cosine", *BATCH, "--out", str(locked / "runs")]) == 2
    err = capsys.readouterr().err
    assert "not a writable folder" in err and err.count("\n") == 1
    assert list(locked.iterdir()) == []


@pytest.mark.realtime
def test_an_interrupted_batch_keeps_its_finished_jobs_and_says_so(tmp_path):
    out = tmp_path / "runs"
    proc = subprocess.Popen(_command("batch", "cosine", "car-lap", *BATCH[:-4], "--h-u", "0.05", "--starts", "1",
                                     "--processes", "1", "--out", str(out)),
                            env=ENV, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    try:
        line = ""
        deadline = time.monotonic() + 60.0
        while "job 1/2 done" not in line and time.monotonic() < deadline:
            line = proc.stderr.readline()
            assert line or proc.poll() is None
        assert "job 1/2 done" in line and "cosine" in line
        proc.send_signal(signal.SIGINT)
        sent = time.monotonic()
        _, err = proc.communicate(timeout=10)
        assert time.monotonic() - sent < 5.0
    finally:
        proc.kill()
    assert proc.returncode == 130, err
    assert "Traceback" not in err
    assert "1 of 2 jobs were done" in err and "batch.csv" in err and "no partial result" not in err
    rows = list(csv.DictReader(open(out / "batch.csv")))
    assert [(r["profile"], r["status"]) for r in rows] == [("cosine", "ok"), ("car-lap", "interrupted")]
    assert report.is_result_folder(out / "cosine--yaw-track") and not (out / "car-lap--yaw-track").exists()


# ---- row 4: compare ------------------------------------------------------------------------------------

def test_compare_replaces_only_its_own_files_and_only_with_overwrite(result_folder, tmp_path, capsys):
    out = tmp_path / "c"
    out.mkdir()
    (out / "compare.csv").write_text("the user's\n")
    for extra in ([], ["--overwrite"]):
        assert main(["compare", str(result_folder), "--out", str(out), *extra]) == 2
        assert capsys.readouterr().out == ""  # refused before any work
    assert (out / "compare.csv").read_text() == "the user's\n"
    fresh = tmp_path / "d"
    assert main(["compare", str(result_folder), "--out", str(fresh)]) == 0
    assert main(["compare", str(result_folder), "--out", str(fresh)]) == 2
    assert "add --overwrite" in capsys.readouterr().err
    assert main(["compare", str(result_folder), "--out", str(fresh), "--overwrite"]) == 0


def test_compare_on_a_batch_folder_names_its_job_folders(batch_folder, capsys):
    assert main(["compare", str(batch_folder)]) == 2
    err = capsys.readouterr().err
    assert "batch folder" in err and str(batch_folder / "cosine--yaw-track") in err


# ---- rows 5, 6: runaway sizes ------------------------------------------------------------------------

@pytest.mark.realtime
def test_a_short_recording_in_milliseconds_is_refused_at_once(tmp_path, capsys):
    path = tmp_path / "ms.csv"  # 3 s at 100 Hz, its time in milliseconds
    path.write_text("t,wx,wy,wz,fx,fy,fz\n" + "".join(f"{10 * k},0,0,0,0,1,9.81\n" for k in range(301)))
    with pytest.raises(profiles.ProfileError):  # read as 3000 s it would run for many minutes
        profiles.load(str(path))
    start = time.perf_counter()
    assert main(["optimize", str(path), "--config", "yaw-track", "--out", str(tmp_path / "r")]) == 2
    assert time.perf_counter() - start < 2.0
    err = capsys.readouterr().err
    assert "column 't' looks like milliseconds" in err and "every 10 s" in err
    # a hand-written table of a few breakpoints in seconds is not a recording: still read
    table = tmp_path / "table.csv"
    table.write_text("t,wx,wy,wz,fx,fy,fz\n0,0,0,0,0,0,9.81\n2,0,0,0,0,2,9.81\n5,0,0,0,0,2,9.81\n6,0,0,0,0,0,9.81\n")
    assert profiles.load(str(table)).duration == 6.0


@pytest.mark.realtime
def test_online_estimates_its_size_and_names_a_step_that_fits(tmp_path, monkeypatch, capsys):
    monkeypatch.setattr(sizing, "available_memory", lambda: 8e9)

    def run(*args, **kwargs):
        raise AssertionError("the run was started")  # it would take minutes and gigabytes

    monkeypatch.setattr(online, "run", run)
    start = time.perf_counter()
    assert main(["online", "dfs-catapult", "--step", "1e-5", "--out", str(tmp_path / "o")]) == 2
    assert time.perf_counter() - start < 5.0
    err = capsys.readouterr().err
    assert "closed-loop steps" in err and "Use --step" in err and err.count("\n") == 1
    assert not (tmp_path / "o").exists()


# ---- rows 8, 9: tracebacks -----------------------------------------------------------------------------

@pytest.mark.realtime
@pytest.mark.parametrize("delay", [0.2, 0.6])
def test_ctrl_c_while_the_libraries_load_exits_130_quietly(tmp_path, delay):
    proc = subprocess.Popen(_command("optimize", *QUICK, "--out", str(tmp_path / "r")), env=ENV,
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    time.sleep(delay)
    proc.send_signal(signal.SIGINT)
    try:
        _, err = proc.communicate(timeout=5)
    finally:
        proc.kill()
    assert proc.returncode == 130, err
    # The libraries may have loaded by then and the plan's line come first: the signal's line ends it.
    assert "Traceback" not in err and err.strip().splitlines()[-1].startswith("desdemona: interrupted (SIGINT)")
    assert not (tmp_path / "r").exists()


def test_plot_on_an_incomplete_folder_is_one_line(result_folder, tmp_path, capsys):
    broken = tmp_path / "broken"
    shutil.copytree(result_folder, broken)
    summary = json.loads((broken / "summary.json").read_text())
    del summary["parameters"]["joints"]["yaw"]["kind"]
    (broken / "summary.json").write_text(json.dumps(summary))
    assert main(["plot", str(broken)]) == 2
    err = capsys.readouterr().err
    assert "not a complete result folder" in err and "'kind'" in err and err.count("\n") == 1
    del summary["parameters"]
    (broken / "summary.json").write_text(json.dumps(summary))
    assert main(["plot", str(broken)]) == 2
    err = capsys.readouterr().err
    assert "has no 'parameters.joints'" in err and err.count("\n") == 1


# ---- rows 10, 12: clear messages ------------------------------------------------------------------------

def test_messages_say_what_to_do_in_plain_words(tmp_path, capsys):
    assert main(["optimize", *QUICK[:-4], "--h-u", "1e-9", "--out", str(tmp_path / "a")]) == 2
    err = capsys.readouterr().err
    assert "--h-u 1e-09" in err and "0 s" not in err
    huge = tmp_path / "huge.csv"
    huge.write_text("t,wx,wy,wz,fx,fy,fz\n0,0,0,0,0,0,9.81\n1e30,0,0,0,0,0,9.81\n")
    assert main(["optimize", str(huge), "--config", "yaw-track", "--out", str(tmp_path / "b")]) == 2
    err = capsys.readouterr().err
    assert "far longer than a session" in err and "GB" not in err
    semicolon = tmp_path / "semicolon.csv"
    semicolon.write_text("t;wx;wy;wz;fx;fy;fz\n0;0;0;0;0;0;9,81\n1;0;0;0;0;0;9,81\n")
    comma = tmp_path / "comma.csv"
    comma.write_text("t,wx,wy,wz,fx,fy,fz\n0,0,0,0,0,0,9,81\n1,0,0,0,0,0,9,81\n")
    for path, hint in ((semicolon, "separator ';'?"), (comma, "decimal comma?")):
        assert main(["optimize", str(path), "--out", str(tmp_path / "c")]) == 2
        err = capsys.readouterr().err
        assert hint in err and "comma-separated with '.' as the decimal point" in err
    assert main(["optimize", *QUICK, "--initial", "given", "--initial-state", "nan,0;0,0",
                 "--out", str(tmp_path / "d")]) == 2
    err = capsys.readouterr().err
    assert "finite" in err and "inf" not in err.replace("finite", "")


def test_a_plan_far_beyond_memory_is_said_in_words():
    path = profiles.DesiredPath("long", np.array([0.0, 1e9]), np.array([[0, 0, 0, 0, 0, profiles.G]] * 2))
    from desdemona.cueing.formulation import ProblemOptions
    from desdemona.machine.configs import get_configuration

    with pytest.raises(sizing.TooLarge) as info:
        sizing.check_fits(path, get_configuration("full"), ProblemOptions(h_u=0.001))
    assert "more than 1,000 times the memory" in str(info.value)


def test_overwrite_refusal_reads_well(result_folder, capsys):
    (result_folder / "mine.txt").write_text("x")
    try:
        assert _optimize(result_folder, "--overwrite") == 2
    finally:
        (result_folder / "mine.txt").unlink()
    err = capsys.readouterr().err
    assert "and this one holds other files too (mine.txt)" in err and "is holds" not in err


def test_plot_redraws_the_figures_of_an_online_result(tmp_path, capsys):
    out, pulse = tmp_path / "live", tmp_path / "pulse.csv"
    pulse.write_text("t,M\n" + "".join(f"{k / 10},{9.81 + (3 if 5 <= k < 15 else 0)}\n" for k in range(21)))
    assert main(["online", str(pulse), "--horizon", "1", "--step", "0.1", "--out", str(out)]) == 0
    for name in ("online.png", "online_felt.png", "compute_time.png"):
        (out / name).unlink()
    assert main(["plot", str(out)]) == 0
    printed = capsys.readouterr().out
    for name in ("online.png", "online_felt.png", "compute_time.png"):
        assert (out / name).exists() and name in printed


# ---- a built-in path written to CSV ----------------------------------------------------------------------

def test_profiles_writes_a_builtin_path_to_csv(tmp_path, capsys):
    target = tmp_path / "my-motion.csv"
    assert main(["profiles", "catapult", "--csv", str(target)]) == 0
    path = profiles.load(str(target))
    catapult = profiles.get_profile("catapult")
    assert path.duration == catapult.duration and path.weights == catapult.weights
    (target).write_text("the user's")
    assert main(["profiles", "catapult", "--csv", str(target)]) == 2
    assert "add --overwrite" in capsys.readouterr().err and target.read_text() == "the user's"
    assert main(["profiles", "catapult", "--csv", str(target), "--overwrite"]) == 0
    assert main(["profiles", "nope", "--csv", str(tmp_path / "x.csv")]) == 2
    assert main(["profiles"]) == 0 and "catapult" in capsys.readouterr().out


@pytest.mark.parametrize("wrapper", [RuntimeError("Error calling __set_name__ on 'Field' instance"),
                                     ImportError("initialization failed")])
@pytest.mark.parametrize("interrupt", ["guard", "keyboard"])
def test_a_stop_raised_while_a_class_is_created_is_still_a_stop(monkeypatch, capsys, wrapper, interrupt):
    """A Ctrl-C that lands while a module defines a dataclass, or while an extension module
    initialises, reaches the command as a RuntimeError or an ImportError caused by the interrupt
    (Python wraps what a field's __set_name__ or the module's initialisation raises): it is reported
    as the interrupt it is, exit 130 and one line, not a traceback."""
    from desdemona.cli import commands
    from desdemona.support import guard

    def loading(args):
        try:
            raise guard.Interrupted(signal.SIGINT) if interrupt == "guard" else KeyboardInterrupt
        except (guard.Interrupted, KeyboardInterrupt) as exc:
            raise wrapper from exc

    monkeypatch.setattr(commands, "run_model", loading)
    assert main(["model", "--config", "dfs"]) == 130
    assert "interrupted (SIGINT)" in capsys.readouterr().err


def test_ctrl_c_inside_an_extension_module_s_initialisation_exits_130_quietly(tmp_path):
    """SciPy's HiGHS module, cut short by a Ctrl-C while it initialises, raises an ImportError caused
    by the interrupt: the command ends as for any Ctrl-C while the libraries load (exit 130, one
    line). The interrupt is raised where that import happens, so that the test does not race it."""
    script = ("import builtins, sys\n"
              "real = builtins.__import__\n"
              "def cut(name, *args, **kwargs):\n"
              "    if name == 'scipy.signal':\n"
              "        try:\n"
              "            raise KeyboardInterrupt\n"
              "        except KeyboardInterrupt as exc:\n"
              "            raise ImportError('initialization failed') from exc\n"
              "    return real(name, *args, **kwargs)\n"
              "builtins.__import__ = cut\n"
              "from desdemona.cli import main\n")
    done = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, timeout=60)
    assert done.returncode == 130, done.stderr
    assert done.stderr == "desdemona: interrupted (SIGINT): stopped, nothing written\n"

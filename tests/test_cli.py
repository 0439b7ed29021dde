"""The command line: exit codes, messages and the model summary; how a run starts and ends."""

import contextlib
import io
import os

import numpy as np
import pytest

from desdemona import profiles
from desdemona.cli import main
from desdemona.results.report import load


def test_model_summary(capsys):
    assert main(["model", "--config", "full"]) == 0
    out = capsys.readouterr().out
    assert "configuration 'full'" in out
    assert "q6 cabin" in out and "f_cabin" in out and "inertia eigenvalues" in out


def test_model_toy_yaw_track(capsys):
    assert main(["model", "--config", "yaw-track", "--base", "thesis-toy"]) == 0
    out = capsys.readouterr().out
    assert "'thesis-toy'" in out and "held at" in out


def test_the_command_runs_openblas_on_one_thread_unless_told_otherwise(monkeypatch, capsys):
    """A command sets OPENBLAS_NUM_THREADS=1 before its first solve loads CasADi's OpenBLAS, whose idle
    threads otherwise spin between a factorisation's small blocks and take a core from the other
    start (allocator.one_blas_thread); a user's own setting stays."""
    monkeypatch.delenv("OPENBLAS_NUM_THREADS", raising=False)
    assert main(["model", "--config", "dfs"]) == 0
    assert os.environ["OPENBLAS_NUM_THREADS"] == "1"
    monkeypatch.setenv("OPENBLAS_NUM_THREADS", "2")
    assert main(["model", "--config", "dfs"]) == 0
    assert os.environ["OPENBLAS_NUM_THREADS"] == "2"
    capsys.readouterr()


def test_unknown_configuration_lists_valid_ones(capsys):
    assert main(["model", "--config", "nope"]) == 2
    err = capsys.readouterr().err
    assert "unknown configuration 'nope'" in err
    for name in ("dfs", "yaw-track", "yaw-track-cabin", "full"):
        assert name in err


def test_a_misspelt_option_gets_its_commands_usage_and_the_nearest_name(tmp_path, capsys):
    """An option a command does not know is refused by that command, with its usage and the option
    nearest to it; an abbreviation of an option is refused too, not taken for it."""
    out = str(tmp_path / "r")
    for argv, words in ((["online", "catapult", "--predicter", "hold", "--out", out],
                         "unrecognized arguments: --predicter hold (did you mean --predictor?)"),
                        (["online", "catapult", "--conf", "dfs", "--out", out],
                         "unrecognized arguments: --conf dfs (did you mean --config?)"),
                        (["import", "log", "a.csv", "--accel-unit", "g", "--out", out, "--levle"],
                         "unrecognized arguments: --levle (did you mean --level?)")):
        assert main(argv) == 2
        err = capsys.readouterr().err
        assert err.startswith(f"usage: desdemona {' '.join(argv[:2 if argv[0] == 'import' else 1])} ")
        assert words in err.splitlines()[-1]
    assert not (tmp_path / "r").exists()


def test_bad_parameter_file(tmp_path, capsys):
    path = tmp_path / "p.toml"
    path.write_text("[joints.track]\nvelocity = 3\n")
    assert main(["model", "--params", str(path)]) == 2
    assert "joints.track.velocity" in capsys.readouterr().err


# ---- how a run starts and ends, its weights and gain -----------------------------------------

QUICK = ["--config", "yaw-track", "--starts", "1", "--h-u", "0.1"]


@pytest.fixture(scope="module")
def session_folder(tmp_path_factory):
    """The cosine from rest (the default) to rest, with numeric weights and a gain; its printed line
    says how it ends (an on-line run ends free)."""
    out = tmp_path_factory.mktemp("session") / "cosine"
    with contextlib.redirect_stdout(io.StringIO()) as printed:
        assert main(["optimize", "cosine", *QUICK, "--final", "rest", "--weights", "0,0,1,0,1,0", "--gain", "0.5",
                     "--out", str(out)]) == 0
    assert ", ends still (--final rest)" in printed.getvalue()
    return out


def test_rest_starts_and_ends_with_every_joint_still(session_folder):
    traj, summary = load(session_folder)
    np.testing.assert_allclose(traj.qd[0], 0.0, atol=1e-9)
    np.testing.assert_allclose(traj.qd[-1], 0.0, atol=1e-6)
    assert summary["options"]["problem"]["initial"] == "rest"
    assert summary["options"]["problem"]["final"] == "rest"


def test_weights_and_gain_reach_the_problem(session_folder):
    traj, summary = load(session_folder)
    assert summary["options"]["problem"]["weights"] == [0, 0, 1, 0, 1, 0]
    cosine = profiles.get_profile("cosine")
    np.testing.assert_allclose(traj.S_d[:, 4], 0.5 * cosine.sample(traj.t)[:, 4], atol=1e-9)
    np.testing.assert_allclose(traj.S_d[:, 5], profiles.G)  # 1 g kept


def test_given_start_is_kept(tmp_path):
    out = tmp_path / "given"
    assert main(["optimize", "cosine", *QUICK, "--initial", "given", "--initial-state", "0.2,-1.5;1.0,0.3",
                 "--final", "none", "--out", str(out)]) == 0
    traj, _ = load(out)
    np.testing.assert_allclose(traj.q[0], [0.2, -1.5], atol=1e-9)
    np.testing.assert_allclose(traj.qd[0], [1.0, 0.3], atol=1e-9)


@pytest.mark.parametrize("args, fragment", [
    (["--initial", "given"], "--initial given needs --initial-state"),
    (["--initial", "rest", "--initial-state", "0,0;0,0"], "goes with --initial given"),
    (["--initial", "given", "--initial-state", "0,0,0;0,0,0"], "give 2 positions, ';', 2 rates"),
    (["--initial", "given", "--initial-state", "0,9;0,0"], "track position 9 is outside"),
    (["--initial", "given", "--initial-state", "0,0;9,0"], "yaw rate 9 is above its limit"),
    (["--initial", "given", "--initial-state", "a,0;0,0"], "not a number"),
    (["--weights", "1,2,3"], "six finite numbers"),
    (["--weights", "heavy"], "give one of felt, path, thresholds"),
    (["--gain", "-1"], "gain -1"),
    (["--method", "thesis", "--weights", "path"], "--method thesis reproduces the thesis"),
])
def test_bad_session_options_exit_2(tmp_path, capsys, args, fragment):
    out = tmp_path / "r"
    assert main(["optimize", "cosine", *QUICK, *args, "--out", str(out)]) == 2
    assert fragment in capsys.readouterr().err
    assert not out.exists()


# ---- import: --out is required (jsbsim: or --list); the summary line in words ----

def test_import_help_says_out_is_required(capsys):
    assert main(["import", "log", "--help"]) == 0
    usage = capsys.readouterr().out.split("\n\n")[0]
    assert " --out PATH.csv" in " ".join(usage.split()) and "[--out" not in usage
    assert main(["import", "jsbsim", "--help"]) == 0
    assert "(--list | --out PATH.csv)" in capsys.readouterr().out
    assert main(["import", "log", "imu.csv", "--accel-unit", "g", "--rate-unit", "deg/s"]) == 2
    assert "required: --out" in capsys.readouterr().err
    assert main(["import", "jsbsim", "b737_runway_new"]) == 2
    assert "--list --out is required" in capsys.readouterr().err


def test_import_line_says_six_channels_or_modulus(tmp_path, capsys):
    """A 3 s log at rest (forward, right, down axes: the force reads -1 g on z)."""
    log = tmp_path / "imu.csv"
    t = np.arange(301) / 100
    rows = np.column_stack([t, 0 * t, 0 * t, -1 + 0 * t, 0 * t, 0 * t, 0 * t])
    np.savetxt(log, rows, delimiter=",", header="t,ax,ay,az,p,q,r", comments="", fmt="%.6g")
    argv = ["import", "log", str(log), "--accel-unit", "g", "--rate-unit", "deg/s", "--out"]
    assert main([*argv, str(tmp_path / "six.csv")]) == 0
    line = capsys.readouterr().out
    assert "3 s, 301 samples, six channels, peak |f| 1.00 g" in line and ", S," not in line
    assert main([*argv, str(tmp_path / "m.csv"), "--modulus"]) == 0
    assert "samples, modulus (t,M), peak" in capsys.readouterr().out


def test_headline_prints_no_negative_zero_lag_and_marks_the_search_edge():
    from dataclasses import replace

    from desdemona.check import metrics

    t = np.arange(201) * 0.01
    S = np.column_stack([np.sin(t + k) for k in range(6)])
    m = metrics.of_arrays(t, S, S + 0.01 * np.cos(3 * t)[:, None], np.zeros((201, 1)), np.zeros((201, 1)), ["yaw"])
    assert "lag 0.00 s" in replace(m, lag_s=np.full(6, -0.001)).headline()
    assert "lag -0.01 s" in replace(m, lag_s=np.full(6, -0.01)).headline()
    # at the search's edge the lag is that long or longer (or none fits), and said so
    assert "lag >= 2.00 s at the search's edge (wz)" in replace(m, lag_s=np.full(6, 2.0)).headline()
    assert "lag <= -2.00 s at the search's edge (wz)" in replace(m, lag_s=np.full(6, -2.0)).headline()
    assert "lag 1.85 s" in replace(m, lag_s=np.full(6, 1.85)).headline()

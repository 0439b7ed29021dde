"""The optimize, profiles and plot commands: result folders, round trips and bad input."""

import json

import numpy as np
import pytest
import scipy.io

from desdemona.cli import main
from desdemona.results.report import load

FAST = ["--starts", "1", "--h-u", "0.1"]


@pytest.fixture(scope="module")
def catapult_folder(tmp_path_factory):
    out = tmp_path_factory.mktemp("runs") / "catapult"
    assert main(["optimize", "catapult", "--config", "yaw-track-cabin", "--out", str(out), *FAST]) == 0
    return out


def test_optimize_writes_the_whole_folder(catapult_folder):
    names = {p.name for p in catapult_folder.iterdir()}
    assert {"trajectory.csv", "summary.json", "trajectory.mat", "path.png", "joints.png", "limits.png",
            "view.html"} <= names
    summary = json.loads((catapult_folder / "summary.json").read_text())
    assert summary["metrics"]["limits_kept"] is True
    assert summary["metrics"]["worst_use"]["effort"] <= 1 + 1e-6
    assert summary["configuration"]["free_joints"] == ["yaw", "track", "inner_gimbal"]
    assert summary["versions"]["casadi"] and summary["command"].startswith("desdemona")
    for png in ("path.png", "joints.png", "limits.png", "limit_prices.png"):
        assert (catapult_folder / png).read_bytes()[:4] == b"\x89PNG"
    # every limit of every free joint priced (the yaw and the gimbal have no travel), the held ones too
    prices = summary["limit_prices"]
    assert set(prices["rate"]) == {"yaw", "track", "inner_gimbal"} and set(prices["position"]) == {"track"}
    assert set(prices["held_position"]) == {"heave", "outer_gimbal", "cabin"}
    for joints in prices.values():
        for entry in joints.values():
            assert isinstance(entry["price"], float) and entry["binds_s"] >= 0.0
            assert len(entry["binds_from_s"]) == len(entry["binds_to_s"])


def test_trajectory_files_agree(catapult_folder):
    traj, summary = load(catapult_folder)
    mat = scipy.io.loadmat(catapult_folder / "trajectory.mat")
    np.testing.assert_allclose(mat["t"][:, 0], traj.t, rtol=1e-9)
    np.testing.assert_allclose(mat["q_track"][:, 0], traj.q[:, 1], rtol=1e-9, atol=1e-12)
    np.testing.assert_allclose(mat["fy_d"][:, 0], traj.S_d[:, 4], rtol=1e-9, atol=1e-12)
    assert np.abs(traj.q[:, 1]).max() <= 4.0


def test_plot_redraws_figures(catapult_folder, capsys):
    (catapult_folder / "path.png").unlink()
    (catapult_folder / "view.html").unlink()
    (catapult_folder / "limit_prices.png").unlink()
    assert main(["plot", str(catapult_folder)]) == 0
    assert (catapult_folder / "path.png").exists()
    assert (catapult_folder / "limit_prices.png").exists()
    assert (catapult_folder / "view.html").exists()


def test_dfs_modulus_folder_has_the_modulus_figure(tmp_path):
    out = tmp_path / "dfs"
    assert main(["optimize", "dfs-catapult", "--config", "dfs", "--out", str(out), *FAST, "--no-view"]) == 0
    assert (out / "modulus.png").exists()
    assert not (out / "view.html").exists()


def test_profiles_lists_every_builtin(capsys):
    assert main(["profiles"]) == 0
    out = capsys.readouterr().out
    for name in ("cosine", "catapult", "double-pulse", "triple-pulse", "car-lap", "roller-coaster"):
        assert name in out


@pytest.mark.parametrize("args, fragment", [
    (["optimize", "catapolt"], "unknown profile 'catapolt'"),
    (["optimize", "catapult", "--config", "nope"], "unknown configuration 'nope'"),
    (["optimize", "missing.csv"], "missing.csv: file not found"),
    (["optimize", "roller-coaster", "--config", "yaw-track"], "gives only the modulus"),
    (["optimize", "catapult", "--h-u", "-1"], "--h-u -1"),
    (["optimize", "catapult", "--starts", "0"], "--starts"),
])
def test_bad_input_exits_2_and_writes_nothing(tmp_path, capsys, args, fragment):
    out = tmp_path / "result"
    assert main([*args, "--out", str(out)]) == 2
    assert fragment in capsys.readouterr().err
    assert not out.exists()
    assert list(tmp_path.iterdir()) == []


def test_bad_csv_and_missing_folder(tmp_path, capsys):
    bad = tmp_path / "bad.csv"
    bad.write_text("t,wx,wy,wz,fx,fy,fz\n0,0,0,0,0,nan,9.81\n0.1,0,0,0,0,1,9.81\n")
    assert main(["optimize", str(bad), "--out", str(tmp_path / "r")]) == 2
    assert "fy is not a finite number" in capsys.readouterr().err
    assert main(["optimize", "catapult", "--out", str(tmp_path / "no" / "such" / "r")]) == 2
    assert "no/such does not exist" in capsys.readouterr().err
    assert sorted(p.name for p in tmp_path.iterdir()) == ["bad.csv"]


def test_existing_folder_is_not_overwritten(tmp_path, capsys):
    out = tmp_path / "r"
    out.mkdir()
    (out / "notes.txt").write_text("the user's")  # an empty folder is taken as a new one (test_new_user)
    assert main(["optimize", "catapult", "--out", str(out)]) == 2
    assert "already exists" in capsys.readouterr().err
    assert [p.name for p in out.iterdir()] == ["notes.txt"]


def test_batch_on_dask_equals_local_processes(tmp_path, capsys):
    distributed = pytest.importorskip("distributed")
    from desdemona import default_params
    from desdemona.cueing.offline import OptimizeOptions
    from desdemona.runs import batch
    from desdemona.runs.session import Choices

    jobs = [batch.Job("catapult", "yaw-track"), batch.Job("dfs-catapult", "dfs")]  # two configurations, two workers
    choices, options = Choices(h_u=0.1), OptimizeOptions(starts=1)
    local = batch.run_batch(jobs, default_params(), choices, options, tmp_path / "local", processes=2)
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                  dashboard_address=None) as cluster:
        remote = batch.run_batch(jobs, default_params(), choices, options, tmp_path / "dask",
                                 dask_address=cluster.scheduler_address)
    assert [r.status for r in local] == ["ok"] * 2
    for a, b in zip(local, remote):
        assert (a.profile, a.config, a.status) == (b.profile, b.config, b.status)
        assert a.rms == b.rms and a.worst_use == b.worst_use
        ta, _ = load(a.folder)
        tb, _ = load(b.folder)
        np.testing.assert_array_equal(ta.q, tb.q)
    assert (tmp_path / "dask" / "batch.csv").read_text().count("\n") == 3


def test_batch_command(tmp_path, capsys):
    out = tmp_path / "b"
    code = main(["batch", "catapult", "cosine", "--configs", "yaw-track", "--out", str(out),
                 "--starts", "1", "--h-u", "0.1", "--processes", "2"])
    assert code == 0
    table = capsys.readouterr().out
    assert table.count(" ok ") == 2 and "false rot" in table and "rev/s" in table
    assert (out / "catapult--yaw-track" / "summary.json").exists()
    assert (out / "catapult--yaw-track" / "view.html").exists()
    import csv
    import json

    rows = list(csv.DictReader(open(out / "batch.csv")))
    assert [r["profile"] for r in rows] == ["catapult", "cosine"]
    felt = json.loads((out / "catapult--yaw-track" / "summary.json").read_text())["quality"]
    assert float(rows[0]["reversals_per_s_max"]) == pytest.approx(max(felt["joints"]["reversals_per_s"].values()))
    assert main(["batch", "catapult", "--configs", "nope", "--out", str(out)]) == 2


def test_perception_run_writes_perceived_figure(tmp_path):
    out = tmp_path / "felt"
    assert main(["optimize", "catapult", "--config", "yaw-track", "--perception", "thesis", "--out", str(out),
                 *FAST]) == 0
    summary = json.loads((out / "summary.json").read_text())
    assert summary["metrics"]["rms_perceived"] is not None
    assert (out / "perceived.png").exists()
    traj, _ = load(out)
    assert traj.S_perc is not None and traj.S_perc.shape == traj.S.shape


def test_unknown_option_exits_2(tmp_path, capsys):
    out = tmp_path / "r"
    assert main(["optimize", "catapult", "--out", str(out), "--bogus"]) == 2
    assert "unrecognized arguments: --bogus" in capsys.readouterr().err
    assert not out.exists()
    assert main(["--help"]) == 0


def test_progress_is_told_after_each_start():
    from desdemona import Model, default_params, profiles
    from desdemona.cueing.formulation import ProblemOptions
    from desdemona.cueing.offline import OptimizeOptions, optimize

    seen = []
    optimize(profiles.catapult(duration=3.0, push=1.0, quiet=0.5), Model(default_params(), "yaw-track"),
             OptimizeOptions(ProblemOptions(h_u=0.1), starts=3),
             progress=lambda done, total, best: seen.append((done, total, best)))
    assert [s[:2] for s in seen] == [(0, 3), (1, 3), (2, 3), (3, 3)]  # once built, then after each start
    best = [s[2] for s in seen]
    assert best[0] == float("inf")
    assert best == sorted(best, reverse=True)  # the best cost so far never gets worse

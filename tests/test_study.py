"""Design studies (desdemona.runs.study, `desdemona study`): the points are the machines asked for,
bad input is one line before any work, a study interrupted resumes with only the missing points, and a
Dask cluster gives the same table as local processes."""

import csv
import json
import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import numpy as np
import pytest

import desdemona
from desdemona.cli import main
from desdemona.machine.params import ParameterError, load_params, number_keys
from desdemona.results import studyfigures
from desdemona.runs import study

TRACK, YAW_RATE = "joints.track.position_m.max", "joints.yaw.velocity_deg_s"
ACCELERATION = "joints.track.acceleration_m_s2"
SHORT = ["--config", "yaw-track", "--h-u", "0.1", "--starts", "1"]
# what differs between two runs of the same points: where and how long
RUN_COLUMNS = ("folder", "solve_s")


def _rows(out: Path) -> list[dict]:
    with open(out / "study.csv", newline="") as fh:
        return list(csv.DictReader(fh))


def test_a_key_sets_that_number_of_the_machine_and_nothing_else():
    base = load_params()
    varied = load_params(numbers={TRACK: 3.5, YAW_RATE: 100.0, "head_offset_mm.x": 250.0,
                                  "bodies.cabin.inertia_kg_m2.xy": 20.0})
    assert varied.joints[1].position == (-4.0, 3.5)
    assert varied.joints[0].velocity == pytest.approx(np.radians(100.0))
    assert varied.head_offset == pytest.approx((0.25, 0.0, 0.0))
    assert varied.bodies[5].inertia[0][1] == varied.bodies[5].inertia[1][0] == 20.0  # symmetric, as a tensor is
    assert varied.joints[2:] == base.joints[2:] and varied.bodies[:5] == base.bodies[:5]
    assert {TRACK, YAW_RATE, "gravity_m_s2", "bodies.arm.mass_kg"} <= set(number_keys())


@pytest.mark.parametrize("numbers, words", [
    ({"joints.track.upper": 3.0}, "nearest: joints.track.position_m.max"),
    ({"joints.yaw.velocity": 3.0}, "joints.yaw.velocity_deg_s"),
    ({"joints.track.velocity_m_s": -1.0}, "must be > 0"),
    ({TRACK: -5.0}, "must be less than max"),
    ({"joints.yaw.position_deg.max": 90.0}, "unbounded"),
    ({"bodies.cabin.inertia_kg_m2.xx": 5000.0}, "not the inertia of a rigid body"),
])
def test_a_key_or_value_the_machine_refuses_is_named(numbers, words):
    with pytest.raises(ParameterError, match=words):
        load_params(numbers=numbers)


@pytest.mark.parametrize("extra, words", [
    (["--grid", "joints.track.upper=3,4"], "nearest: joints.track.position_m.max"),
    (["--grid", f"{TRACK}=3,-5"], "must be less than max"),
    (["--grid", f"{TRACK}=3,x"], "numbers separated by commas"),
    (["--sample", f"{TRACK}=4:3", "--points", "4"], "LOW must be less than HIGH"),
    (["--sample", f"{TRACK}=3:4"], "needs --points"),
    (["--grid", f"{TRACK}=3,4", "--max-time", "5"],
     "estimated on 2 processes (each point's estimate, summed), above --max-time 5 s"),
    (["--grid", f"{TRACK}=3,4", "--front", "rms,trackk"], "is not a column"),
    (["--config", "nope"], "unknown configuration"),
])
def test_bad_input_is_one_line_and_exit_2_before_any_work(tmp_path, capsys, extra, words):
    out = tmp_path / "s"
    assert main(["study", "cosine", *SHORT, "--out", str(out), *extra]) == 2
    err = capsys.readouterr().err
    assert words in err and err.count("\n") == 1 and "Traceback" not in err
    assert not out.exists()


def test_a_study_whose_points_at_once_would_not_fit_in_memory_is_refused_with_its_estimate(tmp_path, capsys):
    out = tmp_path / "s"
    argv = ["study", "car-lap", "--config", "full", "--grid", f"{TRACK}=3,4", "--processes", "2000", "--out", str(out)]
    assert main(argv) == 2
    err = capsys.readouterr().err
    assert "GB of memory" in err and "fewer --processes (2000 points at once" in err and err.count("\n") == 1
    assert not out.exists()


def test_the_sample_is_a_seeded_latin_hypercube_within_its_bounds():
    asked = study.Study(("cosine",), ("yaw-track",), grid=((YAW_RATE, (100.0, 150.0)),),
                        sample=((TRACK, 3.0, 4.0), ("head_offset_m.z", -0.2, 0.2)), points=5, seed=3)
    values = asked.values()
    assert len(values) == 10 and values == asked.values()
    track = np.array([v[TRACK] for v in values[:5]])
    assert ((3.0 <= track) & (track <= 4.0)).all()
    # a Latin hypercube: each fifth of each range holds exactly one point
    assert sorted(np.floor((track - 3.0) / 0.2).astype(int)) == [0, 1, 2, 3, 4]
    assert [v[YAW_RATE] for v in values] == [100.0] * 5 + [150.0] * 5


def test_the_front_is_the_points_no_other_beats_in_both():
    x = np.array([1.0, 2.0, 3.0, 2.5, 1.5, np.nan])
    y = np.array([5.0, 3.0, 1.0, 4.0, 5.5, 0.0])
    assert studyfigures.front(x, y).tolist() == [0, 1, 2]


@pytest.fixture(scope="module")
def small(tmp_path_factory):
    """Two track accelerations x two recordings on yaw-track, solved on one local process."""
    out = tmp_path_factory.mktemp("study") / "s"
    argv = ["study", "cosine", "catapult", *SHORT, "--grid", f"{ACCELERATION}=2,5", "--out", str(out),
            "--processes", "1", "--front", f"{ACCELERATION},rms"]
    assert main(argv) == 0
    return out, argv


def test_a_small_study_writes_its_table_and_figures(small):
    out, _ = small
    rows = _rows(out)
    assert [(r["recording"], float(r[ACCELERATION])) for r in rows] == [("cosine", 2.0), ("catapult", 2.0),
                                                                        ("cosine", 5.0), ("catapult", 5.0)]
    for row in rows:
        summary = json.loads((Path(row["folder"]) / "summary.json").read_text())
        # the point was solved on the machine its row names, and kept that machine's every limit
        assert summary["parameters"]["joints"]["track"]["acceleration"] == float(row[ACCELERATION])
        assert summary["metrics"]["limits_kept"] and float(row["worst_use"]) <= 1 + 1e-6
        assert float(row["use_acceleration_track"]) <= 1 + 1e-6
        assert row["status"] == "ok" and float(row["rms"]) == summary["metrics"]["rms_weighted"]
    # the cosine's track works at its acceleration limit: a lower limit costs felt error
    cosine = {float(r[ACCELERATION]): float(r["rms"]) for r in rows if r["recording"] == "cosine"}
    assert cosine[2.0] > 1.5 * cosine[5.0]
    assert float(next(r for r in rows if r["recording"] == "cosine")["use_acceleration_track"]) > 0.99
    assert {"felt.png", "front.png", "binding.png"} <= {p.name for p in out.iterdir()}
    try:
        import pandas
        import pyarrow  # noqa: F401
    except ImportError:
        assert not (out / "study.parquet").exists()
    else:  # the same table, its numbers as numbers
        frame = pandas.read_parquet(out / "study.parquet")
        assert frame["rms"].tolist() == [float(r["rms"]) for r in rows] and list(frame.columns) == list(rows[0])


def test_limit_prices_become_columns_where_a_result_has_them():
    summary = {"metrics": {"rms_weighted": 1.0, "rms_perceived": None, "worst_use": {"position": 0.5},
                           "worst_use_per_joint": {"position": {"track": 0.5}}},
               "solver": {"converged": True, "iterations": 3, "timings_s": {"wall": 0.1}, "status": "x"},
               "limit_prices": {"position": {"track": {"price": 0.25, "binds_s": [1.0]}}}}
    row = study.summary_row(summary)
    assert row["price_position_track"] == 0.25 and row["use_position_track"] == 0.5
    del summary["limit_prices"]
    assert not any(k.startswith("price_") for k in study.summary_row(summary))
    what, values = studyfigures.binding([{**row, "status": "ok"}], study.BINDS)
    assert "price" in what and values == {"position_track": 0.25}


@pytest.mark.realtime
def test_ctrl_c_half_way_then_the_same_command_solves_only_the_missing_points(tmp_path, capsys):
    """Acceptance: SIGINT after the second of four points stops the study promptly (130), keeps the
    points done and the table; the same command again solves only the others, never a finished one."""
    env = dict(os.environ, PYTHONPATH=str(Path(desdemona.__file__).resolve().parent.parent))
    out = tmp_path / "s"
    argv = ["study", "cosine", *SHORT, "--grid", f"{TRACK}=2,3,3.5,4", "--out", str(out), "--processes", "1"]
    proc = subprocess.Popen([sys.executable, "-m", "desdemona", *argv], env=env, stderr=subprocess.PIPE, text=True)
    try:
        deadline = time.monotonic() + 120.0
        while time.monotonic() < deadline:
            line = proc.stderr.readline()
            if not line or "point 2/4 done" in line:
                break
        proc.send_signal(signal.SIGINT)
        sent = time.monotonic()
        err = proc.stderr.read()
        proc.wait(timeout=15.0)
    finally:
        proc.kill()
    assert time.monotonic() - sent < 15.0
    assert proc.returncode == 130, err
    assert "the same command again solves the others" in err.strip().splitlines()[-1]
    done = {p.name: p.stat().st_mtime_ns for p in (out / "points").iterdir() if (p / "summary.json").exists()}
    assert 2 <= len(done) < 4
    statuses = [r["status"] for r in _rows(out)]
    assert statuses.count("ok") == len(done) and statuses.count("interrupted") == 4 - len(done)

    assert main(argv) == 0  # the same command again, here
    again = capsys.readouterr().err
    assert f"{len(done)} already solved, {4 - len(done)} to solve" in again
    assert again.count(" done, ") == 4 - len(done)
    assert all((out / "points" / name).stat().st_mtime_ns == mtime for name, mtime in done.items())
    assert [r["status"] for r in _rows(out)] == ["ok"] * 4


def test_the_same_study_on_a_dask_cluster_gives_the_same_table(small, tmp_path):
    distributed = pytest.importorskip("distributed")
    out, argv = small
    remote = tmp_path / "dask"
    with distributed.LocalCluster(n_workers=1, threads_per_worker=1, processes=False, protocol="tcp",
                                  host="127.0.0.1", dashboard_address=None) as cluster:
        argv = [a if a != str(out) else str(remote) for a in argv]
        assert main([*argv, "--dask", cluster.scheduler_address]) == 0
    local, dask = _rows(out), _rows(remote)
    assert len(dask) == 4
    for a, b in zip(local, dask):
        assert {k: v for k, v in a.items() if k not in RUN_COLUMNS} == {k: v for k, v in b.items()
                                                                       if k not in RUN_COLUMNS}

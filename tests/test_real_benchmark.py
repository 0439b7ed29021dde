"""``benchmarks/real.py``'s judgement of its on-line rows against the classical loop (point 1 of the
on-line issue): which rows are worse, on which measure, and where a correlation says little."""

import importlib
from pathlib import Path

import numpy as np
import pytest

from desdemona import profiles

BENCHMARKS = Path(__file__).resolve().parents[1] / "benchmarks"


def load_real(monkeypatch):
    monkeypatch.syspath_prepend(str(BENCHMARKS))
    return importlib.import_module("real")


def row(case, **figures):
    base = {"case": case, "config": "dfs", "mode": "hold", "force_rms": 1.0, "rotation_peak": 10.0,
            "correlation": 0.9, "direction_peak": 5.0, "direction_made": 5.0, "reversals": 0.5,
            "classical_force_rms": 2.0, "classical_rotation_peak": 20.0, "classical_correlation": 0.5,
            "classical_direction_peak": 20.0, "classical_direction_made": 20.0}
    return {**base, **figures}


def test_real_lists_the_rows_worse_than_the_loop_measure_by_measure(monkeypatch):
    real = load_real(monkeypatch)
    rows = [row("better"), row("forceful", force_rms=2.5), row("late", correlation=0.4, shape=0.5),
            row("turned", direction_peak=31.0, direction_made=31.0, rotation_peak=21.0),
            row("upright", direction_peak=29.0, direction_made=29.0),
            row("push-over", direction_peak=179.0, direction_made=3.0, classical_direction_peak=170.0),
            row("shaky", reversals=1.2, target_reversals=0.3), row("bobbing", reversals=1.6, target_reversals=1.7),
            {**row("off-line"), "mode": "offline", "force_rms": 9.0},
            # the future known: as forceful (the cost's trade, marked +), not as late (the prediction's)
            {**row("forceful", force_rms=2.2), "mode": "perfect"}, {**row("late"), "mode": "perfect"},
            # the whole future solved off-line: as forceful against the hold row's loop (marked o)
            {**row("forceful", force_rms=2.1, classical_force_rms=None), "mode": "offline"}]
    text = real.against_loop(rows)
    assert text.startswith("Against the classical loop, 4 of 10 on-line rows worse on no measure")
    lines = dict(line[2:].split(": ", 1) for line in text.splitlines()[2:])
    assert lines["felt force RMS above the loop's"] == ("2 rows: forceful on dfs (hold) 2.500 against 2.000+o; "
                                                        "forceful on dfs (perfect) 2.200 against 2.000o")
    assert "cost's own trade" in lines["+"] and "off-line optimum" in lines["o"]
    assert lines["peak felt rotation above the loop's"].startswith("1 row: turned")
    assert lines["correlation below the loop's"] == "1 row: late on dfs (hold) 0.40 against 0.50*"
    # 30 deg or the loop's, the larger: 29 deg against a loop's 20 is not worse; nor is a push-over's
    # 179 deg against the loop's 170, where a still cabin is as far off (the machine made 3 deg of it)
    assert lines["felt direction made above max(30 deg, the loop's)"] == "1 row: turned on dfs (hold) 31.0 against 30.0"
    assert lines["more than one reversal a second"] == ("2 rows: shaky on dfs (hold) 1.20 against 1.00; "
                                                        "bobbing on dfs (hold) 1.60 against 1.00t")
    assert "desired force itself reverses" in lines["t"]
    assert "less than one perception threshold" in lines["*"]
    assert real.against_loop([rows[8]]) == ""  # off-line rows are not judged against the loop
    assert "+" not in real.against_loop(rows[:9])  # no perfect row, no mark
    assert "2.000+; " in real.against_loop(rows[:11])  # no off-line twin, no o


def test_the_targets_own_reversals_are_those_of_its_force(monkeypatch):
    """A modulus bobbing at 1 Hz about 1 g reverses twice a second, as must the joint that makes it; a
    six-channel path counts its force channels less g, not g itself."""
    real = load_real(monkeypatch)
    t = np.arange(0.0, 20.0, 0.01)
    bob = profiles.G + 0.5 * np.sin(2 * np.pi * t)
    assert real.target_reversals(profiles.DesiredPath("m", t, None, modulus=bob)) == pytest.approx(2.0, abs=0.1)
    S = np.zeros((len(t), 6))
    S[:, 5], S[:, 3] = profiles.G, 2.0 * np.sin(0.2 * np.pi * t)  # still vertical, a 0.1 Hz sway
    assert real.target_reversals(profiles.DesiredPath("s", t, S)) == pytest.approx(0.2, abs=0.06)


def test_the_shape_of_a_desired_channel_is_counted_in_perception_thresholds(monkeypatch):
    real = load_real(monkeypatch)
    t = np.linspace(0.0, 10.0, 101)
    path = profiles.DesiredPath("m", t, None, modulus=9.81 + 0.14 * np.sin(t))  # ranges 0.28 m/s^2
    assert abs(real.shape_thresholds(path, "fz") - 1.0) < 0.01  # the f_z threshold is 0.28 m/s^2


def test_a_folder_of_ones_own_paths_is_read_as_it_is(monkeypatch, tmp_path):
    """``--corpus`` naming a folder of imported paths without an index: one case per path, its form
    from its columns, a forecast beside it taken; nothing is built there (no JSBSim run, no file)."""
    real = load_real(monkeypatch)
    t = np.arange(0.0, 4.0, 0.02)
    (tmp_path / "ride-M.csv").write_text("t,M\n" + "".join(f"{x:.2f},{9.81 + np.sin(x):.4f}\n" for x in t))
    six = profiles.load("catapult")
    (tmp_path / "launch.csv").write_text("t,wx,wy,wz,fx,fy,fz\n" + "".join(
        ",".join(f"{v:.6g}" for v in (x, *row)) + "\n" for x, row in zip(six.t, six.S_d)))
    (tmp_path / "launch.forecast.csv").write_text("not read here\n")
    monkeypatch.setattr(real.subprocess, "run", lambda *a, **k: (_ for _ in ()).throw(AssertionError("built")))
    before = sorted(p.name for p in tmp_path.iterdir())
    cases = {c["name"]: c for c in real.corpus_cases(tmp_path)}
    assert sorted(cases) == ["launch", "ride-M"]
    assert cases["ride-M"]["form"] == "modulus" and cases["launch"]["form"] == "six"
    assert cases["launch"]["forecast"] == "launch.forecast.csv" and "forecast" not in cases["ride-M"]
    assert cases["ride-M"]["duration_s"] == 4.0 and cases["launch"]["duration_s"] == round(six.duration, 1)
    assert sorted(p.name for p in tmp_path.iterdir()) == before
    (tmp_path / "broken.csv").write_text("t,M\n0,x\n")
    with pytest.raises(SystemExit, match="broken.csv"):
        real.corpus_cases(tmp_path)


def test_a_folder_with_no_paths_is_refused_and_not_built_into(monkeypatch, tmp_path, capsys):
    """A mistyped --corpus, or a folder without paths, is one error naming how to build a corpus there;
    the JSBSim corpus is not built into it."""
    real = load_real(monkeypatch)
    monkeypatch.setattr(real.subprocess, "run", lambda *a, **k: (_ for _ in ()).throw(AssertionError("built")))
    for folder in (tmp_path / "typo", tmp_path):
        with pytest.raises(SystemExit) as stop:
            real.main(["--corpus", str(folder), "--modes", "hold", "--out", str(tmp_path / "out")])
        assert stop.value.code == 2
        assert "no paths there" in capsys.readouterr().err
    assert not (tmp_path / "typo").exists() and sorted(p.name for p in tmp_path.iterdir()) == []


def test_the_table_has_the_nod_cross_coupling_and_msdv_of_the_mpc_and_the_loop(monkeypatch):
    """The worst nod's peak and MSDV_z read from a summary's quality (none from one written before
    they were), and one cell each for the row and its classical loop."""
    real = load_real(monkeypatch)
    quality = {"cross_coupling": {"pitch": {"velocity_peak_deg_s": 12.0}, "roll": {"velocity_peak_deg_s": 31.0},
                                  "yaw": {"velocity_peak_deg_s": 4.0}, "worst": "roll"},
               "sickness": {"msdv_z": 1.25}}
    assert real.suffered(quality) == {"cross_coupling": 31.0, "msdv_z": 1.25}
    assert real.suffered({}) == {"cross_coupling": None, "msdv_z": None}
    line = real.table([{**row("spun"), "duration_s": 10.0, "exit": 0, "wall_s": 5.0, "peak_mb": 100.0,
                        "cross_coupling": 31.0, "msdv_z": 1.25, "classical_cross_coupling": 48.0,
                        "classical_msdv_z": 2.5}]).splitlines()
    header = [c.strip() for c in line[0].split("|")]
    cells = [c.strip() for c in line[2].split("|")]
    assert len(header) == len(cells) == len(line[1].split("|"))
    assert cells[header.index("nod x-coupling [deg/s]")] == "31" and cells[header.index("MSDV_z")] == "1.25"
    assert cells[header.index("nod x-coupling")] == "48" and cells[len(header) - 1 - header[::-1].index("MSDV_z")] == "2.50"

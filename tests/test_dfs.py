"""The whole-machine dynamic flight simulator (issue 14): yaw and gimbals planned together, from rest,
smooth, within every limit, against the classical loop that drives the gimbals too."""

import json

import numpy as np
import pytest

from desdemona import Model, profiles
from desdemona.cli import main
from desdemona.online import MPCOptions, OnlineOptions, run
from desdemona.params import JOINT_NAMES

# The acceptance setting: 50 Hz, a 2 s horizon.
SESSION = MPCOptions(horizon=2.0, step=0.02, deadline=float("inf"))


def most_reversals(quality) -> float:
    return float(np.max(quality.sign_changes_per_s))


@pytest.mark.parametrize("path, below", [(profiles.dfs_catapult(), 0.75), (profiles.roller_coaster(duration=15.0), 0.6)],
                         ids=["dfs-catapult", "roller-coaster"])
def test_online_dfs_drives_yaw_and_gimbals_smoothly_and_beats_the_classical_loop(params, path, below):
    result = run(path, Model(params, "dfs"), OnlineOptions(SESSION))
    assert result.model.config.joint_names == ("yaw", "outer_gimbal", "inner_gimbal", "cabin")
    assert result.check.passed and result.baseline_check.passed  # jerk included, every joint
    assert result.check.worst["jerk"] <= 1.0 + 1e-6 and set(result.loop.sources) == {"mpc"}
    assert most_reversals(result.quality) <= 1.0
    # measured: 1.919 against 2.758 (dfs-catapult), 1.781 against 3.571 (15 s of the coaster)
    assert result.check.rms_modulus <= below * result.baseline_check.rms_modulus
    # the gimbals keep the felt force near the occupant's vertical: measured 2.8 and 2.7 deg RMS (classical 6.8, 10.2)
    assert np.degrees(result.quality.direction_rms) < 4.0
    assert np.degrees(result.quality.direction_rms) < np.degrees(result.baseline_quality.direction_rms)


def test_online_dfs_on_a_noisy_recorded_modulus_with_the_hold_predictor(params):
    """An accelerometer log: dfs-catapult at 100 Hz with 0.5 m/s^2 of noise and a 1 % gain error."""
    path = profiles.get_profile("dfs-catapult-recorded")
    result = run(path, Model(params, "dfs"), OnlineOptions(SESSION, predictor="hold"))
    assert result.check.passed and set(result.loop.sources) == {"mpc"}
    assert most_reversals(result.quality) <= 1.0
    # measured 3.24 against the classical loop's 3.03: holding the present value, the plan lags a loop
    # that reacts to the next sample; with the true future it is 30 % below (the test above)
    assert result.check.rms_modulus <= 1.1 * result.baseline_check.rms_modulus


def test_offline_dfs_result_folder_has_six_joints_within_every_limit(tmp_path, capsys):
    out = tmp_path / "dfs"
    assert main(["optimize", "dfs-catapult", "--config", "dfs", "--out", str(out), "--starts", "2", "--quiet"]) == 0
    assert "RMS(M - M_d)" in capsys.readouterr().out
    lines = [line for line in (out / "trajectory.csv").read_text().splitlines() if not line.startswith("#")]
    header = lines[0].split(",")
    for label in ("q", "qd", "qdd"):
        assert [c for c in header if c.startswith(label + "_")] == [f"{label}_{j}" for j in JOINT_NAMES]
    table = np.array([[float(x) for x in line.split(",")] for line in lines[1:]])
    np.testing.assert_allclose(table[:, header.index("q_track")], -4.0)  # held at the outer end
    summary = json.loads((out / "summary.json").read_text())
    assert summary["metrics"]["limits_kept"]
    assert set(summary["metrics"]["worst_use"]) >= {"jerk", "acceleration", "effort", "power"}
    assert max(summary["metrics"]["worst_use"].values()) <= 1.0 + 1e-6
    quality = summary["quality"]
    assert max(quality["joints"]["sign_changes_per_s"].values()) <= 1.0
    assert quality["felt_direction"]["rms_deg"] < 5.0
    assert set(quality["felt_rotation"]["peak_deg_s"]) == {"wx", "wy", "wz"}
    for png in ("joints.png", "felt.png", "modulus.png", "path.png"):
        assert (out / png).is_file()

"""The package's top level: the main jobs from one import, results as values and DataFrames."""

import numpy as np
import pytest

import desdemona as dd


def test_main_jobs_from_one_import():
    path = dd.load_path("cosine")
    model = dd.Model(dd.thesis_toy_params(), "yaw-track")
    result = dd.optimize(path, model, dd.OptimizeOptions(dd.ProblemOptions(h_u=0.1), starts=1))
    assert result.check.passed and isinstance(result.plan, dd.Plan)
    # the plan reproduces the trajectory it was checked on
    q, qd, qdd = result.plan.at(result.trajectory.t)
    np.testing.assert_allclose(q, result.trajectory.q, atol=1e-12)
    found = dd.metrics.of_trajectory(result.trajectory, model.config.joint_names)
    assert found.rms[4] == pytest.approx(np.sqrt(np.mean((result.trajectory.S - result.trajectory.S_d)[:, 4] ** 2)))

    live = dd.run_online(dd.load_path("dfs-catapult"), dd.Model(config="dfs"),
                         dd.OnlineOptions(dd.MPCOptions(horizon=1.0, step=0.1, deadline=float("inf"))))
    assert live.check.passed and live.baseline_check is not None
    assert len(live.loop.compute_times) == len(live.plan.u) == 120


def test_result_as_a_dataframe():
    pandas = pytest.importorskip("pandas")
    path = dd.load_path("cosine")
    model = dd.Model(dd.thesis_toy_params(), "yaw-track")
    result = dd.optimize(path, model, dd.OptimizeOptions(dd.ProblemOptions(h_u=0.25), starts=1))
    frame = result.to_dataframe()
    assert isinstance(frame, pandas.DataFrame) and frame.index.name == "t"
    assert {"q_yaw", "qd_track", "tau_yaw", "fy", "fy_d", "M", "M_d"} <= set(frame.columns)
    np.testing.assert_array_equal(frame["q_track"].to_numpy(), result.trajectory.q[:, 1])


def test_unknown_path_names_the_built_in_ones():
    with pytest.raises(dd.ProfileError, match="catapult"):
        dd.load_path("nope")

"""Off-line in overlapping windows: the choice of the window, its refusals, and a stitched result that
starts each window where the one before was and passes the whole check."""

import numpy as np
import pytest

from desdemona import profiles
from desdemona.check.simulate import check
from desdemona.cli import main
from desdemona.cueing import sizing, windows
from desdemona.cueing.formulation import ProblemOptions
from desdemona.cueing.offline import OptimizeOptions, optimize
from desdemona.machine.model import Model
from desdemona.runs import session


def _long(duration: float):
    return profiles.cosine(amplitude=3.0, omega=0.4, duration=duration, dt=0.05)


def test_the_default_is_whole_up_to_its_length_and_windows_above(params):
    model, options = Model(params, "yaw-track"), ProblemOptions(h_u=0.2)
    assert windows.choose(_long(windows.WHOLE_UP_TO), model, options, None) is None
    assert windows.choose(_long(windows.WHOLE_UP_TO + 10), model, options, None) == windows.DEFAULT_WINDOW
    assert windows.choose(_long(windows.WHOLE_UP_TO + 10), model, options, 0) is None
    assert windows.choose(_long(40.0), model, options, 50.0) is None  # longer than the path: whole


def test_a_window_shorter_than_the_machine_can_stop_in_says_which_would_do(params):
    model = Model(params, "yaw-track")
    shortest = 2 * windows.overlap(model)
    assert windows.overlap(model) >= 2 * windows.stopping_time(model)
    with pytest.raises(windows.WindowError, match=f"use --window {shortest:g} or more"):
        windows.choose(_long(100.0), model, ProblemOptions(h_u=0.2), shortest - 1)


def test_a_window_larger_than_the_memory_says_which_would_fit(params, monkeypatch):
    monkeypatch.setattr(sizing, "available_memory", lambda: 0.6e9)
    with pytest.raises(windows.WindowError, match=r"use --window \d+ or less"):
        windows.choose(_long(2000.0), Model(params, "full"), ProblemOptions(h_u=0.05), 1000.0)


def test_where_no_window_fits_the_memory_it_names_the_step_that_makes_one_fit(params, monkeypatch):
    model, options = Model(params, "full"), ProblemOptions(h_u=0.001)
    shortest = 2 * windows.overlap(model)
    fine = sizing.estimate(windows.part(_long(2000.0), 0.0, shortest), model.config, options, 1, model.limits.smooth)
    coarse = sizing.estimate(windows.part(_long(2000.0), 0.0, shortest), model.config,
                             ProblemOptions(h_u=0.002), 1, model.limits.smooth)
    between = 0.5 * (fine.memory + coarse.memory)  # the 0.001 s window does not fit, the 0.002 s one does
    monkeypatch.setattr(sizing, "available_memory", lambda: between)
    with pytest.raises(windows.WindowError, match=r"no window fits .* use --h-u 0\.002 or more"):
        windows.choose(_long(2000.0), model, options, shortest)


def test_the_command_refuses_a_bad_window_before_any_work(tmp_path, capsys):
    path = tmp_path / "long.csv"
    profiles.write_csv(path, _long(60.0))
    out = tmp_path / "out"
    code = main(["optimize", str(path), "--config", "yaw-track", "--out", str(out), "--window", "5", "--quiet"])
    assert code == 2 and not out.exists()
    assert "--window 5: shorter than the machine needs" in capsys.readouterr().err


def test_perception_is_refused_in_windows(params):
    with pytest.raises(session.ChoiceError, match="--window 0"):
        session.offline(_long(60.0), Model(params, "yaw-track-cabin"), session.Choices(window=40.0),
                        perception=object())


def test_windows_stitch_into_one_checked_plan_close_to_the_whole_solve(params):
    path, model = _long(50.0), Model(params, "yaw-track")
    options = OptimizeOptions(ProblemOptions(h_u=0.2, initial="rest", final="centre"), starts=1)
    told = []
    result = windows.optimize_windowed(path, model, options, 30.0, announce=lambda *a: told.append(a))
    assert [a[:2] for a in told] == [(1, 3), (2, 3), (3, 3)]
    assert [a[2] for a in told] == pytest.approx([0.0, 15.0, 30.0]) and told[-1][3] == pytest.approx(50.0)
    assert result.check.passed and result.converged
    plan = result.plan
    assert plan.t_nodes[0] == 0.0 and plan.t_nodes[-1] == pytest.approx(50.0)
    assert np.all(np.diff(plan.t_nodes) > 0)
    # the stitched plan, integrated from its start, passes through every window's own states
    again, _ = check(model, path, plan, 0.1)
    assert again.passed and again.rms == pytest.approx(result.check.rms)
    whole = optimize(path, model, options)
    assert result.check.rms <= 1.05 * whole.check.rms + 1e-3, (result.check.rms, whole.check.rms)
    # the limits' prices of the windows' kept parts are the whole solve's, to the coupling between
    # windows they leave out (measured: 0.7-2.7 % on the dearest)
    windowed, solved = result.prices.to_dict(), whole.prices.to_dict()
    for family, joint in (("held_position", "outer_gimbal"), ("acceleration", "yaw"), ("position", "track")):
        assert windowed[family][joint]["price"] == pytest.approx(solved[family][joint]["price"], rel=0.05)


def test_windows_start_a_keep_apart_and_the_last_reaches_the_end():
    """In intervals: windows of 1,200 that keep 900; the last is as long as what is left."""
    assert windows._windows(1700, 1200, 900) == [0, 900]
    assert windows._windows(1210, 1200, 900) == [0, 900]
    assert windows._windows(2400, 1200, 900) == [0, 900, 1800]
    assert windows._windows(12000, 1200, 900)[-2:] == [9900, 10800]
    assert windows._windows(1200, 1200, 900) == [0]


def test_a_later_windows_guesses_bring_the_start_s_motion_to_rest_within_the_travel(params):
    """A window after the first starts moving (the track at 1.2 m/s towards its end, the cabin turning):
    its guesses bring the track, the joint with a travel, to rest at the plans' braking, so that no
    position needs clipping (a clipped guess leaves its gaps open; held at zero acceleration, the track
    ran past its end), and leave the joints that turn freely turning."""
    from desdemona.cueing.offline import initial_guesses, settled
    from desdemona.cueing.transcription import CueingProblem

    model = Model(params, "yaw-track-cabin")
    lim, n = model.limits, model.n
    q0, qd0, a0 = np.array([0.3, 2.5, 0.1]), np.array([0.8, 1.2, -0.4]), np.array([0.1, 0.5, 0.0])
    options = ProblemOptions(h_u=0.2, initial="given", initial_state=(q0, qd0, a0), final="none", stoppable=True,
                             solver="ipopt", compile=False)
    problem = CueingProblem(model, _long(10.0), options)
    held = np.zeros((problem.N, n))
    free, _ = problem.guess(q0, qd0, held, a0, clip=False)
    assert free[:, 1].max() > lim.position_max[1]  # the motion carried on: the track past its end
    u = settled(problem, qd0, a0, held)
    clipped, _ = problem.guess(q0, qd0, u, a0)
    unclipped, _ = problem.guess(q0, qd0, u, a0, clip=False)
    assert np.allclose(clipped, unclipped)  # within the travel and the rates without clipping
    assert abs(unclipped[-1, n + 1]) < 1e-4  # the track at rest (to a hair: whole steps)
    assert np.all(u[:, [0, 2]] == 0.0)  # the yaw's and the cabin's accelerations left as they were
    assert np.all(np.abs(u[:, 1]) <= max(abs(a0[1]), options.braking * lim.acceleration[1]) + 1e-9)
    guesses = initial_guesses(problem, 2, seed=0)
    assert [name for name, _, _ in guesses] == ["from the start: yaw spun up", "from the start: yaw spun up the other way"]
    for name, x, _ in guesses:
        assert abs(x[-1, n + 1]) < 1e-4, name
        assert np.all(x[:, 1] < lim.position_max[1]), name


def test_braked_joints_come_to_rest_within_their_limits():
    """plan.braked: with jerk limits the acceleration ramps (at most J a step) to at most A against the
    motion and the rate ends at zero; without them the acceleration is held over each interval, at most
    A, and the rate ends exactly at zero after |qd| / A."""
    from desdemona.machine.plan import braked, node_states, ramp

    h, A, J = np.full(200, 0.05), np.array([0.5, 2.0]), np.array([1.0, 20.0])
    qd0, a0 = np.array([1.2, -0.7]), np.array([0.4, 0.0])
    u = braked(qd0, a0, h, A, J)
    starts, jerks = ramp(u, h[:, None], a0, J)
    assert np.all(np.abs(jerks) <= J + 1e-12)
    assert np.all(np.abs(starts) <= np.maximum(np.abs(a0), A) + 1e-12)
    _, qd = node_states(np.zeros(2), qd0, starts, h[:, None], jerks)
    assert np.all(np.abs(qd[-1]) < 1e-6) and np.all(np.abs(u[-1]) < 1e-2)
    held = braked(qd0, a0, h, A)
    assert np.all(np.abs(held) <= A + 1e-12)
    assert np.allclose(qd0 + np.cumsum(held * h[:, None], axis=0)[-1], 0.0, atol=1e-12)
    assert np.count_nonzero(np.isclose(held[:, 0], -0.5)) == 48  # 1.2 m/s at 0.5 m/s^2: 2.4 s
    assert np.all(np.abs(held[48:, 0]) < 1e-12)
    assert not braked(np.zeros(2), np.zeros(2), h, A, J).any() and not braked(np.zeros(2), np.zeros(2), h, A).any()


def test_batch_solves_in_the_window_asked_and_chooses_as_optimize_does(tmp_path, params, monkeypatch):
    """``batch --window`` solves each job in windows (batch.csv says how many), and without it a job is
    resolved as ``optimize`` resolves it: one session, one solve (:mod:`desdemona.runs.solve`)."""
    import csv

    from desdemona.runs import batch, solve

    path = tmp_path / "long.csv"
    profiles.write_csv(path, _long(50.0))
    out = tmp_path / "out"
    code = main(["batch", str(path), "--configs", "yaw-track", "--out", str(out), "--window", "30", "--h-u", "0.2",
                 "--starts", "1", "--processes", "1", "--no-view", "--quiet"])
    with open(out / "batch.csv") as table:
        rows = list(csv.DictReader(table))
    assert code == 0 and [(r["status"], r["windows"]) for r in rows] == [("ok", "3")]
    assert "windows" in (out / "long--yaw-track" / "summary.json").read_text()
    # without --window: the default of optimize's, here windows above 40 s (in this process)
    monkeypatch.setattr(windows, "WHOLE_UP_TO", 40.0)
    model, choices = Model(params, "yaw-track"), session.Choices(h_u=0.2)
    assert solve.resolve(_long(50.0), model, choices, workers=1, starts=1).window == windows.DEFAULT_WINDOW
    job = batch.run_job(batch.Job(str(path), "yaw-track", view=False), params, choices, OptimizeOptions(starts=1),
                        str(tmp_path))
    assert (job.status, job.windows) == ("ok", 3), job.message
    assert solve.resolve(_long(30.0), model, choices, workers=1, starts=1).window is None

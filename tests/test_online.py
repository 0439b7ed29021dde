"""The on-line controller: closed loop against the classical loop and the off-line optimum, faults."""

import argparse
import dataclasses
import json

import numpy as np
import pytest

from desdemona import Model, profiles
from desdemona.baselines.classical import still_home
from desdemona.baselines.followers import tilt_angles
from desdemona.check.simulate import check, closed_loop
from desdemona.control.mpc import HOMING_AFTER, MPC, REST_RATE, SHIFT_MAX, MPCOptions, _Solved
from desdemona.control.online import OnlineOptions, run
from desdemona.control.predictors import (
    HOLD_PERSISTENCE,
    PREDICTORS,
    HoldPredictor,
    cue_age,
    predict_hold,
    predict_linear,
    predict_perfect,
)
from desdemona.cueing.formulation import ProblemOptions
from desdemona.cueing.offline import OptimizeOptions, optimize
from desdemona.machine.plan import HOMING_RATE, HOMING_TIME, State, advance, homing_rate
from desdemona.occupant.perception import thesis_model
from desdemona.profiles import DesiredPath, along_vertical

# No deadline in tests: timings are measured in the benchmark, never asserted here.
OPTIONS = MPCOptions(horizon=1.0, step=0.05, deadline=float("inf"))


def dfs_runs(params, path, method="rti"):
    model = Model(params, "dfs")
    result = run(path, model, OnlineOptions(dataclasses.replace(OPTIONS, method=method)))
    # the bound no on-line controller can beat: the off-line optimum from the same state, rest
    offline = optimize(path, model, OptimizeOptions(ProblemOptions(h_u=OPTIONS.step, initial="rest"), starts=2))
    return result.loop, result.check, result.baseline_check, offline.check


@pytest.mark.parametrize("path, method", [(profiles.dfs_catapult(), "rti"), (profiles.dfs_catapult(), "nlp"),
                                          (profiles.roller_coaster(duration=15.0), "rti")],
                         ids=["catapult-rti", "catapult-nlp", "roller-coaster-rti"])
def test_dfs_mpc_beats_the_classical_loop_and_nears_the_offline_optimum(params, path, method):
    loop, mpc, classical, offline = dfs_runs(params, path, method)
    assert mpc.passed and classical.passed
    assert mpc.rms < classical.rms
    assert mpc.rms <= 1.2 * offline.rms
    assert set(loop.sources) == {"mpc"}


def test_yaw_track_cabin_closed_loop_keeps_every_limit(params):
    path = profiles.catapult(level=15.0, push=1.0, quiet=0.5, duration=4.0)
    model = Model(params, "yaw-track-cabin")
    result = run(path, model, OnlineOptions(OPTIONS)).check
    assert result.passed
    assert result.rms_channels[4] < np.sqrt(np.mean(path.S_d[:, 4] ** 2))  # better than not moving


class Faulty(MPC):
    """An MPC whose solver fails or runs late on chosen steps."""

    def __init__(self, *args, fail=(), late=(), **kw):
        super().__init__(*args, **kw)
        self.fail, self.late, self.count = set(fail), set(late), 0

    def _solve(self, q, qd, a, data, **kw):
        solved = super()._solve(q, qd, a, data, **kw)
        self.count += 1
        if self.count - 1 in self.fail:
            return solved._replace(success=False)
        if self.count - 1 in self.late:
            return solved._replace(success=True, elapsed=2.0 * self.deadline)
        return solved


def faulty_predictor(bad_steps, kind):
    def predict(path, now, horizon):
        preview = predict_perfect(path, now, horizon)
        if round(now / OPTIONS.step) in bad_steps:
            if kind == "nan":
                M = preview.M_d.copy()
                M[3] = np.nan
                return preview.t, M
            return predict_perfect(path, now, horizon / 3)  # short
        return preview
    return predict


@pytest.mark.parametrize("fault", ["fail", "late", "nan", "short", "long outage"])
def test_fallback_engages_and_the_run_stays_within_limits(params, fault):
    model = Model(params, "dfs")
    path = profiles.dfs_catapult()
    steps = range(60, 70) if fault != "long outage" else range(60, 140)  # 80 steps: four horizons
    kwargs = {"fail": steps} if fault in ("fail", "long outage") else {"late": steps} if fault == "late" else {}
    # a deadline no real solve comes near, so that only the injected steps are late
    controller = Faulty(model, dataclasses.replace(OPTIONS, deadline=30.0), **kwargs)
    predictor = faulty_predictor(set(steps), fault) if fault in ("nan", "short") else predict_perfect
    loop = closed_loop(controller, path, predictor)
    assert len(loop.plan.u) == int(path.duration / OPTIONS.step)
    assert all(loop.sources[k] != "mpc" for k in steps)
    assert loop.sources[59] == "mpc" and loop.sources[-1] == "mpc"
    if fault == "long outage":
        assert "brake" in loop.sources and "shifted" in loop.sources
    else:
        assert {loop.sources[k] for k in steps} == {"shifted"}
    result, _ = check(model, path, loop.plan, step=OPTIONS.step)
    assert result.passed, result.describe_violations()


def test_a_long_outage_follows_the_last_plan_for_at_most_shift_max_then_brakes(params):
    """A 4 s plan is followed open-loop for at most SHIFT_MAX (2 s) of an outage, then the machine
    brakes, and the first plan after it starts from a fresh seed: on the 747 take-off on full with 3 s
    of every 6 s refused, the felt force RMS fell 1.88 -> 1.13 so (the loop 0.95), the stale plan's
    tail had turned the cabin 47 deg beyond a still cabin's error. The run keeps every limit."""
    model = Model(params, "yaw-track")
    path = profiles.catapult(duration=6.0)
    options = MPCOptions(horizon=4.0, step=0.1, deadline=30.0)
    controller = Faulty(model, options, fail=range(10, 45))
    loop = closed_loop(controller, path, predict_perfect)
    shifted = round(SHIFT_MAX / options.step) - 1  # plan_age + 2 steps within SHIFT_MAX
    assert loop.sources[9] == "mpc" and set(loop.sources[10:10 + shifted]) == {"shifted"}
    assert set(loop.sources[10 + shifted:45]) == {"brake"} and set(loop.sources[45:]) == {"mpc"}
    result, _ = check(model, path, loop.plan, step=options.step)
    assert result.passed, result.describe_violations()


class Lost(MPC):
    """An MPC that never gets a plan (its solver fails every cycle, without solving)."""

    def _solve(self, q, qd, a, data, **kw):
        zero = np.zeros((len(self.problem.steps), self.model.n))
        return _Solved((zero, zero), False, 0.0, q, None)


def test_home_is_where_a_still_cabin_cues_the_present_force_and_is_reached_slowly(params):
    """classical.still_home: the track and heave centred, the inner gimbal at its nearest half turn, the
    cabin tilted by tilt coordination so that, still, it feels the force's horizontal part exactly
    (the model's S there), whichever half turn; a tilting joint more than a quarter turn from its home
    has none (NaN), nor has the arm. plan.homing_rate goes there at the homing rates, slowing to settle
    without overshoot, and nowhere while the arm turns."""
    model = Model(params, "full")
    for force in ([0.0, 1.35, 9.7], [1.0, -2.0, 9.5]):
        for psi in (0.1, 3.0, -3.1, 6.2):
            home = still_home(np.array([5.0, 1.0, -0.5, 0.1, psi, 0.1]), model, np.array(force))
            assert np.isnan(home[0]) and home[1] == home[2] == 0.0 and home[4] == pytest.approx(np.pi * round(psi / np.pi))
            felt = np.asarray(model.S(np.nan_to_num(home), np.zeros(6), np.zeros(6))).ravel()[3:]
            np.testing.assert_allclose(felt[1], force[1], atol=1e-9)  # f_y = g sin q4 exactly
            assert felt[0] == pytest.approx(force[0], rel=0.03, abs=1e-9)  # f_x = g cos q4 sin q6
    assert np.isnan(still_home(np.array([0.0, 0, 0, 0, 0, 2.0]), model)[5])  # upside down-ish: stays
    q = np.array([5.0, 3.9, -0.5, 0.3, 2 * np.pi - 0.2, 2.0])
    linear, home = np.isfinite(model.limits.position_min), still_home(q, model)
    turn, line = HOMING_RATE
    np.testing.assert_allclose(homing_rate(q, np.zeros(6), home, linear, 0), [0.0, -line, line, -turn, turn, 0.0])
    assert not homing_rate(q, np.r_[REST_RATE, np.zeros(5)], home, linear, 0).any()
    near = np.array([0, 1e-3, 0, 0, 0, 0.0])  # 1 mm from the centre: the way left over HOMING_TIME
    assert homing_rate(near, np.zeros(6), np.zeros(6), linear, 0)[1] == pytest.approx(-1e-3 / HOMING_TIME)


@pytest.mark.parametrize("config", ["dfs", "dfs-yaw", "yaw-track-cabin"])
def test_a_lost_planner_brakes_and_homes_on_every_configuration(params, config):
    """Every configuration's fallback brakes a turning machine and, once its arm is still, brings the
    rest home within every limit: the arm still, the track centred, the cabin upright."""
    model = Model(params, config)
    options = MPCOptions(horizon=1.0, step=0.05)
    mpc, t = Lost(model, options), np.arange(0.0, 1.05, 0.05)
    values = np.full(len(t), 12.0) if config == "dfs-yaw" else np.tile([0.0, 0, 0, 0, 0, 12.0], (len(t), 1))
    q, qd = np.full(model.n, 0.2), np.r_[0.5, np.zeros(model.n - 1)]
    state = State(q, qd, np.zeros(model.n))
    for _ in range(round(30.0 / options.step)):
        command = mpc.step(state, (t, values))
        assert command.source == "brake" and mpc._safe_sequence(state, command.sequence, command.jerks)
        state = state.advance(command.qdd, options.step, command.jerks[0])
    np.testing.assert_allclose(state.qd, 0.0, atol=1e-4)
    np.testing.assert_allclose(state.q[1:], 0.0, atol=1e-3)


@pytest.mark.parametrize("forward", [0.0, 1.35])
def test_a_lost_planner_brakes_then_brings_the_cabin_home_slowly(params, forward):
    """With no plan for good (full, every solve failing), the brake stops the machine, holds it for
    HOMING_AFTER, then brings it home at the homing rates, the cabin tilted by tilt coordination of the
    present force: level under 1 g, pitched under a held forward force (as the classical washout
    tilts), every cycle within every limit and no joint faster than its homing rate once stopped. On the 747 take-off with every
    plan refused from 20 s, holding the pose where it stopped gave a felt force RMS of 1.65, going
    level 1.89, the tilt 0.93 (the classical loop 0.95): benchmarks/outages.py."""
    model = Model(params, "full")
    options = MPCOptions(horizon=1.0, step=0.05)
    mpc, g = Lost(model, options), params.gravity
    t = np.arange(0.0, 1.05, 0.05)
    values = np.tile([0.0, 0.0, 0.0, 0.0, forward, np.sqrt(g * g - forward * forward)], (len(t), 1))
    state = State(np.array([0.0, 0.5, -0.3, 0.25, 0.1, -0.2]), np.r_[0.02, 0.2, -0.2, 0.1, 0.0, 0.05], np.zeros(6))
    rates, positions = [], []
    for _ in range(round(40.0 / options.step)):
        command = mpc.step(state, (t, values))
        assert command.source == "brake" and mpc._safe_sequence(state, command.sequence, command.jerks)
        state = state.advance(command.qdd, options.step, command.jerks[0])
        rates.append(state.qd.copy())
        positions.append(state.q.copy())
    stopped = round(HOMING_AFTER / options.step)  # held where it stopped until then
    np.testing.assert_allclose(positions[stopped - 1], positions[stopped * 3 // 4], atol=2e-3)  # coming to rest
    roll, pitch = tilt_angles(0.0, forward, g)
    np.testing.assert_allclose(state.q[1:], [0.0, 0.0, roll, 0.0, pitch], atol=1e-3)
    assert np.all(np.abs(rates[stopped:]) <= np.r_[REST_RATE, HOMING_RATE[1], HOMING_RATE[1], [HOMING_RATE[0]] * 3] * 1.01)


def test_brake_command_keeps_every_limit(params):
    model = Model(params, "yaw-track-cabin")
    mpc = MPC(model, OPTIONS)
    lim = model.limits
    q = np.array([0.0, 0.5, 0.0])  # a stoppable state: 0.83 m to brake the track from 2.9 m/s
    qd = np.array([0.95, 0.9, 1.0]) * lim.velocity
    a = np.zeros(3)
    qdd, jerk = mpc.brake(q, qd, a)
    # the acceleration starts where it is and turns towards braking, within the jerk limit
    assert np.all(qdd == a) and np.all(np.sign(jerk) == -np.sign(qd)) and mpc._safe(q, qd, qdd, jerk)
    assert np.all(np.abs(jerk) <= lim.jerk)


def test_predictors():
    path = profiles.catapult()
    now, horizon = 1.1, 0.5
    perfect = predict_perfect(path, now, horizon)
    np.testing.assert_allclose(perfect.S_d[:, 4], path.sample(now + perfect.t)[:, 4])
    hold = predict_hold(path, now, horizon)
    recent = (path.t > now - 0.2) & (path.t <= now)
    line = np.polyfit(path.t[recent], path.S_d[recent, 4], 1)
    np.testing.assert_allclose(hold.S_d[:, 4], np.polyval(line, now), rtol=1e-9)
    np.testing.assert_allclose(predict_hold(path, now, horizon, window=1e-9).S_d[:, 4], path.sample([now])[0, 4])
    fresh = HoldPredictor(persistence=None)  # with no history it holds the same estimate
    np.testing.assert_allclose(fresh(path, now, horizon).S_d, hold.S_d, rtol=1e-12)
    np.testing.assert_allclose(HoldPredictor()(path, now, horizon).S_d[0], hold.S_d[0], rtol=1e-12)
    linear = predict_linear(path, now, horizon)
    k = np.searchsorted(path.t, now, side="right") - 1
    slope = (path.S_d[k, 4] - path.S_d[k - 1, 4]) / (path.t[k] - path.t[k - 1])
    np.testing.assert_allclose(linear.S_d[-1, 4], path.S_d[k, 4] + slope * (now + horizon - path.t[k]), rtol=1e-9)


def test_one_table_of_predictors_gives_the_choices_and_every_check(params, tmp_path, capsys):
    """The command line's choices are the table's (serve's: those that may run live), and every check
    of a predictor's need says, from the table, which option gives it; the library, the session and
    the command all say the same."""
    from desdemona.cli import main
    from desdemona.cli.options import build_parser
    from desdemona.control import predictors
    from desdemona.runs import session

    def choices(command):
        sub = next(a for a in build_parser()._actions if isinstance(a, argparse._SubParsersAction))
        return tuple(next(a for a in sub.choices[command]._actions if a.dest == "predictor").choices)

    assert choices("online") == predictors.names() == tuple(PREDICTORS)
    assert choices("serve") == predictors.names(live=True) == tuple(n for n, k in PREDICTORS.items() if k.live)
    assert "perfect" not in predictors.names(live=True)  # it needs the future
    assert {n: k.needs for n, k in PREDICTORS.items() if k.needs} == {"route": predictors.REFERENCE,
                                                                      "forecast": predictors.FORECAST}
    path, model = profiles.catapult(), Model(params, "yaw-track")
    for call in (lambda: predictors.predictor("route"), lambda: OnlineOptions(predictor="route"),
                 lambda: session.online(path, model, predictor="route"),
                 lambda: session.live(model, channels=6, predictor="route")):
        with pytest.raises(ValueError, match="--predictor route needs --reference PROFILE_OR_CSV, a recording"):
            call()
    with pytest.raises(ValueError, match="--predictor forecast needs --forecast FILE, the vehicle's forecasts"):
        predictors.predictor("forecast")
    session.live(model, channels=6, predictor="forecast")  # live: the host sends its forecasts
    for call in (lambda: predictors.predictor("hold", reference=path),
                 lambda: OnlineOptions(predictor="hold", reference=path),
                 lambda: session.online(path, model, predictor="linear", reference=path)):
        with pytest.raises(ValueError, match="--reference is used only with --predictor route"):
            call()
    with pytest.raises(ValueError, match="--predictor perfect: a live session uses one of hold, linear"):
        session.live(model, channels=6, predictor="perfect")
    with pytest.raises(ValueError, match="--predictor psychic: must be one of perfect, hold"):
        OnlineOptions(predictor="psychic")
    out = tmp_path / "never"
    assert main(["online", "catapult", "--config", "yaw-track", "--predictor", "route", "--out", str(out)]) == 2
    assert "--predictor route needs --reference" in capsys.readouterr().err and not out.exists()


def test_online_command_writes_the_folder(tmp_path, capsys):
    from desdemona.cli import main

    out = tmp_path / "online"
    assert main(["online", "dfs-catapult", "--config", "dfs", "--horizon", "1", "--step", "0.05",
                 "--predictor", "perfect", "--out", str(out)]) == 0
    names = {p.name for p in out.iterdir()}
    assert {"trajectory.csv", "summary.json", "trajectory.mat", "cycles.csv", "online.png",
            "compute_time.png", "modulus.png", "limits.png"} <= names
    summary = json.loads((out / "summary.json").read_text())
    assert summary["metrics"]["limits_kept"] is True
    assert summary["metrics"]["rms_modulus"] < summary["metrics"]["rms_modulus_classical_loop"]
    assert summary["cycles"]["count"] == 240
    assert (out / "cycles.csv").read_text().count("\n") == 241
    assert main(["online", "dfs-catapult", "--horizon", "50", "--out", str(tmp_path / "x")]) == 2
    assert "--horizon" in capsys.readouterr().err
    assert not (tmp_path / "x").exists()


def test_online_warns_when_most_cycles_ran_without_a_fresh_plan(tmp_path, capsys):
    """A deadline no plan can meet (1 us): every cycle falls back, the run still keeps every limit
    (exit 0, written), and the command says on stderr how many cycles went without a plan, why, and
    what gives the plans their time; a run whose plans all came says nothing."""
    from desdemona.cli import main
    from desdemona.cli.commands import fallback_warning

    out = tmp_path / "late"
    assert main(["online", "cosine", "--config", "yaw-track", "--horizon", "1", "--step", "0.05",
                 "--deadline", "1e-6", "--out", str(out), "--no-view"]) == 0
    err = capsys.readouterr().err
    cycles = (out / "cycles.csv").read_text().count("\n") - 1
    assert f"warning: {cycles:,} of {cycles:,} cycles (100 %) ran without a fresh plan" in err
    assert f"deadline missed {cycles:,} times" in err and "against 0.001 ms" in err and "--deadline" in err
    assert fallback_warning(("mpc",) * 100, ("",) * 100, np.full(100, 1e-3), 0.02) == ""
    mixed = ("mpc",) * 90 + ("brake",) * 10
    warning = fallback_warning(mixed, ("",) * 90 + ("solver failed",) * 10, np.full(100, 1e-3), 0.02)
    assert warning.startswith("10 of 100 cycles (10 %)") and "solver failed 10 times" in warning
    assert "in part" in warning and "--deadline" not in warning  # not late: more time would not help


def test_perceived_mpc_lowers_the_perceived_error(params):
    """yaw-track-cabin on-line with the thesis' vestibular model carried from step to step."""
    model = Model(params, "yaw-track-cabin")
    path = profiles.catapult(level=15.0, push=1.0, quiet=0.5, duration=4.0)
    perceived = {}
    for perception in (None, thesis_model()):
        loop = run(path, model, OnlineOptions(dataclasses.replace(OPTIONS, perception=perception))).loop
        result, _ = check(model, path, loop.plan, step=OPTIONS.step, perception=thesis_model())
        assert result.passed and set(loop.sources) == {"mpc"}
        perceived[perception is not None] = result.rms_perceived
    assert perceived[True] < perceived[False]


@pytest.mark.parametrize("config", ["dfs", "yaw-track", "yaw-track-cabin"])
def test_from_rest_the_mpc_leaves_the_stationary_point(params, config):
    """A session starts at rest, where the yaw has no gradient (at 1 g on dfs the modulus has none):
    the MPC must still turn the arm, near the off-line optimum from rest. dfs: the built-in catapult;
    the others: a shorter catapult, where "rest" is where the first plan wants the machine, as the
    off-line problem's rest chooses it (on yaw-track-cabin: 5.14 against 5.78 from home, the off-line
    optimum 4.77). 2 s horizon."""
    short = config != "dfs"
    path = profiles.catapult(level=15.0, push=1.0, quiet=0.5, duration=4.0) if short else profiles.catapult()
    model = Model(params, config)
    options = dataclasses.replace(OPTIONS, horizon=2.0)
    result = run(path, model, OnlineOptions(options))
    offline = optimize(path, model, OptimizeOptions(ProblemOptions(h_u=OPTIONS.step, initial="rest"), starts=3))
    assert np.all(result.plan.qd0 == 0.0)
    if config == "dfs":  # the cabin follows the force: at rest at home, as off-line
        assert np.all(result.plan.q0 == 0.0)
    else:  # placed (within the limits: the check has passed), the arm's angle aside, where that saves a
        # felt error: on yaw-track the placed plan costs what the plan from home does to 8 digits (71.008837)
        assert result.plan.q0[0] == 0.0 and np.any(result.plan.q0[1:] != 0.0) == (config != "yaw-track")
    if config == "yaw-track-cabin":
        home = run(path, model, OnlineOptions(options, initial="home"))
        assert np.all(home.plan.q0 == 0.0) and home.check.passed
        assert result.check.rms < 0.95 * home.check.rms
    if np.abs(offline.trajectory.qd[:, 0]).max() > 0.5:  # where the optimum turns the arm, so does the MPC
        assert np.abs(result.plan.nodes()[1][:, 0]).max() > 0.5
    assert result.check.passed and set(result.loop.sources) == {"mpc"}
    assert result.check.rms <= 1.2 * offline.check.rms
    if config == "dfs":  # the thesis' claim (7.6): anticipation beats the classical loop
        assert result.check.rms <= 0.8 * result.baseline_check.rms


def test_thesis_timing_replans_every_T_c_and_applies_each_plan_one_period_later(params):
    """Thesis 7.5: T_h = 1 s, T_c = 0.4 s, h = 0.1 s; a plan computed from the state at t is applied
    from t + T_c (7.1, figure 7.2). The first plan is computed in the cycle before the session, from
    the start state, so it is the plan an undelayed controller makes at t = 0."""
    path = profiles.catapult()
    model = Model(params, "dfs-yaw")
    timing = MPCOptions(horizon=1.0, step=0.1, replan=0.4, deadline=float("inf"))
    now = run(path, model, OnlineOptions(timing))
    late = run(path, model, OnlineOptions(dataclasses.replace(timing, delay=True)))
    for result, first in ((now, 0.0), (late, -0.4)):
        assert result.check.passed and set(result.loop.sources) == {"mpc"}
        np.testing.assert_allclose(result.loop.cycle_times, np.arange(first, 8.0, 0.4), atol=1e-12)
        assert len(result.plan.u) == 80
        assert result.check.rms < result.baseline_check.rms  # both beat the classical loop
    assert np.any(now.plan.u[:4] != 0.0)
    np.testing.assert_array_equal(late.plan.u[:4], now.plan.u[:4])  # ready when the session starts
    # with perfect preview and an exact plant the state a plan starts from is predicted exactly, so
    # the delay costs nothing; told only the present, a plan acts on news 0.4 s old
    np.testing.assert_allclose(late.plan.u, now.plan.u, atol=1e-9)
    assert late.check.rms == pytest.approx(now.check.rms, rel=1e-9)
    held = [run(path, model, OnlineOptions(dataclasses.replace(timing, delay=delay), predictor="hold")).check.rms
            for delay in (False, True)]
    assert held[1] > held[0]
    # a plan every T_c = 4 steps is solved to convergence, as the thesis does in its T_c; a single
    # real-time iteration per plan is worse (measured 5.27 against 5.03, the off-line bound 4.28)
    assert timing.plan_method == "nlp" and MPCOptions().plan_method == "rti"
    single = run(path, model, OnlineOptions(dataclasses.replace(timing, delay=True, method="rti")))
    assert late.check.rms < 0.97 * single.check.rms


def test_a_short_horizon_plans_on_with_the_path_held(params, tmp_path, capsys):
    """The thesis' timing on the whole-machine dfs: 1 s does not fit the arm's spin-up and the
    gimbals' turn, and a plan priced only to its end leaves the arm idle (felt force 7.02, the bound
    4.74); reaching 2 s with the last previewed value held, 5.70."""
    from desdemona.cli import main

    path, model = profiles.catapult(), Model(params, "dfs")
    timing = MPCOptions(horizon=1.0, step=0.1, replan=0.4, delay=True, deadline=float("inf"))
    assert timing.length == 1.0 and dataclasses.replace(timing, reach=2.0).length == 2.0
    blind, reaching = (run(path, model, OnlineOptions(dataclasses.replace(timing, reach=reach)))
                       for reach in (None, 2.0))
    bound = optimize(path, model, OptimizeOptions(ProblemOptions(h_u=0.1, initial="rest", stoppable=True,
                                                                 braking=timing.braking), starts=3)).check.rms
    assert reaching.check.passed and reaching.check.rms < 0.85 * blind.check.rms
    assert reaching.check.rms < 1.25 * bound < blind.check.rms
    # the command line reaches the default horizon; --reach below --horizon is refused by name
    out = tmp_path / "thesis"
    thesis = ["online", "catapult", "--config", "dfs", "--horizon", "1", "--step", "0.1", "--replan", "0.4", "--delay"]
    assert main([*thesis, "--out", str(out)]) == 0
    assert "reach 2 s" in json.loads((out / "summary.json").read_text())["method"]
    assert main([*thesis, "--reach", "0.5", "--out", str(tmp_path / "x")]) == 2
    assert "--reach 0.5: must be at least --horizon (1 s)" in capsys.readouterr().err
    with pytest.raises(ValueError, match="at least the horizon"):
        MPCOptions(horizon=1.0, reach=0.5)


def test_mpc_method_is_checked():
    with pytest.raises(ValueError, match="one of auto, rti, nlp"):
        MPCOptions(method="sqp")


def test_online_command_thesis_timing(tmp_path, capsys):
    from desdemona.cli import main

    out = tmp_path / "thesis"
    assert main(["online", "catapult", "--config", "dfs-yaw", "--horizon", "1", "--step", "0.1", "--replan", "0.4",
                 "--delay", "--out", str(out)]) == 0
    assert (out / "cycles.csv").read_text().count("\n") == 22  # the cycle before the session, 20 of 0.4 s
    assert main(["online", "catapult", "--config", "dfs", "--step", "0.1", "--replan", "0.25",
                 "--out", str(tmp_path / "x")]) == 2
    assert "whole number of steps" in capsys.readouterr().err


@pytest.mark.parametrize("speed", [1.1, 0.9])
def test_route_predictor_previews_a_faster_or_slower_noisy_replay(params, speed):
    """A ride on a known coaster, replayed 10 % faster or slower with sensor noise: previewed from the
    reference recording, the MPC comes within 30 % of perfect preview and well below holding the
    present value."""
    reference = profiles.roller_coaster(duration=20.0)
    rng = np.random.default_rng(7)
    t = np.arange(0.0, reference.duration / speed, 0.01)
    noisy = reference.sample_modulus(speed * t) + rng.normal(0.0, 0.3, len(t))
    live = DesiredPath("live", t, None, modulus=np.maximum(noisy, 0.0))
    model = Model(params, "dfs")
    options = dataclasses.replace(OPTIONS, horizon=2.0, step=0.05)
    rms = {name: run(live, model, OnlineOptions(options, predictor=name,
                                                reference=reference if name == "route" else None)).check.rms
           for name in ("perfect", "hold", "route")}
    assert rms["route"] <= 1.3 * rms["perfect"]
    assert rms["route"] <= 0.8 * rms["hold"]


SHORT_PATHS = {
    "cosine": lambda: profiles.cosine(duration=3.0),
    "catapult": lambda: profiles.catapult(level=15.0, push=1.0, quiet=0.5, duration=4.0),
    "double-pulse": lambda: profiles.pulses(count=2, width=0.5, gap=0.5, quiet=0.5, tail=1.0),
    "triple-pulse": lambda: profiles.pulses(count=3, width=0.5, gap=0.5, quiet=0.5, tail=1.0),
    "car-lap": lambda: profiles.car_lap(duration_target=8.0),
    "roller-coaster": lambda: profiles.roller_coaster(duration=8.0),
    "dfs-catapult": lambda: profiles.dfs_catapult(),
}
SUITED = [(name, config) for name in SHORT_PATHS for config in ("dfs", "yaw-track", "yaw-track-cabin", "full")
          if config == "dfs" or name not in ("roller-coaster", "dfs-catapult")]


@pytest.mark.parametrize("name, config", SUITED, ids=[f"{n}-{c}" for n, c in SUITED])
def test_every_profile_from_rest_beats_its_classical_baseline(params, name, config):
    """Short versions of every built-in profile on every configuration it suits: from rest, within
    every limit, and better than what a simulator runs today (classical loop or washout)."""
    path = SHORT_PATHS[name]()
    result = run(path, Model(params, config), OnlineOptions(dataclasses.replace(OPTIONS, horizon=2.0, step=0.1)))
    assert result.check.passed and result.baseline_check.passed
    assert np.all(result.plan.qd0 == 0.0)
    assert result.check.rms < result.baseline_check.rms


def test_the_perception_map_is_built_with_the_controller(params):
    """The linear map through which a controller perceives its horizon (CueingProblem.perceive) took
    9 ms to build in a session's first cycle on `dfs` at 100 Hz, beyond that cycle's 10 ms deadline on
    a slower machine: it is built with the controller, before the session, and kept."""
    mpc = MPC(Model(params, "dfs"), dataclasses.replace(OPTIONS, perception=thesis_model()))
    built = mpc.problem._perceive_map
    assert built is not None
    mpc.problem.perceive(np.ones((mpc.problem.N * mpc.problem.m, 6)))
    assert mpc.problem._perceive_map is built


def test_the_felt_filters_follow_every_sub_step_of_a_cycle(params):
    """With perception the MPC carries what the occupant has felt from one cycle to the next: the
    filter state after a cycle is the filter run on S at each of the cycle's m sub-steps."""
    model = Model(params, "yaw-track-cabin")
    mpc = MPC(model, dataclasses.replace(OPTIONS, perception=thesis_model(), substeps=2))
    path = profiles.catapult(level=10.0, push=1.0, quiet=0.2, duration=2.0)
    state = (np.zeros(model.n), np.array([0.5, 0.2, 0.0]), np.array([0.3, 0.5, 0.1]))
    mpc.step(state, path)
    z0 = mpc.z
    command = mpc.step(state, path)
    assert np.abs(mpc.z - z0).max() > 1e-4
    prob, m = mpc.problem, mpc.problem.m
    s = np.arange(m)[:, None] / m * OPTIONS.step
    qdd, jerk = command.sequence[0], command.jerks[0]
    S = model.S(*advance(state[0], state[1], qdd, s, jerk), qdd + jerk * s)
    _, states = prob.filter.simulate(S, z0)
    np.testing.assert_allclose(mpc.z, states[m], rtol=1e-10, atol=1e-12)


def test_the_canals_follow_a_plan_whose_intervals_vary(params, monkeypatch):
    """The canals model (first-order channels) keeps the plan's coarse tail: each stage carries the
    felt rotation over its own interval, as scipy's zero-order hold of that interval's sub-steps does,
    and the controller places its start (at rest the canals feel nothing wherever the machine stands)."""
    import scipy.signal

    from desdemona.cueing import formulation as problem_module
    from desdemona.occupant.perception import canals_model

    model = Model(params, "yaw-track-cabin")
    canals = canals_model()
    options = dataclasses.replace(OPTIONS, horizon=2.0, perception=canals, substeps=2, tail_step=0.2, fine=0.2)
    mpc = MPC(model, options)
    prob = mpc.problem
    assert not prob.uniform and set(np.round(prob.steps, 9)) == {0.05, 0.2}
    rng = np.random.default_rng(5)
    x = np.r_[rng.normal(size=3 * model.n) * 0.3, rng.normal(size=prob.nz)]
    u = rng.normal(size=model.n)
    for k in (0, prob.N - 1):  # a fine interval and a coarse one
        h, m = prob.steps[k], prob.m
        data = prob.with_steps(np.zeros((prob.m * 6, prob.N)))[:, k]
        z_next = np.asarray(prob.stage(x, u, data)[0]).ravel()[prob.n_motion:]
        Ad, Bd, *_ = scipy.signal.cont2discrete(canals.state_space(), h / m, method="zoh")
        z = x[prob.n_motion:]
        q, qd, a = np.split(x[:prob.n_motion], 3)
        for j in range(m):
            t = j * h / m
            z = Ad @ z + Bd @ model.S(*advance(q, qd, a, t, u), a + u * t)
        np.testing.assert_allclose(z_next, z, rtol=1e-10, atol=1e-12)
    # the desired path perceived over the same grid (one linear map a cycle), sub-step by sub-step
    S, z = rng.normal(size=(prob.N * prob.m, 6)), rng.normal(size=prob.nz)
    y, states = prob.perceive(S, z)
    zoh = {h: scipy.signal.cont2discrete(canals.state_space(), h / prob.m, method="zoh") for h in set(prob.steps)}
    for k, h in enumerate(np.repeat(prob.steps, prob.m)):
        Ad, Bd, C, D, _ = zoh[h]
        np.testing.assert_allclose(y[k], C @ z + D @ S[k], rtol=1e-10, atol=1e-12)
        z = Ad @ z + Bd @ S[k]
        np.testing.assert_allclose(states[k + 1], z, rtol=1e-10, atol=1e-12)
    with monkeypatch.context() as patch:  # a horizon too long for the map: step by step, the same
        patch.setattr(problem_module, "PERCEPTION_MAP_SIZE", 0)
        np.testing.assert_allclose(prob.perceive(S, states[0])[1], states, rtol=1e-12, atol=1e-14)
    path = profiles.catapult(level=10.0, push=1.0, quiet=0.5, duration=3.0)
    q0, _ = mpc.place((np.zeros(model.n), np.zeros(model.n)), path)
    assert mpc.plan is not None and np.any(q0 != 0.0)
    assert mpc.step((q0, np.zeros(model.n)), path).source == "mpc"
    with pytest.raises(ValueError, match="uniform grid"):
        ProblemOptions(steps=(0.05, 0.1), perception=thesis_model())
    assert len(set(dataclasses.replace(options, perception=thesis_model()).grid())) == 1


@pytest.mark.parametrize("config, horizon", [("yaw-track", 4.0), ("dfs", 2.0)])
def test_the_command_plans_further_ahead_where_the_track_moves(tmp_path, config, horizon):
    """Without --horizon: 4 s where the track's position must be planned, 2 s on dfs, at most the path."""
    from desdemona.cli import main
    from desdemona.control.mpc import default_horizon

    assert default_horizon(Model(config=config).config) == horizon
    out = tmp_path / config
    path = "catapult" if config == "yaw-track" else "dfs-catapult"
    assert main(["online", path, "--config", config, "--step", "0.1", "--out", str(out)]) == 0
    assert f"horizon {horizon:g} s" in json.loads((out / "summary.json").read_text())["method"]
    short = tmp_path / "short.csv"
    profiles.write_csv(short, profiles.catapult(level=10.0, push=1.0, quiet=0.5, duration=3.0))
    if config == "yaw-track":
        assert main(["online", str(short), "--config", config, "--step", "0.1", "--out", str(tmp_path / "s")]) == 0
        assert "horizon 3 s" in json.loads((tmp_path / "s" / "summary.json").read_text())["method"]


def test_online_command_starts_at_rest_steady_or_a_given_state(tmp_path, capsys):
    """--initial rest (the default: on dfs every joint still at its centre), steady (on dfs a centrifuge
    spun up to the path's first modulus, the cabin aligned with the force) or given (--initial-state);
    the command offers every start the library has."""
    from desdemona.baselines.classical import steady_start
    from desdemona.cli import main

    short = tmp_path / "short.csv"
    path = profiles.dfs_catapult(duration=3.0)
    profiles.write_csv(short, path)
    common = [str(short), "--config", "dfs", "--step", "0.05", "--horizon", "1", "--no-view"]

    def start(out):
        import csv

        lines = [line for line in (out / "trajectory.csv").read_text().splitlines() if not line.startswith("#")]
        first = next(csv.DictReader(lines))
        return [float(first[c]) for c in ("q_yaw", "q_outer_gimbal", "q_cabin", "qd_yaw", "qd_outer_gimbal")]

    assert main(["online", *common, "--out", str(tmp_path / "rest")]) == 0
    np.testing.assert_array_equal(start(tmp_path / "rest"), 0.0)  # on dfs, rest is at home
    summary = json.loads((tmp_path / "rest" / "summary.json").read_text())
    assert summary["start"]["initial"] == "rest" and not any(summary["start"]["q0"].values())
    assert main(["online", *common, "--initial", "steady", "--out", str(tmp_path / "steady")]) == 0
    q0, qd0 = steady_start(path, Model(config="dfs"))
    M0 = path.modulus[0]
    np.testing.assert_allclose(qd0, [np.sqrt(np.sqrt(M0**2 - 9.81**2) / 4.0), 0, 0, 0])
    np.testing.assert_allclose(start(tmp_path / "steady"), [q0[0], q0[1], q0[3], qd0[0], 0.0], atol=1e-9)
    summary = json.loads((tmp_path / "steady" / "summary.json").read_text())
    assert summary["quality"]["felt_direction"]["peak_deg"] < 5.0  # aligned from the first instant
    state = "0,0.1,0,0;1.2,0,0,0"
    assert main(["online", *common, "--initial", "given", "--initial-state", state, "--out", str(tmp_path / "given")]) == 0
    np.testing.assert_allclose(start(tmp_path / "given"), [0, 0.1, 0, 1.2, 0], atol=1e-12)
    assert "started (given): yaw 0 rad at 1.2 rad/s, outer_gimbal 0.1 rad, inner_gimbal 0 rad, cabin 0 rad\n" in capsys.readouterr().out
    assert main(["online", *common, "--initial-state", state, "--out", str(tmp_path / "given2")]) == 0  # given
    np.testing.assert_allclose(start(tmp_path / "given2"), [0, 0.1, 0, 1.2, 0], atol=1e-12)
    from desdemona.cli.options import build_parser
    from desdemona.control.online import INITIAL_CHOICES

    online_command = build_parser()._subparsers._group_actions[0].choices["online"]
    assert next(a for a in online_command._actions if a.dest == "initial").choices == INITIAL_CHOICES
    for bad, message in ((["--initial", "given"], "needs --initial-state"),
                         (["--initial", "steady", "--initial-state", state], "goes with --initial given"),
                         (["--initial", "given", "--initial-state", "0,0,0,0;9,0,0,0"], "above its limit")):
        assert main(["online", *common, *bad, "--out", str(tmp_path / "bad")]) == 2
        assert message in capsys.readouterr().err
        assert not (tmp_path / "bad").exists()


def test_hold_predictor_keeps_noise_out_and_follows_a_step():
    """A 100 Hz log of a steady 14.7 m/s^2 with 0.5 m/s^2 of noise, then a step to 24.5 at 3 s: the
    held value hardly moves on the steady stretch (the bare estimate wanders by its standard error,
    about 0.2 m/s^2), follows the step within a few samples, and on a clean ramp it is the line's end."""
    rng = np.random.default_rng(3)
    t = np.arange(0.0, 4.0, 0.01)
    clean = np.where(t < 3.0, 14.7, 24.5)
    path = DesiredPath("log", t, None, modulus=clean + rng.normal(0.0, 0.5, len(t)))
    hold = HoldPredictor()
    held = np.array([hold(path, now, 1.0).modulus[0] for now in np.arange(0.0, 4.0, 0.02)])
    bare = np.array([predict_hold(path, now, 1.0).modulus[0] for now in np.arange(0.0, 4.0, 0.02)])
    steady = slice(20, 145)  # 0.4-2.9 s
    assert np.std(np.diff(held[steady])) < 0.3 * np.std(np.diff(bare[steady]))
    assert np.abs(held[steady] - 14.7).max() < 0.5
    assert abs(held[np.searchsorted(np.arange(0.0, 4.0, 0.02), 3.2)] - 24.5) < 1.0  # 0.2 s after the step
    ramp = DesiredPath("ramp", t, None, modulus=10.0 + 2.0 * t)
    hold = HoldPredictor()
    for now in (0.5, 1.0, 1.5):
        assert hold(ramp, now, 1.0).modulus[0] == pytest.approx(10.0 + 2.0 * now, abs=1e-9)


def test_cue_age_is_how_long_a_channel_kept_half_its_departure_from_rest():
    times = np.arange(0.0, 3.0, 0.5)  # 0 .. 2.5
    values = np.array([[0.0, 1.0], [4.0, 1.0], [0.9, -2.0], [3.0, -2.0], [2.5, -3.0], [2.0, -2.0]])
    # channel 0: 2.0 now, at >= 1.0 since the 0.9 at t = 1.0: 1.5 s; channel 1: -2.0 now, on that side
    # at >= 1.0 since the +1.0 at t = 0.5: 2.0 s
    np.testing.assert_allclose(cue_age(times, values, np.zeros(2)), [1.5, 2.0])
    np.testing.assert_allclose(cue_age(times, values[:, :1] + 9.81, np.array([9.81])), [1.5])
    np.testing.assert_allclose(cue_age(times, np.ones((6, 1)), np.zeros(1)), [2.5])  # never short: all of it


def test_hold_predictor_expects_a_cue_to_last_as_long_as_it_has():
    """f_z at 1 g with a 0.3 s spike to 20 m/s^2 at 2 s, then 14 m/s^2 from 4 s on, and a roll rate of
    0.5 rad/s from 2 s on (50 Hz calls): 0.2 s into the spike f_z's departure from g is previewed
    weighed by T / (T + tau) with T = HOLD_PERSISTENCE + 0.2 s, 20 s into the plateau with 0.5 + 20 s,
    the roll rate with 0.5 + 0.2 s and 0.5 + 22 s; without persistence, or as a modulus, all are held."""
    t = np.arange(0.0, 30.0, 0.01)
    fz = np.where(t >= 4.0, 14.0, np.where((t >= 2.0) & (t < 2.3), 20.0, 9.81))
    S = np.zeros((len(t), 6))
    S[:, 5], S[:, 0] = fz, np.where(t >= 2.0, 0.5, 0.0)
    path = DesiredPath("spike", t, S)
    modulus = along_vertical(DesiredPath("spike", t, None, modulus=fz))  # as dfs cues it: S and the modulus
    hold, held, hold_modulus = HoldPredictor(), HoldPredictor(persistence=None), HoldPredictor()
    previews = {}
    for now in np.arange(0.0, 24.0 + 1e-9, 0.02):
        previews[round(now, 2)] = hold(path, now, 4.0), held(path, now, 4.0), hold_modulus(modulus, now, 4.0)
    for now, level, age, roll_age in ((2.2, 20.0, 0.2, 0.2), (24.0, 14.0, 20.0, 22.0)):
        decaying, kept, as_modulus = previews[now]
        tau = decaying.t
        lasting = [(HOLD_PERSISTENCE + a) / (HOLD_PERSISTENCE + a + tau) for a in (age, roll_age)]
        np.testing.assert_allclose(decaying.S_d[:, 5] - 9.81, (level - 9.81) * lasting[0], atol=0.05 * (level - 9.81))
        np.testing.assert_allclose(decaying.S_d[:, 0], 0.5 * lasting[1], atol=0.02)
        np.testing.assert_allclose(kept.S_d, np.tile(kept.S_d[0], (len(tau), 1)))
        np.testing.assert_allclose(as_modulus.S_d, np.tile(as_modulus.S_d[0], (len(tau), 1)))
    assert previews[2.2][0].S_d[-1, 5] < 11.5 < 13.0 < previews[24.0][0].S_d[-1, 5]


def test_a_steady_start_tilts_the_cabin_to_the_first_desired_force(params):
    """Off dfs, --initial steady starts still with the cabin tilted by tilt coordination of the path's
    first force (the cosine starts at f_y = 5 m/s^2, held at g/2 by 30 deg), and the classical
    washout's filters start trimmed to it."""
    from desdemona.baselines.classical import steady_start

    path = profiles.cosine()
    model = Model(params, "full")
    q0, qd0 = steady_start(path, model)
    np.testing.assert_array_equal(qd0, 0.0)
    f = model.S(q0, qd0, np.zeros(6))[3:6]
    np.testing.assert_allclose(f, [0.0, 4.905, 9.81 * np.cos(np.pi / 6)], atol=1e-12)  # f_y 5 held at g/2: 30 deg
    np.testing.assert_array_equal(q0[:3], 0.0)  # yaw, track and heave at home
    car = profiles.get_profile("car-lap")  # braking at 9 m/s^2: pitched by 30 deg, f_x = -g/2
    np.testing.assert_allclose(model.S(*steady_start(car, model), np.zeros(6))[3], -4.905, atol=1e-12)
    for config in ("yaw-track", "yaw-track-cabin"):  # nothing can tilt: rest at home
        assert not np.any(np.r_[steady_start(path, Model(params, config))])
    options = dataclasses.replace(OPTIONS, horizon=2.0)
    home, steady, rest = (run(path, model, OnlineOptions(options, initial=start)) for start in ("home", "steady", "rest"))
    assert steady.check.passed and np.allclose(steady.plan.q0, q0)
    assert steady.check.rms < 0.5 * home.check.rms
    # at rest where the first plan wants it: tilted too, by the plan's own choice
    assert rest.check.passed and rest.check.rms < 0.5 * home.check.rms
    # on a steady lateral force the trimmed washout's high-pass sees no step at t = 0: its track
    # stays at the centre; from zero filter states it runs 1.4 m out and back
    from desdemona.baselines.washout import classical_washout

    t = np.arange(0.0, 2.0, 0.05)
    level = DesiredPath("steady", t, np.tile([0.0, 0.0, 0.0, 0.0, 5.0, 9.81], (len(t), 1)))
    start = steady_start(level, model)
    track = [np.abs(classical_washout(level, model, state=start, trimmed=trimmed).nodes()[0][:, 1]).max()
             for trimmed in (True, False)]
    assert track[0] < 1e-9 and track[1] > 1.0
    with pytest.raises(ValueError, match="go together"):
        OnlineOptions(initial="given")


def test_the_online_command_weighs_as_optimize_does(tmp_path):
    """Off dfs the command's cost weighs false rotation by the perception thresholds ("felt"), as
    `optimize` does, unless told --weights path; on dfs the path's own (rotation 0.1)."""
    from desdemona.cli import main

    short = tmp_path / "short.csv"
    path = profiles.catapult(level=10.0, push=1.0, quiet=0.5, duration=3.0)
    profiles.write_csv(short, path)
    used = {}
    for spec in (None, "path"):
        out = tmp_path / f"w-{spec}"
        extra = [] if spec is None else ["--weights", spec]
        assert main(["online", str(short), "--config", "yaw-track", "--step", "0.1", *extra, "--out", str(out)]) == 0
        used[spec] = json.loads((out / "summary.json").read_text())["options"]["mpc"]["weights"]
    np.testing.assert_allclose(used[None], profiles.weights_for("felt", path))
    np.testing.assert_allclose(used["path"], path.weights)
    assert used[None][2] > 5.0 * used["path"][2]  # yaw rate weighed by its threshold


def test_a_placed_start_is_within_half_a_turn_of_home_and_feels_the_same():
    """A freely turning gimbal placed four turns away (24.3 rad) starts at the same attitude within
    half a turn: the cue and the torques are those of the placed start."""
    model = Model(config="full")
    controller = MPC(model, OPTIONS)
    q = np.array([0.3, 1.0, -0.2, 24.3, -7.0, 3.5])
    qd, qdd = np.zeros(6), np.full(6, 0.1)
    wrapped = controller._within_a_turn(q)
    bounded = np.isfinite(model.limits.position_min)
    assert np.all(np.abs(wrapped[~bounded]) <= np.pi) and np.array_equal(wrapped[bounded], q[bounded])
    np.testing.assert_allclose(wrapped[3], 24.3 - 8 * np.pi)
    np.testing.assert_allclose(model.S(wrapped, qd, qdd), model.S(q, qd, qdd), atol=1e-12)
    tau = model.functions["tau"]
    np.testing.assert_allclose(np.asarray(tau(wrapped, qd, qdd)), np.asarray(tau(q, qd, qdd)), atol=1e-9)


def test_online_perception_reports_the_perceived_error_of_the_controller_and_the_loop(tmp_path, capsys):
    from desdemona.cli import main

    out = tmp_path / "felt"
    assert main(["online", "cosine", "--config", "yaw-track", "--horizon", "1", "--step", "0.05",
                 "--deadline", "100", "--perception", "thesis", "--out", str(out), "--no-view"]) == 0
    metrics = json.loads((out / "summary.json").read_text())["metrics"]
    assert metrics["rms_perceived"] > 0 and metrics["rms_perceived_classical"] > 0
    assert f"perceived {metrics['rms_perceived']:.4g}" in capsys.readouterr().out
    assert main(["online", "dfs-catapult", "--config", "dfs-yaw", "--perception", "thesis",
                 "--out", str(tmp_path / "modulus")]) == 2
    assert "not to the dfs modulus" in capsys.readouterr().err


def test_a_modulus_below_g_is_planned_for_as_g_and_the_cabin_stays_upright():
    """On dfs the felt force is never weaker than g. A desired modulus of 3.5 m/s^2 for 9 s, chased as
    it is with the future known, turned the cabin over (felt force 178 deg from the occupant's
    vertical, 359 deg/s of false rotation); planned for as g, the nearest the machine can do, it stays
    within 30 deg and follows better than the classical loop."""
    from desdemona.profiles import at_least_g

    np.testing.assert_array_equal(at_least_g(np.array([3.0, 12.0])), [profiles.G, 12.0])
    S = at_least_g(np.array([[0, 0, 0, 0.0, 3.0, 4.0], [0, 0, 0, 0, 0, 0], [0, 0, 0, 0, 0, 20.0]]))
    np.testing.assert_allclose(S[:, 3:], [[0, 0.6 * profiles.G, 0.8 * profiles.G], [0, 0, profiles.G], [0, 0, 20]])
    t = np.arange(0, 20.001, 0.01)
    M = np.where((t > 5) & (t < 14), 3.5, 14.7)
    M = np.convolve(np.r_[np.full(50, M[0]), M, np.full(50, M[-1])], np.ones(101) / 101, mode="valid")
    path = DesiredPath("low", t, None, modulus=M)
    result = run(path, Model(config="dfs"), OnlineOptions(MPCOptions(horizon=2.0, step=0.02, deadline=float("inf"),
                                                                     reach=2.0)))
    assert result.quality.felt_direction()["peak_deg"] < 30.0
    assert result.check.rms < result.baseline_check.rms


def _hold_session(path, model, **timing):
    """The ``online`` command's session with the hold predictor, without a deadline."""
    from desdemona.runs import session

    return session.online(path, model, predictor="hold", deadline=float("inf"), **timing)


def _session_run(path, **timing):
    """The ``online`` command's run on yaw-track-cabin with the hold predictor, without a deadline."""
    model = Model(config="yaw-track-cabin")
    cued = _hold_session(path, model, **timing)
    return run(cued.path, model, cued.options)


def _worst_reversals(result) -> float:
    return max(result.quality.to_dict()["joints"]["reversals_per_s"].values())


class _HeldAsItIs(HoldPredictor):
    def __init__(self):
        super().__init__(persistence=None)


@pytest.mark.parametrize("share", [1.0, 0.5])
def test_an_unreachable_held_force_does_not_swing_the_plan_from_cycle_to_cycle(share, monkeypatch):
    """A sustained force beyond what yaw-track-cabin can hold (the rudder kick's -3.2 m/s^2 forward,
    held as it is over the horizon): the cabin's yaw turns the small force the machine can hold towards
    it. The Gauss-Newton model leaves out the curvature of that large residual, so one full QP step a
    cycle overshoots and the next swings back: 39 reversals a second of the cabin's acceleration. Half
    the step from the previous plan (the default) is below one a second
    (docs/benchmarks/damped-real-time-iteration.md), with the held force as it is and with the hold predictor's
    persistence. Shown with the
    raw rotation in the cost, where it was found (the canals' cost happens not to swing here)."""
    t = np.arange(0, 10.0 + 1e-9, 0.01)
    S = np.tile([0.0, 0.0, 0.0, -3.2, 1.2, 8.9], (len(t), 1))
    S[:, 2] = 0.03 * np.sin(0.5 * t)
    if share == 0.5:
        assert _worst_reversals(_session_run(DesiredPath("unreachable", t, S), rti_step=share)) < 1.0
    monkeypatch.setitem(PREDICTORS, "hold", dataclasses.replace(PREDICTORS["hold"], make=_HeldAsItIs))
    result = _session_run(DesiredPath("unreachable", t, S), rti_step=share, perception=None)
    if share == 1.0:
        assert _worst_reversals(result) > 10.0  # the cause, shown: full steps swing
    else:
        assert _worst_reversals(result) < 1.0


def test_a_held_spike_is_not_planned_for_as_a_sustained_cue(monkeypatch):
    """An elevator doublet's shape on full: f_z -18 m/s^2 for 0.5 s, then 35 for 1 s, then 1 g again.
    Held as it is for the 4 s horizon, the -18 m/s^2 is planned for as lasting, and the gimbals turn
    the cabin over towards it and back: the felt f_z runs against the desired (correlation -0.74,
    felt force RMS 12.6). Expected to last as long as it has (the default), the plan follows it
    (correlation 0.83, RMS 10.4; c172-doublet on full: 11.8 -> 9.0)."""
    t = np.arange(0, 8.0 + 1e-9, 0.01)
    S = np.zeros((len(t), 6))
    S[:, 5] = 9.81
    S[(t >= 2.0) & (t < 2.5), 5] = -18.0
    S[(t >= 2.5) & (t < 3.5), 5] = 35.0
    S[(t >= 2.0) & (t < 3.5), 1] = -0.3
    path = DesiredPath("spike", t, S)

    def felt(result):
        quality = result.quality.to_dict()["channels"]
        return np.linalg.norm([quality["rms"][c] for c in ("fx", "fy", "fz")]), quality["correlation"]["fz"]

    model = Model(config="full")
    cued = _hold_session(path, model)
    expected, expected_correlation = felt(run(cued.path, model, cued.options))
    monkeypatch.setitem(PREDICTORS, "hold", dataclasses.replace(PREDICTORS["hold"], make=_HeldAsItIs))
    cued = _hold_session(path, model)
    held, held_correlation = felt(run(cued.path, model, cued.options))
    assert held_correlation < 0.0 < 0.5 < expected_correlation
    assert expected < 0.9 * held


def test_a_still_yaw_is_drawn_towards_a_spin_up_by_degrees():
    """A still yaw is seeded with a spin-up (zero rate is a stationary point of the cue). Switched to
    a spin-up whenever the yaw's rate over the seed dipped below REST_RATE, a slow steady turn (the
    737's, on yaw-track-cabin) was re-seeded every few cycles and each re-seed kicked every joint (5
    reversals a second); the seed is drawn towards the spin-up by degrees now, all the way at rest and
    not at all from REST_RATE on."""
    model = Model(config="yaw-track-cabin")
    mpc = MPC(model, MPCOptions(horizon=1.0, step=0.05, deadline=float("inf")))
    N = mpc.problem.N
    spin = mpc.options.spin_up * model.limits.acceleration[0]
    seeds = []
    for rate in (0.0, 0.5 * REST_RATE, 0.999 * REST_RATE, 1.001 * REST_RATE):
        seeds.append(mpc._leave_rest(np.array([rate, 0.0, 0.0]), np.zeros((N, model.n)))[:, 0])
    np.testing.assert_allclose(seeds[0], spin)
    np.testing.assert_allclose(seeds[1], 0.5 * spin, rtol=0.05)
    assert np.all(np.abs(seeds[2]) < 0.01 * spin) and np.all(seeds[3] == 0.0)


def test_the_real_time_iteration_takes_the_share_of_its_step():
    with pytest.raises(ValueError, match="rti_step"):
        MPCOptions(rti_step=0.0)
    model = Model(config="yaw-track-cabin")
    mpc = MPC(model, MPCOptions(horizon=1.0, step=0.05, deadline=float("inf")))
    prob = mpc.problem
    x, u = prob.guess(np.zeros(model.n), np.array([0.3, 0.0, 0.0]), np.zeros((prob.N, model.n)), np.zeros(model.n))
    w = prob.pack(x, u)
    bounds = prob.start_bounds(np.zeros(model.n), np.array([0.3, 0.0, 0.0]), np.zeros(model.n))
    data = np.asarray(prob.with_steps(np.tile([0, 0, 0.1, -2.0, 1.0, 9.0], (prob.N, len(prob.fractions))).T))
    p = data.ravel(order="F")
    whole, ok = mpc._rti(w, p, bounds)
    half, ok_half = mpc._rti(w, p, bounds, 0.5)
    assert ok and ok_half and np.linalg.norm(whole - w) > 1e-3
    np.testing.assert_allclose(half - w, 0.5 * (whole - w), atol=1e-12)


def test_the_real_time_iteration_through_buffers_is_casadis_plain_call():
    """The QP's data and HPIPM evaluated in place (FunctionBuffer) give CasADi's plain call's step bit
    for bit, cycle after cycle: a buffer kept across calls made HPIPM's plugin solve another QP from
    the second call on."""
    model = Model(config="dfs")
    mpc = MPC(model, MPCOptions(horizon=1.0, deadline=float("inf")))
    rti, prob = mpc._rti, mpc.problem
    t = np.linspace(0.0, 1.0, 51)
    qd = np.array([1.0, 0.0, 0.0, 0.0])
    for k in range(3):
        x, u = prob.guess(np.zeros(model.n), qd, np.zeros((prob.N, model.n)), np.zeros(model.n))
        w = prob.pack(x, u)
        bounds = prob.start_bounds(np.zeros(model.n), qd, np.zeros(model.n))
        values = np.zeros((t.size, 6))
        values[:, 5] = 12.0 + 2.0 * k + np.sin(t)  # the modulus along the occupant's vertical
        p = np.asarray(mpc._data(t, values)).ravel(order="F")
        H, gradient, A, g = rti.data(w, p)
        g = np.asarray(g).ravel()
        plain = rti.qp(h=H, g=gradient, a=A, lba=bounds.lbg - g, uba=bounds.ubg - g, lbx=bounds.lbx - w,
                       ubx=bounds.ubx - w)
        step, ok = rti(w, p, bounds)
        assert ok and rti.qp.stats()["success"]
        assert np.array_equal(step, w + np.asarray(plain["x"]).ravel())
        qd = qd * 1.5


def test_the_classical_loop_starts_on_the_gimbal_branch_it_steers_from():
    """A placed start with the outer gimbal turned past 90 deg (the cabin's attitude on the gimbals'
    other branch): the classical loop starts from the same pose on the branch near home, still; from a
    start it steers from already, or with the gimbals moving, it starts where the MPC did."""
    from desdemona.control.online import _loop_start
    from desdemona.machine.kinematics import cabin_pose

    model = Model(config="full")
    placed = np.array([0.0, -3.73, -0.99, 3.07, 0.04, -3.14])  # b737-steady-turn's placed start
    start = _loop_start(model, placed, np.zeros(6))
    assert abs(start[3]) < 0.1 and abs(start[5]) < 0.01
    np.testing.assert_allclose(cabin_pose(start), cabin_pose(placed), atol=1e-12)
    home_branch = np.array([0.0, 0.03, -0.99, -0.04, 3.12, 0.0])
    assert np.all(_loop_start(model, home_branch, np.zeros(6)) == home_branch)
    moving = np.r_[0.0, 0.0, 0.0, 0.1, 0.0, 0.0]
    assert np.all(_loop_start(model, placed, moving) == placed)
    assert np.all(_loop_start(Model(config="yaw-track-cabin"), placed[[0, 1, 5]], np.zeros(3)) == placed[[0, 1, 5]])


def test_the_felt_rotation_beyond_its_band_and_its_ceiling_is_priced_again(params):
    """With ``rotation_band`` each sub-step adds the felt rotation beyond the band (per canal channel,
    either way) to the residuals, BAND_WEIGHT times its weight: nothing within the band, the excess
    beyond it; ``rotation_ceiling`` adds the excess beyond the ceiling again, CEILING_WEIGHT times."""
    from desdemona.cueing.formulation import BAND_WEIGHT, CEILING_WEIGHT
    from desdemona.occupant.perception import canals_model

    model = Model(params, "yaw-track-cabin")
    options = dataclasses.replace(OPTIONS, perception=canals_model(), substeps=1)
    plain, banded, ceiled = (MPC(model, dataclasses.replace(options, rotation_band=band, rotation_ceiling=top)).problem
                             for band, top in ((None, None), (2.0, None), (2.0, 2.75)))
    thresholds = np.asarray(canals_model().thresholds[:3])
    x, u = np.zeros(plain.nx), np.zeros(plain.nu)
    data = plain.with_steps(np.zeros((6, plain.N)))[:, 0]
    h, T = data[0], 1.0 / data[2]
    for felt in (np.array([0.5, -1.5, 1.9]), np.array([3.0, -2.5, 0.0])):  # in thresholds
        z = felt * thresholds / plain.filter.C[np.arange(3), np.arange(3)]  # at rest: felt = C z
        x[plain.n_motion:] = z
        r0, r1, r2 = (np.asarray(p.residual(x, u, data)).ravel() for p in (plain, banded, ceiled))
        assert len(r1) == len(r0) + 3 and len(r2) == len(r0) + 6
        for residuals, width, weight, at in ((r1, 2.0, BAND_WEIGHT, 6), (r2, 2.0, BAND_WEIGHT, 6),
                                             (r2, 2.75, CEILING_WEIGHT, 9)):
            beyond = np.sign(felt) * np.maximum(np.abs(felt) - width, 0.0) * thresholds
            expected = np.sqrt(weight * h / T * plain.cost_weights[:3]) * beyond
            np.testing.assert_allclose(residuals[at:at + 3], expected, atol=1e-12)
        np.testing.assert_allclose(np.delete(r1, np.s_[6:9]), r0, atol=1e-12)
        np.testing.assert_allclose(np.delete(r2, np.s_[6:12]), r0, atol=1e-12)
    assert np.any(r2[9:12] != 0)  # the second felt rotation reaches beyond the ceiling
    for name in ("rotation_band", "rotation_ceiling"):
        with pytest.raises(ValueError, match="perception model"):
            ProblemOptions(**{name: 1.0})


def test_online_weighs_the_felt_rotation_by_default_where_the_path_is_s(tmp_path, capsys):
    """``online`` takes the canals model, a band of one threshold (five on dfs, whose arm spins up for any
    force above g) and a ceiling of 20, but on dfs-yaw (the modulus alone); --perception none,
    --rotation-band none and --rotation-ceiling none switch them off; the felt figures are judged
    through the thesis' model whatever the plan weighed."""
    from desdemona.cli import main
    from desdemona.runs import session

    out = tmp_path / "default"
    assert main(["online", "cosine", "--config", "yaw-track", "--horizon", "1", "--step", "0.05",
                 "--deadline", "100", "--out", str(out), "--no-view"]) == 0
    summary = json.loads((out / "summary.json").read_text())
    assert summary["options"]["mpc"]["perception"]["name"] == "canals"
    assert (summary["options"]["mpc"]["rotation_band"], summary["options"]["mpc"]["rotation_ceiling"]) == (1.0, 20.0)
    assert summary["quality"]["vestibular_model"] == "thesis"
    path = profiles.load("cosine")
    for config, choices, expected in (("yaw-track", {"perception": None}, (None, None, None)),
                                      ("yaw-track", {"rotation_band": None}, ("canals", None, 20.0)),
                                      ("yaw-track", {"rotation_ceiling": None}, ("canals", 1.0, None)),
                                      ("dfs", {}, ("canals", 5.0, 20.0)), ("dfs-yaw", {}, (None, None, None))):
        mpc = session.online(path, Model(config=config), **choices).options.mpc
        assert (getattr(mpc.perception, "name", None), mpc.rotation_band, mpc.rotation_ceiling) == expected
        assert mpc.spin_weight == (session.SPIN_WEIGHT if config == "dfs" else 0.0)
    capsys.readouterr()
    for extra, message in ((["--rotation-band", "wide"], "--rotation-band 'wide'"),
                           (["--rotation-ceiling", "-1"], "--rotation-ceiling -1"),
                           (["--rotation-ceiling", "nan"], "--rotation-ceiling nan: must be a finite number"),
                           (["--perception", "none", "--rotation-band", "1"], "needs a perception model"),
                           (["--perception", "none", "--rotation-ceiling", "20"], "needs a perception model"),
                           (["--spin-weight", "some"], "--spin-weight 'some': a weight, or none"),
                           (["--spin-weight", "-0.1"], "--spin-weight -0.1: a number >= 0"),
                           (["--perception", "none", "--spin-weight", "0.1"], "and with a perception model")):
        assert main(["online", "cosine", "--config", "yaw-track", "--out", str(tmp_path / "bad"), *extra]) == 2
        assert message in capsys.readouterr().err
        assert not (tmp_path / "bad").exists()


def test_the_gimbals_null_motion_is_what_s_does_not_see():
    """At the inner gimbal's lock the outer gimbal and the cabin turning against each other turn the
    cabin by nothing, and that is the motion :func:`gimbal_null_rate` prices: the cosine between their
    axes is -sin q5 (against the model's S at random attitudes); the term is zero away from the lock
    and for the motion the occupant feels, only where all three gimbals are free, and by default
    on-line on dfs with the real-time iteration alone (where it was measured)."""
    from desdemona.cueing.formulation import NULL_WEIGHT, Formulation
    from desdemona.machine.kinematics import gimbal_null_rate

    model = Model(config="dfs")
    gimbals, rest = model.config.gimbals, np.zeros(4)
    for q in np.random.default_rng(1).uniform(-np.pi, np.pi, size=(5, 4)):
        outer, cabin = (np.asarray(model.S(q, e, rest)).ravel()[:3] for e in np.eye(4)[[1, 3]])
        assert np.dot(outer, cabin) == pytest.approx(-np.sin(q[2]), abs=1e-12)
    lock, away = np.array([0.3, 0.4, -np.pi / 2, -0.2]), np.array([0.3, 0.4, 0.0, -0.2])
    null, felt = np.array([0.0, 1.0, 0.0, -1.0]), np.array([0.0, 1.0, 0.0, 1.0])
    assert np.abs(np.asarray(model.S(lock, null, rest)).ravel()[:3]).max() < 1e-12
    assert float(gimbal_null_rate(lock, null, gimbals)) == pytest.approx(1.0)
    assert float(gimbal_null_rate(lock, felt, gimbals)) == pytest.approx(0.0, abs=1e-15)
    assert float(gimbal_null_rate(away, null, gimbals)) == 0.0
    assert gimbal_null_rate(np.zeros(3), np.zeros(3), Model(config="yaw-track-cabin").config.gimbals) is None
    path, full = along_vertical(profiles.load("dfs-catapult")), Model(config="full")
    weights = [Formulation(m, path, ProblemOptions(h_u=0.1), parametric=p).null_weight
               for m, p in ((model, True), (model, False), (full, True))]
    assert weights == [NULL_WEIGHT, 0.0, 0.0]
    quick = MPCOptions(horizon=1.0, step=0.1, tail_step=None, deadline=float("inf"))
    assert [MPC(model, dataclasses.replace(quick, method=m)).problem.null_weight for m in ("rti", "nlp")] == [
        NULL_WEIGHT, 0.0]
    with pytest.raises(ValueError, match="null_weight"):
        ProblemOptions(null_weight=-1.0)


def test_on_dfs_a_steady_spin_of_the_cabin_is_washed_out():
    """On dfs the cabin's spin about the occupant's vertical (the inner gimbal's, the cabin upright)
    changes nothing the occupant feels once the canals have stopped feeling it, so a cost on the felt
    rotation alone leaves it where it is: on a recorded car drive the plans built one up to 100-180
    deg/s for minutes and stopped following the modulus. From a cabin spinning at 90 deg/s on a quiet
    path (1 g held), the session's default slows it to under half in 20 s; without the weight of the
    spin as it is, it keeps spinning, and no faster: the arm's spin-up is not seeded where the preview
    asks for no more than g (it was, on every cycle, and that drew the plans into spinning the cabin
    up: 90 to 139 deg/s in 20 s without the weight, to 131 with it)."""
    from desdemona.runs import session

    model, n = Model(config="dfs"), 201
    path = DesiredPath("quiet", np.linspace(0.0, 20.0, n), None, modulus=np.full(n, profiles.G))
    spinning = np.array([0.0, 0.0, np.radians(90.0), 0.0])  # yaw, outer gimbal, inner gimbal, cabin
    cued = session.online(path, model, session.Choices(initial_state=(np.zeros(4), spinning)),
                          deadline=float("inf"))
    assert cued.options.mpc.spin_weight == session.SPIN_WEIGHT > 0
    left = []
    for weight in (session.SPIN_WEIGHT, 0.0):
        mpc = dataclasses.replace(cued.options.mpc, spin_weight=weight)
        result = run(cued.path, model, dataclasses.replace(cued.options, mpc=mpc))
        assert result.check.passed
        left.append(abs(result.trajectory.qd[-1, 2]) / spinning[2])
    assert left[0] < 0.5 and 0.8 < left[1] < 1.1, left
    with pytest.raises(ValueError, match="spin_weight"):
        ProblemOptions(spin_weight=0.1)  # without a perception model the rotation is weighed as it is


def test_on_dfs_the_gimbals_do_not_spin_against_each_other_at_their_lock():
    """The built-in dfs catapult through the command's session on dfs: without the null-motion term
    the plans let the outer gimbal and the cabin run against each other near the inner gimbal's lock
    (about 170 deg/s, measured, without the felt rotation's ceiling, which since keeps this path away
    from the lock); with it (the on-line default) neither passes 90 deg/s (measured 71, and 36 without
    the weight of the spin as it is, which the default has since), and the RMS error is within 2 %;
    nor with the ceiling too (33). Measured with the band of one threshold, where the spin was found:
    dfs's default band of five keeps this path away from the lock with or without the term (34 deg/s)."""
    from desdemona.runs import session

    model = Model(config="dfs")
    cued = session.online(profiles.load("dfs-catapult"), model, deadline=float("inf"),
                          rotation_band=session.ROTATION_BAND)
    assert cued.options.mpc.rotation_ceiling is not None
    peaks, rms = [], []
    for weight, ceiling in ((None, None), (0.0, None), (None, cued.options.mpc.rotation_ceiling)):
        mpc = dataclasses.replace(cued.options.mpc, null_weight=weight, rotation_ceiling=ceiling)
        result = run(cued.path, model, dataclasses.replace(cued.options, mpc=mpc))
        rates = np.abs(result.trajectory.qd[:, [1, 3]]).max(axis=0)
        peaks.append(np.degrees(rates).max())
        rms.append(result.check.rms)
    assert peaks[0] < 90.0 < 120.0 < peaks[1] and peaks[2] < 60.0
    assert rms[0] < 1.02 * rms[1]


@pytest.mark.parametrize("name", ["hold", "linear"])
def test_a_live_predictor_given_only_what_it_looks_back_at_predicts_the_same(name):
    """A live session gives a predictor only the past it reads (``looks_back``: its cost per cycle the
    same however long the session): on a noisy 120 Hz recording, the preview from the last second
    equals the one from ten seconds, cycle after cycle (the hold predictor's memory of held values is
    its own)."""
    from desdemona.control.predictors import PREDICTORS, predictor

    rng = np.random.default_rng(3)
    t = np.arange(0.0, 12.0, 1 / 120)
    S = np.column_stack([0.2 * np.sin(t), 0 * t, 0.1 * np.cos(2 * t), 3 * np.sin(0.5 * t), 0 * t, -9.81 + t / 12])
    S += 0.05 * rng.standard_normal(S.shape)
    back = PREDICTORS[name].looks_back
    whole, short = predictor(name), predictor(name)
    for now in np.arange(10.0, 12.0, 0.01):
        k = int(np.searchsorted(t, now, side="right"))
        full = whole(DesiredPath("host", t[max(0, k - 1200):k], S[max(0, k - 1200):k]), t[k - 1], 2.0)
        recent = t[:k] > t[k - 1] - back
        cut = short(DesiredPath("host", t[:k][recent], S[:k][recent]), t[k - 1], 2.0)
        np.testing.assert_array_equal(cut.t, full.t)
        np.testing.assert_allclose(cut.S_d, full.S_d, rtol=0, atol=1e-12)

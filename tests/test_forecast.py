"""The ``forecast`` predictor: the vehicle's own forecasts, their file, and the JSBSim model run ahead."""

import numpy as np
import pytest

from desdemona import Model, profiles
from desdemona.cli import main
from desdemona.control.mpc import MPCOptions
from desdemona.control.online import OnlineOptions, run
from desdemona.control.predictors import ForecastPredictor, predict_perfect, predictor
from desdemona.profiles import DesiredPath, ProfileError
from desdemona.profiles.forecast import Forecast, read_forecast, time_origin, write_forecast

OPTIONS = MPCOptions(horizon=1.0, step=0.05, deadline=float("inf"))


def true_forecast(path: DesiredPath, every: float, seconds: float) -> Forecast:
    """Forecasts that are the path's own future: every ``every`` s, the next ``seconds`` of its samples."""
    blocks = []
    for t0 in path.t[:: max(1, round(every / np.min(np.diff(path.t))))]:
        rows = (path.t >= t0) & (path.t <= t0 + seconds + 1e-9)
        blocks.append((t0, path.t[rows], path.S_d[rows] if path.S_d is not None else path.modulus[rows]))
    return Forecast.of(blocks)


def short_path() -> DesiredPath:
    return profiles.catapult(level=15.0, push=1.0, quiet=0.5, duration=3.0)


def write(tmp_path, text: str):
    file = tmp_path / "f.csv"
    file.write_text(text)
    return file


GOOD = "t0,t,M\n0,0,9.81\n0,0.5,10\n0.5,0.5,10\n0.5,1.0,11\n"


def test_a_written_forecast_reads_back_and_keeps_its_forecasts(tmp_path):
    path = short_path()
    forecast = true_forecast(path, 0.1, 1.0)
    write_forecast(tmp_path / "f.csv", forecast, ["made in a test"])
    again = read_forecast(tmp_path / "f.csv", path)
    np.testing.assert_allclose(again.t0, forecast.t0, rtol=1e-11)  # 12 significant digits
    np.testing.assert_array_equal(again.first, forecast.first)
    np.testing.assert_allclose(again.S_d, forecast.S_d, rtol=1e-11, atol=1e-11)
    t, S, _ = again.issued(0.25)  # the latest issued at or before 0.25 s: the one of 0.2 s
    assert t[0] == pytest.approx(0.2) and S.shape == (len(t), 6)
    shifted = write(tmp_path, "t0,t,M\n100,100,9.81\n100,100.5,10\n100.5,100.5,10\n100.5,101,11\n")
    assert read_forecast(shifted, origin=100.0).t0.tolist() == [0.0, 0.5]  # the motion file's clock


@pytest.mark.parametrize("text, message", [
    ("t0,t,fx\n0,0,1\n", "missing column 'wx'"),  # not the six channels, nor the modulus
    ("t0,t,Mz\n0,0,1\n", "unknown column 'Mz'"),
    ("t,wx,wy,wz,fx,fy,fz\n0,0,0,0,0,0,9.81\n", "missing column 't0'"),
    ("t0,t,M\n0,0,9.81\n0,0.5,nan\n", "line 3: M is not a finite number"),
    ("t0,t,M\n0.5,0.5,9.81\n0,0,9.81\n", "line 3: t0 = 0 s after t0 = 0.5 s"),
    ("t0,t,M\n0,0.1,9.81\n", "line 2: the forecast issued at t0 = 0 s starts at t = 0.1 s"),
    ("t0,t,M\n0,0,9.81\n0,0.5,9.81\n0,0.4,9.81\n", "line 4: t = 0.4 s does not increase"),
    ("t0,t,M\n0,0,9.81\n0,0.5\n", "line 3: 2 values for 3 columns"),
    ("t0,t,M\n0,0,-1\n", "line 2: M is negative"),
    ("t0,t,M\n", "no forecast samples"),
])
def test_a_bad_forecast_file_is_refused_naming_the_problem(tmp_path, text, message):
    with pytest.raises(ProfileError, match=message.replace("(", r"\(")):
        read_forecast(write(tmp_path, text))


def test_a_forecast_must_have_the_channels_and_the_time_of_its_motion(tmp_path):
    six = short_path()
    with pytest.raises(ProfileError, match="a forecast of the modulus .* six channels"):
        read_forecast(write(tmp_path, GOOD), six)
    late = write(tmp_path, "t0,t,M\n50,50,9.81\n50,50.5,10\n")
    with pytest.raises(ProfileError, match="miss the motion's time"):
        read_forecast(late, profiles.modulus_version(six))


def test_the_predictor_never_reads_the_live_path_after_now():
    path = short_path()
    forecast = Forecast.of([(0.0, [0.0, 2.0], np.tile([0, 0, 0, 1.0, 2.0, 9.81], (2, 1))),
                            (1.0, [1.0, 1.5, 3.0], np.tile([0, 0, 0, 3.0, -1.0, 9.81], (3, 1)))])
    for now in (0.0, 0.5, 1.0, 1.23, 2.9):
        clean = ForecastPredictor(forecast)(path, now, 1.0)
        S = path.S_d.copy()
        S[path.t > now + 1e-9] = np.nan  # the future poisoned: a preview that reads it is not finite
        poisoned = DesiredPath(path.name, path.t, path.S_d.copy(), path.weights)
        poisoned.S_d[:] = S
        preview = ForecastPredictor(forecast)(poisoned, now, 1.0)
        np.testing.assert_array_equal(preview.S_d, clean.S_d)
        k = np.searchsorted(path.t, now + 1e-9) - 1
        np.testing.assert_array_equal(preview.S_d[0], path.S_d[k])  # starts from the present
    late = ForecastPredictor(forecast)(path, 1.23, 1.0)
    np.testing.assert_allclose(late.S_d[-1, 3:5], [3.0, -1.0])  # the latest forecast, its last value held


def test_before_the_first_forecast_the_present_is_held():
    path = short_path()
    forecast = Forecast.of([(1.0, [1.0, 2.0], np.tile([0, 0, 0, 3.0, 0, 9.81], (2, 1)))])
    preview = ForecastPredictor(forecast)(path, 0.5, 1.0)
    k = np.searchsorted(path.t, 0.5 + 1e-9) - 1
    np.testing.assert_array_equal(preview.S_d, np.tile(path.S_d[k], (len(preview.t), 1)))


@pytest.mark.parametrize("config", ["dfs", "yaw-track-cabin"])
def test_a_forecast_of_the_true_future_runs_as_perfect(params, config):
    path = short_path() if config != "dfs" else profiles.modulus_version(short_path())
    model = Model(params, config)
    forecast = true_forecast(path, 0.1, 1.5)
    for now in (0.0, 0.3, 1.7):  # the preview itself: perfect's to round-off
        cued = model.config.cue_path(path)
        np.testing.assert_allclose(ForecastPredictor(forecast.map(model.config.cue_path))(cued, now, 1.0).S_d,
                                   predict_perfect(cued, now, 1.0).S_d, atol=1e-9)
    perfect = run(path, model, OnlineOptions(OPTIONS))
    forecasted = run(path, model, OnlineOptions(OPTIONS, predictor="forecast", forecast=forecast))
    np.testing.assert_allclose(forecasted.check.rms, perfect.check.rms, rtol=1e-6)
    np.testing.assert_allclose(forecasted.plan.u, perfect.plan.u, atol=1e-6)


def test_the_forecast_predictor_needs_a_forecast():
    with pytest.raises(ValueError, match="needs --forecast FILE"):
        predictor("forecast")
    with pytest.raises(ValueError, match="--forecast is used only with --predictor forecast"):
        OnlineOptions(OPTIONS, predictor="hold", forecast=true_forecast(short_path(), 0.5, 1.0))
    assert OnlineOptions(OPTIONS, predictor="forecast").forecast is None  # a live session's: the host sends it


def test_online_command_reads_a_forecast_file_on_the_motion_files_clock(tmp_path, capsys):
    path = profiles.modulus_version(short_path())
    motion = tmp_path / "motion.csv"
    moved = DesiredPath(path.name, path.t + 10.0, None, modulus=path.modulus)  # the file's clock from 10 s
    profiles.write_csv(motion, moved)
    assert time_origin(motion) == 10.0
    forecast = true_forecast(moved, 0.1, 1.5)
    write_forecast(tmp_path / "motion.forecast.csv", forecast)
    common = ["online", str(motion), "--config", "dfs", "--horizon", "1", "--step", "0.1", "--no-view"]
    # read on the motion file's clock: its forecasts, issued from 10 s, fall on the path's 0-3 s
    assert main([*common, "--predictor", "forecast", "--forecast", str(tmp_path / "motion.forecast.csv"),
                 "--out", str(tmp_path / "forecast")]) == 0
    assert (tmp_path / "forecast" / "summary.json").exists()
    capsys.readouterr()
    bad = write(tmp_path, "t0,t,M\n0,0,9.81\n0,0.5,nan\n")
    for extra, named in (([ "--predictor", "forecast", "--forecast", str(bad)], "not a finite number"),
                         (["--predictor", "forecast"], "--forecast FILE"),
                         (["--predictor", "hold", "--forecast", str(bad)], "only with --predictor forecast")):
        assert main([*common, *extra, "--out", str(tmp_path / "bad")]) == 2
        assert named in capsys.readouterr().err
        assert not (tmp_path / "bad").exists()


def test_the_jsbsim_model_run_ahead_with_the_controls_held():
    pytest.importorskip("jsbsim")
    from desdemona.profiles import jsbsim

    # rudder_kick ramps rudder and aileron from 0.1 s to 3.1 s of sim time, then holds them
    path, _, forecast = jsbsim.forecast_from_jsbsim("rudder_kick", 1.0, 6.0, 0.5, 1.0)
    truth, _ = jsbsim.from_jsbsim("rudder_kick", 1.0, 6.0)
    np.testing.assert_array_equal(path.S_d, truth.S_d)
    # issued at the model's step nearest each 0.5 s, to the crop's end
    assert len(forecast.t0) == 11 and np.all(np.abs(forecast.t0 - 0.5 * np.arange(11)) < 0.005)
    gap = []
    for t0 in forecast.t0:
        t, S, _ = forecast.issued(t0)
        assert t[0] == t0 and t[-1] == pytest.approx(t0 + 1.0, abs=0.011)
        inside = t <= path.t[-1]
        gap.append(np.max(np.abs(S[inside] - path.sample(t[inside]))))
    gap = np.array(gap)
    # while the ramps run, the held controls make another future; once they are held in the script
    # too, the run ahead is the flight itself (up to the filter's edge past the crop's end)
    assert np.all(gap[forecast.t0 < 1.5] > 0.1)
    assert np.all(gap[(forecast.t0 > 2.2) & (forecast.t0 < 3.5)] < 1e-9)
    modulus = forecast.map(profiles.modulus_version)
    np.testing.assert_allclose(modulus.modulus, np.linalg.norm(forecast.S_d[:, 3:], axis=1))

"""Quality metrics against closed forms, and the ``compare`` command on two result folders."""

import json
import math

import numpy as np
import pytest

from desdemona.check import metrics
from desdemona.occupant import perception

DT = 0.01
T = np.arange(0.0, 10.0 + DT / 2, DT)


def pulse(t, centre, width=0.4):
    return np.exp(-0.5 * ((t - centre) / width) ** 2)


def smooth_noise(rng, n, columns=6):
    """A random smooth signal (K, columns): white noise through a moving average."""
    white = rng.standard_normal((n + 50, columns))
    kernel = np.ones(50) / 50
    return np.column_stack([np.convolve(white[:, j], kernel, mode="valid")[:n] for j in range(columns)])


@pytest.mark.parametrize("delay", [0.0, 0.3, -0.45, 1.27])
def test_pure_delay_gives_that_lag(delay):
    S_d = np.column_stack([pulse(T, 4.0 + 0.5 * j) for j in range(6)])
    S = np.column_stack([pulse(T, 4.0 + 0.5 * j + delay) for j in range(6)])
    assert np.allclose(metrics.lag(T, S, S_d), delay, atol=DT)
    assert np.allclose(metrics.lag(T, S, S_d, refine=False), delay, atol=DT)


def test_delayed_random_signal_gives_that_lag_within_a_sample():
    rng = np.random.default_rng(1)
    x = smooth_noise(rng, len(T) + 200)
    shift = 37  # samples: S[k] = S_d[k - 37]
    S_d, S = x[200:], x[200 - shift:len(x) - shift]
    assert np.allclose(metrics.lag(T, S, S_d), shift * DT, atol=DT)


def test_lag_is_searched_only_within_the_window():
    S_d = pulse(T, 3.0, width=1.0)[:, None]
    S = pulse(T, 6.0, width=1.0)[:, None]  # 3 s late, beyond a 1 s window: the best inside is its edge
    assert metrics.lag(T, S, S_d, window=1.0)[0] == pytest.approx(1.0)
    assert metrics.lag(T, S, S_d, window=4.0)[0] == pytest.approx(3.0, abs=DT)
    assert metrics.lag(T, S, S_d, window=100.0)[0] == pytest.approx(3.0, abs=DT)  # clipped to 5 s


def test_scaled_copy_correlates_one_and_negated_copy_minus_one():
    rng = np.random.default_rng(2)
    S_d = smooth_noise(rng, len(T))
    scale = rng.uniform(0.1, 5.0, 6)
    assert np.allclose(metrics.correlation(scale * S_d + 3.0, S_d), 1.0)
    assert np.allclose(metrics.correlation(-scale * S_d, S_d), -1.0)
    assert np.allclose(metrics.lag(T, scale * S_d, S_d), 0.0, atol=DT)


def test_correlation_and_lag_are_undefined_for_a_constant_channel():
    rng = np.random.default_rng(3)
    S_d = smooth_noise(rng, len(T))
    S_d[:, 5] = 9.81  # f_z carries gravity only
    S = S_d + 0.1 * smooth_noise(rng, len(T))
    r, lags = metrics.correlation(S, S_d), metrics.lag(T, S, S_d)
    assert np.isnan(r[5]) and np.isnan(lags[5])
    assert np.all(np.isfinite(r[:5])) and np.all(np.isfinite(lags[:5]))


def test_rms_of_a_constant_offset_is_its_size():
    offset = np.array([0.1, -0.2, 0.3, -1.0, 2.0, 0.5])
    S_d = smooth_noise(np.random.default_rng(4), len(T))
    assert np.allclose(metrics.rms(S_d + offset - S_d), np.abs(offset))


def test_known_constant_rotation_gives_its_peak_false_cue():
    S_d = np.zeros((len(T), 6))
    S_d[:, 4] = 5.0 * np.cos(2.0 * T)  # f_y wanted, crossing zero
    S_d[:, 5] = 9.81
    S = S_d.copy()
    S[:, 2] = math.radians(10.0)  # a steady 10 deg/s yaw nobody asked for
    S[:, 3] = 0.5 * np.sin(T)  # a false f_x of 0.5 m/s^2 at its peak
    peak = metrics.peak_false_cue(S, S_d)
    assert math.degrees(peak[2]) == pytest.approx(10.0)
    assert peak[3] == pytest.approx(0.5, abs=1e-4)
    assert peak[0] == peak[1] == 0.0
    assert peak[4] == pytest.approx(0.0)  # S = S_d also where f_y_d crosses zero
    assert np.isnan(peak[5])  # f_z_d = g is never below the threshold


def test_perceived_error_of_a_perfect_path_is_zero():
    S_d = smooth_noise(np.random.default_rng(5), len(T)) + np.r_[0, 0, 0, 0, 0, 9.81]
    m = metrics.of_arrays(T, S_d, S_d, np.zeros((len(T), 1)), np.zeros((len(T), 1)), ["yaw"])
    assert np.all(m.perceived_rms == 0.0) and np.all(m.rms == 0.0)
    assert np.all(m.above_threshold_pct == 0.0)


def test_perceived_difference_is_the_difference_of_perceptions():
    rng = np.random.default_rng(6)
    S_d = smooth_noise(rng, len(T)) + np.r_[0, 0, 0, 0, 0, 9.81]
    S = S_d + smooth_noise(rng, len(T))
    model = perception.thesis_model()
    expected = model.perceive(S, DT) - model.perceive(S_d, DT)
    assert np.allclose(metrics.perceived_difference(S, S_d, DT, model), expected, atol=1e-9)


@pytest.mark.parametrize("factor, share", [(0.5, 0.0), (2.0, 100.0)])
def test_constant_force_difference_below_or_above_threshold(factor, share):
    """The otoliths pass a steady force (unit DC gain) and start in steady state: |perceived error| stays
    at factor x threshold from the first sample. The canals do not feel a steady rotation (zero DC gain)."""
    S_d = np.tile(np.r_[0, 0, 0, 0, 0, 9.81], (len(T), 1))
    S = S_d + factor * perception.THRESHOLDS
    felt = metrics.perceived_difference(S, S_d, DT)
    assert np.allclose(np.abs(felt[:, 3:]), factor * perception.THRESHOLDS[3:])
    above = metrics.time_above_threshold(felt)
    assert np.all(above[3:] == share)
    assert np.all(above[:3] == 0.0)


def square_wave(t, period, amplitude):
    """+amplitude for the first half of each period, -amplitude for the second."""
    return np.where(np.mod(t, period) < period / 2, amplitude, -amplitude)


def test_square_wave_acceleration_sign_changes_and_jerk():
    h, period, amplitude = 0.001, 0.5, 3.0
    t = h * np.arange(4000)  # 0 ... 3.999 s
    qdd = square_wave(t, period, amplitude)[:, None]
    duration, changes = t[-1], 2 * 4.0 / period - 1  # 15 reversals between 8 half periods
    assert metrics.sign_changes_per_second(t, qdd)[0] == pytest.approx(changes / duration)
    assert np.abs(metrics.jerk(t, qdd)).max() == pytest.approx(2 * amplitude / h)
    # each reversal jumps by 2A within one step h: sqrt(sum (2A/h)^2 h / T)
    assert metrics.jerk_rms(t, qdd)[0] == pytest.approx(math.sqrt(changes * (2 * amplitude) ** 2 / h / duration))
    assert metrics.variation_per_second(t, qdd)[0] == pytest.approx(changes * 2 * amplitude / duration)


def test_sign_changes_are_direct_reversals_outside_the_deadband():
    t = np.arange(8.0)
    qdd = np.array([[1.0, -1.0, 0.0, 1.0, 5e-7, -2.0, -1e-6, 3.0]]).T  # +, -, 0, +, (0), -, -, +: 2
    assert metrics.sign_changes_per_second(t, qdd)[0] == pytest.approx(2 / 7.0)


def test_reversals_count_swings_across_the_hysteresis_band_only():
    h, period, amplitude = 0.001, 0.5, 3.0
    t = h * np.arange(4000)
    square = square_wave(t, period, amplitude)
    rng = np.random.default_rng(3)
    # a dither of 4 % of the peak around a level: sign changes by the hundred, no reversal
    dither = 0.04 * amplitude * rng.uniform(-1.0, 1.0, len(t))
    # the same dither on a slow ramp through zero: exactly one reversal, many raw sign changes
    ramp = np.linspace(-amplitude, amplitude, len(t)) + dither
    qdd = np.column_stack([square, dither, ramp, np.zeros(len(t))])
    reversals = metrics.reversals_per_second(t, qdd)
    raw = metrics.sign_changes_per_second(t, qdd)
    assert reversals[0] == pytest.approx(raw[0]) == pytest.approx(15 / t[-1])
    # the dither's own peak is its scale: 4 % of the peak of the *trajectory* is the band
    assert metrics.reversals_per_second(t, np.column_stack([dither + amplitude, square]))[0] == 0.0
    assert raw[1] > 100 and raw[2] > 10
    assert reversals[2] == pytest.approx(1 / t[-1])
    assert reversals[3] == 0.0


def test_headline_prints_reversals_and_the_summary_keeps_both():
    t = 0.01 * np.arange(500)
    S_d = np.zeros((len(t), 6))
    S_d[:, 5] = 9.81
    qdd = np.column_stack([np.sin(t), 1e-3 * np.sign(np.sin(40 * t)) + 1.0])
    m = metrics.of_arrays(t, S_d, S_d, qdd, np.zeros_like(qdd), ("yaw", "track"))
    assert "acceleration reversals/s" in m.headline() and "sign changes" not in m.headline()
    joints = m.to_dict()["joints"]
    assert joints["sign_changes_per_s"]["yaw"] == pytest.approx(1 / t[-1])
    assert joints["reversals_per_s"]["track"] == 0.0
    assert m.key_figures()["reversals_per_s_max"] == pytest.approx(1 / t[-1])


def test_modulus_and_joint_rates_at_start():
    rng = np.random.default_rng(7)
    M_d = 9.81 + smooth_noise(rng, len(T), 1)[:, 0]
    qd = rng.standard_normal((len(T), 2))
    m = metrics.of_arrays(T, np.zeros((len(T), 6)), None, np.zeros((len(T), 2)), qd, ["yaw", "track"],
                          M=2.0 * M_d, M_d=M_d)
    assert m.rms is None and m.modulus_correlation == pytest.approx(1.0)
    assert m.modulus_lag_s == pytest.approx(0.0, abs=DT)
    assert m.modulus_rms == pytest.approx(float(metrics.rms(M_d)))
    assert np.array_equal(m.qd_start, qd[0])
    summary = m.to_dict()
    json.dumps(summary, allow_nan=False)
    assert summary["channels"]["rms"] is None
    assert summary["joints"]["qd_start"]["track"] == qd[0, 1]
    assert "RMS(M - M_d)" in m.headline()


@pytest.fixture(scope="module")
def two_results(tmp_path_factory):
    """Two small result folders on the same path: our optimiser at two control steps."""
    from desdemona.cli import main

    root = tmp_path_factory.mktemp("results")
    folders = []
    for h_u in ("0.1", "0.25"):
        out = root / f"h{h_u}"
        assert main(["optimize", "cosine", "--config", "yaw-track", "--base", "thesis-toy", "--h-u", h_u,
                     "--starts", "1", "--out", str(out)]) == 0
        folders.append(out)
    return folders


def test_compare_two_folders(two_results, tmp_path, capsys):
    from desdemona.cli import main
    from desdemona.results import report

    capsys.readouterr()
    out = tmp_path / "cmp"
    assert main(["compare", *map(str, two_results), "--out", str(out)]) == 0
    printed = capsys.readouterr().out
    header = printed.splitlines()[0].split()
    assert header == ["metric", "h0.1", "h0.25"]
    assert "above_threshold_pct fy [%]" in printed and "sign_changes_per_s yaw [1/s]" in printed
    for name in ("compare.csv", "compare_path.png", "compare_felt.png", "compare_qdd.png"):
        assert (out / name).is_file()
    rows = {line.split(",")[0]: line.split(",") for line in (out / "compare.csv").read_text().splitlines()}
    assert rows["metric"] == ["metric", "unit", "h0.1", "h0.25"]
    assert rows["configuration"][2:] == ["yaw-track", "yaw-track"]
    # the table holds the metrics of each folder's own trajectory
    traj, summary = report.load(two_results[1])
    expected = metrics.of_trajectory(traj, summary["configuration"]["free_joints"])
    assert float(rows["rms fy"][3]) == pytest.approx(expected.rms[4])
    assert rows["correlation fz"][2:] == ["", ""]  # f_z_d = g: no correlation to speak of
    json.dumps(expected.to_dict(), allow_nan=False)  # ready for summary.json
    assert "peak false rotation" in expected.headline()
    # what the occupant suffers, per folder: the nods' cross-coupling and the sickness dose
    assert float(rows["cross_coupling pitch velocity_peak"][3]) == pytest.approx(
        expected.to_dict()["cross_coupling"]["pitch"]["velocity_peak_deg_s"])
    assert float(rows["sickness msdv_z"][3]) == pytest.approx(expected.sickness_dose.msdv_z)
    assert "cross-couples" in expected.headline() and "MSDV_z" in expected.headline()


def test_compare_rejects_a_folder_that_is_not_a_result(two_results, tmp_path, capsys):
    from desdemona.cli import main

    (tmp_path / "summary.json").write_text("{}")
    (tmp_path / "trajectory.csv").write_text("# units\n# t,x\n0,1\n")
    for bad in (tmp_path, tmp_path / "missing"):
        capsys.readouterr()
        assert main(["compare", str(two_results[0]), str(bad)]) == 2
        err = capsys.readouterr().err
        assert err.count("\n") == 1 and str(bad) in err

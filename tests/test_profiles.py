"""Built-in profiles' defining properties; the CSV reader's strictness; round trips."""

import numpy as np
import pytest

from desdemona import profiles
from desdemona.profiles import ProfileError, read_csv, write_csv


def test_cosine_amplitude_and_frequency():
    p = profiles.cosine(amplitude=5.0, omega=2.0, duration=5.0)
    f_y = p.S_d[:, 4]
    assert f_y.max() == pytest.approx(5.0) and f_y.min() == pytest.approx(-5.0, abs=1e-3)
    spectrum = np.abs(np.fft.rfft(profiles.cosine(duration=100 * np.pi).S_d[:-1, 4]))
    freqs = 2 * np.pi * np.fft.rfftfreq(len(spectrum) * 2 - 1, d=0.01)
    assert freqs[np.argmax(spectrum)] == pytest.approx(2.0, abs=0.02)
    np.testing.assert_allclose(p.S_d[:, 5], 9.81)
    assert p.weights == (0, 0, 0, 0, 1, 0)


def test_catapult_quiet_start_plateau_level_and_duration():
    p = profiles.catapult(level=20.0, push=2.0, quiet=1.0, rise=0.2)
    f_y = p.S_d[:, 4]
    assert np.all(f_y[p.t < 1.0] == 0.0)
    plateau = p.t[np.isclose(f_y, 20.0)]
    assert plateau[-1] - plateau[0] == pytest.approx(2.0, abs=0.011)
    assert f_y.max() == pytest.approx(20.0)


@pytest.mark.parametrize("count", [2, 3])
def test_pulse_trains_have_that_many_pulses(count):
    p = profiles.pulses(count=count, level=15.0)
    rising = np.flatnonzero((p.S_d[1:, 4] >= 7.5) & (p.S_d[:-1, 4] < 7.5))
    assert len(rising) == count


def test_car_lap_closes_with_bounded_accelerations():
    p = profiles.car_lap(lateral_max=9.0, accel_max=4.0, brake_max=8.0)
    assert p.duration == pytest.approx(35.0, rel=0.05)
    assert np.abs(p.S_d[:, 3]).max() <= 9.0 + 1e-9
    assert p.S_d[:, 4].max() <= 4.0 + 1e-6 and p.S_d[:, 4].min() >= -8.0 - 1e-6
    # a closed lap turns through one full turn and ends at the speed it started with
    heading = np.trapezoid(p.S_d[:, 2], p.t)
    assert heading == pytest.approx(2 * np.pi, rel=0.01)
    speed_change = np.trapezoid(p.S_d[:, 4], p.t)
    assert abs(speed_change) < 0.1


def test_roller_coaster_treatment_of_7_5_2():
    p = profiles.roller_coaster(limit=3 * 9.81, cutoff_hz=5.0)
    assert p.S_d is None
    assert p.M_d.min() >= 0.5 * 9.81 - 0.2  # half gravity is added to the ride's modulus
    assert p.M_d.max() <= 3 * 9.81 * 1.02  # limited (filter overshoot aside)
    spectrum = np.abs(np.fft.rfft(p.M_d - p.M_d.mean()))
    freqs = np.fft.rfftfreq(len(p.M_d), d=0.01)
    assert spectrum[freqs > 10].max() < 0.01 * spectrum.max()


def test_csv_round_trip(tmp_path):
    for name in ("catapult", "dfs-catapult"):
        p = profiles.get_profile(name)
        write_csv(tmp_path / "p.csv", p)
        q = read_csv(tmp_path / "p.csv")
        np.testing.assert_allclose(q.t, p.t, rtol=0, atol=1e-12)
        np.testing.assert_allclose(q.M_d, p.M_d, rtol=0, atol=1e-12)
        if p.S_d is not None:
            np.testing.assert_allclose(q.S_d, p.S_d, rtol=0, atol=1e-12)
            assert q.weights == p.weights  # carried by the '# weights:' line


GOOD = "t,wx,wy,wz,fx,fy,fz\n0,0,0,0,0,0,9.81\n0.1,0,0,0,0,1,9.81\n0.2,0,0,0,0,2,9.81\n"


@pytest.mark.parametrize("text, fragment", [
    (GOOD.replace("0.1,0,0,0,0,1,9.81", "0.1,0,0,0,0,nan,9.81"), "line 3: fy is not a finite number"),
    (GOOD.replace("0.2,", "0.1,"), "line 4: time 0.1 s does not increase"),
    (GOOD.replace("t,wx,wy,wz,fx,fy,fz", "t,wx,wy,wz,fx,fy"), "missing column 'fz'"),
    (GOOD.replace("fz", "fzz"), "unknown column 'fzz'"),
    ("t,wx,wy,wz,fx,fy,fz\n0,0,0,0,0,0,9.81\n", "at least two rows"),
    (GOOD.replace("0.2,0,0,0,0,2,9.81", "0.2,0,0,0,0,2000,9.81"), "line 4: |f| = 2000 m/s^2 is above"),
    (GOOD.replace("0.1,0,0,0,0,1,9.81", "0.1,0,0,0,0,abc,9.81"), "line 3: not a number"),
    (GOOD.replace("0.1,0,0,0,0,1,9.81", "0.1,0,0,0,0,1"), "line 3: 6 values for 7 columns"),
    ("", "no header"),
    ("t,M\n0,9.81\n0.1,-1\n0.2,9.81\n", "line 3: M = -1 m/s^2 is negative"),
    ("t,M,M\n0,9.81,1\n0.1,1,1\n", "column 'M' twice"),
    # a 30 s path written in milliseconds: 8 hours at one sample per 500 "s"
    ("t,M\n" + "".join(f"{500 * k},9.81\n" for k in range(61)), "column 't' looks like milliseconds"),
])
def test_bad_csv_names_the_problem(tmp_path, text, fragment):
    path = tmp_path / "bad.csv"
    path.write_text(text)
    with pytest.raises(ProfileError) as info:
        read_csv(path)
    assert fragment in str(info.value) and "bad.csv" in str(info.value)


def _turn(rate, force=9.81, seconds=3.0):
    """A path turning steadily at ``rate`` about z with ``force`` up, sampled at 10 Hz."""
    return "t,wx,wy,wz,fx,fy,fz\n" + "".join(f"{k / 10},0,0,{rate},0,1,{force}\n"
                                            for k in range(int(seconds * 10) + 1))


@pytest.mark.parametrize("text, fragment", [
    (_turn(33.0), "line 2: |omega| stays above 10 rad/s for 3 s (up to 33): rates in deg/s?"),
    (_turn(0.5, 1.0).replace(",0,1,1.0", ",0,0.2,1.0"), "|f| has a median of 1.02 and never exceeds 1.02 m/s^2"),
    ("t,M\n" + "".join(f"{k / 10},{1 + 0.1 * (k % 3)}\n" for k in range(31)), "M has a median of 1.1"),
])
def test_a_path_in_degrees_per_second_or_in_g_is_refused(tmp_path, text, fragment):
    """Units a user mixes up in a hand-made path, inside the gross limits: a paraglider's spiral at
    33 deg/s written as rad/s, forces or a modulus written in g."""
    path = tmp_path / "bad.csv"
    path.write_text(text)
    with pytest.raises(ProfileError) as info:
        read_csv(path)
    assert fragment in str(info.value)


def test_a_real_spin_and_a_weightless_crop_are_read(tmp_path):
    """Not taken for a unit mistake: a spin at 3 rad/s for 3 s, a brief 12 rad/s flick (under a second)
    and a weightless stretch (|f| near 0)."""
    flick = _turn(3.0).replace("\n1.0,0,0,3.0,", "\n1.0,0,0,12.0,").replace("\n1.5,0,0,3.0,", "\n1.5,0,0,12.0,")
    weightless = "t,M\n" + "".join(f"{k / 10},{0.05 * (k % 2)}\n" for k in range(31))
    for name, text in (("spin", _turn(3.0)), ("flick", flick), ("weightless", weightless)):
        (tmp_path / f"{name}.csv").write_text(text)
        read_csv(tmp_path / f"{name}.csv")


def test_columns_in_any_order_and_a_byte_order_mark(tmp_path):
    """Columns are read by name (a spreadsheet may reorder them) and the UTF-8 mark it writes is skipped."""
    reordered = "fz,t,fy,fx,wz,wy,wx\n9.81,0,0,0,0,0,0\n9.81,0.1,1,0,0,0,0.5\n9.81,0.2,2,0,0,0,0\n"
    (tmp_path / "r.csv").write_text(reordered)
    (tmp_path / "bom.csv").write_bytes(b"\xef\xbb\xbf" + GOOD.encode())
    p, q = read_csv(tmp_path / "r.csv"), read_csv(tmp_path / "bom.csv")
    np.testing.assert_allclose(p.S_d[1], [0.5, 0, 0, 0, 1, 9.81])
    np.testing.assert_allclose(q.S_d[:, 4], [0, 1, 2])
    (tmp_path / "m.csv").write_text("M,t\n9.81,0\n12,1\n")
    np.testing.assert_allclose(read_csv(tmp_path / "m.csv").M_d, [9.81, 12])


def test_non_utf8_file_is_one_message(tmp_path):
    path = tmp_path / "latin.csv"
    path.write_bytes(b"# caf\xe9 au lait\n" + GOOD.encode())
    with pytest.raises(ProfileError, match=r"latin.csv: line 1: not UTF-8 text \(byte 0xe9\)"):
        read_csv(path)


def test_comments_and_modulus_files(tmp_path):
    path = tmp_path / "m.csv"
    path.write_text("# a modulus path\nt,M\n# comment inside\n0,9.81\n0.5,12\n1.0,15\n")
    p = read_csv(path)
    np.testing.assert_allclose(p.M_d, [9.81, 12, 15])
    assert p.S_d is None


def test_unknown_profile():
    with pytest.raises(ProfileError, match="unknown profile 'catapolt'.*cosine"):
        profiles.get_profile("catapolt")


def test_dfs_catapult_pulses_on_a_constant_modulus():
    p = profiles.dfs_catapult(base=1.5 * 9.81, pulse=9.81)
    assert p.S_d is None
    np.testing.assert_allclose(p.M_d[p.t < 3.0], 1.5 * 9.81)
    np.testing.assert_allclose(p.M_d[(p.t > 3.3) & (p.t < 5.3)], 2.5 * 9.81)
    np.testing.assert_allclose(p.M_d[p.t > 9.5], 1.5 * 9.81)


def test_cosine_sweep_and_modulus_versions():
    sweep = profiles.cosine_sweep(omegas=(2.0, 3.0, 4.0, 5.0), duration=5.0)
    # a cosine at omega crosses zero omega * T / pi times (rounded) in T seconds
    zero_crossings = [np.count_nonzero(np.diff(np.sign(p.S_d[:, 4]))) for p in sweep]
    assert zero_crossings == [round(w * 5.0 / np.pi) for w in (2.0, 3.0, 4.0, 5.0)]
    catapult = profiles.catapult()
    m = profiles.modulus_version(catapult)
    assert m.S_d is None
    np.testing.assert_allclose(m.M_d, np.hypot(catapult.S_d[:, 4], 9.81))


def test_csv_weights_line(tmp_path):
    path = tmp_path / "w.csv"
    path.write_text("# a ride\n#  Weights: 1, 1, 1, 3, 1, 0.5\n" + GOOD)
    assert read_csv(path).weights == (1, 1, 1, 3, 1, 0.5)
    path.write_text(GOOD)
    assert read_csv(path).weights == (1,) * 6  # none given: Q = I


@pytest.mark.parametrize("line, fragment", [
    ("# weights: 1,1,1,3,1", "six finite numbers"),
    ("# weights: 1,1,1,x,1,1", "not a number"),
    ("# weights: 1,1,1,-3,1,1", ">= 0"),
    ("# weights: 0,0,0,0,0,0", "not all zero"),
    ("# weights 1,1,1,1,1,1", "'# weights: wx,wy,wz,fx,fy,fz'"),
    ("# weights: 1,1,1,1,1,1\n# weights: 1,1,1,1,1,1", "line 2: a second weights line"),
])
def test_bad_csv_weights_name_the_line(tmp_path, line, fragment):
    path = tmp_path / "w.csv"
    path.write_text(line + "\n" + GOOD)
    with pytest.raises(ProfileError, match="w.csv: line [12]") as info:
        read_csv(path)
    assert fragment in str(info.value)


def test_weights_specs():
    path = profiles.get_profile("catapult")  # the thesis' weights (0, 0, 0, 3, 1, 1)
    thresholds = profiles.THRESHOLDS
    np.testing.assert_array_equal(profiles.weights_for("path", path), path.weights)
    w = profiles.weights_for("thresholds", path)
    np.testing.assert_allclose(w * thresholds**2, w[4] * thresholds[4] ** 2)  # one threshold costs the same
    assert w[4] == 1.0
    felt = profiles.weights_for("felt", path)
    np.testing.assert_array_equal(felt[3:], path.weights[3:])
    np.testing.assert_allclose(felt[:3] * thresholds[:3] ** 2, 3.0 * thresholds[4] ** 2)
    np.testing.assert_array_equal(profiles.weights_for("1,2,3,4,5,6", path), [1, 2, 3, 4, 5, 6])
    np.testing.assert_array_equal(profiles.weights_for((0, 0, 1, 0, 0, 0), path), [0, 0, 1, 0, 0, 0])
    for bad in ("heavy", "1,2", "1,1,1,1,1,nan"):
        with pytest.raises(ProfileError, match="weights"):
            profiles.weights_for(bad, path)


def test_gain_scales_the_motion_around_one_g():
    path = profiles.get_profile("car-lap")
    half = path.with_gain(0.5)
    rest = np.array([0, 0, 0, 0, 0, profiles.G])
    np.testing.assert_allclose(half.S_d - rest, 0.5 * (path.S_d - rest), atol=1e-12)
    assert half.weights == path.weights and path.with_gain(1.0) is path
    coaster = profiles.get_profile("roller-coaster")
    np.testing.assert_allclose(coaster.with_gain(0.5).M_d, profiles.G + 0.5 * (coaster.M_d - profiles.G))
    with pytest.raises(ProfileError, match="gain"):
        path.with_gain(0.0)

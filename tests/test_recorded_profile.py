"""A recorded-looking path (the noisy test input): its rate, gain and noise, for full and
modulus-only paths, deterministic for a seed."""

import math

import numpy as np
import pytest

from desdemona import profiles
from desdemona.profiles import ProfileError, recorded_version


def noise_of(recorded, path, gain_error):
    """What recorded_version added beyond the resampled path times its gain."""
    scale = 1.0 + gain_error
    if path.S_d is None:
        return recorded.modulus - scale * path.sample_modulus(recorded.t)
    return recorded.S_d - scale * path.sample(recorded.t)


def rms_within(noise, expected, samples):
    """RMS of white Gaussian noise: its estimate from n samples has a standard error of about
    expected / sqrt(2 n); allow five of those."""
    return math.sqrt(np.mean(np.square(noise))) == pytest.approx(expected, abs=5 * expected / math.sqrt(2 * samples))


def test_without_noise_it_is_the_resampled_path_times_its_gain():
    path = profiles.catapult()
    rec = recorded_version(path, noise_rms=0.0, rate_hz=40.0, gain_error=-0.03)
    assert np.allclose(np.diff(rec.t), 1 / 40.0) and rec.t[0] == 0.0 and rec.t[-1] == pytest.approx(path.t[-1])
    np.testing.assert_allclose(rec.S_d, 0.97 * path.sample(rec.t), rtol=1e-12, atol=1e-12)
    np.testing.assert_allclose(rec.S_d[:, 5], 0.97 * 9.81)  # the scale error scales gravity too
    assert rec.weights == path.weights and rec.modulus is None


def test_full_path_noise_has_the_requested_rms_per_channel_and_is_white():
    path = profiles.catapult()
    rec = recorded_version(path, noise_rms=0.5, rate_hz=100.0, gain_error=0.01, seed=4)
    noise = noise_of(rec, path, 0.01)
    K = len(rec.t)
    assert K == len(path.t) and np.allclose(np.diff(rec.t), 0.01)
    for j in range(3):
        assert rms_within(noise[:, 3 + j], 0.5, K)
        assert rms_within(noise[:, j], math.radians(0.5), K)
    assert abs(noise[:, 3:].mean()) < 5 * 0.5 / math.sqrt(3 * K)
    x = noise[:, 4] - noise[:, 4].mean()
    assert abs(np.dot(x[1:], x[:-1]) / np.dot(x, x)) < 5 / math.sqrt(K)  # no correlation between samples
    assert abs(np.corrcoef(noise[:, 3], noise[:, 4])[0, 1]) < 5 / math.sqrt(K)  # nor between channels


def test_modulus_path_is_noisy_clipped_at_zero_and_at_the_rate_asked():
    path = profiles.dfs_catapult()
    rec = recorded_version(path, noise_rms=0.5, rate_hz=250.0, gain_error=0.01, seed=0)
    assert rec.S_d is None and np.allclose(np.diff(rec.t), 0.004) and rec.t[-1] == pytest.approx(12.0)
    assert rms_within(noise_of(rec, path, 0.01), 0.5, len(rec.t))
    # the gain: least squares of the recording on the path
    clean = path.sample_modulus(rec.t)
    assert np.dot(rec.modulus, clean) / np.dot(clean, clean) == pytest.approx(1.01, abs=1e-3)
    near_zero = profiles.DesiredPath("low", path.t, None, modulus=np.full(len(path.t), 0.2))
    low = recorded_version(near_zero, noise_rms=0.5)
    assert low.modulus.min() == 0.0 and np.mean(low.modulus == 0.0) > 0.2  # |f| >= 0: clipped, not negative


def test_the_same_seed_gives_the_same_recording():
    path = profiles.catapult()
    a, b = recorded_version(path, seed=7), recorded_version(path, seed=7)
    assert np.array_equal(a.t, b.t) and np.array_equal(a.S_d, b.S_d)
    assert not np.array_equal(a.S_d, recorded_version(path, seed=8).S_d)


def test_the_issue_14_input_is_built_in():
    rec = profiles.get_profile("dfs-catapult-recorded")
    expected = recorded_version(profiles.dfs_catapult(), noise_rms=0.5, rate_hz=100.0, gain_error=0.01, seed=0)
    assert np.array_equal(rec.t, expected.t) and np.array_equal(rec.modulus, expected.modulus)
    assert "100 Hz" in rec.description and "1% gain error" in rec.description


@pytest.mark.parametrize("kwargs", [{"noise_rms": -0.1}, {"noise_rms": math.nan}, {"rate_hz": 0.0},
                                    {"rate_hz": 0.05}, {"gain_error": -1.0}])
def test_impossible_settings_are_refused(kwargs):
    with pytest.raises(ProfileError, match=next(iter(kwargs))):
        recorded_version(profiles.catapult(), **kwargs)

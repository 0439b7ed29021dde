"""Felt motion: the felt-direction error and the felt rotation against closed forms, for full
and modulus-only paths."""

import json
import math

import numpy as np
import pytest

from desdemona.check import metrics
from desdemona.occupant import perception
from desdemona.profiles import G

DT = 0.01
T = np.arange(0.0, 20.0 + DT / 2, DT)
REST = np.r_[0.0, 0.0, 0.0, 0.0, 0.0, G]


def tilted(angle, axis=0, magnitude=G):
    """A specific force of ``magnitude`` tilted from cabin +z by ``angle`` [rad] towards +x (axis 0) or +y."""
    f = np.zeros(3)
    f[axis], f[2] = magnitude * math.sin(angle), magnitude * math.cos(angle)
    return f


def of_modulus_path(S, vestibular=None):
    """The metrics of a modulus-only result (S_d None), as a dfs result is measured."""
    K = len(S)
    M = np.linalg.norm(S[:, 3:], axis=1)
    return metrics.of_arrays(T[:K], S, None, np.zeros((K, 1)), np.zeros((K, 1)), ["yaw"], M=M, M_d=M,
                             vestibular=vestibular)


def high_pass_canals(tau):
    """A model whose canals are the first-order high-pass tau s / (1 + tau s): a step W is felt as
    W exp(-t / tau), W itself at the step."""
    canals = tuple(perception.Channel(f"canal {i}", gain=tau, s_power=1, zeros=(), poles=(tau,)) for i in "xyz")
    return perception.VestibularModel("high-pass", canals + perception.thesis_model().channels[3:])


@pytest.mark.parametrize("degrees, axis", [(0.0, 0), (3.0, 0), (-25.0, 1), (90.0, 1), (170.0, 0)])
def test_tilted_force_gives_its_angle_against_the_vertical(degrees, axis):
    f = np.tile(tilted(math.radians(degrees), axis, magnitude=2.3 * G), (len(T), 1))
    error = metrics.direction_error(f)
    assert np.allclose(error, math.radians(abs(degrees)), atol=1e-12)


def test_direction_error_against_a_desired_force_is_the_angle_between_them():
    rng = np.random.default_rng(11)
    f_d = rng.standard_normal((200, 3))
    angle = rng.uniform(0.0, math.pi, 200)
    normal = np.cross(f_d, rng.standard_normal((200, 3)))  # rotate f_d about an axis normal to it
    normal /= np.linalg.norm(normal, axis=1, keepdims=True)
    unit = f_d / np.linalg.norm(f_d, axis=1, keepdims=True)
    f = (np.cos(angle)[:, None] * unit + np.sin(angle)[:, None] * np.cross(normal, unit)) * rng.uniform(0.1, 30, (200, 1))
    assert np.allclose(metrics.direction_error(f, f_d), angle, atol=1e-12)
    assert np.allclose(metrics.direction_error(f_d * 3.0, f_d), 0.0, atol=1e-12)


def test_direction_is_undefined_without_a_force():
    f = np.array([[0.0, 0.0, 0.0], [0.0, 0.0, G], [1.0, 0.0, 0.0]])
    error = metrics.direction_error(f)
    assert np.isnan(error[0]) and error[1] == 0.0 and error[2] == pytest.approx(math.pi / 2)
    assert np.isnan(metrics.direction_error(f[1:2], np.zeros((1, 3)))[0])
    assert all(math.isnan(x) for x in metrics.direction_statistics(error[:1], 0.01))


def test_direction_threshold_is_the_lateral_otolith_threshold_at_1g():
    assert metrics.direction_threshold() == pytest.approx(math.asin(0.17 / 9.81))
    assert math.degrees(metrics.direction_threshold()) == pytest.approx(0.993, abs=1e-3)


def test_modulus_path_at_rest_feels_nothing():
    m = of_modulus_path(np.tile(REST, (len(T), 1)))
    assert m.direction_reference == "cabin +z"
    assert m.direction_rms == 0.0 and m.direction_peak == 0.0 and m.direction_above_pct == 0.0
    assert np.all(m.rotation_rms == 0.0) and np.all(m.rotation_peak == 0.0) and np.all(m.rotation_above_pct == 0.0)


def test_modulus_path_with_a_known_tilt_half_the_time():
    """f tilted by 2 deg during the second half: RMS 2/sqrt(2) deg (to one sample), peak 2 deg, above the
    0.99 deg threshold half the time."""
    S = np.tile(REST, (len(T), 1))
    late = T >= 10.0
    S[late, 3:] = tilted(math.radians(2.0), axis=1, magnitude=1.5 * G)
    m = of_modulus_path(S)
    share = np.mean(late)
    assert math.degrees(m.direction_peak) == pytest.approx(2.0)
    assert math.degrees(m.direction_rms) == pytest.approx(2.0 * math.sqrt(share))
    assert m.direction_above_pct == pytest.approx(100.0 * share)
    summary = m.to_dict()
    json.dumps(summary, allow_nan=False)
    assert summary["felt_direction"]["peak_deg"] == pytest.approx(2.0)
    assert summary["felt_direction"]["reference"] == "cabin +z"
    assert m.key_figures()["felt_direction_peak_deg"] == pytest.approx(2.0)
    assert "felt direction off by" in m.headline() and "peak felt rotation 0 deg/s" in m.headline()


def test_full_path_direction_is_measured_against_the_desired_force():
    """A lateral force wanted and felt in the same direction: no direction error, however large its
    tilt from the vertical; felt 5 deg further round: 5 deg."""
    S_d = np.tile(REST, (len(T), 1))
    S_d[:, 3:] = tilted(math.radians(40.0), axis=1)
    S = S_d.copy()
    zeros = np.zeros((len(T), 1))
    m = metrics.of_arrays(T, S, S_d, zeros, zeros, ["yaw"])
    assert m.direction_reference == "S_d" and m.direction_peak == pytest.approx(0.0, abs=1e-12)
    S[:, 3:] = tilted(math.radians(45.0), axis=1, magnitude=0.7 * G)
    m = metrics.of_arrays(T, S, S_d, zeros, zeros, ["yaw"])
    assert math.degrees(m.direction_rms) == pytest.approx(5.0) and math.degrees(m.direction_peak) == pytest.approx(5.0)
    assert m.direction_above_pct == 100.0


def test_the_machine_made_direction_error_is_what_its_motion_adds_to_a_still_cabins():
    """A push-over's negative g: a still cabin is 180 deg off and made none of it (0); a felt force
    tilted 30 deg from the vertical against an upright target made 30 deg; one that follows a
    target tilted 40 deg made -40 (it brought the force nearer); on a modulus path the error itself."""
    zeros = np.zeros((len(T), 1))
    S_d = np.tile(REST, (len(T), 1))
    S_d[:, 5] = -1.9 * G
    still = np.tile(REST, (len(T), 1))
    m = metrics.of_arrays(T, still, S_d, zeros, zeros, ["yaw"])
    assert math.degrees(m.direction_peak) == pytest.approx(180.0) and m.direction_made_peak == pytest.approx(0.0)
    tilted_by = np.tile(REST, (len(T), 1))
    tilted_by[:, 3:] = tilted(math.radians(30.0), axis=0)
    upright = np.tile(REST, (len(T), 1))
    m = metrics.of_arrays(T, tilted_by, upright, zeros, zeros, ["yaw"])
    assert math.degrees(m.direction_made_peak) == pytest.approx(30.0)
    S_d[:, 3:] = tilted(math.radians(40.0), axis=1, magnitude=1.2 * G)
    made = metrics.direction_made(S_d[:, 3:], S_d[:, 3:])
    np.testing.assert_allclose(np.degrees(made), -40.0)
    assert m.to_dict()["felt_direction"]["made_peak_deg"] == pytest.approx(30.0)
    np.testing.assert_allclose(metrics.direction_made(tilted_by[:, 3:]), metrics.direction_error(tilted_by[:, 3:]))


@pytest.mark.parametrize("channel", [0, 1, 2])
def test_rotation_step_through_a_high_pass_canal_is_felt_as_its_exponential(channel):
    tau, W, start = 5.9, math.radians(10.0), 2.0
    S = np.tile(REST, (len(T), 1))
    S[T >= start, channel] = W
    felt = metrics.felt_rotation(S, None, DT, high_pass_canals(tau))
    after = T >= start
    assert np.all(felt[~after] == 0.0)
    assert np.allclose(felt[after, channel], W * np.exp(-(T[after] - start) / tau), rtol=1e-9, atol=1e-15)
    assert np.all(np.delete(felt, channel, axis=1) == 0.0)
    m = of_modulus_path(S, high_pass_canals(tau))
    assert m.rotation_peak[channel] == pytest.approx(W)  # felt at once, in full
    # above the threshold while W exp(-t / tau) >= threshold, i.e. for tau ln(W / threshold) after the step
    felt_for = tau * math.log(W / perception.THRESHOLDS[channel])
    assert m.rotation_above_pct[channel] == pytest.approx(100.0 * felt_for / (T[-1] + DT), abs=100.0 * DT / T[-1])
    assert m.felt_rotation()["peak_deg_s"][metrics.CHANNELS[channel]] == pytest.approx(10.0)


def test_rotation_step_through_the_thesis_canals_follows_their_step_response():
    """The thesis' canal (eq. 6.3): the sampled response to a held step is the continuous step response
    at the sample times (the discretisation is exact for held inputs); after the lead's spike it decays
    with tau_1 = 5.9 s."""
    W, start = math.radians(6.0), 1.0
    S = np.tile(REST, (len(T), 1))
    S[T >= start, 2] = W
    model = perception.thesis_model()
    felt = metrics.felt_rotation(S, None, DT, model)[:, 2]
    k = int(np.argmax(T >= start))
    expected = W * model.channels[2].step_response(T[k:] - T[k])
    assert np.allclose(felt[k:], expected, rtol=1e-6, atol=1e-12 * W)
    one, later = k + int(round(1.0 / DT)), k + int(round(6.9 / DT))
    assert felt[later] / felt[one] == pytest.approx(math.exp(-5.9 / 5.9), rel=1e-6)
    m = of_modulus_path(S, model)
    assert m.rotation_peak[2] == pytest.approx(np.abs(felt).max())


def test_full_path_felt_rotation_is_the_canal_part_of_the_perceived_error():
    rng = np.random.default_rng(12)
    S_d = np.tile(REST, (len(T), 1)) + 0.1 * np.cumsum(rng.standard_normal((len(T), 6)), axis=0) * DT
    S = S_d + 0.2 * np.sin(T)[:, None] * rng.uniform(-1, 1, 6)
    zeros = np.zeros((len(T), 1))
    m = metrics.of_arrays(T, S, S_d, zeros, zeros, ["yaw"])
    felt = metrics.perceived_difference(S, S_d, DT)[:, :3]
    assert np.allclose(metrics.felt_rotation(S, S_d, DT), felt, atol=1e-12)
    assert np.allclose(m.rotation_rms, m.perceived_rms[:3])
    assert np.allclose(m.rotation_above_pct, m.above_threshold_pct[:3])
    assert np.allclose(m.rotation_peak, np.abs(felt).max(axis=0))


def test_rows_and_dict_carry_the_felt_metrics_in_degrees():
    S = np.tile(REST, (len(T), 1))
    S[:, 3:] = tilted(math.radians(1.5))
    S[:, 0] = math.radians(4.0) * np.sin(2.0 * T)
    m = of_modulus_path(S)
    rows = {name: (unit, value) for name, unit, value in m.rows()}
    assert rows["felt_direction rms"] == ("deg", pytest.approx(1.5))
    assert rows["felt_direction threshold"][1] == pytest.approx(0.993, abs=1e-3)
    assert rows["felt_rotation peak wx"][0] == "deg/s"
    assert rows["felt_rotation peak wx"][1] == pytest.approx(math.degrees(m.rotation_peak[0]))
    assert rows["felt_rotation above_threshold_pct wz"] == ("%", 0.0)
    names = [name.split()[0] for name in rows]
    assert sorted(names, key=metrics.Metrics.ROW_GROUPS.index) == names  # grouped in ROW_GROUPS' order
    felt = m.to_dict()["felt_rotation"]
    assert set(felt) == {"rms_deg_s", "peak_deg_s", "above_threshold_pct"}
    assert felt["rms_deg_s"]["wx"] == pytest.approx(math.degrees(m.rotation_rms[0]))

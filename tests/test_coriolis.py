"""Coriolis cross-coupling of a head nod in a turning cabin, against its closed form."""

import math

import numpy as np
import pytest

from desdemona.occupant import coriolis, perception

RNG = np.random.default_rng(79)


def test_a_nod_is_thirty_degrees_in_half_a_second_at_minimum_jerk():
    for nod in coriolis.NODS:
        tau = np.linspace(0.0, nod.duration, 2001)
        theta, rate = nod.angle_at(tau), nod.rate_at(tau)
        assert abs(theta[-1]) == pytest.approx(math.radians(30.0))
        assert theta[0] == 0.0 and rate[0] == 0.0 and rate[-1] == 0.0
        assert np.gradient(theta, tau) == pytest.approx(rate, abs=1e-3 * np.abs(rate).max())
        assert np.abs(rate).max() == pytest.approx(1.875 * math.radians(30.0) / 0.5, rel=1e-5)


def test_a_constant_spin_and_a_pitch_nod_give_the_closed_form():
    """Spin W about z, the head pitched by theta about x: v = (0, W sin theta, W (cos theta - 1)) and
    a = dv/dt = (0, W cos theta, -W sin theta) theta' in the head's axes."""
    W = 2.1
    nod = coriolis.NODS[0]
    tau = np.linspace(0.0, nod.duration, 101)
    v, a = coriolis.cross_coupling(np.array([0.0, 0.0, W]), nod, tau)
    theta, rate = nod.angle_at(tau), nod.rate_at(tau)
    assert v == pytest.approx(np.stack([0 * tau, W * np.sin(theta), W * (np.cos(theta) - 1.0)], axis=1), abs=1e-12)
    assert a == pytest.approx(np.stack([0 * tau, W * np.cos(theta) * rate, -W * np.sin(theta) * rate], axis=1),
                              abs=1e-12)


@pytest.mark.parametrize("nod", coriolis.NODS, ids=lambda n: n.name)
def test_for_any_constant_spin_the_acceleration_is_omega_cross_omega_head_and_the_velocity_its_integral(nod):
    """a = (R^T Omega) x omega_head; its integral over the nod is v; |v| at the end is the chord
    2 |Omega_perp| sin(30 deg / 2) of the spin's part across the nod's axis, and a spin along that axis
    is not cross-coupled at all."""
    tau = np.linspace(0.0, nod.duration, 4001)
    for _ in range(5):
        omega = RNG.normal(size=3)
        v, a = coriolis.cross_coupling(omega, nod, tau)
        R = coriolis.rotation_about(nod.axis, nod.angle_at(tau))
        in_head = np.einsum("kji,j->ki", R, omega)
        assert a == pytest.approx(np.cross(in_head, nod.rate_at(tau)[:, None] * np.asarray(nod.axis)), abs=1e-12)
        integral = np.concatenate([[0.0 * omega], np.cumsum((a[1:] + a[:-1]) / 2.0 * np.diff(tau)[:, None], axis=0)])
        assert v == pytest.approx(integral, abs=1e-6)
        across = omega - np.dot(omega, nod.axis) * np.asarray(nod.axis)
        assert np.linalg.norm(v[-1]) == pytest.approx(2.0 * np.linalg.norm(across) * math.sin(math.radians(15.0)))
    v, a = coriolis.cross_coupling(3.0 * np.asarray(nod.axis), nod, tau)
    assert np.abs(v).max() < 1e-12 and np.abs(a).max() < 1e-12


def test_a_result_spinning_steadily_about_z_is_cross_coupled_by_pitch_and_roll_nods_not_yaw():
    W = math.radians(120.0)
    t = np.arange(0.0, 5.0, 0.02)
    figures = coriolis.statistics(t, np.tile([0.0, 0.0, W], (len(t), 1)))
    peak_rate = 1.875 * math.radians(30.0) / 0.5
    for name in ("pitch", "roll"):
        nod = figures.nods[name]
        assert nod.velocity_peak == pytest.approx(2.0 * W * math.sin(math.radians(15.0)), rel=1e-9)
        assert nod.velocity_rms == pytest.approx(nod.velocity_peak)
        assert nod.acceleration_peak == pytest.approx(W * peak_rate, rel=1e-3)  # at the nod's sampled middle
        assert nod.above_threshold_pct == 100.0
    assert figures.nods["yaw"].velocity_peak == pytest.approx(0.0, abs=1e-12)
    assert figures.nods["yaw"].above_threshold_pct == 0.0
    assert figures.worst[0] in ("pitch", "roll")


def test_a_still_cabin_cross_couples_nothing_and_a_slow_one_stays_below_threshold():
    t = np.arange(0.0, 3.0, 0.01)
    still = coriolis.statistics(t, np.zeros((len(t), 3)))
    assert all(n.velocity_peak == 0.0 and n.above_threshold_pct == 0.0 for n in still.nods.values())
    # |v| <= 2 sin(15 deg) |Omega| = 0.52 |Omega|: a spin of 4 deg/s stays under every canal threshold
    slow = coriolis.statistics(t, np.tile([0.0, 0.0, math.radians(4.0)], (len(t), 1)))
    assert all(n.above_threshold_pct == 0.0 for n in slow.nods.values())
    assert math.degrees(2.0 * math.radians(4.0) * math.sin(math.radians(15.0))) < math.degrees(
        perception.THRESHOLDS[:3].min())


def test_the_share_above_threshold_counts_the_starts_at_which_the_cabin_turns():
    """Half the time spinning, half still (a nod started just before the spin starts catches its onset)."""
    t = np.arange(0.0, 10.0, 0.01)
    omega = np.where((t >= 5.0)[:, None], [0.0, 0.0, 1.0], 0.0)
    share = coriolis.statistics(t, omega).nods["pitch"].above_threshold_pct
    assert 50.0 <= share <= 50.0 + 100.0 * 0.5 / 10.0 + 0.1


def test_the_summary_names_every_nod_in_degrees():
    t = np.arange(0.0, 2.0, 0.01)
    d = coriolis.statistics(t, np.tile([0.5, 0.0, 1.0], (len(t), 1))).to_dict()
    assert d["nod"]["angle_deg"] == pytest.approx(30.0) and d["nod"]["duration_s"] == 0.5
    assert set(d) >= {"pitch", "roll", "yaw", "worst"}
    assert d["pitch"]["velocity_peak_deg_s"] == pytest.approx(math.degrees(2.0 * 1.0 * math.sin(math.radians(15.0))),
                                                              rel=1e-9)

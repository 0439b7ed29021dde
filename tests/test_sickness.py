"""The sickness dose: ISO 2631-1's W_f against the standard's own table, MSDV_z on sines in closed
form, and the subjective vertical conflict model's structure (Bos & Bles 1998)."""

import math

import numpy as np
import pytest

from desdemona.occupant import sickness

#: ISO 2631-1:1997, table 3: W_f in one-third octave bands, nominal band frequency [Hz] -> factor x 1000.
ISO_W_F = {0.02: 24.2, 0.025: 37.7, 0.0315: 59.7, 0.04: 97.1, 0.05: 157, 0.063: 267, 0.08: 461, 0.1: 695,
           0.125: 895, 0.16: 1006, 0.2: 992, 0.25: 854, 0.315: 619, 0.4: 384, 0.5: 224, 0.63: 116,
           0.8: 53.0, 1.0: 23.5, 1.25: 9.98, 1.6: 3.77, 2.0: 1.55, 2.5: 0.64, 3.15: 0.25, 4.0: 0.097}
G = 9.81


def test_w_f_from_its_definition_matches_the_standards_table_within_one_percent():
    f = np.array(list(ISO_W_F))
    assert 1000.0 * sickness.w_f_gain(f) == pytest.approx(np.array(list(ISO_W_F.values())), rel=0.01)


@pytest.mark.parametrize("f", list(ISO_W_F))
def test_msdv_of_a_sine_on_gravity_is_the_tabulated_gain_times_its_rms(f):
    """The sampled filter (100 Hz, as the results' grids) on a sine of 1 m/s^2 riding on 1 g: over the
    last whole periods, after the start's transient, MSDV^2 / duration = (W_f A)^2 / 2."""
    dt, periods = 0.01, 10
    tail = periods / f
    t = np.arange(0.0, max(300.0, 3.0 * tail), dt)
    a_w = sickness.weighted_vertical(t, G + np.sin(2.0 * math.pi * f * t))
    last = t >= t[-1] + dt - tail
    gain = sickness.msdv(t[last], a_w[last]) / math.sqrt(tail / 2.0)
    assert gain == pytest.approx(ISO_W_F[f] / 1000.0, rel=0.01)


def test_a_cabin_at_rest_or_under_a_steady_force_has_no_dose():
    t = np.arange(0.0, 60.0, 0.02)
    for f_z in (np.full_like(t, G), np.full_like(t, 3.0 * G)):
        dose = sickness.dose(t, f_z)
        assert dose.msdv_z == pytest.approx(0.0, abs=1e-9)
        assert dose.conflict_incidence_end_pct == pytest.approx(0.0, abs=1e-12)


def test_msdv_grows_with_the_square_root_of_time_and_the_iso_incidence_is_a_third_of_it():
    t = np.arange(0.0, 1200.0, 0.02)
    f_z = G + 1.0 * np.sin(2.0 * math.pi * 0.2 * t)
    half = t < 600.0
    whole, first = sickness.dose(t, f_z), sickness.dose(t[half], f_z[half])
    assert whole.msdv_z / first.msdv_z == pytest.approx(math.sqrt(2.0), rel=0.01)
    assert whole.iso_incidence_pct == pytest.approx(whole.msdv_z / 3.0)


def test_the_conflict_of_a_step_in_force_decays_with_the_subjective_verticals_time_constant():
    """f_z steps by F: the subjective vertical follows 1 / (tau s + 1), so c = F exp(-t / tau)."""
    dt, F, tau = 0.01, 5.0, sickness.BOS_BLES["tau"]
    t = np.arange(0.0, 30.0, dt)
    f_z = np.where(t >= 1.0, G + F, G)
    c = sickness.vertical_conflict(t, f_z)
    after = t >= 1.0 + dt
    # the first-order hold ramps the step over one sample; afterwards the decay is exact
    assert c[after] == pytest.approx(F * np.exp(-(t[after] - 1.0 - dt / 2.0) / tau), rel=2e-3)
    assert np.abs(c[t < 1.0 - dt]).max() < 1e-12


def test_a_saturating_conflict_raises_the_incidence_as_the_second_order_integration_of_P():
    """With |c| >> b the Hill function is 1, and MSI(t) = P (1 - (1 + t / tau_I) exp(-t / tau_I))."""
    p = dict(sickness.BOS_BLES, tau=1e9)  # the subjective vertical never follows: c = f_z - g, constant
    t = np.arange(0.0, 3600.0, 0.5)
    f_z = np.where(t > 0.0, G + 100.0, G)
    msi = sickness.conflict_incidence(t, f_z, p)
    x = np.maximum(t - 0.25, 0.0) / p["tau_I"]  # the first-order hold ramps the step over the first 0.5 s
    expected = p["P"] * (1.0 - (1.0 + x) * np.exp(-x))
    hill = (100.0 / p["b"]) ** 2 / (1.0 + (100.0 / p["b"]) ** 2)
    assert msi[1:] == pytest.approx(hill * expected[1:], rel=2e-3, abs=1e-3)
    assert msi.max() < p["P"]


def test_sickness_is_worst_near_the_standards_most_nauseogenic_band():
    """W_f peaks at 0.16 Hz: the same vertical sine gives a larger dose there than at 0.02 or 2 Hz."""
    t = np.arange(0.0, 600.0, 0.02)
    doses = {f: sickness.dose(t, G + np.sin(2.0 * math.pi * f * t)).msdv_z for f in (0.02, 0.16, 2.0)}
    assert doses[0.16] > 10.0 * doses[0.02] and doses[0.16] > 100.0 * doses[2.0]

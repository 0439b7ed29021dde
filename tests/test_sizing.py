"""Problem size before building it, and targets no trajectory can give (sizing)."""

import numpy as np
import pytest

from desdemona import Model, profiles
from desdemona.cueing import sizing
from desdemona.cueing.formulation import ProblemOptions
from desdemona.cueing.transcription import CueingProblem
from desdemona.machine.configs import get_configuration


def test_estimate_counts_the_problem_it_will_build(params):
    path = profiles.cosine(duration=2.0)
    options = ProblemOptions(h_u=0.1)
    size = sizing.estimate(path, get_configuration("yaw-track"), options)
    built = CueingProblem(Model(params, "yaw-track"), path, options)
    assert size.intervals == built.N == 20
    assert size.variables == built.nlp["x"].numel()


def test_too_large_says_what_to_change(monkeypatch):
    monkeypatch.setattr(sizing, "available_memory", lambda: 4e9)
    path = profiles.cosine(duration=600.0, dt=0.1)
    with pytest.raises(sizing.TooLarge) as info:
        sizing.check_fits(path, get_configuration("full"), ProblemOptions(h_u=0.01))
    message = str(info.value)
    assert "60,000 control intervals" in message and "4.0 GB are available" in message
    h_u = float(message.split("Use --h-u ")[1].split()[0])
    assert sizing.estimate(path, get_configuration("full"), ProblemOptions(h_u=h_u)).memory <= 4e9


def test_steady_limit_is_the_centrifuge_at_its_rim(params):
    """Yaw at its rate limit with the cabin 4 m out: |f| = sqrt((R w^2)^2 + g^2), since the default
    track force (200 kN) holds the 6 t riding on it at the rim (176 kN)."""
    model = Model(params, "yaw-track")
    w, R, g = params.velocity_max[0], 4.0, params.gravity
    assert sizing.steady_modulus_limit(model) == pytest.approx(np.hypot(R * w**2, g), rel=1e-9)


def test_unreachable_targets_of_dfs(params):
    model = Model(params, "dfs")
    t = np.linspace(0.0, 10.0, 1001)
    M = np.where(t < 5.0, 0.5 * params.gravity, 5.0 * params.gravity)
    report = sizing.unreachable(profiles.DesiredPath("x", t, None, modulus=M), model)
    assert report["below_g"]["share_of_time"] == pytest.approx(0.5, abs=0.01)
    assert report["below_g"]["worst_m_s2"] == pytest.approx(0.5 * params.gravity)
    # the 1 s mean rises above the limit (31 m/s^2) 0.09 s after the step from 0.5 g to 5 g
    assert report["above_steady_limit"]["share_of_time"] == pytest.approx(0.491, abs=0.002)
    assert "unreachable target" in sizing.describe(report)
    assert sizing.unreachable(profiles.dfs_catapult(), model) == {"below_g": None, "above_steady_limit": None}


def test_a_rest_logged_at_standard_gravity_is_not_below_g(params):
    """A phone's log at rest reads 9.80665 m/s^2 and its noise: below the model's g (9.81) by less than
    the vertical force's perception threshold (0.28 m/s^2), not counted as unreachable; a dip of 0.4 is."""
    t = np.linspace(0.0, 10.0, 1001)
    noisy = 9.80665 + 0.05 * np.random.default_rng(0).standard_normal(len(t))
    for config in ("dfs", "yaw-track-cabin", "full"):
        model = Model(params, config)
        assert sizing.unreachable(profiles.DesiredPath("x", t, None, modulus=noisy), model)["below_g"] is None
        dip = np.where((t > 4.0) & (t < 6.0), params.gravity - 0.4, noisy)
        assert sizing.unreachable(profiles.DesiredPath("x", t, None, modulus=dip), model)["below_g"] is not None

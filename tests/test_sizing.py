"""Problem size and run time before building it, and targets no trajectory can give (sizing)."""

import time

import numpy as np
import pytest

from desdemona import Model, profiles
from desdemona.control.mpc import MPCOptions
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


def _refused(capsys, argv) -> tuple[str, float]:
    """The exit-2 line of a command refused before any work, and the processor time it took."""
    from desdemona.cli import main

    start = time.process_time()
    assert main(argv) == 2
    seconds = time.process_time() - start
    lines = capsys.readouterr().err.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("desdemona: error: "), lines
    return lines[0], seconds


def test_an_online_run_too_long_is_refused_with_the_step_that_fits(tmp_path, capsys):
    """20 times its duration by default: 240,000 cycles of dfs-catapult are refused at once (the
    memory allows them), naming a --step whose estimate fits, and --max-time that would allow it."""
    out = tmp_path / "run"
    line, seconds = _refused(capsys, ["online", "dfs-catapult", "--config", "dfs", "--step", "5e-5",
                                      "--out", str(out)])
    assert "240,000 closed-loop steps" in line and seconds < 2.0 and not out.exists()
    step = float(line.split("Use --step ")[1].split()[0])
    allowed = float(line.split("--max-time ")[1].split()[0])
    path, dfs = profiles.load("dfs-catapult"), get_configuration("dfs")
    mpc = MPCOptions(step=5e-5)
    assert sizing.estimate_time_online(path, dfs, MPCOptions(step=step)) <= sizing.time_limit(path)
    assert sizing.check_time_online(path, dfs, mpc, max_time=allowed) <= allowed
    assert sizing.check_time_online(path, dfs, MPCOptions()) <= sizing.time_limit(path)  # the default runs


def test_an_offline_run_too_long_is_refused_with_the_h_u_that_fits(tmp_path, capsys):
    out = tmp_path / "run"
    line, seconds = _refused(capsys, ["optimize", "catapult", "--config", "full", "--h-u", "0.001", "--out", str(out)])
    assert "8,000 control intervals" in line and seconds < 2.0 and not out.exists()
    h_u = float(line.split("Use --h-u ")[1].split()[0])
    path, full = profiles.load("catapult"), get_configuration("full")
    assert sizing.estimate_time(path, full, h_u, "fatrop", 4, 2) <= sizing.time_limit(path) == 160.0
    assert sizing.check_time(path, full, 0.05, "fatrop", 4, 2) < 60.0  # the default runs
    line, _ = _refused(capsys, ["optimize", "catapult", "--config", "full", "--max-time", "-3", "--out", str(out)])
    assert line.endswith("--max-time -3: must be a positive number of seconds") and not out.exists()


def test_the_estimate_grows_with_the_work():
    """Twice the intervals, twice the starts on one worker, a solver twice as dear per interval: more."""
    path, full = profiles.load("catapult"), get_configuration("full")
    base = sizing.estimate_time(path, full, 0.01, "fatrop") - sizing.BASE_SECONDS
    assert sizing.estimate_time(path, full, 0.005, "fatrop") - sizing.BASE_SECONDS > 2 * base
    assert sizing.estimate_time(path, full, 0.01, "fatrop", starts=2) - sizing.BASE_SECONDS > 1.5 * base
    assert sizing.estimate_time(path, full, 0.01, "fatrop", starts=2, workers=2) == base + sizing.BASE_SECONDS
    assert sizing.estimate_time(path, full, 0.01, "fatrop", window=2.0) < base + sizing.BASE_SECONDS

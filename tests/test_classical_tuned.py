"""The tuned classical washout (:func:`desdemona.baselines.washout.tuned`): on a sustained force the arm holds it
as a centrifuge does, the felt force in the cabin follows the intent, and every limit holds."""

import numpy as np
import pytest

from desdemona.baselines.washout import (
    ARM_RATE_SHARE,
    Washout,
    _gimbal_angles,
    _rotation_between,
    classical_washout,
    tuned,
)
from desdemona.check.simulate import TOLERANCE, check, evaluate_plan
from desdemona.machine.model import Model
from desdemona.profiles import DesiredPath

STEP = 0.05
G = 9.81


def sustained(force, duration: float = 100.0, yaw_rate: float = -0.2) -> DesiredPath:
    """From level flight, a 2 s ramp to the specific force ``force`` (3,) in the cabin [m/s^2] and the
    yaw rate ``yaw_rate`` [rad/s], held: a steady coordinated turn, or a race car's long corner."""
    t = np.arange(0.0, duration + 1e-9, STEP)
    ramp = np.clip(t / 2.0, 0.0, 1.0)[:, None]
    level = np.array([0.0, 0.0, 0.0, 0.0, 0.0, G])
    held = np.r_[0.0, 0.0, yaw_rate, force]
    return DesiredPath("sustained", t, level + ramp * (held - level))


def felt_force_rms(model, path, settings) -> tuple[float, object, object]:
    plan = classical_washout(path, model, settings=settings, state=(np.zeros(model.n), np.zeros(model.n)))
    traj = evaluate_plan(model, path, plan, path.t)
    return float(np.sqrt(np.mean(np.sum((traj.S[:, 3:] - traj.S_d[:, 3:]) ** 2, axis=1)))), plan, traj


def held_force(config: str, force) -> np.ndarray:
    """The force the tuned arm holds in steady rotation: what the desired force needs of the arm beyond
    ``arm_min`` (eq. 7.7: on full the centripetal force beside g, sqrt(|f|^2 - g^2); on yaw-track-cabin
    the horizontal force), the arm's rate within its share of the limit, turned onto the desired
    direction."""
    model = Model(config=config)
    settings, force = tuned(model.config), np.asarray(force, dtype=float)
    need = np.sqrt(force @ force - G**2) if config == "full" else np.hypot(force[0], force[1])
    rate = min(np.sqrt(max(need - settings.arm_min, 0.0) / settings.radius), ARM_RATE_SHARE * model.limits.velocity[0])
    centripetal = settings.radius * rate**2
    if config == "full":
        return force / np.linalg.norm(force) * np.hypot(G, centripetal)
    return np.r_[force[:2] / need * centripetal, G]


@pytest.mark.parametrize("config, force", [("full", (0.0, 0.0, 4.0 * G)),  # a steady 4 g turn
                                           ("yaw-track-cabin", (0.0, 8.0, G))])  # 0.8 g in a long corner
def test_the_tuned_washout_holds_a_sustained_force_within_every_limit(config, force):
    model = Model(config=config)
    path = sustained(force)
    old, _, _ = felt_force_rms(model, path, Washout())
    rms, plan, traj = felt_force_rms(model, path, tuned(model.config))
    assert rms < 0.8 * old
    # the felt force in the cabin, re-simulated, is what the arm holds once it is up to speed
    late = traj.t > path.t[-1] - 5.0
    np.testing.assert_allclose(traj.S[late, 3:], np.broadcast_to(held_force(config, force), (late.sum(), 3)),
                               atol=0.3)
    assert np.all(traj.qd[late, 0] < 0.0)  # the arm turns the way the vehicle does
    result, _ = check(model, path, plan, STEP)
    for name, worst in result.worst.items():
        assert worst <= 1.0 + TOLERANCE, (name, worst, result.describe_violations())
    assert np.abs(plan.acceleration_jumps()).max() < 1e-9


def test_the_default_washout_is_the_tuned_one_per_configuration():
    """The tuned settings are the configuration's data: the two tuned ones run them, the others the
    untuned defaults."""
    path = sustained((0.0, 0.0, 1.2 * G), duration=4.0)
    assert tuned(Model(config="yaw-track").config) == Washout()
    assert tuned(Model(config="full").config) != tuned(Model(config="yaw-track-cabin").config) != Washout()
    for config in ("full", "yaw-track-cabin", "yaw-track"):
        model = Model(config=config)
        default = classical_washout(path, model)
        expected = classical_washout(path, model, settings=tuned(model.config))
        np.testing.assert_array_equal(default.u, expected.u)


def test_the_pointing_rotation_takes_the_desired_direction_to_the_arm_force_and_back_to_gimbal_angles():
    """R d = f for the smallest rotation, and the gimbal angles of R rebuild it (R = Rx Rz Ry, eq. A.7)."""
    from desdemona.machine.kinematics import rotation

    rng = np.random.default_rng(7)
    d, f = rng.normal(size=(20, 3)), rng.normal(size=(20, 3))
    d[:, 2], f[:, 2] = np.abs(d[:, 2]) + 0.5, np.abs(f[:, 2]) + 0.5  # both up: never opposite
    d /= np.linalg.norm(d, axis=1)[:, None]
    f /= np.linalg.norm(f, axis=1)[:, None]
    R = _rotation_between(d, f)
    np.testing.assert_allclose(np.einsum("kij,kj->ki", R, d), f, atol=1e-12)
    np.testing.assert_allclose(R @ np.transpose(R, (0, 2, 1)), np.broadcast_to(np.eye(3), R.shape), atol=1e-12)
    for Rk, (a, b, c) in zip(R, _gimbal_angles(R)):
        np.testing.assert_allclose(rotation(0, a) @ rotation(2, b) @ rotation(1, c), Rk, atol=1e-12)

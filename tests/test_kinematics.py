"""Kinematics against closed forms: appendix B (eq. B.2-B.5), eq. 7.7 and simple rigid motions."""

import casadi as ca
import numpy as np
import pytest

from desdemona import Model
from desdemona.machine import kinematics
from tests.states import random_states


def test_rest_level_cabin_feels_plus_g():
    S = kinematics.S(np.zeros(6), np.zeros(6), np.zeros(6), gravity=9.81)
    np.testing.assert_allclose(S, [0, 0, 0, 0, 0, 9.81], atol=1e-15)


def test_rotations_are_right_handed():
    # Rz(90 deg) takes x to y; Rx(90 deg) takes y to z; Ry(90 deg) takes z to x (eq. A.2-A.4).
    np.testing.assert_allclose(kinematics.rotation(2, np.pi / 2) @ [1, 0, 0], [0, 1, 0], atol=1e-15)
    np.testing.assert_allclose(kinematics.rotation(0, np.pi / 2) @ [0, 1, 0], [0, 0, 1], atol=1e-15)
    np.testing.assert_allclose(kinematics.rotation(1, np.pi / 2) @ [0, 0, 1], [1, 0, 0], atol=1e-15)


def test_cabin_pose_follows_eq_A7():
    q = np.array([0.3, -1.2, 0.4, 0.5, -0.7, 1.1])
    R = lambda a, x: kinematics.rotation(a, x)  # noqa: E731
    expected_R = R(2, q[0]) @ R(0, q[3]) @ R(2, q[4]) @ R(1, q[5])
    expected_p = R(2, q[0]) @ np.array([0.0, q[1], q[2]])
    H = kinematics.cabin_pose(q)
    np.testing.assert_allclose(H[:3, :3], expected_R, atol=1e-15)
    np.testing.assert_allclose(H[:3, 3], expected_p, atol=1e-15)


def test_appendix_B_path_at_100_random_states(toy):
    """S of the yaw-track configuration equals eq. B.5 (with the q2*qdd1 typo corrected, see B.3)."""
    model = Model(toy, "yaw-track")
    q, qd, qdd = random_states(model, 200, seed=1)
    S = model.S(q, qd, qdd)
    q2, q1d, q2d, q1dd, q2dd = q[:, 1], qd[:, 0], qd[:, 1], qdd[:, 0], qdd[:, 1]
    g = toy.gravity
    expected = np.column_stack([0 * q2, 0 * q2, q1d, -q2 * q1dd - 2 * q1d * q2d, q2dd - q1d**2 * q2,
                                g + 0 * q2])
    np.testing.assert_allclose(S, expected, rtol=1e-12, atol=1e-12)


def test_dfs_modulus_eq_7_7(params):
    """q2 = -4 m: at constant yaw rate M = sqrt((4 w^2)^2 + g^2); yaw acceleration adds (4 qdd1)^2."""
    model = Model(params, "dfs-yaw")
    g = params.gravity
    for w in (0.0, 0.5, 1.3, 2.7):
        np.testing.assert_allclose(model.modulus(0.2, w, 0.0), np.sqrt((4 * w**2) ** 2 + g**2), rtol=1e-14)
        for a in (-0.7, 0.4):
            expected = np.sqrt((4 * a) ** 2 + (4 * w**2) ** 2 + g**2)
            np.testing.assert_allclose(model.modulus(0.2, w, a), expected, rtol=1e-14)


def test_gimbal_alignment_puts_specific_force_on_cabin_z(params):
    """With the gimbals of :func:`gimbal_alignment`, the dfs cabin feels (0, 0, M) (chapter 7)."""
    dfs = Model(params, "dfs-yaw")
    rng = np.random.default_rng(7)
    for _ in range(20):
        q1, q1d, q1dd = rng.uniform(-3, 3), rng.uniform(-2.5, 2.5), rng.uniform(-0.8, 0.8)
        f_arm = dfs.f_cabin(q1, q1d, q1dd)  # gimbals at zero: arm-frame specific force
        q4, q6 = kinematics.gimbal_alignment(f_arm)
        q = np.array([q1, -4.0, -1.0, q4, 0.0, q6])
        qd = np.array([q1d, 0, 0, 0, 0, 0.0])
        qdd = np.array([q1dd, 0, 0, 0, 0, 0.0])
        f = kinematics.S(q, qd, qdd, params.gravity)[3:]
        np.testing.assert_allclose(f, [0, 0, np.linalg.norm(f_arm)], atol=1e-12)


def test_head_offset_adds_rigid_body_terms(params):
    """A head offset r in a yawing cabin adds the tangential and centripetal terms of r."""
    r = np.array([0.1, 0.3, 0.5])
    w, a = 1.1, 0.4
    q, qd, qdd = np.zeros(6), np.array([w, 0, 0, 0, 0, 0.0]), np.array([a, 0, 0, 0, 0, 0.0])
    S0 = kinematics.S(q, qd, qdd, params.gravity)
    S1 = kinematics.S(q, qd, qdd, params.gravity, head_offset=r)
    omega, alpha = np.array([0, 0, w]), np.array([0, 0, a])
    extra = np.cross(alpha, r) + np.cross(omega, np.cross(omega, r))
    np.testing.assert_allclose(S1[3:] - S0[3:], extra, atol=1e-13)
    np.testing.assert_allclose(S1[:3], S0[:3], atol=1e-15)


@pytest.mark.parametrize("config", ["dfs", "dfs-yaw", "yaw-track", "yaw-track-cabin", "full"])
def test_float_and_casadi_evaluations_agree(params, config):
    model = Model(params, config)
    q, qd, qdd = random_states(model, 20, seed=3)
    for sym in (ca.SX, ca.MX):
        x = [sym.sym(name, model.n) for name in ("q", "qd", "qdd")]
        f = ca.Function("check", x, [model.S(*x), model.tau(*x), model.power(*x)])
        for k in range(len(q)):
            S, tau, power = (np.asarray(v).ravel() for v in f(q[k], qd[k], qdd[k]))
            np.testing.assert_allclose(S, model.S(q[k], qd[k], qdd[k]), rtol=1e-12, atol=1e-12)
            np.testing.assert_allclose(tau, model.tau(q[k], qd[k], qdd[k]), rtol=1e-12, atol=1e-6)
            np.testing.assert_allclose(power, model.power(q[k], qd[k], qdd[k]), rtol=1e-12, atol=1e-6)


def test_batch_evaluation_equals_one_by_one(params):
    model = Model(params, "full")
    q, qd, qdd = random_states(model, 7, seed=4)
    batch = model.S(q, qd, qdd)
    assert batch.shape == (7, 6)
    for k in range(7):
        np.testing.assert_array_equal(batch[k], model.S(q[k], qd[k], qdd[k]))
    with pytest.raises(ValueError, match="shape"):
        model.S(q[:, :5], qd, qdd)


def test_numeric_calls_in_place_equal_casadis_own_call(params):
    """One sample and a few (evaluated in place through a kept FunctionBuffer), many (one CasADi call)
    and CasADi's own call give the same bits, from two threads at once as from one."""
    from concurrent.futures import ThreadPoolExecutor

    from desdemona.support.symbolic import FEW, call

    model = Model(params, "full")
    q, qd, qdd = random_states(model, FEW + 5, seed=5)
    S, M = model.functions["S"], model.functions["M"]
    own = np.asarray(S(q.T, qd.T, qdd.T)).T
    np.testing.assert_array_equal(call(S, q, qd, qdd), own)  # many: one call
    np.testing.assert_array_equal(call(S, q[:3], qd[:3], qdd[:3]), own[:3])  # a few: in place
    np.testing.assert_array_equal(call(M, q[2], matrix=True), np.asarray(M(q[2])))

    def one_by_one(rows):
        return [call(S, q[k], qd[k], qdd[k]) for k in rows for _ in range(50)][::50]

    with ThreadPoolExecutor(2) as pool:
        done = [pool.submit(one_by_one, rows) for rows in (range(0, 8), range(8, len(q)))]
    np.testing.assert_array_equal(np.vstack(done[0].result() + done[1].result()), own)


def test_gimbal_twin_is_the_same_cabin_attitude_on_the_other_branch():
    """Rx(a) Rz(b) Ry(c) = Rx(a + pi) Rz(pi - b) Ry(c + pi): the same pose, and at rest the same S."""
    from desdemona.machine.kinematics import S, cabin_pose, gimbal_twin

    rng = np.random.default_rng(7)
    for _ in range(5):
        q = np.r_[rng.uniform(-3, 3), rng.uniform(-4, 4), rng.uniform(-1, 1), rng.uniform(-3, 3, 3)]
        twin = gimbal_twin(q)
        np.testing.assert_allclose(cabin_pose(twin), cabin_pose(q), atol=1e-12)
        np.testing.assert_allclose(S(twin, np.zeros(6), np.zeros(6)), S(q, np.zeros(6), np.zeros(6)), atol=1e-12)
        assert np.all(np.abs(twin[3:]) <= np.pi) and np.all(twin[:3] == q[:3])
        wrapped = (q[3:] + np.pi) % (2 * np.pi) - np.pi
        np.testing.assert_allclose(gimbal_twin(twin)[3:], wrapped, atol=1e-12)

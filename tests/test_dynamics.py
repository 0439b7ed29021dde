"""Dynamics against appendix B (eq. B.1), Pinocchio, and the identities of Lagrangian mechanics."""

import dataclasses

import casadi as ca
import numpy as np
import pytest

from desdemona import Model
from desdemona.machine import dynamics, kinematics
from tests.states import random_states

try:  # the independent rigid-body reference; only its own test needs it
    import pinocchio as pin
except ImportError:
    pin = None
needs_pinocchio = pytest.mark.skipif(pin is None, reason="needs Pinocchio (pip install pin)")


def rel_err(a, b):
    return np.linalg.norm(np.asarray(a) - np.asarray(b)) / max(np.linalg.norm(b), 1e-300)


def test_appendix_B_equation_of_motion(toy):
    """tau, M and C of yaw-track with the toy parameters equal eq. B.1 at 200 random states."""
    model = Model(toy, "yaw-track")
    ie1, ie2, m2 = 1.0, 2.0, 2.0
    q, qd, qdd = random_states(model, 200, seed=11)
    tau = model.tau(q, qd, qdd)
    for k in range(len(q)):
        q2, q1d, q2d = q[k, 1], qd[k, 0], qd[k, 1]
        M = np.array([[ie1 + ie2 + m2 * q2**2, 0.0], [0.0, m2]])
        C = np.array([[q2 * m2 * q2d, q2 * m2 * q1d], [-q2 * m2 * q1d, 0.0]])
        np.testing.assert_allclose(model.mass_matrix(q[k]), M, rtol=1e-12, atol=1e-12)
        np.testing.assert_allclose(model.coriolis_matrix(q[k], qd[k]), C, rtol=1e-12, atol=1e-12)
        np.testing.assert_allclose(tau[k], M @ qdd[k] + C @ qd[k], rtol=1e-12, atol=1e-12)
    np.testing.assert_allclose(model.gravity_vector(q[0]), [0.0, 0.0], atol=1e-12)


def pinocchio_model(params):
    """The chain of eq. A.7 built independently in Pinocchio, with a frame at the head."""
    joints = [pin.JointModelRZ(), pin.JointModelPY(), pin.JointModelPZ(),
              pin.JointModelRX(), pin.JointModelRZ(), pin.JointModelRY()]
    model = pin.Model()
    parent = 0
    for joint, body in zip(joints, params.bodies):
        parent = model.addJoint(parent, joint, pin.SE3.Identity(), body.name)
        inertia = pin.Inertia(body.mass, np.array(body.com), np.array(body.inertia))
        model.appendBodyToJoint(parent, inertia, pin.SE3.Identity())
    head = pin.SE3(np.eye(3), np.array(params.head_offset))
    frame = model.addFrame(pin.Frame("head", parent, head, pin.FrameType.OP_FRAME))
    model.gravity.linear = np.array([0.0, 0.0, -params.gravity])
    return model, frame


@pytest.mark.parametrize("head_offset", [(0.0, 0.0, 0.0), (0.15, -0.1, 0.6)])
@needs_pinocchio
def test_full_model_equals_pinocchio(params, head_offset):
    params = dataclasses.replace(params, head_offset=head_offset)
    model = Model(params, "full")
    pmodel, frame = pinocchio_model(params)
    data = pmodel.createData()
    q, qd, qdd = random_states(model, 150, seed=12)
    tau = model.tau(q, qd, qdd)
    S = model.S(q, qd, qdd)
    for k in range(len(q)):
        assert rel_err(tau[k], pin.rnea(pmodel, data, q[k], qd[k], qdd[k])) < 1e-9
        M_pin = pin.crba(pmodel, data, q[k])
        M_pin = np.triu(M_pin) + np.triu(M_pin, 1).T
        assert rel_err(model.mass_matrix(q[k]), M_pin) < 1e-9
        pin.forwardKinematics(pmodel, data, q[k], qd[k], qdd[k])
        pin.updateFramePlacements(pmodel, data)
        omega = pin.getFrameVelocity(pmodel, data, frame, pin.LOCAL).angular
        accel = pin.getFrameClassicalAcceleration(pmodel, data, frame, pin.LOCAL).linear
        R = data.oMf[frame].rotation
        f = accel - R.T @ pmodel.gravity.linear
        np.testing.assert_allclose(S[k, :3], omega, rtol=1e-10, atol=1e-10)
        np.testing.assert_allclose(S[k, 3:], f, rtol=1e-10, atol=1e-9)


@pytest.mark.parametrize("config", ["dfs", "dfs-yaw", "yaw-track", "yaw-track-cabin", "full"])
def test_mass_matrix_symmetric_positive_definite(params, config):
    model = Model(params, config)
    q, _, _ = random_states(model, 100, seed=13)
    for k in range(len(q)):
        M = model.mass_matrix(q[k])
        np.testing.assert_array_equal(M, M.T)
        assert np.linalg.eigvalsh(M).min() > 0.0


@pytest.mark.parametrize("simplified", [False, True])
def test_Mdot_minus_2C_is_skew_symmetric(params, simplified):
    p = params.simplified() if simplified else params
    model = Model(p, "full")
    qs, qds = ca.SX.sym("q", 6), ca.SX.sym("qd", 6)
    M_dot = ca.Function("Mdot", [qs, qds], [ca.jtimes(model.mass_matrix(qs), qs, qds)])
    q, qd, _ = random_states(model, 100, seed=14)
    for k in range(len(q)):
        A = np.asarray(M_dot(q[k], qd[k])) - 2.0 * model.coriolis_matrix(q[k], qd[k])
        assert np.abs(A + A.T).max() <= 1e-9 * np.abs(A).max()


@pytest.mark.parametrize("gravity", [0.0, 9.81])
def test_power_balance(params, gravity):
    """d/dt (T + V) = qd . tau, by central differences in time along the motion (1e-6 relative)."""
    p = dataclasses.replace(params, gravity=gravity)
    model = Model(p, "full")
    q, qd, qdd = random_states(model, 100, seed=15)
    h = 1e-4

    def energy(sign):
        qs = q + sign * h * qd + 0.5 * h**2 * qdd
        qds = qd + sign * h * qdd
        T = model.kinetic_energy(qs, qds)[:, 0]
        V = model.potential_energy(qs)[:, 0]
        return T + V

    dE = (energy(+1) - energy(-1)) / (2 * h)
    power = np.sum(model.power(q, qd, qdd), axis=1)
    np.testing.assert_allclose(dE, power, rtol=1e-6, atol=1e-6 * np.abs(power).max())


@pytest.mark.parametrize("config", ["dfs", "dfs-yaw", "yaw-track", "yaw-track-cabin", "full"])
def test_forward_dynamics_inverts_inverse_dynamics(params, config):
    model = Model(params, config)
    q, qd, qdd = random_states(model, 100, seed=16)
    tau = model.tau(q, qd, qdd)
    np.testing.assert_allclose(model.forward_dynamics(q, qd, tau), qdd, rtol=1e-9, atol=1e-9)


def test_gravity_acts_through_heave_and_offset_cabin(params):
    """N = dV/dq: the heave carries every body above it; the cabin's low centre of mass swings."""
    q = np.array([0.4, 1.0, 0.3, 0.0, 0.0, 0.2])
    N = dynamics.gravity_vector(q, params)
    riding = sum(b.mass for b in params.bodies[2:])
    np.testing.assert_allclose(N[2], riding * params.gravity, rtol=1e-14)
    # cabin: com (0, 0, -0.2) turned by q6 about y: height -0.2 cos(q6), dV/dq6 = m g 0.2 sin(q6)
    m6 = params.bodies[5].mass
    np.testing.assert_allclose(N[5], m6 * params.gravity * 0.2 * np.sin(0.2), rtol=1e-12)
    np.testing.assert_allclose(N[[0, 1]], [0.0, 0.0], atol=1e-9)
    simplified = dynamics.gravity_vector(q, params.simplified())
    np.testing.assert_allclose(simplified[3:], 0.0, atol=1e-9)


def test_configuration_rows_equal_full_model_with_held_joints_at_rest(params):
    """A reduced model is the full eq. A.26 with held joints fixed, rows of the free joints."""
    for name in ("dfs", "dfs-yaw", "yaw-track", "yaw-track-cabin"):
        model = Model(params, name)
        cfg = model.config
        q, qd, qdd = random_states(model, 30, seed=17)
        full_tau = dynamics.inverse_dynamics(cfg.expand(q), cfg.expand(qd, "zero"), cfg.expand(qdd, "zero"), params)
        np.testing.assert_allclose(model.tau(q, qd, qdd), full_tau[:, list(cfg.free)], rtol=1e-12, atol=1e-6)
        full_S = kinematics.S(cfg.expand(q), cfg.expand(qd, "zero"), cfg.expand(qdd, "zero"), params.gravity)
        np.testing.assert_allclose(model.S(q, qd, qdd), full_S, rtol=1e-13, atol=1e-13)


def test_yaw_track_interaction_at_the_rim(params):
    """Holding what rides on the track at the rim at full yaw rate takes most of the track force."""
    model = Model(params, "yaw-track")
    lim = model.limits
    tau = model.tau([0.0, lim.position_max[1]], [lim.velocity[0], 0.0], [0.0, 0.0])
    riding = sum(b.mass for b in params.bodies[1:])
    np.testing.assert_allclose(-tau[1], riding * 4.0 * lim.velocity[0] ** 2, rtol=1e-12)
    assert 0.5 < abs(tau[1]) / lim.effort[1] < 1.0

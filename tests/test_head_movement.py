"""The cost of the cabin's rotation in space where a head may move (``--head-movement-weight``): off by
default it leaves the stage's residuals as they were; on, it adds the cabin's angular velocity at each
point of the stage, weighed by its share of the interval."""

import math

import numpy as np
import pytest

from desdemona import profiles
from desdemona.cueing.formulation import Formulation, ProblemOptions
from desdemona.machine.model import Model
from desdemona.machine.plan import advance
from desdemona.runs import session

RNG = np.random.default_rng(7)


@pytest.mark.parametrize("config", ["dfs", "yaw-track-cabin"])
def test_the_weight_adds_the_cabins_angular_velocity_at_every_point_and_nothing_else(params, config):
    model = Model(params, config)
    t = np.linspace(0.0, 2.0, 41)
    path = (profiles.DesiredPath("m", t, None, modulus=np.full(len(t), 12.0)) if config == "dfs" else
            profiles.DesiredPath("s", t, np.tile([0.0, 0.0, 0.2, 1.0, 0.0, 9.81], (len(t), 1))))
    off, weight = Formulation(model, path, ProblemOptions(h_u=0.1)), 4.0
    on = Formulation(model, path, ProblemOptions(h_u=0.1, head_movement_weight=weight))
    x, u = RNG.normal(size=off.nx) * 0.3, RNG.normal(size=off.nu) * 0.3
    d = RNG.uniform(0.5, 1.0, size=off.residual.size1_in(2))
    r_off, r_on = np.ravel(off.residual(x, u, d)), np.ravel(on.residual(x, u, d))
    points = len(off.fractions)
    assert len(r_on) == len(r_off) + 3 * points
    assert r_on[:len(r_off)] == pytest.approx(r_off, rel=1e-12, abs=1e-12)
    n, h_u, inv_T = model.n, d[0], d[2]
    for j, fraction in enumerate(off.fractions):  # the cabin's angular velocity at the point
        tau = fraction * h_u
        a, jerk = (x[2 * n:3 * n], u) if off.smooth else (u, None)
        q, qd = advance(x[:n], x[n:2 * n], a, tau, jerk)
        omega = np.ravel(model.functions["S"](q, qd, a + jerk * tau if off.smooth else a))[:3]
        assert r_on[len(r_off) + 3 * j:len(r_off) + 3 * j + 3] == pytest.approx(
            math.sqrt(weight * h_u * inv_T / points) * omega, rel=1e-9, abs=1e-12)


def test_the_session_takes_it_off_line_and_on_line_and_refuses_a_negative_one(params):
    model = Model(params, "dfs")
    t = np.linspace(0.0, 4.0, 81)
    path = profiles.DesiredPath("m", t, None, modulus=np.full(len(t), 12.0))
    assert session.offline(path, model).options.head_movement_weight == 0.0
    chosen = session.Choices(head_movement_weight=2.5)
    assert session.offline(path, model, chosen).options.head_movement_weight == 2.5
    assert session.online(path, model, chosen, horizon=1.0).options.mpc.head_movement_weight == 2.5
    with pytest.raises(session.ChoiceError, match="--head-movement-weight -1: must be a number >= 0"):
        session.offline(path, model, session.Choices(head_movement_weight=-1.0))
    with pytest.raises(session.ChoiceError, match="drop --head-movement-weight"):
        session.thesis(path, Model(params, "yaw-track"), chosen)
    with pytest.raises(ValueError, match="head_movement_weight"):
        ProblemOptions(head_movement_weight=math.nan)


def test_the_controller_plans_with_it(params):
    from desdemona.control.mpc import MPC, MPCOptions

    mpc = MPC(Model(params, "dfs"), MPCOptions(horizon=1.0, head_movement_weight=2.0))
    assert mpc.problem.options.head_movement_weight == 2.0

"""Jerk limits: parameters, continuous plans, the check, the off-line and on-line optimisers."""

import math

import numpy as np
import pytest

from desdemona import profiles
from desdemona.check.simulate import check
from desdemona.control.mpc import MPC, MPCOptions
from desdemona.cueing.formulation import ProblemOptions
from desdemona.cueing.transcription import CueingProblem
from desdemona.machine.model import Model
from desdemona.machine.params import ParameterError, load_params
from desdemona.machine.plan import (
    STOP_LAG,
    Plan,
    State,
    advance,
    ramp,
    settled_rate,
    settled_rates,
    stopping_extent,
    stopping_jerk,
    stopping_reach,
)


def test_jerk_limits_load_with_units_and_must_be_all_or_none(params, toy, tmp_path):
    assert params.jerk_max[0] == pytest.approx(math.radians(180.0))
    assert params.jerk_max[1] == 20.0
    assert np.all(np.isinf(toy.jerk_max))
    good = tmp_path / "j.toml"
    good.write_text("[joints.track]\njerk_m_s3 = 12.5\n")
    assert load_params(good).jerk_max[1] == 12.5
    wrong_unit = tmp_path / "w.toml"
    wrong_unit.write_text("[joints.track]\njerk_deg_s3 = 10\n")
    with pytest.raises(ParameterError, match="jerk"):
        load_params(wrong_unit)
    partial = tmp_path / "p.toml"
    partial.write_text('[joints.yaw]\njerk = "unbounded"\n')
    with pytest.raises(ParameterError, match="give every joint a jerk limit"):
        load_params(partial)


def test_cubic_advance_and_plan_match_the_closed_form():
    """Constant jerk j from (q0, qd0, a0): q = q0 + qd0 t + a0 t^2/2 + j t^3/6."""
    q, qd = advance(1.0, 2.0, 3.0, 0.5, 4.0)
    assert q == pytest.approx(1.0 + 1.0 + 0.375 + 4.0 * 0.125 / 6.0)
    assert qd == pytest.approx(2.0 + 1.5 + 0.5)
    u, jerk = ramp(np.array([[1.0], [1.0], [0.0], [0.0]]), 0.1, a0=[0.0], jerk_max=[5.0])
    np.testing.assert_allclose(jerk.ravel(), [5.0, 5.0, -5.0, -5.0])
    plan = Plan(np.arange(5) * 0.1, [0.0], [0.0], u, jerk)
    np.testing.assert_allclose(plan.acceleration_jumps(), 0.0, atol=1e-15)
    # the rate is the integral of a piecewise-linear acceleration: 0.5 * (sum of trapezoids)
    _, qd_end, a_end = plan.at([0.4])
    assert a_end[0, 0] == pytest.approx(0.0, abs=1e-12)
    assert qd_end[0, 0] == pytest.approx(0.1 * (0.25 + 0.75 + 0.75 + 0.25))


def test_check_reports_a_step_of_acceleration_as_a_jerk_violation(params):
    model = Model(params, "dfs-yaw")
    path = profiles.dfs_catapult(duration=1.0)
    t = np.arange(51) * 0.02
    from_rest = Plan(t, [0.0], [0.0], np.full((50, 1), 0.2))  # 0.2 rad/s^2 from the first instant
    result, _ = check(model, path, from_rest, step=0.02)
    assert result.worst["jerk"] > 1.0 and not result.passed
    u = np.full((50, 1), 0.2)
    u[25:] = 0.1  # a step half-way
    result, _ = check(model, path, Plan(t, [0.0], [1.0], u), step=0.02)
    assert result.worst["jerk"] > 1.0 and not result.passed
    u, jerk = ramp(np.full((50, 1), 0.2), 0.02, a0=[0.0], jerk_max=model.limits.jerk)
    result, _ = check(model, path, Plan(t, [0.0], [1.0], u, jerk), step=0.02)
    assert result.worst["jerk"] == pytest.approx(1.0) and result.passed
    toy = Model(load_params(base="thesis-toy"), "yaw-track")  # no jerk limits: steps are allowed
    result, _ = check(toy, profiles.cosine(duration=1.0), Plan(t, [0.0, 0.0], [0.0, 0.0], np.full((50, 2), 0.1)), step=0.02)
    assert result.worst["jerk"] == 0.0


def test_offline_plan_from_rest_is_continuous_and_within_the_jerk_limit(params):
    model = Model(params, "dfs-yaw")
    problem = CueingProblem(model, profiles.dfs_catapult(duration=4.0), ProblemOptions(h_u=0.05, initial="rest"))
    assert problem.smooth and problem.nx == 3
    x, u = problem.guess(np.zeros(1), np.zeros(1), np.full((problem.N, 1), 0.5), np.zeros(1))
    sol = problem.solve(x, u)
    assert sol.success
    plan = sol.plan
    assert plan.u[0, 0] == 0.0  # from rest: no acceleration at t = 0 either
    np.testing.assert_allclose(plan.acceleration_jumps(), 0.0, atol=1e-9)
    assert np.max(np.abs(plan.jerk)) <= model.limits.jerk[0] * (1 + 1e-6)
    result, _ = check(model, problem.path, plan, problem.h_sub)
    assert result.passed


def test_mpc_commands_continue_the_acceleration_and_the_brake_ramps(params):
    model = Model(params, "dfs-yaw")
    mpc = MPC(model, MPCOptions(horizon=1.0))
    preview = profiles.dfs_catapult(duration=2.0)
    a = np.array([0.3])
    command = mpc.step((np.zeros(1), np.array([1.0]), a), preview)
    assert command.source == "mpc"
    assert command.sequence[0, 0] == pytest.approx(a[0])  # starts where the machine's acceleration is
    assert abs(command.jerks[0, 0]) <= model.limits.jerk[0] * (1 + 1e-9)
    qdd, jerk = mpc.brake(np.zeros(1), np.array([2.0]), np.array([0.5]))
    assert qdd[0] == 0.5 and jerk[0] == pytest.approx(-model.limits.jerk[0])  # turns towards braking at the limit


def test_mpc_grid_is_fine_near_now_and_coarse_beyond():
    grid = MPCOptions(horizon=2.0, step=0.02, tail_step=0.1, fine=0.4).grid()
    assert grid.sum() == pytest.approx(2.0)
    assert np.all(grid[:20] == 0.02) and np.allclose(grid[20:], 0.1) and len(grid) == 36
    assert np.all(MPCOptions(horizon=2.0, step=0.02, tail_step=None).grid() == 0.02)
    # a tail that doubles beyond 2 s: 0.1 s to 2 s, 0.2 s beyond (46 intervals in 4 s, not 56)
    grid = MPCOptions(horizon=4.0, step=0.02, far=2.0).grid()
    t = np.cumsum(grid) - grid
    assert grid.sum() == pytest.approx(4.0) and len(grid) == 46
    assert np.allclose(grid[(t >= 0.4 - 1e-9) & (t < 2.0 - 1e-9)], 0.1) and np.allclose(grid[t >= 2.0 - 1e-9], 0.2)
    assert MPCOptions(horizon=3.3, step=0.02, far=2.0).grid().sum() == pytest.approx(3.3)  # the last one shorter
    assert len(MPCOptions(horizon=4.0, step=0.02, far=None).grid()) == 56
    assert len(MPCOptions(horizon=4.0, step=0.02).grid()) == 56  # "auto" before a controller resolves it
    with pytest.raises(ValueError, match="far"):
        MPCOptions(far=-1.0)
    # at 100 Hz: the steps of the cycle and one more, then 0.02 s to 0.4 s (37 intervals in 2 s, not 56)
    grid = MPCOptions(horizon=2.0, step=0.01).grid()
    assert len(grid) == 37 and grid.sum() == pytest.approx(2.0)
    assert np.all(grid[:2] == 0.01) and np.allclose(grid[2:21], 0.02) and np.allclose(grid[21:], 0.1)
    assert len(MPCOptions(horizon=2.0, step=0.01, fine_step=None).grid()) == 56
    assert np.allclose(MPCOptions(horizon=2.0, step=0.01, replan=0.04).grid()[:7], [0.01] * 5 + [0.02] * 2)


def test_the_tail_doubles_where_the_cabin_tilts(params):
    """``far`` "auto": the controller's 4 s plans on full have the doubled tail, those on
    yaw-track-cabin (whose damped iteration swung a steady turn's yaw with it) do not."""
    from desdemona.control.mpc import FAR, MPC

    full = MPC(Model(params, "full"), MPCOptions(horizon=4.0))
    assert full.options.far == FAR and full.problem.N == 46
    assert MPC(Model(params, "yaw-track-cabin"), MPCOptions(horizon=4.0)).problem.N == 56
    assert MPC(Model(params, "full"), MPCOptions(horizon=4.0, far=None)).problem.N == 56


def test_ramp_matches_its_recursion_for_several_joints_and_steps():
    """Each interval starts where the last ended and moves towards its target at most at the jerk
    limit: the recursion written out in NumPy, on random targets, mixed steps and an unlimited joint."""
    rng = np.random.default_rng(3)
    targets, h = rng.normal(size=(30, 3)), np.r_[np.full(10, 0.02), np.full(20, 0.1)]
    a0, limit = rng.normal(size=3), np.array([5.0, 0.5, np.inf])
    starts, jerks = ramp(targets, h[:, None], a0, limit)
    a = a0.copy()
    for k in range(len(targets)):
        np.testing.assert_array_equal(starts[k], a)
        np.testing.assert_array_equal(jerks[k], np.clip((targets[k] - a) / h[k], -limit, limit))
        a = a + jerks[k] * h[k]
    assert np.all(np.abs(jerks[:, 1]) <= 0.5) and np.any(np.abs(jerks[:, 1]) == 0.5)
    starts, _ = ramp(targets, 0.1)  # no a0: the first target at once; no limit: every target reached
    np.testing.assert_allclose(starts[1:], targets[:-1], atol=1e-12)


def test_the_shifted_plan_is_the_last_plans_acceleration_where_the_new_intervals_end(params):
    """The seed of the next cycle (``MPC._shifted_plan``) reads the last plan's accelerations as
    :meth:`Plan.at` does, at the ends of the new grid's intervals, held past its end."""
    from desdemona.control.mpc import MPC, MPCOptions

    controller = MPC(Model(params, "dfs"), MPCOptions(horizon=2.0))
    prob, step = controller.problem, controller.options.step
    rng = np.random.default_rng(4)
    length = int(round(prob.t_nodes[-1] / step))
    u, jerk = ramp(rng.normal(size=(length, 4)), step, np.zeros(4), controller.limits.jerk)
    for age in (0, 1, 7):
        controller.plan, controller.plan_age = (u, jerk), age
        times = np.minimum((age + 1) * step + prob.t_nodes[1:], prob.t_nodes[-1])
        expected = Plan(np.arange(length + 1) * step, np.zeros(4), np.zeros(4), u, jerk).at(times)[2]
        lim = controller.limits.acceleration
        np.testing.assert_array_equal(controller._shifted_plan(prob), np.clip(expected, -lim, lim))


def test_a_rate_backs_off_by_the_bulge_of_its_own_intervals(params):
    """Between nodes a rate is a parabola that may bulge j_max h^2 / 8 past both ends: each node keeps
    that much of the intervals beside it inside the limit, so the fine first steps of an on-line plan
    may come nearer the limit than its coarse tail. An arm held at its rate limit for a force beyond
    the machine stays there, not a tail's bulge (0.0039 rad/s, 0.15 %) below it."""
    model = Model(params, "dfs-yaw")
    mpc = MPC(model, MPCOptions(horizon=2.0, step=0.02, tail_step=0.1, fine=0.4))
    prob, v, j = mpc.problem, model.limits.velocity[0], model.limits.jerk[0]
    h = np.asarray(prob.steps)
    assert h.min() == pytest.approx(0.02) and h.max() == pytest.approx(0.1)
    nw = prob.nx + prob.nu
    rates = prob.ubx[nw + 1:prob.N * nw:nw]  # the rate at nodes 1 .. N - 1 (node 0 is the start)
    np.testing.assert_allclose(rates, v - j * np.maximum(h[:-1], h[1:])**2 / 8)
    assert rates[0] == pytest.approx(v - j * 0.02**2 / 8) and rates[-1] == pytest.approx(v - j * 0.1**2 / 8)
    # far above what the arm can hold, from just under its rate limit: the plan holds the rate
    preview = profiles.dfs_catapult(base=5.0 * 9.81, pulse=0.0, duration=3.0)
    qd0 = v - 0.001
    command = mpc.step((np.zeros(1), np.array([qd0]), np.zeros(1)), preview)
    assert command.source == "mpc"
    qd = qd0 + np.cumsum(command.sequence[:, 0]) * 0.02
    assert qd.min() >= qd0 - 1e-6 and qd.max() <= v - j * 0.02**2 / 8 + 1e-9


def test_a_position_backs_off_by_the_bulge_of_its_own_intervals(params):
    """The same for positions, qdd_max h_sub^2 / 8: on ``full`` the 4 s plan's tail has 0.2 s intervals,
    whose bulge kept the heave 25 mm inside its 1 m travel, also over the fine steps a cycle runs;
    the stopping rows back off as the node they start from."""
    model = Model(params, "full")
    prob = MPC(model, MPCOptions(horizon=4.0)).problem
    h, a, nw = np.asarray(prob.steps), model.limits.acceleration, prob.nx + prob.nu
    assert prob.m == 1 and h.min() == pytest.approx(0.02) and h.max() == pytest.approx(0.2)
    heave = prob.ubx[nw + 2:prob.N * nw:nw]  # the heave at nodes 1 .. N - 1
    np.testing.assert_allclose(heave, 1.0 - a[2] * np.maximum(h[:-1], h[1:])**2 / 8)
    assert heave[0] == pytest.approx(1.0 - a[2] * 0.02**2 / 8) and heave[-1] == pytest.approx(1.0 - a[2] * 0.2**2 / 8)
    # the stopping rows (track, heave) of the first and last stage, by the node after each
    rows = [i for i, f in enumerate(prob.families) if f.name == "stopping"]
    assert len(rows) == 1 and prob.families[0].name != "position"  # one sub-step: no inner points
    offset = sum(f.lower.size for f in prob.families[:rows[0]])
    stride = prob.nx + sum(f.lower.size for f in prob.families)
    first = prob.ubg[prob.nx + prob.n_initial + offset:][:2]
    last = prob.ubg[prob.n_initial + (prob.N - 1) * stride + prob.nx + offset:][:2]
    np.testing.assert_allclose(first, [4.0, 1.0] - a[1:3] * 0.02**2 / 8)
    np.testing.assert_allclose(last, [4.0, 1.0] - a[1:3] * 0.2**2 / 8)
    # a start the fine nodes reach leaves the bounds as they are (no widening a cycle); one beyond them
    # widens the first nodes out to it
    q0 = np.zeros(6)
    q0[1] = 3.99
    assert prob.bounds_from(q0)[1] is prob.ubx
    q0[1] = 4.0
    ubx = prob.bounds_from(q0)[1]
    assert ubx is not prob.ubx and ubx[nw + 1] == 4.0 and ubx[(prob.N - 1) * nw + 1] == prob.ubx[(prob.N - 1) * nw + 1]


def test_braking_near_the_end_of_a_joints_travel_stops_within_it(params):
    """The brake's approach to rest, proportional to the rate, covers about qd T; near the end of a
    joint's travel (the heave on ``full`` 28 mm from its end at 0.13 m/s, where a run that missed its
    deadlines for seconds was left braking) the joint stops as quickly as its limits allow instead,
    within its travel and without turning back."""
    model = Model(params, "full")
    mpc = MPC(model, MPCOptions(horizon=4.0))
    h, lim = mpc.options.step, model.limits
    q, qd, a = np.array([0, 0, 0.9715, 0, 0, 0.0]), np.array([0, 0, 0.133, 0, 0, 0.0]), np.zeros(6)
    heave = []
    for _ in range(100):
        qdd, jerk = mpc.brake(q, qd, a)
        assert np.all(np.abs(jerk) <= lim.jerk * (1 + 1e-9)) and np.all(np.abs(qdd) <= lim.acceleration * (1 + 1e-9))
        q, qd, a = q + qd * h + qdd * h**2 / 2 + jerk * h**3 / 6, qd + qdd * h + jerk * h**2 / 2, qdd + jerk * h
        heave.append(q[2])
    assert max(heave) <= lim.position_max[2] and abs(qd[2]) < 1e-6
    assert heave[-1] >= max(heave) - 1e-3  # at rest where it stopped, not turned back (0.16 mm)


def test_the_quickest_stops_jerk_is_the_strongest_that_does_not_pass_rest():
    """stopping_jerk's closed form, on random states from rest-like to fast: where neither limit
    binds, its jerk leaves the rate along the motion, once the acceleration is ramped to zero at J,
    at or above zero, and a jerk stronger by 1e-9 J leaves it below (the root, from above); it never
    leaves [-J, J] nor takes the acceleration past A."""
    rng = np.random.default_rng(7)
    A, J, h = np.array([0.8, 5.0, 5.0, 1.5, 1.5, 1.5]), np.array([1.0, 10.0, 10.0, 3.0, 3.0, 3.0]), 0.02
    inner = 0
    for scale in (1e-6, 1e-2, 1.0, 3.0):
        for _ in range(400):
            qd, a = rng.normal(size=6) * scale, rng.uniform(-1, 1, 6) * np.minimum(A, J * h * rng.choice([0.3, 3, 30]))
            k = stopping_jerk(qd, a, h, A, J)
            s = np.where(qd != 0.0, np.sign(qd), -np.sign(a))
            u, b, kk = s * qd, s * a, s * k
            left = settled_rate(u + b * h + 0.5 * kk * h * h, b + kk * h, J)
            stronger = kk - 1e-9 * J
            below = settled_rate(u + b * h + 0.5 * stronger * h * h, b + stronger * h, J)
            free = (np.abs(kk) < J) & (kk > (-A - b) / h + 1e-9 * J)
            inner += int(free.sum())
            assert np.all(left[free] >= 0.0) and np.all(below[free] < 0.0)
            assert np.all(np.abs(k) <= J) and np.all(b + kk * h >= -A * (1 + 1e-12))
    assert inner > 1000  # states braked by the root, not by a limit


def _braked(mpc, q, qd, a, steps):
    """The states of ``steps`` cycles of the controller's brake from (q, qd, a)."""
    state = State(q, qd, a)
    for _ in range(steps):
        qdd, jerk = mpc.brake(state.q, state.qd, state.a)
        state = state.advance(qdd, mpc.options.step, jerk)
        yield state


def test_the_stopping_reach_bounds_the_brake_from_both_sides(params):
    """From every state of a grid of rates and accelerations (both signs, motions the brake turns
    over included), placed so that stopping_extent (at the limits, with the brake's lag) ends
    exactly at the track's end, the brake of MPC stops the track within its travel: the bound the
    controller's check relies on. Where the acceleration is along the motion the bound is tight
    (within 8 cm of where the ordinary brake, which stops more gently, ends in the open)."""
    model = Model(params, "full")
    mpc = MPC(model, MPCOptions(horizon=4.0))
    lim, h = model.limits, mpc.options.step
    A, J, top = lim.acceleration[1], lim.jerk[1], lim.position_max[1]
    for qd0 in np.linspace(-3.0, 3.0, 13):
        for a0 in np.linspace(-A, A, 11):
            low, high = stopping_extent(0.0, qd0, a0, A, J, h)
            q, qd, a = np.zeros(6), np.zeros(6), np.zeros(6)
            up = qd0 + a0 * abs(a0) / (2 * J) >= 0
            q[1], qd[1], a[1] = top - max(high, 0.0) if up else -top - min(low, 0.0), qd0, a0
            states = list(_braked(mpc, q, qd, a, 300))
            extremes = [q[1]] + [s.q[1] for s in states]
            assert -top <= min(extremes) and max(extremes) <= top, (qd0, a0, min(extremes), max(extremes))
            assert abs(states[-1].qd[1]) < 1e-6
    braking = 0.5 * A  # the plans' braking: the ordinary brake, away from the ends, goes a little further
    *_, rest = _braked(mpc, np.zeros(6), np.r_[0, 2.0, 0, 0, 0, 0], np.r_[0, 2.0, 0, 0, 0, 0], 300)
    assert 0.0 < rest.q[1] - float(stopping_reach(2.0, 2.0, braking, J)) < 0.08


def test_a_state_the_controller_accepts_can_brake_to_rest_within_the_travel(params):
    """The invariant behind the fallback: a command sequence is accepted only if the state it leaves
    is stoppable (MPC._safe_sequence), and from every such state the brake stops the joint within its
    travel. Checked on a grid of heave states on ``full`` near the top of its travel, moving up, the
    acceleration either way; the state of a one-QP plan that came late on the 747 take-off (heave at
    0.94 m, 0.56 m/s up, accelerating) is refused."""
    model = Model(params, "full")
    mpc = MPC(model, MPCOptions(horizon=4.0))
    lim = model.limits
    zero = np.zeros(6)

    def at(q, qd, a):
        return (np.array([0, 0, q, 0, 0, 0.0]), np.array([0, 0, qd, 0, 0, 0.0]), np.array([0, 0, a, 0, 0, 0.0]))

    assert not mpc._safe_sequence(State(*at(0.9398, 0.5622, 0.214)), [], [])
    accepted = 0
    for q0 in (0.5, 0.7, 0.85, 0.95):
        for qd0 in (0.2, 0.6, 1.0, 1.6, 2.2):
            for a0 in (-4.0, -1.0, 0.0, 2.0, 4.5):
                if not mpc._safe_sequence(State(*at(q0, qd0, a0)), [], []):
                    continue
                accepted += 1
                for s in _braked(mpc, *at(q0, qd0, a0), 150):
                    assert lim.position_min[2] <= s.q[2] <= lim.position_max[2], (q0, qd0, a0, s.q[2])
                assert abs(s.qd[2]) < 1e-3 and np.allclose(s.q[[0, 1, 3, 4, 5]], zero[:5])
    assert 30 <= accepted < 100  # states refused too: the grid reaches past what can stop


def test_a_state_the_controller_accepts_can_brake_within_the_velocity_limits(params):
    """The rate rises by a |a| / 2J while the brake's ramp takes the acceleration to zero: a state
    whose rate is near its limit and still rising is refused (MPC._safe_sequence), and from every
    state accepted on a grid near the track's velocity limit the brake keeps it (the stress run of
    the 747 take-off with 2.5 ms deadlines was refused once for the track at 1.015x its velocity)."""
    model = Model(params, "full")
    mpc = MPC(model, MPCOptions(horizon=4.0))
    lim = model.limits
    vmax, J = lim.velocity[1], lim.jerk[1]
    accepted = 0
    for qd0 in vmax - np.array([0.01, 0.05, 0.2]):
        for a0 in (-2.0, 0.0, 0.5, 1.0, 2.0, 4.0):
            q, qd, a = np.zeros(6), np.r_[0, qd0, 0, 0, 0, 0], np.r_[0, a0, 0, 0, 0, 0]
            if not mpc._safe_sequence(State(q, qd, a), [], []):
                assert qd0 + a0 * abs(a0) / (2 * J) > vmax
                continue
            accepted += 1
            for s in _braked(mpc, q, qd, a, 100):
                assert abs(s.qd[1]) <= vmax * (1 + 1e-6), (qd0, a0, s.qd[1])
    assert 6 <= accepted < 18


def test_the_off_line_rate_rows_are_convex_and_keep_the_same_states():
    """settled_rates: within the velocity limits its two rows keep exactly the states that
    |settled_rate| <= V keeps, never fewer by more than the smoothing; the highest is convex and the
    lowest concave in (qd, a), where qd + a |a| / 2J is concave for a < 0."""
    import casadi as ca
    J, V = 3.0, 1.0
    rng = np.random.default_rng(1)
    qd, a = rng.uniform(-V, V, 200_000), rng.uniform(-4.0, 4.0, 200_000)
    highest, lowest = settled_rates(qd, a, J)
    assert np.array_equal((highest <= V) & (lowest >= -V), np.abs(settled_rate(qd, a, J)) <= V)
    assert np.all(highest >= settled_rate(qd, a, J) - 1e-15) and np.all(lowest <= settled_rate(qd, a, J) + 1e-15)
    x = ca.SX.sym("x", 2)
    rows = settled_rates(x[0], x[1], J)
    curvature = ca.Function("c", [x], [ca.hessian(rows[0], x)[0], ca.hessian(rows[1], x)[0]])
    old = ca.Function("o", [x], [ca.hessian(settled_rate(x[0], x[1], J, eps=1e-8), x)[0]])
    for point in ([0.9, -2.0], [0.9, -1e-5], [0.9, 0.0], [0.9, 1e-5], [-0.9, 2.0], [0.0, 3.0]):
        up, down = (np.linalg.eigvalsh(np.array(h)) for h in curvature(point))
        assert up.min() >= -1e-12 and down.max() <= 1e-12, point
    assert np.linalg.eigvalsh(np.array(old([0.9, -2.0]))).min() < -0.1  # what the rows replace


@pytest.mark.parametrize("method", ["rti", "nlp"])
def test_a_start_just_beyond_the_stopping_rows_is_planned_from(params, method):
    """A one-QP plan keeps its stopping rows to first order and can leave a state whose own stop (at
    the plans' braking) lies a fraction of a millimetre beyond them; along the strongest ramp a stop's
    reach stays where it is, so no plan kept the rows from there and the controller fell back (the
    catapult on `full`, 6 cycles running). The rows now reach out to such a start until its
    acceleration can have passed the braking: the track at 2.6 m/s, accelerating at 4.5 m/s^2 towards
    its end, 0.2 mm and 1 mm beyond, is planned from and the plan passes the check."""
    model = Model(params, "full")
    lim = model.limits
    t = np.arange(0.0, 2.05, 0.05)
    values = np.tile([0.0, 0.0, 0.0, 0.0, 0.0, 9.81], (len(t), 1))
    for excess in (2e-4, 1e-3):
        mpc = MPC(model, MPCOptions(horizon=2.0, step=0.05, method=method, deadline=float("inf")))
        bound = mpc.problem._node_positions[1][1][1]  # the first stopping row's upper bound on the track
        q, qd, a = np.zeros(6), np.r_[0, 2.6, 0, 0, 0, 0], np.r_[0, 4.5, 0, 0, 0, 0]
        lag = mpc.problem._stop_lag(slice(None))  # the brake's lag the rows carry
        q[1] = bound + excess - stopping_reach(qd, a, mpc.options.braking * lim.acceleration, lim.jerk, lag=lag)[1]
        command = mpc.step((q, qd, a), (t, values))
        assert (command.source, command.reason) == ("mpc", ""), excess


def test_the_plans_stopping_rows_are_never_short_of_the_controllers_check(params):
    """The rows a plan keeps on-line (the reach at the plans' braking, with the brake's lag) reach at
    least as far as the check the controller holds a plan to (the reach at the limits, with the lag,
    :func:`stopping_extent`): a plan that keeps its rows is not refused for its stop (the catapult on
    `full` fell back once, a heave state 1.6 mm inside its row but 3 mm past the check). Zero at rest,
    so that a joint at rest at its end can be planned from."""
    lim = Model(params, "full").limits
    A, J, h = lim.acceleration[2], lim.jerk[2], 0.05
    lag = STOP_LAG * A * h * h
    for qd in np.linspace(-3.0, 3.0, 25):
        for a in np.linspace(-A, A, 21):
            row = float(stopping_reach(qd, a, 0.5 * A, J, lag=lag))
            vector = np.zeros(6)
            _, high = stopping_extent(np.zeros(6), vector + qd, vector + a, lim.acceleration, lim.jerk, h)
            # moving away, the reach is negative and the node's own position bound is what binds
            assert max(row, 0.0) >= high[2] - 1e-4, (qd, a, row, high[2])  # the smoothing's 0.05 mm aside
    assert abs(float(stopping_reach(0.0, 0.0, 0.5 * A, J, lag=lag))) < 1e-9

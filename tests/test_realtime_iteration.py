"""The real-time iteration's preparation and feedback (desdemona.cueing.realtime_iteration): the QP
linearised before the preview is known, then fed the preview, takes the step the one-shot QP takes."""

import copy

import numpy as np
import pytest

from desdemona import Model
from desdemona.control.mpc import MPC, MPCOptions
from desdemona.machine.plan import State
from desdemona.occupant.perception import canals_model

T = np.linspace(0.0, 1.0, 11)


def _preview(config, k: int, drift: float = 1.0):
    """A changing desired path, a new one each cycle (``drift``: how fast it changes): the modulus on
    dfs, S with the cabin's force and a roll rate elsewhere."""
    if config.takes_modulus:
        return T, 9.81 * (1.3 + 0.5 * np.sin(0.7 * T + 0.3 * drift * k))
    values = np.zeros((len(T), 6))
    values[:, 5] = 9.81 + np.cos(T + 0.2 * drift * k)
    values[:, 3] = 2.0 * np.sin(0.5 * T + 0.2 * drift * k)
    values[:, 0] = 0.1 * np.sin(T - 0.1 * drift * k)
    return T, values


@pytest.mark.parametrize(("config", "perception", "band", "drift"),
                         [("dfs", None, None, 1.0), ("yaw-track-cabin", canals_model(), None, 1.0),
                          ("yaw-track-cabin", canals_model(), 0.5, 0.05), ("yaw-track-cabin", canals_model(), 0.5, 1.0)])
def test_the_prepared_then_fed_qp_takes_the_one_shot_step(config, perception, band, drift, monkeypatch):
    """Cycle after cycle, the controller prepared between cycles (MPC.prepare) and then stepped on a
    new preview poses the QP the same controller poses in one shot from the same state and preview
    (every array HPIPM is given, to 1e-12 of its scale), and takes the same step: the cycle's command
    to 1e-9 (relative), the whole plan to 1e-8 (the interior-point solver's iterates carry the gradient's last
    bits into the plan's ninth digit), on the modulus of dfs and on S with the felt filters carried
    (canals), with the felt rotation's band too (its dead zone: residuals affine in the preview piece
    by piece, a preview that crosses a piece's edge evaluated afresh)."""
    model = Model(config=config)
    mpc = MPC(model, MPCOptions(horizon=1.0, step=0.05, perception=perception, rotation_band=band))
    assert mpc._rti.splits
    fed = []
    feedback = mpc._rti.feedback
    monkeypatch.setattr(mpc._rti, "feedback", lambda *a: fed.append(1) or feedback(*a))
    state = State(np.zeros(model.n), np.zeros(model.n), np.zeros(model.n))
    command = mpc.step(state, _preview(model.config, 0, drift))
    for k in range(1, 8):
        state = state.advance(command.sequence[0], 0.05, command.jerks[0])
        one_shot = copy.copy(mpc)  # the same controller, stepped without preparing
        expected = one_shot.step(state, _preview(model.config, k, drift))
        posed = {name: array.copy() for name, array in mpc._rti._qp_in.items()}
        mpc.prepare(state)
        assert mpc._rti.ready
        command = mpc.step(state, _preview(model.config, k, drift))
        for name, array in mpc._rti._qp_in.items():
            scale = float(np.max(np.abs(np.nan_to_num(posed[name], posinf=0.0, neginf=0.0)), initial=1.0))
            np.testing.assert_allclose(array, posed[name], rtol=0, atol=1e-12 * scale, err_msg=name)
        assert command.source == expected.source == "mpc"
        np.testing.assert_allclose(command.sequence, expected.sequence, rtol=1e-9, atol=1e-9)
        np.testing.assert_allclose(command.jerks, expected.jerks, rtol=1e-9, atol=1e-9)
        np.testing.assert_allclose(mpc.plan[0], one_shot.plan[0], rtol=0, atol=1e-8)
        np.testing.assert_allclose(mpc.plan[1], one_shot.plan[1], rtol=0, atol=1e-8)
    assert len(fed) == 7 and mpc._rti.splits  # every later cycle was fed, none linearised afresh
    if band is not None:  # a slow preview stays on its pieces; a fast one crosses the band's edges
        assert (mpc._rti.refreshed <= 2) if drift < 1.0 else (mpc._rti.refreshed >= 1)
    else:
        assert mpc._rti.refreshed == 0


def test_a_step_from_another_state_than_the_prepared_one_linearises_afresh():
    """A state that is not the one prepared for (the machine re-anchored, or moved by a park) is
    not fed into the prepared QP: the step is the one-shot one."""
    model = Model(config="dfs")
    mpc = MPC(model, MPCOptions(horizon=1.0, step=0.05))
    state = State(np.zeros(model.n), np.zeros(model.n), np.zeros(model.n))
    command = mpc.step(state, _preview(model.config, 0))
    state = state.advance(command.sequence[0], 0.05, command.jerks[0])
    mpc.prepare(state)
    moved = State(state.q + 1e-3, state.qd, state.a)
    one_shot = copy.copy(mpc)
    one_shot._prepared = None
    expected = one_shot.step(moved, _preview(model.config, 1))
    mpc.prepare(state)
    command = mpc.step(moved, _preview(model.config, 1))
    np.testing.assert_array_equal(command.sequence, expected.sequence)


@pytest.mark.parametrize("config", ["dfs", "yaw-track-cabin"])
def test_a_cycle_with_nothing_new_follows_the_plan_and_the_next_is_still_fed(config):
    """A cycle with no new preview (a host slower than the service) takes the last plan's next step
    without a QP (MPC.follow), carries the felt and the desired filter states over it (the desired one
    along the last preview: a constant preview's state after the two steps, as the perception model
    gives it), and the cycle after it, prepared from where that step leaves the machine, is fed into
    the prepared QP and takes the one-shot step. Nothing to follow: None."""
    model = Model(config=config)
    perception = None if model.config.takes_modulus else canals_model()
    mpc = MPC(model, MPCOptions(horizon=1.0, step=0.05, perception=perception))
    state = State(np.zeros(model.n), np.zeros(model.n), np.zeros(model.n))
    assert mpc.follow(state) is None  # no plan yet
    t, values = _preview(model.config, 0)
    constant = (t, np.repeat(values[5:6], len(t), axis=0))  # after a changing one: the filters move
    for preview in (_preview(model.config, 0), constant):
        command = mpc.step(state, preview)
        state = state.advance(command.sequence[0], 0.05, command.jerks[0])
    plan = copy.deepcopy(mpc.plan)
    followed = mpc.follow(state)
    assert (followed.source, followed.reason) == ("shifted", "nothing new since the last plan")
    np.testing.assert_array_equal(followed.sequence, plan[0][1:2])
    np.testing.assert_array_equal(followed.jerks, plan[1][1:2])
    if mpc.problem.nz:
        prob = mpc.problem
        z = mpc._z_d_path[0]  # the desired filter's state as the step began, over its two steps' sub-steps
        for _ in range(2 * prob.m):
            z = prob.filter.Ad @ z + prob.filter.Bd @ constant[1][0]
        np.testing.assert_allclose(mpc.z_d, z, rtol=1e-9, atol=1e-12)
        assert not np.allclose(mpc.z_d, mpc._z_d_path[0])
    state = state.advance(followed.sequence[0], 0.05, followed.jerks[0])
    mpc.prepare(state)
    assert mpc._rti.ready
    one_shot = copy.copy(mpc)
    one_shot._prepared = None  # linearised afresh
    expected = one_shot.step(state, _preview(model.config, 2))
    command = mpc.step(state, _preview(model.config, 2))
    assert command.source == expected.source == "mpc"
    np.testing.assert_allclose(command.sequence, expected.sequence, rtol=1e-9, atol=1e-9)
    state = state.advance(command.sequence[0], 0.05, command.jerks[0])
    # the plan runs out (where the desired filter is carried: its part of equal steps): nothing to follow
    last = len(mpc.plan[0]) if not mpc.problem.nz else min(len(mpc.plan[0]), int(np.argmin(np.r_[mpc._counts, 0] == 1)))
    for _ in range(len(mpc.plan[0])):
        if (followed := mpc.follow(state)) is None:
            break
        state = state.advance(followed.sequence[0], 0.05, followed.jerks[0])
    assert followed is None and mpc.plan_age + 2 > last

"""A session's choices resolved once (desdemona.runs.session): the same problem whichever command asks."""

import argparse
import dataclasses

import numpy as np
import pytest

from desdemona import Model, profiles
from desdemona.cli.options import build_parser
from desdemona.cueing import windows
from desdemona.cueing.formulation import WALL, ProblemOptions
from desdemona.occupant.perception import canals_model
from desdemona.runs import session
from desdemona.runs.session import ChoiceError, Choices


@pytest.fixture(scope="module")
def catapult():
    return profiles.get_profile("catapult")


def test_weights_default_to_the_configuration_s_and_reach_the_problem(catapult):
    model = Model(config="yaw-track-cabin")
    resolved = session.offline(catapult, model)
    np.testing.assert_array_equal(resolved.options.weights, profiles.weights_for("felt", catapult))
    dfs = Model(config="dfs")
    dfs_catapult = profiles.get_profile("dfs-catapult")
    on_dfs = session.offline(dfs_catapult, dfs)
    np.testing.assert_array_equal(on_dfs.options.weights, on_dfs.path.weights)  # "path" on an aligned machine
    online = session.online(dfs_catapult, dfs)
    assert online.options.mpc.weights == on_dfs.options.weights  # one rule off-line and on-line


def test_batch_and_optimize_resolve_the_same_problem(catapult):
    """batch's jobs and optimize call the same function: the same ProblemOptions for the same choices."""
    model = Model(config="full")
    choices = Choices(weights="thresholds", gain=0.5, final="rest", h_u=0.1)
    a, b = session.offline(catapult, model, choices), session.offline(catapult, model, choices)
    assert a.options == b.options and a.options.weights == tuple(profiles.weights_for("thresholds", a.path))
    np.testing.assert_allclose(a.path.S_d[:, :3], 0.5 * catapult.S_d[:, :3])


def test_a_given_state_implies_initial_given_everywhere(catapult):
    model = Model(config="yaw-track-cabin")
    text = "0,-1.5,0;0,0,0"
    off = session.offline(catapult, model, Choices(initial_state=text))
    on = session.online(catapult, model, Choices(initial_state=text))
    assert off.options.initial == on.options.initial == "given"
    np.testing.assert_array_equal(off.options.initial_state[0], on.options.initial_state[0])
    with pytest.raises(ChoiceError, match="goes with --initial given"):
        session.offline(catapult, model, Choices(initial="rest", initial_state=text))
    with pytest.raises(ChoiceError, match="track position 9 is outside"):
        session.online(catapult, model, Choices(initial_state="0,9,0;0,0,0"))
    with pytest.raises(ChoiceError, match="--initial home: one of rest, free, given"):
        session.offline(catapult, model, Choices(initial="home"))


def test_online_timing_defaults_live_in_the_session(catapult):
    """The horizon and reach the command line uses: the configuration's default horizon, reaching at
    least that far whatever horizon is asked for."""
    model = Model(config="yaw-track-cabin")
    mpc = session.online(catapult, model).options.mpc
    assert (mpc.horizon, mpc.reach) == (4.0, 4.0)
    short = session.online(catapult, model, horizon=1.0).options.mpc
    assert (short.horizon, short.reach) == (1.0, 4.0)
    assert session.online(catapult, model, tail_step=0.0).options.mpc.tail_step is None
    for kwargs, message in (({"reach": 0.5, "horizon": 1.0}, "--reach 0.5"), ({"deadline": 0.0}, "--deadline 0"),
                            ({"replan": 0.03}, "--replan"), ({"predictor": "route"}, "needs --reference")):
        with pytest.raises(ChoiceError, match=message):
            session.online(catapult, model, **kwargs)


def test_bad_choices_name_themselves(catapult):
    model = Model(config="yaw-track-cabin")
    for choices, message in ((Choices(h_u=1e-4), "--h-u 0.0001"), (Choices(h_u=100.0), "at most the path's"),
                             (Choices(weights="heavy"), "give one of felt"), (Choices(gain=-1.0), "gain -1")):
        with pytest.raises(ValueError, match=message):
            session.offline(catapult, model, choices)
    with pytest.raises(ValueError, match="gives only the modulus"):
        session.offline(profiles.get_profile("dfs-catapult"), model)
    with pytest.raises(ChoiceError, match="--method thesis reproduces the thesis"):
        session.thesis(catapult, model, Choices(weights="path"))


@pytest.mark.parametrize("command", ["optimize", "batch", "online"])
def test_every_command_hands_its_choices_over_by_name(command):
    """The commands do not resolve choices themselves: each builds Choices from its arguments by the
    fields' names, so a choice added to Choices and to the shared options reaches all three."""
    argv = {"optimize": ["optimize", "catapult", "--out", "x"],
            "batch": ["batch", "catapult", "--configs", "full", "--out", "x"],
            "online": ["online", "catapult", "--out", "x"]}[command]
    args = build_parser().parse_args([*argv, "--weights", "thresholds", "--gain", "0.7"])
    assert Choices.of(args) == Choices(weights="thresholds", gain=0.7)
    assert Choices.of(argparse.Namespace()) == Choices()


def test_a_jerk_weight_reaches_the_problem_off_line_and_on_line(catapult):
    model = Model(config="yaw-track-cabin")
    assert session.offline(catapult, model, Choices(jerk_weight=0.5)).options.jerk_weight == 0.5
    assert session.online(catapult, model, Choices(jerk_weight=0.5)).options.mpc.jerk_weight == 0.5
    assert session.offline(catapult, model).options.jerk_weight is None  # the configuration's default
    with pytest.raises(ChoiceError, match="--jerk-weight -1"):
        session.offline(catapult, model, Choices(jerk_weight=-1.0))
    args = build_parser().parse_args(["batch", "catapult", "--configs", "full", "--out", "x", "--jerk-weight", "2"])
    assert Choices.of(args).jerk_weight == 2.0


def test_the_wall_reaches_the_off_and_on_line_problems_and_is_checked(catapult):
    from desdemona.control.mpc import MPC, MPCOptions

    model = Model(config="yaw-track-cabin")
    assert session.offline(catapult, model, Choices(wall=0.0)).options.wall == 0.0
    assert session.offline(catapult, model).options.wall == WALL
    assert ProblemOptions().wall == 0.0 and MPCOptions().wall == 0.0  # the thesis' formulation
    online = session.online(catapult, model).options.mpc
    assert online.wall == WALL and session.online(catapult, model, Choices(wall=0.0)).options.mpc.wall == 0.0
    assert MPC(model, dataclasses.replace(online, horizon=1.0, reach=1.0)).problem.options.wall == WALL
    for bad in (-1.0, float("nan")):
        for resolve in (session.offline, session.online):
            with pytest.raises(ChoiceError, match="--wall"):
                resolve(catapult, model, Choices(wall=bad))
    for command in (["optimize", "catapult", "--out", "x"], ["batch", "catapult", "--configs", "full", "--out", "x"],
                    ["online", "catapult", "--out", "x"],
                    ["serve", "--listen", "127.0.0.1:9000", "--send", "127.0.0.1:9001", "--out", "x"]):
        assert Choices.of(build_parser().parse_args([*command, "--wall", "0"])).wall == 0.0
    with pytest.raises(ChoiceError, match="drop --wall"):
        session.thesis(catapult, model, Choices(wall=1.0))


def test_the_offline_solver_is_fatrop_on_full_up_to_its_length(catapult):
    """auto: fatrop on yaw-track-cabin, full and dfs (three joints or more) for a solve of at most FATROP_UP_TO
    intervals, a longer path there in windows unless the user asks otherwise; IPOPT elsewhere; an
    asked solver is kept."""
    full, ytc, two = Model(config="full"), Model(config="yaw-track-cabin"), Model(config="yaw-track")
    assert session.offline(catapult, full).options.solver == "fatrop"
    assert session.offline(catapult, ytc).options.solver == "fatrop"
    assert session.offline(catapult, two).options.solver == "ipopt"
    assert session.offline(profiles.get_profile("dfs-catapult"), Model(config="dfs")).options.solver == "fatrop"
    assert session.offline(profiles.get_profile("dfs-catapult"), Model(config="dfs-yaw")).options.solver == "ipopt"
    assert session.offline(catapult, full, solver="ipopt").options.solver == "ipopt"
    step = Choices().h_u
    longer = profiles.cosine(amplitude=3.0, omega=0.4, duration=(session.FATROP_UP_TO + 20) * step, dt=0.05)
    windowed = session.offline(longer, full)  # fatrop in windows, not IPOPT on the whole
    assert windowed.options.solver == "fatrop" and windowed.window == windows.DEFAULT_WINDOW
    assert session.offline(longer, full, Choices(window=0)).options.solver == "ipopt"
    assert session.offline(longer, full, solver="ipopt").window is None
    assert session.offline(longer, ytc).window == windows.DEFAULT_WINDOW
    assert session.offline(longer, two).window is None
    perceived = session.offline(longer, full, perception=canals_model())  # its filters need the whole path
    assert perceived.window is None and perceived.options.solver == "ipopt"
    assert session.offline(longer, full, Choices(h_u=2 * step)).options.solver == "fatrop"

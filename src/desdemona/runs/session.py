"""A session's choices, resolved once: from what the user asks for to the problem that is solved.

A user chooses a desired path, a machine, and how the session goes: what the cost weighs
(``weights``), the motion gain, how the machine starts and ends, the control step. This module
turns those :class:`Choices` into the desired path the configuration follows and the options of the
problem, for every command alike: :func:`offline` for ``optimize`` and each job of ``batch``,
:func:`thesis` for ``optimize --method thesis``, :func:`online` for ``online``. The command line, the
benchmarks and the tests call these functions; each raises :class:`ChoiceError` (a
:class:`~desdemona.profiles.ProfileError` for a path's problem) with a message that names the
choice, and checks that the problem fits in memory (:mod:`desdemona.cueing.sizing`).

One rule for the figure a session is judged by: the RMS of ``S - S_d`` (printed, and written as
``rms`` in ``summary.json``) is weighted by the session's weights, the ones the optimiser or the
controller minimised, off-line and on-line alike (thesis eq. 3.6's Q).
"""

from __future__ import annotations

import dataclasses
import math
import os
from dataclasses import dataclass

import numpy as np

from desdemona import profiles
from desdemona.cueing import sizing
from desdemona.machine.model import Model
from desdemona.occupant.perception import canals_model
from desdemona.profiles import DesiredPath


class ChoiceError(ValueError):
    """A choice that cannot make a session, or choices that do not go together; the message names them."""


#: The shortest control step [s] the command line accepts.
MIN_H_U = 1e-3
#: How each command may start a session (the first is its default).
OFFLINE_STARTS = ("rest", "free", "given")
#: ``optimize``'s default solver on three joints or more (``yaw-track-cabin``, ``full``, ``dfs``):
#: fatrop, up to this many intervals per solve (60 s at 0.05 s); a longer path there is solved in
#: windows. fatrop on the compiled stages takes a third of IPOPT's time on ``full`` (its iterations are
#: half as dear, and fewer), 0.5-0.9 of it on ``dfs`` and ``yaw-track-cabin``; beyond, CasADi's fatrop
#: interface takes a time that grows with the square of the intervals to set up (12 s for 1,140, 40 s
#: for 1,880, 87 s for 2,400): the runway (85 s) on ``full`` took 123 s in windows of 60 s against 142 s
#: whole, RMS +0.4 %, and the two cases beyond 1,800 stopped at fatrop's iteration cap whole and
#: converged in windows (docs/benchmarks/fatrop-on-the-compiled-stages.md,
#: docs/benchmarks/fatrop-on-blasfeo-for-the-processor.md,
#: docs/benchmarks/fatrop-on-dfs.md, docs/benchmarks/fatrop-on-yaw-track-cabin.md).
FATROP_UP_TO = 1200
ONLINE_STARTS = ("rest", "home", "steady", "given")
#: An on-line session's felt-rotation band [perception thresholds] (:attr:`MPCOptions.rotation_band`)
#: with a perception model (docs/benchmarks/felt-rotation-band.md), and on a configuration whose cabin follows the force
#: (``dfs``), whose arm must spin up to make any sustained force (:func:`default_rotation_band`).
ROTATION_BAND, ALIGNED_ROTATION_BAND = 1.0, 5.0
#: An on-line session's felt-rotation ceiling [perception thresholds] (:attr:`MPCOptions.rotation_ceiling`)
#: with a perception model (docs/benchmarks/felt-rotation-ceiling.md).
ROTATION_CEILING = 20.0
#: An on-line session's weight of the spin about the occupant's vertical as it is, felt or not, on a
#: configuration whose cabin follows the force (``dfs``), as a share of the yaw channel's
#: (:attr:`MPCOptions.spin_weight`, docs/benchmarks/a-steady-spin-of-the-cabin-on-dfs.md).
SPIN_WEIGHT = 0.1


@dataclass(frozen=True)
class Choices:
    """What the user chooses for a session; None: the default.

    weights : a spec of :func:`desdemona.profiles.weights_for` ("felt", "path", "thresholds" or six
        numbers), None for the configuration's default (:attr:`Configuration.default_weights`);
    gain : the motion gain around 1 g (:meth:`DesiredPath.with_gain`);
    initial : how the machine starts (:data:`OFFLINE_STARTS`, :data:`ONLINE_STARTS`), None: "rest",
        or "given" when ``initial_state`` is given;
    initial_state : (q0, qd0) of the free joints, or their text "q1,q2,...;qd1,qd2,..." (SI units);
    final : how an off-line session ends: "centre", "rest" or "none" (on-line plans end stoppable);
    h_u : the off-line control step [s];
    jerk_weight : the jerk's weight in the cost (:attr:`ProblemOptions.jerk_weight`), None: the
        default of the configuration, off-line or on-line.
    window : off-line, solve in overlapping windows this long [s] (:mod:`desdemona.cueing.windows`); 0: the
        whole path at once; None: windows above :data:`~desdemona.cueing.windows.WHOLE_UP_TO` seconds.
    wall : the cost's wall before the position limits (:attr:`ProblemOptions.wall`, off-line and
        on-line), None: :data:`~desdemona.cueing.formulation.WALL`.
    head_movement_weight : the weight of the cabin's angular velocity in space in the cost
        (:attr:`ProblemOptions.head_movement_weight`, off-line and on-line), None: 0.
    """

    weights: str | tuple | None = None
    gain: float = 1.0
    initial: str | None = None
    initial_state: str | tuple | None = None
    final: str = "centre"
    h_u: float = 0.05
    jerk_weight: float | None = None
    window: float | None = None
    wall: float | None = None
    head_movement_weight: float | None = None

    @classmethod
    def of(cls, namespace) -> Choices:
        """The choices an ``argparse`` namespace holds, each field by its name (missing: the default)."""
        return cls(**{f.name: getattr(namespace, f.name) for f in dataclasses.fields(cls)
                      if getattr(namespace, f.name, None) is not None})


@dataclass(frozen=True, eq=False)
class Session:
    """A resolved session: the desired path the configuration follows (with the gain), and the
    options of its problem (:class:`~desdemona.cueing.formulation.ProblemOptions` off-line,
    :class:`~desdemona.control.online.OnlineOptions` on-line), and its size (:mod:`desdemona.cueing.sizing`);
    off-line also the window it is solved in (None: whole), the processes its starts run on, and its
    method ("optimize", or "thesis": the thesis' own optimiser, :func:`thesis`)."""

    path: DesiredPath
    model: Model
    options: object
    size: sizing.Size
    window: float | None = None
    workers: int = 1
    method: str = "optimize"


def cued(path: DesiredPath, model: Model, choices: Choices) -> DesiredPath:
    """The path the configuration follows: ``path`` with the gain, as the configuration cues it
    (:meth:`Configuration.cue_path`), refused where the configuration needs channels it lacks."""
    if not model.config.takes_modulus and path.S_d is None:
        raise profiles.ProfileError(f"configuration {model.config.name!r} needs a full path t,wx,wy,wz,fx,fy,fz; "
                                    f"{path.name} gives only the modulus (use --config dfs)")
    return model.config.cue_path(path.with_gain(choices.gain))


def cost(path: DesiredPath, model: Model, choices: Choices) -> dict:
    """The fields of the cost that the choices set, for :class:`ProblemOptions` and :class:`MPCOptions`
    alike: the diagonal of Q for the cued ``path``, the jerk's weight and the head movement's."""
    spec = choices.weights if choices.weights is not None else model.config.default_weights
    jerk, head = choices.jerk_weight, choices.head_movement_weight or 0.0
    for option, value in (("jerk-weight", jerk), ("head-movement-weight", head)):
        if value is not None and not (math.isfinite(value) and value >= 0):
            raise ChoiceError(f"--{option} {value:g}: must be a number >= 0")
    return {"weights": tuple(profiles.weights_for(spec, path)), "jerk_weight": jerk, "head_movement_weight": head}


def start(model: Model, choices: Choices, allowed: tuple[str, ...]) -> tuple[str, tuple | None]:
    """(initial, state): how the session starts, and the given state (q0, qd0) checked against the
    machine's limits, or None."""
    state = choices.initial_state
    initial = choices.initial or ("given" if state is not None else allowed[0])
    if initial not in allowed:
        raise ChoiceError(f"--initial {initial}: one of {', '.join(allowed)}")
    if (state is not None) != (initial == "given"):
        raise ChoiceError("--initial given needs --initial-state, and --initial-state goes with --initial given")
    if isinstance(state, str):
        state = parse_state(state, model)
    return initial, state


def offline(path: DesiredPath, model: Model, choices: Choices = Choices(), solver: str = "auto",
            perception=None, workers: int | None = 1, starts: int = 1) -> Session:
    """The session of ``optimize`` and of each job of ``batch``: the cued path and its
    :class:`~desdemona.cueing.formulation.ProblemOptions`, checked to fit in memory with ``workers`` at once
    (None: fitted, one process per core and at most one per start, fewer where they would not fit in
    memory together). solver "auto": fatrop on three joints or more (``yaw-track-cabin``, ``full``,
    ``dfs``) where a solve (the path, or its window) has at most :data:`FATROP_UP_TO` intervals, and on
    a longer path there in windows of :data:`~desdemona.cueing.windows.DEFAULT_WINDOW` unless a window
    is asked for; IPOPT elsewhere."""
    if workers is not None:
        return _offline(path, model, choices, solver, perception, workers)
    workers = max(1, min(len(os.sched_getaffinity(0)), starts))
    while True:
        try:
            return _offline(path, model, choices, solver, perception, workers)
        except sizing.TooLarge:
            if workers == 1:
                raise
            workers -= 1


def _offline(path: DesiredPath, model: Model, choices: Choices, solver: str, perception, workers: int) -> Session:
    """:func:`offline` on ``workers`` processes."""
    from desdemona.cueing import windows
    from desdemona.cueing.formulation import ProblemOptions

    _check_h_u(choices.h_u, path)
    if model.config.modulus_cost and perception is not None:
        raise ChoiceError("--perception applies to the full path S, not to the dfs modulus")
    wall = _wall(choices)
    path = cued(path, model, choices)
    initial, state = start(model, choices, OFFLINE_STARTS)
    problem = ProblemOptions(h_u=choices.h_u, solver="ipopt" if solver == "auto" else solver, perception=perception,
                             initial=initial, final=choices.final, initial_state=state, wall=wall,
                             **cost(path, model, choices))
    staged = model.n >= 3  # `yaw-track-cabin`, `full` and `dfs`: fatrop's (FATROP_UP_TO)
    whole_up_to = windows.WHOLE_UP_TO  # there, fatrop in windows beyond its length, not IPOPT on the whole
    if solver == "auto" and staged:
        whole_up_to = min(whole_up_to, FATROP_UP_TO * choices.h_u)
    window = _window(path, model, problem, choices.window, workers, whole_up_to)
    part = path if window is None else windows.part(path, 0.0, window)
    if solver == "auto":
        few = round(part.duration / choices.h_u) <= FATROP_UP_TO
        problem = dataclasses.replace(problem, solver="fatrop" if staged and few else "ipopt")
    size = sizing.check_fits(part, model.config, problem, workers, model.limits.smooth)
    return Session(path, model, problem, size, window, workers)


def _window(path: DesiredPath, model: Model, problem, asked: float | None, workers: int,
            whole_up_to: float) -> float | None:
    """The off-line window (:func:`desdemona.cueing.windows.choose`), its errors as the user's."""
    from desdemona.cueing import windows

    try:
        return windows.choose(path, model, problem, asked, workers, whole_up_to)
    except windows.WindowError as error:
        raise ChoiceError(str(error)) from None


def thesis(path: DesiredPath, model: Model, choices: Choices = Choices()) -> Session:
    """The session of ``optimize --method thesis``, the thesis' own setting (5.2): the path's weights,
    a free start and a free end, a control step of at least 0.1 s."""
    from desdemona.cueing.formulation import ProblemOptions

    if choices.window:
        raise ChoiceError("--method thesis solves the whole path at once: drop --window")
    for option, value in (("wall", choices.wall), ("head-movement-weight", choices.head_movement_weight)):
        if value is not None:
            raise ChoiceError(f"--method thesis reproduces the thesis' cost, which has no such term: drop --{option}")
    if (choices.initial, choices.initial_state, choices.final, choices.weights) != (None, None, "centre", None):
        raise ChoiceError("--method thesis reproduces the thesis: its weights are the path's and its start "
                         "free; drop --initial, --initial-state, --final and --weights")
    if path.S_d is None:
        raise ChoiceError(f"--method thesis fits the six channels of a full path (thesis 5.2); {path.name} gives "
                          "only the modulus: drop --method thesis (ours follows a modulus on dfs)")
    _check_h_u(choices.h_u, path)
    cued(path, model, choices)  # the channels checked; the thesis' method cues the path itself
    path = path.with_gain(choices.gain)
    problem = ProblemOptions(h_u=max(choices.h_u, 0.1))
    size = sizing.check_fits(path, model.config, problem, 1, model.limits.smooth)
    return Session(path, model, problem, size, method="thesis")


def default_rotation_band(config) -> float:
    """The felt-rotation band of an on-line session with a perception model [perception thresholds]:
    :data:`ROTATION_BAND`, and :data:`ALIGNED_ROTATION_BAND` on a configuration whose cabin follows the
    force (``dfs``). There the arm must spin up to make any force above g, and the canals feel every
    spin-up's onset: priced ten times beyond one threshold, the plan spun up late, seconds behind a
    held modulus (the C172 take-off's correlation 0.46 against the classical loop's 0.87). With five
    thresholds the felt force falls and the correlation rises on the corpus' `dfs` rows, the peak felt
    rotation stays under the loop's (docs/benchmarks/canals-in-the-on-line-cost.md,
    docs/benchmarks/felt-rotation-band.md, docs/benchmarks/a-wider-band-on-dfs.md)."""
    return ALIGNED_ROTATION_BAND if config.aligned else ROTATION_BAND


def _felt(model: Model, perception, rotation_band, rotation_ceiling, spin_weight) -> dict:
    """:func:`online`'s perception model and its weights of the rotation, "auto" resolved and checked, as
    :class:`MPCOptions` takes them."""
    # docs/benchmarks/canals-in-the-on-line-cost.md; on dfs docs/benchmarks/on-line-with-hold-on-dfs-the-felt-rotation.md
    if perception == "auto":
        perception = None if model.config.modulus_cost else canals_model()
    if model.config.modulus_cost and perception is not None:
        raise ChoiceError("--perception applies to the full path S, not to the dfs modulus")
    if rotation_band == "auto":
        rotation_band = None if perception is None else default_rotation_band(model.config)
    if rotation_ceiling == "auto":
        rotation_ceiling = None if perception is None else ROTATION_CEILING
    if spin_weight == "auto":
        spin_weight = SPIN_WEIGHT if perception is not None and model.config.aligned else 0.0
    spin_weight = spin_weight or 0.0  # None: no weight, as the band's and the ceiling's None
    if not (math.isfinite(spin_weight) and spin_weight >= 0) or spin_weight and perception is None:
        raise ChoiceError(f"--spin-weight {spin_weight:g}: a number >= 0, and with a perception model (none with "
                          f"--perception none, nor on dfs-yaw)")
    for option, value in (("band", rotation_band), ("ceiling", rotation_ceiling)):
        if value is not None and not (math.isfinite(value) and value >= 0):
            raise ChoiceError(f"--rotation-{option} {value:g}: must be a finite number of perception thresholds >= 0")
        if value is not None and perception is None:
            raise ChoiceError(f"--rotation-{option} {value:g}: the felt rotation needs a perception model (none with "
                              f"--perception none, nor on dfs-yaw); drop it or give --rotation-{option} none")
    return dict(perception=perception, rotation_band=rotation_band, rotation_ceiling=rotation_ceiling,
                spin_weight=spin_weight)


def online(path: DesiredPath, model: Model, choices: Choices = Choices(), *, horizon: float | None = None,
           reach: float | None = None, step: float = 0.02, predictor: str = "perfect",
           reference: DesiredPath | None = None, forecast=None, perception="auto", rotation_band="auto",
           rotation_ceiling="auto", spin_weight="auto", live: bool = False, **timing) -> Session:
    """The session of ``online``: the cued path and its :class:`~desdemona.control.online.OnlineOptions`.

    horizon : how far the preview reaches [s], None: :func:`~desdemona.control.mpc.default_horizon`
    (at most the path's duration); reach : how far each plan looks [s], None: at least the default
    horizon; step : the plan's step [s]; predictor and reference (a recording of the same course, for
    "route"): :class:`OnlineOptions`; forecast : the vehicle's forecasts of ``path``
    (:class:`~desdemona.profiles.forecast.Forecast`, for "forecast"; None in a live session, whose host
    sends them), given the gain and cued as the path is; perception : a vestibular model through which the controller
    minimises the perceived difference, as :func:`offline` takes it, None for none, "auto":
    :func:`~desdemona.occupant.perception.canals_model` wherever the cost is on S (all but ``dfs-yaw``, whose
    cost is the modulus alone); rotation_band :
    :attr:`MPCOptions.rotation_band` [thresholds], "auto": :func:`default_rotation_band` with a
    perception model; rotation_ceiling : the same of
    :attr:`MPCOptions.rotation_ceiling`, "auto": :data:`ROTATION_CEILING` with a perception model
    (docs/benchmarks/felt-rotation-ceiling.md); spin_weight : :attr:`MPCOptions.spin_weight` (None: 0), "auto":
    :data:`SPIN_WEIGHT`
    with a perception model where the cabin follows the force (``dfs``), else 0; live : a live
    session's (:func:`live`), whose predictor may run live and whose forecasts come from the host
    (:func:`desdemona.control.predictors.check`); ``timing``: the other
    :class:`MPCOptions` fields (replan, delay, deadline, method, tail_step).
    """
    from desdemona.control.mpc import MPCOptions, default_horizon
    from desdemona.control.online import OnlineOptions

    felt = _felt(model, perception, rotation_band, rotation_ceiling, spin_weight)
    if reference is not None and (reference.S_d is None) != (path.S_d is None):
        raise ChoiceError(f"--reference {reference.name}: its channels ({'t,M' if reference.S_d is None else 'S'}) "
                         f"differ from the path's")
    _predictor(predictor, live, reference, forecast)
    if forecast is not None:
        if forecast.channels != (1 if path.S_d is None else 6):
            raise ChoiceError(f"--forecast: its channels ({'t0,t,M' if forecast.channels == 1 else 'S'}) differ "
                              f"from the path's")
        forecast = forecast.map(lambda forecast_path: cued(forecast_path, model, choices))
    path = cued(path, model, choices)
    default = min(default_horizon(model.config), path.duration)
    horizon = default if horizon is None else horizon
    if not (0 < step and 2 * step <= horizon <= path.duration):
        raise ChoiceError(f"need 0 < --step, 2 steps <= --horizon <= the path's {path.duration:g} s")
    reach = max(horizon, default) if reach is None else reach
    if not (horizon <= reach and math.isfinite(reach)):
        raise ChoiceError(f"--reach {reach:g}: must be at least --horizon ({horizon:g} s), in seconds")
    tail = timing.get("tail_step")
    if tail is not None and not (tail >= 0 and math.isfinite(tail)):
        raise ChoiceError(f"--tail-step {tail:g}: must be a number of seconds >= 0")
    if "tail_step" in timing:
        timing["tail_step"] = tail or None  # 0: the step throughout
    deadline = timing.get("deadline")
    if deadline is not None and not deadline > 0:
        raise ChoiceError(f"--deadline {deadline:g}: must be a positive number of seconds")
    weighted, wall = cost(path, model, choices), _wall(choices)
    try:
        mpc = MPCOptions(horizon=horizon, step=step, reach=reach, wall=wall, **felt, **weighted, **timing)
    except ValueError as exc:
        raise ChoiceError(f"--replan: {exc}") from None
    size = sizing.check_fits_online(path, model.config, mpc)
    initial, state = start(model, choices, ONLINE_STARTS)
    options = OnlineOptions(mpc, predictor=predictor, reference=reference, initial=initial, initial_state=state,
                            forecast=forecast)
    return Session(path, model, options, size)


#: How long a live session is assumed to last when it is sized before it starts [s].
LIVE_SPAN = 600.0
#: The fastest cycle of a live session [Hz].
MAX_LIVE_RATE = 200.0


def live(model: Model, choices: Choices = Choices(), *, channels: int, rate: float | None = None,
         span: float | None = None, **online_kwargs) -> Session:
    """The session of ``serve``: :func:`online` for motion that is not known yet, only its form
    (``channels``: 6 for S, 1 for the modulus) and the cycle's ``rate`` [Hz] (None: the on-line
    step's default, 50 Hz); sized for ``span`` seconds (None: :data:`LIVE_SPAN`). The path the result
    holds is a placeholder at 1 g; ``online_kwargs``: as :func:`online` takes them (not ``step``), the
    predictor one that may run live (:data:`desdemona.control.predictors.PREDICTORS`, default ``hold``)."""
    if channels not in (1, 6):
        raise ChoiceError(f"--channels {channels}: 6 (S) or 1 (the modulus)")
    if rate is not None and not (math.isfinite(rate) and 0 < rate <= MAX_LIVE_RATE):
        raise ChoiceError(f"--rate {rate:g}: at most {MAX_LIVE_RATE:g} cycles a second (the controller takes "
                          f"several milliseconds a cycle; see docs/benchmarks/real-time-service.md)")
    from desdemona.control.predictors import LIVE_DEFAULT

    online_kwargs.setdefault("predictor", LIVE_DEFAULT)
    span = LIVE_SPAN if span is None else span
    t = np.array([0.0, span])
    placeholder = (DesiredPath("host", t, None, modulus=np.full(2, profiles.G)) if channels == 1 else
                   DesiredPath("host", t, np.tile([0.0, 0.0, 0.0, 0.0, 0.0, profiles.G], (2, 1))))
    return online(placeholder, model, choices, step=0.02 if rate is None else 1.0 / rate, live=True, **online_kwargs)


def _predictor(name: str, live: bool, reference, forecast) -> None:
    """The predictor checked against what it needs and where it runs (:func:`desdemona.control.predictors.check`)."""
    from desdemona.control import predictors

    try:
        predictors.check(name, live, reference is not None, forecast is not None)
    except ValueError as exc:
        raise ChoiceError(str(exc)) from None


def parse_state(text: str, model: Model) -> tuple[np.ndarray, np.ndarray]:
    """Positions and rates 'q1,q2,...;qd1,qd2,...' of the free joints (SI), within their limits."""
    names, lim = model.config.joint_names, model.limits
    parts = text.split(";")
    try:
        q, qd = (np.array([float(c) for c in part.split(",")]) for part in parts) if len(parts) == 2 else (None, None)
    except ValueError:
        raise ChoiceError(f"--initial-state {text!r}: not a number") from None
    if q is None or len(q) != model.n or len(qd) != model.n:
        raise ChoiceError(f"--initial-state {text!r}: give {model.n} positions, ';', {model.n} rates "
                         f"(joints {', '.join(names)}; SI units)")
    for k, name in enumerate(names):
        if not (np.isfinite(q[k]) and np.isfinite(qd[k])):
            raise ChoiceError(f"--initial-state: {name}'s position and rate must be finite numbers, got "
                             f"{q[k]:g} and {qd[k]:g}")
        if not lim.position_min[k] <= q[k] <= lim.position_max[k]:
            raise ChoiceError(f"--initial-state: {name} position {q[k]:g} is outside "
                             f"[{lim.position_min[k]:g}, {lim.position_max[k]:g}]")
        if not abs(qd[k]) <= lim.velocity[k]:
            raise ChoiceError(f"--initial-state: {name} rate {qd[k]:g} is above its limit {lim.velocity[k]:g}")
    return q, qd


def _wall(choices: Choices) -> float:
    """The cost's wall before the position limits [m/s^2]: the user's, else
    :data:`~desdemona.cueing.formulation.WALL`, off-line and on-line alike
    (docs/benchmarks/wall-before-the-position-limits.md)."""
    from desdemona.cueing.formulation import WALL

    if choices.wall is None:
        return WALL
    if not (math.isfinite(choices.wall) and choices.wall >= 0):
        raise ChoiceError(f"--wall {choices.wall:g}: must be a number >= 0 (m/s^2)")
    return choices.wall


def _check_h_u(h_u: float, path: DesiredPath) -> None:
    if not (math.isfinite(h_u) and MIN_H_U <= h_u <= path.duration):
        raise ChoiceError(f"--h-u {h_u:g}: must be at least {MIN_H_U:g} s and at most the path's "
                         f"{path.duration:g} s")

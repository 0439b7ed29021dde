"""Predictors: what the on-line controller is told of the future (thesis 7.3).

The thesis assumes "that the path can be fully estimated" and notes that how to estimate it "depends
on the vehicle to be simulated and the mission of the pilot". A predictor is a callable
``predictor(path, now, horizon) -> preview``: it may read the live path only up to ``now`` (except
``perfect``), and returns the expected S_d (or M_d) over [now, now + horizon] as a
:class:`~desdemona.profiles.DesiredPath` whose time starts at 0.

- ``perfect``: the true future (the thesis' assumption; the bound for any other predictor);
- ``hold``: the present value held (:class:`HoldPredictor`: a line's end through the last 0.2 s,
  moved only when it leaves its noise band), its departure from rest expected to last about as long
  as it has lasted so far;
- ``linear``: extrapolated from the last two samples;
- ``forecast``: the vehicle's own forecast (:class:`ForecastPredictor`): its model run ahead with the
  pilot's controls held, read from a forecast file (:mod:`desdemona.profiles.forecast`), or in a live
  session the forecast block the host sends with its motion (:mod:`desdemona.service`);
- ``route``: a known course (:class:`RoutePredictor`): the future taken from a reference recording of
  the same route (a car on a known track, a ride on a coaster, a rehearsed manoeuvre), aligned to the
  live signal by its recent past, so that a run that is faster, slower or noisier than the reference
  is still previewed in step with it.

:data:`PREDICTORS` is their one table: what each needs and where it may run; :func:`check` checks a
choice against it, :func:`predictor` makes a fresh one by name (hold and route predictors carry state
from call to call).
A preview never reads the live path after ``now`` (``perfect`` aside): the tests poison it there.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from desdemona.profiles import DesiredPath
from desdemona.profiles.forecast import START_TOLERANCE, Forecast
from desdemona.profiles.path import REST, G


def predict_perfect(path: DesiredPath, now: float, horizon: float) -> DesiredPath:
    """The true future of the path over [now, now + horizon] (the thesis' assumption in 7.3)."""
    return _window(path, now, horizon, lambda t: t)


#: The hold predictor's estimate of the present value fits a straight line to the samples of the last
#: this many seconds and takes its value at ``now``: one sample of a recorded signal carries all of its
#: noise, and a plan that holds it for the horizon follows the noise; a mean would lag behind a ramp
#: by half the window, the line's end does not.
HOLD_WINDOW = 0.2

#: The held value moves only when the estimate leaves a band of this many standard errors of the
#: estimate around it, and then by the excess (a backlash). Measured on dfs-catapult-recorded (100 Hz,
#: 0.5 m/s^2 of noise) on dfs started in steady rotation: the yaw reversed its acceleration 2.7 times
#: a second on the 1.5 g stretch with the bare estimate, 0.6 with 2 standard errors, for 1 % more
#: modulus RMS (2.80 against 2.76); from rest 0.9 against 1.0 reversals a second, RMS 3.27 against 3.24.
HOLD_BAND = 2.0


#: How long the hold predictor expects a cue to last, at the least [s]. What a held value departs from
#: rest (no rotation and 1 g upright) is weighed tau ahead by T / (T + tau), T = HOLD_PERSISTENCE +
#: ``age``, where ``age`` is how long the channel has kept the same side of rest at no less than
#: :data:`HOLD_AGE_SHARE` of its present departure (in the predictor's own held values, which the noise
#: band keeps clean): the chance that a cue of that age lasts tau more where cues' lengths have no
#: typical scale (a Pareto law; a cue is expected to last about as long as it has lasted). A turn or a
#: take-off run that has lasted 20 s is held nearly as it is; a spike (an elevator doublet's -2 g for
#: half a second) is not planned for as if it would last the whole horizon. Held for 4 s, that spike
#: turned the cabin on ``full`` over and back (c172-doublet: felt force RMS 11.8 against the classical
#: washout's 9.2, correlation -0.58, false rotation 213 deg/s). A modulus path (``dfs``) is held as it
#: is: there a modulus below g is planned as g and cannot turn the cabin over, and the arm's spin-up
#: needs a sustained modulus seen early (measured worse with the persistence on 6 of the 7 corpus
#: cases); see docs/benchmarks/hold-predictor.md.
HOLD_PERSISTENCE = 0.5

#: The share of a channel's present departure from rest below which its cue counts as begun afresh.
HOLD_AGE_SHARE = 0.5

#: How far back the hold predictor remembers its held values for a cue's age [s]: older cues are held
#: as they are.
HOLD_AGE_MAX = 60.0


def rest(path: DesiredPath) -> np.ndarray:
    """What the path's channels are at rest: :data:`~desdemona.profiles.path.REST` for S_d, (G,) for a
    modulus."""
    return REST if path.S_d is not None else np.array([G])


def cue_age(times, values, base) -> np.ndarray:
    """How long [s] each channel of ``values`` (K, channels) at ``times`` (K,), increasing, has kept
    the same side of ``base`` at no less than :data:`HOLD_AGE_SHARE` of its last row's departure from
    it: the last time minus that of the last row short of it; the whole span where none is."""
    departure = values[-1] - base
    short = (values - base) * np.sign(departure) < HOLD_AGE_SHARE * np.abs(departure)
    last = len(times) - 1 - np.argmax(short[::-1], axis=0)  # per channel, the last row short of it
    return times[-1] - np.where(short.any(axis=0), times[last], times[0])


def _present(path: DesiredPath, now: float, window: float) -> tuple[np.ndarray, np.ndarray]:
    """(value, standard error) per channel of the present value: the least-squares line through the
    samples in (now - window, now] at ``now``, and its standard error from the line's residuals; the
    sample at ``now`` and zero where fewer than three samples fall in there."""
    recent = np.flatnonzero((path.t > now - window) & (path.t <= now))
    values = path.S_d if path.S_d is not None else path.M_d[:, None]
    if len(recent) < 3:
        value = path.sample([now])[0] if path.S_d is not None else np.atleast_1d(path.sample_modulus([now]))
        return np.asarray(value, dtype=float), np.zeros(values.shape[1])
    x = path.t[recent] - now
    line = np.polyfit(x, values[recent], 1)  # (2, channels): slope, value at now
    residuals = values[recent] - (line[0] * x[:, None] + line[1])
    spread = np.sqrt(np.sum(residuals**2, axis=0) / (len(recent) - 2))
    # standard error of a line's value at the end of its window: sqrt(1/K + mean(x)^2 / sum((x - mean)^2))
    leverage = 1.0 / len(recent) + np.mean(x) ** 2 / np.sum((x - np.mean(x)) ** 2)
    return line[1], spread * np.sqrt(leverage)


def _held(path: DesiredPath, now: float, horizon: float, value, persistence=None) -> DesiredPath:
    """``value`` over [now, now + horizon], its departure from rest weighed by the chance that it lasts
    tau more, T / (T + tau), with T = ``persistence`` per channel (None: held as it is)."""
    tau = _grid(path, horizon)
    base = rest(path)
    lasting = np.ones((len(tau), 1)) if persistence is None else persistence / (persistence + tau[:, None])
    values = base + (np.asarray(value, dtype=float) - base) * lasting
    S = None if path.S_d is None else values
    M = None if path.S_d is not None else np.maximum(values[:, 0], 0.0)
    return DesiredPath(path.name, tau, S, path.weights, path.description, M)


def predict_hold(path: DesiredPath, now: float, horizon: float, window: float | None = None) -> DesiredPath:
    """The present value held over the horizon: the value at ``now`` of the least-squares line through
    the samples in (now - window, now] (default :data:`HOLD_WINDOW`), or the value at ``now`` where
    fewer than three samples fall in there. Without memory: :class:`HoldPredictor` is what the
    controller uses."""
    return _held(path, now, horizon, _present(path, now, HOLD_WINDOW if window is None else window)[0])


class HoldPredictor:
    """The ``hold`` predictor: the present value (:func:`predict_hold`) held over the horizon, with a
    memory that keeps the noise of a recorded signal out of the plan, its departure from rest expected
    to last about as long as it has lasted (:data:`HOLD_PERSISTENCE`; ``persistence=None``: held as it
    is, whatever its age).

    From call to call the held value moves only where the new estimate lies more than ``band``
    standard errors of the estimate (from the line's residuals) away from it, and then only by the
    excess (a backlash): on a steady stretch the estimate's noise does not move it, on a ramp or a step
    it follows at once, behind by the band (about 0.2 m/s^2 on a 0.5 m/s^2-noise 100 Hz log, nothing
    on a clean signal, whose residuals are only its curvature). A fresh one per run
    (:func:`predictor`).
    """

    def __init__(self, window: float = HOLD_WINDOW, band: float = HOLD_BAND,
                 persistence: float | None = HOLD_PERSISTENCE):
        if not (window > 0 and band >= 0 and (persistence is None or persistence > 0)):
            raise ValueError("the hold predictor needs window > 0, band >= 0 and persistence > 0 (or None)")
        self.window, self.band, self.persistence, self.value = window, band, persistence, None
        self.times, self.values, self.count = np.zeros(0), None, 0  # the held values, for their age

    def _remember(self, now: float) -> None:
        """Add (now, held value) to the memory, whose rows older than :data:`HOLD_AGE_MAX` are dropped
        when it fills (amortised: a copy per filled buffer)."""
        if self.count == len(self.times):
            keep = self.times[:self.count] >= now - HOLD_AGE_MAX
            times = self.times[:self.count][keep]
            size = max(64, 2 * len(times))
            values, self.values = self.values, np.zeros((size, len(self.value)))
            if values is not None:
                self.values[:len(times)] = values[:self.count][keep]
            self.times = np.zeros(size)
            self.times[:len(times)] = times
            self.count = len(times)
        self.times[self.count], self.values[self.count] = now, self.value
        self.count += 1

    def __call__(self, path: DesiredPath, now: float, horizon: float) -> DesiredPath:
        estimate, error = _present(path, now, self.window)
        if self.value is None:
            self.value = estimate
        else:
            excess = estimate - self.value
            width = self.band * error
            self.value = np.where(np.abs(excess) > width, estimate - np.sign(excess) * width, self.value)
        if self.persistence is None or path.modulus is not None:  # a modulus is held as it is (HOLD_PERSISTENCE)
            return _held(path, now, horizon, self.value)
        self._remember(now)
        recent = slice(np.searchsorted(self.times[:self.count], now - HOLD_AGE_MAX), self.count)
        age = cue_age(self.times[recent], self.values[recent], rest(path))
        return _held(path, now, horizon, self.value, self.persistence + age)


def predict_linear(path: DesiredPath, now: float, horizon: float) -> DesiredPath:
    """Linear extrapolation from the last two samples at or before ``now``."""
    k = max(1, int(np.searchsorted(path.t, now, side="right")) - 1)
    t0, t1 = path.t[k - 1], path.t[k]

    def values(column):
        slope = (column[k] - column[k - 1]) / (t1 - t0)
        return lambda t: column[k] + slope * (t - t1)

    t = now + _grid(path, horizon)
    S = None if path.S_d is None else np.column_stack([values(path.S_d[:, i])(t) for i in range(6)])
    M = None if path.S_d is not None else np.maximum(values(path.M_d)(t), 0.0)
    return DesiredPath(path.name, t - now, S, path.weights, path.description, M)


class RoutePredictor:
    """The future from a reference recording of the same course, aligned to the live signal.

    The live run is taken to follow the reference at a position s(t) along the reference's time,
    advancing at a rate near 1 (a lap driven a little faster or slower). At each call the position and
    rate are those that best match the last ``window`` seconds of the live signal to the reference
    (least squares over a grid of rates in ``rates`` and positions within ``search`` seconds of where
    the last estimate predicts, with a small pull towards that prediction where the signal is too flat
    to tell); the preview is the reference from s onwards at that rate.

    reference : a recording of the course, with the same channels as the live path (S_d or M_d);
    window, search [s]; rates : (slowest, fastest) rate of the live run against the reference.
    """

    def __init__(self, reference: DesiredPath, window: float = 2.0, search: float = 1.0,
                 rates: tuple[float, float] = (0.8, 1.25)):
        if not (window > 0 and search > 0 and 0 < rates[0] <= 1.0 <= rates[1]):
            raise ValueError("the route predictor needs window > 0, search > 0 and rates around 1")
        self.reference, self.window, self.search = reference, window, search
        self.rates = np.linspace(rates[0], rates[1], 19)
        values = self._values(reference, reference.t)
        self._scale = 1.0 / (np.std(values, axis=0) + 1e-6)  # every channel counts alike
        self.position, self.rate, self.time = float(reference.t[0]), 1.0, None

    @staticmethod
    def _values(path: DesiredPath, times) -> np.ndarray:
        return path.sample(times) if path.S_d is not None else path.sample_modulus(times)[:, None]

    def _align(self, path: DesiredPath, now: float) -> None:
        expected = self.position if self.time is None else self.position + self.rate * (now - self.time)
        dt = float(np.min(np.diff(path.t)))
        ago = np.arange(0.0, min(self.window, now - path.t[0]) + 1e-9, dt)
        if len(ago) < 5:  # too little seen yet: keep to the expected place
            self.position, self.time = expected, now
            return
        live = self._values(path, now - ago) * self._scale
        positions = expected + np.linspace(-self.search, self.search, 41)
        rates = self.rates
        for _ in range(2):  # a grid, then a finer one around its best point
            times = positions[None, :, None] - rates[:, None, None] * ago[None, None, :]
            reference = self._values(self.reference, times.ravel()).reshape(*times.shape, -1) * self._scale
            error = np.mean((reference - live[None, None]) ** 2, axis=(2, 3))
            error += 1e-3 * ((positions[None, :] - expected) / self.search) ** 2
            i, j = np.unravel_index(np.argmin(error), error.shape)
            best_rate, best_position = rates[i], positions[j]
            positions = best_position + np.linspace(-1, 1, 21) * (positions[1] - positions[0])
            rates = best_rate + np.linspace(-1, 1, 11) * (self.rates[1] - self.rates[0])
        self.position, self.rate, self.time = float(best_position), float(best_rate), now

    def __call__(self, path: DesiredPath, now: float, horizon: float) -> DesiredPath:
        self._align(path, now)
        t = _grid(path, horizon)
        times = np.clip(self.position + self.rate * t, self.reference.t[0], self.reference.t[-1])
        ref = self.reference
        S = None if ref.S_d is None else ref.sample(times)
        M = None if ref.S_d is not None else ref.sample_modulus(times)
        return DesiredPath(path.name, t, S, path.weights, f"route preview from {ref.name}", M)


class ForecastPredictor:
    """The ``forecast`` predictor: the vehicle's own forecasts (a :class:`~desdemona.profiles.forecast.Forecast`),
    e.g. a flight simulator's model run ahead from each issue time with the pilot's controls held.

    At ``now`` the preview is the latest forecast issued at t0 <= now: the present value of the live
    path (its last sample at or before ``now``) as the first sample, so that the plan starts from what
    is true, then the forecast's samples after ``now``, linearly interpolated onto the path's finest
    step; where the forecast ends before ``now + horizon`` its last value is held, and before the first
    forecast the present value is held. The live path is never read after ``now``.

    The forecast file (:func:`~desdemona.profiles.forecast.read_forecast`): a CSV file with columns
    ``t0,t,wx,wy,wz,fx,fy,fz`` (or ``t0,t,M`` for a modulus path), one row per forecast sample, the
    forecasts in order of their issue time t0, each starting with its sample at ``t = t0``; times on
    the motion file's clock, channels as the motion file's. Its values must be those of the path the
    controller follows (gain and cueing applied as to the path: :meth:`Forecast.map`).
    """

    def __init__(self, forecast: Forecast):
        self.forecast = forecast

    def __call__(self, path: DesiredPath, now: float, horizon: float) -> DesiredPath:
        if (path.S_d is None) != (self.forecast.S_d is None):
            raise ValueError(f"the forecast's channels ({self.forecast.channels}) are not the path's")
        k = max(0, int(np.searchsorted(path.t, now + START_TOLERANCE, side="right")) - 1)
        knots = np.zeros(1)
        S = None if path.S_d is None else path.S_d[k:k + 1]
        M = None if path.modulus is None else path.modulus[k:k + 1]
        issued = self.forecast.issued(now)
        if issued is not None:
            t, S_f, M_f = issued
            ahead = t > now + START_TOLERANCE
            knots = np.r_[knots, t[ahead] - now]
            S = None if S is None else np.vstack([S, S_f[ahead]])
            if M is not None:  # a path with S and its modulus: the forecast's own, or |f| of its S
                M = np.r_[M, (M_f if M_f is not None else np.linalg.norm(S_f[:, 3:], axis=1))[ahead]]
        grid = _grid(path, horizon)
        S = None if S is None else np.column_stack([np.interp(grid, knots, S[:, i]) for i in range(6)])
        M = None if M is None else np.interp(grid, knots, M)
        return DesiredPath(path.name, grid, S, path.weights, "the vehicle's forecast", M)


@dataclass(frozen=True)
class Need:
    """What a predictor needs besides the live path: the command line's option that gives it (and its
    metavar), what it is, and where a live session (``serve``) takes it from instead (None: the option)."""

    option: str
    metavar: str
    what: str
    live: str | None = None

    def asked(self, live: bool) -> str:
        """How a user gives it, where the session runs."""
        return self.live if live and self.live else f"{self.option} {self.metavar}, {self.what}"


#: A recording of the same course (``route``).
REFERENCE = Need("--reference", "PROFILE_OR_CSV", "a recording of the same course (same channels as the path)")
#: The vehicle's forecasts (``forecast``): a file on-line, the block a simulator host sends in a live session.
FORECAST = Need("--forecast", "FILE", "the vehicle's forecasts (docs/guide/online.md#predictors)",
                live="the forecast block the host sends with its motion")


@dataclass(frozen=True)
class Kind:
    """One predictor of :data:`PREDICTORS`: ``make``, a function ``predictor(path, now, horizon)`` or a
    class (which carries state from call to call: a fresh one per run, given its need); what it does
    (``summary``, the help's); what it ``needs`` (:data:`REFERENCE`, :data:`FORECAST` or None);
    whether it may run in a live session (``serve``; all may run in ``online``); and how many seconds
    of the past it reads (``looks_back``; None: all it is given): a live session gives it no more,
    each cycle's preview then costs the same however long the session."""

    make: object
    summary: str
    needs: Need | None = None
    live: bool = True
    looks_back: float | None = None


#: The predictors, by name: the one table that the command line's choices and help, every check of
#: what a predictor needs (:func:`check`) and :func:`predictor` read. ``perfect`` cannot run live: it
#: needs the future.
PREDICTORS = {
    "perfect": Kind(predict_perfect, "the true future (the thesis' assumption)", live=False),
    "hold": Kind(HoldPredictor, "the present held", looks_back=5 * HOLD_WINDOW),  # its memory is its own
    "linear": Kind(predict_linear, "extrapolated from the last two samples", looks_back=5 * HOLD_WINDOW),
    "route": Kind(RoutePredictor, "a recording of the same course, aligned to the live signal", REFERENCE),
    "forecast": Kind(ForecastPredictor, "the vehicle's own forecasts, its model run ahead", FORECAST),
}

#: A live session's predictor unless told.
LIVE_DEFAULT = "hold"


def names(live: bool = False) -> tuple[str, ...]:
    """The predictors' names, those that may run in a live session with ``live``."""
    return tuple(name for name, kind in PREDICTORS.items() if kind.live or not live)


def users(need: Need) -> tuple[str, ...]:
    """The predictors that read what ``need`` gives."""
    return tuple(name for name, kind in PREDICTORS.items() if kind.needs is need)


def describe(live: bool = False) -> str:
    """The predictors (:func:`names`) for a user, one clause each with what it needs: the help's."""
    def needs(need):
        return "" if need is None else f" (needs {need.live if live and need.live else need.option})"

    return "; ".join(f"{name}: {kind.summary}{needs(kind.needs)}"
                     for name, kind in PREDICTORS.items() if kind.live or not live)


def check(name: str, live: bool | None = False, reference: bool = False, forecast: bool = False) -> Kind:
    """The predictor ``name`` (:data:`PREDICTORS`), checked to run where it is asked (``live``: in a
    live session, ``serve``; False: ``online``; None: either, not known yet) with what is given (a
    ``reference``, a ``forecast``): raises ValueError, naming the options, for an unknown name, a
    predictor a live session cannot run, a need not given (a live session's forecast comes from the
    host) or a reference or forecast given to a predictor that does not read it."""
    allowed = names(bool(live))
    if name not in allowed:
        where = "a live session uses" if live and name in PREDICTORS else "must be"
        raise ValueError(f"--predictor {name}: {where} one of {', '.join(allowed)}")
    kind = PREDICTORS[name]
    for need, given in ((REFERENCE, reference), (FORECAST, forecast)):
        if kind.needs is need and not given and (live is False or need.live is None):
            raise ValueError(f"--predictor {name} needs {need.asked(False)}")
        if given and kind.needs is not need:
            raise ValueError(f"{need.option} is used only with --predictor {' or '.join(users(need))}")
    return kind


def predictor(name: str, reference: DesiredPath | None = None, forecast: Forecast | None = None):
    """A fresh predictor called ``name`` (:data:`PREDICTORS`), given what it needs (:func:`check`):
    ``route`` its reference recording, ``forecast`` the vehicle's forecasts."""
    kind = check(name, reference=reference is not None, forecast=forecast is not None)
    if kind.needs is not None:
        return kind.make(reference if kind.needs is REFERENCE else forecast)
    return kind.make() if isinstance(kind.make, type) else kind.make  # a class carries state: a fresh one per run


def _grid(path: DesiredPath, horizon: float) -> np.ndarray:
    """Times [0, horizon] at the path's finest sample step."""
    dt = float(np.min(np.diff(path.t)))
    return np.linspace(0.0, horizon, max(2, int(round(horizon / dt)) + 1))


def _window(path: DesiredPath, now: float, horizon: float, source_times) -> DesiredPath:
    t = now + _grid(path, horizon)
    times = np.clip(source_times(t), path.t[0], path.t[-1])
    S = None if path.S_d is None else path.sample(times)
    M = None if path.S_d is not None else path.sample_modulus(times)
    return DesiredPath(path.name, t - now, S, path.weights, path.description, M)

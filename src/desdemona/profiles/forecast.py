"""Forecasts of a desired path: what a vehicle's own model says the motion will be, issued as it runs.

A flight or driving simulator can run its model ahead from the present state with the pilot's
controls held; each such run is a forecast of the motion from its issue time ``t0`` on. A forecast
file is a CSV file, one row per forecast sample, the forecasts one after another in order of issue:

    t0,t,wx,wy,wz,fx,fy,fz       (or t0,t,M for a modulus path)
    0.0,0.0,0,0,0,0,0,9.81       # the forecast issued at t0 = 0: its first sample at t = t0 (the present),
    0.0,0.01,0,0,0,0,0.1,9.81    #   then its later samples, t increasing (any step, any length)
    0.1,0.1,...                  # the next forecast, issued at t0 = 0.1

Times are on the motion file's own clock (absolute times, the unit of its ``t`` column: seconds;
a motion file that does not start at 0 is shifted to 0 when read, its forecasts with it), the
channels those of the motion file (``wx..fz`` in SI units, as :mod:`.csvfile` reads them, or ``M``),
columns in any order, ``#`` comments. The issue times ``t0`` increase from forecast to forecast; each
forecast starts at its ``t0``. :func:`read_forecast` refuses any other file with a message that names
the line and the problem; :func:`write_forecast` writes one.
"""

from __future__ import annotations

import csv
import io
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from desdemona.profiles.log import data_lines
from desdemona.profiles.path import CHANNELS, MAX_SPECIFIC_FORCE, DesiredPath, ProfileError

#: The columns of a forecast of a full path and of a modulus path.
FORECAST_COLUMNS = ("t0", "t", *CHANNELS)
MODULUS_FORECAST_COLUMNS = ("t0", "t", "M")
#: How close a forecast's first sample must be to its issue time [s] (a file's rounding of both).
START_TOLERANCE = 1e-6


@dataclass(frozen=True, eq=False)
class Forecast:
    """Forecasts of a path, each issued at a time ``t0``, stored one after another.

    t0 : (K,) strictly increasing issue times [s], on the path's clock;
    first : (K + 1,) the row of each forecast's first sample in ``t`` (``first[K]`` = the row count);
    t : (R,) sample times [s]: forecast k's rows ``first[k]:first[k + 1]``, increasing from its t0;
    S_d : (R, 6) the forecast S (omega_cabin [rad/s], f_cabin [m/s^2]), or None for a modulus forecast;
    modulus : (R,) the forecast modulus [m/s^2] where given, else None.
    """

    t0: np.ndarray
    first: np.ndarray
    t: np.ndarray
    S_d: np.ndarray | None
    modulus: np.ndarray | None = None

    def __post_init__(self):
        rows = len(self.t)
        if len(self.first) != len(self.t0) + 1 or self.first[-1] != rows or np.any(np.diff(self.first) < 1):
            raise ValueError("a forecast needs at least one sample per issue time")
        if self.S_d is None and self.modulus is None:
            raise ValueError("a forecast needs S_d or the modulus")

    @classmethod
    def of(cls, blocks) -> Forecast:
        """The forecast of ``blocks``: (t0, t (k,), values (k, 6) for S or (k,) for the modulus) each."""
        blocks = list(blocks)
        if not blocks:
            raise ValueError("a forecast needs at least one issue")
        values = [np.asarray(v, dtype=float) for _, _, v in blocks]
        stacked = np.concatenate(values)
        first = np.r_[0, np.cumsum([len(v) for v in values])]
        t0 = np.array([float(b[0]) for b in blocks])
        t = np.concatenate([np.asarray(b[1], dtype=float) for b in blocks])
        return cls(t0, first, t, stacked if stacked.ndim == 2 else None, None if stacked.ndim == 2 else stacked)

    @property
    def channels(self) -> int:
        """6 for S, 1 for the modulus only."""
        return 1 if self.S_d is None else 6

    def issued(self, now: float):
        """(t, S_d, modulus) of the latest forecast issued at or before ``now`` [s], or None before the first
        (S_d or modulus None where the forecast has none)."""
        k = int(np.searchsorted(self.t0, now + START_TOLERANCE, side="right")) - 1
        if k < 0:
            return None
        rows = slice(int(self.first[k]), int(self.first[k + 1]))
        return (self.t[rows], None if self.S_d is None else self.S_d[rows],
                None if self.modulus is None else self.modulus[rows])

    def map(self, transform) -> Forecast:
        """Every sample through ``transform(DesiredPath) -> DesiredPath``, a function of each sample alone
        (a gain, :meth:`Configuration.cue_path`, :func:`.modulus_version`): one path transformation,
        whether it is applied to a path or to its forecasts."""
        rows = len(self.t)
        pad = max(0, 2 - rows)  # a path needs two samples

        def padded(x):
            return None if x is None else np.concatenate([x, np.repeat(x[-1:], pad, axis=0)])

        made = transform(DesiredPath("forecast", np.arange(rows + pad, dtype=float), padded(self.S_d),
                                     modulus=padded(self.modulus)))
        return Forecast(self.t0, self.first, self.t, None if made.S_d is None else made.S_d[:rows],
                        None if made.modulus is None else made.modulus[:rows])


def read_forecast(file: str | Path, path: DesiredPath | None = None, origin: float = 0.0) -> Forecast:
    """Read a forecast file (the module's format), its times shifted by ``-origin`` [s] (the first time of
    the motion file, :func:`time_origin`). With ``path``, the motion it forecasts, its channels must be
    the path's and its issue times must overlap the path's time.

    Strict: a missing, unknown or repeated column, a value that is not a finite number, issue times out
    of order, a forecast that does not start at its t0 or whose t does not increase, a negative modulus,
    |f| above 100 g, no data: :class:`ProfileError` naming the file and the line.
    """
    file = Path(file)
    lines = data_lines(file)
    columns = [c.strip() for c in next(csv.reader([lines[0][1]]))]
    layout = next((c for c in (FORECAST_COLUMNS, MODULUS_FORECAST_COLUMNS) if sorted(columns) == sorted(c)), None)
    if layout is None:
        wanted = MODULUS_FORECAST_COLUMNS if "M" in columns else FORECAST_COLUMNS
        missing = [c for c in wanted if c not in columns]
        unknown = [c for c in columns if c not in FORECAST_COLUMNS + MODULUS_FORECAST_COLUMNS]
        detail = (f"unknown column {unknown[0]!r}" if unknown else f"missing column {missing[0]!r}" if missing
                  else "repeated columns, or M with the full path")
        raise ProfileError(f"{file}: line {lines[0][0]}: {detail}; the columns must be "
                           f"'{','.join(FORECAST_COLUMNS)}' or '{','.join(MODULUS_FORECAST_COLUMNS)}' (any order)")
    data = _numbers(file, lines[1:], columns)[:, [columns.index(c) for c in layout]]
    numbers = [n for n, _ in lines[1:]]
    grouped = _grouped(file, numbers, data[:, 0], data[:, 1], data[:, 2:])  # checked on the file's clock
    forecast = Forecast(grouped.t0 - origin, grouped.first, grouped.t - origin, grouped.S_d, grouped.modulus)
    if path is not None:
        _check_fits(file, forecast, path)
    return forecast


def _numbers(file: Path, lines, columns) -> np.ndarray:
    """The data lines as an (R, columns) array of finite numbers."""
    if not lines:
        raise ProfileError(f"{file}: a header but no forecast samples")
    try:
        data = np.loadtxt([line for _, line in lines], delimiter=",", ndmin=2, dtype=float)
    except ValueError:
        data = None
    if data is None or data.shape[1] != len(columns):
        for number, line in lines:  # find the line at fault, for the message
            cells = next(csv.reader([line]))
            if len(cells) != len(columns):
                raise ProfileError(f"{file}: line {number}: {len(cells)} values for {len(columns)} columns")
            try:
                [float(c) for c in cells]
            except ValueError:
                raise ProfileError(f"{file}: line {number}: not a number in {line.strip()!r}") from None
        raise ProfileError(f"{file}: not a comma-separated table of numbers")
    bad = ~np.isfinite(data)
    if np.any(bad):
        row, col = np.argwhere(bad)[0]
        raise ProfileError(f"{file}: line {lines[row][0]}: {columns[col]} is not a finite number (NaN or inf)")
    return data


def _grouped(file: Path, numbers, t0, t, values) -> Forecast:
    """The rows (issue time, time, channels) grouped into forecasts, each checked."""
    def fail(row: int, text: str):
        raise ProfileError(f"{file}: line {numbers[row]}: {text}")

    back = np.flatnonzero(np.diff(t0) < 0)
    if len(back):
        k = back[0] + 1
        fail(k, f"t0 = {t0[k]:g} s after t0 = {t0[k - 1]:g} s: the forecasts must follow one another in order of "
                f"their issue time t0, each forecast's rows together")
    first = np.r_[0, np.flatnonzero(np.diff(t0) > 0) + 1]
    late = np.flatnonzero(np.abs(t[first] - t0[first]) > START_TOLERANCE)
    if len(late):
        k = first[late[0]]
        fail(k, f"the forecast issued at t0 = {t0[k]:g} s starts at t = {t[k]:g} s: its first sample must be at "
                f"t0, the present")
    steps = np.diff(t) <= 0
    steps[first[1:] - 1] = False  # a new forecast starts again at its t0
    if np.any(steps):
        k = int(np.argmax(steps)) + 1
        fail(k, f"t = {t[k]:g} s does not increase in the forecast issued at t0 = {t0[k]:g} s (previous t = "
                f"{t[k - 1]:g} s)")
    if values.shape[1] == 1:
        if np.any(values[:, 0] < 0):
            fail(int(np.argmax(values[:, 0] < 0)), "M is negative; the modulus |f| is >= 0")
        magnitude = values[:, 0]
    else:
        magnitude = np.linalg.norm(values[:, 3:], axis=1)
    if np.any(magnitude > MAX_SPECIFIC_FORCE):
        k = int(np.argmax(magnitude > MAX_SPECIFIC_FORCE))
        fail(k, f"|f| = {magnitude[k]:.4g} m/s^2 is above {MAX_SPECIFIC_FORCE:.4g} m/s^2: wrong units? "
                f"(SI: rad/s and m/s^2 expected)")
    S = values if values.shape[1] == 6 else None
    return Forecast(t0[first], np.r_[first, len(t)], t, S, values[:, 0] if S is None else None)


def _check_fits(file: Path, forecast: Forecast, path: DesiredPath) -> None:
    """Refuse a forecast whose channels are not the path's, or whose issue times miss the path's time."""
    path_channels = 1 if path.S_d is None else 6
    if forecast.channels != path_channels:
        kinds = {1: "the modulus (t0,t,M)", 6: "six channels (t0,t,wx,wy,wz,fx,fy,fz)"}
        raise ProfileError(f"{file}: a forecast of {kinds[forecast.channels]}, but the motion {path.name} has "
                           f"{'only the modulus M' if path_channels == 1 else 'six channels'}: write the forecast "
                           f"with the motion's channels")
    if forecast.t0[0] > path.t[-1] or forecast.t[-1] < path.t[0]:
        raise ProfileError(f"{file}: its forecasts, issued from {forecast.t0[0]:g} s to {forecast.t0[-1]:g} s, miss "
                           f"the motion's time {path.t[0]:g}-{path.t[-1]:g} s: are its times on the motion "
                           f"file's clock?")


def write_forecast(file: str | Path, forecast: Forecast, comments=()) -> Path:
    """Write ``forecast`` in the module's format (12 significant digits), each of ``comments`` a ``#`` line."""
    columns = MODULUS_FORECAST_COLUMNS if forecast.S_d is None else FORECAST_COLUMNS
    values = forecast.modulus[:, None] if forecast.S_d is None else forecast.S_d
    issue = np.repeat(forecast.t0, np.diff(forecast.first))
    buffer = io.StringIO()
    for comment in comments:
        buffer.write(f"# {comment}\n")
    np.savetxt(buffer, np.column_stack([issue, forecast.t, values]), fmt="%.12g", delimiter=",",
               header=",".join(columns), comments="")
    Path(file).write_text(buffer.getvalue())
    return Path(file)


def time_origin(motion: str | Path) -> float:
    """The first time [s] of a motion CSV file, where its path's time 0 is (0 for a built-in path)."""
    file = Path(motion)
    if not file.is_file():
        return 0.0
    lines = (line for line in file.read_bytes().decode("utf-8-sig", errors="replace").splitlines()
             if line.strip() and not line.lstrip().startswith("#"))
    header = [c.strip() for c in next(csv.reader([next(lines, "")]))]
    first = next(lines, None)
    if "t" not in header or first is None:
        return 0.0  # not a motion file: reading it as the path reports that
    try:
        return float(next(csv.reader([first]))[header.index("t")])
    except (ValueError, IndexError):
        return 0.0

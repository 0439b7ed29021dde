"""Desired paths from a logged motion: an IMU's or a vehicle simulator's output as CSV.

The log holds, per sample, a time, three accelerometer readings and three angular rates, in columns
named by the user, in declared units and along declared axes; a log of accelerometer readings alone
(a phone's, a ride logger's) gives the modulus form ``t,M`` for ``dfs``, whose |f| needs no axes. An
accelerometer reads specific force ``f = a - g_vec`` (+1 g up at rest), which is what a person feels
and what a desired path holds; a log of kinematic acceleration (0 at rest) is not one, and the
convention check says so.

The rows go through: units to SI, the log's axes turned into the cabin frame (x right, y forward,
z up), a uniform grid at the log's own median step, the lever arm from the sensor to the head
(``f_head = f_sensor + alpha x r + omega x (omega x r)``), the anti-alias filter and resampling, the
convention check (where the log is still the force reads +1 g up; without rates, 1 g) and the crop.
"""

from __future__ import annotations

import csv
import math
from dataclasses import dataclass, replace
from pathlib import Path

import numpy as np

from desdemona.profiles import clock, convert, csvfile, turns
from desdemona.profiles.clock import TIME_UNITS
from desdemona.profiles.path import DesiredPath, G, ProfileError
from desdemona.support import files

#: Standard gravity [m/s^2], what a sensor's "g" unit means (ISO 80000-3); the simulator's own gravity
#: (:data:`.path.G`, 9.81) stays what the paths and the convention check use.
STANDARD_GRAVITY = 9.80665
ACCEL_UNITS = {"g": STANDARD_GRAVITY, "m/s2": 1.0, "m/s^2": 1.0}
RATE_UNITS = {"deg/s": math.pi / 180.0, "rad/s": 1.0}
#: The written path's rate when none is given: the log's own, at most this [Hz]...
MAX_DEFAULT_RATE = 100.0
#: ... and at least this [Hz]: a slower log is interpolated to it. Every command reads a path sampled
#: at 2 Hz or slower as one whose time is in milliseconds (:func:`.csvfile.time_unit_problem`).
MIN_DEFAULT_RATE = 10.0
#: A gap between two readings longer than this many of the log's median steps is bridged by
#: interpolation with a warning (a phone's log of a coaster ride missed 0.79 s at 59 ms a reading).
GAP_STEPS = 4.0
#: A clock declared in seconds (``--time-unit s``) is taken as such up to this median step [s] (a phone's
#: log of a row a second), where an undeclared one looks like milliseconds from 0.5 s on; a slower one
#: cannot hold a motion worth cueing, and is more likely milliseconds declared wrong.
MAX_DECLARED_STEP = 2.0
#: With ``--level``, the force of a still stretch other than the first that reads more than this [deg]
#: from up after levelling is warned of (:func:`_level_note`).
LEVEL_AGREEMENT = 2.0
#: A log's median step shorter than this [s] (10 kHz) is a time unit declared too large.
MIN_STEP = 1e-4


@dataclass(frozen=True)
class LogFormat:
    """How a log is laid out: column names, units and the directions of its x, y, z axes.

    time : the time column; accel, rates : three column names each (the log's x, y, z), rates None
    for a log without angular rates (the modulus form only, :func:`from_log`);
    accel_unit : ``g`` or ``m/s2``; rate_unit : ``deg/s`` or ``rad/s``; time_unit : ``s``, ``ms``, ``us`` or ``ns``,
    None for seconds not declared: only a declared ``s`` takes a clock that steps 0.5 s or more as seconds
    (:func:`_check_time_unit`);
    axes : the cabin-frame direction of the log's x, y, z (``forward,right,down`` = vehicle body axes);
    lever_arm : (3,) [m] from the sensor to the head, in the log's axes;
    rates_file : a second CSV log that holds the rates, with a time column of the same name and unit
    (a phone logger's, which writes each sensor to a file of its own: :func:`with_rates_file`);
    inertial : the accelerometer columns hold the inertial force, the specific force's opposite (-1 g
    up at rest: Apple's Core Motion, and Sensor Logger on an iPhone unless its "Standardise Units &
    Frames" is on). No choice of right-handed axes turns all three signs, so it is a setting of its own.
    """

    time: str = "t"
    accel: tuple[str, str, str] = ("ax", "ay", "az")
    rates: tuple[str, str, str] | None = ("p", "q", "r")
    accel_unit: str = "m/s2"
    rate_unit: str = "rad/s"
    time_unit: str | None = None
    axes: tuple[str, str, str] = ("forward", "right", "down")
    lever_arm: tuple[float, float, float] = (0.0, 0.0, 0.0)
    rates_file: str | None = None
    inertial: bool = False

    @property
    def clock_unit(self) -> str:
        """The time column's unit, declared or not (``s``)."""
        return self.time_unit or "s"

    def __post_init__(self):
        units = [("--accel-unit", self.accel_unit, ACCEL_UNITS), ("--time-unit", self.clock_unit, TIME_UNITS)]
        columns = [("--accel", self.accel)]
        if self.rates is not None:  # None: a log without angular rates
            units.append(("--rate-unit", self.rate_unit, RATE_UNITS))
            columns.append(("--rates", self.rates))
        for label, value, known in units:
            if value not in known:
                raise ProfileError(f"{label} {value!r}: use one of {', '.join(known)}")
        for label, names in columns:
            if len(names) != 3:
                raise ProfileError(f"{label} {','.join(names)}: give three column names, for x, y and z")
        if self.rates_file is not None and self.rates is None:
            raise ProfileError("--rates-file holds the angular rates: name their columns with --rates")
        if len(self.lever_arm) != 3 or not all(math.isfinite(x) for x in self.lever_arm):
            raise ProfileError(f"--lever-arm {self.lever_arm}: give three numbers x,y,z in metres")
        convert.axes_rotation(self.axes)  # raises on a left-handed or degenerate set


def data_lines(file: Path) -> list[tuple[int, str]]:
    """(line number, text) of a UTF-8 CSV's lines other than blank ones and ``#`` comments; the first is
    its header. Where the first such line is all numbers, the header is the nearest ``#`` comment above it
    that names as many columns (a dataset's ``#timestamp [ns],w_RS_S_x [rad s^-1],...``), its ``#``
    dropped. Cells split by semicolons, tabs or ``|``, their numbers perhaps with a decimal comma (a
    European spreadsheet's, phyphox's, X-Plane's export), are given as commas and points
    (:func:`.csvfile.comma_lines`). A file that cannot be read, is not UTF-8, holds no line or no header
    raises :class:`ProfileError`."""
    try:
        text = file.read_bytes().decode("utf-8-sig")
    except OSError as exc:
        raise ProfileError(f"{file}: cannot read: {exc.strerror or exc}") from None
    except UnicodeDecodeError:
        raise ProfileError(f"{file}: not UTF-8 text; save it as UTF-8 CSV") from None
    numbered = csvfile.comma_lines(list(enumerate(text.splitlines(), start=1)))
    lines = [(i, line) for i, line in numbered if line.strip() and not line.lstrip().startswith("#")]
    if not lines:
        raise ProfileError(f"{file}: no header and no data")
    first, row = lines[0]
    if _numbers_only(row):  # no header line: a comment above may name the columns (EuRoC's "#timestamp [ns],...")
        comments = [(i, line.lstrip()[1:]) for i, line in reversed(numbered[:first - 1]) if line.strip()]
        named = [(i, c) for i, c in comments if len(csvfile.cells(c)) > 1 and not _numbers_only(c)]
        header = next(((i, c) for i, c in named if len(csvfile.cells(c)) == len(csvfile.cells(row))), None)
        if header is None:
            near = f": the '#' comment at line {named[0][0]} names {len(csvfile.cells(named[0][1]))} columns, the rows have " \
                f"{len(csvfile.cells(row))}" if named else ""
            raise ProfileError(f"{file}: line {first}: numbers where the header should be{near}; the first line "
                               f"that is not a '#' comment, or a '#' comment above the rows, must name the columns")
        lines[0:0] = [header]
    return lines


def _numbers_only(line: str) -> bool:
    """Whether every cell of a CSV line reads as a number (a row of data, not a header)."""
    try:
        [float(c) for c in csvfile.cells(line)]
    except ValueError:
        return False
    return True


def read_log(file: str | Path, columns: list[str], time: str | None = None) -> tuple[dict[str, np.ndarray], bool, int]:
    """The named columns of a CSV log as float arrays, keyed by the names given; whether the time column
    ``time`` holds ISO 8601 dates and times (:func:`.clock.date_seconds`) rather than numbers, as its first
    row tells; and in how many decimals of its unit it is counted. The time column is read exactly
    (:mod:`.clock`): dates as whole microseconds since 1970 (6 decimals of a second), numbers written
    with a decimal point or none as integer counts of their last decimal (``1691185678.25``: 2), where
    float64 would lose the last digits of a clock from 1970; others as floats (0). ``#`` lines are
    comments; the first other line names the columns, or the comment above it (:func:`data_lines`),
    where a name may be given with its ``#`` too. A missing column, a cell that is not a number (or not
    a date where the first row's is), fewer than two rows raise :class:`ProfileError` naming them (and
    the log's columns)."""
    file = Path(file)
    lines = data_lines(file)
    header = csvfile.cells(lines[0][1])
    given, columns = columns, [c[1:].strip() if c not in header and c.startswith("#") else c for c in columns]
    missing = [c for c in columns if c not in header]
    if missing:
        raise ProfileError(f"{file}: no column{'s' if len(missing) > 1 else ''} {', '.join(map(repr, missing))}; "
                           f"the log's columns are {', '.join(header)} (name them with --time, --accel, --rates)")
    index = [header.index(c) for c in columns]
    first = csvfile.cells(lines[1][1]) if len(lines) > 1 else []
    column = index[given.index(time)] if time in given else -1
    when = clock.when(first[column]) if 0 <= column < len(first) and not _numbers_only(first[column]) else None
    time_reader = (clock.number_reader("is not a number, nor a date and time (ISO 8601's 2023-08-04 17:47:58-04:00, "
                                       "MATLAB's 04-Aug-2023 21:47:58.250)")
                   if when is None else clock.date_reader(when.tzinfo is not None))
    parsers = [time_reader if k == column else clock.number_reader("is not a number") for k in index]
    rows, counts = [], clock.Counts() if column >= 0 and when is None else None
    for number, line in lines[1:]:
        cells = next(csv.reader([line]))
        values = []
        for name, k, parse in zip(columns, index, parsers):
            cell = cells[k].strip() if k < len(cells) else ""
            try:
                values.append(parse(cell))
            except ValueError as exc:
                what = "no value" if not cell else f"{cell!r} {exc}"
                raise ProfileError(f"{file}: line {number}: column {name!r}: {what}, in {line.strip()!r}") from None
        if not all(math.isfinite(v) for v in values):
            raise ProfileError(f"{file}: line {number}: not a finite number (NaN or inf) in {line.strip()!r}")
        rows.append(values)
        if counts is not None:
            counts.add(cells[column].strip())
    if len(rows) < 2:
        raise ProfileError(f"{file}: needs at least two rows of data, found {len(rows)}")
    data = np.array(rows)
    read = {c: data[:, k] for k, c in enumerate(given)}
    exact = counts.counts() if counts is not None else None
    if exact is not None:
        read[time] = exact[0]
    return read, when is not None, clock.DATE_DECIMALS if when is not None else 0 if exact is None else exact[1]


def from_log(file: str | Path, fmt: LogFormat = LogFormat(), start: float | None = None,
             end: float | None = None, rate: float | None = None, modulus: bool = False,
             check: bool = True, to_g: bool = False, zero_rates: bool = False,
             level: bool = False) -> tuple[DesiredPath, list[str]]:
    """The desired path of a logged motion (see the module's docstring) from ``start`` to ``end`` [s of
    the log's time] (None: all), at ``rate`` [Hz] (None: the log's own, at least
    :data:`MIN_DEFAULT_RATE` and at most :data:`MAX_DEFAULT_RATE`), its time 0 at the crop's start;
    with ``modulus`` its ``t,M`` form. Returns the path and its ``source:`` comment lines. The time
    column may hold ISO 8601 dates and times (:func:`read_log`), and ``start``, ``end`` are then
    seconds since 1970 (:func:`date_seconds`).

    With ``check`` the convention check runs on the whole log (:func:`.convert.check_convention`); a log
    with no still stretch cannot be checked and is refused unless ``check`` is False. A log without
    rates (``fmt.rates`` None) gives only the modulus form (``modulus``); its check reads only |f| (1 g
    at rest, in whatever axes) over its longest stretch of steady force. ``to_g``: the readings are
    scaled so that the still stretch reads 1 g (a sensor whose scale is off: a phone read 0.90-0.96 g
    in a coaster's station), within the check's 0.8-1.25 g. ``zero_rates``: the rates' mean where the
    log is still (a gyro's bias, up to :data:`.convert.MAX_GYRO_BIAS`) is taken off every rate, before
    the lever arm and the check (:func:`gyro_bias`). ``level``: forces and rates are turned by the
    smallest rotation that makes the still force read straight up (:func:`.convert.levelling`), for a
    sensor mounted at an angle to the vehicle.
    """
    file = Path(file)
    _refuse_combinations(fmt, modulus, check, to_g, zero_rates, level)
    origin, t, f, omega, dated, notes = _readings(file, fmt)
    logged = t  # the times with a reading, before the grid bridges the gaps between them
    R = convert.axes_rotation(fmt.axes)
    f = convert.turn_to_cabin(f * (ACCEL_UNITS[fmt.accel_unit] * (-1.0 if fmt.inertial else 1.0)), R)
    omega = np.zeros_like(f) if omega is None else convert.turn_to_cabin(omega * RATE_UNITS[fmt.rate_unit], R)
    t, X = convert.uniform_grid(t, np.column_stack([omega, f]))
    native = 1.0 / float(np.median(np.diff(t)))
    rate = min(max(native, MIN_DEFAULT_RATE), MAX_DEFAULT_RATE) if rate is None else float(rate)
    if not rate > 1.0 / csvfile.MS_MEDIAN_STEP:
        raise ProfileError(f"--rate {rate:g}: give more than {1.0 / csvfile.MS_MEDIAN_STEP:g} samples per second (a "
                           f"path sampled that slowly is read as one whose time is in milliseconds)")
    bias = gyro_bias(file, fmt, t, X, rate, logged, origin, dated) if zero_rates else None
    if bias is not None:
        X[:, :3] -= bias.omega_cabin
    # read before the lever arm, whose force such rates would swamp; said after the convention check,
    # whose words on a log that is nowhere still come first
    unit = fmt.rates is not None and turns.rate_unit_problem(t, X[:, :3], X[:, 3:], fmt.rate_unit)
    r_cabin = R @ np.asarray(fmt.lever_arm, dtype=float)
    if np.any(r_cabin != 0):
        X[:, 3:] = head_force(X[:, :3], X[:, 3:], r_cabin, native)
    t, X = convert.resample(t, X, rate, antialias="gaussian")
    scale = 1.0
    if check:
        still, later = _convention_checked(file, fmt, t, X, logged, origin, level, dated)
        if to_g:
            scale = G / float(np.linalg.norm(still.f_cabin))
            X[:, 3:] *= scale
        if level:
            turn = convert.levelling(still.f_cabin)
            tilt = math.degrees(math.acos(min(1.0, float(turn[2, 2]))))
            X = np.column_stack([X[:, :3] @ turn.T, X[:, 3:] @ turn.T])
            notes = notes + _level_note(still, later, turn, tilt, origin, dated)
    if unit:
        raise ProfileError(f"{file}: {unit}")
    lo, t, X = _cropped(file, t, X, start, end, origin, dated)
    convert.check_no_crash(origin + lo + t, X[:, 3:], str(file))
    a, b = origin + lo, origin + lo + float(t[-1])
    span = f"{clock.text(a, True)} to {clock.text(b, True)}" if dated else f"{convert.seconds(a)}-{convert.seconds(b)} s"
    path = convert.make_path(file.stem, t, X[:, :3], X[:, 3:], f"log {file.name}, {span}", modulus)
    changes = [f"readings scaled by {scale:.4f} to read 1 g where still (--to-g)"] if to_g else []
    if level:
        changes.append(f"turned by {tilt:.3g} deg so that the force reads straight up where still (--level)")
    if bias is not None:
        rates = ", ".join(f"{math.degrees(x):.3g}" for x in bias.omega_cabin)
        changes.append(f"rates less their bias ({rates}) deg/s in the cabin's x,y,z before any --level, read still "
                       f"from {clock.text(origin + bias.t0, dated)} (--zero-rates)")
    comments = _source_lines(file, fmt, span, f"{convert.filter_note(native, rate, 'gaussian')}; convention check "
                             f"{'passed' if check else 'skipped (--no-check)'}", changes, modulus, dated)
    gap = longest_gap(logged, lo, lo + float(t[-1]))
    slow = native < 1.0 / csvfile.MS_MEDIAN_STEP  # a clock from 1970 in its unit (_check_time_unit)
    return path, comments + ([] if gap is None else [
        f"warning: no reading for {gap[0]:.3g} s from {clock.text(origin + gap[1], dated)} of the log's time "
        f"({gap[0] / gap[2]:.0f} of its median steps of {gap[2]:.3g} s), bridged by a straight line"]) + (
        [f"warning: the log has a reading every {1 / native:.3g} s: what changes faster than {native / 2:.3g} Hz "
         f"(a bump, a gear change, the onset of a brake) is not in it"] if slow else []) + [
        f"warning: {note}" for note in notes]


def _read_clock(file: Path, fmt: LogFormat, columns: list[str],
                both: bool = False) -> tuple[float, dict[str, np.ndarray], bool, list[str]]:
    """(the first time [s of the log's clock], :func:`read_log` of the time column and ``columns``, whether
    the clock holds dates, warnings), the times in seconds from the first (their differences taken in
    the clock's exact counts first, :func:`.clock.seconds_from_first`).
    Refused where the time does not increase or is in a unit other than declared
    (:func:`_check_time_unit`; ``both``: the unit is declared for this file and the accelerometer's both,
    and the refusal says so). A warning where the clock reads a date from 1970 in another unit only
    (:func:`_unit_note`)."""
    data, dated, decimals = read_log(file, [fmt.time, *columns], time=fmt.time)
    if dated and fmt.clock_unit != "s":
        raise ProfileError(f"{file}: column {fmt.time!r} holds dates and times, read as seconds since 1970: "
                           f"drop --time-unit {fmt.clock_unit}")
    origin, t = clock.seconds_from_first(data[fmt.time], decimals, fmt.clock_unit)
    data[fmt.time] = t
    steps = np.diff(t)
    if np.any(steps <= 0):
        k, back = int(np.argmax(steps <= 0)), int(np.sum(steps <= 0))
        many = (f"; so on {back} of its {len(steps)} steps: the rows of two sensors interleaved (an IMU instance "
                f"column, ArduPilot's I)? keep one sensor's rows") if back >= max(10, 0.1 * len(steps)) else ""
        raise ProfileError(f"{file}: column {fmt.time!r}: time {clock.text(origin + t[k + 1], dated)} at data row "
                           f"{k + 2} does not increase (previous {clock.text(origin + t[k], dated)}){many}")
    _check_time_unit(file, fmt, t, origin, "; --time-unit is the unit of both files' clocks" if both else "")
    return origin, data, dated, [] if dated else _unit_note(fmt, origin)


def _unit_note(fmt: LogFormat, origin: float) -> list[str]:
    """A warning where the log's first time, ``origin`` [s] as read in its declared unit, is no date
    (:data:`.clock.EPOCH_DATES`) but would be one in another unit: seconds since 1970 declared as
    milliseconds pass every check of a long log, a thousand times too short. Not a refusal: a clock since
    the sensor started may too."""
    if clock.is_date(origin):
        return []
    first = origin / TIME_UNITS[fmt.clock_unit]  # the number the column holds
    other = next((u for u, seconds in TIME_UNITS.items() if clock.is_date(first * seconds)), None)
    if other is None:
        return []
    return [f"column {fmt.time!r} read as {fmt.clock_unit} starts {clock.text(origin, True)}; read as "
            f"{other} it starts {clock.text(first * TIME_UNITS[other], True)}: if its clock counts from 1970, declare "
            f"--time-unit {other}"]


def _readings(file: Path, fmt: LogFormat) -> tuple[float, np.ndarray, np.ndarray, np.ndarray | None, bool, list[str]]:
    """(the first time [s of the log's clock], the times [s from it], forces (N, 3), rates (N, 3) or None,
    whether the clock holds dates, warnings) of the log, in its units and axes; the rates from
    ``fmt.rates_file`` where it names one (:func:`with_rates_file`), and then the times those rates cover."""
    own_rates = fmt.rates if fmt.rates is not None and fmt.rates_file is None else ()
    origin, data, dated, notes = _read_clock(file, fmt, [*fmt.accel, *own_rates])
    t, f = data[fmt.time], np.column_stack([data[c] for c in fmt.accel])
    if fmt.rates_file is None:
        return origin, t, f, np.column_stack([data[c] for c in own_rates]) if own_rates else None, dated, notes
    keep, omega, more = with_rates_file(file, fmt, origin, t, dated)
    return origin + t[keep][0], t[keep] - t[keep][0], f[keep], omega, dated, notes + more


def with_rates_file(file: Path, fmt: LogFormat, origin: float, t: np.ndarray,
                    dated: bool) -> tuple[np.ndarray, np.ndarray, list[str]]:
    """(which of the accelerometer log's times ``t`` [s from ``origin``] the rates cover, the rates (K, 3)
    at those times, warnings): ``fmt.rates_file``'s, interpolated linearly, over the span both logs
    cover (a phone logger writes the accelerometer and the gyroscope to files of their own, each at its
    own instants; a clock of dates and one of seconds since 1970 are the same clock). Refused where it
    is the log itself, where its clock is not the log's (no common span of a second), or where it has
    a gap of more than :data:`GAP_STEPS` of its median steps within that span. A warning where it
    covers less of the log than the log's first and last steps, or is read 2 Hz or slower."""
    other = Path(fmt.rates_file)
    if files.same_file(other, file):
        raise ProfileError(f"--rates-file {other}: is the accelerometer's log itself; name the gyroscope's file")
    origin_r, rates, other_dated, _ = _read_clock(other, fmt, list(fmt.rates), both=True)  # its clock's unit: the log's
    tr = rates[fmt.time] + (origin_r - origin)  # on the accelerometer log's count
    lo, hi = max(t[0], tr[0]), min(t[-1], tr[-1])
    where = lambda x: clock.text(origin + x, dated)  # noqa: E731
    if not hi - lo >= 1.0:
        raise ProfileError(f"{other}: its rates run from {clock.text(origin_r, other_dated)} to "
                           f"{clock.text(origin_r + rates[fmt.time][-1], other_dated)}, the log {file.name} from "
                           f"{where(0.0)} to {where(t[-1])}: no common second; is column {fmt.time!r} the same "
                           f"clock in both?")
    gap = longest_gap(tr, lo, hi)
    if gap is not None:
        raise ProfileError(f"{other}: no rate reading for {gap[0]:.3g} s from {where(gap[1])} "
                           f"({gap[0] / gap[2]:.0f} of its median steps of {gap[2]:.3g} s)")
    keep = (t >= lo) & (t <= hi)
    step, step_r = float(np.median(np.diff(t))), float(np.median(np.diff(tr)))
    notes = [f"the rates of {other.name} cover {where(lo)} to {where(hi)} of the log's {where(0.0)} to "
             f"{where(t[-1])}: the path is cut to them"] if lo - t[0] > step or t[-1] - hi > step else []
    if step_r >= csvfile.MS_MEDIAN_STEP:
        notes.append(f"{other.name} has a rate reading every {step_r:.3g} s: a turn's onset and end are "
                     f"spread over that, out of step with the force")
    return keep, np.column_stack([np.interp(t[keep], tr, rates[c]) for c in fmt.rates]), notes


def _cropped(file: Path, t, X, start: float | None, end: float | None, origin: float, dated: bool = False):
    """(the crop's start, its times from 0, its samples) of the grid ``t`` [s from the log's first
    time, ``origin`` on the log's clock], ``X``, from ``start`` to ``end`` [s of the log's clock].
    A start or end outside the log by more than a step is refused: on a clock from 1970 ``--start 5``
    would otherwise import the whole log (:func:`.convert.crop`)."""
    step = float(t[1] - t[0])
    for option, when in (("--start", start), ("--end", end)):
        if when is not None and not -step <= float(when) - origin <= float(t[-1]) + step:
            given = clock.text(when, dated) if dated else convert.seconds(when)
            hint = f" (give {option} as a date and time, as the log's)" if dated and when < clock.EPOCH_DATES[0] else ""
            raise ProfileError(f"{file}: {option} {given}: outside the log, which runs from "
                               f"{clock.text(origin, dated)} to {clock.text(origin + t[-1], dated)} of its own clock{hint}")
    lo = 0.0 if start is None else float(start) - origin
    t, X = convert.crop(t, X, lo, None if end is None else float(end) - origin, str(file),
                        lambda x: clock.text(origin + x, dated))
    return lo, t, X


def _refuse_combinations(fmt: LogFormat, modulus: bool, check: bool, to_g: bool, zero_rates: bool,
                         level: bool) -> None:
    """Refuse the options of :func:`from_log` that cannot go together, naming the fix."""
    if fmt.rates is None and not modulus:
        raise ProfileError("--rates none: without angular rates a log gives only the modulus form t,M (dfs): "
                           "add --modulus, or name the rate columns with --rates")
    for option, wanted in (("--lever-arm", any(fmt.lever_arm)), ("--zero-rates", zero_rates), ("--level", level)):
        if fmt.rates is None and wanted:
            raise ProfileError(f"{option} needs the angular rates: name the rate columns with --rates")
    for option, wanted in (("--to-g", to_g), ("--zero-rates", zero_rates), ("--level", level)):
        if wanted and not check:
            raise ProfileError(f"{option} reads the still stretch that the convention check finds: drop --no-check")


def _source_lines(file: Path, fmt: LogFormat, span: str, filtered: str, changes: list[str],
                  modulus: bool, dated: bool = False) -> list[str]:
    """The ``source:`` comment lines of an imported log: its columns and units, its axes and lever arm,
    the crop, the filter and the check, and what was changed in the readings."""
    rates = "none" if fmt.rates is None else f"{','.join(fmt.rates)} [{fmt.rate_unit}]" + (
        "" if fmt.rates_file is None else f" from {Path(fmt.rates_file).name}")
    time = "date and time" if dated else fmt.clock_unit
    accel = fmt.accel_unit + (", inertial: sign turned" if fmt.inertial else "")
    return [f"source: log {file.name}, columns time {fmt.time} [{time}], accel {','.join(fmt.accel)} [{accel}], "
            f"rates {rates}",
            f"source: axes {','.join(fmt.axes)} for the log's x,y,z -> cabin (right,forward,up); lever arm "
            f"sensor->head {','.join(f'{x:g}' for x in fmt.lever_arm)} m (log axes)",
            f"source: crop {span} of the log's time (t = 0 here), {filtered}"
            + "".join(f"; {change}" for change in changes) + ("; modulus |f| only" if modulus else "")]


def gyro_bias(file: Path, fmt: LogFormat, t, X, rate: float, logged, origin: float,
              dated: bool = False) -> convert.Still:
    """The first still stretch of the log's grid (``t``, ``X`` = omega, f in the cabin frame, before the
    anti-alias filter to ``rate`` [Hz]) read with the rates about their mean, the gyro's bias
    (:func:`.convert.find_still`, ``biased``): a resting MEMS gyro reads a few deg/s, which would be
    cued as a turn. Refused where the log is nowhere still, or its rates are not steady there, saying
    what the rates read (:func:`_rates_hint`)."""
    tr, Xr = convert.resample(t, X, rate, antialias="gaussian")  # noise filtered as the check will see it
    still = convert.find_still(tr, Xr[:, :3], Xr[:, 3:], usable=measured(tr, logged), biased=True)
    if still is None:
        raise ProfileError(f"{file}: --zero-rates: the log is nowhere still for {convert.STILL_SECONDS:g} s (a "
                           f"steady force, rates steady within {math.degrees(convert.STILL_RATE):g} deg/s of a mean "
                           f"below {math.degrees(convert.MAX_GYRO_BIAS):g} deg/s): no bias to read"
                           f"{_rates_hint(fmt, tr, Xr, logged, origin, dated)}")
    return still


def _convention_checked(file: Path, fmt: LogFormat, t, X, logged, origin: float, level: bool = False,
                        dated: bool = False) -> tuple[convert.Still, list[convert.Still]]:
    """The still stretch of the log's grid (``t``, ``X`` = omega, f in the cabin frame), whose force
    the convention check has passed: +1 g up, or 1 g in whatever direction without rates, over the
    longest steady stretch (:func:`.convert.find_still`), never across a gap (:func:`measured`); and the
    later still stretches where ``level`` reads the first (else none). With ``level`` the force may lie
    up to :data:`.convert.MAX_TILT_DEG` from up (a sensor mounted at an angle; without it
    :data:`.convert.UP_TOLERANCE_DEG`, a vehicle parked on a slope), and the stretch is the first still
    one: a log starts at rest, and a steady acceleration is as still (:func:`_level_note`)."""
    usable = measured(t, logged)
    if level:
        later = convert.find_still(t, X[:, :3], X[:, 3:], usable=usable, every=True)
        still, later = (later[0], later[1:]) if later else (None, [])
    else:
        still, later = convert.find_still(t, X[:, :3], X[:, 3:], usable=usable, longest=fmt.rates is None), []
    if still is None:
        steady, what = ("a steady force", "units") if fmt.rates is None else \
            (f"rates below {math.degrees(convert.STILL_RATE):g} deg/s and a steady force", "axes and units")
        hint = _rates_hint(fmt, t, X, logged, origin, dated)
        raise ProfileError(f"{file}: the convention check cannot run: the log is nowhere still for "
                           f"{convert.STILL_SECONDS:g} s ({steady}){hint}; else check its {what} by hand and add "
                           f"--no-check")
    try:
        convert.check_convention(replace(still, t0=origin + still.t0, t1=origin + still.t1),
                                 ",".join(fmt.axes) + " for the log's x,y,z" + (
                                     ", the default, a vehicle's body axes; a phone lying flat, screen up, its "
                                     "top forward: --axes right,forward,up" if fmt.axes == LogFormat.axes else ""),
                                 up=None if fmt.rates is None else (0.0, 0.0, 1.0),
                                 tolerance=convert.MAX_TILT_DEG if level else convert.UP_TOLERANCE_DEG,
                                 tilt_fix="" if level else
                                 f"; --level turns a sensor mounted at up to {convert.MAX_TILT_DEG:g} deg upright",
                                 down_fix="" if fmt.inertial else "; or, where the axes are right, the readings "
                                 "are the inertial force, -1 g up at rest (an iPhone's Core Motion): --inertial",
                                 when=(lambda x: clock.text(x, True)) if dated else None)
    except ProfileError as exc:
        raise ProfileError(f"{file}: {exc}") from None
    return still, later


def _level_note(still: convert.Still, later: list[convert.Still], turn, tilt: float, origin: float,
                dated: bool) -> list[str]:
    """A warning where a still stretch after the first, which ``--level`` read (``still``) and turned
    ``tilt`` [deg] by ``turn`` to read straight up, reads more than :data:`LEVEL_AGREEMENT` from up once
    turned (``later``, as found before the turn: a turn changes no stretch's stillness): the farthest of
    them. One of the two is a steady acceleration or a slope, not the rest."""
    off = [(math.degrees(math.acos(min(1.0, float((turn @ s.f_cabin)[2] / np.linalg.norm(s.f_cabin))))), s)
           for s in later]
    angle, other = max(off, key=lambda pair: pair[0], default=(0.0, None))
    if angle <= LEVEL_AGREEMENT:
        return []
    when = lambda x: clock.text(origin + x, dated)  # noqa: E731
    return [f"--level turned the log by {tilt:.3g} deg to read straight up from {when(still.t0)} to "
            f"{when(still.t1)}, the first still stretch; from {when(other.t0)} to {when(other.t1)} it is as "
            f"still but reads {angle:.3g} deg from up: one of them is a steady acceleration or a slope, not "
            f"the rest (crop the log with --start to begin at rest)"]


def _rates_hint(fmt: LogFormat, t, X, logged, origin: float, dated: bool = False) -> str:
    """Why a log with rates may be nowhere still, where the rates say: a steady rate where the force is
    steady (a gyro's bias, for --zero-rates; beyond one, a turn or deg/s declared as rad/s), or rates
    that would be still in deg/s."""
    if fmt.rates is None:
        return ""
    usable = measured(t, logged)
    steady = convert.find_still(t, X[:, :3], X[:, 3:], usable=usable, biased=True, max_bias=np.inf)
    if steady is not None:
        rates = ", ".join(f"{math.degrees(x):.3g}" for x in steady.omega_cabin)
        where = (f"; from {clock.text(origin + steady.t0, dated)} the force is steady and the rates read a steady "
                 f"({rates}) deg/s")
        if np.linalg.norm(steady.omega_cabin) <= convert.MAX_GYRO_BIAS:
            return f"{where} (cabin x,y,z): a gyro's bias? --zero-rates takes it off"
        return (f"{where}, more than a gyro's bias ({math.degrees(convert.MAX_GYRO_BIAS):g} deg/s): a steady turn, "
                f"or the rates in deg/s declared as {fmt.rate_unit}?")
    if fmt.rate_unit == "rad/s" and convert.find_still(t, np.radians(X[:, :3]), X[:, 3:], usable=usable) is not None:
        return "; read as deg/s the rates are still: are they in deg/s, declared as rad/s (--rate-unit deg/s)?"
    return ""


def longest_gap(logged, lo: float, hi: float) -> tuple[float, float, float] | None:
    """The longest time without a reading between ``lo`` and ``hi`` [s of the log's time] as (its length,
    where it starts, the log's median step) [s], where longer than :data:`GAP_STEPS` median steps, else None."""
    logged = np.asarray(logged, dtype=float)
    median = float(np.median(np.diff(logged)))
    inside = logged[(logged >= lo - median) & (logged <= hi + median)]
    if len(inside) < 2:
        return None
    steps = np.diff(inside)
    k = int(np.argmax(steps))
    return (float(steps[k]), float(inside[k]), median) if steps[k] > GAP_STEPS * median else None


def measured(grid, logged) -> np.ndarray:
    """(N,) bool: the ``grid`` times [s] within one of the log's median steps of a reading (``logged``),
    not in a gap the grid bridges by interpolation: a straight line across a gap looks as steady as a
    rest (a coaster's log with 40 s missing before its ride was taken to be still at 1.5 g)."""
    grid, logged = np.asarray(grid, dtype=float), np.asarray(logged, dtype=float)
    k = np.clip(np.searchsorted(logged, grid), 1, len(logged) - 1)
    nearest = np.minimum(np.abs(grid - logged[k - 1]), np.abs(logged[k] - grid))
    return nearest <= float(np.median(np.diff(logged))) * (1.0 + 1e-9)


def _check_time_unit(file: Path, fmt: LogFormat, t: np.ndarray, origin: float = 0.0, also: str = "") -> None:
    """Refuse a time column in a unit other than declared (:func:`_time_problem`, on the times in
    seconds ``t`` from the first, ``origin`` [s]): a unit 1000 times smaller (milliseconds declared as
    seconds), a span of days, or steps shorter than :data:`MIN_STEP` (microseconds declared as
    nanoseconds: a log of 16 ms at 200 kHz). The refusal names the first unit under which the same
    rule passes. A log sampled at 2 Hz or slower whose clock reads a date (:data:`.clock.EPOCH_DATES`),
    or whose unit is declared and steps at most :data:`MAX_DECLARED_STEP`, is in its unit: its slowness
    is a warning of :func:`from_log`, not a unit."""
    problem = _time_problem(t)
    declared = fmt.time_unit is not None and float(np.median(np.diff(t))) <= MAX_DECLARED_STEP
    if problem is None or (problem == "ms" and (clock.is_date(origin) or declared)):
        return
    where = f"{file}: column {fmt.time!r} [{fmt.clock_unit}]"
    likely = next((unit for unit, seconds in TIME_UNITS.items()  # the first under which the check passes
                   if _time_problem(t * seconds / TIME_UNITS[fmt.clock_unit]) is None), None)
    fix = (f"declare --time-unit {likely}" if likely else "check the column") + also
    if problem == "days":
        duration = float(t[-1] - t[0])
        raise ProfileError(f"{where} spans {duration:.3g} s ({duration / 86400:.3g} days), far longer than a "
                           f"session (minutes): wrong time column? Else {fix}")
    if problem == "fast":
        raise ProfileError(f"{where}: {csvfile.describe_steps(t)} read as {fmt.clock_unit}, sampled at "
                           f"{1e-3 / float(np.median(np.diff(t))):.3g} kHz: {fix}")
    if fmt.clock_unit == "s":
        raise ProfileError(f"{where} looks like milliseconds: {csvfile.describe_steps(t)}; a recording is sampled "
                           f"faster than {1 / csvfile.MS_MEDIAN_STEP:g} Hz: {fix}" + ("" if fmt.time_unit else
                           f" (a log truly read that seldom, at most every {MAX_DECLARED_STEP:g} s: declare --time-unit s)"))
    raise ProfileError(f"{where}: {csvfile.describe_steps(t)} read as {fmt.clock_unit}; a recording is sampled "
                       f"faster than {1 / csvfile.MS_MEDIAN_STEP:g} Hz: {fix}")


def _time_problem(t: np.ndarray) -> str | None:
    """The CSV reader's rule on times ``t`` [s] (:func:`.csvfile.time_unit_problem`: ``"days"`` or
    ``"ms"``), and ``"fast"``: a median step shorter than :data:`MIN_STEP`; None where none applies."""
    problem = csvfile.time_unit_problem(t)
    return problem if problem is not None or float(np.median(np.diff(t))) >= MIN_STEP else "fast"


def head_force(omega, f_sensor, r, rate_hz: float) -> np.ndarray:
    """Specific force at the head (N, 3) [m/s^2] from the sensor's, for a rigid vehicle:
    ``f_head = f_sensor + alpha x r + omega x (omega x r)``, ``r`` (3,) [m] from the sensor to the head,
    ``omega`` (N, 3) [rad/s] on a uniform grid at ``rate_hz``; ``alpha`` is the derivative of ``omega``
    low-passed at :data:`.convert.ALPHA_CUTOFF_HZ` (a derivative amplifies sensor noise). All in one
    frame."""
    smooth = convert.lowpass(omega, rate_hz, convert.ALPHA_CUTOFF_HZ)
    alpha = np.gradient(smooth, 1.0 / rate_hz, axis=0)
    return f_sensor + np.cross(alpha, r) + np.cross(omega, np.cross(omega, r))

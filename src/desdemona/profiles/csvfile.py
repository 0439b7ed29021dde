"""Desired paths as CSV files: the strict reader and the writer (columns ``t,wx,wy,wz,fx,fy,fz`` or
``t,M``, SI units, ``#`` comments, an optional ``# weights:`` line)."""

from __future__ import annotations

import csv
import io
import math
import re
from pathlib import Path

import numpy as np

from desdemona.profiles.path import (MAX_ANGULAR_VELOCITY, MAX_SPECIFIC_FORCE, MODULUS_COLUMNS, PATH_COLUMNS,
                                     DesiredPath, G, ProfileError)
from desdemona.profiles.weights import _weight_numbers

#: |omega| [rad/s] that a path may not keep for :data:`SUSTAINED_FOR` [s] or longer: rates in deg/s.
MAX_SUSTAINED_RATE = 10.0
SUSTAINED_FOR = 1.0
#: The median of |f| [m/s^2] of a path written in g (with at most half a g in all): 1 g within the
#: tolerance of a log's rest (:data:`.convert.MAGNITUDE_TOLERANCE`).
G_LIKE_MEDIAN = (0.8, 1.25)

#: A log's cells are split by one of these (:func:`comma_lines`; ``|``: X-Plane's Data.txt).
DELIMITERS = (",", ";", "\t", "|")
#: A number written with a decimal comma, in a log whose cells are not split by commas.
_DECIMAL_COMMA = re.compile(r"^([+-]?\d*),(\d+(?:[eE][+-]?\d+)?)$")


def read_csv(path: str | Path) -> DesiredPath:
    """Read a desired path from CSV: columns ``t,wx,wy,wz,fx,fy,fz`` (SI) or ``t,M``, in any order; ``#``
    comments; UTF-8, with or without the byte-order mark spreadsheet programs write.

    Strict: every problem (missing or unknown column, a value that is not a finite number, time not
    strictly increasing, fewer than two rows, a negative modulus, |f| above 100 g, |omega| above
    50 rad/s or above 10 rad/s for a second, forces that read like g, a time column that looks like
    milliseconds) raises :class:`ProfileError` naming the file
    and the line or column.
    """
    path = Path(path)
    try:
        text = path.read_bytes().decode("utf-8-sig")
    except OSError as exc:
        raise ProfileError(f"{path}: cannot read: {exc.strerror or exc}") from None
    except UnicodeDecodeError as exc:
        line = path.read_bytes()[: exc.start].count(b"\n") + 1
        raise ProfileError(f"{path}: line {line}: not UTF-8 text (byte 0x{exc.object[exc.start]:02x}); "
                           f"save it as UTF-8 CSV") from None
    weights = _header_weights(path, text)
    lines = [(i + 1, line) for i, line in enumerate(text.splitlines())
             if line.strip() and not line.lstrip().startswith("#")]
    if not lines:
        raise ProfileError(f"{path}: no header and no data")
    header_line, header = lines[0]
    columns = [c.strip() for c in next(csv.reader([header]))]
    layout = next((cols for cols in (PATH_COLUMNS, MODULUS_COLUMNS) if sorted(columns) == sorted(cols)), None)
    if layout is None:
        missing = [c for c in (MODULUS_COLUMNS if "M" in columns else PATH_COLUMNS) if c not in columns]
        unknown = [c for c in columns if c not in PATH_COLUMNS + MODULUS_COLUMNS]
        repeated = [c for c in columns if columns.count(c) > 1]
        detail = (f"unknown column {unknown[0]!r}" if unknown else f"column {repeated[0]!r} twice" if repeated
                  else f"missing column {missing[0]!r}" if missing else "a modulus M with the full path")
        separator = next((c for c in ";\t|" if c in header), None)
        if separator is not None:
            detail += (f" (separator {separator!r}? the file must be comma-separated with '.' as the decimal "
                       f"point, as a spreadsheet's 'CSV UTF-8' export writes)")
        raise ProfileError(f"{path}: line {header_line}: {detail}; the columns must be "
                           f"'{','.join(PATH_COLUMNS)}' or '{','.join(MODULUS_COLUMNS)}' (SI units, any order)")
    rows = []
    for number, line in lines[1:]:
        cells = next(csv.reader([line]))
        if len(cells) != len(columns):
            hint = (" (a decimal comma? the file must be comma-separated with '.' as the decimal point)"
                    if len(cells) > len(columns) else "")
            raise ProfileError(f"{path}: line {number}: {len(cells)} values for {len(columns)} columns{hint}")
        try:
            values = [float(c) for c in cells]
        except ValueError:
            hint = "; the file must be comma-separated with '.' as the decimal point" if ";" in line else ""
            raise ProfileError(f"{path}: line {number}: not a number in {line.strip()!r}{hint}") from None
        bad = [columns[k] for k, v in enumerate(values) if not math.isfinite(v)]
        if bad:
            raise ProfileError(f"{path}: line {number}: {bad[0]} is not a finite number (NaN or inf)")
        rows.append(values)
    if len(rows) < 2:
        raise ProfileError(f"{path}: needs at least two rows of data, found {len(rows)}")
    data = np.array(rows)[:, [columns.index(c) for c in layout]]  # reordered as ``layout``
    t = data[:, 0]
    steps = np.diff(t)
    if np.any(steps <= 0):
        k = int(np.argmax(steps <= 0))
        raise ProfileError(f"{path}: line {lines[k + 2][0]}: time {t[k + 1]:g} s does not increase "
                           f"(previous {t[k]:g} s)")
    _check_time_unit(path, t)
    name = path.stem
    # a file whose time starts later is read from its first time as t = 0, and says so where it is described
    described = f"read from {path.name}" + (f", its time from {t[0]:g} s as t = 0" if t[0] != 0 else "")
    if layout == MODULUS_COLUMNS:
        negative = data[:, 1] < 0
        if np.any(negative):
            k = int(np.argmax(negative))
            raise ProfileError(f"{path}: line {lines[k + 1][0]}: M = {data[k, 1]:g} m/s^2 is negative; the "
                               f"modulus |f| is >= 0")
        read = DesiredPath(name, t - t[0], None, modulus=data[:, 1], description=described)
    else:
        read = DesiredPath(name, t - t[0], data[:, 1:], weights=weights, description=described)
    check_units(read, lambda k: f"{path}" if k is None else f"{path}: line {lines[k + 1][0]}")
    return read


def _header_weights(path, text: str) -> tuple[float, ...]:
    """The weights a CSV file carries in a comment line ``# weights: wx,wy,wz,fx,fy,fz`` (at most one;
    strict, see :func:`weights_for`), else Q = I."""
    found = [(i + 1, line.lstrip()[1:].strip()) for i, line in enumerate(text.splitlines())
             if line.lstrip().startswith("#") and line.lstrip()[1:].strip().lower().startswith("weights")]
    if not found:
        return (1.0,) * 6
    if len(found) > 1:
        raise ProfileError(f"{path}: line {found[1][0]}: a second weights line (the first is line {found[0][0]})")
    number, comment = found[0]
    key, colon, value = comment.partition(":")
    if not colon or key.strip().lower() != "weights":
        raise ProfileError(f"{path}: line {number}: write the weights as '# weights: wx,wy,wz,fx,fy,fz'")
    try:
        return tuple(_weight_numbers([float(c) for c in value.split(",")]))
    except (ValueError, ProfileError) as exc:
        detail = str(exc) if isinstance(exc, ProfileError) else f"not a number in {value.strip()!r}"
        raise ProfileError(f"{path}: line {number}: {detail}") from None


# A time column in milliseconds read as seconds. Judged by the sampling step as well as the length: a
# recording is sampled at 10-1000 Hz, so in milliseconds its median step is 1-100, which read as
# seconds is 2 Hz or slower, useless for cueing (cues live in 0.1-10 Hz). A few rows that far apart
# are a hand-written table of breakpoints (t = 0, 2, 5, 10 s), not a recording: the step alone decides
# from MS_MIN_ROWS samples on; fewer are refused only when they span over an hour (a session lasts
# minutes, and as seconds either would ask for tens of thousands of control intervals).
MS_DURATION = 3600.0  # [s]
MS_MEDIAN_STEP = 0.5  # [s]
MS_MIN_ROWS = 20


def _check_time_unit(path: Path, t: np.ndarray) -> None:
    """Refuse a time column that spans more than 1000 x MS_DURATION s, or looks like milliseconds: a
    median step of MS_MEDIAN_STEP s or more over at least MS_MIN_ROWS samples (a recording sampled at
    2 Hz or slower), or over more than MS_DURATION s."""
    problem = time_unit_problem(t)
    if problem == "days":
        duration = float(t[-1] - t[0])
        raise ProfileError(f"{path}: column 't' spans {duration:.3g} s ({duration / 86400:.3g} days), far longer "
                           f"than a session (minutes): the time column must be in seconds")
    if problem == "ms":
        raise ProfileError(f"{path}: column 't' looks like milliseconds: {describe_steps(t)}; a recording is "
                           f"sampled faster than {1 / MS_MEDIAN_STEP:g} Hz and the time column must be in seconds "
                           f"(divide it by 1000)")


def time_unit_problem(t: np.ndarray) -> str | None:
    """The rule of :func:`_check_time_unit` for times ``t`` [s] (increasing): ``"days"`` (longer than any
    session even read as milliseconds), ``"ms"`` (looks like milliseconds read as seconds) or None."""
    duration, step = float(t[-1] - t[0]), float(np.median(np.diff(t)))
    if duration > 1000 * MS_DURATION:  # even read as milliseconds, longer than any session
        return "days"
    if step >= MS_MEDIAN_STEP and (len(t) >= MS_MIN_ROWS or duration > MS_DURATION):
        return "ms"
    return None


def describe_steps(t: np.ndarray) -> str:
    """``N samples every S s (median), D s in all`` for times ``t`` [s]."""
    return (f"{len(t)} samples every {float(np.median(np.diff(t))):g} s (median), "
            f"{float(t[-1] - t[0]):g} s in all")


def runs(mask) -> tuple[np.ndarray, np.ndarray]:
    """The runs of True in the boolean ``mask``: (starts, ends), each run ``mask[start:end]``."""
    edges = np.flatnonzero(np.diff(np.concatenate(([False], np.asarray(mask, dtype=bool), [False])).astype(np.int8)))
    return edges[::2], edges[1::2]


#: What mends a path in g or in deg/s, in the words of the file commands (a live stream has its own).
FIXES = ("multiply the force column(s) by 9.80665 (SI: m/s^2 expected; import log: --accel-unit g)",
         "Divide them by 57.2958 (SI: rad/s expected; import log: --rate-unit deg/s)")


def check_units(path: DesiredPath, where, fixes: tuple[str, str] = FIXES) -> None:
    """Refuse a path whose magnitudes are in the wrong units: |f| (or M) above 100 g or reading like g
    (:func:`_check_not_in_g`), |omega| above 50 rad/s or held above :data:`MAX_SUSTAINED_RATE`
    (:func:`_check_sustained_rate`). ``where(k)`` names sample k in a message (a file's line), and
    ``where(None)`` the path; ``fixes`` what mends a force in g and rates in deg/s."""
    label = "M" if path.S_d is None else "|f|"
    rate = None if path.S_d is None else np.linalg.norm(path.S_d[:, :3], axis=1)
    _check_magnitude(where, path.M_d, label, MAX_SPECIFIC_FORCE, "m/s^2")
    if rate is not None:
        _check_magnitude(where, rate, "|omega|", MAX_ANGULAR_VELOCITY, "rad/s")
    _check_not_in_g(where(None), path.M_d, label, fixes[0])
    if rate is not None:
        _check_sustained_rate(where, path.t, rate, fixes[1])


def _check_magnitude(where, values, label, limit, unit):
    over = np.abs(values) > limit
    if np.any(over):
        k = int(np.argmax(over))
        raise ProfileError(f"{where(k)}: {label} = {values[k]:.4g} {unit} is above "
                           f"{limit:.4g} {unit}: wrong units? (SI: rad/s and m/s^2 expected)")


def _check_not_in_g(where, size, label, fix=FIXES[0]):
    """Refuse specific forces written in g: a path whose |f| (or M) reads about 1 for most of its
    length (its median within :data:`G_LIKE_MEDIAN`) and never reaches half a g in m/s^2. A motion near
    1 m/s^2 throughout (a tenth of g) is no vehicle's on Earth; a weightless crop reads near 0."""
    median, peak = float(np.median(size)), float(np.max(size))
    if G_LIKE_MEDIAN[0] <= median <= G_LIKE_MEDIAN[1] and peak < 0.5 * G:
        raise ProfileError(f"{where}: {label} has a median of {median:.3g} and never exceeds {peak:.3g} m/s^2: "
                           f"it reads like g (at rest 1 g is {G:g} m/s^2); {fix}")


def _check_sustained_rate(where, t, rate, fix=FIXES[1]):
    """Refuse rates written in deg/s: |omega| above :data:`MAX_SUSTAINED_RATE` for
    :data:`SUSTAINED_FOR` or longer, several turns a second that no vehicle a simulator cues keeps
    (a fighter rolls at up to about 5 rad/s for a moment; the corpus peaks at 2)."""
    for first, end in zip(*runs(rate > MAX_SUSTAINED_RATE)):
        if t[end - 1] - t[first] >= SUSTAINED_FOR:
            raise ProfileError(f"{where(first)}: |omega| stays above {MAX_SUSTAINED_RATE:g} "
                               f"rad/s for {t[end - 1] - t[first]:.3g} s (up to {rate[first:end].max():.4g}): rates "
                               f"in deg/s? {fix}")


def write_csv(path_or_file, path: DesiredPath, comments=()) -> None:
    """Write a desired path as CSV (the format :func:`read_csv` reads), full precision; each of
    ``comments`` (e.g. ``"source: ..."``) becomes a ``# `` line after the first."""
    buffer = io.StringIO()
    buffer.write(f"# {path.name}: {path.description}\n")
    for comment in comments:
        buffer.write(f"# {comment}\n")
    if path.S_d is None:
        buffer.write(",".join(MODULUS_COLUMNS) + "\n")
        for t, m in zip(path.t, path.modulus):
            buffer.write(f"{float(t)!r},{float(m)!r}\n")
    else:
        buffer.write("# weights: " + ",".join(repr(float(w)) for w in path.weights) + "\n")
        buffer.write(",".join(PATH_COLUMNS) + "\n")
        for t, row in zip(path.t, path.S_d):
            buffer.write(",".join(repr(float(x)) for x in (t, *row)) + "\n")
    Path(path_or_file).write_text(buffer.getvalue())


def cells(line: str, delimiter: str = ",") -> list[str]:
    """The cells of one CSV line, split by ``delimiter``, their blanks stripped."""
    return [c.strip() for c in next(csv.reader([line], delimiter=delimiter), [])]


def comma_lines(numbered: list[tuple[int, str]]) -> list[tuple[int, str]]:
    """The (line number, text) of a CSV's lines, as they are where commas split its cells; else written
    anew with commas (a ``#`` comment's text after its ``#``), a decimal comma in a number as a point.
    The delimiter is the one of :data:`DELIMITERS` that splits the first two lines other than blank
    ones and ``#`` comments into as many cells, and into the most (a comma where none makes two)."""
    first = [line for _, line in numbered if line.strip() and not line.lstrip().startswith("#")][:2]

    def width(delimiter):  # how many cells the first lines have, split by ``delimiter``; 0: not as many
        counts = {len(cells(line, delimiter)) for line in first}
        return counts.pop() if len(counts) == 1 else 0

    delimiter = max(DELIMITERS, key=lambda d: (width(d), d == ","))
    if delimiter == "," or width(delimiter) < 2:
        return numbered
    out = io.StringIO()
    writer = csv.writer(out, lineterminator="")
    rewritten = []
    for number, line in numbered:
        mark = "#" if line.lstrip().startswith("#") else ""
        if line.strip():
            out.seek(0)
            out.truncate()
            writer.writerow([_DECIMAL_COMMA.sub(r"\1.\2", c) for c in cells(line.lstrip()[len(mark):], delimiter)])
            line = mark + out.getvalue()
        rewritten.append((number, line))
    return rewritten

"""A log's time column, read exactly: numbers in a declared unit, or ISO 8601 dates and times.

A clock from 1970 (seconds, milliseconds or nanoseconds since then) is a number of 10 to 19 digits,
and float64 keeps 15 to 17: at 1.7e9 s it keeps a quarter of a microsecond, and a log stamped
``1691185678.25, 1691185678.26, ...`` reads steps that wander by that much. Its steps are then no
longer uniform, the log is put on a grid of its median step, and the last sample is lost. So a column
of numbers written with a decimal point or none is read as exact integer counts of its last decimal
(:class:`Counts`), and a column of dates and times as whole microseconds (:func:`date_reader`); only
their differences, a few minutes' worth, become floats.
"""

from __future__ import annotations

import re
from datetime import datetime, timedelta, timezone

import numpy as np

from desdemona.profiles import convert

#: Seconds per unit of a time column; ``us`` and ``ns`` are the clocks of IMU datasets and robot logs
#: (EuRoC's and ROS's time stamps are nanoseconds since 1970).
TIME_UNITS = {"s": 1.0, "ms": 1e-3, "us": 1e-6, "ns": 1e-9}
#: The dates [s since 1970] a clock from 1970 reads in its unit, 2000-01-01 to 2100-01-01: a log whose
#: first time is one is in that unit however slowly sampled (a drive averaged to a row a second); in a
#: unit 1000 times off it would read January 1970 or the year 33,000.
EPOCH_DATES = (946684800.0, 4102444800.0)
#: A dated clock is counted in microseconds: this many decimals of a second (:func:`date_reader`).
DATE_DECIMALS = 6
_DECIMAL = re.compile(r"[+-]?(\d+)(?:\.(\d*))?")


def date_seconds(text: str) -> float | None:
    """Seconds since 1970 of a date and time (:func:`when`: ``2023-08-04 17:47:58-04:00``,
    ``2023-08-04T21:47:58.25Z``; one without a UTC offset is taken as UTC), or None where ``text`` is
    not one."""
    moment = when(text)
    return None if moment is None else utc(moment).timestamp()


#: Dates and times as other tools write them, besides ISO 8601: MATLAB's default datetime
#: (``04-Aug-2023 21:47:58.250``, what ``writetimetable`` writes), with and without its fraction.
OTHER_DATES = ("%d-%b-%Y %H:%M:%S.%f", "%d-%b-%Y %H:%M:%S")


def when(text: str) -> datetime | None:
    """The date and time ``text`` writes in ISO 8601 or one of :data:`OTHER_DATES`, or None."""
    text = text.strip()
    try:
        return datetime.fromisoformat(text)
    except ValueError:
        pass
    for layout in OTHER_DATES:
        try:
            return datetime.strptime(text, layout)
        except ValueError:
            continue
    return None


def utc(moment: datetime) -> datetime:
    """``moment`` with its UTC offset, UTC where it has none."""
    return moment if moment.tzinfo is not None else moment.replace(tzinfo=timezone.utc)


def is_date(seconds: float) -> bool:
    """Whether a time [s since 1970] is one of :data:`EPOCH_DATES`."""
    return EPOCH_DATES[0] <= seconds <= EPOCH_DATES[1]


def text(seconds: float, dated: bool) -> str:
    """A time of a log's clock [s]: ``1403636599.75856 s``, or for a log stamped
    with dates and times the UTC date and time, ``2023-08-04T21:47:58+00:00``."""
    if not dated:
        return f"{convert.seconds(seconds)} s"
    return datetime.fromtimestamp(seconds, timezone.utc).isoformat(timespec="milliseconds").replace(".000+", "+")


def number_reader(reason: str):
    """A cell's number, refused with ``reason`` where it is not one."""
    def read(cell: str) -> float:
        try:
            return float(cell)
        except ValueError:
            raise ValueError(reason) from None
    return read


def date_reader(offset: bool):
    """A cell's whole microseconds since 1970 (as :func:`date_seconds` reads it; exact in a float64, where
    seconds keep only a quarter of one), refused where it is not a date and time, or where it has a UTC
    offset and the first row's has not (``offset``), or the reverse: a column mixing the two would read
    local times as UTC beside them (hours apart, or one hour across a change of summer time)."""
    def read(cell: str) -> float:
        moment = when(cell)
        if moment is None:
            raise ValueError("is not a date and time as the first row's")
        if (moment.tzinfo is not None) != offset:
            raise ValueError("has a UTC offset, the first row's has none" if offset is False
                             else "has no UTC offset, the first row's has one")
        return (utc(moment) - datetime(1970, 1, 1, tzinfo=timezone.utc)) // timedelta(microseconds=1)
    return read


class Counts:
    """A column of numbers written with at most nine decimals and no exponent, gathered cell by cell
    (:meth:`add`) as exact integers: :meth:`counts` gives them in units of the column's last decimal.
    None once a cell is written otherwise (``1.7e9``), or a count would not fit an int64."""

    def __init__(self):
        self._cells: list[tuple[bool, str, str]] | None = []

    def add(self, cell: str) -> None:
        match = _DECIMAL.fullmatch(cell) if self._cells is not None else None
        if match is None or len(match[2] or "") > 9:
            self._cells = None
            return
        self._cells.append((cell[0] == "-", match[1], match[2] or ""))

    def counts(self) -> tuple[np.ndarray, int] | None:
        """(the counts (int64), the number of decimals they count), or None (:class:`Counts`)."""
        if not self._cells:
            return None
        decimals = max(len(fraction) for _, _, fraction in self._cells)
        values = [(-1 if minus else 1) * int(whole + fraction.ljust(decimals, "0"))
                  for minus, whole, fraction in self._cells]
        if max(abs(v) for v in values) >= 2**62:
            return None
        return np.array(values, dtype=np.int64), decimals


def seconds_from_first(clock: np.ndarray, decimals: int, unit: str) -> tuple[float, np.ndarray]:
    """(the first time [s], the times [s] from it) of a clock's values in ``unit`` (:data:`TIME_UNITS`),
    counted in units of ``decimals`` decimals of it: the differences are taken before any rounding (exact
    in integers) and divided by the power of ten, so that ``k`` hundredths read ``k / 100``."""
    scale, first = TIME_UNITS[unit], clock[0]
    return float(first) / 10**decimals * scale, (clock - first) / 10**decimals * scale

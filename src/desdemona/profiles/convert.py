"""From a vehicle's motion to a desired path: the axes turn into the cabin frame, resampling with an
anti-alias filter, cropping, the convention check and writing the CSV safely.

Shared by the JSBSim import (:mod:`.jsbsim`) and the log import (:mod:`.log`). The cabin frame is x
right, y forward, z up; vehicle body axes are x forward, y right, z down (DESIGN.md, "Vehicle data
in"), so ``f_cabin = R_cabin_body f_body`` and ``omega_cabin = R_cabin_body omega_body`` with the proper
rotation :data:`R_CABIN_BODY` (det +1: angular velocity, a pseudo-vector, turns like the force).
"""

from __future__ import annotations

import math
import os
from dataclasses import dataclass
from pathlib import Path
from typing import Literal

import numpy as np
from scipy import ndimage, signal

from desdemona.profiles.csvfile import check_units, runs, write_csv
from desdemona.profiles.path import DesiredPath, G, ProfileError, modulus_version
from desdemona.support import files

#: Body axes (x forward, y right, z down) to cabin axes (x right, y forward, z up): fx = f_y_body,
#: fy = f_x_body, fz = -f_z_body; wx = q, wy = p, wz = -r.
R_CABIN_BODY = np.array([[0.0, 1.0, 0.0],
                         [1.0, 0.0, 0.0],
                         [0.0, 0.0, -1.0]])

#: The cabin's unit vector for each direction name a log's axis may be declared as.
DIRECTIONS = {"right": (1.0, 0.0, 0.0), "left": (-1.0, 0.0, 0.0),
              "forward": (0.0, 1.0, 0.0), "back": (0.0, -1.0, 0.0),
              "up": (0.0, 0.0, 1.0), "down": (0.0, 0.0, -1.0)}

#: Above this specific force [g] a flight has crashed (ground contact, a spin gone numerically wild):
#: no person or motion simulator takes it, and it is no path to cue.
CRASH_G = 20.0
#: A force above CRASH_G this little [s] before it turns NaN is the simulation running away, not a crash.
DIVERGE_SECONDS = 1.0

# The convention check (DESIGN.md: where the vehicle is still, the felt force is +1 g up).
STILL_SECONDS = 1.0          # [s] the shortest still stretch the check uses
#: [rad/s] |omega| below this: above a resting IMU's gyro noise and bias, below an airliner's steady
#: turn (1.45 deg/s at 30 deg of bank, which reads 1.15 g: not still).
STILL_RATE = np.radians(1.0)
#: [rad/s] the largest mean rate at rest read as a gyro's bias (``find_still(biased=True)``): MEMS
#: gyros' run up to a few deg/s uncalibrated (EuRoC's ADIS16448 4.6); beyond this it is a turn.
MAX_GYRO_BIAS = np.radians(10.0)
STILL_SPREAD = 0.03          # RMS of f about its mean, relative to |mean f| ...
STILL_SPREAD_ABS = 0.05      # ... plus this [m/s^2]
UP_TOLERANCE_DEG = 30.0      # direction of the still force from up (a parked car on a slope)
#: [deg] a still force up to this far from up is a sensor mounted at an angle (named as a tilt, and what
#: ``import log --level`` turns upright); beyond it, an axis declared wrong.
MAX_TILT_DEG = 60.0
MAGNITUDE_TOLERANCE = (0.8, 1.25)  # |f| / g at rest

#: Cut-off of the filter before the rates are differentiated for the lever arm's alpha [Hz]: motion
#: cues live below about 10 Hz, and a derivative amplifies the sensor's noise above.
ALPHA_CUTOFF_HZ = 10.0
FILTER_ORDER = 4
#: Anti-alias cut-off as a share of the new sample rate (0.4 = 80 % of the new Nyquist frequency).
CUTOFF_PER_RATE = 0.4
#: The gain of a log's anti-alias filter (:func:`gaussian_lowpass`) at the new Nyquist frequency: what
#: folds back from just above it is cut to a tenth, as the zero-phase Butterworth's -20 dB at 1.3 x its
#: cut-off; its gain at a fifth of the Nyquist frequency (10 Hz at 100 Hz) is still 0.91.
NYQUIST_GAIN = 0.1
#: A rate within this share of a log's own is its own (a clock's jitter moves the median step a little).
RATE_TOLERANCE = 1e-3


def turn_to_cabin(v, R_cabin_from) -> np.ndarray:
    """(N, 3) vectors in another frame turned into the cabin frame: ``v_cabin = R v``, row by row."""
    return np.asarray(v, dtype=float) @ np.asarray(R_cabin_from, dtype=float).T


def axes_rotation(axes) -> np.ndarray:
    """R_cabin_log (3, 3) from the directions of a log's x, y, z axes, e.g. ``("forward", "right", "down")``.

    Each name is one of :data:`DIRECTIONS`; the three must be perpendicular and right-handed (a proper
    rotation, det +1), else :class:`ProfileError` says which.
    """
    names = [str(a).strip().lower() for a in axes]
    if len(names) != 3:
        raise ProfileError(f"--axes {','.join(names)}: give three directions, for the log's x, y and z")
    unknown = [a for a in names if a not in DIRECTIONS]
    if unknown:
        raise ProfileError(f"--axes: unknown direction {unknown[0]!r}; use {', '.join(DIRECTIONS)}")
    R = np.column_stack([DIRECTIONS[a] for a in names])
    if abs(np.linalg.det(R)) < 0.5:
        raise ProfileError(f"--axes {','.join(names)}: two axes along the same line; give one of "
                           f"forward/back, one of right/left, one of up/down")
    if np.linalg.det(R) < 0:
        flipped = {"up": "down", "down": "up", "left": "right", "right": "left", "forward": "back",
                   "back": "forward"}
        raise ProfileError(f"--axes {','.join(names)}: a left-handed set (x cross y = -z); an IMU's axes are "
                           f"right-handed: is z {flipped[names[2]]}?")
    return R


def uniform_grid(t, X) -> tuple[np.ndarray, np.ndarray]:
    """Samples ``X`` (N, k) at times ``t`` (N,) [s] interpolated onto a uniform grid of the median step
    (unchanged if ``t`` is uniform already)."""
    t = np.asarray(t, dtype=float)
    X = np.asarray(X, dtype=float)
    step = float(np.median(np.diff(t)))
    if np.allclose(np.diff(t), step, rtol=1e-6, atol=1e-9):
        return t, X
    n = int(np.floor((t[-1] - t[0]) / step + 1e-9)) + 1
    grid = t[0] + step * np.arange(n)
    return grid, np.column_stack([np.interp(grid, t, X[:, i]) for i in range(X.shape[1])])


def lowpass(X, rate_hz: float, cutoff_hz: float) -> np.ndarray:
    """X (N, k) sampled uniformly at ``rate_hz`` through a zero-phase Butterworth low-pass (order
    :data:`FILTER_ORDER`, applied forwards and backwards: no delay). Unchanged if the cut-off is at or
    above 0.45 of the rate (nothing to remove) or the signal too short to filter."""
    X = np.asarray(X, dtype=float)
    if cutoff_hz >= 0.45 * rate_hz:
        return X
    sos = signal.butter(FILTER_ORDER, cutoff_hz, fs=rate_hz, output="sos")
    if len(X) <= 3 * (2 * len(sos) + 1):
        return X
    return signal.sosfiltfilt(sos, X, axis=0)


def gaussian_lowpass(X, rate_hz: float, new_rate_hz: float) -> np.ndarray:
    """X (N, k) sampled uniformly at ``rate_hz``, smoothed for resampling at the lower ``new_rate_hz``:
    convolved with a Gaussian whose gain at the new Nyquist frequency f_N is :data:`NYQUIST_GAIN`
    (H(f) = exp(-2 pi^2 sigma^2 f^2), so sigma = sqrt(ln(1/gain) / 2) / (pi f_N)); the ends held.

    Why a Gaussian and not a Butterworth: its impulse response is positive and symmetric, so the
    filter neither delays nor rings. A step stays monotone between its two levels, a constant stays
    that constant (zero exactly), and nothing comes before a change that the sensor did not see (a zero-phase
    Butterworth overshot a 0.3 g step by 8.6 % and dipped before it: cues nobody asked for). The price is
    a softer edge: the gain falls from 0.91 at f_N / 5 to 0.1 at f_N."""
    X = np.asarray(X, dtype=float)
    sigma_s = math.sqrt(math.log(1.0 / NYQUIST_GAIN) / 2.0) / (math.pi * new_rate_hz / 2.0)
    return ndimage.gaussian_filter1d(X, sigma_s * rate_hz, axis=0, mode="nearest", truncate=4.0)


def resample(t, X, rate_hz: float, t0: float | None = None,
             antialias: Literal["butterworth", "gaussian"] = "butterworth") -> tuple[np.ndarray, np.ndarray]:
    """X (N, k) at uniform times ``t`` [s] resampled to ``rate_hz`` [Hz] from ``t0`` (None: ``t[0]``;
    before ``t[0]`` the first value is held), then interpolated linearly (the filtered signal is smooth
    on the finer grid). Filtered first against aliasing by ``antialias``: "butterworth" (a flight
    simulated, :mod:`.jsbsim`) low-passes at :data:`CUTOFF_PER_RATE` x ``rate_hz`` where that is below
    0.45 of the old rate; "gaussian" (a recorded log, :mod:`.log`) only where the rate goes down, and
    without ringing (:func:`gaussian_lowpass`)."""
    t = np.asarray(t, dtype=float)
    t0 = float(t[0]) if t0 is None else float(t0)
    native = 1.0 / float(np.median(np.diff(t)))
    if antialias == "butterworth":
        X = lowpass(X, native, CUTOFF_PER_RATE * rate_hz)
    elif rate_hz < native * (1.0 - RATE_TOLERANCE):
        X = gaussian_lowpass(X, native, rate_hz)
    n = int(np.floor((t[-1] - t0) * rate_hz + 1e-6)) + 1
    grid = t0 + np.arange(max(n, 1)) / rate_hz
    return grid, np.column_stack([np.interp(grid, t, X[:, i]) for i in range(X.shape[1])])


def filter_note(native_hz: float, rate_hz: float, antialias: str = "butterworth") -> str:
    """How :func:`resample` treated a signal at ``native_hz`` resampled to ``rate_hz``, for a ``source:`` line."""
    if antialias == "gaussian":
        if rate_hz < native_hz * (1.0 - RATE_TOLERANCE):
            return (f"{rate_hz:g} Hz from {native_hz:.4g} Hz through a zero-phase Gaussian low-pass (no ringing; "
                    f"gain {NYQUIST_GAIN:g} at the new Nyquist frequency {rate_hz / 2:g} Hz)")
        return f"{rate_hz:g} Hz from {native_hz:.4g} Hz, interpolated (no anti-alias filter: the rate does not go down)"
    cutoff = CUTOFF_PER_RATE * rate_hz
    if cutoff >= 0.45 * native_hz:
        return f"{rate_hz:g} Hz from {native_hz:.4g} Hz, interpolated (no anti-alias filter needed)"
    return f"{rate_hz:g} Hz from {native_hz:.4g} Hz through a zero-phase Butterworth low-pass at {cutoff:g} Hz"


def seconds(x: float) -> str:
    """A time [s] to the microsecond, without trailing zeros: ``37.04``, and ``1403636599.75856`` for a
    clock that counts from 1970, which ``:g`` would print as 1.40364e+09."""
    return f"{float(x):.6f}".rstrip("0").rstrip(".")


def crop(t, X, start: float | None, end: float | None, what: str, told=None) -> tuple[np.ndarray, np.ndarray]:
    """The samples with ``start <= t <= end`` [s] (None: from the first, to the last), time shifted so
    that the crop starts at 0. Fewer than two samples, or an end not after the start, raises
    :class:`ProfileError`, its times written by ``told`` (a time of ``t`` to text; None: ``5.5 s``; a
    log's import writes them on its own clock, as the user gave them)."""
    t = np.asarray(t, dtype=float)
    told = told or (lambda x: f"{seconds(x)} s")
    lo = t[0] if start is None else float(start)
    hi = t[-1] if end is None else float(end)
    if start is not None and end is not None and not hi > lo:
        raise ProfileError(f"--start {told(lo)} and --end {told(hi)}: the end must be after the start")
    keep = (t >= lo - 1e-6) & (t <= hi + 1e-6)  # a time printed to the microsecond (:func:`seconds`) is on its sample
    if np.count_nonzero(keep) < 2:
        raise ProfileError(f"{what}: nothing between {told(lo)} and {told(hi)} (it runs from {told(t[0])} to "
                           f"{told(t[-1])})")
    return t[keep] - lo, np.asarray(X)[keep]


def check_no_crash(t, f_cabin, what: str) -> None:
    """Refuse a motion whose specific force exceeds :data:`CRASH_G` anywhere (``t`` (N,) [s], ``f_cabin``
    (N, 3) [m/s^2]), naming the time and the value; a force that turns into not a number (NaN or inf)
    is named as a simulation that diverged, as is a force above CRASH_G less than
    :data:`DIVERGE_SECONDS` before it."""
    with np.errstate(over="ignore", invalid="ignore"):  # a diverged simulation overflows to inf and NaN
        n = np.linalg.norm(f_cabin, axis=1) / G
    broken = ~np.isfinite(n)
    crashed = np.where(broken, False, n > CRASH_G)
    b = int(np.argmax(broken))
    k = int(np.argmax(crashed))
    if np.any(crashed) and (not np.any(broken) or t[k] < t[b] - DIVERGE_SECONDS):
        later = (f"; the simulation diverges later, its force not a number from t = {t[b]:.2f} s"
                 if np.any(broken) else "")
        raise ProfileError(f"{what}: the specific force reaches {n[k]:.0f} g at t = {t[k]:.2f} s (above "
                           f"{CRASH_G:g} g: a crash or ground impact, not a motion to cue{later}); crop it "
                           f"away with --start/--end or choose another stretch")
    if np.any(broken):
        runaway = f" (after {n[k]:.3g} g at t = {t[k]:.2f} s)" if np.any(crashed) else ""
        raise ProfileError(f"{what}: the simulation diverged: the specific force is not a number ({n[b]}) "
                           f"from t = {t[b]:.2f} s{runaway}, no motion to cue; crop it away with --end or "
                           f"choose another stretch")


@dataclass(frozen=True)
class Still:
    """A still stretch of a motion: from ``t0`` to ``t1`` [s], its mean specific force [m/s^2] in the cabin
    frame."""

    t0: float
    t1: float
    f_cabin: np.ndarray
    omega_cabin: np.ndarray | None = None  # the mean rates [rad/s] (a gyro's bias, where read about it)


def find_still(t, omega_cabin, f_cabin, max_rate: float = STILL_RATE, usable=None,
               longest: bool = False, biased: bool = False, max_bias: float | None = None,
               every: bool = False) -> Still | list[Still] | None:
    """The stillest stretch of at least :data:`STILL_SECONDS` where the rates are near zero
    (|omega| < ``max_rate`` [rad/s]) and the force nearly constant (RMS about its mean below
    :data:`STILL_SPREAD` of its size plus :data:`STILL_SPREAD_ABS`), or None. Uniform ``t`` [s]; the
    criteria are relative so a log in the wrong unit is still found still (and then diagnosed).
    ``usable`` (N,) bool, if given: a stretch holding any sample not usable is not still.

    ``longest``: the stillest second of the longest such stretch; for a log without rates (zeros),
    where a steady turn or a held pull is steady too, but shorter than a wait at rest or at a constant
    speed (2 s at 1.15 g in a ride were taken for the rest before it).

    ``biased``: the rates are read about their mean over the stretch, which may be up to ``max_bias``
    [rad/s] (None: :data:`MAX_GYRO_BIAS`; a gyro's bias: EuRoC's read 4.6 deg/s at rest); the Still
    carries that mean. The stillest second of the first such stretch: a steady turn is as steady as a
    rest, its rate as constant as a bias, and a log starts at rest more often than in a steady turn
    (a 2.9 deg/s curve after a 3 s rest was taken for the rest).

    ``every``: the stillest second of each such stretch, in time order (a list, empty where none is;
    ``--level`` reads the first: a steady acceleration with no turn is as still to an accelerometer as a
    rest on a slope, and a car's 1.5 m/s^2 for 5 s was taken for the rest)."""
    t = np.asarray(t, dtype=float)
    step = float(np.median(np.diff(t)))
    w = int(round(STILL_SECONDS / step)) + 1
    if len(t) < w:
        return None
    f = np.asarray(f_cabin, dtype=float)
    omega = np.asarray(omega_cabin, dtype=float)
    omega_mean = np.zeros((len(t) - w + 1, 3))
    if biased:  # the largest deviation from the window's mean rate, the mean itself at most MAX_GYRO_BIAS
        windows = np.lib.stride_tricks.sliding_window_view(omega, w, axis=0)  # (windows, 3, w)
        omega_mean = windows.mean(axis=2)
        windows_rate = np.linalg.norm(windows - omega_mean[:, :, None], axis=1).max(axis=1)
        windows_rate[np.linalg.norm(omega_mean, axis=1) > (MAX_GYRO_BIAS if max_bias is None else max_bias)] = np.inf
    else:
        windows_rate = np.lib.stride_tricks.sliding_window_view(np.linalg.norm(omega, axis=1), w).max(axis=1)
    c1 = np.vstack([np.zeros(3), np.cumsum(f, axis=0)])
    c2 = np.vstack([np.zeros(3), np.cumsum(f ** 2, axis=0)])
    mean = (c1[w:] - c1[:-w]) / w
    var = np.maximum((c2[w:] - c2[:-w]) / w - mean ** 2, 0.0).sum(axis=1)
    spread = np.sqrt(var)
    size = np.linalg.norm(mean, axis=1)
    still = (windows_rate < max_rate) & (spread < STILL_SPREAD * size + STILL_SPREAD_ABS)
    if usable is not None:
        still &= np.lib.stride_tricks.sliding_window_view(np.asarray(usable, dtype=bool), w).all(axis=1)
    if not np.any(still):
        return [] if every else None
    starts, ends = runs(still)  # runs of still windows [start, end)
    score = np.where(still, spread / (size + STILL_SPREAD_ABS) + windows_rate / max_rate, np.inf)
    best = [a + int(np.argmin(score[a:b])) for a, b in zip(starts, ends)]  # the stillest window of each run
    if every:
        picked = best
    elif longest or biased:  # the longest (biased: the first) run of still windows
        picked = [best[0 if biased else int(np.argmax(ends - starts))]]
    else:
        picked = [int(np.argmin(score))]
    found = [Still(float(t[k]), float(t[k + w - 1]), mean[k], omega_mean[k]) for k in picked]
    return found if every else found[0]


def check_convention(still: Still, axes_hint: str = "", up=(0.0, 0.0, 1.0),
                     tolerance: float = UP_TOLERANCE_DEG, tilt_fix: str = "", down_fix: str = "",
                     when=None, unit_fixes: tuple[str, str] = (" (--accel-unit g)", " (--accel-unit m/s2)")) -> None:
    """Raise :class:`ProfileError` naming the likely mistake unless the still force reads +1 g up in
    the cabin frame: magnitude within :data:`MAGNITUDE_TOLERANCE` of g and direction within
    ``tolerance`` [deg] (:data:`UP_TOLERANCE_DEG`) of ``up``, the world's up in the cabin frame (cabin +z for a vehicle at rest
    or flying level; from the attitude where it is known; None: the magnitude alone, for a log whose
    axes do not matter). ``axes_hint`` adds how the axes were declared to the message, ``tilt_fix``
    what mends a tilt of up to :data:`MAX_TILT_DEG`, ``down_fix`` what mends a force that reads -1 g;
    ``when`` prints a time of the still stretch (default: seconds to the hundredth); ``unit_fixes`` what
    mends a force in g read as m/s^2 and the reverse (the import's options; a live stream's own words)."""
    f = np.where(np.abs(still.f_cabin) < 1e-9, 0.0, still.f_cabin)  # round-off prints as 0, not 1e-173
    size = float(np.linalg.norm(f))
    when = when or (lambda x: f"{x:.2f} s")
    where = f"still from {when(still.t0)} to {when(still.t1)}, " + (
        f"the force reads {size:.3g} m/s^2" if up is None else
        f"the force reads ({f[0]:.3g}, {f[1]:.3g}, {f[2]:.3g}) m/s^2 in the cabin frame (x right, y forward, z up)")
    lo, hi = MAGNITUDE_TOLERANCE
    ratio = size / G
    if lo / G <= ratio <= hi / G:
        raise ProfileError(f"{where}: |f| = {size:.3g} m/s^2, 1/9.81 of g: the accelerations are in g "
                           f"but declared as m/s^2?{unit_fixes[0]}")
    if lo * G <= ratio <= hi * G:
        raise ProfileError(f"{where}: |f| = {size:.3g} m/s^2, 9.81 g: the accelerations are in m/s^2 but "
                           f"declared as g?{unit_fixes[1]}")
    if ratio < 0.5:
        raise ProfileError(f"{where}: |f| = {ratio:.2f} g, far below 1 g at rest: kinematic acceleration, not "
                           f"specific force? (gravity taken out: a phone's linear acceleration, Sensor Logger's "
                           f"Accelerometer.csv) The log must hold accelerometer readings (specific force, +1 g "
                           f"up at rest: Sensor Logger's TotalAcceleration.csv)")
    if not lo <= ratio <= hi:
        raise ProfileError(f"{where}: |f| = {ratio:.2f} g at rest, not 1 g: wrong accelerometer unit or scale?")
    if up is None:
        return
    up = np.asarray(up, dtype=float) / np.linalg.norm(up)
    angle = float(np.degrees(np.arccos(np.clip(f @ up / size, -1.0, 1.0))))
    if angle <= tolerance:
        return
    hint = f" (declared {axes_hint})" if axes_hint else ""
    if angle >= 180.0 - tolerance:
        raise ProfileError(f"{where}: -1 g, the force points down: the vertical axis is up but declared "
                           f"down (or the reverse)?{hint}{down_fix}")
    if angle < MAX_TILT_DEG:
        raise ProfileError(f"{where}: the force is {angle:.0f} deg from up: which axis is vertical, or is the "
                           f"sensor mounted at an angle?{hint}{tilt_fix}")
    k = int(np.argmax(np.abs(f[:2])))
    raise ProfileError(f"{where}: g lies along cabin {'xy'[k]} ({('right', 'forward')[k]}), not up: which "
                       f"axis is vertical?{hint}")


def levelling(f_still) -> np.ndarray:
    """(3, 3) the smallest rotation that turns the still force ``f_still`` (3,) in the cabin frame onto
    straight up (+z), for a sensor mounted at an angle to the vehicle (EuRoC's, 15-19 deg): about the
    horizontal axis ``f x z`` by the angle between them (Rodrigues' formula)."""
    a = np.asarray(f_still, dtype=float) / np.linalg.norm(f_still)
    z = np.array([0.0, 0.0, 1.0])
    axis, c = np.cross(a, z), float(a @ z)
    s = float(np.linalg.norm(axis))
    if s < 1e-12:  # already up (a force pointing down is refused by the check before)
        return np.eye(3)
    k = axis / s
    K = np.array([[0.0, -k[2], k[1]], [k[2], 0.0, -k[0]], [-k[1], k[0], 0.0]])
    return np.eye(3) + s * K + (1.0 - c) * K @ K


def up_from_attitude(phi, theta) -> np.ndarray:
    """The world's up (3,) in the cabin frame of a vehicle banked ``phi`` and pitched ``theta`` [rad]
    (Euler angles of body axes x forward, y right, z down): the direction a still or steadily moving
    vehicle's specific force points, ``(-sin phi cos theta, sin theta, cos phi cos theta)``."""
    return np.array([-np.sin(phi) * np.cos(theta), np.sin(theta), np.cos(phi) * np.cos(theta)])


def make_path(name: str, t, omega_cabin, f_cabin, description: str, modulus: bool) -> DesiredPath:
    """The desired path of a motion in the cabin frame (``omega_cabin`` [rad/s], ``f_cabin`` [m/s^2],
    (N, 3) each), or its modulus-only form ``t,M`` (``dfs``) when ``modulus``."""
    path = DesiredPath(name, np.asarray(t, dtype=float) - float(t[0]),
                       np.column_stack([omega_cabin, f_cabin]), description=description)
    return modulus_version(path) if modulus else path


def check_out(out, overwrite: bool = False) -> Path:
    """Where :func:`write_path` may write, checked before any work: :class:`ProfileError` for an
    existing ``out`` without ``overwrite``, a folder, or a folder to write into that does not exist."""
    out = Path(out)
    if out.exists() and not overwrite:
        raise ProfileError(f"{out}: already exists; choose another file or add --overwrite")
    if out.is_dir():
        raise ProfileError(f"{out}: is a folder; give a CSV file name")
    if not out.absolute().parent.is_dir():
        raise ProfileError(f"{out}: cannot write it: the folder {out.absolute().parent} does not exist")
    return out


def write_path(out, path: DesiredPath, comments=(), overwrite: bool = False) -> Path:
    """Write ``path`` as CSV to ``out`` with ``# comments`` lines, never half: into a temporary file in
    the same folder, then renamed. A path that the commands would refuse for its units
    (:func:`.csvfile.check_units`, as :func:`.csvfile.read_csv` checks it) is refused, not written. An existing ``out`` is replaced only with ``overwrite``
    (:func:`check_out`); a folder it cannot write in is a :class:`ProfileError` too."""
    out = check_out(out, overwrite)
    check_units(path, lambda k: f"{out}: not written" + ("" if k is None else f": at {path.t[k]:.4g} s"))
    try:
        with files.beside(out) as tmp:
            write_csv(tmp, path, comments=comments)
            os.replace(tmp, out)
    except OSError as exc:
        raise ProfileError(f"{out}: cannot write it: {exc.strerror or exc}") from None
    return out

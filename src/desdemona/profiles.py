"""Desired paths S_d: the motions a person in the cabin should feel (eq. 3.1), built in or read from CSV.

A :class:`DesiredPath` holds a strictly increasing time grid and, per sample, the desired cabin angular
velocity [rad/s] and specific force [m/s^2] in cabin coordinates (layout of S, eq. 3.2), with the
default weights of the cost (the diagonal of Q, eq. 3.6). The ``dfs`` configuration needs only the
modulus M_d = |f_d| (eq. 7.1), which a path may give alone.
"""

from __future__ import annotations

import csv
import io
import math
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from desdemona.perception import THRESHOLDS

G = 9.81
MAX_SPECIFIC_FORCE = 100.0 * G  # beyond this a file is in the wrong units, not a vehicle's motion
MAX_ANGULAR_VELOCITY = 50.0  # rad/s, about 8 turns per second
PATH_COLUMNS = ("t", "wx", "wy", "wz", "fx", "fy", "fz")
MODULUS_COLUMNS = ("t", "M")


class ProfileError(ValueError):
    """A desired path cannot be used: the message names the file, the line or column, and the problem."""


@dataclass(frozen=True, eq=False)
class DesiredPath:
    """A desired path on a time grid.

    t : (N,) strictly increasing sample times [s], from 0.
    S_d : (N, 6) desired (omega_cabin [rad/s], f_cabin [m/s^2]), or None for a modulus-only path.
    weights : (6,) diagonal of Q (eq. 3.6): how much an error in each channel of S costs.
    modulus : (N,) desired modulus [m/s^2] where given directly (``dfs``), else None.
    """

    name: str
    t: np.ndarray
    S_d: np.ndarray | None
    weights: tuple[float, ...] = (1.0, 1.0, 1.0, 1.0, 1.0, 1.0)
    description: str = ""
    modulus: np.ndarray | None = field(default=None)

    def __post_init__(self):
        t = np.asarray(self.t, dtype=float)
        if t.ndim != 1 or len(t) < 2:
            raise ValueError(f"path {self.name!r}: needs at least two samples, got {t.shape}")
        if not np.all(np.isfinite(t)) or not np.all(np.diff(t) > 0):
            raise ValueError(f"path {self.name!r}: time must be finite and strictly increasing")
        object.__setattr__(self, "t", t)
        if self.S_d is None and self.modulus is None:
            raise ValueError(f"path {self.name!r}: give S_d or the modulus")
        if self.S_d is not None:
            S = np.asarray(self.S_d, dtype=float)
            if S.shape != (len(t), 6) or not np.all(np.isfinite(S)):
                raise ValueError(f"path {self.name!r}: S_d must be finite with shape ({len(t)}, 6)")
            object.__setattr__(self, "S_d", S)
        if self.modulus is not None:
            M = np.asarray(self.modulus, dtype=float)
            if M.shape != t.shape or not np.all(np.isfinite(M)) or np.any(M < 0):
                raise ValueError(f"path {self.name!r}: modulus must be finite, >= 0, shape {t.shape}")
            object.__setattr__(self, "modulus", M)
        w = tuple(float(x) for x in self.weights)
        if len(w) != 6 or any(not np.isfinite(x) or x < 0 for x in w):
            raise ValueError(f"path {self.name!r}: weights must be six finite numbers >= 0")
        object.__setattr__(self, "weights", w)

    @property
    def duration(self) -> float:
        return float(self.t[-1] - self.t[0])

    @property
    def M_d(self) -> np.ndarray:
        """(N,) desired modulus of the specific force (eq. 7.1)."""
        return self.modulus if self.modulus is not None else np.linalg.norm(self.S_d[:, 3:], axis=1)

    def with_gain(self, gain: float) -> DesiredPath:
        """The path scaled by a motion gain around 1 g: what the occupant feels at rest is kept, the
        motion on top of it is scaled (on Desdemona subjects preferred lateral gains below 1).

        f_d' = g_cabin + gain (f_d - g_cabin) with g_cabin = (0, 0, G), the specific force of a level
        cabin at rest; omega_d' = gain omega_d; a modulus-only path M_d' = G + gain (M_d - G).
        gain : > 0 (1 returns the path itself). Weights are kept.
        """
        if not (math.isfinite(gain) and gain > 0):
            raise ProfileError(f"gain {gain!r}: must be a positive number (1 = the path as it is)")
        if gain == 1.0:
            return self
        S_d = modulus = None
        if self.S_d is not None:
            rest = np.array([0.0, 0.0, 0.0, 0.0, 0.0, G])
            S_d = rest + gain * (self.S_d - rest)
        if self.modulus is not None:
            modulus = np.maximum(G + gain * (self.modulus - G), 0.0)
        return DesiredPath(self.name, self.t, S_d, self.weights, f"{self.description}, gain {gain:g}", modulus)

    def sample(self, times) -> np.ndarray:
        """S_d linearly interpolated at ``times`` (held constant outside the grid), shape (len, 6)."""
        times = np.asarray(times, dtype=float)
        return np.column_stack([np.interp(times, self.t, self.S_d[:, i]) for i in range(6)])

    def sample_modulus(self, times) -> np.ndarray:
        return np.interp(np.asarray(times, dtype=float), self.t, self.M_d)


#: Named weights of the cost (:func:`weights_for`); the first is the command line's default.
WEIGHT_CHOICES = ("felt", "path", "thresholds")


def weights_for(spec, path: DesiredPath, thresholds=THRESHOLDS) -> np.ndarray:
    """The diagonal of Q (6,) (eq. 3.6) that a weights spec names, for ``path``.

    spec : "path": the path's own (the thesis' for the built-in paths; a CSV file's ``# weights:``
        line, else Q = I);
        "thresholds": each channel by 1 / threshold^2 (``thresholds`` (6,) [rad/s, m/s^2], Reid & Nahon),
        scaled so that f_y's weight is 1: one threshold of error costs the same in every channel;
        "felt": the path's force weights kept, each rotation channel weighted like "thresholds" times
        the path's largest force weight, so that one threshold of false rotation costs as much as one
        threshold of error in the path's most weighted force channel;
        six numbers >= 0, as a sequence or a string "1,1,1,3,1,1".
    Raises :class:`ProfileError` naming the spec when it is none of these.
    """
    thresholds = np.asarray(thresholds, float)
    by_threshold = (thresholds[4] / thresholds) ** 2
    if isinstance(spec, str) and spec.strip() in WEIGHT_CHOICES:
        name = spec.strip()
        own = np.asarray(path.weights, float)
        if name == "path":
            return own
        if name == "thresholds":
            return by_threshold
        return np.r_[by_threshold[:3] * max(own[3:].max(), 0.0), own[3:]]
    if isinstance(spec, str):
        cells = spec.split(",")
        try:
            spec = [float(c) for c in cells]
        except ValueError:
            raise ProfileError(f"weights {spec!r}: give one of {', '.join(WEIGHT_CHOICES)} or six numbers "
                               f"'wx,wy,wz,fx,fy,fz' (e.g. 1,1,1,3,1,1)") from None
    return _weight_numbers(spec)


def _weight_numbers(values) -> np.ndarray:
    """Six finite weights >= 0, not all zero, as a (6,) array; else :class:`ProfileError`."""
    w = np.asarray(values, dtype=float).ravel()
    if len(w) != 6 or not np.all(np.isfinite(w)) or np.any(w < 0) or not np.any(w > 0):
        raise ProfileError(f"weights {[float(x) for x in w]}: need six finite numbers >= 0 "
                           f"(wx,wy,wz,fx,fy,fz), not all zero")
    return w


def _grid(duration: float, dt: float) -> np.ndarray:
    if not (duration > 0 and dt > 0 and dt <= duration):
        raise ValueError(f"need 0 < dt <= duration, got dt = {dt}, duration = {duration}")
    n = int(round(duration / dt))
    return np.linspace(0.0, n * dt, n + 1)


def _smooth_step(t, start: float, rise: float) -> np.ndarray:
    """0 before ``start``, 1 after ``start + rise``, a C1 cosine ramp between."""
    x = np.clip((np.asarray(t) - start) / rise, 0.0, 1.0)
    return 0.5 - 0.5 * np.cos(np.pi * x)


def cosine(amplitude: float = 5.0, omega: float = 2.0, duration: float = 5.0, dt: float = 0.01) -> DesiredPath:
    """The thesis' test path y_dd = A cos(omega t) (eq. 3.9, section 4.7: A = 5 m/s^2, omega = 2 rad/s).

    Only the lateral specific force f_y is weighted (Q of section 3.5.1); f_z = g as at rest.
    amplitude [m/s^2], omega [rad/s], duration [s], dt sample step [s].
    """
    t = _grid(duration, dt)
    S = np.zeros((len(t), 6))
    S[:, 4] = amplitude * np.cos(omega * t)
    S[:, 5] = G
    return DesiredPath("cosine", t, S, weights=(0, 0, 0, 0, 1, 0),
                       description=f"f_y = {amplitude:g} cos({omega:g} t) m/s^2 for {duration:g} s (eq. 3.9)")


def cosine_sweep(omegas=(2.0, 3.0, 4.0, 5.0), amplitude: float = 5.0, duration: float = 5.0,
                 dt: float = 0.01) -> list[DesiredPath]:
    """The frequency sweep of section 5.3 (figure 5.5): the cosine path at omega = 2 ... 5 rad/s."""
    return [cosine(amplitude, omega, duration, dt) for omega in omegas]


def modulus_version(path: DesiredPath) -> DesiredPath:
    """The ``dfs`` version of a path: only the modulus M_d = |f_d| (eq. 7.1), for the aligned cabin."""
    return DesiredPath(f"{path.name} (modulus)", path.t, None, modulus=path.M_d,
                       description=f"modulus of: {path.description}")


#: Weight of each rotation channel in the cost of a path built by :func:`along_vertical`, per
#: (rad/s)^2 against 1 per (m/s^2)^2 of force: 1 rad/s of unwanted rotation costs as much as 0.3 m/s^2
#: of force error. Low on purpose: in a centrifuge the arm's own turn is a rotation that cannot be
#: removed, and the modulus comes first; the gimbals still turn the cabin to keep what remains small.
ALIGNED_ROTATION_WEIGHT = 0.1
#: The weights (diagonal of Q) of a path built by :func:`along_vertical`.
ALIGNED_WEIGHTS = (ALIGNED_ROTATION_WEIGHT,) * 3 + (1.0,) * 3


def along_vertical(path: DesiredPath, rotation_weight: float = ALIGNED_ROTATION_WEIGHT) -> DesiredPath:
    """A modulus-only path as a full one for a cabin that follows the force (thesis 7.2): the felt force
    along the occupant's vertical, f_d = (0, 0, M_d) in cabin coordinates (at rest f = (0, 0, G)), and
    no rotation, omega_d = 0. The modulus stays the path's own."""
    w = float(rotation_weight)
    return DesiredPath(path.name, path.t, vertical_force(path.M_d), (w, w, w, 1.0, 1.0, 1.0),
                       f"{path.description} (force along the occupant's vertical)", path.M_d)


def vertical_force(M) -> np.ndarray:
    """(K, 6) S with the force M (K,) [m/s^2] along cabin +z and no rotation."""
    M = np.asarray(M, dtype=float)
    S = np.zeros((len(M), 6))
    S[:, 5] = M
    return S


def catapult(level: float = 20.0, push: float = 2.0, quiet: float = 1.0, rise: float = 0.2,
             duration: float = 8.0, dt: float = 0.01) -> DesiredPath:
    """A catapult launch from a carrier (section 5.5.2): a quiet start, then ~2 s at ~20 m/s^2 along y.

    level [m/s^2] plateau of f_y; push [s] time at the plateau; quiet [s] before the ramp; rise [s]
    duration of each smooth ramp; duration [s] of the whole path; dt [s] sample step. Errors in f_x cost
    three times those in f_y (section 5.6.2); f_z = g and rotations are not weighted.
    """
    t = _grid(duration, dt)
    up = _smooth_step(t, quiet, rise)
    down = _smooth_step(t, quiet + rise + push, rise)
    S = np.zeros((len(t), 6))
    S[:, 4] = level * (up - down)
    S[:, 5] = G
    return DesiredPath("catapult", t, S, weights=(0, 0, 0, 3, 1, 1),
                       description=f"{quiet:g} s quiet, then {push:g} s at {level:g} m/s^2 along y (5.5.2)")


def car_lap(duration_target: float = 35.0, straight: float = 120.0, radius: float = 30.0,
            lateral_max: float = 9.0, accel_max: float = 4.0, brake_max: float = 8.0,
            speed_max: float = 40.0, dt: float = 0.01) -> DesiredPath:
    """A car driving one lap of a closed track, like the fast-car run of section 5.5.4 (about 35 s).

    Vehicle model: a point mass on a stadium-shaped track (two straights of ``straight`` m joined by
    half circles of ``radius`` m, driven anticlockwise), at the fastest speed profile that keeps the
    lateral acceleration below ``lateral_max``, the driving acceleration below ``accel_max``, the braking
    below ``brake_max`` [m/s^2] and the speed below ``speed_max`` [m/s] (forward-backward pass over the
    arc length). The lap starts and ends in the middle of a bend. The cabin's forward axis is
    +y, +x points to the driver's right, z up; the car's yaw rate is the cabin's omega_z.
    ``duration_target`` stretches the track so the lap takes about that long.
    """
    def lap(scale):
        ds = 0.05
        # start and end in the middle of a bend, where the speed is the bend's limit: the lap closes
        half, full, long = np.pi * radius / 2, np.pi * radius, straight * scale
        edges = np.cumsum([0.0, half, long, full, long, half])
        s = np.arange(0.0, edges[-1] + ds / 2, ds)
        in_bend = (s < edges[1]) | ((s >= edges[2]) & (s < edges[3])) | (s >= edges[4])
        curvature = np.where(in_bend, 1.0 / radius, 0.0)
        v = np.minimum(speed_max, np.sqrt(lateral_max / np.maximum(curvature, 1e-9)))
        for i in range(1, len(s)):  # driving limit, forward
            v[i] = min(v[i], np.sqrt(v[i - 1] ** 2 + 2 * accel_max * ds))
        for i in range(len(s) - 2, -1, -1):  # braking limit, backward
            v[i] = min(v[i], np.sqrt(v[i + 1] ** 2 + 2 * brake_max * ds))
        time = np.concatenate([[0.0], np.cumsum(ds / (0.5 * (v[1:] + v[:-1])))])
        return s, v, curvature, time

    scale = 1.0
    for _ in range(30):  # stretch the straights until the lap time is near the target
        s, v, curvature, time = lap(scale)
        scale *= (duration_target / time[-1]) ** 1.5
        scale = float(np.clip(scale, 0.05, 50.0))
    t = _grid(time[-1], dt)
    speed = np.interp(t, time, v)
    kappa = np.interp(t, time, curvature)
    longitudinal = np.interp(t, 0.5 * (time[1:] + time[:-1]), np.diff(v) / np.diff(time))
    S = np.zeros((len(t), 6))
    S[:, 2] = speed * kappa  # anticlockwise: yaw rate up
    S[:, 3] = -speed**2 * kappa  # centripetal acceleration points left: -x
    S[:, 4] = longitudinal
    S[:, 5] = G
    return DesiredPath("car-lap", t, S, weights=(1, 1, 1, 1, 1, 1),
                       description=f"one {t[-1]:.0f} s lap of a {2 * straight * scale + 2 * np.pi * radius:.0f} m "
                                   f"stadium track, bends of {radius:g} m (5.5.4)")


def pulses(count: int = 3, level: float = 15.0, width: float = 1.0, gap: float = 1.5, quiet: float = 1.0,
           rise: float = 0.15, tail: float = 2.0, dt: float = 0.01) -> DesiredPath:
    """A train of ``count`` smooth pulses of f_y (the double and triple pulse of 5.5.3 and 5.6.3).

    level [m/s^2]; width [s] at the plateau; gap [s] between pulses; quiet and tail [s] before the
    first and after the last; rise [s] of each ramp. Errors in f_x cost three times those in f_y.
    """
    period = width + 2 * rise + gap
    duration = quiet + count * period - gap + tail
    t = _grid(duration, dt)
    S = np.zeros((len(t), 6))
    for k in range(count):
        start = quiet + k * period
        S[:, 4] += level * (_smooth_step(t, start, rise) - _smooth_step(t, start + rise + width, rise))
    S[:, 5] = G
    name = {2: "double-pulse", 3: "triple-pulse"}.get(count, f"{count}-pulse")
    return DesiredPath(name, t, S, weights=(0, 0, 0, 3, 1, 1),
                       description=f"{count} pulses of {level:g} m/s^2 along y, {width:g} s each (5.5.3)")


def roller_coaster(duration: float = 40.0, seed: int = 3, cutoff_hz: float = 5.0, limit: float = 3.0 * G,
                   dt: float = 0.01) -> DesiredPath:
    """A roller-coaster ride for the dynamic flight simulator, treated as in section 7.5.2.

    Generator (documented, deterministic for a seed): a ride of hills and valleys, a sequence of
    vertical load factors n(t) built from half-sine segments of random duration (1-3 s) and level
    (0 to 3.5 g, airtime included), plus lateral forces in the bends (+-1 g). The thesis' treatment
    follows: the modulus of the ride's specific force plus half gravity (so that accelerations below
    1 g can be simulated), limited to ``limit`` [m/s^2], then low-pass filtered at ``cutoff_hz``
    (second-order Butterworth, zero phase). Only the modulus is returned (for ``dfs``).
    """
    import scipy.signal

    rng = np.random.default_rng(seed)
    t = _grid(duration, dt)
    vertical = np.full(len(t), G)
    lateral = np.zeros(len(t))
    start = 2.0
    while start < duration - 1.0:
        length = rng.uniform(1.0, 3.0)
        level = rng.uniform(0.0, 3.5) * G
        inside = (t >= start) & (t < start + length)
        shape = np.sin(np.pi * (t[inside] - start) / length)
        vertical[inside] = G + (level - G) * shape
        if rng.uniform() < 0.4:
            lateral[inside] = rng.choice([-1.0, 1.0]) * G * shape
        start += length + rng.uniform(0.3, 1.0)
    modulus = np.hypot(vertical, lateral) + 0.5 * G
    modulus = np.minimum(modulus, limit)
    b, a = scipy.signal.butter(2, cutoff_hz, fs=1.0 / dt)
    modulus = np.maximum(scipy.signal.filtfilt(b, a, modulus), 0.0)
    return DesiredPath("roller-coaster", t, None, weights=(0, 0, 0, 1, 1, 1), modulus=modulus,
                       description=f"a {duration:g} s ride: modulus + g/2, limited to {limit:g} m/s^2, "
                                   f"{cutoff_hz:g} Hz low-pass (7.5.2)")


def dfs_catapult(base: float = 1.5 * G, pulse: float = 1.0 * G, duration: float = 12.0,
                 dt: float = 0.01) -> DesiredPath:
    """The on-line catapult of section 7.5.1: pulses superposed on a constant acceleration (modulus).

    base [m/s^2] the steady modulus; pulse [m/s^2] the height of a 2 s launch pulse at 3 s and a 1 s
    pulse at 8 s.
    """
    t = _grid(duration, dt)
    M = np.full(len(t), base)
    M += pulse * (_smooth_step(t, 3.0, 0.3) - _smooth_step(t, 5.3, 0.3))
    M += 0.6 * pulse * (_smooth_step(t, 8.0, 0.2) - _smooth_step(t, 9.2, 0.2))
    return DesiredPath("dfs-catapult", t, None, modulus=M,
                       description=f"modulus {base:g} m/s^2 with launch pulses (7.5.1)")


#: White noise on a rotation channel of :func:`recorded_version` per unit of noise on a force channel
#: [rad/s per m/s^2]: 1 deg/s per m/s^2, so the default 0.5 m/s^2 comes with 0.5 deg/s. An assumption
#: of ours, not a sensor's data sheet: a vehicle's vibration sets both more than the sensors do. Against
#: the perception thresholds (Reid & Nahon) it is the milder of the two: 0.5 m/s^2 is three times the
#: otoliths' 0.17 m/s^2, 0.5 deg/s a sixth of the canals' 3 deg/s.
RATE_NOISE_PER_FORCE_NOISE = math.radians(1.0)


def recorded_version(path: DesiredPath, noise_rms: float = 0.5, rate_hz: float = 100.0,
                     gain_error: float = 0.01, seed: int = 0) -> DesiredPath:
    """The path as a recording of it would look: an accelerometer (and rate gyro) log, resampled, with
    a scale error and white noise; the noisy test input of issue 14 ("the built-in dfs-catapult plus
    white noise of 0.5 m/s^2 RMS sampled at 100 Hz and a 1% gain error", built in as
    ``dfs-catapult-recorded``).

    1. Resampled on t[0] + k / rate_hz up to t[-1] [s] by linear interpolation (no anti-alias filter: a
       path is smooth, a logger's own filter is not modelled); time stays strictly increasing.
    2. Multiplied by (1 + gain_error), gravity included: a sensor's scale error scales its whole reading.
    3. White Gaussian noise, independent per sample and channel, of RMS ``noise_rms`` [m/s^2] on each
       force channel, or on the modulus, and ``noise_rms`` x :data:`RATE_NOISE_PER_FORCE_NOISE` [rad/s]
       on each rotation channel. Noise on each axis of f moves |f| by about its component along f, so
       adding it to the modulus directly is the same to first order while |f| >> noise_rms; the
       modulus is then clipped at 0, since |f| >= 0.

    Deterministic for a ``seed`` (:func:`numpy.random.default_rng`). Weights are kept.
    path : a full or modulus-only path; noise_rms [m/s^2] >= 0; rate_hz [Hz] > 0, at least two samples
    in the path's duration; gain_error > -1 (0.01 reads 1% high).
    """
    for label, value, valid, allowed in (("noise_rms", noise_rms, noise_rms >= 0, ">= 0 [m/s^2]"),
                                         ("rate_hz", rate_hz, rate_hz > 0, "> 0 [Hz]"),
                                         ("gain_error", gain_error, gain_error > -1, "> -1")):
        if not (math.isfinite(value) and valid):
            raise ProfileError(f"{label} = {value!r}: must be a finite number {allowed}")
    count = math.floor(path.duration * rate_hz + 1e-9) + 1
    if count < 2:
        raise ProfileError(f"rate_hz = {rate_hz:g}: fewer than two samples in the {path.duration:g} s of "
                           f"{path.name!r}")
    t = path.t[0] + np.arange(count) / rate_hz
    rng = np.random.default_rng(seed)
    scale = 1.0 + gain_error
    S_d = modulus = None
    if path.S_d is not None:
        noise = rng.standard_normal((count, 6)) * noise_rms
        noise[:, :3] *= RATE_NOISE_PER_FORCE_NOISE
        S_d = scale * path.sample(t) + noise
    if path.modulus is not None:
        modulus = np.maximum(scale * path.sample_modulus(t) + noise_rms * rng.standard_normal(count), 0.0)
    return DesiredPath(f"{path.name} (recorded)", t, S_d, path.weights,
                       f"{path.description}, as recorded at {rate_hz:g} Hz with {noise_rms:g} m/s^2 RMS noise "
                       f"and a {100 * gain_error:g}% gain error", modulus)


#: Built-in profiles: name -> function returning a DesiredPath with its documented defaults.
PROFILES = {
    "cosine": cosine,
    "catapult": catapult,
    "double-pulse": lambda: pulses(count=2),
    "triple-pulse": lambda: pulses(count=3),
    "car-lap": car_lap,
    "roller-coaster": roller_coaster,
    "dfs-catapult": dfs_catapult,
    "dfs-catapult-recorded": lambda: recorded_version(dfs_catapult()),
}


def get_profile(name: str) -> DesiredPath:
    """The built-in profile ``name`` with its default parameters."""
    if name not in PROFILES:
        raise ProfileError(f"unknown profile {name!r}; built-in profiles: {', '.join(PROFILES)} "
                           f"(or give a CSV file)")
    return PROFILES[name]()


def load(name_or_file: str | Path) -> DesiredPath:
    """A built-in profile by name, or a desired path read from a CSV file (:func:`read_csv`).

    Raises :class:`ProfileError` naming the built-in profiles when ``name_or_file`` is neither.
    """
    name = str(name_or_file)
    if name in PROFILES:
        return get_profile(name)
    if name.lower().endswith(".csv") or Path(name).exists():
        if not Path(name).exists():
            raise ProfileError(f"{name}: file not found")
        return read_csv(name)
    return get_profile(name)  # raises, listing the built-in profiles


def read_csv(path: str | Path) -> DesiredPath:
    """Read a desired path from CSV: columns ``t,wx,wy,wz,fx,fy,fz`` (SI) or ``t,M``, in any order; ``#``
    comments; UTF-8, with or without the byte-order mark spreadsheet programs write.

    Strict: every problem (missing or unknown column, a value that is not a finite number, time not
    strictly increasing, fewer than two rows, a negative modulus, |f| above 100 g, |omega| above
    50 rad/s, a time column that looks like milliseconds) raises :class:`ProfileError` naming the file
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
        raise ProfileError(f"{path}: line {header_line}: {detail}; the columns must be "
                           f"'{','.join(PATH_COLUMNS)}' or '{','.join(MODULUS_COLUMNS)}' (SI units, any order)")
    rows = []
    for number, line in lines[1:]:
        cells = next(csv.reader([line]))
        if len(cells) != len(columns):
            raise ProfileError(f"{path}: line {number}: {len(cells)} values for {len(columns)} columns")
        try:
            values = [float(c) for c in cells]
        except ValueError:
            raise ProfileError(f"{path}: line {number}: not a number in {line.strip()!r}") from None
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
    if layout == MODULUS_COLUMNS:
        negative = data[:, 1] < 0
        if np.any(negative):
            k = int(np.argmax(negative))
            raise ProfileError(f"{path}: line {lines[k + 1][0]}: M = {data[k, 1]:g} m/s^2 is negative; the "
                               f"modulus |f| is >= 0")
        _check_magnitude(path, lines, data[:, 1:2], "M", MAX_SPECIFIC_FORCE, "m/s^2")
        return DesiredPath(name, t - t[0], None, modulus=data[:, 1], description=f"read from {path.name}")
    _check_magnitude(path, lines, np.linalg.norm(data[:, 4:7], axis=1, keepdims=True), "|f|",
                     MAX_SPECIFIC_FORCE, "m/s^2")
    _check_magnitude(path, lines, np.linalg.norm(data[:, 1:4], axis=1, keepdims=True), "|omega|",
                     MAX_ANGULAR_VELOCITY, "rad/s")
    return DesiredPath(name, t - t[0], data[:, 1:], weights=weights, description=f"read from {path.name}")


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


# A time column in milliseconds read as seconds: a path of hours sampled at most twice a second. No
# vehicle recording meant for motion cueing has both (cues live in 0.1-10 Hz and a session lasts
# minutes), and as seconds it would ask for hundreds of thousands of control intervals.
MS_DURATION = 3600.0  # [s]
MS_MEDIAN_STEP = 0.5  # [s]


def _check_time_unit(path: Path, t: np.ndarray) -> None:
    duration, step = float(t[-1] - t[0]), float(np.median(np.diff(t)))
    if duration > MS_DURATION and step >= MS_MEDIAN_STEP:
        raise ProfileError(f"{path}: column 't' looks like milliseconds: {duration:g} s ({duration / 3600:.1f} h) "
                           f"sampled every {step:g} s; the time column must be in seconds (divide it by 1000)")


def _check_magnitude(path, lines, values, label, limit, unit):
    over = np.abs(values[:, 0]) > limit
    if np.any(over):
        k = int(np.argmax(over))
        raise ProfileError(f"{path}: line {lines[k + 1][0]}: {label} = {values[k, 0]:.4g} {unit} is above "
                           f"{limit:.4g} {unit}: wrong units? (SI: rad/s and m/s^2 expected)")


def write_csv(path_or_file, path: DesiredPath) -> None:
    """Write a desired path as CSV (the format :func:`read_csv` reads), full precision."""
    buffer = io.StringIO()
    buffer.write(f"# {path.name}: {path.description}\n")
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

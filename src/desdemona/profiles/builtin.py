"""The built-in desired paths: the thesis' test paths (cosine, catapult, pulses) and vehicle-like
ones made from formulas (a car lap, a roller coaster, a dfs catapult), with the thesis' weights."""

from __future__ import annotations

import math

import numpy as np

from desdemona.profiles.path import DesiredPath, G, ProfileError


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
    a scale error and white noise; the noisy test input ("the built-in dfs-catapult plus
    white noise of 0.5 m/s^2 RMS sampled at 100 Hz and a 1% gain error", built in as
    ``dfs-catapult-recorded``).

    1. Resampled on ``t[0] + k / rate_hz`` up to ``t[-1]`` [s] by linear interpolation (no anti-alias filter: a
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

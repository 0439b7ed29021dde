"""What the occupant feels and what the machine does: the quality metrics of a result.

Each metric is one pure NumPy function of sampled arrays; :func:`of_arrays` (or :func:`of_trajectory`
for a :class:`~desdemona.check.simulate.Trajectory`) computes them all into one :class:`Metrics` value with
``to_dict()`` for a ``summary.json`` and ``headline()`` for a printed line. They work from the
trajectory alone, so they apply to off-line, on-line and batch results and to folders read back with
:func:`desdemona.results.report.load`.

Definitions (S, S_d : (K, 6) on a time grid t : (K,) [s]; channels wx, wy, wz [rad/s], fx, fy, fz
[m/s^2]; a grid that is uniform but for a possibly shorter last step, as every result's is):

- RMS: ``sqrt(mean_k (S - S_d)^2)`` per channel (eq. 5.1 with Q = I, per channel).
- Correlation: Pearson's r of S with S_d per channel; undefined (NaN, ``None`` in JSON) where either
  is constant, since r divides by both standard deviations.
- Lag: the delay L [s] maximising the cross-correlation of S with S_d, as Pearson's r of the
  overlapping samples (S[k], S_d[k - L/dt]) at each whole-sample shift, within ``|L| <= window``
  (default :data:`LAG_WINDOW`, 2 s, at most half the path's length), refined between samples by the
  parabola through the peak and its neighbours; positive when S lags S_d. Undefined where the
  correlation is.
- Perceived error: the vestibular model (default the thesis', :func:`perception.thesis_model`) applied
  to S - S_d, which equals perceived S minus perceived S_d because the filters are linear and start in
  the steady state of their first input. Its RMS per channel, and the share of time [%] in which its
  magnitude is at or above the channel's perception threshold (:data:`perception.THRESHOLDS`, Reid &
  Nahon 1985).
- Peak false cue: per channel, ``max |S - S_d|`` over the samples where ``|S_d|`` is below the
  channel's perception threshold (where no motion is wanted, the rider should feel none); undefined
  where S_d is never that quiet (e.g. fz, which carries gravity).
- Jerk per joint: the commanded acceleration qdd is piecewise constant, so its derivative is a train
  of jumps. We take ``(qdd[k+1] - qdd[k]) / (t[k+1] - t[k])`` between consecutive samples: its peak
  ``max |.|`` and its time-weighted RMS ``sqrt(sum (.)^2 dt / T)``. Both scale with 1 / (the result's
  grid step), so compare them between results on the same grid. The total variation of qdd per second
  ``sum |qdd[k+1] - qdd[k]| / T`` (the mean |jerk|, impulses included) does not depend on the grid.
- Acceleration sign changes per second per joint, as ``shared/tools/felt_check.py`` counts them: qdd
  with ``|qdd| <`` :data:`DEADBAND` counts as 0, and every pair of consecutive samples whose signs are
  opposite (+ then -, or - then +) is one change; the count is divided by the duration T = t[-1] - t[0].
  A reversal through a zero sample (+, 0, -) is therefore not counted, and a solver's noise of a few
  1e-6 around zero is. This raw count is kept in ``summary.json`` only: on real inputs a joint dithering
  at a limit or around zero changes sign many times a second with no motion a rider could notice.
- Acceleration reversals per second per joint, what a rider notices: with a hysteresis of d =
  :data:`REVERSAL_SHARE` (5 %) of the joint's peak ``max |qdd|`` over the trajectory, one reversal is a
  crossing from above +d to below -d or back (samples within +-d keep the side last left), divided by
  T. A square wave of amplitude A reverses at every step; a dither of less than 5 % of the peak around
  any value never does. This is the figure that is printed.
- Joint rates at t[0] (a session starts at rest: all zero).
- Modulus ``M = |f|`` against ``M_d`` (the dfs configuration, eq. 7.1, 7.2): RMS, correlation, lag.
- Felt-direction error: per sample the angle [rad; deg where reported] between the felt
  specific force f = S[:, 3:6] and the desired direction, that of f_d = S_d[:, 3:6] on a full path,
  else (a modulus-only path, S_d None: the dfs configuration) the occupant's vertical, cabin +z, along
  which a level cabin at rest feels f = (0, 0, +g). Computed as ``atan2(|f x d|, f . d)`` (accurate
  near 0 and 180 deg); undefined (NaN) where |f| or |d| is below :data:`NO_FORCE`, and left out of
  the statistics there. Its RMS and peak over the defined samples, and the share of them [%] at or
  above :func:`direction_threshold`. That threshold is our assumption, not a published tilt threshold:
  a tilt of f by an angle a puts ``|f| sin a`` on a lateral otolith axis, so we take the angle at
  which that reaches the lateral otolith threshold at 1 g, ``asin(0.17 / 9.81)`` = 0.99 deg with
  Reid & Nahon's thresholds (the vestibular model's own thresholds are used).
  Made by the machine (:func:`direction_made`): per sample that error minus the one a still, level
  cabin leaves (f = (0, 0, +g)), its peak ``made_peak``: how far the machine's motion turned the felt
  force away from the desired direction beyond where standing still leaves it. Where the desired
  force itself turns (a push-over's negative g, a transient the aircraft makes in a tenth of a
  second) a still cabin is already far off; this part is the machine's own. Zero for a still cabin,
  negative where the motion brings the felt force nearer; on a modulus path the error itself.
- Felt rotation: the cabin's angular velocity S[:, :3] minus the desired S_d[:, :3] (zero
  where S_d is None: no rotation is wanted from a modulus path) through the semicircular-canal channels
  of the vestibular model, i.e. the canal part of the perceived error above, also for modulus paths.
  Per channel (wx, wy, wz) its RMS and peak ``max |.|`` [rad/s; deg/s where reported] and the share of
  time [%] at or above the channel's threshold (:data:`perception.THRESHOLDS`). The thesis' canals
  (eq. 6.3) are a high-pass with a lead: a step of angular velocity W is felt as a spike of up to 12 W
  within a few ms (the zero at tau_L = 0.11 s against the poles at 5 and 2 ms), then as about
  0.98 W exp(-t / 5.9 s). The cabin's own angular velocity is continuous (joint rates are), so the
  spike shows only where S_d steps.
- What the occupant suffers beyond the cue (:mod:`desdemona.occupant.coriolis`,
  :mod:`desdemona.occupant.sickness`): the Coriolis cross-coupling of a standard head nod (pitch, roll,
  yaw by 30 deg in 0.5 s) started at each sample, from the cabin's angular velocity in space S[:, :3]:
  per nod the peak and RMS of the cross-coupled angular velocity and acceleration and the share of
  time at which a nod would be felt (any canal at or above its threshold); and the sickness dose of
  the vertical force S[:, 5]: ISO 2631-1's MSDV_z and vomiting incidence, and Bos & Bles' subjective
  vertical conflict and incidence. Both of the cabin's motion alone: a wanted rotation cross-couples
  as much as an unwanted one.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
import scipy.signal

from desdemona.machine.params import default_params
from desdemona.occupant import coriolis, perception, sickness
from desdemona.profiles import CHANNELS, G
from desdemona.support.units import ROUND_OFF, shown  # noqa: F401 (the printed figures' resolution)

#: Names of S's channels, as in a path CSV's header (and trajectory.csv). Not imported from report, which
#: sits above this module in the data flow and may import it.

#: Half-width of the lag search [s]: cueing delays beyond a few hundred ms are already gross.
LAG_WINDOW = 2.0
#: |qdd| below this [rad/s^2 | m/s^2] counts as zero for sign changes (as in felt_check.py).
DEADBAND = 1e-6
#: Hysteresis of a reversal, as a share of the joint's peak |qdd| (:func:`reversals_per_second`).
REVERSAL_SHARE = 0.05
CHANNEL_UNITS = ("rad/s",) * 3 + ("m/s^2",) * 3
#: |f| below this [m/s^2] has no direction (free fall): the felt-direction error is undefined there.
NO_FORCE = 1e-6


def rms(x) -> np.ndarray:
    """Root mean square over samples. x : (K, m) -> (m,), or (K,) -> scalar, in x's unit."""
    x = np.asarray(x, dtype=float)
    return np.sqrt(np.mean(x * x, axis=0))


def _varies(x) -> np.ndarray:
    """(m,) True where column of x (K, m) is not constant (to 1e-9 of its magnitude)."""
    return np.ptp(x, axis=0) > 1e-9 * np.maximum(1.0, np.max(np.abs(x), axis=0))


def correlation(S, S_d) -> np.ndarray:
    """Pearson correlation per column of S (K, m) with S_d (K, m) -> (m,) in [-1, 1].

    NaN where S or S_d is constant in that column (the coefficient would be 0/0).
    """
    S, S_d = np.atleast_2d(np.asarray(S, float).T).T, np.atleast_2d(np.asarray(S_d, float).T).T
    defined = _varies(S) & _varies(S_d)
    x, y = S - S.mean(axis=0), S_d - S_d.mean(axis=0)
    with np.errstate(invalid="ignore", divide="ignore"):
        r = (x * y).sum(axis=0) / np.sqrt((x * x).sum(axis=0) * (y * y).sum(axis=0))
    return np.where(defined, np.clip(r, -1.0, 1.0), np.nan)


def step_of(t) -> float:
    """The sample step [s] of a grid t (K,): its median step (a last step may be shorter)."""
    t = np.asarray(t, float)
    if t.ndim != 1 or len(t) < 2 or not np.all(np.diff(t) > 0):
        raise ValueError("t must be a strictly increasing time grid of at least two samples")
    return float(np.median(np.diff(t)))


def lag(t, S, S_d, window: float = LAG_WINDOW, refine: bool = True) -> np.ndarray:
    """Delay [s] of each column of S (K, m) behind S_d (K, m) that maximises their correlation.

    t : (K,) uniform grid [s]; window : largest |delay| searched [s], at most half the path's length.
    At each whole-sample shift L the correlation is Pearson's r of the overlapping parts (S[k], S_d[k - L]),
    so a pure delay gives r = 1 at its own shift, not biased towards 0 by the shrinking overlap;
    refine : place the peak between samples by the parabola through it and its two neighbours (not on
    the window's edge). Positive when S lags S_d (S[k] ~ S_d[k - L]); NaN where the correlation is.
    """
    dt = step_of(t)
    S, S_d = np.atleast_2d(np.asarray(S, float).T).T, np.atleast_2d(np.asarray(S_d, float).T).T
    K = len(S)
    reach = min((K - 1) // 2, math.floor(window / dt + 1e-9))
    shifts = np.arange(-reach, reach + 1)
    defined = _varies(S) & _varies(S_d)
    out = np.full(S.shape[1], np.nan)
    for j in np.flatnonzero(defined):
        r = _shifted_correlation(S[:, j], S_d[:, j], shifts)
        i = int(np.argmax(r))
        offset = 0.0
        if refine and 0 < i < len(r) - 1 and np.all(np.isfinite(r[i - 1:i + 2])):
            curvature = r[i - 1] - 2.0 * r[i] + r[i + 1]
            if curvature < 0.0:
                offset = 0.5 * (r[i - 1] - r[i + 1]) / curvature
        out[j] = (shifts[i] + offset) * dt
    return out


def _shifted_correlation(x, y, shifts) -> np.ndarray:
    """Pearson's r of (x[k], y[k - L]) over their overlap, for each shift L in ``shifts`` (consecutive
    integers); -inf where a part is constant. Sums over overlaps from one FFT correlation and prefix sums."""
    K = len(x)
    x, y = x - x.mean(), y - y.mean()  # r does not change; the sums lose less to rounding
    full = scipy.signal.correlate(x, y)  # full[K - 1 + L] = sum_k x[k] y[k - L]
    sxy = full[K - 1 + shifts]
    n = K - np.abs(shifts)
    x0, y0 = np.maximum(shifts, 0), np.maximum(-shifts, 0)  # first index of each overlap

    def moments(v, start):
        c1, c2 = np.r_[0.0, np.cumsum(v)], np.r_[0.0, np.cumsum(v * v)]
        s1 = c1[start + n] - c1[start]
        return s1, c2[start + n] - c2[start] - s1 * s1 / n

    sx, vx = moments(x, x0)
    sy, vy = moments(y, y0)
    floor = 1e-12 * K * max(np.mean(x * x), np.mean(y * y))
    with np.errstate(invalid="ignore", divide="ignore"):
        r = (sxy - sx * sy / n) / np.sqrt(vx * vy)
    return np.where((vx > floor) & (vy > floor), r, -np.inf)


def perceived_difference(S, S_d, dt: float, vestibular: perception.VestibularModel | None = None) -> np.ndarray:
    """Perceived S minus perceived S_d (K, 6), in the units of S, through a vestibular model.

    S, S_d : (K, 6); dt : sample step [s]; vestibular : default :func:`perception.thesis_model`.
    Computed as the perception of S - S_d: the same by linearity (chapter 6's filters are linear and
    :meth:`~perception.VestibularModel.perceive` starts them in the steady state of their first input).
    """
    vestibular = perception.thesis_model() if vestibular is None else vestibular
    return vestibular.perceive(np.asarray(S, float) - np.asarray(S_d, float), dt)


def time_above_threshold(difference, thresholds=perception.THRESHOLDS) -> np.ndarray:
    """Share of samples [%] per channel in which |difference| (K, m) is at or above its threshold (m,)."""
    return 100.0 * (1.0 - np.mean(perception.below_threshold(difference, thresholds), axis=0))


def peak_false_cue(S, S_d, thresholds=perception.THRESHOLDS) -> np.ndarray:
    """Peak |S - S_d| (6,) per channel over the samples where |S_d| < threshold: motion felt where none is
    wanted, in the units of S. NaN where S_d is never below the threshold in that channel."""
    S, S_d = np.asarray(S, float), np.asarray(S_d, float)
    quiet = perception.below_threshold(S_d, thresholds)
    error = np.where(quiet, np.abs(S - S_d), -np.inf).max(axis=0)
    return np.where(quiet.any(axis=0), error, np.nan)


def direction_error(f, f_d=None) -> np.ndarray:
    """Angle [rad] (K,) between the felt specific force f (K, 3) and the desired direction.

    f_d : (K, 3) the desired specific force, whose direction is wanted; None for the occupant's
    vertical, cabin +z (modulus-only paths). In [0, pi]; NaN where |f| or |f_d| < :data:`NO_FORCE`.
    """
    f = np.asarray(f, float).reshape(-1, 3)
    d = np.broadcast_to(np.array([0.0, 0.0, 1.0]), f.shape) if f_d is None else np.asarray(f_d, float).reshape(-1, 3)
    angle = np.arctan2(np.linalg.norm(np.cross(f, d), axis=1), np.sum(f * d, axis=1))
    defined = (np.linalg.norm(f, axis=1) >= NO_FORCE) & (np.linalg.norm(d, axis=1) >= NO_FORCE)
    return np.where(defined, angle, np.nan)


def direction_made(f, f_d=None) -> np.ndarray:
    """The felt-direction error [rad] (K,) beyond a still, level cabin's: :func:`direction_error` of f
    (K, 3) less that of (0, 0, +g) against the same desired direction (f_d (K, 3), or None for cabin
    +z, where a still cabin's is zero). In [-pi, pi]; NaN where the error is undefined."""
    f = np.asarray(f, float).reshape(-1, 3)
    still = np.broadcast_to(np.array([0.0, 0.0, G]), f.shape)
    return direction_error(f, f_d) - direction_error(still, f_d)


def direction_threshold(thresholds=perception.THRESHOLDS) -> float:
    """Felt-direction error [rad] taken as noticeable: asin(lateral otolith threshold / g), the tilt at
    which a 1 g specific force puts the smaller of the x and y thresholds of ``thresholds`` (6,) on a
    lateral axis; 0.99 deg for Reid & Nahon's 0.17 m/s^2. An assumption (see the module's notes)."""
    return math.asin(min(1.0, min(thresholds[3], thresholds[4]) / G))


def direction_statistics(error, threshold: float) -> tuple[float, float, float]:
    """(RMS [rad], peak [rad], share at or above ``threshold`` [%]) of a felt-direction error (K,)
    over its defined samples; NaN for all three where none is defined."""
    error = np.asarray(error, float)
    error = error[np.isfinite(error)]
    if not len(error):
        return math.nan, math.nan, math.nan
    return float(rms(error)), float(error.max()), float(100.0 * np.mean(error >= threshold))


def felt_rotation(S, S_d, dt: float, vestibular: perception.VestibularModel | None = None) -> np.ndarray:
    """Perceived rotation (K, 3) [rad/s]: S[:, :3] - S_d[:, :3] through the model's canal channels.

    S : (K, 6); S_d : (K, 6), or None where no rotation is wanted (a modulus-only path); dt : step [s];
    vestibular : default :func:`perception.thesis_model`. The canal part of :func:`perceived_difference`,
    whose force channels see no difference here.
    """
    S = np.asarray(S, float)
    reference = S.copy()
    reference[:, :3] = 0.0 if S_d is None else np.asarray(S_d, float)[:, :3]
    return perceived_difference(S, reference, dt, vestibular)[:, :3]


def jerk(t, qdd) -> np.ndarray:
    """Jumps of the commanded accelerations over their time step: (K - 1, n) [rad/s^3 | m/s^3].

    t : (K,) [s]; qdd : (K, n), piecewise constant, so this is zero inside an interval and
    jump / step at its boundary: it scales with 1 / step (see the module's notes).
    """
    t = np.asarray(t, float)
    return np.diff(np.asarray(qdd, float), axis=0) / np.diff(t)[:, None]


def jerk_rms(t, qdd) -> np.ndarray:
    """Time-weighted RMS of :func:`jerk` per joint (n,): sqrt(sum jerk^2 dt / T)."""
    t = np.asarray(t, float)
    return np.sqrt(np.sum(jerk(t, qdd) ** 2 * np.diff(t)[:, None], axis=0) / (t[-1] - t[0]))


def variation_per_second(t, qdd) -> np.ndarray:
    """Total variation of qdd per second per joint (n,): sum |qdd[k+1] - qdd[k]| / T, the mean |jerk|
    with its impulses; independent of the grid [rad/s^3 | m/s^3]."""
    t = np.asarray(t, float)
    return np.abs(np.diff(np.asarray(qdd, float), axis=0)).sum(axis=0) / (t[-1] - t[0])


def sign_changes_per_second(t, qdd, deadband: float = DEADBAND) -> np.ndarray:
    """Direct reversals of qdd (K, n) between consecutive samples per second, per joint (n,) [1/s].

    |qdd| < deadband counts as zero and a step to or from zero is no reversal, so +, - counts once and
    +, 0, - not at all: the formula of ``shared/tools/felt_check.py``, whose numbers these reproduce.
    """
    t, qdd = np.asarray(t, float), np.asarray(qdd, float)
    signs = np.sign(np.where(np.abs(qdd) < deadband, 0.0, qdd))
    return np.count_nonzero(np.abs(np.diff(signs, axis=0)) == 2.0, axis=0) / (t[-1] - t[0])


def reversals_per_second(t, qdd, share: float = REVERSAL_SHARE) -> np.ndarray:
    """Reversals of qdd (K, n) per second per joint (n,) [1/s], with a hysteresis of ``share`` of each
    joint's peak |qdd|: a crossing from above +d to below -d, or from below -d to above +d, with
    d = share * max |qdd| (see the module's definitions). A joint whose peak is below :data:`DEADBAND`
    never reverses."""
    t, qdd = np.asarray(t, float), np.asarray(qdd, float).reshape(len(t), -1)
    counts = np.zeros(qdd.shape[1])
    for k, x in enumerate(qdd.T):
        peak = np.abs(x).max(initial=0.0)
        if peak < DEADBAND:
            continue
        side = np.sign(x[np.abs(x) > share * peak])  # the samples outside the band, in order
        counts[k] = np.count_nonzero(side[1:] != side[:-1])
    return counts / (t[-1] - t[0])


@dataclass(frozen=True, eq=False)
class Metrics:
    """The quality metrics of one trajectory against its desired path (see the module's definitions).

    Per channel of S (6,), None where the result has no full desired path S_d: rms, correlation, lag_s,
    perceived_rms, above_threshold_pct, peak_false_cue (units of S; NaN where undefined).
    Per joint (n,) in the order of ``joints``: jerk_peak, jerk_rms, qdd_variation_per_s,
    sign_changes_per_s (raw), reversals_per_s (with a hysteresis), qd_start (joint rate at t[0]). Modulus M against M_d: modulus_rms [m/s^2],
    modulus_correlation, modulus_lag_s.
    Felt direction (full and modulus paths), against ``direction_reference`` ("S_d" or "cabin +z"):
    direction_rms, direction_peak, direction_threshold [rad] and direction_above_pct [%]; the peak of
    the part the machine made, direction_made_peak [rad] (:func:`direction_made`).
    Felt rotation (3,) per canal channel wx, wy, wz (full and modulus paths): rotation_rms,
    rotation_peak [rad/s] and rotation_above_pct [%]. NaN where undefined; ``to_dict`` and ``rows``
    give these in degrees, the keys naming the unit.
    """

    joints: tuple[str, ...]
    vestibular: str
    lag_window_s: float
    duration_s: float
    rms: np.ndarray | None
    correlation: np.ndarray | None
    lag_s: np.ndarray | None
    perceived_rms: np.ndarray | None
    above_threshold_pct: np.ndarray | None
    peak_false_cue: np.ndarray | None
    jerk_peak: np.ndarray
    jerk_rms: np.ndarray
    qdd_variation_per_s: np.ndarray
    sign_changes_per_s: np.ndarray
    reversals_per_s: np.ndarray
    qd_start: np.ndarray
    modulus_rms: float | None
    modulus_correlation: float | None
    modulus_lag_s: float | None
    direction_reference: str
    direction_rms: float
    direction_peak: float
    direction_threshold: float
    direction_above_pct: float
    direction_made_peak: float
    rotation_rms: np.ndarray
    rotation_peak: np.ndarray
    rotation_above_pct: np.ndarray
    cross_coupling: coriolis.CrossCoupling | None = None
    sickness_dose: sickness.Dose | None = None

    CHANNEL_FIELDS = ("rms", "correlation", "lag_s", "perceived_rms", "above_threshold_pct", "peak_false_cue")
    JOINT_FIELDS = ("jerk_peak", "jerk_rms", "qdd_variation_per_s", "sign_changes_per_s", "reversals_per_s",
                    "qd_start")
    #: The first word of every name in :meth:`rows`, in the order the rows come.
    ROW_GROUPS = (*CHANNEL_FIELDS, "felt_direction", "felt_rotation", *JOINT_FIELDS, "modulus", "cross_coupling",
                  "sickness")

    def felt_direction(self) -> dict[str, float | None]:
        """The felt-direction error's statistics in degrees, JSON-safe: rms_deg, peak_deg,
        above_threshold_pct, threshold_deg, made_peak_deg (beyond a still cabin's)."""
        return {"rms_deg": _degrees(self.direction_rms), "peak_deg": _degrees(self.direction_peak),
                "above_threshold_pct": _plain(self.direction_above_pct),
                "threshold_deg": _degrees(self.direction_threshold),
                "made_peak_deg": _degrees(self.direction_made_peak)}

    def felt_rotation(self) -> dict[str, dict[str, float | None]]:
        """The felt rotation's statistics per canal channel (wx, wy, wz), JSON-safe: rms_deg_s,
        peak_deg_s, above_threshold_pct."""
        return {"rms_deg_s": dict(zip(CHANNELS[:3], map(_degrees, self.rotation_rms))),
                "peak_deg_s": dict(zip(CHANNELS[:3], map(_degrees, self.rotation_peak))),
                "above_threshold_pct": dict(zip(CHANNELS[:3], map(_plain, self.rotation_above_pct)))}

    def to_dict(self) -> dict:
        """JSON-safe nested dict: floats or None (for NaN), channel and joint names as keys."""
        channels = {name: None if getattr(self, name) is None
                    else dict(zip(CHANNELS, map(_plain, getattr(self, name)))) for name in self.CHANNEL_FIELDS}
        joints = {name: dict(zip(self.joints, map(_plain, getattr(self, name)))) for name in self.JOINT_FIELDS}
        return {"vestibular_model": self.vestibular, "lag_window_s": self.lag_window_s,
                "duration_s": self.duration_s, "channels": channels, "joints": joints,
                "modulus": {"rms": _plain(self.modulus_rms), "correlation": _plain(self.modulus_correlation),
                            "lag_s": _plain(self.modulus_lag_s)},
                "felt_direction": {"reference": self.direction_reference, **self.felt_direction()},
                "felt_rotation": self.felt_rotation(), **self._suffered(lambda part: part.to_dict())}

    def _suffered(self, show) -> dict:
        """``show`` of the cross-coupling and the sickness dose, under their keys, where computed."""
        parts = {"cross_coupling": self.cross_coupling, "sickness": self.sickness_dose}
        return {key: show(part) for key, part in parts.items() if part is not None}

    def rows(self) -> list[tuple[str, str, float | None]]:
        """The metrics flattened for a table: (name, unit, value) per channel, joint and modulus."""
        per_joint = joint_units(self.joints)
        units = {"rms": CHANNEL_UNITS, "correlation": ("",) * 6, "lag_s": ("s",) * 6,
                 "perceived_rms": CHANNEL_UNITS, "above_threshold_pct": ("%",) * 6,
                 "peak_false_cue": CHANNEL_UNITS,
                 "jerk_peak": [u + "/s^3" for u in per_joint], "jerk_rms": [u + "/s^3" for u in per_joint],
                 "qdd_variation_per_s": [u + "/s^3" for u in per_joint],
                 "sign_changes_per_s": ("1/s",) * len(self.joints), "reversals_per_s": ("1/s",) * len(self.joints),
                 "qd_start": [u + "/s" for u in per_joint]}
        rows = []
        for name in self.CHANNEL_FIELDS:
            values = getattr(self, name)
            for i, channel in enumerate(CHANNELS):
                rows.append((f"{name} {channel}", units[name][i], None if values is None else _plain(values[i])))
        rows += [(f"felt_direction {name.removesuffix('_deg')}", "%" if name.endswith("pct") else "deg", value)
                 for name, value in self.felt_direction().items()]
        rows += [(f"felt_rotation {name.removesuffix('_deg_s')} {channel}", "%" if name.endswith("pct") else "deg/s",
                  value) for name, values in self.felt_rotation().items() for channel, value in values.items()]
        for name in self.JOINT_FIELDS:
            for k, joint in enumerate(self.joints):
                rows.append((f"{name} {joint}", units[name][k], _plain(getattr(self, name)[k])))
        rows += [("modulus rms", "m/s^2", _plain(self.modulus_rms)),
                 ("modulus correlation", "", _plain(self.modulus_correlation)),
                 ("modulus lag_s", "s", _plain(self.modulus_lag_s))]
        return rows + [row for part in self._suffered(lambda part: part.rows()).values() for row in part]

    def key_figures(self) -> dict[str, float | None]:
        """The few numbers a table of many runs shows (the batch table): peak false rotation [deg/s],
        the worst felt force error RMS [m/s^2] (full paths), RMS(M - M_d) [m/s^2] (modulus paths), the
        most acceleration reversals per second of any joint [1/s] (with the hysteresis); for every path the felt-direction
        error's RMS and peak [deg] and the largest felt rotation of any canal channel [deg/s]."""
        rotation = None if self.peak_false_cue is None else self.peak_false_cue[:3]
        return {
            "peak_false_rotation_deg_s": None if rotation is None or not np.isfinite(rotation).any()
            else math.degrees(float(np.nanmax(rotation))),
            "felt_force_rms_max": None if self.perceived_rms is None else float(np.max(self.perceived_rms[3:])),
            "rms_modulus": _plain(self.modulus_rms),
            "reversals_per_s_max": float(np.max(self.reversals_per_s)) if len(self.joints) else None,
            "felt_direction_rms_deg": _degrees(self.direction_rms),
            "felt_direction_peak_deg": _degrees(self.direction_peak),
            "felt_rotation_peak_deg_s": _degrees(np.max(self.rotation_peak)),
            "cross_coupling_peak_deg_s": None if self.cross_coupling is None
            else _degrees(self.cross_coupling.worst[1].velocity_peak),
            "msdv_z": None if self.sickness_dose is None else self.sickness_dose.msdv_z,
        }

    def _lag(self, lag: float) -> str:
        """``lag 0.12 s``, or where the search found its best at its window's edge, which says only that
        the lag is that long or longer (or no lag fits): ``lag >= 2.00 s at the search's edge``."""
        if abs(lag) < self.lag_window_s - 1e-9:
            return f"lag {shown(lag):z.2f} s"
        return f"lag {'>=' if lag > 0 else '<='} {lag:z.2f} s at the search's edge"

    def headline(self) -> str:
        """One line of the figures a rider and an operator look at first."""
        parts = []
        if self.rms is not None:
            i = int(np.argmax(self.rms))
            parts.append(f"worst RMS {shown(self.rms[i]):.3g} {CHANNEL_UNITS[i]} ({CHANNELS[i]})")
            if np.isfinite(self.correlation[i]):
                parts.append(f"correlation {self.correlation[i]:.2f}, {self._lag(self.lag_s[i])} ({CHANNELS[i]})")
            i = int(np.argmax(self.above_threshold_pct))
            parts.append(f"felt above threshold {self.above_threshold_pct[i]:.0f}% of the time ({CHANNELS[i]})")
            rotation = self.peak_false_cue[:3]
            if np.isfinite(rotation).any():
                i = int(np.nanargmax(rotation))
                parts.append(f"peak false rotation {shown(math.degrees(rotation[i])):.3g} deg/s ({CHANNELS[i]})")
        elif self.modulus_rms is not None:
            parts.append(f"RMS(M - M_d) {shown(self.modulus_rms):.3g} m/s^2")
            if self.modulus_correlation is not None and np.isfinite(self.modulus_correlation):
                parts.append(f"correlation {self.modulus_correlation:.2f}, {self._lag(self.modulus_lag_s)}")
            i = int(np.argmax(self.rotation_peak))
            parts.append(f"peak felt rotation {shown(math.degrees(self.rotation_peak[i])):.3g} deg/s ({CHANNELS[i]})")
        if np.isfinite(self.direction_rms):
            parts.append(f"felt direction off by {shown(math.degrees(self.direction_rms)):.3g} deg RMS, "
                         f"{shown(math.degrees(self.direction_peak)):.3g} deg peak (against {self.direction_reference})")
        if len(self.joints):
            k = int(np.argmax(self.reversals_per_s))
            parts.append(f"max {shown(self.reversals_per_s[k]):.3g} acceleration reversals/s ({self.joints[k]}, "
                         f"swings over {100 * REVERSAL_SHARE:.0f}% of its peak)")
            k = int(np.argmax(np.abs(self.qd_start)))
            unit = joint_units(self.joints)[k]
            parts.append(f"largest rate at start {shown(abs(self.qd_start[k])):.3g} {unit}/s ({self.joints[k]})")
        return ", ".join(parts + list(self._suffered(lambda part: part.headline()).values()))


def of_arrays(t, S, S_d, qdd, qd, joint_names, M=None, M_d=None,
              vestibular: perception.VestibularModel | None = None, lag_window: float = LAG_WINDOW) -> Metrics:
    """All metrics of a sampled trajectory.

    t : (K,) [s]; S : (K, 6); S_d : (K, 6) or None (a modulus-only path); qdd, qd : (K, n) of the joints
    ``joint_names`` (n,); M, M_d : (K,) [m/s^2] or None; vestibular : default the thesis' model.
    """
    t = np.asarray(t, float)
    dt = step_of(t)
    vestibular = perception.judging(vestibular)
    qdd, qd = np.asarray(qdd, float).reshape(len(t), -1), np.asarray(qd, float).reshape(len(t), -1)
    S = np.asarray(S, float)
    channel = dict.fromkeys(Metrics.CHANNEL_FIELDS)
    if S_d is not None:
        S_d = np.asarray(S_d, float)
        felt = perceived_difference(S, S_d, dt, vestibular)
        rotation = felt[:, :3]  # = felt_rotation(S, S_d, dt, vestibular), already at hand
        channel = {"rms": rms(np.asarray(S) - S_d), "correlation": correlation(S, S_d),
                   "lag_s": lag(t, S, S_d, lag_window), "perceived_rms": rms(felt),
                   "above_threshold_pct": time_above_threshold(felt, vestibular.thresholds),
                   "peak_false_cue": peak_false_cue(S, S_d, vestibular.thresholds)}
    else:
        rotation = felt_rotation(S, None, dt, vestibular)
    threshold = direction_threshold(vestibular.thresholds)
    f_d = None if S_d is None else S_d[:, 3:]
    direction = direction_statistics(direction_error(S[:, 3:], f_d), threshold)
    made = direction_made(S[:, 3:], f_d)
    modulus = (None, None, None)
    if M is not None and M_d is not None:
        modulus = (float(rms(np.asarray(M) - M_d)), float(correlation(M, M_d)[0]),
                   float(lag(t, M, M_d, lag_window)[0]))
    return Metrics(joints=tuple(joint_names), vestibular=vestibular.name, lag_window_s=float(lag_window),
                   duration_s=float(t[-1] - t[0]), **channel,
                   jerk_peak=np.abs(jerk(t, qdd)).max(axis=0, initial=0.0), jerk_rms=jerk_rms(t, qdd),
                   qdd_variation_per_s=variation_per_second(t, qdd),
                   sign_changes_per_s=sign_changes_per_second(t, qdd),
                   reversals_per_s=reversals_per_second(t, qdd), qd_start=qd[0].copy(),
                   modulus_rms=modulus[0], modulus_correlation=modulus[1], modulus_lag_s=modulus[2],
                   direction_reference="cabin +z" if S_d is None else "S_d", direction_rms=direction[0],
                   direction_peak=direction[1], direction_threshold=threshold, direction_above_pct=direction[2],
                   direction_made_peak=float(np.nanmax(made)) if np.isfinite(made).any() else math.nan,
                   rotation_rms=rms(rotation), rotation_peak=np.abs(rotation).max(axis=0),
                   rotation_above_pct=time_above_threshold(rotation, vestibular.thresholds[:3]),
                   cross_coupling=coriolis.statistics(t, S[:, :3], vestibular.thresholds[:3]),
                   sickness_dose=sickness.dose(t, S[:, 5]))


def of_trajectory(traj, joint_names, vestibular: perception.VestibularModel | None = None,
                  lag_window: float = LAG_WINDOW) -> Metrics:
    """All metrics of a :class:`~desdemona.check.simulate.Trajectory` (free joints named ``joint_names``)."""
    return of_arrays(traj.t, traj.S, traj.S_d, traj.qdd, traj.qd, joint_names, traj.M, traj.M_d,
                     vestibular, lag_window)


def _plain(value) -> float | None:
    """A JSON-safe float, or None for NaN and None."""
    return None if value is None or not math.isfinite(value) else float(value)


def _degrees(value) -> float | None:
    """An angle [rad] (or angular velocity [rad/s]) in degrees (per second), JSON-safe as :func:`_plain`."""
    value = _plain(value)
    return None if value is None else math.degrees(value)


def joint_units(joints) -> list[str]:
    """'rad' or 'm' per joint name, from the machine's chain (eq. A.7): a joint's kind is its name's."""
    kinds = {j.name: j.kind for j in default_params().joints}
    return ["rad" if kinds[name] == "revolute" else "m" for name in joints]

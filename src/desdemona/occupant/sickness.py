"""The sickness dose of a session: ISO 2631-1's motion sickness dose value and a conflict model.

Both read the specific force along the occupant's vertical, ``f_z = S[:, 5]`` (cabin z, up) [m/s^2]:
what an accelerometer on the seat measures, so gravity's share changes as the cabin tilts, as it does
for the otoliths.

**MSDV_z** (ISO 2631-1:1997, "Mechanical vibration and shock - Evaluation of human exposure to
whole-body vibration - Part 1", annex D): ``MSDV_z = sqrt(integral a_w(t)^2 dt)`` [m/s^1.5]
over the session, with ``a_w`` the vertical acceleration through the weighting W_f. W_f is the
standard's own filter definition (annex A: band limiting, acceleration-velocity transition and upward
step, with f1 = 0.08 Hz, f2 = 0.63 Hz, Q1 = Q2 = 1/sqrt(2), f3 = infinity, f4 = 0.25 Hz, Q4 = 0.86,
f5 = 0.0625 Hz, Q5 = 0.80, f6 = 0.1 Hz, Q6 = 0.80)::

    W_f(s) = s^2 / (s^2 + sqrt(2) w1 s + w1^2) * w2^2 / (s^2 + sqrt(2) w2 s + w2^2)
             * w4^2 / (s^2 + w4 / Q4 s + w4^2) * (s^2 + w5 / Q5 s + w5^2) / (s^2 + w6 / Q6 s + w6^2)

with w_i = 2 pi f_i. It is applied to the sampled f_z as the exact response of that continuous
filter to the samples joined by straight lines (first-order hold), started in the steady state of
the first sample (W_f passes no constant: a cabin at rest has a_w = 0). The hold loses
``sinc^2(f dt)`` of a sine of frequency f: 0.5 % at 4 Hz on a 100 Hz grid, where W_f is 1e-4.
The standard's estimate of the share of people who may vomit (annex D):
``MSI = K_m MSDV_z`` [%] with K_m = 1/3 for a mixed population of unadapted adults.

**Subjective vertical conflict** (J. E. Bos and W. Bles, "Modelling motion sickness and subjective
vertical mismatch detailed for vertical motions", Brain Research Bulletin 47(5), 1998, 537-542):
sickness grows with the conflict between the vertical the senses give and the subjective vertical,
which follows it with a lag. Restricted to vertical motion, as the paper details it: the sensed
vertical is f_z; the subjective vertical its first-order low-pass with time constant tau; the
conflict ``c = f_z - LP_tau(f_z)``; its size through a Hill function ``h = (|c| / b)^n /
(1 + (|c| / b)^n)``; the incidence ``MSI(t) = P h`` through the second-order low-pass
``1 / (tau_I s + 1)^2`` [%]. Parameters (:data:`BOS_BLES`): tau = 5 s, b = 0.7 m/s^2, n = 2,
P = 85 %, tau_I = 12 min, fitted in the paper to seasickness incidence data. The paper's text was not
at hand when this was written: b, n, P and tau_I are the values the model is usually restated with,
and tau is ours; check them against the paper before relying on this incidence (MSDV_z above does
not depend on them). Sessions of a few minutes reach
a small part of the incidence that the same motion held for an hour would.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
import scipy.signal

from desdemona.support.units import shown

#: W_f's parameters (ISO 2631-1:1997, annex A): corner frequencies [Hz] and quality factors.
W_F = {"f1": 0.08, "f2": 0.63, "f4": 0.25, "Q4": 0.86, "f5": 0.0625, "Q5": 0.80, "f6": 0.1, "Q6": 0.80}
#: ISO 2631-1 annex D: the share of people who may vomit [%] per MSDV_z [m/s^1.5] (mixed adults).
K_M = 1.0 / 3.0
#: Bos & Bles (1998): subjective vertical's time constant tau [s], Hill function's b [m/s^2] and n,
#: the incidence's ceiling P [%] and its time constant tau_I [s].
BOS_BLES = {"tau": 5.0, "b": 0.7, "n": 2.0, "P": 85.0, "tau_I": 720.0}


def w_f() -> tuple[np.ndarray, np.ndarray]:
    """W_f(s) as (numerator, denominator) coefficients in s, highest power first."""
    w = {k: 2.0 * math.pi * v for k, v in W_F.items() if k.startswith("f")}
    root2 = math.sqrt(2.0)
    num = np.polymul(np.polymul([1.0, 0.0, 0.0], [w["f2"] ** 2]), np.polymul([w["f4"] ** 2],
                                                                            [1.0, w["f5"] / W_F["Q5"], w["f5"] ** 2]))
    den = np.polymul(np.polymul([1.0, root2 * w["f1"], w["f1"] ** 2], [1.0, root2 * w["f2"], w["f2"] ** 2]),
                     np.polymul([1.0, w["f4"] / W_F["Q4"], w["f4"] ** 2], [1.0, w["f6"] / W_F["Q6"], w["f6"] ** 2]))
    return num, den


def w_f_gain(f_hz) -> np.ndarray:
    """|W_f(j 2 pi f)| at frequencies f [Hz] (array)."""
    num, den = w_f()
    return np.abs(scipy.signal.freqs(num, den, worN=2.0 * math.pi * np.asarray(f_hz, float))[1])


@dataclass(frozen=True)
class Held:
    """A continuous filter applied to samples at step dt joined by straight lines (first-order hold):
    exact at the samples. Kept in modal form, x_i[k+1] = lam_i x_i[k] + b_i u[k], y = Re(sum c_i x_i)
    + d u, so that a pole near 1 (0.0625 Hz on a 100 Hz grid) loses nothing to a polynomial's
    rounding and each mode runs as one recursion (:func:`scipy.signal.lfilter`)."""

    lam: np.ndarray
    b: np.ndarray
    c: np.ndarray
    d: float

    @classmethod
    def of(cls, num, den, dt: float) -> Held:
        """The filter num / den (coefficients in s, highest power first; distinct poles) at step dt [s]."""
        A, B, C, D = scipy.signal.tf2ss(num, den)
        Ad, Bd, Cd, Dd, _ = scipy.signal.cont2discrete((A, B, C, D), dt, method="foh")
        lam, V = np.linalg.eig(Ad)
        return cls(lam, np.linalg.solve(V, Bd[:, 0].astype(complex)), (Cd @ V)[0], float(Dd[0, 0]))

    def __call__(self, u, start: str = "steady") -> np.ndarray:
        """The output (K,) for inputs u (K,), from the steady state of u[0] (``start="steady"``) or
        from rest (``"rest"``)."""
        u = np.asarray(u, float)
        y = self.d * u
        for lam, b, c in zip(self.lam, self.b, self.c):
            x0 = b * u[0] / (1.0 - lam) if start == "steady" else 0.0
            x = scipy.signal.lfilter([1.0], [1.0, -lam], b * u, zi=[lam * x0])[0]  # x[k + 1]
            y = y + (c * np.r_[x0, x[:-1]]).real
        return y


def step_of(t) -> float:
    """The grid's step [s] (its median: a last step may be shorter)."""
    return float(np.median(np.diff(np.asarray(t, float))))


def weighted_vertical(t, f_z) -> np.ndarray:
    """a_w (K,) [m/s^2]: the vertical specific force f_z (K,) [m/s^2] on the grid t (K,) [s] through W_f."""
    return Held.of(*w_f(), step_of(t))(f_z)


def msdv_so_far(t, a_w) -> np.ndarray:
    """sqrt(integral a_w^2 dt) [m/s^1.5] from the start to each sample (K,) of a weighted acceleration
    a_w (K,) on the grid t (K,) [s]: each sample held over its step (the last over the grid's step)."""
    t = np.asarray(t, float)
    steps = np.append(np.diff(t), step_of(t))
    return np.sqrt(np.cumsum(np.asarray(a_w, float) ** 2 * steps))


def msdv(t, a_w) -> float:
    """The session's MSDV [m/s^1.5]: :func:`msdv_so_far` at its end."""
    return float(msdv_so_far(t, a_w)[-1])


def vertical_conflict(t, f_z, tau: float = BOS_BLES["tau"]) -> np.ndarray:
    """Bos & Bles' conflict c (K,) [m/s^2]: f_z less its low-pass 1 / (tau s + 1), from rest at f_z[0]."""
    return np.asarray(f_z, float) - Held.of([1.0], [tau, 1.0], step_of(t))(f_z)


def conflict_incidence(t, f_z, parameters=None) -> np.ndarray:
    """Bos & Bles' motion sickness incidence MSI(t) (K,) [%] of a vertical specific force f_z (K,)
    [m/s^2] on the grid t (K,) [s]; parameters as :data:`BOS_BLES` (the default)."""
    p = BOS_BLES if parameters is None else parameters
    ratio = (np.abs(vertical_conflict(t, f_z, p["tau"])) / p["b"]) ** p["n"]
    hill = ratio / (1.0 + ratio)
    # the double pole of 1 / (tau_I s + 1)^2 as two first-order stages: a modal form needs distinct poles
    stage = Held.of([1.0], [p["tau_I"], 1.0], step_of(t))
    return p["P"] * stage(stage(hill, "rest"), "rest")


@dataclass(frozen=True)
class Dose:
    """The sickness dose of one session: MSDV_z [m/s^1.5], ISO's vomiting incidence K_m MSDV_z [%],
    RMS of Bos & Bles' conflict [m/s^2] and their incidence at the session's end and its peak [%]."""

    msdv_z: float
    iso_incidence_pct: float
    conflict_rms: float
    conflict_incidence_end_pct: float
    conflict_incidence_peak_pct: float

    UNITS = {"msdv_z": "m/s^1.5", "iso_incidence_pct": "%", "conflict_rms": "m/s^2",
             "conflict_incidence_end_pct": "%", "conflict_incidence_peak_pct": "%"}

    def to_dict(self) -> dict[str, float]:
        return {name: getattr(self, name) for name in self.UNITS}

    def rows(self) -> list[tuple[str, str, float]]:
        """(name, unit, value) per figure, for a table of metrics."""
        return [(f"sickness {name.removesuffix('_pct')}", unit, getattr(self, name)) for name, unit in self.UNITS.items()]

    def headline(self) -> str:
        return (f"sickness dose MSDV_z {shown(self.msdv_z):.3g} m/s^1.5 (ISO: {shown(self.iso_incidence_pct):.2g}% "
                f"may vomit; vertical conflict: {shown(self.conflict_incidence_end_pct):.2g}%)")


def dose(t, f_z) -> Dose:
    """The :class:`Dose` of a session: t (K,) [s], f_z (K,) [m/s^2] (S[:, 5])."""
    value = msdv(t, weighted_vertical(t, f_z))
    incidence = conflict_incidence(t, f_z)
    conflict = vertical_conflict(t, f_z)
    return Dose(value, K_M * value, float(np.sqrt(np.mean(conflict ** 2))), float(incidence[-1]),
                float(incidence.max()))

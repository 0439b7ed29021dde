"""Desired paths S_d: the motions a person in the cabin should feel (eq. 3.1), built in or read from CSV.

A :class:`DesiredPath` holds a strictly increasing time grid and, per sample, the desired cabin angular
velocity [rad/s] and specific force [m/s^2] in cabin coordinates (layout of S, eq. 3.2), with the
default weights of the cost (the diagonal of Q, eq. 3.6). The ``dfs`` configuration needs only the
modulus M_d = |f_d| (eq. 7.1), which a path may give alone.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

G = 9.81


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

    def sample(self, times) -> np.ndarray:
        """S_d linearly interpolated at ``times`` (held constant outside the grid), shape (len, 6)."""
        times = np.asarray(times, dtype=float)
        return np.column_stack([np.interp(times, self.t, self.S_d[:, i]) for i in range(6)])

    def sample_modulus(self, times) -> np.ndarray:
        return np.interp(np.asarray(times, dtype=float), self.t, self.M_d)


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

"""The desired path value S_d (eq. 3.1): a time grid and, per sample, the desired cabin angular velocity
[rad/s] and specific force [m/s^2] in cabin coordinates (layout of S, eq. 3.2), with the default weights
of the cost (the diagonal of Q, eq. 3.6). The ``dfs`` configuration needs only the modulus
M_d = |f_d| (eq. 7.1), which a path may give alone.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from desdemona.support.units import GRAVITY as G

MAX_SPECIFIC_FORCE = 100.0 * G  # beyond this a file is in the wrong units, not a vehicle's motion
#: S of a level cabin at rest: no rotation, gravity felt as (0, 0, G).
REST = np.array([0.0, 0.0, 0.0, 0.0, 0.0, G])
REST.flags.writeable = False
MAX_ANGULAR_VELOCITY = 50.0  # rad/s, about 8 turns per second
PATH_COLUMNS = ("t", "wx", "wy", "wz", "fx", "fy", "fz")
#: The channels of S (eq. 3.2): the cabin's angular velocity and specific force, in cabin coordinates.
CHANNELS = PATH_COLUMNS[1:]
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
            S_d = REST + gain * (self.S_d - REST)
        if self.modulus is not None:
            modulus = np.maximum(G + gain * (self.modulus - G), 0.0)
        return DesiredPath(self.name, self.t, S_d, self.weights, f"{self.description}, gain {gain:g}", modulus)

    def sample(self, times) -> np.ndarray:
        """S_d linearly interpolated at ``times`` (held constant outside the grid), shape (len, 6)."""
        times = np.asarray(times, dtype=float)
        return np.column_stack([np.interp(times, self.t, self.S_d[:, i]) for i in range(6)])

    def sample_modulus(self, times) -> np.ndarray:
        return np.interp(np.asarray(times, dtype=float), self.t, self.M_d)


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


def at_least_g(values) -> np.ndarray:
    """A modulus (K,) at least G, or the force of S (K, 6) at least G long, in its direction (straight
    up where it is zero); NaN stays NaN."""
    values = np.array(values, dtype=float)
    if values.ndim == 1:
        return np.where(values < G, G, values)
    f = values[:, 3:]
    size = np.linalg.norm(f, axis=1)
    weak = size < G
    up = np.tile([0.0, 0.0, 1.0], (int(weak.sum()), 1))
    f[weak] = np.where(size[weak, None] > 0, f[weak] * (G / np.where(size[weak] > 0, size[weak], 1.0))[:, None], G * up)
    return values


def above_g(values, by: float) -> bool:
    """Whether a modulus (K,) or the force of S (K, 6) is longer than G by more than ``by`` [m/s^2]
    somewhere."""
    values = np.asarray(values, dtype=float)
    return bool(np.max(values if values.ndim == 1 else np.linalg.norm(values[:, 3:], axis=1)) > G + by)

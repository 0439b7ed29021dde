"""Coriolis cross-coupling: what a head movement made in a turning cabin does to the canals.

The canals are fixed in the head and sense the head's angular velocity in space. With the cabin turning
in space at ``Omega`` (the path's ``S[:, :3]``: omega_cabin, cabin coordinates) and the head turning
in the cabin at ``omega_head`` (head coordinates), the head's angular velocity in its own coordinates
is ``R^T Omega + omega_head``, where ``R = R_cabin_head`` is the head's attitude in the cabin. The
movement the occupant makes (``omega_head``) is expected; what is not is that the cabin's rotation,
read by canals that now point elsewhere, changes:

- cross-coupled angular velocity ``v = R^T Omega - Omega`` (what the canals read of the cabin's
  rotation with the head moved, less what they read with it upright, canal by canal) [rad/s];
- cross-coupled angular acceleration ``a = (R^T Omega) x omega_head`` [rad/s^2], the Coriolis term
  of the head's angular acceleration in space (``d/dt (R^T Omega) = (R^T Omega) x omega_head +
  R^T dOmega/dt``). For a constant spin ``a = dv/dt`` exactly; where the cabin's rotation changes
  during the movement, ``v`` also holds ``(R^T - I) dOmega/dt`` integrated, the change of the
  cabin's rotation read by canals turned away.

For a spin W about z and a pitch nod theta(t) about x both reduce to the closed form
``v = (0, W sin(theta), W (cos(theta) - 1))`` (in the head's x, y, z) and ``a = dv/dt``: a spinning
occupant who nods feels a tumble about the axis the nod turned into the plane of the spin, and the
canal that left that plane reads a loss of spin. The canals then hold the step in velocity and let it
fade with their time constant (about 6 s, :mod:`.perception`): this is the disorienting and
nauseogenic stimulus of a centrifuge (F. E. Guedry and A. J. Benson, "Coriolis cross-coupling effects:
disorienting and nauseogenic or not?", Aviation, Space, and Environmental Medicine 49(1), 1978,
29-35), and why the thesis' Desdemona (chapter 1) changes the felt force by the track's radius
rather than by the spin where it can.

The standard head movement (:data:`NODS`): a pitch (about the cabin's x, right: the head down), a
roll (about y, forward: the head to the right shoulder) and a yaw (about z, up: the head to the left)
of 30 deg in 0.5 s, from the head upright in the cabin, with the minimum-jerk profile of voluntary
movements (T. Flash and N. Hogan, "The coordination of arm movements: an experimentally confirmed
mathematical model", J. Neuroscience 5(7), 1985, 1688-1703): ``theta(s) = A (10 s^3 - 15 s^4 + 6 s^5)``,
s = t / T, peak rate 1.875 A / T = 112.5 deg/s. The size is this project's choice (a glance at an
instrument or over the canopy's rail), not a figure from a study; a movement of other size scales
``v`` like ``sin`` of its angle and ``a`` with its rate.

Per result and per nod, the occupant is taken to start the nod at every sample t_k of the result
(the cabin's own ``Omega(t_k + tau)``, linearly interpolated, during the nod's 0.5 s; held at the last
sample past the end): per start the peak |v| and |a| over the nod, and whether some canal's
|v_i| reaches its perception threshold (``perception.THRESHOLDS``, Reid & Nahon, per head axis x, y,
z, as :mod:`desdemona.check.metrics` applies them to the cabin's axes). Over the starts
(:func:`statistics`): peak and RMS of both, and the share of starts [%] at which a nod would be
felt as a tumble. ``v`` is the stimulus, not its perception: the thesis' canal reads a velocity step
at unit gain between 1 / 5.9 s and 1 / 0.11 s, and a nod of 0.5 s lies at that band's top, where
its lead adds to the onset.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from desdemona.occupant import perception
from desdemona.support.units import shown

#: The standard nod: 30 deg [rad] in 0.5 s [s], sampled at this many instants of its own.
NOD_ANGLE = math.radians(30.0)
NOD_DURATION = 0.5
NOD_SAMPLES = 21
#: Starts evaluated at once (memory: CHUNK x NOD_SAMPLES x 3 doubles per array).
CHUNK = 4096


@dataclass(frozen=True)
class Nod:
    """A head movement from upright about a fixed ``axis`` (3,) of the cabin (unit; the head's axis
    too, as the head turns about it) through ``angle`` [rad] in ``duration`` [s], minimum jerk."""

    name: str
    axis: tuple[float, float, float]
    angle: float = NOD_ANGLE
    duration: float = NOD_DURATION

    def angle_at(self, tau) -> np.ndarray:
        """theta(tau) [rad] for tau (...) [s] in [0, duration]."""
        s = np.clip(np.asarray(tau, float) / self.duration, 0.0, 1.0)
        return self.angle * s ** 3 * (10.0 - 15.0 * s + 6.0 * s * s)

    def rate_at(self, tau) -> np.ndarray:
        """dtheta/dtau [rad/s] for tau (...) [s] in [0, duration]."""
        s = np.clip(np.asarray(tau, float) / self.duration, 0.0, 1.0)
        return self.angle / self.duration * 30.0 * s * s * (1.0 - s) ** 2


#: The standard nods in the cabin frame (x right, y forward, z up): the head down, to the right
#: shoulder, to the left.
NODS = (Nod("pitch", (1.0, 0.0, 0.0), -NOD_ANGLE), Nod("roll", (0.0, 1.0, 0.0)), Nod("yaw", (0.0, 0.0, 1.0)))


def rotation_about(axis, angle) -> np.ndarray:
    """Rotation matrices (..., 3, 3) by ``angle`` (...) [rad] about the unit ``axis`` (3,) (Rodrigues)."""
    k = np.asarray(axis, float)
    K = np.array([[0.0, -k[2], k[1]], [k[2], 0.0, -k[0]], [-k[1], k[0], 0.0]])
    angle = np.asarray(angle, float)[..., None, None]
    return np.eye(3) + np.sin(angle) * K + (1.0 - np.cos(angle)) * (K @ K)


def cross_coupling(omega_cabin, nod: Nod, tau) -> tuple[np.ndarray, np.ndarray]:
    """Cross-coupled angular velocity v and acceleration a (..., 3) in head coordinates during ``nod``.

    omega_cabin : (..., 3) the cabin's angular velocity in space, cabin coordinates [rad/s], at the
    nod's instants tau (...) [s] (broadcast together). Returns ``v = R^T Omega - Omega`` [rad/s] and
    ``a = (R^T Omega) x omega_head`` [rad/s^2] (see the module's notes)."""
    omega = np.asarray(omega_cabin, float)
    R = rotation_about(nod.axis, nod.angle_at(tau))
    in_head = (omega[..., None, :] @ R)[..., 0, :]  # R^T Omega
    omega_head = np.asarray(nod.rate_at(tau))[..., None] * np.asarray(nod.axis)
    return in_head - omega, np.cross(in_head, omega_head)


#: The names and units of :meth:`NodFigures.to_dict`'s values, in its order.
FIGURE_UNITS = (("velocity_peak", "deg/s"), ("velocity_rms", "deg/s"), ("acceleration_peak", "deg/s^2"),
                ("acceleration_rms", "deg/s^2"), ("above_threshold", "%"))


@dataclass(frozen=True)
class NodFigures:
    """Over the starts of one nod: peak and RMS of the per-start peaks of |v| [rad/s] and |a|
    [rad/s^2], and the share of starts [%] at which some canal's |v_i| reaches its threshold."""

    velocity_peak: float
    velocity_rms: float
    acceleration_peak: float
    acceleration_rms: float
    above_threshold_pct: float

    def to_dict(self) -> dict[str, float]:
        """In degrees, JSON-safe."""
        return {"velocity_peak_deg_s": math.degrees(self.velocity_peak),
                "velocity_rms_deg_s": math.degrees(self.velocity_rms),
                "acceleration_peak_deg_s2": math.degrees(self.acceleration_peak),
                "acceleration_rms_deg_s2": math.degrees(self.acceleration_rms),
                "above_threshold_pct": self.above_threshold_pct}


def per_start(t, omega_cabin, nod: Nod, thresholds=perception.THRESHOLDS[:3]) -> tuple[np.ndarray, ...]:
    """For a nod started at each sample of t (K,) [s] in a cabin turning at omega_cabin (K, 3) [rad/s]:
    the peak |v| [rad/s] (K,), the peak |a| [rad/s^2] (K,) and whether some |v_i| reaches
    ``thresholds`` (3,) [rad/s] (K,) during it."""
    t, omega = np.asarray(t, float), np.asarray(omega_cabin, float).reshape(len(t), 3)
    tau = np.linspace(0.0, nod.duration, NOD_SAMPLES)
    v_peak, a_peak, felt = np.empty(len(t)), np.empty(len(t)), np.empty(len(t), bool)
    for start in range(0, len(t), CHUNK):
        when = t[start:start + CHUNK, None] + tau  # (chunk, M)
        position = np.interp(when, t, np.arange(len(t), dtype=float))  # held at the last sample past the end
        first = np.minimum(position.astype(int), len(t) - 2) if len(t) > 1 else np.zeros(when.shape, int)
        share = (position - first)[..., None]
        inside = (1.0 - share) * omega[first] + share * omega[np.minimum(first + 1, len(t) - 1)]
        v, a = cross_coupling(inside, nod, tau)
        v_peak[start:start + CHUNK] = np.linalg.norm(v, axis=-1).max(axis=1)
        a_peak[start:start + CHUNK] = np.linalg.norm(a, axis=-1).max(axis=1)
        felt[start:start + CHUNK] = (np.abs(v) >= np.asarray(thresholds, float)).any(axis=(1, 2))
    return v_peak, a_peak, felt


def nod_figures(t, omega_cabin, nod: Nod, thresholds=perception.THRESHOLDS[:3]) -> NodFigures:
    """The :class:`NodFigures` of one nod over a result's samples (see :func:`per_start`)."""
    v_peak, a_peak, felt = per_start(t, omega_cabin, nod, thresholds)
    return NodFigures(float(v_peak.max()), float(np.sqrt(np.mean(v_peak ** 2))), float(a_peak.max()),
                      float(np.sqrt(np.mean(a_peak ** 2))), float(100.0 * np.mean(felt)))


@dataclass(frozen=True)
class CrossCoupling:
    """The :class:`NodFigures` of each standard nod of :data:`NODS`, by name."""

    nods: dict[str, NodFigures]

    @property
    def worst(self) -> tuple[str, NodFigures]:
        """The nod whose cross-coupled velocity peaks highest, and its figures."""
        return max(self.nods.items(), key=lambda item: item[1].velocity_peak)

    def to_dict(self) -> dict:
        """JSON-safe: the nod's definition, each nod's figures in degrees, and the worst nod's name."""
        nod = NODS[0]
        return {"nod": {"angle_deg": round(math.degrees(abs(nod.angle)), 9), "duration_s": nod.duration,
                        "profile": "minimum jerk", "axes": {n.name: list(n.axis) for n in NODS}},
                **{name: figures.to_dict() for name, figures in self.nods.items()},
                "worst": self.worst[0]}

    def rows(self) -> list[tuple[str, str, float]]:
        """(name, unit, value) per nod and figure, in degrees, for a table of metrics."""
        return [(f"cross_coupling {nod} {key}", unit, value) for nod, figures in self.nods.items()
                for (key, unit), value in zip(FIGURE_UNITS, figures.to_dict().values())]

    def headline(self) -> str:
        """The worst nod's peak and share above threshold, for a printed line."""
        name, figures = self.worst
        return (f"head {name} nod cross-couples up to {shown(math.degrees(figures.velocity_peak)):.3g} deg/s, "
                f"{shown(math.degrees(figures.acceleration_peak)):.3g} deg/s^2 (felt {figures.above_threshold_pct:.0f}% "
                f"of the time)")


def statistics(t, omega_cabin, thresholds=perception.THRESHOLDS[:3]) -> CrossCoupling:
    """:class:`CrossCoupling` of a result: t (K,) [s], omega_cabin (K, 3) [rad/s] (S[:, :3]),
    thresholds (3,) [rad/s] per canal (head x, y, z)."""
    return CrossCoupling({nod.name: nod_figures(t, omega_cabin, nod, thresholds) for nod in NODS})

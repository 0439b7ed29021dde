"""Reduced configurations: which joints move and where the others are held (chapters 5, 7, appendix B).

A configuration is data, not a code path: the free joints and the positions of the held ones. Held
joints have zero rate and acceleration; their bodies still ride along, so their masses and inertias
stay in the dynamics ("rigid connections", section 5.5), and their forces are not motor limits.

- ``dfs``: the dynamic flight simulator of chapter 7 (7.2) driving the whole machine. The yaw spins
  the arm and the three gimbals turn the cabin; the track is held at its outer end (q2 = -4 m) and the
  heave at its lowest (q3 = -1 m). Given only the modulus M_d of the force (eq. 7.1, 7.2), the cue
  is the force along the occupant's vertical, f = (0, 0, M_d) in cabin coordinates, and no rotation
  (:func:`desdemona.profiles.along_vertical`): the optimiser plans the gimbals with the yaw, within
  their own limits, instead of assuming they follow. Chapter 8's advice, with the gimbals as joints.
- ``dfs-yaw``: the thesis' own one-joint formulation of chapter 7: only the yaw, cost on the modulus
  M = |f| (eq. 7.3, 7.7), the gimbals assumed to align the cabin
  (:func:`desdemona.machine.kinematics.gimbal_alignment`) and not planned. Kept to reproduce its figures.
- ``yaw-track``: yaw and track, the two-joint model of appendix B and chapters 4-5.
- ``yaw-track-cabin``: yaw, track and cabin yaw (q5), the three-joint model of section 5.6.
- ``yaw-heave-cabin``: yaw, heave and cabin yaw (q5), the track held at its outer end (q2 = -4 m):
  the arm's force (centripetal and tangential) turned by the cabin's yaw onto the wanted horizontal
  direction, the heave for the vertical. Held at the end, as in ``dfs``, because a held track makes
  every horizontal force from the arm alone, f = R qd1^2 and R qdd1 (eq. 7.7): at the largest radius
  a force takes the slowest yaw rate, so the least rotation that the occupant feels and did not ask for.
- ``full``: all six joints.

Only this module numbers the joints: every other layer asks a configuration what it can do (moves
the track, tilts the cabin, takes a modulus, ...) and where a joint sits among the free ones.
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import casadi as ca
import numpy as np

from desdemona.machine.kinematics import GIMBALS
from desdemona.machine.params import JOINT_NAMES, MachineParams

#: The joints q1..q6 (eq. A.7) as 0-based indices into a full joint vector.
YAW, TRACK, HEAVE = range(3)
OUTER_GIMBAL, INNER_GIMBAL, CABIN_GIMBAL = GIMBALS


def _joint(joint: int, doc: str) -> property:
    """A property of :class:`Configuration`: where ``joint`` sits among its free joints, None where held."""
    return property(lambda config: config._slot(joint), doc=doc)


@dataclass(frozen=True)
class Configuration:
    """A set of free joints (0-based indices into q1..q6) and the positions of the held ones.

    fixed : (6,) position of every joint when held [rad | m]; the entries of free joints are unused.
    modulus_cost : True where the cue is the modulus of the specific force (``dfs-yaw``), not all of S.
    aligned : a path that gives only the modulus asks for it along the occupant's vertical, with no
        rotation (``dfs``, see :meth:`cue_path`).
    """

    name: str
    free: tuple[int, ...]
    fixed: tuple[float, ...]
    modulus_cost: bool
    description: str
    aligned: bool = False
    #: The classical washout's tuned settings on this configuration, by the names of
    #: :class:`desdemona.baselines.washout.Washout`'s fields (empty: its untuned defaults). Found by
    #: ``benchmarks/tune_classical.py`` (docs/benchmarks/classical-washout-tuned.md): the baseline an
    #: on-line result is judged against is part of the configuration's data.
    washout: tuple[tuple[str, float | bool], ...] = ()

    def __post_init__(self):
        if list(self.free) != sorted(set(self.free)) or not set(self.free) <= set(range(6)) or not self.free:
            raise ValueError(f"configuration {self.name!r}: free joints {self.free} must be distinct indices "
                             "0..5 in increasing order")
        if len(self.fixed) != 6:
            raise ValueError(f"configuration {self.name!r}: {len(self.fixed)} held positions, not 6")

    def _slot(self, joint: int) -> int | None:
        return self.free.index(joint) if joint in self.free else None

    # Where each joint sits among the free ones (its index into a free-joint vector), None where held.
    # The free joints keep the order q1..q6, so the yaw, where it is free, is the first.
    yaw = _joint(YAW, "The central yaw q1 among the free joints, None where held.")
    track = _joint(TRACK, "The linear track q2 among the free joints, None where held.")
    heave = _joint(HEAVE, "The heave q3 among the free joints, None where held.")
    outer_gimbal = _joint(OUTER_GIMBAL, "The outer gimbal q4 (about x: roll) among the free joints, None where held.")
    inner_gimbal = _joint(INNER_GIMBAL, "The inner gimbal q5 (about z: the cabin's yaw) among the free joints, "
                                        "None where held.")
    cabin_gimbal = _joint(CABIN_GIMBAL, "The cabin gimbal q6 (about y: pitch) among the free joints, None where held.")

    @property
    def gimbals(self) -> tuple[int, int, int] | None:
        """(outer, inner, cabin) gimbals among the free joints where all three are free, else None."""
        slots = tuple(self._slot(j) for j in GIMBALS)
        return None if None in slots else slots

    # What the configuration can do

    @property
    def turns_arm(self) -> bool:
        """The central yaw q1 is free."""
        return YAW in self.free

    @property
    def moves_track(self) -> bool:
        """The track q2 is free: the cabin's radius can change."""
        return TRACK in self.free

    @property
    def moves_heave(self) -> bool:
        """The heave q3 is free: the cabin can drop or rise (a felt force below g for a moment)."""
        return HEAVE in self.free

    @property
    def tilts_cabin(self) -> bool:
        """The outer gimbal q4 is free: the cabin can roll its vertical off the arm's (tilt
        coordination, or the force turned onto the occupant's vertical)."""
        return OUTER_GIMBAL in self.free

    @property
    def turns_cabin_only(self) -> bool:
        """The cabin can turn about its vertical (the inner gimbal q5) but not tilt, and does not follow
        the force along the occupant's vertical (``yaw-track-cabin``)."""
        return INNER_GIMBAL in self.free and OUTER_GIMBAL not in self.free and not self.aligned

    @property
    def yaw_and_gimbals(self) -> bool:
        """The yaw is free and every other free joint is a gimbal: the classical loop of figure 7.4
        (the yaw from the modulus, the gimbals after the force's direction) applies (``dfs``,
        ``dfs-yaw``)."""
        return self.free[:1] == (YAW,) and set(self.free[1:]) <= set(GIMBALS)

    @property
    def held_track(self) -> float:
        """The track's held position q2 [m]: the arm's radius (its size) where the track does not move;
        unused (0) where it does."""
        return self.fixed[TRACK]

    @property
    def held(self) -> dict[int, float]:
        """{joint index into q1..q6: its held position [rad | m]} of every joint that does not move."""
        return {i: self.fixed[i] for i in range(6) if i not in self.free}

    def held_moved(self, joint: int, by: float) -> Configuration:
        """The same configuration with held ``joint``'s position moved ``by`` [rad | m] (a study of
        what the held position costs: :mod:`desdemona.cueing.prices`)."""
        if joint in self.free:
            raise ValueError(f"configuration {self.name!r}: {JOINT_NAMES[joint]} is not held")
        fixed = list(self.fixed)
        fixed[joint] += by
        return replace(self, fixed=tuple(fixed))

    def select(self, x):
        """The free joints' values (..., n) of full (..., 6) joint values ``x`` (the inverse of
        :meth:`expand`)."""
        return np.asarray(x, dtype=float)[..., list(self.free)]

    def summary(self) -> dict:
        """The configuration as a summary.json records it: name, free joints, held positions."""
        return {"name": self.name, "free_joints": list(self.joint_names), "held_positions": list(self.fixed)}

    @property
    def default_weights(self) -> str:
        """The weights spec (:func:`desdemona.profiles.weights_for`) a session uses unless told:
        "felt" (false rotation weighted by its perception threshold), or the path's own on an aligned
        configuration, whose arm must turn to make the force: the rotation that comes with it cannot be
        removed, only kept small (the 0.1 of :func:`desdemona.profiles.along_vertical`)."""
        return "path" if self.aligned else "felt"

    @property
    def takes_modulus(self) -> bool:
        """A path that gives only the modulus M_d can be followed (``dfs``, ``dfs-yaw``)."""
        return self.modulus_cost or self.aligned

    def cue_path(self, path):
        """The desired path this configuration follows: ``path`` itself, or for an aligned
        configuration and a modulus-only path, the modulus along cabin +z with no rotation
        (:func:`desdemona.profiles.along_vertical`)."""
        if self.aligned and path.S_d is None:
            from desdemona.profiles import along_vertical

            return along_vertical(path)
        return path

    @property
    def n(self) -> int:
        """Number of free joints."""
        return len(self.free)

    @property
    def joint_names(self) -> tuple[str, ...]:
        return tuple(JOINT_NAMES[i] for i in self.free)

    def expand(self, x, held_value: str = "position"):
        """Full (6,) vector from the free joints' values.

        x : (n,) or (N, n) free-joint values, or a CasADi column of length n.
        held_value : "position" fills held joints with their fixed positions, "zero" with zeros (rates,
            accelerations and forces of held joints).
        """
        filler = self.fixed if held_value == "position" else (0.0,) * 6
        if isinstance(x, (ca.SX, ca.MX)):
            return ca.vertcat(*[x[self.free.index(i)] if i in self.free else filler[i] for i in range(6)])
        x = np.asarray(x, dtype=float)
        full = np.broadcast_to(np.asarray(filler, dtype=float), x.shape[:-1] + (6,)).copy()
        full[..., list(self.free)] = x
        return full

    def limits(self, params: MachineParams) -> "Limits":
        """Limits of the free joints (eq. 3.3-3.5), SI."""
        idx = list(self.free)
        return Limits(position_min=params.position_min[idx], position_max=params.position_max[idx],
                      velocity=params.velocity_max[idx], acceleration=params.acceleration_max[idx],
                      effort=params.effort_max[idx], power=params.power_max[idx], jerk=params.jerk_max[idx])


@dataclass(frozen=True, eq=False)
class Limits:
    """Limits of a set of joints, one (n,) array per kind of limit, SI (eq. 3.3-3.5).

    position_min, position_max : [rad | m], -inf / inf where a joint is unbounded; velocity
    [rad/s | m/s], acceleration [rad/s^2 | m/s^2], effort [N*m | N], power [W], jerk [rad/s^3 | m/s^3]
    (inf where unbounded): symmetric bounds.
    """

    position_min: np.ndarray
    position_max: np.ndarray
    velocity: np.ndarray
    acceleration: np.ndarray
    effort: np.ndarray
    power: np.ndarray
    jerk: np.ndarray

    @property
    def smooth(self) -> bool:
        """True where the jerk is bounded: plans then have continuous, piecewise-linear accelerations."""
        return bool(np.all(np.isfinite(self.jerk)))

    @property
    def bounded(self) -> list[int]:
        """Indices of the joints whose position is bounded."""
        return [i for i in range(len(self.velocity)) if np.isfinite(self.position_max[i])]


CONFIGURATIONS: dict[str, Configuration] = {
    c.name: c for c in (
        Configuration("dfs", (0, 3, 4, 5), (0.0, -4.0, -1.0, 0.0, 0.0, 0.0), False,
                      "dynamic flight simulator: yaw and gimbals, track at -4 m, force along the occupant's "
                      "vertical (chapter 7)", aligned=True),
        Configuration("dfs-yaw", (0,), (0.0, -4.0, -1.0, 0.0, 0.0, 0.0), True,
                      "the thesis' dynamic flight simulator: yaw only, track at -4 m, cue = |f| (chapter 7)"),
        Configuration("yaw-track", (0, 1), (0.0,) * 6, False,
                      "yaw and linear track (appendix B, chapters 4-5)"),
        Configuration("yaw-track-cabin", (0, 1, 4), (0.0,) * 6, False,
                      "yaw, track and cabin yaw q5 (section 5.6)",
                      washout=(("omega_hp", 0.188), ("omega_centre", 0.188), ("omega_lp", 0.375), ("tilt_rate", 0.279),
                               ("omega_rot", 0.333), ("gain", 0.931), ("arm", True), ("radius", 2.25),
                               ("omega_arm", 0.399), ("arm_accel", 0.05), ("arm_min", 4.0))),
        # the track held at its outer end: every horizontal force comes from the arm (f = R qd1^2,
        # R qdd1, eq. 7.7), and at the largest radius a force takes the slowest yaw rate, so the least
        # rotation the occupant feels and did not ask for; the cabin's yaw q5 turns it where wanted
        Configuration("yaw-heave-cabin", (0, 2, 4), (0.0, -4.0, 0.0, 0.0, 0.0, 0.0), False,
                      "yaw, heave and cabin yaw q5, track held at -4 m: the arm's force turned by the cabin"),
        Configuration("full", (0, 1, 2, 3, 4, 5), (0.0,) * 6, False,
                      "all six joints",
                      washout=(("omega_hp", 0.188), ("omega_centre", 0.375), ("omega_lp", 0.665), ("tilt_rate", 0.279),
                               ("omega_rot", 0.188), ("gain", 0.665), ("tilt_limit", 0.455), ("arm", True),
                               ("radius", 3.75), ("omega_arm", 0.798), ("arm_accel", 0.133), ("arm_min", 12.0))),
    )
}


def get_configuration(config: str | Configuration) -> Configuration:
    """The configuration called ``config`` (or ``config`` itself); a clear error for an unknown name."""
    if isinstance(config, Configuration):
        return config
    if config not in CONFIGURATIONS:
        raise ValueError(f"unknown configuration {config!r}; valid configurations: "
                         f"{', '.join(CONFIGURATIONS)}")
    return CONFIGURATIONS[config]

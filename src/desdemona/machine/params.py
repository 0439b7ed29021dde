"""Machine parameters of Desdemona: joint limits and body inertias.

The thesis' tables A.1-A.4 (motor limits, masses, centres of mass, inertias) are confidential. The
built-in defaults (``data/default.toml``) stand in for them and are labelled as assumptions there; the
thesis' toy set of section 4.7 ships as ``data/thesis-toy.toml``. A user TOML file overrides any subset
of a base set, so the real values drop in without code changes.

Every number in a file carries its unit in its key (``velocity_deg_s``, ``force_kN``,
``inertia_kg_m2``); inside the package everything is SI (rad, m, s, kg, N, N*m, W). Files are validated on
load: an unknown key, a missing or wrong unit, a wrong type or an impossible value raises
:class:`ParameterError` with a message naming the key, the value and what is allowed.

Joint order and kinds follow eq. A.7: q1 yaw (revolute, z), q2 track (prismatic, y), q3 heave
(prismatic, z), q4 outer gimbal (revolute, x), q5 inner gimbal (revolute, z), q6 cabin (revolute, y).
Body ``i`` is described in the frame of joint ``i`` (the frame after that joint's motion).
"""

from __future__ import annotations

import dataclasses
import math
import tomllib
from dataclasses import dataclass
from importlib import resources
from pathlib import Path
from typing import Any, Literal

import numpy as np

from desdemona.support.units import GRAVITY

JOINT_NAMES = ("yaw", "track", "heave", "outer_gimbal", "inner_gimbal", "cabin")
JOINT_KINDS: tuple[Literal["revolute", "prismatic"], ...] = (
    "revolute", "prismatic", "prismatic", "revolute", "revolute", "revolute")
BODY_NAMES = ("arm", "track_sledge", "heave_carriage", "outer_gimbal", "inner_gimbal", "cabin")
BUILTIN_SETS = ("default", "thesis-toy")

_DEG = math.pi / 180.0
# Unit suffixes a key may carry, per physical quantity, with the factor to SI.
_UNITS: dict[str, dict[str, float]] = {
    "angle": {"rad": 1.0, "deg": _DEG},
    "length": {"m": 1.0, "mm": 1e-3},
    "angular_velocity": {"rad_s": 1.0, "deg_s": _DEG, "rpm": 2.0 * math.pi / 60.0},
    "linear_velocity": {"m_s": 1.0},
    "angular_acceleration": {"rad_s2": 1.0, "deg_s2": _DEG},
    "linear_acceleration": {"m_s2": 1.0},
    "angular_jerk": {"rad_s3": 1.0, "deg_s3": _DEG},
    "linear_jerk": {"m_s3": 1.0},
    "torque": {"N_m": 1.0, "kN_m": 1e3},
    "force": {"N": 1.0, "kN": 1e3},
    "power": {"W": 1.0, "kW": 1e3, "MW": 1e6},
    "mass": {"kg": 1.0, "t": 1e3},
    "inertia": {"kg_m2": 1.0},
}
# quantity -> physical kind for (revolute, prismatic) joints
_JOINT_QUANTITIES = {
    "position": ("angle", "length"),
    "velocity": ("angular_velocity", "linear_velocity"),
    "acceleration": ("angular_acceleration", "linear_acceleration"),
    "jerk": ("angular_jerk", "linear_jerk"),
    "torque": ("torque", None),
    "force": (None, "force"),
    "power": ("power", "power"),
}
_BODY_QUANTITIES = {"mass": "mass", "com": "length", "inertia": "inertia"}
_TOP_QUANTITIES = {"gravity": "linear_acceleration", "head_offset": "length"}
_TOP_PLAIN = ("name", "base")


class ParameterError(ValueError):
    """A machine parameter file or value is invalid; the message names the key."""


@dataclass(frozen=True)
class JointLimits:
    """Limits of one joint, SI units (eq. 3.3-3.5).

    position : (min, max) [rad | m], or None where the joint is unbounded.
    velocity, acceleration : symmetric bounds [rad/s | m/s], [rad/s^2 | m/s^2].
    effort : torque [N*m] of a revolute joint or force [N] of a prismatic one.
    power : bound on |effort * velocity| [W].
    jerk : symmetric bound on the rate of change of the acceleration [rad/s^3 | m/s^3]; inf where the
        parameter set gives none (the thesis' toy set): the joint's acceleration may then step.
    """

    name: str
    kind: Literal["revolute", "prismatic"]
    position: tuple[float, float] | None
    velocity: float
    acceleration: float
    effort: float
    power: float
    jerk: float = math.inf


@dataclass(frozen=True)
class Body:
    """Inertial data of one body in the frame of the joint that moves it.

    mass : [kg]; com : (3,) centre of mass [m]; inertia : 3x3 tensor about the centre of mass,
    in the body frame's axes [kg*m^2].
    """

    name: str
    mass: float
    com: tuple[float, float, float]
    inertia: tuple[tuple[float, float, float], ...]

    def spatial_inertia(self) -> np.ndarray:
        """(6, 6) generalised inertia about the frame origin, twist order (omega, v) (section A.5).

        Kinetic energy is 1/2 V^T G V with V the body twist in body coordinates; the centre-of-mass
        offset enters through the parallel-axis and coupling blocks, as the thesis' generalised mass.
        """
        c = np.asarray(self.com)
        cx = np.array([[0.0, -c[2], c[1]], [c[2], 0.0, -c[0]], [-c[1], c[0], 0.0]])
        m = self.mass
        top = np.hstack([np.asarray(self.inertia) - m * cx @ cx, m * cx])
        bottom = np.hstack([-m * cx, m * np.eye(3)])
        return np.vstack([top, bottom])




@dataclass(frozen=True)
class MachineParams:
    """All machine parameters: six joints and six bodies in the order of eq. A.7, gravity, head offset."""

    name: str
    joints: tuple[JointLimits, ...]
    bodies: tuple[Body, ...]
    gravity: float = GRAVITY
    head_offset: tuple[float, float, float] = (0.0, 0.0, 0.0)

    @property
    def position_min(self) -> np.ndarray:
        """(6,) lower position bounds [rad | m]; -inf where unbounded."""
        return np.array([-np.inf if j.position is None else j.position[0] for j in self.joints])

    @property
    def position_max(self) -> np.ndarray:
        """(6,) upper position bounds [rad | m]; +inf where unbounded."""
        return np.array([np.inf if j.position is None else j.position[1] for j in self.joints])

    @property
    def velocity_max(self) -> np.ndarray:
        return np.array([j.velocity for j in self.joints])

    @property
    def acceleration_max(self) -> np.ndarray:
        return np.array([j.acceleration for j in self.joints])

    @property
    def jerk_max(self) -> np.ndarray:
        """(6,) jerk bounds [rad/s^3 | m/s^3]; inf where the set gives none."""
        return np.array([j.jerk for j in self.joints])

    @property
    def effort_max(self) -> np.ndarray:
        return np.array([j.effort for j in self.joints])

    @property
    def power_max(self) -> np.ndarray:
        return np.array([j.power for j in self.joints])

    def simplified(self) -> "MachineParams":
        """The thesis' simplified dynamics (section 5.7): every centre of mass moved to its frame origin."""
        bodies = tuple(dataclasses.replace(b, com=(0.0, 0.0, 0.0)) for b in self.bodies)
        return dataclasses.replace(self, name=self.name + " (simplified)", bodies=bodies)

    def to_dict(self) -> dict[str, Any]:
        """Plain SI values, for result files (``summary.json``)."""
        return {
            "name": self.name,
            "gravity_m_s2": self.gravity,
            "head_offset_m": list(self.head_offset),
            "joints": {j.name: {"kind": j.kind,
                                "position": None if j.position is None else list(j.position),
                                "velocity": j.velocity, "acceleration": j.acceleration,
                                "effort": j.effort, "power": j.power,
                                "jerk": None if math.isinf(j.jerk) else j.jerk} for j in self.joints},
            "bodies": {b.name: {"mass_kg": b.mass, "com_m": list(b.com),
                                "inertia_kg_m2": [list(r) for r in b.inertia]} for b in self.bodies},
        }


# ----------------------------------------------------------------------------------------------
# Loading


def load_params(path: str | Path | None = None, base: str | None = None,
                numbers: dict[str, float] | None = None) -> MachineParams:
    """Machine parameters: a built-in set, overridden by the keys of an optional user TOML file, then
    by single ``numbers``.

    Parameters
    ----------
    path : a TOML file giving any subset of the keys of ``data/default.toml``; None for none.
    base : built-in set to start from, one of ``BUILTIN_SETS``. Defaults to the file's ``base`` key,
        else ``"default"``.
    numbers : values by their dotted key (:func:`number_keys`: ``joints.track.position_m.max``),
        checked as a file's are (a design study's point, :mod:`desdemona.runs.study`).

    Raises
    ------
    ParameterError : naming the file, the key, the value and what is allowed.
    """
    user: dict[str, Any] = {}
    source = "<built-in>"
    if path is not None:
        source = str(path)
        try:
            with open(path, "rb") as fh:
                user = tomllib.load(fh)
        except FileNotFoundError:
            raise ParameterError(f"{source}: parameter file not found") from None
        except tomllib.TOMLDecodeError as exc:
            raise ParameterError(f"{source}: not valid TOML: {exc}") from None
    chosen = base or (user["base"] if "base" in user else "default")
    if chosen not in BUILTIN_SETS:
        raise ParameterError(f"{source}: base = {chosen!r}: unknown parameter set; "
                             f"valid: {', '.join(BUILTIN_SETS)}")
    text = resources.files("desdemona").joinpath(f"data/{chosen}.toml").read_text()
    merged = _parse(tomllib.loads(text), f"<built-in {chosen}>")
    merged = _merge(merged, _parse(user, source))
    if numbers:
        source = f"{source} with {', '.join(f'{k} = {v:g}' for k, v in numbers.items())}"
        merged = _merge(merged, _parse(_fragment(numbers, merged), source))
    return _build(merged, source)


# Elements of a parameter given as a list, by name (a key of :func:`number_keys` ends in one).
_ELEMENTS = {"position": ("min", "max"), "head_offset": ("x", "y", "z"), "com": ("x", "y", "z"),
             "inertia": ("xx", "yy", "zz", "xy", "xz", "yz")}


# Words for a limit that are not its key's, and the quantity they mean (for an unknown key's nearest).
_MEANT = {"upper": "max", "lower": "min", "max": "max", "min": "min", "travel": "position", "rate": "velocity",
          "speed": "velocity", "accel": "acceleration", "torque": "torque", "force": "force"}


def number_keys() -> tuple[str, ...]:
    """Every single number of a parameter file as a dotted key, in each of its units: ``gravity_m_s2``,
    ``head_offset_m.x``, ``joints.track.position_m.max``, ``joints.yaw.velocity_deg_s``,
    ``joints.yaw.torque_kN_m``, ``bodies.cabin.mass_kg``, ``bodies.cabin.com_m.z``,
    ``bodies.cabin.inertia_kg_m2.xx``: what a design study may vary (``load_params(numbers=...)``)."""
    def leaves(quantity: str, kind: str, element: str | None = None) -> list[str]:
        names = [f"{quantity}_{unit}" for unit in _UNITS[kind]]
        return [f"{n}.{e}" for n in names for e in _ELEMENTS[quantity]] if quantity in _ELEMENTS else names

    keys = [*leaves("gravity", "linear_acceleration"), *leaves("head_offset", "length")]
    for i, name in enumerate(JOINT_NAMES):
        col = 0 if JOINT_KINDS[i] == "revolute" else 1
        keys += [f"joints.{name}.{leaf}" for quantity, kinds in _JOINT_QUANTITIES.items() if kinds[col]
                 for leaf in leaves(quantity, kinds[col])]
    for name in BODY_NAMES:
        keys += [f"bodies.{name}.{leaf}" for quantity, kind in _BODY_QUANTITIES.items()
                 for leaf in leaves(quantity, kind)]
    return tuple(keys)


def _fragment(numbers: dict[str, float], merged: dict[str, Any]) -> dict[str, Any]:
    """The parameter file (as ``tomllib`` reads it) that sets ``numbers`` (:func:`number_keys`) on the
    parsed set ``merged``: an element of a list (a position's min, a head offset's x) is written with
    the list's other elements as ``merged`` has them. Raises :class:`ParameterError` for an unknown key,
    with the nearest known ones."""
    known = number_keys()
    fragment: dict[str, Any] = {}
    for key, value in numbers.items():
        if key not in known:
            import difflib

            prefix = ".".join(key.split(".")[:2]) + "."
            within = [k for k in known if k.startswith(prefix)] if prefix.split(".")[0] in ("joints", "bodies") else []
            meant = _MEANT.get(key.split(".")[-1])  # a limit named in words: its key's quantity
            within = [k for k in within if meant in k] if meant else within
            near = difflib.get_close_matches(key, within or known, n=3, cutoff=0.5 if not within else 0.0)
            raise ParameterError(f"{key}: unknown parameter; nearest: {', '.join(near) or 'none'} (keys are "
                                 "written as in a parameter file, with their unit: joints.track.position_m.max, "
                                 "joints.yaw.velocity_deg_s, head_offset_m.x)")
        *where, leaf = key.split(".")
        element = None
        if leaf in {e for names in _ELEMENTS.values() for e in names} and where[-1].split("_")[0] in (
                "position", "head", "com", "inertia"):
            *where, leaf, element = key.split(".")
        table = fragment
        for part in where:
            table = table.setdefault(part, {})
        if element is None:
            table[leaf] = value
            continue
        quantity, unit = _split_key(leaf, _ELEMENTS)
        if leaf not in table:
            group = merged["top"] if not where else merged[where[0]][where[1]]
            current = group.get("position" if quantity == "position" else quantity)
            if current is None:
                raise ParameterError(f"{key}: joints.{where[1]} has no position limit (unbounded): give both "
                                     f"ends in a --params file first")
            kind = _TOP_QUANTITIES.get(quantity) or _BODY_QUANTITIES.get(quantity) or (
                "angle" if JOINT_KINDS[JOINT_NAMES.index(where[1])] == "revolute" else "length")
            table[leaf] = (np.asarray(current, dtype=float) / _UNITS[kind][unit]).tolist()
        cell = _ELEMENTS[quantity].index(element)
        if quantity == "inertia":
            a, b = ("xyz".index(element[0]), "xyz".index(element[1]))
            table[leaf][a][b] = table[leaf][b][a] = value
        else:
            table[leaf][cell] = value
    return fragment


def default_params() -> MachineParams:
    """The built-in defaults (assumptions standing in for thesis tables A.1-A.4, see data/default.toml)."""
    return _builtin("default")


def thesis_toy_params() -> MachineParams:
    """The thesis' toy parameters of section 4.7 (M1 = 1, ie1 = 1, M2 = 2, ie2 = 2)."""
    return _builtin("thesis-toy")


def _builtin(name: str) -> MachineParams:
    # Parsed once per process: MachineParams is immutable, so sharing it is safe.
    if name not in _BUILTIN_CACHE:
        _BUILTIN_CACHE[name] = load_params(base=name)
    return _BUILTIN_CACHE[name]


_BUILTIN_CACHE: dict[str, MachineParams] = {}


def _split_key(key: str, quantities) -> tuple[str, str | None]:
    """'velocity_deg_s' -> ('velocity', 'deg_s'); 'position' -> ('position', None)."""
    for q in sorted(quantities, key=len, reverse=True):
        if key == q:
            return q, None
        if key.startswith(q + "_"):
            return q, key[len(q) + 1:]
    return "", None


def _unit_factor(where: str, quantity: str, quantity_kind: str, unit: str | None, value) -> float:
    units = _UNITS[quantity_kind]
    keys = ", ".join(f"{quantity}_{u}" for u in units)
    if unit is None:
        raise ParameterError(f"{where}: {value!r} has no unit; write the unit in the key: one of {keys}")
    if unit not in units:
        raise ParameterError(f"{where}: unit '{unit}' is not a unit of {quantity_kind.replace('_', ' ')}; "
                             f"valid keys: {keys}")
    return units[unit]


def _number(where: str, value) -> float:
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        raise ParameterError(f"{where}: expected a number, got {value!r} ({type(value).__name__})")
    x = float(value)
    if not math.isfinite(x):
        raise ParameterError(f"{where}: {value!r} is not a finite number")
    return x


def _numbers(where: str, value, shape: tuple[int, ...]) -> np.ndarray:
    arr = value
    if not isinstance(value, list):
        raise ParameterError(f"{where}: expected a list of {shape[0]} numbers, got {value!r}")
    try:
        arr = np.array(value, dtype=object)
    except ValueError:
        raise ParameterError(f"{where}: ragged list {value!r}") from None
    if arr.shape != shape:
        raise ParameterError(f"{where}: expected shape {shape}, got {value!r}")
    return np.array([_number(where, v) for v in arr.ravel()]).reshape(shape)


def _parse(data: dict[str, Any], source: str) -> dict[str, Any]:
    """Check keys and units of one file; return {'top': {...}, 'joints': {...}, 'bodies': {...}} in SI."""
    out: dict[str, Any] = {"top": {}, "joints": {}, "bodies": {}}
    for key, value in data.items():
        where = f"{source}: {key}"
        if key in _TOP_PLAIN:
            if not isinstance(value, str):
                raise ParameterError(f"{where}: expected a string, got {value!r}")
            out["top"][key] = value
        elif key == "joints":
            out["joints"] = _parse_group(value, where, JOINT_NAMES, _parse_joint)
        elif key == "bodies":
            out["bodies"] = _parse_group(value, where, BODY_NAMES, _parse_body)
        else:
            quantity, unit = _split_key(key, _TOP_QUANTITIES)
            if not quantity:
                valid = ", ".join([*_TOP_PLAIN, "gravity_m_s2", "head_offset_m", "joints", "bodies"])
                raise ParameterError(f"{where}: unknown key; valid keys: {valid}")
            factor = _unit_factor(where, quantity, _TOP_QUANTITIES[quantity], unit, value)
            if quantity == "gravity":
                out["top"]["gravity"] = _number(where, value) * factor
            else:
                out["top"]["head_offset"] = tuple(float(x) for x in _numbers(where, value, (3,)) * factor)
    return out


def _parse_group(value, where, names, parse_one) -> dict[str, dict]:
    if not isinstance(value, dict):
        raise ParameterError(f"{where}: expected a table, got {value!r}")
    out = {}
    for name, table in value.items():
        if name not in names:
            raise ParameterError(f"{where}.{name}: unknown name; valid: {', '.join(names)}")
        if not isinstance(table, dict):
            raise ParameterError(f"{where}.{name}: expected a table, got {table!r}")
        out[name] = parse_one(table, f"{where}.{name}", names.index(name))
    return out


def _parse_joint(table: dict, where: str, index: int) -> dict[str, Any]:
    kind = JOINT_KINDS[index]
    col = 0 if kind == "revolute" else 1
    out: dict[str, Any] = {}
    for key, value in table.items():
        w = f"{where}.{key}"
        quantity, unit = _split_key(key, _JOINT_QUANTITIES)
        if not quantity:
            raise ParameterError(f"{w}: unknown key; valid: position, velocity, acceleration, jerk, "
                                 f"{'torque' if col == 0 else 'force'}, power (each with a unit suffix)")
        qkind = _JOINT_QUANTITIES[quantity][col]
        if qkind is None:
            other = "torque_N_m or torque_kN_m" if col == 0 else "force_N or force_kN"
            raise ParameterError(f"{w}: a {kind} joint has a {'torque' if col == 0 else 'force'} limit, "
                                 f"write {other}")
        if quantity in ("position", "jerk") and value == "unbounded":
            out[quantity] = None if quantity == "position" else math.inf
            continue
        factor = _unit_factor(w, quantity, qkind, unit, value)
        if quantity == "position":
            lo, hi = _numbers(w, value, (2,)) * factor
            if not lo < hi:
                raise ParameterError(f"{w}: min {value[0]!r} must be less than max {value[1]!r}")
            out["position"] = (float(lo), float(hi))
        else:
            x = _number(w, value) * factor
            if not x > 0.0:
                raise ParameterError(f"{w}: {value!r} must be > 0")
            out["effort" if quantity in ("torque", "force") else quantity] = x
    return out


def _parse_body(table: dict, where: str, index: int) -> dict[str, Any]:
    out: dict[str, Any] = {}
    for key, value in table.items():
        w = f"{where}.{key}"
        quantity, unit = _split_key(key, _BODY_QUANTITIES)
        if not quantity:
            raise ParameterError(f"{w}: unknown key; valid: mass_kg, com_m, inertia_kg_m2")
        factor = _unit_factor(w, quantity, _BODY_QUANTITIES[quantity], unit, value)
        if quantity == "mass":
            m = _number(w, value) * factor
            if m < 0.0:
                raise ParameterError(f"{w}: {value!r} must be >= 0")
            out["mass"] = m
        elif quantity == "com":
            out["com"] = tuple(float(x) for x in _numbers(w, value, (3,)) * factor)
        else:
            out["inertia"] = _inertia(w, value, factor)
    return out


def _inertia(where: str, value, factor: float) -> tuple[tuple[float, ...], ...]:
    if isinstance(value, list) and len(value) == 3 and not isinstance(value[0], list):
        inertia = np.diag(_numbers(where, value, (3,)))
    else:
        inertia = _numbers(where, value, (3, 3))
    inertia = inertia * factor
    scale = max(1.0, float(np.abs(inertia).max()))
    if not np.allclose(inertia, inertia.T, atol=1e-12 * scale):
        raise ParameterError(f"{where}: {value!r} is not symmetric")
    moments = np.linalg.eigvalsh(inertia)
    if moments.min() < -1e-12 * scale:
        raise ParameterError(f"{where}: {value!r} is not positive semi-definite "
                             f"(principal moments {moments.tolist()})")
    # A rigid body's principal moments obey the triangle inequality (I_a <= I_b + I_c).
    if 2.0 * moments.max() > moments.sum() + 1e-9 * scale:
        raise ParameterError(f"{where}: {value!r} is not the inertia of a rigid body: the principal "
                             f"moments {moments.tolist()} violate I_a <= I_b + I_c")
    return tuple(tuple(float(x) for x in row) for row in inertia)


def _merge(base: dict[str, Any], user: dict[str, Any]) -> dict[str, Any]:
    merged = {"top": {**base["top"], **user["top"]}, "joints": {}, "bodies": {}}
    for group in ("joints", "bodies"):
        for name in set(base[group]) | set(user[group]):
            merged[group][name] = {**base[group].get(name, {}), **user[group].get(name, {})}
    return merged


def _build(merged: dict[str, Any], source: str) -> MachineParams:
    joints = []
    for i, name in enumerate(JOINT_NAMES):
        table = merged["joints"].get(name, {})
        missing = [k for k in ("position", "velocity", "acceleration", "effort", "power") if k not in table]
        if missing:
            raise ParameterError(f"{source}: joints.{name}: missing {', '.join(missing)}")
        joints.append(JointLimits(name=name, kind=JOINT_KINDS[i], **table))
    bounded = [j.name for j in joints if math.isfinite(j.jerk)]
    if bounded and len(bounded) < len(joints):
        free = ", ".join(j.name for j in joints if not math.isfinite(j.jerk))
        raise ParameterError(f"{source}: joints.{free.split(',')[0]}: jerk is unbounded while "
                             f"{', '.join(bounded)} have jerk limits; give every joint a jerk limit "
                             f"(jerk_deg_s3, jerk_rad_s3 or jerk_m_s3) or none ({free} have none)")
    bodies = []
    for name in BODY_NAMES:
        table = merged["bodies"].get(name, {})
        missing = [k for k in ("mass", "com", "inertia") if k not in table]
        if missing:
            raise ParameterError(f"{source}: bodies.{name}: missing {', '.join(missing)}")
        bodies.append(Body(name=name, **table))
    top = merged["top"]
    gravity = top["gravity"]  # the built-in base always defines gravity, head offset and name
    if not 0.0 <= gravity <= 30.0:
        raise ParameterError(f"{source}: gravity_m_s2 = {gravity!r}: must lie in [0, 30] m/s^2")
    head = top["head_offset"]
    if max(abs(x) for x in head) > 3.0:
        raise ParameterError(f"{source}: head_offset_m = {list(head)!r}: each coordinate must lie in "
                             f"[-3, 3] m (the cabin is smaller than that)")
    return MachineParams(name=top["name"], joints=tuple(joints),
                         bodies=tuple(bodies), gravity=float(gravity),
                         head_offset=tuple(float(x) for x in head))

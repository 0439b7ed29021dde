"""Desired paths S_d: the motions a person in the cabin should feel (eq. 3.1), and their sources.

One module per source, all giving a :class:`DesiredPath`: the built-in paths (:mod:`.builtin`), CSV
files (:mod:`.csvfile`), JSBSim flights (:mod:`.jsbsim`, the optional ``jsbsim`` package loaded only
when a flight is run) and logged motions (:mod:`.log`), the last two through :mod:`.convert` (axes,
units, anti-alias resampling, the convention check); the value itself is :mod:`.path`, the cost's
weights :mod:`.weights`.
"""

from __future__ import annotations

from pathlib import Path

from desdemona.occupant.perception import THRESHOLDS
from desdemona.profiles.builtin import (PROFILES, RATE_NOISE_PER_FORCE_NOISE, car_lap, catapult, cosine,
                                        cosine_sweep, dfs_catapult, get_profile, pulses, recorded_version,
                                        roller_coaster)
from desdemona.profiles.csvfile import read_csv, write_csv
from desdemona.profiles.jsbsim import from_jsbsim
from desdemona.profiles.log import LogFormat, from_log
from desdemona.profiles.path import (ALIGNED_ROTATION_WEIGHT, ALIGNED_WEIGHTS, CHANNELS, MAX_ANGULAR_VELOCITY,
                                     MAX_SPECIFIC_FORCE, MODULUS_COLUMNS, PATH_COLUMNS, DesiredPath, G,
                                     ProfileError, above_g, along_vertical, at_least_g, modulus_version,
                                     vertical_force)
from desdemona.profiles.weights import WEIGHT_CHOICES, weights_for

__all__ = ["ALIGNED_ROTATION_WEIGHT", "ALIGNED_WEIGHTS", "CHANNELS", "G", "LogFormat", "MAX_ANGULAR_VELOCITY",
           "MAX_SPECIFIC_FORCE", "MODULUS_COLUMNS", "PATH_COLUMNS", "PROFILES", "RATE_NOISE_PER_FORCE_NOISE",
           "THRESHOLDS", "WEIGHT_CHOICES", "DesiredPath", "ProfileError", "above_g", "along_vertical", "at_least_g", "car_lap",
           "catapult", "cosine", "cosine_sweep", "dfs_catapult", "from_jsbsim", "from_log", "get_profile", "load",
           "modulus_version", "pulses", "read_csv", "recorded_version", "roller_coaster", "vertical_force",
           "weights_for", "write_csv"]


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

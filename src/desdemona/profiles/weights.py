"""Weights of the cost (the diagonal of Q, eq. 3.6) by name or by number, for a desired path."""

from __future__ import annotations

import numpy as np

from desdemona.occupant.perception import THRESHOLDS
from desdemona.profiles.path import DesiredPath, ProfileError

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

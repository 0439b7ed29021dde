"""Seeded random states within the machine's ranges, for identity and cross-checks."""

import numpy as np


def random_states(model, count: int, seed: int):
    """``count`` seeded states (q, qd, qdd), each (count, n), spread over the free joints' ranges."""
    rng = np.random.default_rng(seed)
    lim = model.limits
    lo = np.where(np.isfinite(lim.position_min), lim.position_min, -np.pi)
    hi = np.where(np.isfinite(lim.position_max), lim.position_max, np.pi)
    q = rng.uniform(lo, hi, size=(count, model.n))
    qd = rng.uniform(-1.0, 1.0, size=(count, model.n)) * lim.velocity
    qdd = rng.uniform(-1.0, 1.0, size=(count, model.n)) * lim.acceleration
    return q, qd, qdd

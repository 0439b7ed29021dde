"""One definition for floats and symbols: evaluate a CasADi Function on whatever the caller has.

Every model equation is written once, as a CasADi expression in SX symbols, and wrapped in a
``casadi.Function``. Calling that Function with SX or MX arguments inlines (SX) or embeds (MX) the same
expression, with exact derivatives, for the optimisers; calling it with numbers evaluates it. This module
does the numeric side: NumPy in, NumPy out, and a whole trajectory at once when rows are stacked.
"""

from __future__ import annotations

import casadi as ca
import numpy as np


def is_symbolic(*args) -> bool:
    return any(isinstance(a, (ca.SX, ca.MX)) for a in args)


def call(fun: ca.Function, *args, matrix: bool = False):
    """Evaluate ``fun`` (one output) on floats, arrays or CasADi symbols.

    Numeric arguments are vectors of shape (n,) for one state, or (N, n) for N states at once (rows are
    samples); the result is then (m,) or (N, m), or with ``matrix`` (m, k) or (N, m, k). Scalars are
    accepted where n = 1. Symbolic arguments give a symbolic result of the Function's output shape.
    """
    if is_symbolic(*args):
        return fun(*args)
    arrays = [np.asarray(a, dtype=float) for a in args]
    batch = arrays[0].ndim == 2
    for k, a in enumerate(arrays):
        n = fun.size1_in(k)
        if a.ndim > 2 or (a.ndim == 2) != batch or a.shape[-1:] not in ((n,), ()) or (a.ndim == 0 and n != 1):
            raise ValueError(f"{fun.name()}: argument {fun.name_in(k)} has shape {a.shape}, "
                             f"expected ({n},) or (N, {n})")
    columns = [a.T if a.ndim == 2 else a.reshape(-1, 1) for a in arrays]
    out = np.asarray(fun(*columns))  # (m, k * N): CasADi maps over horizontally stacked samples
    m, k = fun.size1_out(0), fun.size2_out(0)
    if not batch:
        return out if matrix else out[:, 0]
    samples = out.shape[1] // k
    if not matrix:
        return out.T
    return out.reshape(m, samples, k).transpose(1, 0, 2)

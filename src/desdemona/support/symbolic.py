"""One definition for floats and symbols: evaluate a CasADi Function on whatever the caller has.

Every model equation is written once, as a CasADi expression in SX symbols, and wrapped in a
``casadi.Function``. Calling that Function with SX or MX arguments inlines (SX) or embeds (MX) the same
expression, with exact derivatives, for the optimisers; calling it with numbers evaluates it. This module
does the numeric side: NumPy in, NumPy out, and a whole trajectory at once when rows are stacked.
"""

from __future__ import annotations

import threading
import weakref

import casadi as ca
import numpy as np

FEW = 8  # samples evaluated one by one through a kept buffer (:func:`_buffered`), not as one call
_local = threading.local()  # each thread its own buffers: a FunctionBuffer holds its work memory


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
    if not batch or len(arrays[0]) <= FEW:
        samples = [arrays] if not batch else [[a[i] for a in arrays] for i in range(len(arrays[0]))]
        outs = [_buffered(fun, sample) for sample in samples]
        if outs and outs[0] is not None:
            outs = [out.reshape(fun.size2_out(0), -1).T if matrix else out for out in outs]
            return np.stack(outs) if batch else outs[0]
    columns = [a.T if a.ndim == 2 else a.reshape(-1, 1) for a in arrays]
    out = np.asarray(fun(*columns))  # (m, k * N): CasADi maps over horizontally stacked samples
    m, k = fun.size1_out(0), fun.size2_out(0)
    if not batch:
        return out if matrix else out[:, 0]
    samples = out.shape[1] // k
    if not matrix:
        return out.T
    return out.reshape(m, samples, k).transpose(1, 0, 2)


def bound(fun: ca.Function, args: dict, results: dict):
    """A FunctionBuffer of ``fun`` that reads ``args`` and writes ``results`` in place (each a dict
    from an input's or output's index or name to a float array of its nonzeros), and the callable
    that evaluates it. The arrays must live as long as the buffer."""
    buffer, evaluate = fun.buffer()
    for key, array in args.items():
        buffer.set_arg(key if isinstance(key, int) else fun.index_in(key), memoryview(array))
    for key, array in results.items():
        buffer.set_res(key if isinstance(key, int) else fun.index_out(key), memoryview(array))
    return buffer, evaluate


def _buffered(fun: ca.Function, arrays) -> np.ndarray | None:
    """One sample of an SX Function with dense arguments and result, evaluated in place through a
    FunctionBuffer kept for it while the Function lives (None where it does not apply). CasADi's plain
    call converts every argument and result: one sample of S on ``full`` takes 0.046 ms that way and
    0.007 ms here, and a controller's cycle calls the model and its guard a few times
    (docs/benchmarks/real-time-iteration-without-conversions.md)."""
    kept = getattr(_local, "buffers", None)
    if kept is None:
        kept = _local.buffers = weakref.WeakKeyDictionary()
    if fun not in kept:
        dense = all(fun.sparsity_in(k).is_dense() for k in range(fun.n_in())) and fun.sparsity_out(0).is_dense()
        kept[fun] = None
        if fun.is_a("SXFunction") and dense:
            inputs = [np.zeros(fun.nnz_in(k)) for k in range(fun.n_in())]
            result = np.zeros(fun.nnz_out(0))
            kept[fun] = (*bound(fun, dict(enumerate(inputs)), {0: result}), inputs, result)
    if kept[fun] is None:
        return None
    _, evaluate, inputs, result = kept[fun]
    for into, a in zip(inputs, arrays):
        into[:] = a.ravel()
    evaluate()
    return result.copy()

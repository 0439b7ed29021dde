"""Keep freed memory in the process for the next factorisation (glibc only), and BLAS to one thread.

IPOPT factorises its KKT matrix with MUMPS once or twice per iteration, and MUMPS allocates its
workspace anew each time: tens of MB on ``full``. glibc serves blocks that large by ``mmap`` and
returns them to the system on ``free``, so every factorisation starts by faulting in fresh zeroed
pages. Raising the ``mmap`` and trim thresholds keeps that memory in the heap and reuses it: the car
lap on ``full`` solves in 11.5 s instead of 13.7 s (measured, same iterations). The process keeps its
peak memory until it ends, which a command that exits after the run does not mind; a library user
decides for themselves, so only the command line and the benchmarks call this.
"""

from __future__ import annotations

import ctypes
import ctypes.util
import os

M_TRIM_THRESHOLD, M_MMAP_THRESHOLD = -1, -3  # from glibc's malloc.h
THRESHOLD = 1 << 30


def reuse_freed_memory() -> bool:
    """Raise glibc's mmap and trim thresholds to 1 GiB; False where the C library is not glibc."""
    name = ctypes.util.find_library("c")
    try:
        libc = ctypes.CDLL(name)
        mallopt = libc.mallopt
    except (OSError, AttributeError, TypeError):
        return False
    return bool(mallopt(M_MMAP_THRESHOLD, THRESHOLD)) and bool(mallopt(M_TRIM_THRESHOLD, THRESHOLD))


def one_blas_thread() -> None:
    """Have OpenBLAS (the one CasADi's MUMPS factorises with) run one thread per process, unless the
    environment says otherwise: it reads ``OPENBLAS_NUM_THREADS`` when CasADi loads it, at the first
    solve. With a thread per core, its idle threads spin on ``sched_yield`` between the small dense
    blocks of a factorisation (375,000 calls in one solve), taking a core from the other start: the
    C172 take-off off-line on ``yaw-track-cabin``, four starts on two workers, 17.2 s (8.5 s of it system
    time) -> 13.3 s (0.5 s); its modulus on ``dfs`` 44.5 -> 40.1 s; the same iterations and optima. The
    parallelism is the starts', one process each, and the stage functions' threads."""
    os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")

"""Stage functions compiled to machine code once, and kept on disk for every later run.

CasADi evaluates an SX Function in its own virtual machine; generated as C and compiled, the same
function runs several times faster. On the off-line catapult on ``full`` (160 stages) the constraint
Jacobian took 2.9 s of a 10.9 s solve interpreted and 0.57 s compiled. The code is straight-line
arithmetic that the compiler's optimisations barely speed up: ``-O0`` compiles the stage functions of
``full`` in 1.3 s, ``-O1`` in 5.5 s (``-O2`` 38 s for the Jacobian alone) for the same solve time.

The stage functions depend only on the machine, the configuration and the problem's options: the
interval's length and the desired values are their inputs. So a library is compiled once per machine
parameter set and configuration and reused by every path and every later run. It is found by the
SHA-256 of its C source (with the CasADi version and the compiler command), in :func:`cache_dir`; a
new library is written under a temporary name and renamed, so that two processes compiling the same
source at once leave one whole file. Files there are only ever added: remove the folder to clear it.

Without a C compiler (``$CC``, else ``cc``), or when compiling fails, :func:`compiled` returns None
and the caller keeps the virtual machine: slower, same results.
"""

from __future__ import annotations

import hashlib
import os
import shutil
import subprocess
import tempfile
import warnings
from pathlib import Path

import casadi as ca

FLAGS = ("-O0", "-fPIC", "-shared")
# Where compiling takes longer than this, something is wrong with the toolchain: keep the virtual machine.
TIMEOUT = 300.0


def cache_dir() -> Path:
    """``$DESDEMONA_CACHE``, else ``$XDG_CACHE_HOME/desdemona``, else ``~/.cache/desdemona``."""
    if os.environ.get("DESDEMONA_CACHE"):
        return Path(os.environ["DESDEMONA_CACHE"])
    base = os.environ.get("XDG_CACHE_HOME") or Path.home() / ".cache"
    return Path(base) / "desdemona"


def compiler() -> str | None:
    """The C compiler's path, or None."""
    return shutil.which(os.environ.get("CC", "cc"))


def library(functions: list[ca.Function], flags: tuple[str, ...] = FLAGS) -> tuple[str, Path]:
    """The C source of ``functions`` and the path its compiled library (compiled with ``flags``) has
    in the cache."""
    generator = ca.CodeGenerator("stages.c", {"with_header": False})
    for function in functions:
        generator.add(function)
    source = generator.dump()
    key = hashlib.sha256("\n".join([ca.__version__, str(compiler()), *flags, source]).encode()).hexdigest()
    return source, cache_dir() / f"stages-{key[:24]}.so"


def is_cached(functions: list[ca.Function]) -> bool:
    """Whether these functions' library is already in the cache."""
    return library(functions)[1].exists()


def compiled(functions: list[ca.Function], flags: tuple[str, ...] = FLAGS) -> list[ca.Function] | None:
    """The same functions, evaluated by a library compiled with ``flags`` from the cache (compiled now
    if it is not there yet), or None without a working compiler (with a warning that says why)."""
    source, path = library(functions, flags)
    if not path.exists():
        cc = compiler()
        if cc is None:
            warnings.warn(f"no C compiler ({os.environ.get('CC', 'cc')}): the stage functions stay "
                          "interpreted (slower, same results)", RuntimeWarning, stacklevel=2)
            return None
        try:
            path.parent.mkdir(parents=True, exist_ok=True)
        except OSError as error:
            warnings.warn(f"cannot create the cache {path.parent} ({error}): the stage functions stay "
                          "interpreted", RuntimeWarning, stacklevel=2)
            return None
        with tempfile.TemporaryDirectory(dir=path.parent, prefix=".compiling-") as work:
            c_file, so_file = Path(work) / "stages.c", Path(work) / path.name
            c_file.write_text(source)
            try:
                subprocess.run([cc, *flags, str(c_file), "-o", str(so_file), "-lm"], check=True,
                               capture_output=True, text=True, timeout=TIMEOUT)
            except (OSError, subprocess.SubprocessError) as error:
                detail = getattr(error, "stderr", "") or str(error)
                warnings.warn(f"compiling the stage functions failed ({detail.strip()[:300]}): they stay "
                              "interpreted", RuntimeWarning, stacklevel=2)
                return None
            os.replace(so_file, path)  # atomic: a reader sees no library or a whole one
    return [ca.external(function.name(), str(path)) for function in functions]

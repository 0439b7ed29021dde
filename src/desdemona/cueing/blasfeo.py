"""HPIPM and fatrop on linear algebra built for this processor (the real-time iteration's QP, thesis
chapter 7, and the off-line NLP on ``full`` and ``dfs``, chapter 4).

CasADi's wheel ships HPIPM, the structure-exploiting QP solver of :mod:`desdemona.cueing.realtime_iteration`, and
fatrop, the structure-exploiting NLP solver of :mod:`desdemona.cueing.transcription` off-line, both linked
against BLASFEO built for a generic x86-64 target: its matrix kernels are 4x4 blocks of plain C.
Measured on 2026-12-03 (600 QPs of the F-16 turn on ``full``, `hold`, 46 intervals of 18 states and 6
controls, each solved three times): two thirds of the QP's time is in those kernels. BLASFEO built for
processors with AVX2 and FMA (its ``X64_INTEL_HASWELL`` target: every x86-64 server processor since
2013) solves the same QPs in the same iterations 2.2-2.8x faster: median 6.7-6.9 -> 2.4-3.2 ms, p99
11.2-11.5 -> 3.9-4.4 ms; the `dfs` QPs at 100 Hz (56 intervals of 12 states) 2.39 -> 1.18 ms median.
See docs/benchmarks/qp-linear-algebra.md; for fatrop, docs/benchmarks/fatrop-on-blasfeo-for-the-processor.md.

So, where it can, :func:`load` compiles the BLASFEO sources kept in ``data/blasfeo`` (version
:data:`VERSION`, the one CasADi's HPIPM and fatrop are linked against; BSD 2-clause, ``LICENSE.txt``
there) once into the cache (:func:`desdemona.cueing.compiled.cache_dir`), beside copies of CasADi's own HPIPM
plugin and library, has CasADi load its ``hpipm`` plugin from there, and then its ``fatrop`` plugin
from CasADi's own folder: the dynamic linker binds fatrop's ``libblasfeo.so.0`` to the one already
loaded. HPIPM and fatrop are the same code; only the kernels under them change, and with them the
rounding of their solutions (tested against CasADi's build in a separate process). The panel size of
the double-precision matrices, which their own code depends on, is 4 in both builds
(``blasfeo_block_size.h``).

Everywhere else CasADi's build is used, as before, and :func:`status` says why: another processor
or system, another BLASFEO in CasADi, no C compiler, a failed build (with a warning), HPIPM or fatrop
loaded before :func:`load` ran, or ``DESDEMONA_BLASFEO=generic`` in the environment (to compare the two).
"""

from __future__ import annotations

import concurrent.futures
import contextlib
import hashlib
import os
import platform
import shutil
import subprocess
import sys
import tempfile
import threading
import warnings
from pathlib import Path

import casadi as ca

from desdemona.cueing import compiled
from desdemona.support import guard

VERSION = "0.1.4.2"
SOURCES = Path(__file__).parents[1] / "data" / "blasfeo"
# The flags of BLASFEO's own Makefile for TARGET=X64_INTEL_HASWELL, LA=HIGH_PERFORMANCE, BLAS_API=0.
C_FLAGS = ("-O2", "-fPIC", "-DLA_HIGH_PERFORMANCE", "-DBLASFEO_REF_API", "-DMF_PANELMAJ", "-DK_MAX_STACK=300",
           "-DUSE_C99_MATH", "-DEXT_DEP", "-DOS_LINUX", "-DEXTERNAL_BLAS_NONE", "-m64", "-mavx2", "-mfma",
           "-DTARGET_X64_INTEL_HASWELL")
ASM_FLAGS = ("-DLA_HIGH_PERFORMANCE", "-DMF_PANELMAJ", "-DMACRO_LEVEL=1", "-DOS_LINUX")
# CasADi's files copied beside the new BLASFEO: its HPIPM plugin finds libhpipm.so, and that finds
# libblasfeo.so.0, in its own folder ($ORIGIN)
CASADI_FILES = ("libcasadi_conic_hpipm.so", "libhpipm.so")
BUILD_TIMEOUT = 300.0  # seconds for the whole build; beyond it something is wrong with the toolchain

_lock = threading.Lock()
_status: str | None = None


def status() -> str | None:
    """What the ``hpipm`` and ``fatrop`` plugins run on, as :func:`load` left it (None before it ran)."""
    return _status


def unavailable() -> str | None:
    """Why BLASFEO cannot be built for this process, or None when it can."""
    if os.environ.get("DESDEMONA_BLASFEO", "").lower() == "generic":
        return "DESDEMONA_BLASFEO=generic"
    if not sys.platform.startswith("linux") or platform.machine() not in ("x86_64", "AMD64"):
        return f"built only for x86-64 Linux, this is {sys.platform} on {platform.machine()}"
    if not compiled.processor_flags():
        return "the processor lacks AVX2 or FMA"
    casadi_dir = Path(ca.__file__).parent
    if not (casadi_dir / f"libblasfeo.so.{VERSION}").exists():
        return f"CasADi {ca.__version__}'s HPIPM is linked against another BLASFEO than {VERSION}"
    missing = [name for name in CASADI_FILES if not (casadi_dir / name).exists()]
    if missing:
        return f"CasADi {ca.__version__} has no {', '.join(missing)}"
    if compiled.compiler() is None:
        return f"no C compiler ({os.environ.get('CC', 'cc')})"
    return None


def load(wait: bool = True) -> str:
    """Have CasADi's ``hpipm`` and ``fatrop`` plugins run on BLASFEO built for this processor, building
    it into the cache the first time (about 15 s on two cores), where it can; once per process (a
    plugin, once loaded, stays). Returns :func:`status`.

    wait : where it is not built yet, build it now; else (an off-line solve, which a first run should
    not hold up for it) run on CasADi's build this time and build it in the background for later runs
    (:func:`desdemona.cueing.compiled.start_once`). The two give the same iterates to round-off."""
    global _status
    with _lock:
        if _status is None:
            _status = _load(wait)
        return _status


def _load(wait: bool) -> str:
    generic = "CasADi's generic BLASFEO"
    if _mapped("libcasadi_conic_hpipm") or _mapped("libfatrop"):
        return f"{generic} (HPIPM or fatrop was loaded before)"
    reason = unavailable()
    if reason:
        return f"{generic} ({reason})"
    if not wait and not built():
        folder = _folder()
        folder.parent.mkdir(parents=True, exist_ok=True)
        marker = folder.with_name(folder.name + ".building")
        script = "import sys; from desdemona.cueing import blasfeo; blasfeo._background(sys.argv[1])"
        compiled.start_once(marker, [sys.executable, "-c", script, str(marker)], env=compiled.package_environment())
        return f"{generic} (BLASFEO for this processor is being built in the background, for later runs)"
    try:
        folder = build()
    except (OSError, subprocess.SubprocessError) as error:
        warnings.warn(f"building BLASFEO {VERSION} for this processor failed ({error}); HPIPM and fatrop run "
                      "on CasADi's generic build (slower, same results)", RuntimeWarning, stacklevel=3)
        return f"{generic} (the build failed: {error})"
    before = ca.GlobalOptions.getCasadiPath()
    try:
        ca.GlobalOptions.setCasadiPath(str(folder))
        ca.load_conic("hpipm")
    except RuntimeError as error:
        return f"{generic} (the plugin in {folder} did not load: {error})"
    finally:
        ca.GlobalOptions.setCasadiPath(before)
    try:  # from CasADi's folder; its libblasfeo.so.0 is the one loaded now
        ca.load_nlpsol("fatrop")
    except RuntimeError:
        pass  # a CasADi without fatrop: HPIPM alone
    mapped = _mapped("libblasfeo")
    if mapped and all(Path(m).parent == folder for m in mapped):
        return f"BLASFEO {VERSION} for AVX2 ({folder})"
    return f"{generic} (another BLASFEO was loaded before: {', '.join(sorted(set(mapped)))})"


def build() -> Path:
    """The cache's folder with BLASFEO built for this processor and CasADi's HPIPM beside it, built now
    if it is not there. The build runs in a temporary folder in the cache (as :mod:`desdemona.cueing.compiled`
    compiles), whose finished library folder is renamed into place, so a folder in the cache is always
    complete (two processes building at once keep one); nothing is left behind by a failed or
    interrupted build."""
    manifest = (SOURCES / "sources.txt").read_text().split()
    cc, folder = compiled.compiler(), _folder()
    if built():
        return folder
    folder.parent.mkdir(parents=True, exist_ok=True)
    with guard.lasting(f"building BLASFEO {VERSION} for this processor", f", once, into {folder.parent} (about "
                       "15 s on two cores)"), tempfile.TemporaryDirectory(dir=folder.parent, prefix=".hpipm-") as work:
        objects = _compile(cc, manifest, Path(work))
        lib = Path(work) / "lib"
        lib.mkdir()
        _run([cc, "-shared", "-Wl,-soname,libblasfeo.so.0", "-o", str(lib / "libblasfeo.so.0"),
              *map(str, objects), "-lm"])
        casadi_dir = Path(ca.__file__).parent
        for name in CASADI_FILES:
            shutil.copy2(casadi_dir / name, lib / name)
        try:
            lib.rename(folder)
        except OSError:  # another process finished first: keep its folder
            if not (folder / "libblasfeo.so.0").exists():
                raise
    return folder


def _folder() -> Path:
    """The cache's folder of BLASFEO built for this processor (built or not)."""
    manifest = (SOURCES / "sources.txt").read_text().split()
    key = hashlib.sha256("\n".join([VERSION, ca.__version__, str(compiled.compiler()), *C_FLAGS, *ASM_FLAGS,
                                    *manifest]).encode()).hexdigest()
    return compiled.cache_dir() / f"hpipm-{key[:24]}"


def built() -> bool:
    """Whether the cache holds BLASFEO built for this processor, with CasADi's HPIPM beside it."""
    folder = _folder()
    return all((folder / name).exists() for name in (*CASADI_FILES, "libblasfeo.so.0"))


def _background(marker: str) -> None:
    """:func:`load`'s process that builds BLASFEO for later runs, at the lowest priority; the marker
    that keeps other runs from starting another removed at its end, whatever happened."""
    compiled.lowest_priority()
    try:
        with open(os.devnull, "w") as quiet, contextlib.redirect_stderr(quiet):
            build()
    finally:
        Path(marker).unlink(missing_ok=True)


def _compile(cc: str, manifest: list[str], work: Path) -> list[Path]:
    """Each source of the manifest compiled by ``cc`` to an object in ``work``, on every core."""
    include = str(SOURCES / "include")

    def one(k: int, source: str) -> Path:
        obj = work / f"{k:03d}.o"
        flags = ASM_FLAGS if source.endswith(".S") else (*C_FLAGS, f"-I{include}")
        _run([cc, *flags, "-c", "-o", str(obj), str(SOURCES / source)])
        return obj

    with concurrent.futures.ThreadPoolExecutor(max_workers=os.cpu_count() or 1) as pool:
        futures = [pool.submit(one, k, source) for k, source in enumerate(manifest)]
        try:
            return [future.result(timeout=BUILD_TIMEOUT) for future in futures]
        except BaseException:
            for future in futures:
                future.cancel()
            raise


def _run(command: list[str]) -> None:
    done = subprocess.run(command, capture_output=True, text=True, timeout=BUILD_TIMEOUT)
    if done.returncode != 0:
        raise subprocess.SubprocessError(f"{Path(command[0]).name} exited {done.returncode}: "
                                         f"{done.stderr.strip()[-500:]}")


def _mapped(name: str) -> list[str]:
    """The files of this process' memory map whose name starts with ``name``."""
    try:
        with open(f"/proc/{os.getpid()}/maps") as fh:
            paths = {line.split()[-1] for line in fh if len(line.split()) >= 6}
    except OSError:
        return []
    return sorted(p for p in paths if Path(p).name.startswith(name))

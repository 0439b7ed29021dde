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

An optimised library (fatrop's stage functions at ``-O1`` with fused multiply-adds) takes a minute or
more to compile on ``full`` (6.7 MB of C; gcc's register allocation on straight-line code): a first
run, or the first after a changed weight or limit, does not wait for it. It compiles the same sources
at ``-O0``, each function a file of its own side by side on the cores (3.8 MB, a few seconds), solves
on that, and leaves the optimised library to a process of its own at the lowest priority, for later
runs (:func:`build`, :func:`in_background`; docs/benchmarks/first-run.md). The two
libraries give the same results to round-off, not bit for bit: the first run's iterates may differ
from a later run's in the last digits.

A fatrop solver of a problem that later runs pose again (the windows of a recording, the same for
every recording: :mod:`desdemona.cueing.windows`) is kept there too, serialized with its NLP's library
(:func:`store_solver`): CasADi's set-up of fatrop for a problem's structure takes 15 s at 1,200
intervals, loading it back under a second.

Without a C compiler (``$CC``, else ``cc``), or when compiling fails, :func:`compiled` returns None
and the caller keeps the virtual machine: slower, same results.
"""

from __future__ import annotations

import concurrent.futures
import contextlib
import gzip
import hashlib
import os
import platform
import shutil
import subprocess
import sys
import tempfile
import threading
import time
import warnings
import zlib
from pathlib import Path

import casadi as ca

from desdemona.support import guard

FLAGS = ("-O0", "-fPIC", "-shared")
#: What :func:`build` does where an optimised library is not in the cache yet: "later" compiles it in
#: the background for later runs and runs on the quick one (:data:`FLAGS`) now; "now" waits for it (the
#: benchmarks' steady state); "never" keeps the quick one (the tests: their cache goes with them).
OPTIMISED = "later"
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


def cpu_flags() -> set[str]:
    """The instruction set extensions of this processor (``/proc/cpuinfo``; empty where there is none)."""
    try:
        with open("/proc/cpuinfo") as fh:
            for line in fh:
                if line.startswith("flags"):
                    return set(line.split(":", 1)[1].split())
    except OSError:
        pass
    return set()


def processor_flags() -> tuple[str, ...]:
    """``-mavx2 -mfma`` on an x86-64 processor that has them, else nothing: with optimisation the
    stages' Jacobian and Hessian then evaluate in 13 % less time (fused multiply-adds; measured on
    ``full``, docs/benchmarks/fatrop-on-blasfeo-for-the-processor.md). The flags are part of the cache
    key, so a cache shared with another processor compiles its own library."""
    if platform.machine() in ("x86_64", "AMD64") and {"avx2", "fma"} <= cpu_flags():
        return ("-mavx2", "-mfma")
    return ()


def library(functions: list[ca.Function], flags: tuple[str, ...] = FLAGS) -> tuple[dict[str, str], Path]:
    """The C sources of ``functions``, one file each (:func:`sources`), and the path their compiled
    library (compiled with ``flags``) has in the cache."""
    files = sources(functions)
    key = hashlib.sha256("\n".join([ca.__version__, str(compiler()), *flags, *files, *files.values()]).encode())
    return files, cache_dir() / f"stages-{key.hexdigest()[:24]}.so"


def sources(functions: list[ca.Function]) -> dict[str, str]:
    """Each function's C source by its file's name: compiled side by side on the cores, and linked into
    one library (each file's own helpers are prefixed with its name)."""
    return {f"{function.name()}.c": c_source([function], f"{function.name()}.c") for function in functions}


def is_cached(functions: list[ca.Function]) -> bool:
    """Whether these functions' library is already in the cache."""
    return library(functions)[1].exists()


def compiled(functions: list[ca.Function], flags: tuple[str, ...] = FLAGS) -> list[ca.Function] | None:
    """The same functions, evaluated by a library compiled with ``flags`` from the cache (compiled now
    if it is not there yet), or None without a working compiler (with a warning that says why)."""
    path = build(functions, flags, later=False)
    return None if path is None else [ca.external(function.name(), str(path)) for function in functions]


def build(functions: list[ca.Function], flags: tuple[str, ...] = FLAGS, later: bool = True) -> Path | None:
    """The path of the cached library of ``functions`` compiled with ``flags`` (compiled now if it is
    not there yet), or None without a working compiler (with a warning that says why).

    later : where ``flags`` optimise (they are not :data:`FLAGS`) and their library is not cached yet,
    return the library of :data:`FLAGS` (``-O0``: seconds to compile, not a minute) and compile the
    optimised one in the background for later runs (as :data:`OPTIMISED` says). The two give the same
    results to round-off (fused multiply-adds), not bit for bit."""
    files, path = library(functions, flags)
    if path.exists():
        return path
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
    if later and tuple(flags) != FLAGS and OPTIMISED != "now":
        quick = library(functions, FLAGS)[1]
        if not quick.exists():
            with guard.lasting("compiling the stage functions for this machine and these options",
                               " (seconds; optimised ones in the background, for later runs)"):
                if not _compiled_into(cc, quick, files, list(FLAGS)):
                    return None
        if OPTIMISED == "later":
            in_background(path, files, list(flags))
        return quick
    # told where it takes long (optimised: fatrop's stage functions on ``full`` take a minute or more
    # at -O1); every compile is timed, for the command to print apart from the solve
    with guard.lasting("compiling the stage functions for this machine and these options",
                       f", once, into {path.parent}", told="-O0" not in flags):
        return path if _compiled_into(cc, path, files, list(flags)) else None


def in_background(target: Path, files: dict[str, str], flags: list[str]) -> None:
    """Compile ``files`` with ``flags`` into the library ``target`` of the cache in a process of its
    own, at the lowest priority, that outlives this one (a later run finds the library there); once
    for all processes that ask at once (a marker file beside the target holds the process' id while
    it lives). The sources wait in a folder of the cache that the compiling process removes."""

    def command() -> list[str]:
        pending = Path(tempfile.mkdtemp(dir=target.parent, prefix=".pending-"))
        for name, source in files.items():
            (pending / name).write_text(source)
        script = "import sys; from desdemona.cueing import compiled; compiled._background(*sys.argv[1:])"
        return [sys.executable, "-c", script, str(compiler()), str(target), str(pending), *flags]

    start_once(target.with_name(target.name + ".building"), command, env=package_environment())


def package_environment() -> dict:
    """This process' environment, with the folder this desdemona is imported from first on the path: a
    process started from it imports the same code, wherever it came from."""
    source = os.pathsep.join([str(Path(__file__).parents[2]), os.environ.get("PYTHONPATH", "")])
    return {**os.environ, "PYTHONPATH": source}


def start_once(marker: Path, command, env: dict | None = None) -> None:
    """Start the process ``command`` (its arguments, or a callable that prepares and returns them) on
    its own, in a session of its own (it outlives this process; it removes ``marker`` when it ends),
    unless the process whose id ``marker`` holds still runs: so of the runs that ask at once, one
    starts it. ``env``: its environment (default: this process'). Where it cannot be started, a
    warning: the run goes on, a later one tries again."""
    try:
        if _alive(marker):
            return
        marker.unlink(missing_ok=True)
        with open(marker, "x") as held:  # exclusive: of two processes asking at once, one starts it
            child = subprocess.Popen(command() if callable(command) else command, stdin=subprocess.DEVNULL,
                                     stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                                     start_new_session=True, close_fds=True, env=env)
            held.write(str(child.pid))
        threading.Thread(target=child.wait, daemon=True).start()  # reaped if this process outlives it
    except FileExistsError:
        return
    except OSError as error:
        marker.unlink(missing_ok=True)
        warnings.warn(f"cannot start {marker.stem} in the background ({error})", RuntimeWarning, stacklevel=3)


def c_source(functions: list[ca.Function], file: str) -> str:
    """The C source of ``functions``, generated as the file ``file`` (its name is in the source)."""
    generator = ca.CodeGenerator(file, {"with_header": False})
    for function in functions:
        generator.add(function)
    return generator.dump()


def linked(source: str, stages: Path, name: str, kept: Path | None = None) -> ca.Function | None:
    """Function ``name`` of the functions whose C ``source`` is :func:`c_source`'s, compiled now into
    a library of their own that calls the compiled stage functions of the library ``stages``
    (:func:`build`); the other functions are in the same library, where CasADi finds them by name
    (``External.factory``: an NLP solver asks its oracle for ``nlp_jac_g``, ``nlp_hess_l``, ...).
    Compiled at ``-O0`` (these functions only assemble the stages' blocks) into a temporary folder that
    is removed once the library is loaded, or, given ``kept``, into that file of the cache (a stored
    solver's, :func:`store_solver`). None, with a warning, where compiling fails."""
    flags = [*FLAGS, str(stages), f"-Wl,-rpath,{stages.parent}"]
    with guard.lasting("compiling the NLP's assembly of the stages", told=False):
        return _linked(source, flags, name, kept)


def _linked(source: str, flags: list[str], name: str, kept: Path | None) -> ca.Function | None:
    if kept is not None:
        return ca.external(name, str(kept)) if _compiled_into(compiler(), kept, {"assembly.c": source}, flags) else None
    with tempfile.TemporaryDirectory(prefix="desdemona-") as work:
        so_file = Path(work) / "assembly.so"
        if not _cc(compiler(), source, Path(work) / "assembly.c", [*flags, "-o", str(so_file)]):
            return None
        return ca.external(name, str(so_file))  # loaded: the file may go


def writable() -> bool:
    """Whether the cache can take new files (a shared, read-only one cannot: nothing is kept then)."""
    folder = cache_dir()
    return folder.is_dir() and os.access(folder, os.W_OK)


def solver_files(key: str) -> tuple[Path, Path]:
    """Where a solver found by ``key`` (a SHA-256 of everything it depends on) is kept in the cache:
    the solver serialized, and its NLP's library (:func:`linked`), whose path the solver holds."""
    return cache_dir() / f"solver-{key[:24]}.casadi.gz", cache_dir() / f"nlp-{key[:24]}.so"


def stored_solver(key: str) -> ca.Function | None:
    """The solver :func:`store_solver` kept under ``key``, or None where there is none (or it no longer
    loads: a warning says why, and the caller builds it again)."""
    file, nlp = solver_files(key)
    if not (file.exists() and nlp.exists()):
        return None
    try:
        solver = ca.Function.deserialize(gzip.decompress(file.read_bytes()).decode())
        with contextlib.suppress(OSError):  # used now: the last to go (_forget_solvers)
            os.utime(file)
        return solver
    except (OSError, RuntimeError, EOFError, zlib.error) as error:
        warnings.warn(f"the solver kept in {file} did not load ({str(error).strip()[:200]}): building it "
                      "again", RuntimeWarning, stacklevel=2)
        return None


def store_solver(key: str, solver: ca.Function) -> None:
    """Keep ``solver`` (whose NLP is the library :func:`linked` compiled into ``solver_files(key)[1]``) in
    the cache for later runs: CasADi sets fatrop up for a problem's structure in a time that grows with
    the square of its intervals (15 s at 1,200), and loads it back in under a second. Written under a
    temporary name and renamed, as the libraries are; where the cache cannot be written, a warning."""
    file = solver_files(key)[0]
    data = gzip.compress(solver.serialize().encode(), compresslevel=1)  # 62 -> 2 MB: mostly sparsity
    written = None
    try:
        with tempfile.NamedTemporaryFile(dir=file.parent, prefix=".storing-", delete=False) as out:
            written = Path(out.name)
            out.write(data)
        written.chmod(0o644)  # readable as the libraries beside it are
        os.replace(written, file)
    except OSError as error:
        if written is not None:
            written.unlink(missing_ok=True)
        warnings.warn(f"cannot keep the solver in {file.parent} ({error}): it is built again next time",
                      RuntimeWarning, stacklevel=2)
        return
    _forget_solvers(file.parent)


#: The solvers the cache keeps (about 3 MB each with their NLP's library): the most recently used.
SOLVERS_KEPT = 24


def _forget_solvers(folder: Path, kept: int = SOLVERS_KEPT) -> None:
    """Remove the solvers :func:`store_solver` kept in ``folder`` beyond the ``kept`` most recently
    used, with their NLP's libraries: every path length of a user's would otherwise keep one."""
    def used(file: Path) -> float:
        try:
            return file.stat().st_mtime
        except OSError:  # gone meanwhile (another run's clean-up)
            return 0.0
    solvers = sorted(folder.glob("solver-*.casadi.gz"), key=used, reverse=True)
    for old in solvers[kept:]:
        stem = old.name[len("solver-"):-len(".casadi.gz")]
        for file in (old, folder / f"nlp-{stem}.so"):
            file.unlink(missing_ok=True)


def oracle(nlp: dict, derivatives: dict[str, ca.Function]) -> list[ca.Function]:
    """An NLP as an NLP solver asks its oracle for it, by name (``nlp_f``, ``nlp_g``, ``nlp_grad_f``,
    ``nlp_jac_g``, ``nlp_hess_l``, ``nlp_grad``), with the given derivatives (``grad_f``, ``jac_g`` and
    ``hess_lag``, the Hessian whole: fatrop copies its stage blocks) for :func:`linked`.

    fatrop asks for the Lagrangian's gradient beside the Hessian and does not read it (CasADi 3.8: the
    same iterates with it zero, measured): it is left at zero, which saves an evaluation of the
    Jacobian per iteration. After a solve CasADi reads f and g from ``nlp_grad``; the multipliers are
    fatrop's own (the solver's options ``calc_lam_x`` and ``calc_lam_p`` off), so its gradients are left
    at zero too, and the NLP's C source without the transposed Jacobian's pattern (a third of it).
    """
    w, p = nlp["x"], nlp.get("p", ca.MX.sym("p", 0, 1))
    lam_f, lam_g = ca.MX.sym("lam_f"), ca.MX.sym("lam_g", nlp["g"].numel())
    f, g = nlp["f"], nlp["g"]
    grad, jac = derivatives["grad_f"](w, p)[1], derivatives["jac_g"](w, p)[1]
    hess = derivatives["hess_lag"](w, p, lam_f, lam_g)
    xp, xpl = ["x", "p"], ["x", "p", "lam_f", "lam_g"]
    return [ca.Function("nlp", [w, p], [f, g], xp, ["f", "g"]),
            ca.Function("nlp_f", [w, p], [f], xp, ["f"]), ca.Function("nlp_g", [w, p], [g], xp, ["g"]),
            ca.Function("nlp_grad_f", [w, p], [grad], xp, ["grad_f_x"]),
            ca.Function("nlp_jac_g", [w, p], [g, jac], xp, ["g", "jac_g_x"]),
            ca.Function("nlp_hess_l", [w, p, lam_f, lam_g], [ca.MX.zeros(w.numel()), hess], xpl,
                        ["grad_gamma_x", "hess_gamma_x_x"]),
            ca.Function("nlp_grad", [w, p, lam_f, lam_g], [f, g, ca.MX(w.numel(), 1), ca.MX(p.numel(), 1)], xpl,
                        ["f", "g", "grad_gamma_x", "grad_gamma_p"])]


def lowest_priority() -> None:
    """This process at the lowest priority: nice 19, and so its session's scheduling group (Linux's
    autogroup: a process in a session of its own shares the processor with the user's run as an equal
    group whatever its nice value; measured, the first run's solve took twice as long beside the
    background compile before)."""
    os.nice(19)
    try:
        with open("/proc/self/autogroup", "w") as group:
            group.write("19")
    except OSError:  # no autogroup here: nice alone
        pass


def _alive(marker: Path) -> bool:
    """Whether the process whose id ``marker`` holds still runs (a marker being written counts)."""
    try:
        text = marker.read_text().strip()
        if not text:
            return time.time() - marker.stat().st_mtime < 10.0
        os.kill(int(text), 0)
    except (OSError, ValueError):
        return False
    return True


def _compiled_into(cc: str | None, target: Path, files: dict[str, str], flags: list[str],
                   workers: int | None = None) -> bool:
    """Compile the C ``files`` (name: source) with ``cc`` and ``flags`` into the library ``target`` of
    the cache: in a temporary folder beside it, then renamed (atomic: a reader sees no library or a
    whole one). Several files are compiled side by side on ``workers`` cores (default: all; the
    largest first) and linked.
    False, with a warning, where compiling fails."""
    with tempfile.TemporaryDirectory(dir=target.parent, prefix=".compiling-") as work:
        so_file = Path(work) / target.name
        if len(files) == 1:
            (name, source), = files.items()
            if not _cc(cc, source, Path(work) / name, [*flags, "-o", str(so_file)]):
                return False
        else:
            compile_only = [f for f in flags if f != "-shared"]
            largest = sorted(files, key=lambda name: -len(files[name]))
            # the threads only compile: a failure is told from here, once (a warning from a thread
            # came after an interrupted run's last line)
            with concurrent.futures.ThreadPoolExecutor(max_workers=workers or os.cpu_count() or 1) as pool:
                failed = [error for error in pool.map(lambda name: _compile_error(
                    cc, files[name], Path(work) / name, [*compile_only, "-c", "-o", str(Path(work) / f"{name}.o")]),
                    largest) if error is not None]
            objects = [str(Path(work) / f"{name}.o") for name in largest]
            if failed:
                _failed(failed[0])
                return False
            if not _cc(cc, None, None, [*flags, *objects, "-o", str(so_file)]):
                return False
        os.replace(so_file, target)
    return True


def _cc(cc: str | None, source: str | None, c_file: Path | None, flags: list[str]) -> bool:
    """Compile ``source`` (written to ``c_file``; None: link the objects among ``flags``) with
    ``flags``; False, with a warning, where it fails."""
    error = _compile_error(cc, source, c_file, flags)
    if error is not None:
        _failed(error, stacklevel=4)
    return error is None


def _compile_error(cc: str | None, source: str | None, c_file: Path | None, flags: list[str]) -> str | None:
    """:func:`_cc` without the warning: None where it compiled, else what the compiler said."""
    try:
        if c_file is not None:
            c_file.write_text(source)
        subprocess.run([cc, *([str(c_file)] if c_file is not None else []), *flags, "-lm"], check=True,
                       capture_output=True, text=True, timeout=TIMEOUT)
    except (OSError, TypeError, subprocess.SubprocessError) as error:
        return (getattr(error, "stderr", "") or str(error)).strip()[:300]
    return None


def _failed(detail: str, stacklevel: int = 4) -> None:
    warnings.warn(f"compiling the stage functions failed ({detail}): they stay interpreted", RuntimeWarning,
                  stacklevel=stacklevel)


def _background(cc: str, target: str, pending: str, *flags: str) -> None:
    """:func:`in_background`'s process: the sources in ``pending`` compiled one after the other (a
    core stays free for the run that started it) into ``target``, then the sources and the marker
    removed, whatever happened. At the lowest priority on a busy machine a file may take many times
    what it takes in the foreground: each may take an hour here."""
    global TIMEOUT
    lowest_priority()
    TIMEOUT = 3600.0
    folder, target_path = Path(pending), Path(target)
    try:
        files = {file.name: file.read_text() for file in sorted(folder.glob("*.c"))}
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")  # nobody reads them: a failure leaves no library, a later run tries again
            _compiled_into(cc, target_path, files, list(flags), workers=1)
    finally:
        shutil.rmtree(folder, ignore_errors=True)
        target_path.with_name(target_path.name + ".building").unlink(missing_ok=True)



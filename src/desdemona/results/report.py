"""Result folders: trajectory.csv, summary.json, trajectory.mat and figures like the thesis'.

A folder is written to a temporary sibling and renamed into place only when complete, so a failed or
interrupted run never leaves a half-written result. Its ``summary.json`` carries ``"format":
"desdemona result"``: only a folder with that mark and nothing but result files in it is ever replaced
(:func:`check_replaceable`), never a file, the working folder, a folder holding the run's input, or a
folder of the user's; the final rename removes nothing the tool did not write, and a command holds
its output folder for its whole run (:func:`claim`), so that two runs never write the same one.
:func:`write` takes an off-line result, :func:`write_online` an on-line one (both values, never live
solver objects); :func:`load` reads a folder back. The figures are drawn by :mod:`desdemona.results.figures`.

``trajectory.csv``: a ``#`` line with the units, then the column names as the first non-comment line
(so pandas, ``csv.DictReader`` and MATLAB's ``readtable`` name the columns), then the rows.
"""

from __future__ import annotations

import contextlib
import csv
import json
import os
import platform
import shutil
import sys
import tempfile
from pathlib import Path

import numpy as np

from desdemona._version import __version__
from desdemona.check.simulate import Trajectory, trajectory_table
from desdemona.cueing import blasfeo
from desdemona.profiles import CHANNELS
from desdemona.results import figures
# The folder rules and readers, here too for the callers that write and read (report.load, ...).
from desdemona.results.folder import (RESULT_FILES, RESULT_FORMAT, ReportError, check_out_folder,  # noqa: F401
                                      check_replaceable, empty_folder, foreign_names, is_result_folder, load,
                                      read_summary, read_table, refuse_batch_folder, trajectory_of)
from desdemona.support import guard

UNITS = "units: SI (s, rad, m, rad/s, m/s, rad/s^2, m/s^2, N*m, N, W)"


LOCK_SUFFIX = ".desdemona-lock"


def lock_path(out_dir: str | Path) -> Path:
    """The lock of an output folder: the hidden sibling ``.<name>.desdemona-lock``."""
    out = Path(os.path.abspath(out_dir))  # "." and ".." by their names
    return out.parent / f".{out.name}{LOCK_SUFFIX}"


@contextlib.contextmanager
def claim(out_dir: str | Path, command: str | None = None):
    """Hold the output folder ``out_dir`` for one run, from before its first check until it ends.

    Two runs writing the same folder at once would mix or lose results: the lock file
    (:func:`lock_path`) is created atomically (``O_CREAT | O_EXCL``) and holds the run's process id
    and command; a second run finds it and is refused with :class:`ReportError` naming them. A lock
    left by a run that no longer exists (killed with SIGKILL, a power cut) is taken over. The lock
    is removed when the block ends, if it is still this run's."""
    lock = lock_path(out_dir)
    if lock.name == f".{LOCK_SUFFIX}":  # the file system's root: never a folder a run may write
        raise ReportError(f"{out_dir}: is the root folder; choose a folder of its own for the result")
    text = f"{os.getpid()}\n{command or command_line()}\n"
    for attempt in range(2):
        try:
            fd = os.open(lock, os.O_WRONLY | os.O_CREAT | os.O_EXCL, 0o644)
            break
        except FileExistsError:
            pid, holder = _lock_holder(lock)
            if attempt == 0 and pid is not None and not _alive(pid):
                with contextlib.suppress(FileNotFoundError):
                    os.unlink(lock)  # stale: its run has ended without removing it
                continue
            who = f"process {pid}" if pid is not None else "another run"
            raise ReportError(f"{out_dir}: another desdemona run is writing it ({who}: {holder or '?'}); "
                              f"wait until it ends or choose another folder (its lock is {lock})") from None
        except OSError as exc:
            raise ReportError(f"{out_dir}: cannot write in {lock.parent}: {exc.strerror or exc}") from None
    else:  # pragma: no cover - the stale lock was taken over by a third run between the two attempts
        raise ReportError(f"{out_dir}: another desdemona run is writing it; choose another folder")
    with os.fdopen(fd, "w") as fh:
        fh.write(text)

    def release() -> None:
        with contextlib.suppress(OSError):
            if lock.read_text() == text:
                os.unlink(lock)

    try:
        with guard.before_hard_exit(release):
            yield lock
    finally:
        release()


def _lock_holder(lock: Path) -> tuple[int | None, str]:
    try:
        pid, _, command = lock.read_text().partition("\n")
        return int(pid), command.strip()
    except (OSError, ValueError):
        return None, ""


def _alive(pid: int) -> bool:
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except OSError:  # it exists, but belongs to someone else
        return True
    return True


def versions() -> dict[str, str]:
    import casadi
    import scipy

    return {"desdemona": __version__, "python": platform.python_version(), "numpy": np.__version__,
            "scipy": scipy.__version__, "casadi": casadi.__version__}


def run_description(path, config) -> dict:
    """The "path" and "configuration" entries of a summary.json."""
    return {"path": {"name": path.name, "description": path.description, "duration_s": path.duration,
                     "weights": list(path.weights)},
            "configuration": config.summary()}


def write(result, out_dir: str | Path, command: str | None = None, overwrite: bool = False,
          unreachable: dict | None = None, protect=(), view: bool = True, extra_summary: dict | None = None,
          draw: bool = True) -> Path:
    """Write the result folder of an off-line :class:`~desdemona.cueing.offline.Result` atomically.

    unreachable : :func:`desdemona.cueing.sizing.unreachable` of the result's path (computed when not given).
    protect, view, draw : see :func:`write_folder`; extra_summary : more entries of summary.json.
    """
    if unreachable is None:
        from desdemona.cueing import sizing

        unreachable = sizing.unreachable(result.path, result.model)
    summary = {
        "command": command,
        **run_description(result.path, result.model.config),
        "method": result.method,
        "metrics": {
            "rms_weighted": result.check.rms,
            "rms_channels": None if result.check.rms_channels is None else dict(
                zip(CHANNELS, map(float, result.check.rms_channels))),
            "rms_perceived": result.check.rms_perceived,
            "rms_modulus": result.check.rms_modulus,
            "check_grid_step_s": result.check.step,
            "limits_kept": result.check.passed,
            "worst_use": result.check.worst,
            "worst_use_per_joint": {k: dict(zip(result.model.config.joint_names, map(float, v)))
                                    for k, v in result.check.use.items()},
        },
        "quality": result.quality.to_dict(),
        "unreachable": unreachable,
        "solver": {"converged": result.converged, "status": result.solution.status,
                   "success": result.solution.success,
                   "iterations": result.solution.iterations, "cost": result.solution.cost,
                   "starts": [vars(s) for s in result.starts], "timings_s": result.timings,
                   **({"linear_algebra": blasfeo.status()} if result.method == "fatrop" else {})},
        "limit_prices": None if getattr(result, "prices", None) is None else result.prices.to_dict(),
        "options": _plain(result.options),
        "parameters": result.model.params.to_dict(),
        "versions": versions(),
        **(extra_summary or {}),
    }
    return write_folder(result.trajectory, summary, result.model.config, out_dir, overwrite,
                        protect=protect, view=view, draw=draw)


def write_folder(traj: Trajectory, summary: dict, config, out_dir: str | Path, overwrite: bool = False,
                 extra=None, protect=(), view: bool = True, draw: bool = True) -> Path:
    """Write trajectory.csv, summary.json, trajectory.mat and the figures into ``out_dir`` atomically.

    overwrite : replace ``out_dir`` if it is a result folder of ours (:func:`check_replaceable`).
    extra : optional ``extra(folder)`` that writes more files into the folder before it is moved in.
    protect : paths (the run's inputs) that the replaced folder must not hold.
    view : also write view.html, the 3D replay (:mod:`desdemona.results.view`), from the folder's files.
    draw : draw the figures (a design study's points leave them to ``desdemona plot``: a second each).
    """
    import scipy.io

    out = Path(out_dir)
    if out.exists() and not overwrite and not empty_folder(out):
        raise ReportError(f"{out}: already exists (it appeared while this run worked, or was not checked); "
                          f"left as it is, nothing written: choose another folder, or --overwrite for an "
                          f"earlier result of desdemona")
    check_replaceable(out, protect)
    summary = {"format": RESULT_FORMAT, **summary}
    parent = out.resolve().parent
    if not parent.is_dir():
        raise ReportError(f"{out}: the parent folder {parent} does not exist")
    try:
        tmp = Path(tempfile.mkdtemp(prefix=f".{out.name}.", dir=parent))
    except OSError as exc:
        raise ReportError(f"{out}: cannot write in {parent}: {exc.strerror or exc}") from None
    try:
        umask = os.umask(0)
        os.umask(umask)
        os.chmod(tmp, 0o777 & ~umask)  # mkdtemp makes it private (0700); a result is an ordinary folder
        names, table = trajectory_table(traj, config)
        with open(tmp / "trajectory.csv", "w") as fh:
            fh.write(f"# {UNITS}\n{','.join(names)}\n")
            np.savetxt(fh, table, delimiter=",", fmt="%.10g")
        (tmp / "summary.json").write_text(json.dumps(summary, indent=2, default=_json_default))
        scipy.io.savemat(tmp / "trajectory.mat", {n.replace("-", "_"): table[:, i] for i, n in enumerate(names)},
                         oned_as="column")
        if draw:
            figures.draw_result(traj, summary, tmp)
        if extra is not None:
            extra(tmp)
        if view:
            from desdemona.results import view as result_view

            result_view.write(tmp)
        with guard.deferred():  # an interrupt between the two renames would lose both folders
            _move_into_place(tmp, out, overwrite, protect)
    except BaseException:
        shutil.rmtree(tmp, ignore_errors=True)
        raise
    return out


def _move_into_place(tmp: Path, out: Path, overwrite: bool, protect) -> None:
    """Rename the finished folder ``tmp`` to ``out``, removing nothing this tool did not write.

    ``out`` was checked before the run; it is checked again here, as something may have appeared there
    while the run worked (os.rename would replace an empty folder, and moving one aside would lose it).
    An earlier result is moved aside, checked once more, and only its result files are deleted."""
    if not out.exists() and not out.is_symlink():
        os.rename(tmp, out)
        return
    if empty_folder(out):  # given empty, or appeared so: nothing in it is lost (check_replaceable)
        check_replaceable(out, protect)  # not the current folder, nor one of its parents
        try:
            os.rmdir(out)
        except OSError as exc:  # a mount point, or something came into it just now
            raise ReportError(f"{out}: cannot be replaced by the result ({exc.strerror or exc}); nothing written: "
                              "choose another folder") from None
        os.rename(tmp, out)
        return
    if not overwrite or not is_result_folder(out):
        raise ReportError(f"{out}: appeared while this run was writing its result (not made by desdemona); "
                          f"left as it is and nothing written: choose another folder")
    try:
        check_replaceable(out, protect)
    except ReportError as exc:
        raise ReportError(f"{exc} (it changed while this run was writing; left as it is, nothing written)") from None
    old = Path(tempfile.mkdtemp(prefix=f".{out.name}.old.", dir=out.absolute().parent))
    os.rename(out, old / out.name)
    if not is_result_folder(old / out.name) or foreign_names(old / out.name):  # changed in between: put it back
        os.rename(old / out.name, out)
        old.rmdir()
        raise ReportError(f"{out}: changed while this run was writing its result; left as it is and nothing "
                          f"written: choose another folder")
    os.rename(tmp, out)
    for item in (old / out.name).iterdir():
        item.unlink()  # result files only (checked above); never a whole tree
    (old / out.name).rmdir()
    old.rmdir()


def redraw_online(traj: Trajectory, summary: dict, out_dir: str | Path) -> list[Path]:
    """Re-draw the figures of an on-line result folder (``online.png``, ``online_felt.png``,
    ``compute_time.png``) from its files; nothing for an off-line one. The classical loop is drawn
    where the folder keeps it (``classical.csv``)."""
    if "cycles" not in summary:
        return []
    out = Path(out_dir)
    joints = summary["configuration"]["free_joints"]
    classical = None
    if (out / "classical.csv").exists():
        classical = trajectory_of(read_table(out / "classical.csv"), joints)
    try:
        with open(out / "cycles.csv", newline="") as fh:
            times = np.array([float(row["compute_time_s"]) for row in csv.DictReader(fh)])
    except (OSError, ValueError, KeyError) as exc:
        raise ReportError(f"{out}: not a readable on-line result folder: {exc}") from None
    limits = summary["parameters"]["joints"]
    return figures.draw_online_run(
        traj, classical, [limits[j]["effort"] for j in joints], [limits[j]["power"] for j in joints], times,
        summary["cycles"]["deadline_s"], f"{summary['path']['name']} on-line, {summary['configuration']['name']}",
        (summary.get("quality") or {}).get("vestibular_model"), out, joints)


def _plain(value):
    if hasattr(value, "__dataclass_fields__"):
        return {k: _plain(getattr(value, k)) for k in value.__dataclass_fields__}
    if isinstance(value, (list, tuple)):
        return [_plain(v) for v in value]
    return value


def _json_default(value):
    if isinstance(value, np.ndarray):
        return value.tolist()
    if isinstance(value, np.generic):
        return value.item()
    raise TypeError(f"cannot write {type(value).__name__} to JSON")


def command_line() -> str:
    return " ".join(["desdemona", *sys.argv[1:]])


def start_description(result) -> dict:
    """Where an on-line session started: the ``initial`` option and the free joints' positions and
    rates (SI units) at t = 0, which "rest" chooses (:meth:`desdemona.control.mpc.MPC.place`)."""
    names, plan = result.model.config.joint_names, result.plan
    return {"initial": result.options.initial, "q0": dict(zip(names, map(float, plan.q0))),
            "qd0": dict(zip(names, map(float, plan.qd0)))}


def online_summary(result, command: str | None = None) -> dict:
    """The summary.json of an on-line :class:`~desdemona.control.online.OnlineResult`."""
    mpc, c = result.options.mpc, result.check
    times, sources = result.loop.compute_times, result.loop.sources
    baseline = result.baseline_check
    return {
        "command": command,
        **run_description(result.path, result.model.config),
        "method": f"mpc ({mpc.plan_method}), predictor {result.options.predictor}, horizon {mpc.horizon:g} s, "
                  + (f"reach {mpc.length:g} s, " if mpc.length > mpc.horizon else "") + f"step {mpc.step:g} s",
        "metrics": {"rms_weighted": c.rms, "rms_modulus": c.rms_modulus,
                    "rms_perceived": c.rms_perceived,
                    "rms_weighted_classical": None if baseline is None else baseline.rms,
                    "rms_perceived_classical": None if baseline is None else baseline.rms_perceived,
                    "rms_modulus_classical_loop": None if baseline is None else baseline.rms_modulus,
                    "limits_kept": c.passed, "worst_use": c.worst, "check_grid_step_s": c.step},
        "start": start_description(result),
        "quality": result.quality.to_dict(),
        "quality_classical_loop": None if result.baseline_quality is None else result.baseline_quality.to_dict(),
        "cycles": {"count": len(times), "deadline_s": result.deadline, "qp_linear_algebra": blasfeo.status(),
                   "compute_time_s": {"median": float(np.median(times)), "p99": float(np.percentile(times, 99)),
                                      "max": float(times.max())},
                   "sources": {s: sources.count(s) for s in ("mpc", "shifted", "brake")},
                   "deadline_misses": int(np.sum(times > result.deadline))},
        "limit_prices": None if getattr(result, "prices", None) is None else result.prices.to_dict(),
        "options": _plain(result.options),
        "parameters": result.model.params.to_dict(),
        "versions": versions(),
    }


def write_online(result, out_dir: str | Path, command: str | None = None, overwrite: bool = False,
                 unreachable: dict | None = None, protect=(), view: bool = True, cycle_columns: dict | None = None,
                 extra_summary: dict | None = None, files: dict | None = None) -> Path:
    """The result folder of an on-line :class:`~desdemona.control.online.OnlineResult`: the usual files plus
    ``cycles.csv`` (per-cycle compute time, source of the command, fallback reason), ``classical.csv``
    (the classical loop's run, columns as trajectory.csv's; none where there is no baseline), ``online.png``
    (like thesis figures 7.5/7.6) and ``compute_time.png`` (compute time per cycle against the deadline).
    unreachable, protect, view : as in :func:`write`; cycle_columns : more columns of ``cycles.csv``,
    name -> one value per cycle (the real-time service's message age, latency, status); extra_summary :
    more entries of ``summary.json``; files : more files of the folder, name -> text (each name one of
    :data:`RESULT_FILES`)."""
    if unreachable is None:
        from desdemona.cueing import sizing

        unreachable = sizing.unreachable(result.path, result.model)
    summary = {**online_summary(result, command), "unreachable": unreachable, **(extra_summary or {})}
    loop = result.loop
    more = cycle_columns or {}

    def extra(folder: Path) -> None:
        with open(folder / "cycles.csv", "w") as fh:
            fh.write(",".join(["t", "compute_time_s", "source", "reason", *more]) + "\n")
            for k, (t, c, s, r) in enumerate(zip(loop.cycle_times, loop.compute_times, loop.sources, loop.reasons)):
                cells = [f"{v[k]:.6g}" if isinstance(v[k], (float, np.floating)) else str(v[k]) for v in more.values()]
                fh.write(",".join([f"{t:.6g}", f"{c:.6g}", s, f"\"{r}\"", *cells]) + "\n")
        if result.baseline is not None:
            names, table = trajectory_table(result.baseline, result.model.config)
            with open(folder / "classical.csv", "w") as fh:
                fh.write(f"# classical loop; {UNITS}\n{','.join(names)}\n")
                np.savetxt(fh, table, delimiter=",", fmt="%.10g")
        for name, text in (files or {}).items():
            (folder / name).write_text(text)
        figures.draw_online(result, folder)

    return write_folder(result.trajectory, summary, result.model.config, out_dir, overwrite, extra,
                        protect=protect, view=view)

"""Result folders: trajectory.csv, summary.json, trajectory.mat and figures like the thesis'.

A folder is written to a temporary sibling and renamed into place only when complete, so a failed or
interrupted run never leaves a half-written result. Its ``summary.json`` carries ``"format":
"desdemona result"``: only a folder with that mark and nothing but result files in it is ever replaced
(:func:`check_replaceable`), never a file, the working folder, a folder holding the run's input, or a
folder of the user's. :func:`write` takes an off-line result, :func:`write_online` an on-line one (both
values, never live solver objects); :func:`load` reads a folder back. The figures are drawn by
:mod:`desdemona.figures`.

``trajectory.csv``: a ``#`` line with the units, then the column names as the first non-comment line
(so pandas, ``csv.DictReader`` and MATLAB's ``readtable`` name the columns), then the rows.
"""

from __future__ import annotations

import json
import os
import platform
import shutil
import sys
import tempfile
from pathlib import Path

import numpy as np

from desdemona import figures, guard
from desdemona._version import __version__
from desdemona.params import JOINT_NAMES
from desdemona.simulate import Trajectory

CHANNELS = ("wx", "wy", "wz", "fx", "fy", "fz")


RESULT_FORMAT = "desdemona result"  # the mark in summary.json that makes a folder ours to replace
# Everything a result folder of ours may hold: replacing one never deletes anything else.
RESULT_FILES = {"trajectory.csv", "summary.json", "trajectory.mat", "cycles.csv"}
UNITS = "units: SI (s, rad, m, rad/s, m/s, rad/s^2, m/s^2, N*m, N, W)"


class ReportError(RuntimeError):
    """The result folder cannot be written or read; the message says where and why."""


def check_replaceable(out_dir: str | Path, protect=()) -> None:
    """Raise :class:`ReportError` unless ``out_dir`` may be replaced by a new result: it is a result
    folder of ours (``summary.json`` with the :data:`RESULT_FORMAT` mark, only result files inside),
    not the working folder or one of its parents, and holds none of the paths in ``protect`` (the
    run's own inputs)."""
    out = Path(out_dir)
    refuse = f"{out}: --overwrite replaces only a desdemona result folder, and this is "
    if not out.exists():
        return
    if out.is_symlink() or not out.is_dir():
        raise ReportError(refuse + "not a folder (a file or a link)")
    real = out.resolve()
    cwd = Path.cwd().resolve()
    if real == cwd or real in cwd.parents:
        raise ReportError(refuse + "the current folder or one of its parents")
    for path in protect:
        if path is not None and real in Path(path).resolve().parents:
            raise ReportError(refuse + f"the folder of the input {path}")
    try:
        mark = json.loads((out / "summary.json").read_text()).get("format")
    except (OSError, ValueError, AttributeError):
        mark = None
    if mark != RESULT_FORMAT:
        raise ReportError(refuse + "not one (no summary.json written by desdemona)")
    others = sorted(p.name for p in out.iterdir() if p.name not in RESULT_FILES and p.suffix != ".png")
    if others:
        raise ReportError(refuse + f"holds other files too ({', '.join(others[:3])}); move them first")


def versions() -> dict[str, str]:
    import casadi
    import scipy

    return {"desdemona": __version__, "python": platform.python_version(), "numpy": np.__version__,
            "scipy": scipy.__version__, "casadi": casadi.__version__}


def trajectory_table(traj: Trajectory, config) -> tuple[list[str], np.ndarray]:
    """Column names and values (K, columns) of trajectory.csv.

    config : the result's :class:`~desdemona.configs.Configuration`. Positions, rates and accelerations
    are given for all six joints, the held ones at their fixed positions and at rest, so that the file
    drives the whole machine; torques and power for the free joints (a held joint's brake is not a
    motor limit, section 5.5).
    """
    names, columns = ["t"], [traj.t[:, None]]
    for label, values, held in (("q", traj.q, "position"), ("qd", traj.qd, "zero"), ("qdd", traj.qdd, "zero")):
        names += [f"{label}_{j}" for j in JOINT_NAMES]
        columns.append(config.expand(values, held))
    for label, values in (("tau", traj.tau), ("power", traj.power)):
        names += [f"{label}_{j}" for j in config.joint_names]
        columns.append(values)
    names += list(CHANNELS)
    columns.append(traj.S)
    if traj.S_d is not None:
        names += [f"{c}_d" for c in CHANNELS]
        columns.append(traj.S_d)
    names += ["M", "M_d"]
    columns += [traj.M[:, None], traj.M_d[:, None]]
    if traj.S_perc is not None:
        names += [f"{c}_perc" for c in CHANNELS] + [f"{c}_d_perc" for c in CHANNELS]
        columns += [traj.S_perc, traj.S_d_perc]
    return names, np.hstack(columns)


def run_description(path, config) -> dict:
    """The "path" and "configuration" entries of a summary.json."""
    return {"path": {"name": path.name, "description": path.description, "duration_s": path.duration,
                     "weights": list(path.weights)},
            "configuration": {"name": config.name, "free_joints": list(config.joint_names),
                              "held_positions": list(config.fixed)}}


def write(result, out_dir: str | Path, command: str | None = None, overwrite: bool = False,
          unreachable: dict | None = None, protect=()) -> Path:
    """Write the result folder of an off-line :class:`~desdemona.offline.Result` atomically.

    unreachable : :func:`desdemona.sizing.unreachable` of the result's path (computed when not given).
    protect : see :func:`write_folder`.
    """
    if unreachable is None:
        from desdemona import sizing

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
                   "starts": [vars(s) for s in result.starts], "timings_s": result.timings},
        "options": _plain(result.options),
        "parameters": result.model.params.to_dict(),
        "versions": versions(),
    }
    return write_folder(result.trajectory, summary, result.model.config, out_dir, overwrite,
                        protect=protect)


def write_folder(traj: Trajectory, summary: dict, config, out_dir: str | Path, overwrite: bool = False,
                 extra=None, protect=()) -> Path:
    """Write trajectory.csv, summary.json, trajectory.mat and the figures into ``out_dir`` atomically.

    overwrite : replace ``out_dir`` if it is a result folder of ours (:func:`check_replaceable`).
    extra : optional ``extra(folder)`` that writes more files into the folder before it is moved in.
    protect : paths (the run's inputs) that the replaced folder must not hold.
    """
    import scipy.io

    out = Path(out_dir)
    if out.exists() and not overwrite:
        raise ReportError(f"{out}: already exists; choose another folder or allow overwriting")
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
        figures.draw_result(traj, summary, tmp)
        if extra is not None:
            extra(tmp)
        with guard.deferred():  # an interrupt between the two renames would lose both folders
            if out.exists():
                old = Path(tempfile.mkdtemp(prefix=f".{out.name}.old.", dir=parent))
                os.replace(out, old / out.name)
                os.replace(tmp, out)
                shutil.rmtree(old)
            else:
                os.replace(tmp, out)
    except BaseException:
        shutil.rmtree(tmp, ignore_errors=True)
        raise
    return out


def load(out_dir: str | Path) -> tuple[Trajectory, dict]:
    """Read a result folder back: its trajectory and summary."""
    out = Path(out_dir)
    try:
        summary = json.loads((out / "summary.json").read_text())
        with open(out / "trajectory.csv") as fh:
            lines = fh.read().splitlines()
        rows = [line for line in lines if not line.startswith("#")]
        if rows and rows[0].startswith("t,"):
            names, rows = rows[0].split(","), rows[1:]
        else:  # written by earlier versions: the column names in a comment
            names = next(line.lstrip("# ") for line in lines if line.lstrip("# ").startswith("t,")).split(",")
        table = np.loadtxt(rows, delimiter=",", ndmin=2)
    except (OSError, ValueError, StopIteration) as exc:
        raise ReportError(f"{out}: not a readable result folder: {exc}") from None
    col = {n: table[:, i] for i, n in enumerate(names)}
    joints = summary["configuration"]["free_joints"]

    def block(prefix):
        return np.column_stack([col[f"{prefix}_{j}"] for j in joints])

    def channels(suffix):
        keys = [f"{c}{suffix}" for c in CHANNELS]
        return np.column_stack([col[k] for k in keys]) if keys[0] in col else None

    traj = Trajectory(t=col["t"], q=block("q"), qd=block("qd"), qdd=block("qdd"), tau=block("tau"),
                      power=block("power"), S=channels(""), S_d=channels("_d"), M=col["M"], M_d=col["M_d"],
                      S_perc=channels("_perc"), S_d_perc=channels("_d_perc"))
    return traj, summary


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




def trajectory_dataframe(traj: Trajectory, config):
    """A pandas DataFrame of a trajectory with the columns of trajectory.csv, indexed by t [s].

    pandas is an optional extra (``pip install 'desdemona[dataframe]'``), not a dependency.
    """
    try:
        import pandas
    except ImportError:
        raise ImportError("a DataFrame needs pandas: pip install 'desdemona[dataframe]'") from None
    names, table = trajectory_table(traj, config)
    return pandas.DataFrame(table[:, 1:], index=pandas.Index(table[:, 0], name="t"), columns=names[1:])


def start_description(result) -> dict:
    """Where an on-line session started: the ``initial`` option and the free joints' positions and
    rates (SI units) at t = 0, which "rest" chooses (:meth:`desdemona.online.MPC.place`)."""
    names, plan = result.model.config.joint_names, result.plan
    return {"initial": result.options.initial, "q0": dict(zip(names, map(float, plan.q0))),
            "qd0": dict(zip(names, map(float, plan.qd0)))}


def online_summary(result, command: str | None = None) -> dict:
    """The summary.json of an on-line :class:`~desdemona.online.OnlineResult`."""
    mpc, c = result.options.mpc, result.check
    times, sources = result.loop.compute_times, result.loop.sources
    baseline = result.baseline_check
    return {
        "command": command,
        **run_description(result.path, result.model.config),
        "method": f"mpc ({mpc.plan_method}), predictor {result.options.predictor}, horizon {mpc.horizon:g} s, "
                  + (f"reach {mpc.length:g} s, " if mpc.length > mpc.horizon else "") + f"step {mpc.step:g} s",
        "metrics": {"rms_weighted": c.rms, "rms_modulus": c.rms_modulus,
                    "rms_weighted_classical": None if baseline is None else baseline.rms,
                    "rms_modulus_classical_loop": None if baseline is None else baseline.rms_modulus,
                    "limits_kept": c.passed, "worst_use": c.worst, "check_grid_step_s": c.step},
        "start": start_description(result),
        "quality": result.quality.to_dict(),
        "quality_classical_loop": None if result.baseline_quality is None else result.baseline_quality.to_dict(),
        "cycles": {"count": len(times), "deadline_s": result.deadline,
                   "compute_time_s": {"median": float(np.median(times)), "p99": float(np.percentile(times, 99)),
                                      "max": float(times.max())},
                   "sources": {s: sources.count(s) for s in ("mpc", "shifted", "brake")},
                   "deadline_misses": int(np.sum(times > result.deadline))},
        "options": _plain(result.options),
        "parameters": result.model.params.to_dict(),
        "versions": versions(),
    }


def write_online(result, out_dir: str | Path, command: str | None = None, overwrite: bool = False,
                 unreachable: dict | None = None, protect=()) -> Path:
    """The result folder of an on-line :class:`~desdemona.online.OnlineResult`: the usual files plus
    ``cycles.csv`` (per-cycle compute time, source of the command, fallback reason), ``online.png``
    (like thesis figures 7.5/7.6) and ``compute_time.png`` (compute time per cycle against the deadline).
    unreachable, protect : as in :func:`write`."""
    if unreachable is None:
        from desdemona import sizing

        unreachable = sizing.unreachable(result.path, result.model)
    summary = {**online_summary(result, command), "unreachable": unreachable}
    loop = result.loop

    def extra(folder: Path) -> None:
        with open(folder / "cycles.csv", "w") as fh:
            fh.write("t,compute_time_s,source,reason\n")
            for t, c, s, r in zip(loop.cycle_times, loop.compute_times, loop.sources, loop.reasons):
                fh.write(f"{t:.6g},{c:.6g},{s},\"{r}\"\n")
        figures.draw_online(result, folder)

    return write_folder(result.trajectory, summary, result.model.config, out_dir, overwrite, extra,
                        protect=protect)

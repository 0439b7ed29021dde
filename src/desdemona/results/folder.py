"""A result folder read back, and the rules that say which folders are ours: what ``plot``, ``view``
and ``compare`` read, and what ``--overwrite`` may replace (:mod:`.report` writes the folders)."""

from __future__ import annotations

import json
import os
from pathlib import Path

import numpy as np

from desdemona.check.simulate import Trajectory
from desdemona.profiles import CHANNELS

RESULT_FORMAT = "desdemona result"  # the mark in summary.json that makes a folder ours to replace


# Everything a result folder of ours may hold: replacing one never deletes anything else.
RESULT_FILES = {"trajectory.csv", "summary.json", "trajectory.mat", "cycles.csv", "classical.csv", "view.html",
                "session.csv", "events.csv"}


class ReportError(RuntimeError):
    """The result folder cannot be written or read; the message says where and why."""


def check_replaceable(out_dir: str | Path, protect=()) -> None:
    """Raise :class:`ReportError` unless ``out_dir`` may be replaced by a new result: it is a result
    folder of ours (``summary.json`` with the :data:`RESULT_FORMAT` mark, only result files inside),
    not the working folder or one of its parents, and holds none of the paths in ``protect`` (the
    run's own inputs)."""
    out = Path(out_dir)
    refuse = f"{out}: --overwrite replaces only a desdemona result folder, and this "
    if not out.exists():
        return
    if out.is_symlink() or not out.is_dir():
        raise ReportError(refuse + "is not a folder (a file or a link)")
    real = out.resolve()
    cwd = Path.cwd().resolve()
    if real == cwd or real in cwd.parents:
        raise ReportError(refuse + "is the current folder or one of its parents")
    if empty_folder(out):
        return  # nothing in it to lose: a new result goes there as into a new folder (batch, compare too)
    for path in protect:
        if path is not None and real in Path(path).resolve().parents:
            raise ReportError(refuse + f"is the folder of the input {path}")
    if not is_result_folder(out):
        raise ReportError(refuse + "is not one (no summary.json written by desdemona)")
    others = foreign_names(out)
    if others:
        raise ReportError(refuse + f"one holds other files too ({', '.join(others[:3])}); move them first")


def empty_folder(path: str | Path) -> bool:
    """Whether ``path`` is a folder (not a link to one) with nothing in it: a result may go there as
    into a folder that does not exist yet, with or without --overwrite."""
    path = Path(path)
    return path.is_dir() and not path.is_symlink() and not any(path.iterdir())


def check_out_folder(out_dir: str | Path, overwrite: bool, ours, what: str) -> None:
    """Raise :class:`ReportError` unless a command may write its files into the folder ``out_dir``
    (``batch``, ``compare``): one that does not exist yet or is empty, or with ``overwrite`` one that
    holds only what ``ours(path)`` recognises as written by an earlier run of the command, whose files
    it then replaces. what : the folder's kind in the messages ("batch folder", "comparison")."""
    out = Path(out_dir)
    if not out.exists() and not out.is_symlink():
        return
    if out.is_symlink() or not out.is_dir():
        raise ReportError(f"{out}: is not a folder (a file or a link); --out names the {what}'s folder")
    if not os.access(out, os.W_OK | os.X_OK):
        raise ReportError(f"{out}: is not a writable folder")
    items = sorted(out.iterdir())
    if not items:
        return
    if not overwrite:
        raise ReportError(f"{out}: already exists; choose another folder or add --overwrite")
    foreign = [p.name for p in items if not ours(p)]
    if foreign:
        raise ReportError(f"{out}: --overwrite replaces only an earlier {what} of desdemona, and this folder "
                          f"holds files it did not write ({', '.join(foreign[:3])}); move them first")


def is_result_folder(folder: str | Path) -> bool:
    """Whether ``folder`` carries the mark of a result folder of ours (its summary.json's format)."""
    try:
        return json.loads((Path(folder) / "summary.json").read_text()).get("format") == RESULT_FORMAT
    except (OSError, ValueError, AttributeError):
        return False


def refuse_batch_folder(folder: str | Path, verb: str) -> None:
    """Raise :class:`ReportError` if ``folder`` is a batch folder (batch.csv, no summary.json): one line
    naming its job folders, to ``verb`` instead."""
    folder = Path(folder)
    if (folder / "batch.csv").is_file() and not (folder / "summary.json").exists():
        jobs = sorted(str(p) for p in folder.iterdir() if is_result_folder(p))
        raise ReportError(f"{folder}: is a batch folder; {verb} its job folders instead: "
                          + (" ".join(jobs) if jobs else "(it holds none)"))


def foreign_names(folder: Path) -> list[str]:
    """The names in a result folder that a result of ours never holds, sorted."""
    return sorted(p.name for p in folder.iterdir()
                  if (p.name not in RESULT_FILES and p.suffix != ".png") or p.is_dir() or p.is_symlink())


# What reading a folder back and drawing its figures needs of its summary.json.
SUMMARY_KEYS = (("configuration", "free_joints"), ("configuration", "name"), ("path", "name"),
                ("parameters", "joints"))


def _has(value, keys) -> bool:
    for key in keys:
        if not isinstance(value, dict) or key not in value:
            return False
        value = value[key]
    return True


def read_table(file: str | Path, live: bool = False) -> dict[str, np.ndarray]:
    """The columns by name of a file written as trajectory.csv is (``classical.csv`` too; also by
    earlier versions, with the names in a comment); :class:`ReportError` naming the file if it cannot
    be read or its rows do not match its names. ``live``: a file being written as a session goes,
    whose last line without its end is a row not written yet (a killed service's), left out."""
    file = Path(file)
    try:
        with open(file) as fh:
            text = fh.read()
        lines = text.splitlines()
        if live and text and not text.endswith("\n"):  # a row being written: not yet one
            lines = lines[:-1]
        rows = [line for line in lines if line and not line.startswith("#")]
        if rows and rows[0].startswith("t,"):
            names, rows = rows[0].split(","), rows[1:]
        else:  # written by earlier versions: the column names in a comment
            names = next(line.lstrip("# ") for line in lines if line.lstrip("# ").startswith("t,")).split(",")
        table = np.loadtxt(rows, delimiter=",", ndmin=2)
    except (OSError, ValueError, StopIteration) as exc:
        raise ReportError(f"{file}: not a readable table: {exc}") from None
    if table.shape[1] != len(names):
        raise ReportError(f"{file}: {table.shape[1]} values per row under {len(names)} column names")
    return {n: table[:, i] for i, n in enumerate(names)}


def read_summary(out_dir: str | Path) -> dict:
    """The summary.json of a result folder, with every key that reading it back needs
    (:data:`SUMMARY_KEYS`); :class:`ReportError` naming what is missing."""
    out = Path(out_dir)
    if not out.is_dir():
        raise ReportError(f"{out}: {'is not a folder' if out.exists() else 'no such folder'}; give a result "
                          "folder of desdemona (one that optimize, online or serve wrote)")
    try:
        summary = json.loads((out / "summary.json").read_text())
    except FileNotFoundError:
        raise ReportError(f"{out}: not a result folder of desdemona: it has no summary.json") from None
    except OSError as exc:
        raise ReportError(f"{out}: its summary.json cannot be read: {exc.strerror or exc}") from None
    except ValueError as exc:
        raise ReportError(f"{out}: its summary.json is not JSON ({exc})") from None
    missing = next((".".join(keys) for keys in SUMMARY_KEYS if not _has(summary, keys)), None)
    if missing is not None:
        raise ReportError(f"{out}: not a complete result folder: its summary.json has no {missing!r}")
    return summary


def trajectory_of(col: dict[str, np.ndarray], joints) -> Trajectory:
    """The :class:`Trajectory` of the columns of :func:`read_table` (free joints ``joints``)."""
    def block(prefix):
        return np.column_stack([col[f"{prefix}_{j}"] for j in joints])

    def channels(suffix):
        keys = [f"{c}{suffix}" for c in CHANNELS]
        return np.column_stack([col[k] for k in keys]) if keys[0] in col else None

    return Trajectory(t=col["t"], q=block("q"), qd=block("qd"), qdd=block("qdd"), tau=block("tau"),
                      power=block("power"), S=channels(""), S_d=channels("_d"), M=col["M"], M_d=col["M_d"],
                      S_perc=channels("_perc"), S_d_perc=channels("_d_perc"))


def load(out_dir: str | Path) -> tuple[Trajectory, dict]:
    """Read a result folder back: its trajectory and summary."""
    out = Path(out_dir)
    summary = read_summary(out)
    col = read_table(out / "trajectory.csv", live=bool(summary.get("live")))
    joints = summary["configuration"]["free_joints"]
    needed = ["t", "M", "M_d"] + [f"{k}_{j}" for k in ("q", "qd", "qdd", "tau", "power") for j in joints]
    absent = [n for n in needed if n not in col]
    if absent:
        raise ReportError(f"{out}: not a complete result folder: its trajectory.csv has no column {absent[0]!r}")
    return trajectory_of(col, joints), summary


LOCK_SUFFIX = ".desdemona-lock"


def lock_path(out_dir: str | Path) -> Path:
    """The lock of an output folder: the hidden sibling ``.<name>.desdemona-lock``."""
    out = Path(os.path.abspath(out_dir))  # "." and ".." by their names
    return out.parent / f".{out.name}{LOCK_SUFFIX}"


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


def live_note(out_dir: str | Path) -> str | None:
    """The line that says a result folder is a served session's log written as it went (its
    summary.json ``"live"``), not the whole result: how far it reaches, and whether the session still
    runs (its ``serve`` holds the folder's lock) or ended without closing (killed); None for a whole
    result. The folder is read as it is, up to its last written cycle."""
    out = Path(out_dir)
    try:
        live = json.loads((out / "summary.json").read_text()).get("live")
    except (OSError, ValueError, AttributeError):
        return None
    if not live:
        return None
    try:
        t = read_table(out / "trajectory.csv", live=True)["t"]
        reach = f"t = {t[-1]:.3f} s" if len(t) else "its start (no host message answered)"
    except (ReportError, KeyError):
        reach = "its start (no cycle written)"
    pid, _ = _lock_holder(lock_path(out))
    if pid is not None and _alive(pid):
        return f"{out}: session still running (process {pid}), written up to {reach}; read up to its last cycle"
    return f"{out}: session ended without closing at {reach}; read up to its last cycle"

"""Result folders side by side: one table of their quality metrics and overlay figures.

The metrics (:mod:`desdemona.check.metrics`) are computed from each folder's trajectory, so folders written
before the metrics existed compare as well as new ones. ``desdemona compare DIR DIR ... --out DIR``
prints :func:`table` and writes ``compare.csv`` and the figures of :func:`write`:
``compare_path.png`` (each folder's S over the desired S_d, or M over M_d for modulus-only paths),
``compare_felt.png`` (perceived S - S_d with the perception thresholds as a grey band) and
``compare_qdd.png`` (the commanded joint accelerations).
"""

from __future__ import annotations

import csv
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from desdemona.check import metrics
from desdemona.check.simulate import Trajectory
from desdemona.occupant import perception
from desdemona.results import figures, report

INFO_ROWS = (("path", ("path", "name")), ("configuration", ("configuration", "name")), ("method", ("method",)))


@dataclass(frozen=True, eq=False)
class Entry:
    """One result folder read back: its column label, trajectory, summary.json, metrics and the
    perceived S - S_d (K, 6) behind them (None for a modulus-only path)."""

    label: str
    trajectory: Trajectory
    summary: dict
    metrics: metrics.Metrics
    felt: np.ndarray | None

    @property
    def joints(self) -> list[str]:
        return self.summary["configuration"]["free_joints"]


def load_results(folders, vestibular: perception.VestibularModel | None = None,
                 lag_window: float = metrics.LAG_WINDOW) -> list[Entry]:
    """Read each result folder and compute its metrics; a folder that is not a result is a ReportError."""
    names = [Path(f).name or str(f) for f in folders]
    labels = names if len(set(names)) == len(names) else [str(f) for f in folders]
    entries = []
    for folder, label in zip(folders, labels):
        if not Path(folder).is_dir():
            raise report.ReportError(f"{folder}: not a folder")
        report.refuse_batch_folder(folder, "compare")
        try:
            traj, summary = report.load(folder)
            joints = summary["configuration"]["free_joints"]
        except (KeyError, IndexError, TypeError) as exc:
            raise report.ReportError(f"{folder}: not a desdemona result folder (missing {exc})") from None
        felt = None if traj.S_d is None else metrics.perceived_difference(traj.S, traj.S_d, metrics.step_of(traj.t),
                                                                        vestibular)
        entries.append(Entry(label, traj, summary, metrics.of_trajectory(traj, joints, vestibular, lag_window), felt))
    return entries


def _info(summary: dict, keys) -> str:
    value = summary
    for key in keys:
        if not isinstance(value, dict) or key not in value:
            return "-"
        value = value[key]
    return str(value)


def rows(entries) -> list[tuple[str, str, list]]:
    """(metric, unit, one value per entry) for every metric any entry has; None where one lacks it.

    The first rows name each folder's path, configuration and method (strings).
    """
    table = [(name, "", [_info(e.summary, keys) for e in entries]) for name, keys in INFO_ROWS]
    per_entry = [{name: (unit, value) for name, unit, value in e.metrics.rows()} for e in entries]
    groups = metrics.Metrics.ROW_GROUPS
    order = sorted(dict.fromkeys(name for values in per_entry for name in values),
                   key=lambda name: groups.index(name.split()[0]))  # stable: joints in their order
    for name in order:
        unit = next(values[name][0] for values in per_entry if name in values)
        table.append((name, unit, [values[name][1] if name in values else None for values in per_entry]))
    return table


def _cell(value, width: int = 28) -> str:
    """A table cell: 4 significant digits, "-" for None, a long text shortened (compare.csv has it whole)."""
    if value is None:
        return "-"
    if isinstance(value, str):
        return value if len(value) <= width else value[:width - 3] + "..."
    return f"{metrics.shown(value):.4g}"


def table(entries) -> str:
    """The metrics of all entries as a plain-text table: rows = metrics, columns = folders."""
    lines = [[f"{name} [{unit}]" if unit else name] + [_cell(v) for v in values]
             for name, unit, values in rows(entries)]
    header = ["metric"] + [e.label for e in entries]
    widths = [max(len(r[i]) for r in lines + [header]) for i in range(len(header))]

    def line(cells):
        return "  ".join([cells[0].ljust(widths[0])] + [c.rjust(w) for c, w in zip(cells[1:], widths[1:])])

    return "\n".join([line(header), "  ".join("-" * w for w in widths)] + [line(r) for r in lines])


def check_out(out_dir: str | Path, overwrite: bool = False) -> None:
    """Raise :class:`~desdemona.results.report.ReportError` unless the comparison may be written into
    ``out_dir``: a folder that does not exist yet or is empty, or with ``overwrite`` an earlier
    comparison of ours (only ``compare.csv`` and ``compare_*.png`` inside), whose files it replaces."""
    report.check_out_folder(out_dir, overwrite, _ours, "comparison")


def _ours(path: Path) -> bool:
    """Whether ``path`` in a comparison's folder is something ``compare`` wrote: its table or a figure."""
    if not path.is_file() or path.is_symlink():
        return False
    return (path.name == "compare.csv" and _is_table(path)) or (path.name.startswith("compare_") and path.suffix == ".png")


def _is_table(path: Path) -> bool:
    """Whether ``path`` is a compare.csv of ours: its first cells are ``metric,unit``, then the path row."""
    try:
        with open(path, newline="") as fh:
            rows = csv.reader(fh)
            return next(rows, [])[:2] == ["metric", "unit"] and next(rows, [""])[0] == INFO_ROWS[0][0]
    except (OSError, UnicodeDecodeError, csv.Error):
        return False


def write(entries, out_dir: str | Path, overwrite: bool = False) -> list[Path]:
    """Write compare.csv and the overlay figures into ``out_dir`` (created if missing; an existing one
    as :func:`check_out` allows); their paths."""
    out = Path(out_dir)
    check_out(out, overwrite)
    try:
        out.mkdir(exist_ok=True)
        with open(out / "compare.csv", "w", newline="") as fh:
            writer = csv.writer(fh)
            writer.writerow(["metric", "unit"] + [e.label for e in entries])
            for name, unit, values in rows(entries):
                writer.writerow([name, unit] + ["" if v is None else v for v in values])
    except OSError as exc:
        raise report.ReportError(f"{out}: cannot write the comparison: {exc.strerror or exc}") from None
    return [out / "compare.csv"] + figures.draw_comparison(entries, out)

"""Result folders side by side: one table of their quality metrics and overlay figures (issue 16).

The metrics (:mod:`desdemona.metrics`) are computed from each folder's trajectory, so folders written
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

from desdemona import metrics, perception, report
from desdemona.simulate import Trajectory

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
    groups = (*metrics.Metrics.CHANNEL_FIELDS, *metrics.Metrics.JOINT_FIELDS, "modulus")
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
    return f"{value:.4g}"


def table(entries) -> str:
    """The metrics of all entries as a plain-text table: rows = metrics, columns = folders."""
    lines = [[f"{name} [{unit}]" if unit else name] + [_cell(v) for v in values]
             for name, unit, values in rows(entries)]
    header = ["metric"] + [e.label for e in entries]
    widths = [max(len(r[i]) for r in lines + [header]) for i in range(len(header))]

    def line(cells):
        return "  ".join([cells[0].ljust(widths[0])] + [c.rjust(w) for c, w in zip(cells[1:], widths[1:])])

    return "\n".join([line(header), "  ".join("-" * w for w in widths)] + [line(r) for r in lines])


def write(entries, out_dir: str | Path) -> list[Path]:
    """Write compare.csv and the overlay figures into ``out_dir`` (created if missing); their paths."""
    out = Path(out_dir)
    try:
        out.mkdir(exist_ok=True)
        with open(out / "compare.csv", "w", newline="") as fh:
            writer = csv.writer(fh)
            writer.writerow(["metric", "unit"] + [e.label for e in entries])
            for name, unit, values in rows(entries):
                writer.writerow([name, unit] + ["" if v is None else v for v in values])
    except OSError as exc:
        raise report.ReportError(f"{out}: cannot write the comparison: {exc.strerror or exc}") from None
    return [out / "compare.csv"] + draw_figures(entries, out)


def draw_figures(entries, out_dir: str | Path) -> list[Path]:
    """Overlay figures of all entries in ``out_dir``; returns their paths."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    out, paths = Path(out_dir), []

    def save(fig, name, title):
        fig.suptitle(title)
        fig.tight_layout()
        fig.savefig(out / name, dpi=100)
        plt.close(fig)
        paths.append(out / name)

    def six_channels():
        fig, axes = plt.subplots(3, 2, figsize=(12, 8), sharex=True)
        for ax in axes[-1]:
            ax.set_xlabel("t [s]")
        return fig, axes.T.ravel()

    full = [e for e in entries if e.trajectory.S_d is not None]
    if full:
        fig, axes = six_channels()
        for i, ax in enumerate(axes):
            ax.plot(full[0].trajectory.t, full[0].trajectory.S_d[:, i], "k-", lw=1.8, label=f"S_d ({full[0].label})")
            for k, e in enumerate(full):
                ax.plot(e.trajectory.t, e.trajectory.S[:, i], f"C{k}--", lw=1.1, label=e.label)
            ax.set_ylabel(report.CHANNEL_LABELS[i])
            ax.grid(alpha=0.3)
        axes[0].legend(fontsize=8)
        save(fig, "compare_path.png", "path S over the desired S_d")
        fig, axes = six_channels()
        for i, ax in enumerate(axes):
            ax.axhspan(-perception.THRESHOLDS[i], perception.THRESHOLDS[i], color="0.8", label="below threshold")
            for k, e in enumerate(full):
                ax.plot(e.trajectory.t, e.felt[:, i], f"C{k}", lw=1.1, label=e.label)
            ax.set_ylabel(f"felt error {report.CHANNEL_LABELS[i]}")
            ax.grid(alpha=0.3)
        axes[0].legend(fontsize=8)
        save(fig, "compare_felt.png", f"perceived S - S_d ({entries[0].metrics.vestibular} model)")
    if len(full) < len(entries):
        fig, ax = plt.subplots(figsize=(10, 4))
        ax.plot(entries[0].trajectory.t, entries[0].trajectory.M_d, "k-", lw=1.8, label=f"M_d ({entries[0].label})")
        for k, e in enumerate(entries):
            ax.plot(e.trajectory.t, e.trajectory.M, f"C{k}--", lw=1.1, label=e.label)
        ax.set_ylabel("modulus [m/s^2]")
        ax.set_xlabel("t [s]")
        ax.grid(alpha=0.3)
        ax.legend(fontsize=8)
        save(fig, "compare_modulus.png", "modulus M over the desired M_d")
    joints = list(dict.fromkeys(j for e in entries for j in e.joints))
    units = metrics.joint_units(joints)
    fig, axes = plt.subplots(len(joints), 1, figsize=(10, 1.9 * len(joints) + 1), sharex=True, squeeze=False)
    for ax, joint, unit in zip(axes[:, 0], joints, units):
        for k, e in enumerate(entries):
            if joint in e.joints:
                column = e.joints.index(joint)
                ax.plot(e.trajectory.t, e.trajectory.qdd[:, column], f"C{k}", lw=1.0, drawstyle="steps-post",
                        label=e.label)
        ax.set_ylabel(f"qdd {joint} [{unit}/s^2]")
        ax.grid(alpha=0.3)
    axes[0, 0].legend(fontsize=8)
    axes[-1, 0].set_xlabel("t [s]")
    save(fig, "compare_qdd.png", "commanded joint accelerations")
    return paths

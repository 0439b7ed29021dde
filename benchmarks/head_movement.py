"""The trade of ``--head-movement-weight``: the cross-coupling of a head nod against the felt force.

    python benchmarks/head_movement.py                       # c172-doublet on dfs, off-line, six weights
    python benchmarks/head_movement.py --cases c172-doublet-M f16-turn-M --weights 0 1 10
    python benchmarks/head_movement.py --table-only          # re-read the result folders, redraw

Each job is ``desdemona optimize CASE --config CONFIG --head-movement-weight W`` on a corpus path
(``benchmarks/corpus``, made by ``benchmarks/corpus.py``), run as its own process. Off-line, so that
the numbers do not depend on the machine's load (on-line plans that miss their deadline fall back, and
a loaded machine changes the result). Per job, from its ``summary.json``: the felt force RMS (the RMS
of ``|f - f_d|``, as ``benchmarks/real.py`` gives it), the largest peak cross-coupled angular velocity
of the standard head nods [deg/s] and MSDV_z [m/s^1.5]. The table goes to stdout and the figure,
one point per weight and one line per case, to ``docs/images/head-movement-trade.png``.
"""

from __future__ import annotations

import argparse
import json
import subprocess
import sys
import time
from pathlib import Path

import real  # benchmarks/real.py: the script's own folder is on the path

from desdemona.runs import batch

HERE = Path(__file__).resolve().parent
FIGURE = HERE.parent / "docs" / "images" / "head-movement-trade.png"
WEIGHTS = (0.0, 0.1, 0.3, 1.0, 3.0, 10.0)


def run_job(case: str, config: str, weight: float, corpus: str, out: str, timeout: float) -> dict:
    """One off-line job as its own process; its exit and wall time [s]."""
    folder = Path(out) / f"{case}--{config}--{weight:g}"
    start = time.perf_counter()
    command = [sys.executable, "-m", "desdemona", "optimize", str(Path(corpus) / f"{case}.csv"), "--config", config,
               "--head-movement-weight", f"{weight:g}", "--out", str(folder), "--overwrite", "--quiet", "--no-view"]
    try:
        code = subprocess.run(command, capture_output=True, text=True, timeout=timeout).returncode
    except subprocess.TimeoutExpired:
        code = "timeout"
    return {"case": case, "config": config, "weight": weight, "exit": code, "wall_s": time.perf_counter() - start,
            "folder": str(folder)}


def figures(job: dict) -> dict:
    """The job's felt force RMS, nod cross-coupling peak and MSDV_z (none where nothing was written)."""
    summary = Path(job["folder"]) / "summary.json"
    if not summary.exists():
        return job
    quality = json.loads(summary.read_text())["quality"]
    return {**job, **real.felt_figures(quality, "fz")}


def draw(rows: list[dict], path: Path) -> Path:
    """Cross-coupling peak against felt force RMS, one point per weight, a line per case and configuration."""
    from matplotlib.figure import Figure

    fig = Figure(figsize=(7, 5))
    ax = fig.subplots()
    runs = sorted({(r["case"], r["config"]) for r in rows})
    for k, (case, config) in enumerate(runs):
        points = sorted((r for r in rows if (r["case"], r["config"]) == (case, config) and "force_rms" in r),
                        key=lambda r: r["weight"])
        ax.plot([r["force_rms"] for r in points], [r["cross_coupling"] for r in points], f"C{k}o-",
                label=f"{case} on {config}")
        for r in points:
            ax.annotate(f"{r['weight']:g}", (r["force_rms"], r["cross_coupling"]), textcoords="offset points",
                        xytext=(4, 4), fontsize=8)
    ax.set_xlabel("felt force RMS |f - f_d| [m/s^2]")
    ax.set_ylabel("peak cross-coupled angular velocity of a head nod [deg/s]")
    ax.set_title("--head-movement-weight (labels), off-line")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    path.parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(path, dpi=100)
    return path


def table(rows: list[dict]) -> str:
    lines = ["| case | configuration | weight | exit | wall [s] | felt force RMS [m/s^2] | nod x-coupling [deg/s] | "
             "MSDV_z [m/s^1.5] |", "| --- " * 8 + "|"]
    for r in rows:
        lines.append(f"| {r['case']} | {r['config']} | {r['weight']:g} | {r['exit']} | {real.cell(r.get('wall_s'), '.0f')} | "
                     f"{real.cell(r.get('force_rms'), '.3f')} | {real.cell(r.get('cross_coupling'), '.1f')} | "
                     f"{real.cell(r.get('msdv_z'), '.2f')} |")
    return "\n".join(lines)


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--cases", nargs="+", default=["c172-doublet-M"], help="corpus files (without .csv)")
    parser.add_argument("--configs", nargs="+", default=["dfs"])
    parser.add_argument("--weights", nargs="+", type=float, default=list(WEIGHTS))
    parser.add_argument("--corpus", type=Path, default=real.CORPUS)
    parser.add_argument("--out", type=Path, default=HERE / "head-movement-results")
    parser.add_argument("--processes", type=int, default=2)
    parser.add_argument("--timeout", type=float, default=1200.0, help="seconds per job")
    parser.add_argument("--table-only", action="store_true", help="re-read the jobs of an earlier run")
    parser.add_argument("--figure", type=Path, default=FIGURE)
    args = parser.parse_args(argv)
    args.out.mkdir(parents=True, exist_ok=True)
    record = args.out / "jobs.jsonl"
    jobs = [(case, config, weight) for case in args.cases for config in args.configs for weight in args.weights]
    if args.table_only:
        done = real.reread(record, jobs, lambda j: (j["case"], j["config"], j["weight"]))
    else:
        progress = real.recorder(record, lambda job: f"{job['case']} on {job['config']}, weight {job['weight']:g}: "
                                                     f"exit {job['exit']}, {job['wall_s']:.0f} s")
        done = batch.map_jobs(run_job, [(*key, str(args.corpus), str(args.out), args.timeout) for key in jobs],
                              args.processes, None, progress)
    rows = sorted(map(figures, done), key=lambda r: (r["case"], r["config"], r["weight"]))
    print(table(rows))
    print(f"figure: {draw(rows, args.figure)}")
    return 0


if __name__ == "__main__":
    sys.exit(main())

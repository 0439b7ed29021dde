"""On-line runs through plan outages: how the fallback carries a session when plans do not come.

    python benchmarks/outages.py                                  # the tables of docs/benchmarks/fallback-to-the-last-plan.md
    python benchmarks/outages.py --cases c172-takeoff-M --config dfs --patterns burst2

Each run is the ``online`` command on a corpus case with ``--predictor hold --deadline 1`` (no plan is
late by the clock), in this process, with a chosen share of the plans refused as late, deterministically:
``random90`` refuses 90 % of them at random (seeded), ``burstN`` every plan in the N s from second 3 of
every 6 s of the session (an outage of N s, then 6 - N s of plans), ``lostN`` every plan from second N
on (the planner lost for good). The placed start's solves are never refused.

Per run, read as ``real.felt_figures`` reads them: the felt force RMS of the vector |f - f_d| [m/s^2],
the classical loop's from the same run, the peak felt direction the machine made [deg]
(:func:`desdemona.check.metrics.direction_made`), the felt direction's RMS error [deg], the peak felt
rotation [deg/s]; and the cycles by source (fresh plan, the last plan followed, the brake).
``docs/benchmarks/fallback-to-the-last-plan.md#fallback-to-the-last-plan`` and
``docs/benchmarks/return-home-in-an-outage.md#return-home-in-an-outage`` have the tables.
"""

from __future__ import annotations

import argparse
import csv
import json
import sys
import tempfile
from pathlib import Path

import numpy as np
import real  # benchmarks/real.py: its felt figures (the script's own folder is on the path)

from desdemona.cli import main
from desdemona.control import mpc

PATTERNS = {"random90": (0.9, None, None), "burst2": (0.0, 2.0, None), "burst3": (0.0, 3.0, None),
            "lost20": (0.0, None, 20.0)}


def refusing(share: float, burst: float | None, after: float | None, seed: int = 0):
    """A replacement for ``MPC._solve`` that marks the chosen plans as late (the fallback then runs)."""
    solve, rng = mpc.MPC._solve, np.random.default_rng(seed)

    def _solve(self, q, qd, a, data, method=None, place=False):
        solved = solve(self, q, qd, a, data, method, place)
        if method is not None or place:  # the placed start's solves
            return solved
        self.cycle_time = getattr(self, "cycle_time", -self.options.step) + self.options.step
        phase = self.cycle_time % 6.0
        lost = after is not None and self.cycle_time >= after
        if rng.random() < share or lost or (burst is not None and 3.0 <= phase < 3.0 + burst):
            return solved._replace(elapsed=float("inf"))
        return solved
    return _solve


def run(case: str, config: str, pattern: str) -> dict:
    original = mpc.MPC._solve
    mpc.MPC._solve = refusing(*PATTERNS[pattern])
    try:
        with tempfile.TemporaryDirectory() as tmp:
            out = Path(tmp) / "result"
            code = main(["online", str(real.CORPUS / f"{case}.csv"), "--config", config, "--predictor", "hold",
                         "--deadline", "1", "--out", str(out), "--no-view"])
            summary = json.loads((out / "summary.json").read_text())
            lines = [line for line in (out / "cycles.csv").read_text().splitlines() if not line.startswith("#")]
            sources = [row["source"] for row in csv.DictReader(lines)]
    finally:
        mpc.MPC._solve = original
    felt, loop = (real.felt_figures(summary[key], "fx") for key in ("quality", "quality_classical_loop"))
    return {"exit": code, "force": felt["force_rms"], "loop": loop["force_rms"], "made": felt["direction_made"],
            "direction": felt["direction_rms"], "rotation": felt["rotation_peak"],
            "sources": {s: sources.count(s) for s in ("mpc", "shifted", "brake")}}


def parse(argv):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--cases", nargs="+", default=["b747-takeoff"])
    parser.add_argument("--config", default="full")
    parser.add_argument("--patterns", nargs="+", choices=list(PATTERNS), default=list(PATTERNS))
    return parser.parse_args(argv)


if __name__ == "__main__":
    args = parse(sys.argv[1:])
    rows = ["| case | configuration | outage | felt force RMS (loop) | made [deg] | direction RMS [deg] | "
            "peak rotation [deg/s] | fresh / last plan / brake |", "| --- | --- | --- | --- | --- | --- | --- | --- |"]
    for case in args.cases:
        for pattern in args.patterns:
            r = run(case, args.config, pattern)
            s = r["sources"]
            rows.append(f"| {case} | {args.config} | {pattern} | {r['force']:.3f} ({r['loop']:.3f}) | "
                        f"{r['made']:.0f} | {r['direction']:.1f} | {r['rotation']:.1f} | "
                        f"{s['mpc']} / {s['shifted']} / {s['brake']} |")
    print("\n".join(rows))

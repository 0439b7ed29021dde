"""What the occupant feels: the thesis' setting against the session default, on every built-in full path.

    python benchmarks/feel.py --configs yaw-track-cabin --out feel.jsonl          # runs, one JSON line each
    python benchmarks/feel.py --configs full --starts 1 --out feel.jsonl        # appends
    python benchmarks/feel.py --table feel.jsonl                               # the markdown table

Settings: ``thesis`` = the path's own weights, free start, free end (thesis 5.2, 5.6);
``rest`` = the path's own weights, from rest to rest with the track and heave centred (what starting
and ending as a session does costs by itself); ``default`` = the command line's default (``felt``
weights, from rest to rest, centred). Metrics from :mod:`desdemona.check.metrics` through the thesis'
vestibular model: peak false rotation [deg/s] (the largest |omega| where |omega_d| is below the
threshold), the perceived (felt) error RMS per channel, and the share of time it is above threshold.
Each run appends one JSON line to ``--out`` as soon as it ends, so a long run can be read part-way.
"""

from __future__ import annotations

import argparse
import json
import math
import time

import numpy as np

from desdemona import Model, default_params, profiles
from desdemona.cueing.offline import OptimizeOptions, optimize
from desdemona.runs import session

PATHS = ("cosine", "catapult", "double-pulse", "triple-pulse", "car-lap")
SETTINGS = {  # name: (weights spec, initial, final)
    "thesis": ("path", "free", "none"),
    "rest": ("path", "rest", "centre"),
    "default": (profiles.WEIGHT_CHOICES[0], "rest", "centre"),
}


def run(name: str, config: str, setting: str, starts: int, h_u: float) -> dict:
    spec, initial, final = SETTINGS[setting]
    choices = session.Choices(weights=spec, initial=initial, final=final, h_u=h_u)
    resolved = session.offline(profiles.get_profile(name), Model(default_params(), config), choices)
    start = time.perf_counter()
    result = optimize(resolved.path, resolved.model, OptimizeOptions(resolved.options, starts=starts))
    q = result.quality
    return {"path": name, "config": config, "setting": setting, "weights": spec, "initial": initial,
            "final": final, "starts": starts, "h_u": h_u, "wall_s": time.perf_counter() - start,
            "status": result.solution.status, "guess": min(result.starts, key=lambda s: s.rms).guess,
            "peak_false_rotation_deg_s": math.degrees(float(np.nanmax(q.peak_false_cue[:3]))),
            "perceived_rms": q.perceived_rms.tolist(), "rms": q.rms.tolist(),
            "above_threshold_pct": q.above_threshold_pct.tolist(),
            "qd_start_max": float(np.abs(q.qd_start).max()), "worst_use": result.check.worst_use}


def table(rows: list[dict]) -> str:
    """Markdown: per path and configuration, each setting's line, then the default against the thesis."""
    head = ("| path | configuration | setting | peak false rotation [deg/s] | felt rotation RMS, worst [deg/s] "
            "| felt f RMS x / y / z [m/s^2] | felt f RMS, worst [m/s^2] | felt above threshold, rotation / force "
            "(worst) [%] | largest rate at start | starts | wall [s] |")
    lines = [head, "|" + " --- |" * (head.count("|") - 1)]
    by_key = {(r["path"], r["config"], r["setting"]): r for r in rows}
    keys = sorted({(r["path"], r["config"]) for r in rows},
                  key=lambda k: (k[1] != "yaw-track-cabin", PATHS.index(k[0]) if k[0] in PATHS else 99))
    for path, config in keys:
        for setting in SETTINGS:
            r = by_key.get((path, config, setting))
            if r is None:
                continue
            felt = r["perceived_rms"]
            above = r["above_threshold_pct"]
            lines.append(
                f"| {path} | {config} | {setting} | {r['peak_false_rotation_deg_s']:.3g} | "
                f"{math.degrees(max(felt[:3])):.3g} | {felt[3]:.3g} / {felt[4]:.3g} / {felt[5]:.3g} | "
                f"{max(felt[3:]):.3g} | {max(above[:3]):.0f} / {max(above[3:]):.0f} | {r['qd_start_max']:.3g} | "
                f"{r['starts']} | {r['wall_s']:.0f} |")
        thesis, default = by_key.get((path, config, "thesis")), by_key.get((path, config, "default"))
        if thesis and default:
            cut = thesis["peak_false_rotation_deg_s"] / max(default["peak_false_rotation_deg_s"], 1e-9)
            ratio = max(default["perceived_rms"][3:]) / max(thesis["perceived_rms"][3:])
            met = "yes" if cut >= 3 and ratio <= 1.5 else "no"
            lines.append(f"| {path} | {config} | **default / thesis** | **cut {cut:.3g}x** | | | "
                         f"**{ratio:.3g}x** | | | | **met: {met}** |")
    return "\n".join(lines)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--configs", nargs="+", default=["yaw-track-cabin"])
    parser.add_argument("--paths", nargs="+", default=list(PATHS))
    parser.add_argument("--settings", nargs="+", default=list(SETTINGS), choices=tuple(SETTINGS))
    parser.add_argument("--starts", type=int, default=4)
    parser.add_argument("--h-u", type=float, default=0.05, dest="h_u")
    parser.add_argument("--out", default="feel.jsonl", help="JSON lines file to append to")
    parser.add_argument("--table", metavar="JSONL", help="print the markdown table of a JSON lines file and stop")
    args = parser.parse_args()
    if args.table:
        with open(args.table) as fh:
            print(table([json.loads(line) for line in fh if line.strip()]))
        return
    for config in args.configs:
        for name in args.paths:
            for setting in args.settings:
                row = run(name, config, setting, args.starts, args.h_u)
                with open(args.out, "a") as fh:
                    fh.write(json.dumps(row) + "\n")
                print(f"{name} {config} {setting}: {row['peak_false_rotation_deg_s']:.3g} deg/s, felt f worst "
                      f"{max(row['perceived_rms'][3:]):.3g} m/s^2, {row['wall_s']:.0f} s", flush=True)


if __name__ == "__main__":
    main()

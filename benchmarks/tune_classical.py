"""Tune the classical washout per configuration on the corpus and the built-in paths: the honest baseline.

    nice -n 10 python benchmarks/tune_classical.py                 # the search, then the before/after table
    python benchmarks/tune_classical.py --table-only               # the table of the tuned settings of the configurations (desdemona.baselines.washout.tuned)
    python benchmarks/tune_classical.py --configs full --cases f16-turn catapult   # a quick look

Cases: every six-channel case of the corpus (``benchmarks/corpus/*.csv`` without ``-M``, built by
``benchmarks/corpus.py`` where missing) and every built-in path with six channels, each run by
:func:`desdemona.baselines.washout.classical_washout` from rest at home, as ``online`` runs its baseline (a
step-by-step loop, no optimiser: the whole corpus takes seconds), on ``yaw-track-cabin`` and ``full``
separately.

Per case: the felt force RMS, the RMS of the vector ``|f - f_d|`` [m/s^2] as ``benchmarks/real.py`` and
``online`` report it; the peak felt direction error [deg] and the peak felt rotation through the canals
[deg/s] (:mod:`desdemona.check.metrics`).

Objective (lower is better): the mean over the cases of each case's felt force RMS divided by the
untuned washout's (``Washout()``): every case counts the same, whatever its length or size. A candidate
is admissible only where its felt rotation and direction are not much worse: the mean over the cases of
(peak + 10) / (untuned peak + 10) at most ``--worse`` (1.5), for the rotation [deg/s] and the direction
[deg] each (the 10 keeps a case whose untuned peak is near zero from weighing like a hundred).

Search: a coordinate search (one setting at a time, the others held, the best kept) over the coarse
grid :data:`COARSE`, from :data:`START` (the untuned filters, the arm on, gently); then one refinement
pass over each numeric setting at 0.75x and 1.33x of its best value. Candidates are compared by their
merit: the objective, plus :data:`PENALTY` x how far the mean rotation or direction ratio exceeds
``--worse`` (so any admissible candidate beats any inadmissible one). The search runs on a ``--step``
grid (0.05 s), each 600 s recording cut to its first :data:`SEARCH_END` s; the table runs every case
whole on the ``online`` grid (0.02 s), each plan checked against every limit
(:func:`desdemona.check.simulate.check`). One process, about 20 minutes on one core.
"""

from __future__ import annotations

import argparse
import dataclasses
import json
import math
import sys
import time
from pathlib import Path

import numpy as np
import real  # benchmarks/real.py: the corpus index (the script's own folder is on the path)

from desdemona import profiles
from desdemona.baselines.washout import Washout, classical_washout, tuned
from desdemona.check import metrics
from desdemona.check.simulate import check, evaluate_plan
from desdemona.machine.model import Model

HERE = Path(__file__).resolve().parent
CONFIGS = ("yaw-track-cabin", "full")
FLOOR = {"rotation_peak": 10.0, "direction_peak": 10.0}  # [deg/s], [deg]

#: The coarse grid, per setting (the start's value among them), in the order the search visits them.
COARSE = {
    "arm_min": (2.0, 4.0, 8.0, 16.0),
    "arm_accel": (0.025, 0.05, 0.1),
    "omega_arm": (0.15, 0.3, 0.6),
    "radius": (2.0, 3.0, 3.5),
    "gain": (0.5, 0.7, 1.0),
    "omega_hp": (0.25, 0.5, 1.0),
    "omega_centre": (0.25, 0.5, 1.0),
    "omega_lp": (0.5, 1.0, 2.0),
    "tilt_rate": tuple(math.radians(x) for x in (3.0, 6.0, 12.0)),
    "tilt_limit": (math.sin(math.radians(20.0)), 0.5, math.sin(math.radians(45.0))),
    "omega_rot": (0.25, 0.5, 1.0),
}
#: Where the search starts: the untuned settings with the arm on, gently, for large forces only. The arm
#: is not a setting of the search: ``arm_min`` = 16 m/s^2 leaves it still on all but the F-16's turns.
START = Washout(arm=True, arm_min=8.0, arm_accel=0.05, omega_arm=0.3)
#: The search's cases end here [s] (the two 600 s recordings: their first 200 s); the table runs them whole.
SEARCH_END = 200.0
#: Weight of an inadmissible candidate's excess (``merit``): any admissible candidate beats any other.
PENALTY = 10.0
#: Settings a configuration does not use (yaw-track-cabin cannot tilt).
UNUSED = {"yaw-track-cabin": {"tilt_limit"}, "full": set()}
REFINE = (0.75, 1.33)
#: Caps of the refinement: no gain above 1; room on the 4 m half-track for the onsets [m].
CAP = {"gain": 1.0, "radius": 3.75}


def load_cases(folder: Path, names=None) -> list[tuple[str, profiles.DesiredPath]]:
    """(name, path) of every six-channel corpus case and built-in path (only ``names`` where given)."""
    out = []
    for case in real.corpus_cases(folder):
        if case["form"] == "six" and (names is None or case["name"] in names):
            out.append((case["name"], profiles.read_csv(folder / case["file"])))
    for name in profiles.PROFILES:
        path = profiles.get_profile(name)
        if path.S_d is not None and (names is None or name in names):
            out.append((name, path))
    return out


def shortened(path: profiles.DesiredPath, end: float) -> profiles.DesiredPath:
    """The path up to ``end`` seconds from its start (the path itself where it is shorter)."""
    keep = path.t <= path.t[0] + end
    return path if keep.all() else profiles.DesiredPath(path.name, path.t[keep], path.S_d[keep])


def evaluate(path, model: Model, settings: Washout, step: float, checked: bool = False) -> dict:
    """The washout from rest at home on a grid of ``step``: felt force RMS, peak felt direction and
    rotation, and (``checked``) whether every limit held."""
    times = np.arange(path.t[0], path.t[-1] + 1e-9, step)
    n = model.n
    plan = classical_washout(path, model, times=times, settings=settings, state=(np.zeros(n), np.zeros(n)))
    quality = metrics.of_trajectory(evaluate_plan(model, path, plan, times), model.config.joint_names)
    row = {"force_rms": float(np.sqrt(np.sum(quality.rms[3:] ** 2))),
           "direction_peak": math.degrees(quality.direction_peak),
           "rotation_peak": math.degrees(float(np.max(quality.rotation_peak)))}
    if checked:
        result, _ = check(model, path, plan, step)
        row.update(passed=bool(result.passed), worst_use=float(result.worst_use))
    return row


def score(rows: list[dict], base: list[dict]) -> dict:
    """The objective (mean felt force RMS ratio) and the mean worsening of rotation and direction."""
    out = {"objective": float(np.mean([r["force_rms"] / b["force_rms"] for r, b in zip(rows, base)]))}
    for key, floor in FLOOR.items():
        out[key] = float(np.mean([(r[key] + floor) / (b[key] + floor) for r, b in zip(rows, base)]))
    return out


def merit(result: dict, worse: float) -> float:
    """The objective, plus :data:`PENALTY` x how far the rotation and direction exceed ``worse``."""
    excess = max(result["rotation_peak"] - worse, 0.0) + max(result["direction_peak"] - worse, 0.0)
    return result["objective"] + PENALTY * excess


def search(config: str, cases, step: float, worse: float, log) -> Washout:
    """The coordinate search of the module's notes on one configuration; returns the best settings."""
    model = Model(config=config)
    cache = {}
    cases = [(name, shortened(path, SEARCH_END)) for name, path in cases]

    def run(settings: Washout) -> dict:
        if settings not in cache:
            start = time.perf_counter()
            rows = [evaluate(path, model, settings, step) for _, path in cases]
            cache[settings] = {**score(rows, base), "rows": rows}
            log({"config": config, "settings": dataclasses.asdict(settings), "seconds": time.perf_counter() - start,
                 **{k: v for k, v in cache[settings].items() if k != "rows"}})
        return cache[settings]

    base = [evaluate(path, model, Washout(), step) for _, path in cases]
    best = START
    best_score = merit(run(best), worse)
    for stage in ("coarse", "refine"):
        for axis in COARSE:
            if axis in UNUSED[config]:
                continue
            if stage == "coarse":
                values = COARSE[axis]
            else:
                values = tuple(float(f"{getattr(best, axis) * f:.3g}") for f in REFINE)
                values = tuple(min(v, CAP[axis]) for v in values) if axis in CAP else values
            for value in values:
                candidate = dataclasses.replace(best, **{axis: value})
                score_ = merit(run(candidate), worse)
                if score_ < best_score:
                    best, best_score = candidate, score_
            result = cache[best]
            print(f"{config} {stage} {axis}: {getattr(best, axis):.4g} -> objective {result['objective']:.4f}, "
                  f"rotation {result['rotation_peak']:.2f}, direction {result['direction_peak']:.2f}", flush=True)
    return best


def table(cases, step: float) -> tuple[str, list[dict]]:
    """The before/after markdown table (untuned ``Washout()`` and the configurations' tuned settings) on ``step``."""
    lines = ["| case | configuration | felt force RMS before / after [m/s^2] | after / before | "
             "direction peak before / after [deg] | rotation peak before / after [deg/s] | limits |",
             "| --- " * 7 + "|"]
    records = []
    for config in CONFIGS:
        model = Model(config=config)
        ratios = []
        for name, path in cases:
            before = evaluate(path, model, Washout(), step, checked=True)
            after = evaluate(path, model, tuned(model.config), step, checked=True)
            ratios.append(after["force_rms"] / before["force_rms"])
            records.append({"case": name, "config": config, "before": before, "after": after})
            limits = "held" if before["passed"] and after["passed"] else "BROKEN"
            lines.append(f"| {name} | {config} | {before['force_rms']:.3f} / {after['force_rms']:.3f} | "
                         f"{ratios[-1]:.2f} | {before['direction_peak']:.0f} / {after['direction_peak']:.0f} | "
                         f"{before['rotation_peak']:.0f} / {after['rotation_peak']:.0f} | {limits} |")
        lines.append(f"| mean ratio | {config} | | {np.mean(ratios):.3f} | | | |")
    return "\n".join(lines), records


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--corpus", type=Path, default=real.CORPUS, help="corpus folder (built if missing)")
    parser.add_argument("--cases", nargs="+", default=None, help="only these cases (corpus or built-in names)")
    parser.add_argument("--configs", nargs="+", choices=CONFIGS, default=CONFIGS)
    parser.add_argument("--step", type=float, default=0.05, help="the search's grid [s]")
    parser.add_argument("--table-step", type=float, default=0.02, help="the table's grid [s] (online's)")
    parser.add_argument("--worse", type=float, default=1.5, help="admissible mean worsening of rotation, direction")
    parser.add_argument("--table-only", action="store_true", help="only the table of the frozen settings")
    parser.add_argument("--out", type=Path, default=HERE / "tune-classical-results.jsonl", help="the search's log")
    args = parser.parse_args(argv)
    cases = load_cases(args.corpus, args.cases)
    print(f"{len(cases)} cases: {', '.join(name for name, _ in cases)}", flush=True)
    if not args.table_only:
        start = time.perf_counter()
        with args.out.open("w") as log_file:
            def log(record):
                log_file.write(json.dumps(record) + "\n")
                log_file.flush()

            for config in args.configs:
                best = search(config, cases, args.step, args.worse, log)
                print(f"{config}: {best!r}", flush=True)
                log({"config": config, "best": dataclasses.asdict(best)})
        print(f"search: {time.perf_counter() - start:.0f} s on {time.strftime('%Y-%m-%d')}", flush=True)
    text, _ = table(cases, args.table_step)
    print(text)
    return 0


if __name__ == "__main__":
    sys.exit(main())

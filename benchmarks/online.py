"""On-line controller benchmark: compute time per cycle and tracking, in one run.

    python benchmarks/online.py

Per configuration, horizon and step: median, p99 and max compute time of a controller step (the
preview handed to it, the command checked against every limit), the fine-grid RMS error of the MPC,
of the classical dynamic-flight-simulator loop (7.4.2; dfs only) and of the off-line optimum (the
best any on-line controller can do), and how often a fallback was used. Perfect preview, no deadline
(every step's own solution is used, so the timings show what each step costs).
"""

from __future__ import annotations

import sys
from collections import Counter

import numpy as np

from desdemona import Model, default_params, profiles
from desdemona.offline import OptimizeOptions, optimize
from desdemona.online import MPCOptions, OnlineOptions, run
from desdemona.problem import ProblemOptions


def row(path, config, horizon, step, method, params):
    model = Model(params, config)
    mpc = MPCOptions(horizon=horizon, step=step, deadline=float("inf"), method=method)
    result = run(path, model, OnlineOptions(mpc))
    classical = "" if result.baseline_check is None else f"{result.baseline_check.rms:.4f}"
    offline = optimize(path, model, OptimizeOptions(ProblemOptions(h_u=step), starts=2)).check
    times = np.percentile(result.loop.compute_times, [50, 99, 100]) * 1e3
    fallbacks = sum(v for k, v in Counter(result.loop.sources).items() if k != "mpc")
    return (f"| {path.name} | {config} | {horizon:g} | {step:g} | {method} | {times[0]:.2f} | {times[1]:.2f} "
            f"| {times[2]:.2f} | {result.check.rms:.4f} | {classical} | {offline.rms:.4f} "
            f"| {result.check.rms / offline.rms:.3f} | {fallbacks} | {'yes' if result.check.passed else 'NO'} |")


def main() -> int:
    params = default_params()
    print("| path | configuration | T_h [s] | h [s] | method | median [ms] | p99 [ms] | max [ms] | RMS MPC "
          "| RMS classical | RMS off-line | MPC / off-line | fallbacks | limits kept |")
    print("| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |")
    for path in (profiles.dfs_catapult(), profiles.roller_coaster()):
        for method in ("rti", "nlp"):
            print(row(path, "dfs", 2.0, 0.02, method, params), flush=True)
        print(row(path, "dfs", 1.0, 0.1, "rti", params), flush=True)  # the thesis' 10 Hz, 1 s horizon
    catapult = profiles.catapult()
    for method in ("rti", "nlp"):
        print(row(catapult, "yaw-track-cabin", 2.0, 0.05, method, params), flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())

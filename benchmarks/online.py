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
from desdemona.baselines import classical_dfs
from desdemona.offline import OptimizeOptions, optimize
from desdemona.online import MPC, PREDICTORS, MPCOptions
from desdemona.problem import ProblemOptions
from desdemona.simulate import check, closed_loop


def row(path, config, horizon, step, method, params):
    model = Model(params, config)
    q0 = qd0 = None
    classical = ""
    if config == "dfs":
        t, q1, q1d, q1dd = classical_dfs(path, model)
        q0, qd0 = [0.0], [q1d[0]]
    controller = MPC(model, MPCOptions(horizon=horizon, step=step, deadline=float("inf"), method=method),
                     weights=path.weights)
    run = closed_loop(controller, path, PREDICTORS["perfect"], q0=q0, qd0=qd0)
    mpc, _ = check(model, path, run.t_nodes, run.q0, run.qd0, run.u, step=step)
    if config == "dfs":
        t, q1, q1d, q1dd = classical_dfs(path, model, times=run.t_nodes)
        c, _ = check(model, path, t, q1[:1], q1d[:1], q1dd[:-1, None], step=step)
        classical = f"{c.rms:.4f}"
    offline = optimize(path, config, params, OptimizeOptions(ProblemOptions(h_u=step), starts=2)).check
    times = np.percentile(run.compute_times, [50, 99, 100]) * 1e3
    fallbacks = sum(v for k, v in Counter(run.sources).items() if k != "mpc")
    return (f"| {path.name} | {config} | {horizon:g} | {step:g} | {method} | {times[0]:.2f} | {times[1]:.2f} "
            f"| {times[2]:.2f} | {mpc.rms:.4f} | {classical} | {offline.rms:.4f} | {mpc.rms / offline.rms:.3f} "
            f"| {fallbacks} | {'yes' if mpc.passed else 'NO'} |")


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

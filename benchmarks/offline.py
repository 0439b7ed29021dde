"""Off-line solver benchmark: ours against the thesis' method, side by side, in one run.

    python benchmarks/offline.py            # prints one markdown table
    python benchmarks/offline.py --quick    # skips the 35 s full-configuration rows and the scaling rows

Every row is measured in this run, on this machine. Wall times are those of one start including the
problem's construction (of the whole multi-start in rows with several starts), "build" the construction
alone and "solve per start" the solver's own time per start, after one untimed run of each method on
the cosine (libraries loaded); RMS is the fine-grid weighted RMS(S - S_d) of the independent check
(grid 10x finer than the solver's), "worst" the highest use of any limit on that grid.

Like the command line, the run keeps freed memory for IPOPT's next factorisation
(:mod:`desdemona.support.allocator`). Compiled stage functions (:mod:`desdemona.cueing.compiled`) go to a cache made
for this run: the first `full` row compiles them (its "build" includes it), the later ones find them.
"""

from __future__ import annotations

import argparse
import dataclasses
import os
import resource
import sys
import tempfile
import time

import numpy as np

from desdemona import Model, default_params, profiles, thesis_toy_params
from desdemona.baselines.thesis import ThesisOptions, optimize_thesis
from desdemona.check.simulate import check
from desdemona.cueing import compiled
from desdemona.cueing.formulation import ProblemOptions
from desdemona.cueing.offline import OptimizeOptions, optimize
from desdemona.support import allocator


@dataclasses.dataclass
class Row:
    path: str
    config: str
    method: str
    rms: float
    worst: float
    iterations: int
    seconds: float
    status: str
    note: str = ""
    build: float = 0.0  # construction of the problem [s]
    per_start: float = 0.0  # the solver's time per start [s]
    starts: int = 1


# The method before the six-joint speed-ups, for the side-by-side rows: the torque and power limits' curvature in
# the Hessian, no weight on the channels Q leaves at zero (the default on three joints or fewer), and
# the stage functions interpreted. Two later changes apply to both rows and cannot be switched off:
# the stages no longer evaluate their ends twice, and freed memory is kept for the factorisations.
BEFORE_SPEED_UPS = {"limit_curvature": True, "unweighted": 0.0, "compile": False}


def ours(path, config, params, solver, h_u, weights=None, starts=1, label="", **problem) -> Row:
    options = OptimizeOptions(ProblemOptions(h_u=h_u, solver=solver, weights=weights, **problem), starts=starts)
    start = time.perf_counter()
    result = optimize(path, Model(params, config), options)
    seconds = time.perf_counter() - start
    s = min(result.starts, key=lambda r: r.rms)
    method = f"ours ({solver}{label})" if starts == 1 else f"ours ({solver}{label}, {starts} starts)"
    return Row(path.name, config, method, result.check.rms, result.check.worst_use, s.iterations,
               seconds, s.status, f"N = {len(result.solution.u)}", result.timings["build"],
               result.timings["solve"] / len(result.starts), starts)


def thesis(path, config, params, h_u, label, **kw) -> Row:
    options = ThesisOptions(h_u=h_u, starts=1, seed=0, **kw)
    start = time.perf_counter()
    problem, runs = optimize_thesis(path, Model(params, config), options)
    seconds = time.perf_counter() - start
    run = runs[0]
    result, _ = check(problem.model, path, run.plan, step=0.01, weights=path.weights)
    return Row(path.name, config, label, result.rms, result.worst_use, run.iterations, seconds,
               "limits kept" if result.passed else "LIMITS EXCEEDED", f"{run.evaluations} evaluations",
               per_start=run.solve_time)


def table(rows: list[Row]) -> str:
    lines = ["| path | configuration | method | fine-grid RMS | worst limit use | iterations | wall time [s] "
             "| build [s] | solve per start [s] | thesis time / ours | ours RMS / thesis | status |",
             "| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |"]
    for r in rows:
        baseline = next((b for b in rows if b.path == r.path and b.config == r.config
                         and b.method.startswith("thesis (5.4")), None)
        speed = rms = ""
        if baseline is not None and r.method.startswith("ours"):
            speed = f"{baseline.seconds / r.seconds:.1f}x"
            if r.starts > 1:  # per start, the construction shared by all of them
                speed = f"{baseline.per_start / r.per_start:.1f}x per start"
            rms = f"{r.rms / baseline.rms:.3f}"
        lines.append(f"| {r.path} | {r.config} | {r.method} | {r.rms:.4f} | {r.worst:.6f} | {r.iterations} "
                     f"| {r.seconds:.3f} | {r.build:.3f} | {r.per_start:.4f} | {speed} | {rms} | {r.status}; {r.note} |")
    return "\n".join(lines)


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="skip the long rows")
    args = parser.parse_args(argv)
    allocator.reuse_freed_memory()
    allocator.one_blas_thread()
    os.environ["DESDEMONA_CACHE"] = tempfile.mkdtemp(prefix="desdemona-benchmark-")
    compiled.OPTIMISED = "now"  # the steady state: optimised libraries, as a later run finds them
    rows: list[Row] = []
    toy, params = thesis_toy_params(), default_params()

    # Thesis 4.7: toy parameters, f_y = 5 cos(2t), 5 s, h_u = 0.1 s, all limits.
    cosine = profiles.cosine()
    # One untimed run of each method first: libraries loaded, model functions built, thread pools up.
    for solver in ("ipopt", "fatrop"):
        ours(cosine, "yaw-track", toy, solver, 0.1)
    thesis(cosine, "yaw-track", toy, 0.1, "warm-up")
    for solver in ("ipopt", "fatrop"):
        rows.append(ours(cosine, "yaw-track", toy, solver, 0.1))
    # The thesis ran 4.7 from many starts: per start, once the problem is built (flat SX graph).
    rows.append(ours(cosine, "yaw-track", toy, "fatrop", 0.1, starts=8))
    rows.append(thesis(cosine, "yaw-track", toy, 0.1, "thesis (5.4: stop on cost change 0.1)"))
    rows.append(thesis(cosine, "yaw-track", toy, 0.1, "thesis (4.7: 40 iterations)", min_cost_change=0.0))
    print(table(rows), file=sys.stderr)

    # Section 5.6.2: the catapult on three joints, 8 s, h_u = 0.05 s.
    catapult = profiles.catapult()
    for solver in ("ipopt", "fatrop"):
        rows.append(ours(catapult, "yaw-track-cabin", params, solver, 0.05))
    rows.append(thesis(catapult, "yaw-track-cabin", params, 0.05, "thesis (5.4: stop on cost change 0.1)"))

    if not args.quick:
        # Scaling with the horizon: a periodic lateral and longitudinal path on three joints.
        for duration in (10.0, 20.0, 40.0):
            t = np.arange(0.0, duration + 1e-9, 0.01)
            S = np.zeros((len(t), 6))
            S[:, 3], S[:, 4], S[:, 5] = 3.0 * np.sin(0.8 * t), 5.0 * np.cos(0.5 * t), 9.81
            path = profiles.DesiredPath(f"periodic {duration:g} s", t, S, weights=(0, 0, 0, 1, 1, 0))
            row = ours(path, "yaw-track-cabin", params, "ipopt", 0.05)
            row.note += f", {1e3 * row.per_start / max(row.iterations, 1):.1f} ms/iteration of the solver"
            rows.append(row)
    # The whole machine: the method before the six-joint speed-ups and the default side by side, in this run.
    paths = [catapult] if args.quick else [catapult, profiles.car_lap()]
    for path in paths:
        first = path is catapult  # compiles the stage functions into the fresh cache
        for label, problem in ((", before the six-joint speed-ups", BEFORE_SPEED_UPS), (", compiling" if first else "", {})):
            row = ours(path, "full", params, "ipopt", 0.05, label=label, **problem)
            peak = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024.0
            row.note += (f", {1e3 * row.seconds / max(row.iterations, 1):.0f} ms/iteration, "
                         f"peak memory of the process so far {peak:.0f} MB")
            rows.append(row)
    print(table(rows))
    return 0


if __name__ == "__main__":
    sys.exit(main())

"""The limit prices of an off-line result against finite differences of real solves, on two paths.

    python benchmarks/limit_prices.py            # catapult on yaw-track-cabin, the double pulse on yaw-track
    python benchmarks/limit_prices.py --top 3    # fewer limits per path

Each path is solved as ``optimize`` poses it (:func:`desdemona.runs.session.offline`: from rest, to
the centre, the wall before the position limits, the felt weights), by IPOPT and by fatrop from the
same guess; the prices of :mod:`desdemona.cueing.prices` come from each solver's multipliers. For the
``--top`` dearest limits (held positions among them) whose price is at least 1e-3 m/s^2, the limit is then moved by 1 % and
5 % (:func:`desdemona.cueing.prices.relaxed`) and the problem solved again by IPOPT, warm from the
IPOPT optimum (its multipliers too, so that it stays in the same local optimum); the finite
difference (J(share) - J) / share is set against the multipliers' dJ/d(epsilon), and the central one
(J(1 %) - J(-1 %)) / 2 %, whose error is not the cost's curvature in the bound. Prints one markdown
table (docs/benchmarks/limit-prices.md). Last, the car lap solved in windows, its prices combined from
the windows' (every relaxed run solves every window again).
"""

from __future__ import annotations

import argparse
import dataclasses
import os
import time

from desdemona import Model, default_params, profiles
from desdemona.cueing import prices
from desdemona.cueing.offline import OptimizeOptions, initial_guesses
from desdemona.cueing.transcription import CueingProblem
from desdemona.cueing.windows import optimize_windowed
from desdemona.runs import session

CASES = (("catapult", "yaw-track-cabin"), ("double-pulse", "yaw-track"))
#: A path solved in windows: the car lap (35 s) in windows of 20 s (four; the machine needs 15 s of overlap).
WINDOWED = ("car-lap", "yaw-track", 20.0)
SHARES = (0.01, 0.05)


def solved(path, model, options, solver, guess=None):
    problem = CueingProblem(model, path, dataclasses.replace(options, solver=solver))
    _, x, u = guess if guess is not None else initial_guesses(problem, 1, 0)[0]
    start = time.perf_counter()
    solution = problem.solve(x, u)
    solve = time.perf_counter() - start
    start = time.perf_counter()
    found = prices.limit_prices(problem, solution)
    return problem, solution, found, solve, time.perf_counter() - start


def windowed(params, top: int) -> str:
    """The rows of a path solved in windows (:func:`desdemona.cueing.windows.optimize_windowed`, IPOPT as
    ``optimize`` chooses on two joints), each relaxed run solving every window again: the combined
    prices (:func:`desdemona.cueing.prices.combined`) against the whole path's cost (the kept parts')."""
    name, config, window = WINDOWED
    model = Model(params, config)
    resolved = session.offline(profiles.PROFILES[name](), model, session.Choices())
    options = OptimizeOptions(dataclasses.replace(resolved.options, compile=False), starts=1)
    start = time.perf_counter()
    base = optimize_windowed(resolved.path, model, options, window)
    seconds = time.perf_counter() - start
    found = base.prices
    for p in [p for p in found.ranked() if abs(p.price) >= 1e-3][:top]:
        costs = {share: optimize_windowed(resolved.path, prices.relaxed(model, p.family, p.joint, share), options,
                                          window).prices.cost for share in (*SHARES, -SHARES[0])}
        cells = [f"{d:+.5g} | {d / p.cost_slope - 1:+.1%}" for d in ((costs[s] - found.cost) / s for s in SHARES)]
        central = (costs[SHARES[0]] - costs[-SHARES[0]]) / (2 * SHARES[0])
        binds = "held" if p.family == prices.HELD else f"{p.binds_s:.2f}"
        print(f"| {name} ({base.timings['windows']} windows of {window:g} s) | {config} | {p.family} | {p.joint} | {binds} | "
              f"{p.price:+.4f} | {p.cost_slope:+.5g} | - | {' | '.join(cells)} | {central / p.cost_slope - 1:+.1%} |")
    return (f"{name} on {config} in windows of {window:g} s: J = {found.cost:.6g} (the kept parts', IPOPT, "
            f"{seconds:.2f} s for every window), felt error sqrt(J) = {found.felt_error:.4g} m/s^2")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--top", type=int, default=5, help="the dearest limits checked per path")
    args = parser.parse_args()
    params = default_params()
    print(f"load before: {os.getloadavg()[0]:.2f}\n")
    print("| path | configuration | limit | joint | binds [s] | price per 10 % [m/s^2] | dJ/deps IPOPT | dJ/deps fatrop "
          "| finite diff. 1 % | error 1 % | finite diff. 5 % | error 5 % | error central +-1 % |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    notes = []
    for name, config in CASES:
        model = Model(params, config)
        resolved = session.offline(profiles.PROFILES[name](), model, session.Choices())
        path, options = resolved.path, dataclasses.replace(resolved.options, compile=False)
        problem, base, found, solve, pricing = solved(path, model, options, "ipopt")
        guess = initial_guesses(problem, 1, 0)[0]
        _, fat, fat_found, fat_solve, fat_pricing = solved(path, model, options, "fatrop", guess)
        notes.append(f"{name} on {config}: J = {base.cost:.6g} (IPOPT {base.status}, {solve:.2f} s; prices "
                     f"{pricing * 1e3:.0f} ms), fatrop J = {fat.cost:.6g} ({fat.status}, {fat_solve:.2f} s; "
                     f"prices {fat_pricing * 1e3:.0f} ms), felt error sqrt(J) = {found.felt_error:.4g} m/s^2, "
                     f"default solver {resolved.options.solver}")
        fat_table = fat_found.to_dict()
        # a limit whose price is below 1e-3 m/s^2 per 10 % is not checked: its relative error means nothing
        rows = [p for p in found.ranked() if abs(p.price) >= 1e-3 and (p.spans or p.family == prices.HELD)][:args.top]
        for p in rows:
            differences, costs = [], {}
            for share in (*SHARES, -SHARES[0]):
                moved = CueingProblem(prices.relaxed(model, p.family, p.joint, share), path, options)
                again = moved.solve(base.x, base.u, warm=base)
                costs[share] = again.cost
                fd = (again.cost - base.cost) / share
                if share > 0:
                    differences.append(f"{fd:+.5g} | {fd / p.cost_slope - 1:+.1%}" + ("" if again.success else " (not converged)"))
            central = (costs[SHARES[0]] - costs[-SHARES[0]]) / (2 * SHARES[0])
            differences.append(f"{central / p.cost_slope - 1:+.1%}")
            binds = "held" if p.family == prices.HELD else f"{p.binds_s:.2f}"
            print(f"| {name} | {config} | {p.family} | {p.joint} | {binds} | {p.price:+.4f} | {p.cost_slope:+.5g} | "
                  f"{fat_table[p.family][p.joint]['cost_slope']:+.5g} | {' | '.join(differences)} |")
    notes.append(windowed(params, args.top))
    print()
    for note in notes:
        print(f"- {note}")
    print(f"\nload after: {os.getloadavg()[0]:.2f}")


if __name__ == "__main__":
    main()

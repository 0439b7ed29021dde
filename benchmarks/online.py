"""On-line controller benchmark: compute time per cycle, tracking and prediction, in one run.

    python benchmarks/online.py            # every table
    python benchmarks/online.py --quick    # the first table only
    python benchmarks/online.py --dfs      # the whole-machine dfs table only
    python benchmarks/online.py --horizon  # the horizon and the stoppable bound table only
    python benchmarks/online.py --configs dfs-yaw dfs   # the first table's rows of these only
    python benchmarks/online.py --reach    # a 2 s preview reaching 4 s where the track moves

Every run starts from rest, as a real session does, unless a row says otherwise: still, where the
first plan wants the machine (``--initial rest``; at home on dfs). Tables (markdown, on stdout):

1. Per path, configuration, horizon, grid and method: median, p99 and max compute time of a cycle (the
   preview handed to it, the command checked against every limit), the fine-grid RMS of what the
   configuration's cost weighs (:func:`rms`: the modulus on the thesis' yaw-only ``dfs-yaw``, the
   felt force elsewhere, on ``dfs`` its direction included) of the MPC, of the classical baseline
   (the dfs loop of 7.4.2 or the classical washout, from the same start) and of two off-line optima
   from rest (the start's position free, ``--initial rest``): as it is, and with the on-line
   formulation's stopping condition, the bound no on-line controller from rest can beat
   (:func:`bounds`); on the dfs configurations the modulus alone against the classical loop; and
   how often a fallback was used. The dfs rows include the thesis' timing (7.5: T_h 1 s, T_c 0.4 s
   delayed, h 0.1 s) as the thesis has it (the plan ends with the preview: K = 0) and as the command
   line runs it (the plan reaching the default horizon, 2 s, the path held past the preview).
   Perfect preview, no deadline (every cycle's own plan is used, so the timings show what each
   cycle costs).
2. Per configuration and predictor: RMS (as in table 1), correlation and lag between desired and felt
   (the modulus on dfs, f_y elsewhere), p99 compute.
3. The route predictor on a ride replayed 10 % faster or slower with sensor noise, against perfect
   preview and holding the present value.
4. The whole-machine dfs (yaw and gimbals planned together) at 50 Hz with a 2 s horizon, and the
   thesis' yaw-only formulation (dfs-yaw) beside it, from rest and from steady rotation at the path's
   first modulus (the thesis' 7.5.1 setting, ``--initial steady``): compute per cycle, the modulus RMS,
   the RMS of the felt force (S against (0, 0, M_d) in the cabin, weighted: what the command line
   prints as RMS), the felt direction error and felt rotation, and the joints' acceleration
   reversals, of the MPC and of the classical loop side by side.
5. (``--horizon``) The multi-joint configurations from rest with a 2 s and a 4 s horizon against the
   bound; with 4 s from home (``--initial home``) against the bound from home; and with 4 s from a
   steady start (``--initial steady``: still, the cabin tilted to the path's first force where it
   can tilt) against the off-line optimum from rest.
6. (``--reach``) The multi-joint configurations from rest with a 2 s preview, the plan ending with it
   or reaching 4 s with the path held past it (what the command line does with ``--horizon 2``
   there), against a 4 s preview.
"""

from __future__ import annotations

import argparse
import sys
from collections import Counter

import numpy as np

from desdemona import Model, default_params, profiles
from desdemona.control.mpc import MPCOptions, default_horizon
from desdemona.control.online import OnlineOptions, run
from desdemona.cueing.formulation import ProblemOptions
from desdemona.cueing.offline import OptimizeOptions, optimize
from desdemona.machine.configs import get_configuration
from desdemona.profiles import DesiredPath


def timings(result) -> np.ndarray:
    return np.percentile(result.loop.compute_times, [50, 99, 100]) * 1e3


def felt(result) -> tuple[float, float]:
    """Correlation and lag [s] of what is felt against what is desired: the modulus on dfs, f_y else."""
    q = result.quality
    if result.model.config.takes_modulus:
        return q.modulus_correlation, q.modulus_lag_s
    return q.correlation[4], q.lag_s[4]


def bounds(path, model, step, home: bool = False) -> dict[str, float]:
    """Off-line optima (RMS as :func:`rms` shows it, 3 starts), all from rest:

    - "free": the start's position free (``--initial rest``), the off-line problem as it is;
    - "bound": the same with the on-line formulation's stopping condition (every planned state can
      brake to rest within the position limits at ``braking`` times the acceleration limit: the MPC
      must keep it because it does not know what follows its horizon). An on-line run from rest
      chooses its start too (:meth:`desdemona.control.mpc.MPC.place`), so this is the bound no on-line
      controller from rest can beat;
    - "home" (when asked): the bound for a start at home (``--initial home``).

    On ``dfs`` rest is at home, off-line and on-line."""
    n, config = model.n, model.config.name
    stop = {"stoppable": True, "braking": MPCOptions().braking}
    options = {"free": ProblemOptions(h_u=step, initial="rest"), "bound": ProblemOptions(h_u=step, initial="rest", **stop)}
    if home:
        options["home"] = ProblemOptions(h_u=step, initial="given", initial_state=(np.zeros(n), np.zeros(n)), **stop)
    return {k: rms(optimize(path, model, OptimizeOptions(o, starts=3)).check, config) for k, o in options.items()}


def tracking_row(path, config, horizon, step, method, params, replan=None, delay=False, bound_cache=None,
                 reach=None) -> str:
    """One row of the first table; ``bound_cache`` (a dict) keeps the off-line optima of a path,
    configuration and step for the next row that needs them."""
    model = Model(params, config)
    mpc = MPCOptions(horizon=horizon, step=step, replan=replan, delay=delay, deadline=float("inf"), method=method,
                     reach=reach)
    result = run(path, model, OnlineOptions(mpc))
    key = (path.name, config, step)
    b = bound_cache[key] if bound_cache is not None and key in bound_cache else bounds(path, model, step)
    if bound_cache is not None:
        bound_cache[key] = b
    free, bound = b["free"], b["bound"]
    t = timings(result)
    fallbacks = sum(v for k, v in Counter(result.loop.sources).items() if k != "mpc")
    timing = f"{horizon:g} | {mpc.length:g} | {step:g} | {mpc.period:g}{' delayed' if delay else ''}"
    ours, classical = rms(result.check, config), rms(result.baseline_check, config)
    modulus = (f"{result.check.rms_modulus / result.baseline_check.rms_modulus:.3f}"
               if model.config.takes_modulus else "")
    return (f"| {path.name} | {config} | {timing} | {mpc.plan_method} | {t[0]:.2f} | {t[1]:.2f} | {t[2]:.2f} "
            f"| {ours:.4f} | {classical:.4f} | {free:.4f} | {ours / free:.3f} "
            f"| {bound:.4f} | {ours / bound:.3f} | {ours / classical:.3f} | {modulus} "
            f"| {fallbacks} | {'yes' if result.check.passed else 'NO'} |")


def rms(check, config) -> float:
    """The RMS a row shows: what the configuration's own cost weighs. The modulus on the thesis'
    yaw-only ``dfs-yaw``; the weighted felt force elsewhere: on ``dfs``, whose gimbals turn the cabin
    to the force, that is the force against (0, 0, M_d) in the cabin, so its direction error counts
    (the modulus alone is in its own column)."""
    return check.rms_modulus if config == "dfs-yaw" else check.rms


def whole_machine_row(path, config, predictor, params, start="rest") -> str:
    result = run(path, Model(params, config), OnlineOptions(MPCOptions(horizon=2.0, step=0.02), predictor=predictor,
                                                            initial=start))
    t = timings(result)
    cells = [f"{t[0]:.2f} | {t[1]:.2f} | {t[2]:.2f}"]
    for check, q in ((result.check, result.quality), (result.baseline_check, result.baseline_quality)):
        cells.append(f"{check.rms_modulus:.3f} | {check.rms:.3f} | {np.degrees(q.direction_rms):.2f} | {np.degrees(q.direction_peak):.1f} "
                      f"| {np.degrees(np.nanmax(q.rotation_peak)):.0f} | {np.max(q.sign_changes_per_s):.2f} "
                      f"| {'yes' if check.passed else 'NO'}")
    return f"| {path.name} | {config} | {start} | {predictor} | {' | '.join(cells)} |"


def predictor_row(path, config, predictor, step, params) -> str:
    result = run(path, Model(params, config), OnlineOptions(MPCOptions(horizon=2.0, step=step), predictor=predictor))
    correlation, lag = felt(result)
    return (f"| {path.name} | {config} | {predictor} | {rms(result.check, config):.4f} | {correlation:.3f} | {lag:.3f} "
            f"| {timings(result)[1]:.2f} |")


def replay(reference: DesiredPath, speed: float, seed: int = 7) -> DesiredPath:
    """The reference ridden ``speed`` times as fast, with 0.3 m/s^2 of white sensor noise at 100 Hz."""
    rng = np.random.default_rng(seed)
    t = np.arange(0.0, reference.duration / speed, 0.01)
    modulus = np.maximum(reference.sample_modulus(speed * t) + rng.normal(0.0, 0.3, len(t)), 0.0)
    return DesiredPath(f"{reference.name} x{speed:g}", t, None, modulus=modulus)


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="the first table only")
    parser.add_argument("--dfs", action="store_true", help="the whole-machine dfs table only")
    parser.add_argument("--horizon", action="store_true", help="the horizon and stoppable-bound table only")
    parser.add_argument("--configs", nargs="+", metavar="NAME", help="the first table's rows of these configurations only")
    parser.add_argument("--reach", action="store_true", help="the short-preview reach table only")
    args = parser.parse_args(argv)
    params = default_params()
    if args.dfs:
        return whole_machine_table(params)
    if args.reach:
        return reach_table(params)
    if args.horizon:
        return horizon_table(params)
    wanted = lambda config: args.configs is None or config in args.configs
    print("| path | configuration | T_h [s] | reach [s] | h [s] | T_c [s] | method | median [ms] | p99 [ms] "
          "| max [ms] | RMS MPC | RMS classical | off-line from rest | MPC / it | off-line from rest, "
          "stoppable (the bound) | MPC / bound | MPC / classical | modulus: MPC / classical | fallbacks "
          "| limits kept |")
    print("|" + " --- |" * 20)
    cache = {}
    for config in ("dfs-yaw", "dfs"):
        for path in (profiles.catapult(), profiles.dfs_catapult(), profiles.roller_coaster()):
            if not wanted(config):
                continue
            for method in ("rti", "nlp"):
                print(tracking_row(path, config, 2.0, 0.02, method, params, bound_cache=cache), flush=True)
            # the thesis' timing (7.5): T_h 1 s, T_c 0.4 s, h 0.1 s, each plan applied one period late;
            # as the thesis has it (K = 0: the plan ends with the preview), and as the command line
            # runs it (the plan reaches the default horizon, the path held past the preview)
            for reach in (None, default_horizon(get_configuration(config))):
                print(tracking_row(path, config, 1.0, 0.1, "auto", params, replan=0.4, delay=True,
                                   bound_cache=cache, reach=reach), flush=True)
    for name in ("catapult", "double-pulse", "car-lap"):
        for config in ("yaw-track", "yaw-track-cabin", "full"):
            if wanted(config):
                print(tracking_row(profiles.get_profile(name), config, 2.0, 0.05, "rti", params), flush=True)
    if args.quick or args.configs:
        return 0
    print("\n| path | configuration | predictor | RMS | correlation | lag [s] | p99 [ms] |")
    print("| --- | --- | --- | --- | --- | --- | --- |")
    for path, config, step in ((profiles.dfs_catapult(), "dfs", 0.02), (profiles.roller_coaster(), "dfs", 0.02),
                               (profiles.catapult(), "yaw-track-cabin", 0.05), (profiles.car_lap(), "full", 0.05)):
        for predictor in ("perfect", "hold", "linear"):
            print(predictor_row(path, config, predictor, step, params), flush=True)
    print("\n| reference | live run | perfect | hold | route | route / perfect | route / hold |")
    print("| --- | --- | --- | --- | --- | --- | --- |")
    model = Model(params, "dfs")
    for reference in (profiles.roller_coaster(), profiles.dfs_catapult()):
        for speed in (1.1, 0.9):
            live = replay(reference, speed)
            r = {p: run(live, model, OnlineOptions(MPCOptions(horizon=2.0, step=0.02), predictor=p,
                                                   reference=reference if p == "route" else None)).check.rms_modulus
                 for p in ("perfect", "hold", "route")}
            print(f"| {reference.name} | {speed:g}x speed, noise 0.3 m/s^2 | {r['perfect']:.4f} | {r['hold']:.4f} "
                  f"| {r['route']:.4f} | {r['route'] / r['perfect']:.3f} | {r['route'] / r['hold']:.3f} |",
                  flush=True)
    return whole_machine_table(params)


def track_cases(params):
    """(name, path, configuration, model) of every built-in track path on every configuration with the track."""
    for name in ("catapult", "double-pulse", "car-lap", "cosine"):
        path = profiles.get_profile(name)
        for config in ("yaw-track", "yaw-track-cabin", "full"):
            yield name, path, config, Model(params, config)


def horizon_table(params, step: float = 0.05) -> int:
    print("| path | configuration | off-line from rest | off-line from rest, stoppable (the bound) "
          "| MPC T_h 2 s | / bound | p99 [ms] | MPC T_h 4 s | / bound | p99 [ms] "
          "| off-line from home, stoppable | MPC T_h 4 s from home | / its bound "
          "| MPC T_h 4 s from a steady start | / off-line from rest | limits kept |")
    print("|" + " --- |" * 16)
    for name, path, config, model in track_cases(params):
        b = bounds(path, model, step, home=True)
        results = {(horizon, start): run(path, model, OnlineOptions(
                       MPCOptions(horizon=horizon, step=step, deadline=float("inf")), initial=start))
                   for horizon, start in ((2.0, "rest"), (4.0, "rest"), (4.0, "home"), (4.0, "steady"))}

        def cell(key, against):
            ours = results[key].check.rms
            p99 = f" | {timings(results[key])[1]:.2f}" if key[1] == "rest" else ""
            return f"{ours:.4f} | {ours / b[against]:.3f}{p99}"

        kept = all(r.check.passed for r in results.values())
        print(f"| {name} | {config} | {b['free']:.4f} | {b['bound']:.4f} | {cell((2.0, 'rest'), 'bound')} "
              f"| {cell((4.0, 'rest'), 'bound')} | {b['home']:.4f} | {cell((4.0, 'home'), 'home')} "
              f"| {cell((4.0, 'steady'), 'free')} | {'yes' if kept else 'NO'} |", flush=True)
    return 0


def reach_table(params, step: float = 0.05) -> int:
    """A preview of 2 s where the track moves, the plan ending with it (``reach`` 2 s) or reaching the
    command line's 4 s with the path held past the preview, against 4 s of preview; from rest, 20 Hz."""
    print("| path | configuration | T_h 2 s, reach 2 s | T_h 2 s, reach 4 s | T_h 4 s | reach 4 s / T_h 4 s "
          "| p99 [ms], reach 2 s | reach 4 s | limits kept |")
    print("|" + " --- |" * 9)
    for name, path, config, model in track_cases(params):
        r = [run(path, model, OnlineOptions(MPCOptions(horizon=h, step=step, deadline=float("inf"), reach=reach)))
             for h, reach in ((2.0, None), (2.0, 4.0), (4.0, None))]
        rms_ = [x.check.rms for x in r]
        kept = all(x.check.passed for x in r)
        print(f"| {name} | {config} | {rms_[0]:.4f} | {rms_[1]:.4f} | {rms_[2]:.4f} | {rms_[1] / rms_[2]:.3f} "
              f"| {timings(r[0])[1]:.2f} | {timings(r[1])[1]:.2f} | {'yes' if kept else 'NO'} |", flush=True)
    return 0


def whole_machine_table(params) -> int:
    print("\n| path | configuration | start | predictor | median [ms] | p99 [ms] | max [ms] "
          "| MPC: RMS(M - M_d) | RMS felt force | direction RMS [deg] | direction peak [deg] | felt rotation peak [deg/s] "
          "| reversals/s (max joint) | limits kept "
          "| classical: RMS(M - M_d) | RMS felt force | direction RMS [deg] | direction peak [deg] "
          "| felt rotation peak [deg/s] | reversals/s (max joint) | limits kept |")
    print("|" + " --- |" * 21)
    for path, predictor in ((profiles.dfs_catapult(), "perfect"), (profiles.roller_coaster(), "perfect"),
                            (profiles.get_profile("dfs-catapult-recorded"), "hold")):
        for start in ("rest", "steady"):
            for config in ("dfs", "dfs-yaw"):
                print(whole_machine_row(path, config, predictor, params, start), flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())

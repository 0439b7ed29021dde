"""What each subcommand of ``desdemona`` does, given its parsed arguments: ``run_NAME(args) -> exit code``.

Each checks its inputs before any work (raising :class:`~desdemona.cli.exits.UserError` or the library's
errors, reported by :func:`desdemona.cli.main` as one line), resolves the session's choices
(:mod:`desdemona.runs.session`), runs the library and prints what it did."""

from __future__ import annotations

import collections
import contextlib
import os
import sys
import time
from pathlib import Path

import numpy as np

from desdemona import profiles
from desdemona.cli.exits import EXIT_NOT_CONVERGED, EXIT_UNSAFE, UserError
from desdemona.cli.progress import OfflineProgress, OnlineProgress, compile_words
from desdemona.cueing import sizing
from desdemona.machine.configs import get_configuration
from desdemona.machine.model import Model
from desdemona.machine.params import load_params
from desdemona.occupant import perception as perception_models
from desdemona.runs import session
from desdemona.support import files, guard

from desdemona.cli.progress import EVERY as PROGRESS_EVERY  # noqa: E402  (re-exported: tests set it)


def _machine(args) -> Model:
    try:
        config = get_configuration(args.config)
    except ValueError as exc:
        raise UserError(str(exc)) from None
    return Model(load_params(args.params, base=args.base), config)


def run_model(args) -> int:
    from desdemona.cli.model_table import describe

    print(describe(_machine(args)))
    return 0


def _inputs(args) -> tuple:
    """The files a run reads: a replaced result folder must not hold them."""
    given = (getattr(args, "profile", None), getattr(args, "reference", None), getattr(args, "forecast", None),
             args.params)
    return tuple(p for p in given if isinstance(p, str) and os.path.exists(p))


def _claim_out(args) -> Path:
    """``args.out``, checked to be creatable and held for this run (:func:`desdemona.results.report.claim`)
    until it ends: a second run on the same folder is refused."""
    from desdemona.results import report

    out = Path(args.out)
    parent = out.absolute().parent
    if not parent.is_dir():
        raise UserError(f"{out}: cannot create it: the folder {parent} does not exist")
    if not os.access(parent, os.W_OK):
        raise UserError(f"{out}: cannot create it: {parent} is not a writable folder")
    args.held.enter_context(report.claim(out))
    return out


def _run_inputs(args):
    """The machine, the desired path and the output folder of a run, each checked before any work."""
    model = _machine(args)
    path = profiles.load(args.profile)
    shift = _shift(args)
    if shift:  # the file's own clock, said once: its times and the result's differ by it
        print(f"desdemona: warning: {args.profile}: its time starts at {shift['time_origin_s']:g} s, read as t = 0 "
              "(the result's times are the file's less that; summary.json keeps it as time_origin_s)",
              file=sys.stderr)
    return model, path, _result_folder(args)


def _shift(args) -> dict:
    """The summary.json entry of a path file whose time does not start at 0: the file's time of t = 0."""
    from desdemona.profiles.forecast import time_origin

    origin = time_origin(args.profile)
    return {"time_origin_s": origin} if origin else {}


def _result_folder(args) -> Path:
    """``args.out``, held for this run (:func:`_claim_out`), refused where it exists unless
    ``--overwrite`` and it is an earlier result that holds none of the run's inputs."""
    from desdemona.results import report

    out = _claim_out(args)
    if out.exists() and not args.overwrite and not report.empty_folder(out):
        raise UserError(f"{out}: already exists; choose another folder or add --overwrite")
    report.check_replaceable(out, protect=_inputs(args))
    return out


def _check_starts(args, processes: str, count: int) -> None:
    """--starts, --seed and the processes of an off-line run (``--workers`` or ``--processes``: ``count``)."""
    from desdemona.cueing.offline import MAX_STARTS

    if args.starts < 1 or count < 1:
        raise UserError(f"--starts and --{processes} must be at least 1")
    if args.starts > MAX_STARTS:
        raise UserError(f"--starts {args.starts}: at most {MAX_STARTS}: each start is a whole solve, and every "
                        "guess is made before the first; for a wider search run again with another --seed")
    if args.seed < 0:
        raise UserError(f"--seed {args.seed}: a seed is a whole number >= 0")


def run_optimize(args) -> int:
    from desdemona.results import report
    from desdemona.runs import solve

    model, path, out = _run_inputs(args)
    _check_starts(args, "workers", 1 if args.workers is None else args.workers)
    thesis = args.method == "thesis"  # the thesis' method has no perception model
    perception = perception_models.get_model(args.perception) if args.perception and not thesis else None
    resolved = solve.resolve(path, model, session.Choices.of(args), args.method, perception, args.workers,
                             args.starts)
    path, problem, size = resolved.path, resolved.options, resolved.size
    estimate = None if thesis else sizing.check_time(
        path, model.config, problem.h_u, problem.solver, args.starts, resolved.workers, resolved.window, args.max_time)
    unreachable = sizing.unreachable(path, model)
    progress = None if args.quiet else OfflineProgress(args.starts, size, path, model.config, estimate=estimate)
    compiling = guard.compile_seconds()
    with contextlib.nullcontext() if progress is None else progress, \
            guard.reporting(None if progress is None else progress.solving, PROGRESS_EVERY,
                            None if progress is None else progress.say):
        result = solve.solve(resolved, args.starts, args.seed, args.refine,
                             progress=None if progress is None else progress.start_done,
                             announce=None if progress is None else progress.window)
    report.write(result, out, command=report.command_line(), overwrite=args.overwrite, unreachable=unreachable,
                 protect=_inputs(args), view=args.view, extra_summary=_shift(args))
    c = result.check
    perceived = f" (perceived {c.rms_perceived:.4g})" if c.rms_perceived is not None else ""
    if model.config.aligned:
        perceived += f", RMS(M - M_d) = {c.rms_modulus:.4g}"
    solver = f"solver {result.solution.status}" + ("" if result.converged else " (NOT CONVERGED)")
    ends = FINAL_WORDS.get(problem.final, "")  # an on-line run ends free: on a short path the end weighs
    compiling = guard.compile_seconds() - compiling  # printed apart from the solve
    print(f"{path.name} on {model.config.name}: RMS = {c.rms:.4g}{perceived}, worst limit use "
          f"{c.worst_use:.4f}, {solver}, {result.timings['wall'] - compiling:.2f} s{compile_words(compiling)}"
          f"{ends}{sizing.describe(unreachable)}; written to {out}")
    print(f"  felt: {result.quality.headline()}")
    if result.prices is not None:
        print(f"  limit prices (felt error {result.prices.felt_error:.4g} m/s^2; its fall were a limit 10 % wider):")
        print("\n".join(f"    {line}" for line in result.prices.table()) or "    no limit binds")
    return 0 if result.converged else EXIT_NOT_CONVERGED


def run_batch(args) -> int:
    from desdemona.cueing.offline import OptimizeOptions
    from desdemona.runs import batch

    out = _claim_out(args)
    batch.check_out(out, args.overwrite)
    for name in args.configs:
        try:
            get_configuration(name)
        except ValueError as exc:
            raise UserError(str(exc)) from None
    for name in args.profiles:
        if name not in profiles.PROFILES and not os.path.isfile(name):
            profiles.load(name)  # raises with the list of built-in profiles, or file not found
    _check_starts(args, "processes", args.processes)
    params = load_params(args.params, base=args.base)
    options = OptimizeOptions(starts=args.starts, seed=args.seed)
    jobs = [batch.Job(p, c, view=args.view) for p in args.profiles for c in args.configs]
    begin = time.perf_counter()

    def progress(done, total, job):
        print(f"desdemona: job {done}/{total} done, {time.perf_counter() - begin:.1f} s: {job.profile} on "
              f"{job.config}: {job.status}", file=sys.stderr, flush=True)

    results = batch.run_batch(jobs, params, session.Choices.of(args), options, out, args.processes, args.dask,
                              progress=None if args.quiet else progress, overwrite=args.overwrite,
                              max_time=args.max_time)
    print(batch.table(results))
    if any(r.status not in ("ok", "not converged") for r in results):
        return EXIT_UNSAFE
    return 0 if all(r.status == "ok" for r in results) else EXIT_NOT_CONVERGED


def _felt_choices(args) -> dict:
    """``online``'s --perception, --rotation-band, --rotation-ceiling and --spin-weight as
    :func:`desdemona.runs.session.online` takes them."""
    choices = {}
    if args.perception is not None:
        choices["perception"] = None if args.perception == "none" else perception_models.get_model(args.perception)
    for name in ("rotation_band", "rotation_ceiling", "spin_weight"):
        value = getattr(args, name)
        if value is not None:
            try:
                choices[name] = None if value == "none" else float(value)
            except ValueError:
                what = "a weight" if name == "spin_weight" else "a number of perception thresholds"
                raise UserError(f"--{name.replace('_', '-')} {value!r}: {what}, or none") from None
    return choices


def run_online(args) -> int:
    from desdemona.check.metrics import joint_units
    from desdemona.control import online
    from desdemona.results import report

    model, path, out = _run_inputs(args)
    reference = None if args.reference is None else profiles.load(args.reference)
    forecast = _forecast(args, path)
    timing = {k: getattr(args, k) for k in ("replan", "delay", "deadline", "method", "tail_step")}
    resolved = session.online(path, model, session.Choices.of(args), horizon=args.horizon, reach=args.reach,
                              step=args.step, predictor=args.predictor, reference=reference, forecast=forecast,
                              **_felt_choices(args), **timing)
    path, options = resolved.path, resolved.options
    estimate = sizing.check_time_online(path, model.config, options.mpc, args.max_time)
    with OnlineProgress(path.duration, estimate=estimate) as progress, guard.reporting(None, tell=progress.say):
        result = online.run(path, model, options, progress=progress.cycle)
    unreachable = sizing.unreachable(path, model)
    report.write_online(result, out, report.command_line(), args.overwrite, unreachable=unreachable,
                        protect=_inputs(args), view=args.view, extra_summary=_shift(args))
    c, times, sources = result.check, result.loop.compute_times, result.loop.sources
    base = result.baseline_check
    classical = "" if base is None else f" (classical loop {base.rms:.4g})"
    if c.rms_perceived is not None:
        classical += f", perceived {c.rms_perceived:.4g}" + ("" if base is None else
                                                             f" (classical loop {base.rms_perceived:.4g})")
    modulus = ""
    if model.config.aligned:
        modulus = f", RMS(M - M_d) = {c.rms_modulus:.4g}"
        if result.baseline_check is not None:
            modulus += f" (classical loop {result.baseline_check.rms_modulus:.4g})"
    print(f"{path.name} on-line on {model.config.name}: RMS = {c.rms:.4g}{classical}{modulus}, worst limit use "
          f"{c.worst_use:.4f}, compute per cycle median {1e3 * np.median(times):.2f} ms, "
          f"p99 {1e3 * np.percentile(times, 99):.2f} ms, fallbacks {len(sources) - sources.count('mpc')}"
          f"{sizing.describe(unreachable)}; written to {out}")
    start = report.start_description(result)
    if any(start["q0"].values()) or any(start["qd0"].values()):
        units = joint_units(start["q0"])
        at = ", ".join(f"{name} {q:.3g} {unit}" + (f" at {qd:.3g} {unit}/s" if qd else "")
                       for (name, q), qd, unit in zip(start["q0"].items(), start["qd0"].values(), units))
        print(f"  started ({start['initial']}): {at}")
    print(f"  felt: {result.quality.headline()}")
    if result.baseline_quality is not None:
        print(f"  felt with the classical loop: {result.baseline_quality.headline()}")
    warning = fallback_warning(sources, result.loop.reasons, times, result.deadline)
    if warning:
        print(f"desdemona: warning: {warning}", file=sys.stderr)
    return 0


#: The share of an on-line run's cycles without a fresh plan above which the command warns.
FALLBACK_WARN = 0.05


def fallback_warning(sources, reasons, times, deadline: float) -> str:
    """A sentence for a run in which more than :data:`FALLBACK_WARN` of the cycles went without a fresh
    plan (``sources`` other than "mpc": the last plan kept, or the brake), why, and what gives the plans
    their time; "" for a run that planned as it should. ``times`` [s] per cycle, ``deadline`` [s]."""
    fallbacks = [reason for source, reason in zip(sources, reasons) if source != "mpc"]
    if len(fallbacks) <= FALLBACK_WARN * len(sources):
        return ""
    late = sum(reason.startswith("deadline missed") for reason in fallbacks)
    why = [f"deadline missed {late:,} times (median compute {1e3 * np.median(times):.3g} ms against "
           f"{1e3 * deadline:.4g} ms)"] if late else []
    others = collections.Counter(reason for reason in fallbacks if not reason.startswith("deadline missed"))
    why += [f"{reason} {count:,} times" for reason, count in others.most_common()]
    braked = sum(source == "brake" for source in sources)
    advice = (" A longer --deadline, a larger --step or a shorter --horizon gives the plans their time." if late
              else "")
    share = len(fallbacks) / len(sources)
    return (f"{len(fallbacks):,} of {len(sources):,} cycles ({100 * share:.0f} %) ran without a fresh plan, "
            f"{braked:,} of them on the brake: {', '.join(why)}. The felt figures are "
            f"{'mostly' if share > 0.5 else 'in part'} the fallbacks', not the plans'.{advice}")


def _forecast(args, path):
    """The forecast file of ``online --forecast``, read on the motion file's clock; None without one."""
    from desdemona.control import predictors
    from desdemona.profiles import forecast

    try:  # before the file is read
        predictors.check(args.predictor, False, args.reference is not None, args.forecast is not None)
    except ValueError as exc:
        raise UserError(str(exc)) from None
    if args.forecast is None:
        return None
    return forecast.read_forecast(args.forecast, path, origin=forecast.time_origin(args.profile))


def run_profiles(args) -> int:
    if (args.name is None) != (args.csv is None):
        raise UserError("give a built-in path and --csv FILE to write it, e.g. 'desdemona profiles catapult "
                        "--csv my-motion.csv'; or neither to list them")
    if args.name is not None:
        if args.name not in profiles.PROFILES:
            raise UserError(f"unknown built-in path {args.name!r}; one of: {', '.join(profiles.PROFILES)}")
        from desdemona.profiles import convert

        print(convert.write_path(args.csv, profiles.get_profile(args.name), overwrite=args.overwrite))
        return 0
    for name in profiles.PROFILES:
        path = profiles.get_profile(name)
        kind = "modulus only (dfs)" if path.S_d is None else "full path"
        print(f"{name:<22} {path.duration:5.1f} s  {kind:<18}  {path.description}")
    return 0


def run_import_jsbsim(args) -> int:
    from desdemona.profiles import convert, jsbsim

    if args.list:
        print("\n".join(jsbsim.shipped_scripts()))
        return 0
    if args.script is None:
        raise UserError("import jsbsim needs SCRIPT: a shipped script's name (see --list) or a script file")
    convert.check_out(args.out, args.overwrite)  # before the flight is flown
    path, comments = jsbsim.from_jsbsim(args.script, args.start, args.end, args.rate, args.modulus)
    _say_imported(convert.write_path(args.out, path, comments, args.overwrite), path, args.script, comments)
    return 0


#: How an off-line plan ends, for its printed line (``optimize --final``; "none" says nothing).
FINAL_WORDS = {"centre": ", ends still with the track and heave centred (--final centre)",
               "rest": ", ends still (--final rest)"}


def run_import_log(args) -> int:
    from desdemona.profiles import convert, log

    for given in (args.file, args.rates_file):
        if given is not None and files.same_file(given, args.out):
            raise UserError(f"--out {args.out}: is the log being read ({given}); choose another file")
    convert.check_out(args.out, args.overwrite)
    try:
        lever_arm = tuple(float(x) for x in args.lever_arm.split(","))
    except ValueError:
        raise UserError(f"--lever-arm {args.lever_arm!r}: give three numbers x,y,z in metres") from None
    names = lambda text: tuple(c.strip() for c in text.split(";" if ";" in text else ","))  # noqa: E731
    rates = None if args.rates.strip().lower() == "none" else names(args.rates)
    if rates is not None and args.rate_unit is None:
        raise UserError("--rate-unit deg/s or rad/s: the unit of the rate columns "
                        f"({','.join(rates)}); for a log without angular rates give --rates none (with --modulus)")
    fmt = log.LogFormat(args.time.strip(), names(args.accel), rates, args.accel_unit, args.rate_unit or "rad/s",
                        args.time_unit, names(args.axes), lever_arm, args.rates_file, args.inertial)
    path, comments = log.from_log(args.file, fmt, args.start, args.end, args.rate, args.modulus, args.check,
                                  args.to_g, args.zero_rates, args.level)
    _say_imported(convert.write_path(args.out, path, comments, args.overwrite), path, args.file, comments)
    return 0


def _say_imported(out: Path, path: profiles.DesiredPath, source=None, comments=()) -> None:
    """The imported path's line, and on stderr each of its ``warning:`` comments, named by ``source``."""
    peak = float(np.max(path.M_d)) / profiles.G
    print(f"{out}: {path.duration:.6g} s, {len(path.t)} samples, "
          f"{'modulus (t,M)' if path.S_d is None else 'six channels'}, "
          f"peak |f| {peak:.2f} g")
    for line in comments:
        if line.startswith("warning: "):
            print(f"{source}: {line}", file=sys.stderr)


def run_plot(args) -> int:
    from desdemona.results import figures, report, view

    report.refuse_batch_folder(args.folder, "plot")
    traj, summary = report.load(args.folder)
    try:
        drawn = figures.draw_result(traj, summary, args.folder)
        drawn += report.redraw_online(traj, summary, args.folder)
    except (KeyError, TypeError, IndexError) as exc:
        raise report.ReportError(f"{args.folder}: not a complete result folder: its summary.json or "
                                 f"trajectory.csv lacks {exc}") from None
    for figure in drawn:
        print(figure)
    print(view.write(args.folder))
    return 0


def run_view(args) -> int:
    from desdemona.results import view

    print(view.write(args.folder, args.out, args.overwrite))
    return 0


def run_compare(args) -> int:
    from desdemona.results import compare

    if not args.lag_window > 0:
        raise UserError("--lag-window must be positive")
    if args.out is not None:
        compare.check_out(_claim_out(args), args.overwrite)
    entries = compare.load_results(args.folders, perception_models.get_model(args.perception), args.lag_window)
    print(compare.table(entries))
    if args.out is not None:
        for written in compare.write(entries, args.out, args.overwrite):
            print(written)
    return 0

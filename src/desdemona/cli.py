"""The ``desdemona`` command: thin wrappers around the library, ``main(argv) -> exit code``."""

from __future__ import annotations

import argparse
import contextlib
import os
import signal
import sys
import time
from pathlib import Path

try:  # a Ctrl-C while the libraries load (a second or two) ends the command quietly, as later
    import numpy as np

    from desdemona import __version__, allocator, guard, profiles, session, sizing
    from desdemona import perception as perception_models
    from desdemona.configs import CONFIGURATIONS, get_configuration
    from desdemona.model import Model
    from desdemona.params import BUILTIN_SETS, ParameterError, load_params
except KeyboardInterrupt:
    print("desdemona: interrupted (SIGINT): stopped, nothing written", file=sys.stderr)
    raise SystemExit(128 + signal.SIGINT) from None

EXIT_USAGE = 2
EXIT_UNSAFE = 3  # no trajectory within every limit was found: nothing is written
EXIT_NOT_CONVERGED = 4  # a result within every limit is written, but the solver did not converge
EXIT_CODES = """exit codes:
  0    done: the result is written
  1    an unexpected error (a bug: please report it with the command)
  2    bad input (profile, CSV, parameters, options, --out), --out being written by another run, or a
       problem too large for this machine's memory; nothing is run and nothing is written
  3    no trajectory within every limit was found; nothing is written (batch: for some job)
  4    a result within every limit is written, but the solver stopped before converging (for example
       at its iteration cap): its status is in the printed line and summary.json ("converged": false)
       (batch: for some job, and no job ended with 3)
  130  interrupted by Ctrl-C (SIGINT), 143 by SIGTERM: stopped within a second or two, workers too;
       no partial result is written (batch: the jobs done by then are kept and listed in batch.csv)"""
SEE_EXIT_CODES = "Exit codes: 0 done, 2 bad input, 3 no safe trajectory, 4 not converged, 130 interrupted; " \
                 "see 'desdemona --help'."
PROGRESS_EVERY = 10.0  # [s] between progress lines inside a long solve (stderr not a terminal)


class UserError(Exception):
    """Bad input from the user: reported as one line on stderr with exit code 2."""


def main(argv: list[str] | None = None) -> int:
    parser = _parser()
    try:
        args = parser.parse_args(argv)
    except SystemExit as exc:  # argparse has printed its message (or --help): report, do not exit
        return int(exc.code or 0)
    except KeyboardInterrupt:
        print(f"desdemona: {guard.Interrupted(signal.SIGINT).message}", file=sys.stderr)
        return 128 + signal.SIGINT
    from desdemona.report import ReportError
    from desdemona.simulate import LimitViolation

    allocator.reuse_freed_memory()  # IPOPT's factorisations reuse their workspace (allocator.py)
    try:
        # args.held: the output folders this run holds (report.claim), released as it ends
        with guard.interruptible(), contextlib.ExitStack() as args.held:
            return args.run(args)
    except KeyboardInterrupt:  # a Ctrl-C before the guard was in place (or after it was removed)
        print(f"desdemona: {guard.Interrupted(signal.SIGINT).message}", file=sys.stderr)
        return 128 + signal.SIGINT
    except BrokenPipeError:  # the reader of stdout has gone (`| head`): the rest is not wanted
        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())  # nor a traceback at exit's flush
        return 0
    except (UserError, ParameterError, profiles.ProfileError, session.ChoiceError, ReportError,
            sizing.TooLarge) as exc:
        print(f"desdemona: error: {exc}", file=sys.stderr)
        return EXIT_USAGE
    except LimitViolation as exc:
        print(f"desdemona: no result written: {exc}", file=sys.stderr)
        return EXIT_UNSAFE
    except guard.Interrupted as exc:
        end_bar = "\n" if sys.stderr.isatty() else ""  # a progress bar may be half drawn
        print(f"{end_bar}desdemona: {exc.message}", file=sys.stderr)
        return exc.code


def _parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(
        prog="desdemona", epilog=EXIT_CODES, formatter_class=argparse.RawDescriptionHelpFormatter,
        description="Optimal motion cueing for the Desdemona simulator.")
    parser.add_argument("--version", action="version", version=f"desdemona {__version__}")
    sub = parser.add_subparsers(title="commands", required=True, metavar="COMMAND")

    model = sub.add_parser(
        "model", help="print the machine model of a configuration and one sample evaluation",
        description="Print the joints, limits and bodies of a configuration and evaluate the model "
                    "(path S, torques, power, inertia) at one sample state.")
    _add_machine_options(model)
    model.set_defaults(run=_run_model)

    opt = sub.add_parser(
        "optimize", epilog=SEE_EXIT_CODES, help="compute the best joint trajectory for a desired path (off-line)",
        description="Compute the joint trajectory that makes the cabin's path S follow the desired S_d as "
                    "closely as possible within every limit of the machine, check it independently on a "
                    "10x finer grid, and write a result folder: trajectory.csv, summary.json, "
                    "trajectory.mat and figures.")
    opt.add_argument("profile", metavar="PROFILE_OR_CSV",
                     help="a built-in profile (see 'desdemona profiles') or a CSV file with header "
                          "t,wx,wy,wz,fx,fy,fz (SI units) or t,M")
    _add_machine_options(opt, default_config="yaw-track-cabin")
    opt.add_argument("--out", required=True, metavar="DIR", help="result folder to create")
    opt.add_argument("--method", choices=("ipopt", "fatrop", "thesis"), default="ipopt",
                     help="ipopt or fatrop: our exact-derivative solver; thesis: the thesis' own "
                          "least-squares method, for comparison (default: ipopt)")
    opt.add_argument("--perception", choices=tuple(perception_models.MODELS), default=None,
                     help="minimise the perceived difference through this vestibular model")
    _add_start_options(opt, starts=4)
    _add_session_options(opt)
    opt.add_argument("--refine", action="store_true",
                     help="solve with the simplified dynamics (centres of mass at the frame origins) first, "
                          "then refine with the full dynamics (thesis 5.7)")
    opt.add_argument("--workers", type=int, default=1, metavar="N",
                     help="parallel processes for the starts (default: 1)")
    _add_overwrite_option(opt)
    opt.add_argument("--quiet", action="store_true",
                     help="no progress on stderr (default: a bar on a terminal, else a line per start)")
    _add_view_option(opt)
    opt.set_defaults(run=_run_optimize)

    batch = sub.add_parser(
        "batch", epilog=SEE_EXIT_CODES, help="optimise many profiles on many configurations, locally or on a Dask cluster",
        description="Run every PROFILE on every configuration of --configs, each into its own result folder "
                    "OUT/<profile>--<configuration>, and print a table of all jobs (also OUT/batch.csv). "
                    "Jobs run on local processes, or on a Dask distributed cluster given its scheduler.")
    batch.add_argument("profiles", nargs="+", metavar="PROFILE_OR_CSV")
    batch.add_argument("--configs", nargs="+", required=True, metavar="NAME",
                       help=f"configurations, from: {', '.join(CONFIGURATIONS)}")
    batch.add_argument("--out", required=True, metavar="DIR", help="folder for all the jobs' results")
    batch.add_argument("--params", metavar="FILE", help="TOML file overriding machine parameters")
    batch.add_argument("--base", choices=BUILTIN_SETS, default=None, help="built-in parameter set")
    _add_start_options(batch, starts=2)
    _add_session_options(batch, given=False)
    batch.add_argument("--processes", type=int, default=2, metavar="N",
                       help="local processes when no --dask is given (default: 2)")
    batch.add_argument("--dask", metavar="ADDRESS", default=None,
                       help="Dask scheduler address (tcp://host:8786): run the jobs on that cluster")
    batch.add_argument("--overwrite", action="store_true",
                       help="write into DIR if it is an earlier batch folder of desdemona (only its batch.csv "
                            "and result folders inside): its jobs' folders and batch.csv are replaced")
    batch.add_argument("--quiet", action="store_true", help="no line on stderr as each job ends")
    _add_view_option(batch)
    batch.set_defaults(run=_run_batch)

    online = sub.add_parser(
        "online", epilog=SEE_EXIT_CODES, help="run the on-line MPC in closed loop on a desired path",
        description="Simulate the on-line model predictive controller: at every step it sees only the "
                    "horizon ahead (through the predictor), plans, and commands the next step; a "
                    "failed or late plan falls back to the previous plan, then to braking. The whole "
                    "run is checked against every limit and written as a result folder with per-cycle "
                    "timings (cycles.csv) and figures.")
    online.add_argument("profile", metavar="PROFILE_OR_CSV")
    _add_machine_options(online, default_config="dfs")
    online.add_argument("--out", required=True, metavar="DIR")
    online.add_argument("--horizon", type=float, default=None, metavar="SECONDS",
                        help="T_h (default: 2 on dfs and dfs-yaw; 4 with the track, whose position is planned "
                             "further ahead; at most the path's duration)")
    online.add_argument("--reach", type=float, default=None, metavar="SECONDS",
                        help="how far each plan looks, at least T_h: beyond T_h, where nothing is known, the "
                             "path is taken as held at its last previewed value, an end cost that prices "
                             "where the plan leaves the machine (default: the larger of T_h and the default "
                             "horizon, so a 1 s horizon on dfs still plans 2 s; --reach equal to --horizon "
                             "for none, the thesis' K = 0)")
    online.add_argument("--step", type=float, default=0.02, metavar="SECONDS",
                        help="h: the plan's grid over the first 0.4 s of the horizon, and the period of the "
                             "commands (default: 0.02)")
    online.add_argument("--tail-step", type=float, default=0.1, metavar="SECONDS",
                        help="the plan's grid beyond the first 0.4 s of the horizon, 0 for --step throughout "
                             "(default: 0.1)")
    online.add_argument("--replan", type=float, default=None, metavar="SECONDS",
                        help="T_c: a new plan every T_c, a whole number of steps (default: every step)")
    online.add_argument("--delay", action="store_true",
                        help="simulate the computation time as the thesis does: a plan computed from the "
                             "state at t is applied from t + T_c (the thesis' setting: --horizon 1 --step 0.1 "
                             "--replan 0.4 --delay)")
    online.add_argument("--deadline", type=float, default=None, metavar="SECONDS",
                        help="compute budget per plan; a later plan is not used (default: T_c)")
    online.add_argument("--predictor", choices=("perfect", "hold", "linear", "route"), default="perfect",
                        help="how the future path is guessed from what is known now: the true future "
                             "(perfect), the present held (hold), extrapolated (linear), or from a "
                             "recording of the same course aligned to the live signal (route, needs "
                             "--reference) (default: perfect)")
    online.add_argument("--reference", metavar="PROFILE_OR_CSV", default=None,
                        help="with --predictor route: a recording of the course (same channels as the path)")
    online.add_argument("--initial", choices=session.ONLINE_STARTS, default=None,
                        help="the machine's state when the session starts: rest: still, where the first "
                             "plan wants it (default; the positions are chosen before the session from the "
                             "first horizon's preview, as optimize's rest chooses them; at home on dfs); "
                             "home: still, every joint at its centre; steady: trimmed to the "
                             "path's first sample, on dfs and dfs-yaw the arm already turning at the rate "
                             "of its modulus with the cabin aligned (a centrifuge spun up before its run, "
                             "as the thesis' on-line catapult of 7.5.1), elsewhere still with the cabin "
                             "tilted by tilt coordination of its force (at most 30 deg, where the gimbals "
                             "can tilt); given: the state of --initial-state (the default when it is given)")
    _add_initial_state_option(online)
    _add_cost_options(online)
    online.add_argument("--method", choices=("auto", "rti", "nlp"), default="auto",
                        help="rti: one QP per plan (fast); nlp: IPOPT to convergence; auto: rti when a "
                             "plan is made every step, nlp when --replan spans several steps, as the "
                             "thesis solves to convergence in its T_c (default: auto)")
    _add_overwrite_option(online)
    _add_view_option(online)
    online.set_defaults(run=_run_online)

    _add_import_parser(sub)

    prof = sub.add_parser("profiles", help="list the built-in desired paths, or write one to CSV",
                          description="List the built-in desired paths with a one-line description; with a "
                                      "NAME and --csv, write that path as a CSV file to edit or to start from "
                                      "(e.g. 'desdemona profiles catapult --csv my-motion.csv').")
    prof.add_argument("name", nargs="?", metavar="NAME", help="a built-in path to write (with --csv)")
    prof.add_argument("--csv", metavar="FILE", default=None,
                      help="write the path NAME to this CSV file (columns t,wx,wy,wz,fx,fy,fz or t,M, SI units, "
                           "its weights in a '# weights:' line)")
    prof.add_argument("--overwrite", action="store_true", help="replace FILE if it exists")
    prof.set_defaults(run=_run_profiles)

    plot = sub.add_parser("plot", help="re-draw the figures of a result folder",
                          description="Re-draw the PNG figures and view.html of a result folder from its "
                                      "trajectory.csv and summary.json.")
    plot.add_argument("folder", metavar="DIR")
    plot.set_defaults(run=_run_plot)

    show = sub.add_parser(
        "view", help="a 3D replay of a result in the browser: one self-contained HTML file",
        description="Write one HTML file that replays a result folder in 3D in any browser, from disk and "
                    "with no network: the arm, track, heave, gimbal rings and cabin moving as the "
                    "trajectory moves them, the felt and desired specific force as arrows at the head, "
                    "and beside it S against S_d, the felt direction and rotation against their "
                    "thresholds and each joint's use of its limits on one time cursor (an on-line "
                    "result's classical loop as a second, faded machine). Play, pause, scrub, speed "
                    "0.1x to 4x, orbit the camera (drag, wheel) or ride inside the cabin.")
    show.add_argument("folder", metavar="RESULT", help="a result folder (of optimize, online or batch)")
    show.add_argument("--out", metavar="FILE.html", default=None,
                      help="where to write it: a new .html file outside any result folder (default: "
                           "RESULT/view.html, the result's own page, replaced)")
    show.add_argument("--overwrite", action="store_true",
                      help="replace FILE.html if it is an earlier page of 'desdemona view' (never another file)")
    show.set_defaults(run=_run_view)

    cmp = sub.add_parser(
        "compare", help="judge result folders side by side: one table of quality metrics, overlay figures",
        description="Read result folders and print their quality metrics side by side (rows = metrics, "
                    "columns = folders): RMS, correlation and lag of S against S_d per channel, the felt "
                    "(perceived) error and its share of time above the perception thresholds, peak false "
                    "cues, jerk and acceleration sign changes per joint, joint rates at the start. The "
                    "metrics come from each folder's trajectory, so older folders compare too.")
    cmp.add_argument("folders", nargs="+", metavar="DIR", help="result folders (of optimize, online or batch)")
    cmp.add_argument("--out", metavar="DIR", default=None,
                     help="also write compare.csv and overlay figures (path, felt error, joint accelerations) here")
    cmp.add_argument("--overwrite", action="store_true",
                     help="write into DIR if it holds an earlier comparison of desdemona (only compare.csv and "
                          "its figures), replacing them")
    cmp.add_argument("--perception", choices=tuple(perception_models.MODELS), default="thesis",
                     help="vestibular model for the felt error (default: thesis)")
    cmp.add_argument("--lag-window", type=float, default=2.0, metavar="SECONDS", dest="lag_window",
                     help="largest delay searched for the lag (default: 2)")
    cmp.set_defaults(run=_run_compare)
    return parser


def _add_import_parser(sub) -> None:
    imp = sub.add_parser(
        "import", help="make a desired path CSV from a JSBSim flight or a logged motion",
        description="Make a desired path (CSV, t,wx,wy,wz,fx,fy,fz in the cabin frame: x right, y forward, "
                    "z up; SI) from a vehicle's motion, with '# source:' lines saying where it came from.")
    kinds = imp.add_subparsers(title="sources", required=True, metavar="SOURCE")
    js = kinds.add_parser(
        "jsbsim", help="a JSBSim flight: what the pilot feels",
        description="Run a JSBSim script (a shipped one by name, e.g. b737_runway_new, or a script file) as "
                    "fast as it computes and write what the pilot feels: the pilot station's specific force "
                    "and the body rates, turned into the cabin frame. Needs the jsbsim package: pip install "
                    "'desdemona[jsbsim]'. A flight above 20 g (a crash) or diverged (NaN) is refused. Without "
                    "--start the path starts where the flight is settled: after the script's first trim, "
                    "else after its start-up transient.")
    js.add_argument("script", nargs="?", metavar="SCRIPT", help="shipped script name or script file (.xml)")
    out_or_list = js.add_mutually_exclusive_group(required=True)  # --out, unless only --list
    out_or_list.add_argument("--list", action="store_true", help="list the shipped scripts and stop")
    _add_import_options(js, "sim time", out_or_list)  # --out right after --list: usage (--list | --out ...)
    js.add_argument("--rate", type=float, default=None, metavar="HZ",
                    help="samples per second of the path, through an anti-alias filter (default: 100; "
                         "JSBSim steps at 120)")
    js.set_defaults(run=_run_import_jsbsim)
    lg = kinds.add_parser(
        "log", help="a logged motion (IMU or simulator output, CSV)",
        description="Read a CSV log of accelerometer readings (specific force: +1 g up at rest, not kinematic "
                    "acceleration) and angular rates, in declared units and axes, into a desired path. Where "
                    "the log is still for 1 s the force must read +1 g up (the convention check).")
    lg.add_argument("file", metavar="FILE", help="CSV log, the first non-# line naming the columns")
    lg.add_argument("--time", default="t", metavar="COL", help="time column (default: t)")
    lg.add_argument("--accel", default="ax,ay,az", metavar="X,Y,Z",
                    help="accelerometer columns, the log's x,y,z (default: ax,ay,az)")
    lg.add_argument("--rates", default="p,q,r", metavar="X,Y,Z",
                    help="angular rate columns, the log's x,y,z (default: p,q,r)")
    lg.add_argument("--accel-unit", required=True, choices=("g", "m/s2"), dest="accel_unit")
    lg.add_argument("--rate-unit", required=True, choices=("deg/s", "rad/s"), dest="rate_unit")
    lg.add_argument("--time-unit", default="s", choices=("s", "ms"), dest="time_unit", help="(default: s)")
    lg.add_argument("--axes", default="forward,right,down", metavar="X,Y,Z",
                    help="direction of the log's x,y,z: each one of forward/back/right/left/up/down, "
                         "right-handed (default: forward,right,down, vehicle body axes)")
    lg.add_argument("--lever-arm", default="0,0,0", metavar="X,Y,Z", dest="lever_arm",
                    help="from the sensor to the head, the log's axes [m] (default: 0,0,0)")
    lg.add_argument("--rate", type=float, default=None, metavar="HZ",
                    help="samples per second of the path, through an anti-alias filter (default: the log's, "
                         "at most 100)")
    lg.add_argument("--no-check", action="store_false", dest="check",
                    help="skip the convention check (for a log that is nowhere still)")
    _add_import_options(lg, "the log's time")
    lg.set_defaults(run=_run_import_log)


def _add_import_options(parser: argparse.ArgumentParser, clock: str, out_group=None) -> None:
    """The options of every import; --out required, or in ``out_group`` (required: it or another)."""
    (out_group or parser).add_argument("--out", metavar="PATH.csv", required=out_group is None,
                                       help="the desired path CSV to write (required"
                                            + (")" if out_group is None else " unless --list)"))
    parser.add_argument("--start", type=float, default=None, metavar="SECONDS",
                        help=f"crop from here [s of {clock}]; it becomes t = 0 (default: the start)")
    parser.add_argument("--end", type=float, default=None, metavar="SECONDS",
                        help=f"crop to here [s of {clock}] (default: the end)")
    parser.add_argument("--modulus", action="store_true", help="write the dfs form t,M (M = |f|)")
    parser.add_argument("--overwrite", action="store_true", help="replace an existing --out file")


def _add_machine_options(parser: argparse.ArgumentParser, default_config: str = "full") -> None:
    parser.add_argument("--config", default=default_config, metavar="NAME",
                        help=f"configuration, one of: {', '.join(CONFIGURATIONS)} (default: {default_config})")
    parser.add_argument("--params", metavar="FILE",
                        help="TOML file overriding any subset of the machine parameters")
    parser.add_argument("--base", choices=BUILTIN_SETS, default=None,
                        help="built-in parameter set to start from (default: default)")


def _add_overwrite_option(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--overwrite", action="store_true",
                        help="replace DIR if it is an earlier result folder of desdemona (never another "
                             "folder, a file, or the current folder)")


def _add_start_options(parser: argparse.ArgumentParser, starts: int) -> None:
    parser.add_argument("--starts", type=int, default=starts, metavar="N",
                        help=f"initial guesses (default: {starts})")
    parser.add_argument("--seed", type=int, default=0, help="seed of the random starts (default: 0)")
    parser.add_argument("--h-u", type=float, default=0.05, metavar="SECONDS", dest="h_u",
                        help="control step: joint accelerations are held this long (default: 0.05)")


def _add_session_options(parser: argparse.ArgumentParser, given: bool = True) -> None:
    """How an off-line run starts and ends, and its cost (:func:`_add_cost_options`). The defaults are
    a real session's; ``--weights path --initial free --final none`` is the thesis' setting."""
    starts = session.OFFLINE_STARTS if given else session.OFFLINE_STARTS[:2]
    parser.add_argument("--initial", choices=starts, default=None,
                        help="rest: every joint still at t = 0, positions free (default); free: the "
                             "optimiser chooses positions and rates (thesis 5.2)"
                        + ("; given: the state of --initial-state" if given else ""))
    if given:
        _add_initial_state_option(parser)
    parser.add_argument("--final", choices=("centre", "rest", "none"), default="centre",
                        help="centre: at rest with the track and heave centred at the end (default); "
                             "rest: every joint still; none: free (thesis)")
    _add_cost_options(parser)


def _add_initial_state_option(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--initial-state", metavar="Q;QD", dest="initial_state", default=None,
                        help="positions and rates of the free joints in their order (see 'desdemona "
                             "model'), SI units (rad, m; rad/s, m/s), e.g. '0,-1.5,0;0,0,0' on "
                             "yaw-track-cabin (implies --initial given)")


def _add_cost_options(parser: argparse.ArgumentParser) -> None:
    """What the cost weighs and the motion gain: the choices of :class:`desdemona.session.Choices`
    that every command takes, resolved by :mod:`desdemona.session` alone."""
    parser.add_argument("--weights", default=None, metavar="SPEC",
                        help="the cost's weight per channel of S (diagonal of Q): felt (default): the path's "
                             "force weights, and rotation weighted by the perception thresholds so that one "
                             "threshold of false rotation costs as much as one of force error; path: the "
                             "path's own (the thesis'; a CSV's '# weights:' line or 1 each; the default on "
                             "dfs, whose arm turns to make the force: a modulus path weighs its rotation "
                             "at 0.1); thresholds: every channel by 1/threshold^2; or six numbers "
                             "wx,wy,wz,fx,fy,fz")
    parser.add_argument("--gain", type=float, default=1.0, metavar="G",
                        help="motion gain around 1 g: f_d -> (0,0,g) + G (f_d - (0,0,g)), omega_d -> G "
                             "omega_d (default: 1)")
    parser.add_argument("--jerk-weight", type=float, default=None, metavar="RHO", dest="jerk_weight",
                        help="the jerk's weight in the cost, against its limit: higher makes the joints "
                             "reverse their accelerations less, at some cost in the cue (default: 5 "
                             "off-line and 3 on-line on dfs, 1 elsewhere)")


def _machine(args) -> Model:
    try:
        config = get_configuration(args.config)
    except ValueError as exc:
        raise UserError(str(exc)) from None
    return Model(load_params(args.params, base=args.base), config)


def _run_model(args) -> int:
    model = _machine(args)
    print(describe(model))
    return 0


def _inputs(args) -> tuple:
    """The files a run reads: a replaced result folder must not hold them."""
    return tuple(p for p in (args.profile, args.params) if p is not None and os.path.exists(p))


def _claim_out(args) -> Path:
    """``args.out``, checked to be creatable and held for this run (:func:`desdemona.report.claim`)
    until it ends: a second run on the same folder is refused."""
    from desdemona import report

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
    from desdemona import report

    model = _machine(args)
    path = profiles.load(args.profile)
    out = _claim_out(args)
    if out.exists() and not args.overwrite:
        raise UserError(f"{out}: already exists; choose another folder or add --overwrite")
    report.check_replaceable(out, protect=_inputs(args))
    return model, path, out


def _run_optimize(args) -> int:
    from desdemona import report
    from desdemona.thesis import ThesisOptions
    from desdemona.offline import OptimizeOptions, optimize, thesis_result

    model, path, out = _run_inputs(args)
    if args.starts < 1 or args.workers < 1:
        raise UserError("--starts and --workers must be at least 1")
    choices = session.Choices.of(args)
    if args.method == "thesis":
        resolved = session.thesis(path, model, choices)
    else:
        perception = perception_models.get_model(args.perception) if args.perception else None
        resolved = session.offline(path, model, choices, args.method, perception, args.workers)
    path, problem, size = resolved.path, resolved.options, resolved.size
    unreachable = sizing.unreachable(path, model)
    progress = None if args.quiet else _Progress(args.starts, size, path, model.config)
    with guard.reporting(None if progress is None else progress.solving, PROGRESS_EVERY):
        if args.method == "thesis":
            result = thesis_result(path, model, ThesisOptions(h_u=problem.h_u, starts=args.starts, seed=args.seed))
        else:
            options = OptimizeOptions(problem, starts=args.starts, seed=args.seed, workers=args.workers,
                                      refine=args.refine)
            result = optimize(path, model, options, progress=None if progress is None else progress.start_done)
    report.write(result, out, command=report.command_line(), overwrite=args.overwrite, unreachable=unreachable,
                 protect=_inputs(args), view=args.view)
    c = result.check
    perceived = f" (perceived {c.rms_perceived:.4g})" if c.rms_perceived is not None else ""
    if model.config.aligned:
        perceived += f", RMS(M - M_d) = {c.rms_modulus:.4g}"
    solver = f"solver {result.solution.status}" + ("" if result.converged else " (NOT CONVERGED)")
    print(f"{path.name} on {model.config.name}: RMS = {c.rms:.4g}{perceived}, worst limit use "
          f"{c.worst_use:.4f}, {solver}, {result.timings['wall']:.2f} s{sizing.describe(unreachable)}; "
          f"written to {out}")
    print(f"  felt: {result.quality.headline()}")
    return 0 if result.converged else EXIT_NOT_CONVERGED


class _Progress:
    """Progress of an off-line run on stderr: a bar on a terminal; else (a log file, a CI job) a line
    when the run starts, one per finished start with the elapsed time and the best cost so far, and one
    every PROGRESS_EVERY seconds inside a long solve."""

    def __init__(self, starts: int, size: sizing.Size, path, config):
        self.begin = time.perf_counter()
        self.tty = sys.stderr.isatty()
        if not self.tty:
            self._say(f"{path.name} on {config.name}: {size.intervals:,} control intervals, {size.variables:,} "
                      f"variables, {starts} start{'s' if starts > 1 else ''}")

    def _say(self, text: str) -> None:
        print(f"desdemona: {text}", file=sys.stderr, flush=True)

    def start_done(self, done: int, total: int, best: float) -> None:
        if self.tty:
            bar = "#" * done + "." * (total - done)
            print(f"\r  starts [{bar}] {done}/{total}", end="" if done < total else "\n", file=sys.stderr,
                  flush=True)
        else:
            self._say(f"start {done}/{total} done, {time.perf_counter() - self.begin:.1f} s, best cost so far {best:.6g}")

    def solving(self, iteration: int, cost: float, seconds: float) -> None:
        if not self.tty:
            self._say(f"  solving: iteration {iteration}, cost {cost:.6g}, {seconds:.0f} s in this start, "
                      f"{time.perf_counter() - self.begin:.1f} s in all")


def _run_batch(args) -> int:
    from desdemona import batch
    from desdemona.offline import OptimizeOptions

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
    if args.starts < 1 or args.processes < 1:
        raise UserError("--starts and --processes must be at least 1")
    params = load_params(args.params, base=args.base)
    options = OptimizeOptions(starts=args.starts, seed=args.seed)
    jobs = [batch.Job(p, c, view=args.view) for p in args.profiles for c in args.configs]
    begin = time.perf_counter()

    def progress(done, total, job):
        print(f"desdemona: job {done}/{total} done, {time.perf_counter() - begin:.1f} s: {job.profile} on "
              f"{job.config}: {job.status}", file=sys.stderr, flush=True)

    results = batch.run_batch(jobs, params, session.Choices.of(args), options, out, args.processes, args.dask,
                              progress=None if args.quiet else progress, overwrite=args.overwrite)
    print(batch.table(results))
    if any(r.status not in ("ok", "not converged") for r in results):
        return EXIT_UNSAFE
    return 0 if all(r.status == "ok" for r in results) else EXIT_NOT_CONVERGED


def _run_online(args) -> int:
    from desdemona import online, report
    from desdemona.metrics import joint_units

    model, path, out = _run_inputs(args)
    reference = None if args.reference is None else profiles.load(args.reference)
    timing = {k: getattr(args, k) for k in ("replan", "delay", "deadline", "method", "tail_step")}
    resolved = session.online(path, model, session.Choices.of(args), horizon=args.horizon, reach=args.reach,
                              step=args.step, predictor=args.predictor, reference=reference, **timing)
    path, options = resolved.path, resolved.options
    result = online.run(path, model, options)
    unreachable = sizing.unreachable(path, model)
    report.write_online(result, out, report.command_line(), args.overwrite, unreachable=unreachable,
                        protect=_inputs(args), view=args.view)
    c, times, sources = result.check, result.loop.compute_times, result.loop.sources
    classical = "" if result.baseline_check is None else f" (classical loop {result.baseline_check.rms:.4g})"
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
    return 0


def _run_profiles(args) -> int:
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


def _run_import_jsbsim(args) -> int:
    from desdemona.profiles import convert, jsbsim

    if args.list:
        print("\n".join(jsbsim.shipped_scripts()))
        return 0
    if args.script is None:
        raise UserError("import jsbsim needs SCRIPT: a shipped script's name (see --list) or a script file")
    convert.check_out(args.out, args.overwrite)  # before the flight is flown
    path, comments = jsbsim.from_jsbsim(args.script, args.start, args.end, args.rate, args.modulus)
    _say_imported(convert.write_path(args.out, path, comments, args.overwrite), path)
    return 0


def _run_import_log(args) -> int:
    from desdemona.profiles import convert, log

    convert.check_out(args.out, args.overwrite)
    try:
        lever_arm = tuple(float(x) for x in args.lever_arm.split(","))
    except ValueError:
        raise UserError(f"--lever-arm {args.lever_arm!r}: give three numbers x,y,z in metres") from None
    names = lambda text: tuple(c.strip() for c in text.split(","))  # noqa: E731
    fmt = log.LogFormat(args.time.strip(), names(args.accel), names(args.rates), args.accel_unit, args.rate_unit,
                        args.time_unit, names(args.axes), lever_arm)
    path, comments = log.from_log(args.file, fmt, args.start, args.end, args.rate, args.modulus, args.check)
    _say_imported(convert.write_path(args.out, path, comments, args.overwrite), path)
    return 0


def _say_imported(out: Path, path: profiles.DesiredPath) -> None:
    peak = float(np.max(path.M_d)) / profiles.G
    print(f"{out}: {path.duration:.6g} s, {len(path.t)} samples, "
          f"{'modulus (t,M)' if path.S_d is None else 'six channels'}, "
          f"peak |f| {peak:.2f} g")


def _run_plot(args) -> int:
    from desdemona import figures, report, view

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


def _run_view(args) -> int:
    from desdemona import view

    print(view.write(args.folder, args.out, args.overwrite))
    return 0


def _add_view_option(parser) -> None:
    parser.add_argument("--no-view", action="store_false", dest="view",
                        help="do not write view.html (the 3D replay, see 'desdemona view') into the result folder")


def _run_compare(args) -> int:
    from desdemona import compare

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


def describe(model: Model) -> str:
    """A human-readable summary of a model and its values at one sample state."""
    p, c = model.params, model.config
    lines = [f"Desdemona model: parameters '{p.name}', configuration '{c.name}'",
             f"  {c.description}",
             f"  gravity {p.gravity:g} m/s^2, head offset {list(p.head_offset)} m (cabin coordinates)",
             "", "Joints (limits; * = free in this configuration):",
             f"  {'':2}{'joint':<14}{'position':>18}{'velocity':>14}{'acceleration':>16}"
             f"{'force/torque':>16}{'power':>12}"]
    for i, j in enumerate(p.joints):
        rev = j.kind == "revolute"
        scale, unit = (180.0 / np.pi, "deg") if rev else (1.0, "m")
        if j.position is None:
            pos = "unbounded"
        else:
            pos = f"[{j.position[0] * scale:g}, {j.position[1] * scale:g}] {unit}"
        held = "" if i in c.free else f"  held at {c.fixed[i] * scale:g} {unit}"
        lines.append(
            f"  {'*' if i in c.free else ' '} q{i + 1} {j.name:<11}{pos:>18}"
            f"{f'{j.velocity * scale:.4g} {unit}/s':>14}{f'{j.acceleration * scale:.4g} {unit}/s2':>16}"
            f"{f'{j.effort / 1e3:.4g} ' + ('kN*m' if rev else 'kN'):>16}{f'{j.power / 1e3:.4g} kW':>12}{held}")
    lines += ["", "Bodies:"]
    for b in p.bodies:
        lines.append(f"  {b.name:<15} {b.mass:8g} kg  com {list(b.com)} m  "
                     f"inertia diag {[round(b.inertia[k][k], 6) for k in range(3)]} kg*m^2")
    # A sample state: every free joint moving at a third of its velocity and acceleration limits.
    lim = model.limits
    q = np.where(np.isfinite(lim.position_max), 0.5 * lim.position_max, 0.3)
    qd, qdd = lim.velocity / 3.0, lim.acceleration / 3.0
    S = model.S(q, qd, qdd)
    tau = model.tau(q, qd, qdd)
    power = model.power(q, qd, qdd)
    eig = np.linalg.eigvalsh(model.mass_matrix(q))
    fmt = lambda v: "[" + ", ".join(f"{x:.4g}" for x in v) + "]"  # noqa: E731
    lines += ["", "Sample state (free joints at 1/3 of their rate and acceleration limits):",
              f"  q    = {fmt(q)}", f"  qd   = {fmt(qd)}", f"  qdd  = {fmt(qdd)}",
              f"  omega_cabin = {fmt(S[:3])} rad/s",
              f"  f_cabin     = {fmt(S[3:])} m/s^2   |f| = {np.linalg.norm(S[3:]):.4g} m/s^2",
              f"  tau         = {fmt(tau)}   (use {fmt(np.abs(tau) / lim.effort)} of the limits)",
              f"  power       = {fmt(power)} W (use {fmt(np.abs(power) / lim.power)} of the limits)",
              f"  inertia eigenvalues = {fmt(eig)}"]
    return "\n".join(lines)


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())

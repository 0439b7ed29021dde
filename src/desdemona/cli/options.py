"""The table of the ``desdemona`` command's subcommands and options (``argparse``), each pointing to
what runs it in :mod:`desdemona.cli.commands`."""

from __future__ import annotations

import argparse
import difflib

from desdemona._version import __version__
from desdemona.cli import commands, serviceoptions, serving, studying
from desdemona.cli.exits import EXIT_CODES, SEE_EXIT_CODES
from desdemona.control import predictors
from desdemona.machine.configs import CONFIGURATIONS
from desdemona.machine.params import BUILTIN_SETS
from desdemona.occupant import perception as perception_models
from desdemona.runs import session


class _Parser(argparse.ArgumentParser):
    """A parser that takes no abbreviation of an option (``--conf`` is not ``--config``) and refuses an
    argument it does not know itself, so that a command's misspelt option gets that command's usage and
    the nearest option's name, not the top-level usage."""

    def __init__(self, *args, **kwargs):
        kwargs.setdefault("allow_abbrev", False)
        super().__init__(*args, **kwargs)

    def parse_known_args(self, args=None, namespace=None):
        namespace, extra = super().parse_known_args(args, namespace)
        if extra:
            known = [o for action in self._actions for o in action.option_strings]
            near = difflib.get_close_matches(extra[0].split("=")[0], known, n=1, cutoff=0.75) if extra[0].startswith("-") else []
            self.error(f"unrecognized arguments: {' '.join(extra)}" + (f" (did you mean {near[0]}?)" if near else ""))
        return namespace, extra


def build_parser() -> argparse.ArgumentParser:
    parser = _Parser(
        prog="desdemona", epilog=EXIT_CODES, formatter_class=argparse.RawDescriptionHelpFormatter,
        description="Optimal motion cueing for the Desdemona simulator.")
    parser.add_argument("--version", action="version", version=f"desdemona {__version__}")
    sub = parser.add_subparsers(title="commands", required=True, metavar="COMMAND")

    model = sub.add_parser(
        "model", help="print the machine model of a configuration and one sample evaluation",
        description="Print the joints, limits and bodies of a configuration and evaluate the model "
                    "(path S, torques, power, inertia) at one sample state.")
    _add_machine_options(model)
    model.set_defaults(run=commands.run_model)

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
    opt.add_argument("--method", choices=("auto", "ipopt", "fatrop", "thesis"), default="auto",
                     help="ipopt or fatrop: our exact-derivative solver; auto: fatrop on yaw-track-cabin, "
                          "full and dfs (a path of more than 1200 intervals, 60 s at the default step, in "
                          "windows), ipopt elsewhere; "
                          "thesis: the thesis' own least-squares method, for comparison (default: auto)")
    opt.add_argument("--perception", choices=tuple(perception_models.MODELS), default=None,
                     help="minimise the perceived difference through this vestibular model")
    _add_start_options(opt, starts=4)
    _add_session_options(opt)
    opt.add_argument("--refine", action="store_true",
                     help="solve with the simplified dynamics (centres of mass at the frame origins) first, "
                          "then refine with the full dynamics (thesis 5.7)")
    opt.add_argument("--workers", type=int, default=None, metavar="N",
                     help="parallel processes for the starts (default: one per core, at most one per start, "
                          "as many as fit in memory)")
    _add_overwrite_option(opt)
    _add_time_option(opt)
    opt.add_argument("--quiet", action="store_true",
                     help="no progress on stderr (default: a bar on a terminal, else a line per start)")
    _add_view_option(opt)
    opt.set_defaults(run=commands.run_optimize)

    batch = sub.add_parser(
        "batch", epilog=SEE_EXIT_CODES, help="optimise many profiles on many configurations, locally or on a Dask cluster",
        description="Run every PROFILE on every configuration of --configs, each into its own result folder "
                    "OUT/<profile>--<configuration>, and print a table of all jobs (also OUT/batch.csv). "
                    "Jobs run on local processes, or on a Dask distributed cluster given its scheduler.")
    batch.add_argument("profiles", nargs="+", metavar="PROFILE_OR_CSV",
                       help="built-in profiles (see 'desdemona profiles') or CSV files of desired paths, "
                            "as optimize takes them; each runs on every configuration of --configs")
    batch.add_argument("--configs", nargs="+", required=True, metavar="NAME",
                       help=f"configurations, from: {', '.join(CONFIGURATIONS)}")
    batch.add_argument("--out", required=True, metavar="DIR", help="folder for all the jobs' results")
    batch.add_argument("--params", metavar="FILE", help="TOML file overriding machine parameters")
    batch.add_argument("--base", choices=BUILTIN_SETS, default=None, help="built-in parameter set")
    _add_start_options(batch, starts=2, why=": half of optimize's 4, as a batch's processes go to its jobs and "
                                             "each job's starts run one after the other; --starts 4 searches as "
                                             "optimize does, in twice the time")
    _add_session_options(batch, given=False)
    batch.add_argument("--processes", type=int, default=2, metavar="N",
                       help="local processes when no --dask is given (default: 2)")
    batch.add_argument("--dask", metavar="ADDRESS", default=None,
                       help="Dask scheduler address (tcp://host:8786): run the jobs on that cluster")
    batch.add_argument("--overwrite", action="store_true",
                       help="write into DIR if it is an earlier batch folder of desdemona (only its batch.csv "
                            "and result folders inside): its jobs' folders and batch.csv are replaced")
    batch.add_argument("--quiet", action="store_true", help="no line on stderr as each job ends")
    _add_time_option(batch, "each job")
    _add_view_option(batch)
    batch.set_defaults(run=commands.run_batch)
    studying.add_parser(sub, _add_start_options, _add_session_options, _add_time_option)

    online = sub.add_parser(
        "online", epilog=SEE_EXIT_CODES, help="run the on-line MPC in closed loop on a desired path",
        description="Simulate the on-line model predictive controller: at every step it sees only the "
                    "horizon ahead (through the predictor), plans, and commands the next step; a "
                    "failed or late plan falls back to the previous plan, then to braking. The whole "
                    "run is checked against every limit and written as a result folder with per-cycle "
                    "timings (cycles.csv) and figures.")
    online.add_argument("profile", metavar="PROFILE_OR_CSV",
                        help="a built-in profile (see 'desdemona profiles') or a CSV file of the desired path, "
                             "as optimize takes it")
    _add_machine_options(online, default_config="dfs")
    _add_time_option(online)
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
                        help="the plan's grid beyond the first 0.4 s of the horizon (on full twice that beyond "
                             "2 s), 0 for --step throughout (default: 0.1)")
    online.add_argument("--replan", type=float, default=None, metavar="SECONDS",
                        help="T_c: a new plan every T_c, a whole number of steps (default: every step)")
    online.add_argument("--delay", action="store_true",
                        help="simulate the computation time as the thesis does: a plan computed from the "
                             "state at t is applied from t + T_c (the thesis' setting: --horizon 1 --step 0.1 "
                             "--replan 0.4 --delay)")
    online.add_argument("--deadline", type=float, default=None, metavar="SECONDS",
                        help="compute budget per plan; a later plan is not used (default: T_c)")
    online.add_argument("--predictor", choices=predictors.names(), default="perfect",
                        help=f"how the future path is guessed from what is known now: {predictors.describe()} "
                             "(default: perfect)")
    online.add_argument(predictors.REFERENCE.option, metavar=predictors.REFERENCE.metavar, default=None,
                        help=f"with --predictor {' or '.join(predictors.users(predictors.REFERENCE))}: "
                             f"{predictors.REFERENCE.what}")
    online.add_argument(predictors.FORECAST.option, metavar=predictors.FORECAST.metavar, default=None,
                        help=f"with --predictor {' or '.join(predictors.users(predictors.FORECAST))}: the "
                             "vehicle's forecasts, a CSV file with columns "
                             "t0,t,wx,wy,wz,fx,fy,fz (or t0,t,M, as the path): for each issue time t0, the "
                             "forecast samples from t = t0 on, times on the motion file's clock "
                             "(docs/guide/online.md#predictors)")
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
    online.add_argument("--perception", choices=(*perception_models.MODELS, "none"), default=None,
                        help="minimise the perceived difference through this vestibular model, and report "
                             "the perceived error of the controller and of the classical loop (default: "
                             "canals, the canals' adaptation alone; none on dfs-yaw, whose cost is the modulus)")
    online.add_argument("--rotation-band", default=None, metavar="THRESHOLDS", dest="rotation_band",
                        help="with a perception model: a felt rotation beyond this many perception "
                             "thresholds weighs ten times its weight, so the plan uses rotation the "
                             "occupant hardly feels; none: no band (default: 1; 5 on dfs, whose arm "
                             "must spin up for any force above g)")
    online.add_argument("--rotation-ceiling", default=None, metavar="THRESHOLDS", dest="rotation_ceiling",
                        help="with a perception model: the felt rotation's error beyond this many perception "
                             "thresholds weighs 110 times its weight (100 on top of the band's 10), a soft "
                             "ceiling: the arm spins up no faster than felt as that much false rotation; "
                             "none: no ceiling (default: 20)")
    online.add_argument("--spin-weight", default=None, metavar="W", dest="spin_weight",
                        help="with a perception model: the weight of the cabin's spin about the occupant's "
                             "vertical as it is, a share of the yaw channel's: the canals stop feeling a "
                             "steady spin, and without this a plan may keep one for minutes; none: 0 "
                             "(default: 0.1 on dfs, none elsewhere)")
    online.add_argument("--method", choices=("auto", "rti", "nlp"), default="auto",
                        help="rti: one QP per plan (fast); nlp: IPOPT to convergence; auto: rti when a "
                             "plan is made every step, nlp when --replan spans several steps, as the "
                             "thesis solves to convergence in its T_c (default: auto)")
    _add_overwrite_option(online)
    _add_view_option(online)
    online.set_defaults(run=commands.run_online)

    _add_import_parser(sub)

    _add_serve_parser(sub)
    _add_machine_parser(sub)
    _add_host_parser(sub)

    prof = sub.add_parser("profiles", help="list the built-in desired paths, or write one to CSV",
                          description="List the built-in desired paths with a one-line description; with a "
                                      "NAME and --csv, write that path as a CSV file to edit or to start from "
                                      "(e.g. 'desdemona profiles catapult --csv my-motion.csv').")
    prof.add_argument("name", nargs="?", metavar="NAME", help="a built-in path to write (with --csv)")
    prof.add_argument("--csv", metavar="FILE", default=None,
                      help="write the path NAME to this CSV file (columns t,wx,wy,wz,fx,fy,fz or t,M, SI units, "
                           "its weights in a '# weights:' line)")
    prof.add_argument("--overwrite", action="store_true", help="replace FILE if it exists")
    prof.set_defaults(run=commands.run_profiles)

    plot = sub.add_parser("plot", help="re-draw the figures of a result folder",
                          description="Re-draw the PNG figures and view.html of a result folder from its "
                                      "trajectory.csv and summary.json.")
    plot.add_argument("folder", metavar="DIR", help="a result folder (of optimize, online, serve or a batch's "
                                                  "job); its figures are drawn again in it")
    plot.set_defaults(run=commands.run_plot)

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
    show.set_defaults(run=commands.run_view)

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
    cmp.set_defaults(run=commands.run_compare)
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
    js.set_defaults(run=commands.run_import_jsbsim)
    lg = kinds.add_parser(
        "log", help="a logged motion (IMU or simulator output, CSV)",
        description="Read a CSV log of accelerometer readings (specific force: +1 g up at rest, not kinematic "
                    "acceleration) and angular rates, in declared units and axes, into a desired path. Where "
                    "the log is still for 1 s the force must read +1 g up (the convention check). A log of "
                    "accelerometer readings alone (--rates none) gives the modulus form for dfs (--modulus), "
                    "in whatever axes; where it is still the force must read 1 g.")
    lg.add_argument("file", metavar="FILE", help="CSV log, the first non-# line naming the columns")
    lg.add_argument("--time", default="t", metavar="COL", help="time column (default: t)")
    lg.add_argument("--accel", default="ax,ay,az", metavar="X,Y,Z",
                    help="accelerometer columns, the log's x,y,z (default: ax,ay,az); names that hold a comma "
                         "(X-Plane's 'Gload,axial') separated by ';'")
    lg.add_argument("--rates", default="p,q,r", metavar="X,Y,Z",
                    help="angular rate columns, the log's x,y,z (default: p,q,r), or separated by ';'; none "
                         "for a log without them (with --modulus)")
    lg.add_argument("--rates-file", default=None, metavar="FILE", dest="rates_file",
                    help="a second CSV log holding the --rates columns, on the same clock (a phone logger's "
                         "gyroscope file beside its accelerometer's); its rates are interpolated onto FILE's "
                         "times, over the span both cover")
    lg.add_argument("--accel-unit", required=True, choices=("g", "m/s2"), dest="accel_unit")
    lg.add_argument("--inertial", action="store_true",
                    help="the accelerometer columns hold the inertial force, -1 g up at rest (an iPhone's Core "
                         "Motion; Sensor Logger on an iPhone unless 'Standardise Units & Frames' is on): "
                         "their sign is turned")
    lg.add_argument("--rate-unit", choices=("deg/s", "rad/s"), dest="rate_unit",
                    help="the unit of the --rates columns (required unless --rates none)")
    lg.add_argument("--time-unit", choices=("s", "ms", "us", "ns"), dest="time_unit",
                    help="(default: s; ns for a dataset's nanosecond stamps, EuRoC's or ROS's; a column of "
                         "ISO 8601 dates and times, 2023-08-04 17:47:58-04:00, is read as such; a clock "
                         "that steps 0.5 s or more is taken for milliseconds unless it reads a date or s "
                         "is declared, up to a step of 2 s)")
    lg.add_argument("--axes", default="forward,right,down", metavar="X,Y,Z",
                    help="direction of the log's x,y,z: each one of forward/back/right/left/up/down, "
                         "right-handed (default: forward,right,down, vehicle body axes)")
    lg.add_argument("--lever-arm", default="0,0,0", metavar="X,Y,Z", dest="lever_arm",
                    help="from the sensor to the head, the log's axes [m] (default: 0,0,0)")
    lg.add_argument("--rate", type=float, default=None, metavar="HZ",
                    help="samples per second of the path, through an anti-alias filter (default: the log's, "
                         "at least 10, interpolated, and at most 100)")
    lg.add_argument("--no-check", action="store_false", dest="check",
                    help="skip the convention check (for a log that is nowhere still)")
    lg.add_argument("--to-g", action="store_true", dest="to_g",
                    help="scale the accelerometer readings so that the still stretch the check finds reads 1 g "
                         "(a sensor whose scale is off, as a phone's can be by 5-10 %%; a reading outside "
                         "0.8-1.25 g is refused as a wrong unit or scale)")
    lg.add_argument("--zero-rates", action="store_true", dest="zero_rates",
                    help="subtract from every rate its mean over the log's first still stretch (a gyro's bias, up "
                         "to 10 deg/s: a MEMS gyro reads a few deg/s at rest, which would be cued as a turn)")
    lg.add_argument("--level", action="store_true",
                    help="turn forces and rates by the smallest rotation that makes the force read straight up "
                         "where the log is still (a sensor mounted at an angle to the vehicle, up to 60 deg; "
                         "without it the check takes 30 deg, a vehicle on a slope)")
    _add_import_options(lg, "the log's time; on a clock from 1970, seconds on that clock, or a date and time "
                            "as the log's")
    lg.set_defaults(run=commands.run_import_log)


def _add_import_options(parser: argparse.ArgumentParser, clock: str, out_group=None) -> None:
    """The options of every import; --out required, or in ``out_group`` (required: it or another)."""
    (out_group or parser).add_argument("--out", metavar="PATH.csv", required=out_group is None,
                                       help="the desired path CSV to write (required"
                                            + (")" if out_group is None else " unless --list)"))
    parser.add_argument("--start", type=_time_or_date, default=None, metavar="SECONDS",
                        help=f"crop from here [s of {clock}]; it becomes t = 0 (default: the start)")
    parser.add_argument("--end", type=_time_or_date, default=None, metavar="SECONDS",
                        help=f"crop to here [s of {clock}] (default: the end)")
    parser.add_argument("--modulus", action="store_true", help="write the dfs form t,M (M = |f|)")
    parser.add_argument("--overwrite", action="store_true", help="replace an existing --out file")


def _time_or_date(text: str) -> float:
    """A time [s], or an ISO 8601 date and time as seconds since 1970 (a log stamped with dates)."""
    from desdemona.profiles.clock import date_seconds

    try:
        return float(text)
    except ValueError:
        seconds = date_seconds(text)
        if seconds is None:
            raise argparse.ArgumentTypeError(f"{text!r}: give seconds, or a date and time as the log's "
                                             f"(2023-08-04 17:47:58-04:00)") from None
        return seconds


def _add_machine_options(parser: argparse.ArgumentParser, default_config: str = "full") -> None:
    parser.add_argument("--config", default=default_config, metavar="NAME",
                        help=f"configuration, one of: {', '.join(CONFIGURATIONS)} (default: {default_config})")
    parser.add_argument("--params", metavar="FILE",
                        help="TOML file overriding any subset of the machine parameters")
    parser.add_argument("--base", choices=BUILTIN_SETS, default=None,
                        help="built-in parameter set to start from (default: default)")


def _add_time_option(parser: argparse.ArgumentParser, what: str = "the run") -> None:
    parser.add_argument("--max-time", type=float, default=None, metavar="SECONDS",
                        help=f"how long {what} may take, as estimated before it starts from figures measured "
                             "per interval and cycle; one estimated to take longer is refused with the step "
                             "that fits (default: 20 times the path's duration, at least 60 s)")


def _add_overwrite_option(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--overwrite", action="store_true",
                        help="replace DIR if it is an earlier result folder of desdemona (never another "
                             "folder, a file, or the current folder)")


def _add_start_options(parser: argparse.ArgumentParser, starts: int, why: str = "") -> None:
    parser.add_argument("--starts", type=int, default=starts, metavar="N",
                        help=f"initial guesses, at most 100 (default: {starts}{why})")
    parser.add_argument("--seed", type=int, default=0, help="seed of the random starts (default: 0)")
    parser.add_argument("--h-u", type=float, default=0.05, metavar="SECONDS", dest="h_u",
                        help="control step: joint accelerations are held this long (default: 0.05)")
    parser.add_argument("--window", type=float, default=None, metavar="SECONDS",
                        help="solve in overlapping windows this long, each starting from the state the one "
                             "before reached, the whole re-checked; memory is bounded by the window. 0: the "
                             "whole path at once (default: windows of 30 s for paths over 150 s, over 60 s on "
                             "yaw-track-cabin, full and dfs with --method auto)")


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
    """What the cost weighs and the motion gain: the choices of :class:`desdemona.runs.session.Choices`
    that every command takes, resolved by :mod:`desdemona.runs.session` alone."""
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
    parser.add_argument("--wall", type=float, default=None, metavar="M_S2",
                        help="the cost of a smooth wall over the last 0.5 %% of the track's and heave's "
                             "travel, as a felt error [m/s^2] at the limit: it keeps a plan from grazing "
                             "a limit, where the off-line solver crawls and an on-line plan dithers; 0 "
                             "lets the plan use the whole travel (default: 1)")
    parser.add_argument("--jerk-weight", type=float, default=None, metavar="RHO", dest="jerk_weight",
                        help="the jerk's weight in the cost, against its limit: higher makes the joints "
                             "reverse their accelerations less, at some cost in the cue (default: 5 "
                             "off-line and 3 on-line on dfs, 1 elsewhere)")
    parser.add_argument("--head-movement-weight", type=float, default=None, metavar="W", dest="head_movement_weight",
                        help="the weight of the cabin's angular velocity in space, all three axes, as it is "
                             "(a felt error of 1 m/s^2 per rad/s): a head moved in a turning cabin is "
                             "cross-coupled, felt as a tumble (see docs/guide/occupant.md); 0: none (default)")


def _add_view_option(parser) -> None:
    parser.add_argument("--no-view", action="store_false", dest="view",
                        help="do not write view.html (the 3D replay, see 'desdemona view') into the result folder")


def _add_serve_parser(sub) -> None:
    serve = sub.add_parser(
        "serve", epilog=SEE_EXIT_CODES, help="run the on-line controller in real time between a simulator host "
                                             "and the machine (UDP)",
        description="Run a session in real time: every cycle take the newest motion the host sent (UDP, "
                    "docs/protocol.md), plan with the on-line controller, check the command against every "
                    "limit and send the machine its setpoint. The machine starts at rest; without a valid "
                    "host message for --timeout cycles it is parked (braked to rest, then held) until the "
                    "host is back. Ctrl-C (or SIGTERM) parks the machine, writes the session to --out and "
                    "exits 130 (143); a second Ctrl-C stops at once after one braking command.")
    _add_machine_options(serve, default_config="dfs")
    serve.add_argument("--listen", required=True, metavar="HOST:PORT",
                       help="where the host's motion arrives, e.g. 127.0.0.1:5500")
    serve.add_argument("--send", required=True, metavar="HOST:PORT",
                       help="where the setpoints go (the motion system), e.g. 127.0.0.1:5501")
    serve.add_argument("--out", required=True, metavar="DIR", help="the session's result folder, written as it ends")
    serve.add_argument("--rate", type=float, default=None, metavar="HZ",
                       help="cycles a second: the plan's step is one cycle (default: 50)")
    serve.add_argument("--channels", type=int, choices=(6, 1), default=None,
                       help="what the host sends: 6, the path S; 1, the modulus M (default: 1 on dfs and "
                            "dfs-yaw, 6 elsewhere)")
    serve.add_argument("--predictor", choices=predictors.names(live=True), default=predictors.LIVE_DEFAULT,
                       help=f"how the controller sees ahead: {predictors.describe(live=True)} "
                            f"(default: {predictors.LIVE_DEFAULT})")
    serve.add_argument(predictors.REFERENCE.option, metavar=predictors.REFERENCE.metavar, default=None,
                       help=f"with --predictor {' or '.join(predictors.users(predictors.REFERENCE))}: "
                            f"{predictors.REFERENCE.what}")
    serve.add_argument("--horizon", type=float, default=None, metavar="SECONDS",
                       help="T_h (default: 2 on dfs and dfs-yaw; 4 with the track)")
    serve.add_argument("--reach", type=float, default=None, metavar="SECONDS",
                       help="how far each plan looks, at least T_h (default: as online)")
    serve.add_argument("--tail-step", type=float, default=0.1, metavar="SECONDS", dest="tail_step",
                       help="the plan's step beyond its first 0.4 s, on full twice that beyond 2 s (default: 0.1; "
                            "0.2 keeps full within 10 ms a cycle at 20 Hz, 0 the cycle throughout)")
    serve.add_argument("--timeout", type=int, default=5, metavar="CYCLES",
                       help="cycles without a valid host message before the machine is parked (default: 5)")
    serve.add_argument("--duration", type=float, default=None, metavar="SECONDS",
                       help="end the session after this long (default: when stopped)")
    serve.add_argument("--quiet-end", type=float, default=None, metavar="SECONDS", dest="quiet_end",
                       help="end the session once the machine is parked and the host has been quiet this long "
                            "(default: never)")
    serviceoptions.add_serve_arguments(serve)
    _add_cost_options(serve)
    _add_overwrite_option(serve)
    _add_view_option(serve)
    serve.set_defaults(run=serving.run_serve)


def _add_machine_parser(sub) -> None:
    machine = sub.add_parser(
        "machine", help="a stand-in for the motion system: follow the setpoints of 'serve', report, check each",
        description="A motion system for one computer (UDP, docs/protocol.md): its joints follow the setpoints "
                    "'desdemona serve' sends through a model of each servo (a transport delay, a position loop, "
                    "measurement noise) and it sends their State back. Its own safety layer, independent of "
                    "the service: no setpoint in time (--timeout) -> it brakes every joint to rest, the fastest "
                    "stop the limits allow, and holds; an emergency stop (a Command from --operator, or "
                    "SIGUSR1) or an injected --fault -> the same stop, then no motion until a reset Command. "
                    "It checks every setpoint (every limit over its cycle, held joints, continuity), the motion "
                    "it made, and when each setpoint came (late, a gap while moving, a burst). Writes "
                    "setpoints.csv, motion.csv, violations.csv, events.csv (appended as it goes) and "
                    "summary.json into --out. Ctrl-C stops the machine and ends once it is at rest.",
        epilog="Exit codes: 0 passed; 1 a violation, a timing fault, or the setpoints ended while the machine "
               "moved (it braked on its own); 2 bad input; 130 interrupted.")
    _add_machine_options(machine, default_config="dfs")
    serviceoptions.add_machine_arguments(machine)
    serviceoptions.add_command_parser(sub)


def _add_host_parser(sub) -> None:
    host = sub.add_parser(
        "host", help="a simulator host on this computer: send a vehicle's motion to 'serve' in real time",
        description="Send a vehicle's motion to 'desdemona serve' (UDP, docs/protocol.md) in real time, as a "
                    "simulator host would: a recorded path, or a JSBSim flight flown as it is sent; or "
                    "forward a running FlightGear's or X-Plane's motion, checked live.")
    kinds = host.add_subparsers(title="hosts", required=True, metavar="HOST")
    replay = kinds.add_parser("replay", help="send a path (built-in or CSV) in real time",
                              description="Send every sample of a path at its time (divided by --speed).")
    replay.add_argument("profile", metavar="PROFILE_OR_CSV",
                        help="the path to send: a built-in profile (see 'desdemona profiles') or a CSV file "
                             "(t,wx,wy,wz,fx,fy,fz or t,M; see --modulus)")
    _add_host_options(replay)
    replay.set_defaults(run=serving.run_host_replay)
    flight = kinds.add_parser("jsbsim", help="fly a JSBSim script in real time and send its pilot's motion",
                              description="Fly a JSBSim script (by name, or an XML file) in real time and send "
                                          "the pilot's motion at --rate, converted as 'import jsbsim' does "
                                          "(needs pip install 'desdemona[jsbsim]').")
    flight.add_argument("script", metavar="SCRIPT",
                        help="a script shipped with JSBSim (see 'desdemona import jsbsim --list') or a script file")
    flight.add_argument("--rate", type=float, default=100.0, metavar="HZ", help="messages a second (default: 100)")
    flight.add_argument("--start", type=float, default=None, metavar="SECONDS",
                        help="the flight's time of the first message (default: after its trim or settling)")
    flight.add_argument("--end", type=float, default=None, metavar="SECONDS",
                        help="the flight's time of the last message (default: the script's end)")
    _add_host_options(flight)
    flight.set_defaults(run=serving.run_host_jsbsim)
    serviceoptions.add_bridge_parsers(kinds)
    serviceoptions.add_key_options(kinds)


def _add_host_options(parser) -> None:
    parser.add_argument("--to", required=True, metavar="HOST:PORT", help="where 'serve' listens, e.g. 127.0.0.1:5500")
    parser.add_argument("--speed", type=float, default=1.0, help="times real time (default: 1)")
    parser.add_argument("--forecast", type=float, default=0.0, metavar="SECONDS",
                        help="send with each message the next SECONDS of the motion (for --predictor forecast; "
                             "the true future of the recording or flight) (default: none)")
    parser.add_argument("--modulus", action="store_true", help="send the modulus |f| only (for dfs)")
    parser.add_argument("--drop", type=float, default=0.0, metavar="SHARE",
                        help="leave out this share of the messages at random, to test a session (default: 0)")
    parser.add_argument("--outage", default=None, metavar="START,LENGTH",
                        help="send nothing for LENGTH seconds from START (motion time), to test a session")
    parser.add_argument("--seed", type=int, default=0, help="seed of --drop (default: 0)")

"""``desdemona study``: its options (beside :mod:`desdemona.cli.options`' table, which hands it the
options every off-line command shares) and what it does (:mod:`desdemona.runs.study`)."""

from __future__ import annotations

import difflib
import sys
import time
from pathlib import Path

from desdemona.cli.exits import EXIT_NOT_CONVERGED, EXIT_UNSAFE, SEE_EXIT_CODES, UserError
from desdemona.cueing import sizing
from desdemona.machine.configs import CONFIGURATIONS
from desdemona.machine.params import BUILTIN_SETS

DEFAULT_CONFIG = "yaw-track-cabin"


def add_parser(sub, start_options, session_options, time_option) -> None:
    """The ``study`` command, with the shared options' adders of :mod:`desdemona.cli.options`."""
    study = sub.add_parser(
        "study", epilog=SEE_EXIT_CODES, help="a design study: vary machine parameters over recordings and "
                                             "configurations, locally or on a Dask cluster",
        description="Solve every point of a grid (--grid) or a space-filling sample (--sample, --points) of "
                    "machine parameters on every RECORDING and --config, each an off-line session as "
                    "optimize's, on local processes or a Dask cluster. Each point's result folder is named by "
                    "its inputs under OUT/points: the same command again solves only the points missing "
                    "(interrupted or failed), never a finished one. Writes OUT/study.csv (and "
                    "study.parquet with pandas and pyarrow): every point's parameters, felt-quality figures, "
                    "limit use and prices, status; and figures: felt.png (the felt error against each "
                    "parameter), front.png (--front), binding.png (which limit binds most).")
    study.add_argument("recordings", nargs="+", metavar="PROFILE_OR_CSV",
                       help="built-in profiles or CSV files of desired paths (the corpus' files), as optimize "
                            "takes them")
    study.add_argument("--config", action="append", default=None, metavar="NAME", dest="configs",
                       help=f"a configuration, repeatable, from: {', '.join(CONFIGURATIONS)} "
                            f"(default: {DEFAULT_CONFIG})")
    study.add_argument("--grid", action="append", default=[], metavar="KEY=V1,V2,...",
                       help="a parameter and its values, repeatable: every combination is a point. KEY is a "
                            "number of the parameter file with its unit, dotted: joints.track.position_m.max, "
                            "joints.yaw.velocity_deg_s, joints.yaw.torque_kN_m, head_offset_m.x, "
                            "bodies.cabin.mass_kg (see 'desdemona model' and data/default.toml)")
    study.add_argument("--sample", action="append", default=[], metavar="KEY=LOW:HIGH",
                       help="a parameter and its bounds, repeatable: --points points of a Latin hypercube "
                            "over all of them (times the grid's combinations)")
    study.add_argument("--points", type=int, default=0, metavar="N", help="points of the --sample")
    study.add_argument("--sample-seed", type=int, default=0, metavar="SEED", dest="sample_seed",
                       help="seed of the sample (default: 0)")
    study.add_argument("--front", default=None, metavar="A,B",
                       help="draw the trade-off front of two columns of the table, both smaller-is-better, "
                            "e.g. joints.track.position_m.max,rms")
    study.add_argument("--out", required=True, metavar="DIR", help="the study's folder (a new one, or an earlier "
                                                                   "study's, which it resumes)")
    study.add_argument("--params", metavar="FILE", help="TOML file overriding machine parameters, the base "
                                                        "of every point")
    study.add_argument("--base", choices=BUILTIN_SETS, default=None, help="built-in parameter set")
    start_options(study, starts=2, why=", as batch's")
    session_options(study, given=False)
    study.add_argument("--processes", type=int, default=2, metavar="N",
                       help="local processes when no --dask is given; with --dask, the cluster's workers, for "
                            "the time estimate (default: 2)")
    study.add_argument("--dask", metavar="ADDRESS", default=None,
                       help="Dask scheduler address (tcp://host:8786): solve the points on that cluster")
    study.add_argument("--quiet", action="store_true", help="no line on stderr as each point ends")
    time_option(study, "the points still to solve, shared over --processes")
    study.set_defaults(run=run_study)


def _study(args):
    """The :class:`~desdemona.runs.study.Study` the options describe, and the --front columns."""
    from desdemona.runs import study

    grid = tuple(study.parse_grid(text) for text in args.grid)
    sample = tuple(study.parse_sample(text) for text in args.sample)
    asked = study.Study(tuple(args.recordings), tuple(dict.fromkeys(args.configs or [DEFAULT_CONFIG])), grid,
                        sample, args.points, args.sample_seed)
    front = None
    if args.front is not None:
        front = tuple(name.strip() for name in args.front.split(","))
        known = [*asked.keys, *study.FIGURES]
        for name in front:
            if name not in known and not name.startswith(("use_", "price_")):
                near = difflib.get_close_matches(name, known, n=3, cutoff=0.5)
                raise UserError(f"--front {args.front}: {name!r} is not a column of the table; "
                                f"{'nearest: ' + ', '.join(near) if near else 'columns: ' + ', '.join(known)}")
        if len(front) != 2:
            raise UserError(f"--front {args.front}: give two columns, A,B")
    return asked, front


def run_study(args) -> int:
    from desdemona.cueing.offline import MAX_STARTS, OptimizeOptions
    from desdemona.results import report, studyfigures
    from desdemona.runs import session, study

    out = Path(args.out)
    args.held.enter_context(report.claim(out))
    study.check_folder(out)
    if not 1 <= args.starts <= MAX_STARTS or args.processes < 1 or args.seed < 0:
        raise UserError(f"--starts from 1 to {MAX_STARTS}, --processes at least 1, --seed at least 0")
    try:
        asked, front = _study(args)
        choices, options = session.Choices.of(args), OptimizeOptions(starts=args.starts, seed=args.seed)
        planned = study.plan(asked, choices, options, args.params, args.base)
    except study.StudyError as exc:
        raise UserError(str(exc)) from None
    begin = time.perf_counter()

    def announce(kept, todo, seconds):
        words = f", about {sizing.duration_words(seconds)} estimated" if todo else ""
        recordings, configs = len(asked.recordings), len(asked.configs)
        print(f"desdemona: study of {len(planned)} points ({len(planned) // (recordings * configs)} parameter "
              f"points x {recordings} recording(s) x {configs} configuration(s)): {kept} already solved, {todo} to "
              f"solve{words}", file=sys.stderr, flush=True)

    def progress(done, total, point, status):
        print(f"desdemona: point {done}/{total} done, {time.perf_counter() - begin:.1f} s: {point.folder_name} "
              f"{point.recording} on {point.config}: {status}", file=sys.stderr, flush=True)

    outcome = study.run_study(planned, choices, options, out, args.processes, args.dask,
                              None if args.quiet else progress, args.max_time, announce)
    drawn = studyfigures.draw(outcome.rows, asked.keys, out, front, study.BINDS)
    print(study.describe(outcome, asked.keys))
    print(f"written: {', '.join(str(p) for p in [*outcome.files, *drawn])}")
    statuses = {row["status"] for row in outcome.rows}
    if statuses - {"ok", "not converged"}:
        return EXIT_UNSAFE
    return 0 if statuses == {"ok"} else EXIT_NOT_CONVERGED

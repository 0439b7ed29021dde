"""Design studies: what the machine's parameters cost the person in it, across recordings and configurations.

A study varies machine parameters (any number of the parameter file, by its dotted key:
:func:`desdemona.machine.params.number_keys`) on a grid (every combination of the values given) or on a
space-filling sample (a Latin hypercube of ``points`` points between bounds, seeded: SciPy's
:class:`scipy.stats.qmc.LatinHypercube`), or both (the grid times the sample), and solves each
parameter point on each recording and each configuration: one off-line session each
(:func:`desdemona.runs.solve.offline`), on local processes or a Dask cluster through
:func:`desdemona.runs.batch.map_jobs`, as ``batch`` runs its jobs.

A study is resumable. Each point's result folder is named by a SHA-256 of everything its result
depends on (the whole parameter set, the recording's content, the configuration, the session's
choices and options, the package's version), under ``OUT/points/``; a result folder is written whole
or not at all, so one that is there is finished and is kept, and the same study run again solves only
the points missing: those interrupted, and those that failed (a failure leaves no folder). The table
``OUT/study.csv`` (and ``study.parquet`` where pandas writes Parquet) is made from the folders: every
point's inputs, its felt-quality figures (its summary's), the use of each limit, the price of each
limit where the result carries them (``limit_prices`` in summary.json), and its status.
"""

from __future__ import annotations

import csv
import dataclasses
import hashlib
import itertools
import json
import math
import os
import threading
import time
from dataclasses import dataclass
from pathlib import Path

from desdemona import profiles
from desdemona._version import __version__
from desdemona.check.simulate import LimitViolation
from desdemona.cueing import sizing
from desdemona.cueing.offline import OptimizeOptions
from desdemona.machine.configs import get_configuration
from desdemona.machine.model import Model
from desdemona.machine.params import MachineParams, ParameterError, load_params
from desdemona.results import report
from desdemona.runs import batch, session, solve
from desdemona.support import files, guard

#: The files and folders a study writes into its folder (anything else there: not a study folder).
WRITES = ("study.csv", "study.parquet", "points", "felt.png", "front.png", "binding.png")
#: The limit use above which a limit counts as binding in a point [1 = the limit], where the results
#: carry no prices (:func:`desdemona.results.studyfigures.binding`).
BINDS = 0.99


class StudyError(session.ChoiceError):
    """A study that cannot be run as asked; the message names the option."""


@dataclass(frozen=True)
class Study:
    """What a study varies: ``grid`` (key, values) pairs, every combination; ``sample`` (key, low, high)
    triples, ``points`` points of a Latin hypercube seeded with ``seed``; the grid times the sample;
    each parameter point on every recording (built-in names or CSV files) and configuration."""

    recordings: tuple[str, ...]
    configs: tuple[str, ...]
    grid: tuple[tuple[str, tuple[float, ...]], ...] = ()
    sample: tuple[tuple[str, float, float], ...] = ()
    points: int = 0
    seed: int = 0

    @property
    def keys(self) -> tuple[str, ...]:
        """The parameters varied, grid first."""
        return tuple(k for k, _ in self.grid) + tuple(k for k, _, _ in self.sample)

    def values(self) -> list[dict[str, float]]:
        """Every parameter point: the grid's combinations times the sample's points (one empty point
        where nothing varies)."""
        keys = self.keys
        if len(set(keys)) != len(keys):
            twice = sorted({k for k in keys if keys.count(k) > 1})
            raise StudyError(f"a parameter is varied twice: {', '.join(twice)}")
        grid = list(itertools.product(*[values for _, values in self.grid]))
        sampled = [()]
        if self.sample:
            from scipy.stats import qmc

            if self.points < 1:
                raise StudyError("--sample needs --points N, the number of points drawn (at least 1)")
            unit = qmc.LatinHypercube(d=len(self.sample), seed=self.seed).random(self.points)
            low, high = [s[1] for s in self.sample], [s[2] for s in self.sample]
            sampled = [tuple(float(x) for x in row) for row in qmc.scale(unit, low, high)]
        elif self.points:
            raise StudyError("--points goes with --sample: drop it, or sample a parameter")
        return [dict(zip(keys, g + s)) for g in grid for s in sampled]


def parse_grid(text: str) -> tuple[str, tuple[float, ...]]:
    """``KEY=v1,v2,...`` -> (key, values)."""
    key, values = _split(text, "--grid", "KEY=v1,v2,...")
    try:
        numbers = tuple(float(v) for v in values.split(","))
    except ValueError:
        raise StudyError(f"--grid {text}: values are numbers separated by commas, e.g. {key}=3,3.5,4") from None
    if not all(math.isfinite(v) for v in numbers) or len(set(numbers)) != len(numbers):
        raise StudyError(f"--grid {text}: give distinct finite numbers")
    return key, numbers


def parse_sample(text: str) -> tuple[str, float, float]:
    """``KEY=low:high`` -> (key, low, high)."""
    key, bounds = _split(text, "--sample", "KEY=LOW:HIGH")
    try:
        low, high = (float(v) for v in bounds.split(":"))
    except ValueError:
        raise StudyError(f"--sample {text}: give the bounds as LOW:HIGH, e.g. {key}=3:4") from None
    if not (math.isfinite(low) and math.isfinite(high) and low < high):
        raise StudyError(f"--sample {text}: LOW must be less than HIGH, both finite")
    return key, low, high


def _split(text: str, option: str, form: str) -> tuple[str, str]:
    key, sep, rest = text.partition("=")
    if not sep or not key.strip() or not rest.strip():
        raise StudyError(f"{option} {text}: write {form}")
    return key.strip(), rest.strip()


@dataclass(frozen=True)
class Point:
    """One session of a study: parameter values (key, value), a recording, a configuration, and the
    key (SHA-256) that names its result folder."""

    values: tuple[tuple[str, float], ...]
    recording: str
    config: str
    key: str

    @property
    def folder_name(self) -> str:
        return self.key[:20]


def recording_identity(recording: str) -> str:
    """What a point's result depends on of its recording: a file's content (SHA-256), or a built-in's name."""
    if recording in profiles.PROFILES and not os.path.isfile(recording):
        return f"built-in {recording}"
    with open(recording, "rb") as fh:
        return "sha256 " + hashlib.sha256(fh.read()).hexdigest()


def point_key(params: MachineParams, recording: str, config: str, choices: session.Choices,
              options: OptimizeOptions) -> str:
    """The SHA-256 of everything a point's result depends on (JSON, keys sorted)."""
    inputs = {"parameters": params.to_dict(), "recording": recording, "configuration": config,
              "choices": dataclasses.asdict(choices), "starts": options.starts, "seed": options.seed,
              "refine": options.refine, "version": __version__}
    return hashlib.sha256(json.dumps(inputs, sort_keys=True, default=str).encode()).hexdigest()


def plan(study: Study, choices: session.Choices, options: OptimizeOptions, params_file: str | None = None,
         base: str | None = None) -> list[tuple[Point, MachineParams]]:
    """Every point of ``study`` with its machine parameters, each checked (:func:`load_params`: an
    unknown key names the nearest known ones; a value the machine model refuses names it), each
    configuration known and each recording read; before any work. Raises ValueError
    (:class:`StudyError`, :class:`~desdemona.machine.params.ParameterError`,
    :class:`~desdemona.profiles.ProfileError`)."""
    if not study.recordings or not study.configs:
        raise StudyError("a study needs at least one recording and one --config")
    for name in study.configs:
        try:
            get_configuration(name)
        except ValueError as exc:
            raise StudyError(str(exc)) from None
    identity = {}
    for recording in dict.fromkeys(study.recordings):
        profiles.load(recording)  # read and checked (ProfileError naming the file)
        identity[recording] = recording_identity(recording)
    out = []
    for values in study.values():
        params = load_params(params_file, base, values)
        for recording in study.recordings:
            for config in study.configs:
                Model(params, config)
                key = point_key(params, identity[recording], config, choices, options)
                out.append((Point(tuple(values.items()), recording, config, key), params))
    return out


def is_done(out_dir: str | Path, point: Point) -> bool:
    """Whether ``point`` has its result folder in the study folder (written whole or not at all)."""
    return report.is_result_folder(Path(out_dir) / "points" / point.folder_name)


def check_folder(out_dir: str | Path) -> None:
    """Raise :class:`~desdemona.results.report.ReportError` unless ``out_dir`` is new, empty, or a
    study folder (holding only what a study writes: :data:`WRITES`), which a study resumes."""
    out = Path(out_dir)
    if not out.exists():
        return
    if not out.is_dir():
        raise report.ReportError(f"{out}: is not a folder; --out names the study's folder")
    foreign = [p.name for p in out.iterdir() if p.name not in WRITES and not p.name.startswith(".")]
    if foreign:
        raise report.ReportError(f"{out}: is not a study folder (it holds {', '.join(sorted(foreign)[:3])}); "
                                 "choose another --out")


def check_size(todo: list[tuple[Point, MachineParams]], choices: session.Choices, options: OptimizeOptions,
               processes: int, max_time: float | None = None, together: int | None = None) -> float:
    """The estimated seconds of the points ``todo`` on ``processes`` processes at once (each point's
    :func:`desdemona.cueing.sizing.estimate_time`, summed and shared). Raises
    :class:`~desdemona.cueing.sizing.TooLarge` where ``together`` points of a kind (default
    ``processes``: local processes; 1 for a cluster's workers, each on its own) would not fit in this
    computer's memory at once, :class:`~desdemona.cueing.sizing.TooLong` where a point takes longer
    than its own limit (no ``max_time``) or the whole study longer than ``max_time``, saying the
    estimate."""
    together = processes if together is None else together
    seconds, kinds = 0.0, {}
    for point, params in todo:
        kind = (point.recording, point.config)
        if kind not in kinds:
            resolved = solve.resolve(profiles.load(point.recording), Model(params, point.config), choices,
                                     workers=1, starts=options.starts)
            problem, window = resolved.options, resolved.window
            part = resolved.path if window is None else _window_part(resolved.path, window)
            try:
                sizing.check_fits(part, resolved.model.config, problem, max(1, together), resolved.model.limits.smooth)
            except sizing.TooLarge as exc:
                raise sizing.TooLarge(f"{str(exc).replace('--workers', '--processes')} ({together} points at once "
                                      "on this computer)") from None
            estimate = (sizing.check_time if max_time is None else sizing.estimate_time)(
                resolved.path, resolved.model.config, problem.h_u, problem.solver, options.starts, 1, window)
            kinds[kind] = estimate
        seconds += kinds[kind]
    shared = max(seconds / max(1, processes), max(kinds.values()))  # no point is shared out
    if max_time is not None and shared > sizing.time_limit(profiles.load(todo[0][0].recording), max_time):
        raise sizing.TooLong(f"the study's {len(todo)} points to solve: about {sizing.duration_words(shared)} "
                             f"estimated on {processes} process{'es' if processes > 1 else ''} (each point's "
                             f"estimate, summed), above --max-time {max_time:g} s; fewer points or recordings, "
                             "more processes, or a larger --max-time")
    return shared


def _window_part(path, window: float):
    from desdemona.cueing import windows

    return windows.part(path, 0.0, window)


_quick = {"lock": threading.Lock(), "users": 0, "saved": None}


class _QuickCompiles:
    """Inside it, no optimised library is compiled in the background (:data:`compiled.OPTIMISED`
    "never"): a study's parameter sets rarely come back, and a minute of compiling at the lowest
    priority per point would pile up on the workers; the quick library gives the same results to
    round-off. Counted, so that threads of one worker (Dask with threads) leave it as they found it."""

    def __enter__(self):
        from desdemona.cueing import compiled

        with _quick["lock"]:
            if _quick["users"] == 0:
                _quick["saved"], compiled.OPTIMISED = compiled.OPTIMISED, "never"
            _quick["users"] += 1

    def __exit__(self, *exc):
        from desdemona.cueing import compiled

        with _quick["lock"]:
            _quick["users"] -= 1
            if _quick["users"] == 0:
                compiled.OPTIMISED = _quick["saved"]


def run_point(point: Point, params: MachineParams, choices: session.Choices, options: OptimizeOptions,
              out_dir: str) -> dict:
    """Solve one point and write its result folder (no figures, no view: ``desdemona plot`` draws
    them); a failure becomes a status, not an exception, and leaves no folder (it is redone)."""
    start = time.perf_counter()
    folder = Path(out_dir) / "points" / point.folder_name
    try:
        with _QuickCompiles():
            result = solve.offline(profiles.load(point.recording), Model(params, point.config), choices,
                                   workers=1, starts=options.starts, seed=options.seed, refine=options.refine)
        study = {"key": point.key, "values": dict(point.values), "recording": point.recording,
                 "felt": result.quality.key_figures()}
        report.write(result, folder, command=f"desdemona study ({point.recording} on {point.config})",
                     overwrite=True, view=False, draw=False, extra_summary={"study": study})
        status, message = ("ok", "") if result.converged else ("not converged", result.solution.status)
    except LimitViolation as exc:
        status, message = "no safe trajectory", str(exc)
    except (ValueError, RuntimeError, OSError) as exc:
        status, message = "error", str(exc)
    return {"status": status, "message": message, "seconds": time.perf_counter() - start}


@dataclass
class Outcome:
    """A study's run: its table's rows (one per point, in the study's order), how many points were
    solved now and how many were kept from an earlier run, and the table's files."""

    rows: list[dict]
    solved: int
    kept: int
    files: list[Path]


def run_study(planned: list[tuple[Point, MachineParams]], choices: session.Choices, options: OptimizeOptions,
              out_dir: str | Path, processes: int = 2, dask_address: str | None = None, progress=None,
              max_time: float | None = None, announce=None) -> Outcome:
    """Solve the points of ``planned`` (:func:`plan`) that have no result folder yet, on ``processes``
    local processes or the Dask scheduler at ``dask_address`` (:func:`desdemona.runs.batch.map_jobs`),
    and write the table (:func:`write_table`). Everything is checked first (the folder, the sizes:
    :func:`check_size`). progress : optional ``progress(done, total, point, status)`` told as each
    point ends; announce : optional ``announce(kept, to_solve, estimated_seconds)`` told before the
    first. Interrupted, it stops the workers, writes the table of what is done (the others marked
    "interrupted") and re-raises :class:`~desdemona.support.guard.Interrupted` saying so; the same
    study run again solves only what is missing."""
    if dask_address is not None:
        batch.reach_scheduler(dask_address)
    check_folder(out_dir)
    out = Path(out_dir)
    todo = list({p.key: (p, params) for p, params in planned if not is_done(out, p)}.values())  # each once
    seconds = check_size(todo, choices, options, processes, max_time, 1 if dask_address else None) if todo else 0.0
    if announce is not None:
        announce(len(planned) - len(todo), len(todo), seconds)
    (out / "points").mkdir(parents=True, exist_ok=True)
    ran: list[dict | None] = [None] * len(todo)

    def told(done, total, result):
        if progress is not None:
            index = next(i for i, r in enumerate(ran) if r is result)
            progress(done, total, todo[index][0], result["status"])

    try:
        batch.map_jobs(run_point, [(p, params, choices, options, str(out)) for p, params in todo], processes,
                       dask_address, told, ran)
    except guard.Interrupted as exc:
        done = sum(r is not None for r in ran)
        with guard.deferred():  # the table of what is done, not cut by the signal's repeats
            written = write_table(out, table_rows(planned, out, todo, ran, "interrupted"))
        exc.message = (f"interrupted ({exc.name}): stopped; {done} of the {len(todo)} points to solve were solved, "
                       f"{len(planned) - len(todo) + done} of {len(planned)} are in {written[0]}; the same command "
                       "again solves the others")
        raise
    rows = table_rows(planned, out, todo, ran, "missing")
    return Outcome(rows, len(todo), len(planned) - len(todo), write_table(out, rows))


#: The figures of each point's summary in the table, after its inputs and status.
FIGURES = ("rms", "rms_perceived", "worst_use", *batch.FELT_COLUMNS, "felt_direction_rms_deg", "iterations",
           "solve_s")


def table_rows(planned, out: Path, todo, ran, missing: str) -> list[dict]:
    """The table's rows: a finished point's from its folder's summary.json, a failed one's from this
    run, a point not run (interrupted) as ``missing``."""
    failed = {p.key: r for (p, _), r in zip(todo, ran) if r is not None}
    rows = []
    for point, _ in planned:
        row = {"point": point.folder_name, "recording": point.recording, "configuration": point.config,
               **dict(point.values)}
        folder = out / "points" / point.folder_name
        if report.is_result_folder(folder):
            row.update(summary_row(json.loads((folder / "summary.json").read_text())))
            row["folder"] = str(folder)
        else:
            result = failed.get(point.key, {"status": missing, "message": ""})
            row.update(status=result["status"], message=result["message"])
        rows.append(row)
    return rows


def summary_row(summary: dict) -> dict:
    """A finished point's figures from its summary.json: status, :data:`FIGURES`, the use of each limit
    (``use_<family>_<joint>``, 1 = the limit) and, where the result carries them, each limit's price
    (``price_<family>_<joint>``: ``limit_prices[family][joint]["price"]``)."""
    metrics, solver = summary["metrics"], summary["solver"]
    felt = summary.get("study", {}).get("felt", {})
    row = {"status": "ok" if solver["converged"] else "not converged",
           "rms": metrics["rms_weighted"], "rms_perceived": metrics["rms_perceived"],
           "worst_use": max(metrics["worst_use"].values()), **{name: felt.get(name) for name in FIGURES[3:-2]},
           "iterations": solver["iterations"], "solve_s": solver["timings_s"].get("wall"),
           "message": "" if solver["converged"] else solver["status"]}
    for family, joints in sorted(metrics.get("worst_use_per_joint", {}).items()):
        row.update({f"use_{family}_{joint}": use for joint, use in joints.items()})
    for family, joints in sorted((summary.get("limit_prices") or {}).items()):
        if isinstance(joints, dict):
            row.update({f"price_{family}_{joint}": entry.get("price") if isinstance(entry, dict) else entry
                        for joint, entry in joints.items()})
    return row


def columns(rows: list[dict]) -> list[str]:
    """The table's columns: the point, its inputs, its status and figures, then every use and price
    column any row has (sorted), the folder and the message."""
    first = list(dict.fromkeys(k for row in rows for k in row if k not in ("folder", "message")))
    fixed = [k for k in first if not k.startswith(("use_", "price_"))]
    lead = [k for k in fixed if k not in ("status", *FIGURES)]
    return [*lead, "status", *FIGURES, *sorted(k for k in first if k.startswith("price_")),
            *sorted(k for k in first if k.startswith("use_")), "folder", "message"]


def write_table(out: Path, rows: list[dict]) -> list[Path]:
    """``out/study.csv`` (written whole or not at all), and ``out/study.parquet`` where pandas and a
    Parquet engine (pyarrow) are installed; the files written."""
    names = columns(rows)
    target = out / "study.csv"
    with files.beside(target) as tmp:
        with open(tmp, "w", newline="") as fh:
            writer = csv.DictWriter(fh, names, restval="")
            writer.writeheader()
            writer.writerows({k: "" if v is None else v for k, v in row.items()} for row in rows)
        with guard.deferred():
            os.replace(tmp, target)
    written = [target]
    try:
        import pandas
        import pyarrow  # noqa: F401  (pandas' Parquet engine)
    except ImportError:
        return written
    frame = pandas.DataFrame(rows, columns=names)
    with files.beside(out / "study.parquet") as tmp:
        frame.to_parquet(tmp, index=False)
        with guard.deferred():
            os.replace(tmp, out / "study.parquet")
    return [*written, out / "study.parquet"]


def read_table(out_dir: str | Path) -> list[dict]:
    """The rows of a study's ``study.csv``, numbers as floats (empty cells None)."""
    def value(text: str):
        if text == "":
            return None
        try:
            return float(text)
        except ValueError:
            return text

    with open(Path(out_dir) / "study.csv", newline="") as fh:
        return [{k: value(v) for k, v in row.items()} for row in csv.DictReader(fh)]


def describe(outcome: Outcome, keys: tuple[str, ...]) -> str:
    """The study's printed lines: how many points were solved now and kept, each status's count, and
    per recording and configuration the point of least felt error with its parameters."""
    counts: dict[str, int] = {}
    for row in outcome.rows:
        counts[row["status"]] = counts.get(row["status"], 0) + 1
    lines = [f"{len(outcome.rows)} points: {outcome.solved} solved now, {outcome.kept} kept from before; "
             + ", ".join(f"{n} {status}" for status, n in counts.items())]
    best: dict[tuple, dict] = {}
    for row in outcome.rows:
        group = (row["recording"], row["configuration"])
        if row.get("rms") is not None and (group not in best or row["rms"] < best[group]["rms"]):
            best[group] = row
    for (recording, config), row in best.items():
        values = ", ".join(f"{k} = {row[k]:.4g}" for k in keys)
        lines.append(f"  least felt error on {recording} on {config}: RMS {row['rms']:.4g} at "
                     f"{values or 'the base parameters'} (point {row['point']})")
    return "\n".join(lines)

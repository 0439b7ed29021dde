"""Real inputs: every corpus case on every configuration that suits it, off-line and on-line, in one table.

    python benchmarks/real.py                          # build the corpus if missing, run every job, write the table
    python benchmarks/real.py --cases f16-turn --configs dfs --modes offline hold
    python benchmarks/real.py --cases c172-doublet --modes hold perfect forecast --no-docs
    python benchmarks/real.py --modes hold --rate dfs=100 --no-docs   # dfs on-line at 100 Hz
    python benchmarks/real.py --table-only             # re-read the result folders, rewrite the table
    python benchmarks/real.py --dask tcp://scheduler:8786   # the jobs on a Dask cluster
    python benchmarks/real.py --corpus my-rides --modes offline hold   # one's own paths, table printed

The corpus (``benchmarks/corpus.py``) holds flights from JSBSim's shipped scripts and aircraft, each
in the six-channel form (``t,wx,wy,wz,fx,fy,fz``) and the modulus form (``t,M``). A six-channel case
runs on ``yaw-track-cabin`` and ``full``, a modulus case on ``dfs``; each off-line (``desdemona
optimize`` with its defaults) and on-line (``desdemona online --predictor hold``, ``perfect`` and
``forecast``, the command's defaults otherwise). ``forecast`` reads the aircraft's own forecasts
(``NAME.forecast.csv``: every 0.1 s its model run 4 s ahead with the pilot's controls held, made with
the corpus by ``corpus.py --forecasts`` where a case's are missing). ``--corpus`` may name a folder of
one's own paths instead (``desdemona import log`` output, no ``index.json``): each ``NAME.csv`` is a
case of the form its columns give, nothing is built or written in the folder, and the table is only
printed. Every job is the command a user
would type, run as its own process
(so its peak memory is its own: ``ru_maxrss`` of the process; ``--no-view``: the page is not
timed), stopped with SIGINT after
``--timeout`` seconds; the jobs go through :func:`desdemona.runs.batch.map_jobs` (local processes, or a
Dask cluster whose workers see the corpus and the output folder at the same paths).

Per job the table gives: the exit code (0 converged, 4 not converged, 3 no safe trajectory, 2
refused, "timeout"), the wall time and its ratio to the recording's duration, the peak memory, and
what the occupant feels, read from the result's ``summary.json`` ("quality"):

- felt force RMS [m/s^2]: RMS of the vector ``|f - f_d|`` (on ``dfs``: against (0, 0, M_d) in the
  cabin, the force along the occupant's vertical), the same for every configuration and mode;
- correlation and lag [s] of the dominant force channel (the one whose desired value varies most; on
  ``dfs`` f_z against M_d);
- felt direction RMS and peak [deg] and the peak of the part the machine made, beyond a still level
  cabin's (``made``: :func:`desdemona.check.metrics.direction_made`), peak felt rotation through the canals
  [deg/s], acceleration reversals per second of the worst joint (swings across 5 % of its peak);
- what the occupant suffers beyond the cue (:mod:`desdemona.occupant.coriolis`,
  :mod:`desdemona.occupant.sickness`): the peak cross-coupled angular velocity of a head nod (30 deg in
  0.5 s, the worst of pitch, roll and yaw, started at any instant) [deg/s] and the sickness dose
  MSDV_z of the vertical force [m/s^1.5];
- on-line rows: the p99 compute time per cycle [ms] and the deadlines missed; and the classical
  loop's felt force RMS, correlation, felt direction peak, felt rotation peak, nod cross-coupling
  peak and MSDV_z from the same run
  (it reads only the present sample, as ``hold``), with MPC / classical for the felt force;
- on ``forecast`` rows, the share of the gap between ``hold`` and ``perfect`` that the forecast
  closes: (hold - forecast) / (hold - perfect) of the felt force RMS ("-" where the gap is under
  :data:`GAP` of hold's, or a row is missing).

Below the table, the on-line rows worse than the classical loop on any of those measures (the felt
direction by the part the machine made), or reversing a joint's acceleration more than once a second,
marked + where the run's ``perfect`` row is worse too, o where its ``offline`` row is, and t where the
desired force itself reverses as often (point 1 of the on-line issue, :func:`against_loop`).

The machine's load average is recorded before and after the run, and so is its own spread of time
(:func:`jitter`): a fixed piece of work timed again and again, whose p99 over its median is what the
machine adds to any p99 per cycle, whatever the code.
"""

from __future__ import annotations

import argparse
import csv
import json
import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import corpus  # benchmarks/corpus.py: the script's own folder is on the path
import numpy as np
import tables

from desdemona import profiles
from desdemona.check import metrics
from desdemona.occupant import perception
from desdemona.runs import batch

HERE = Path(__file__).resolve().parent
CORPUS = HERE / "corpus"
RESULTS = HERE / "real-results"
DOCS = HERE.parent / "docs" / "benchmarks" / "real-inputs.md"
BEGIN, END = "<!-- real.py table: begin -->", "<!-- real.py table: end -->"

CONFIGS = {"six": ("yaw-track-cabin", "full"), "modulus": ("dfs",)}
MODES = ("offline", "hold", "perfect", "forecast")
#: The smallest gap between hold and perfect, relative to hold's felt force RMS, for a "forecast closes".
GAP = 0.02
FORCE = ("fx", "fy", "fz")


def corpus_cases(folder: Path, build: bool = True, forecasts=()) -> list[dict]:
    """The corpus index: one entry per file (name, file, form "six" or "modulus", duration_s, source,
    and where made, forecast), the corpus built first (``build``) where it is missing or made from another
    definition (:func:`corpus.definition`), and the forecasts of the cases named in ``forecasts`` where
    they are missing. A folder of one's own paths, without an index, is read as it is
    (:func:`own_cases`): nothing is built or written in it."""
    index = folder / "index.json"
    if holds_own_paths(folder):
        return own_cases(folder)
    if build and (not index.exists() or json.loads(index.read_text()).get("definition") != corpus.definition()):
        subprocess.run([sys.executable, str(HERE / "corpus.py"), "--out", str(folder)], check=True)
    cases = json.loads(index.read_text())["cases"]
    missing = sorted({c["name"] for c in cases if c["name"] in forecasts and "forecast" not in c})
    if build and missing:
        subprocess.run([sys.executable, str(HERE / "corpus.py"), "--out", str(folder), "--forecasts", "--cases",
                        *missing], check=True)
        cases = json.loads(index.read_text())["cases"]
    return cases


def holds_own_paths(folder: Path) -> bool:
    """Whether ``folder`` is a folder of one's own paths: CSV files and no corpus index."""
    return not (folder / "index.json").exists() and any(folder.glob("*.csv"))


def own_cases(folder: Path) -> list[dict]:
    """Index entries of a folder of one's own desired paths (``desdemona import log`` writes them): every
    ``NAME.csv`` in it, its form read from its columns, with ``NAME.forecast.csv`` beside it as its
    forecast where there is one; the fields the jobs and the table read. A file that does not read as a
    path stops the run, named."""
    cases = []
    for file in sorted(folder.glob("*.csv")):
        if file.name.endswith(".forecast.csv"):
            continue
        try:
            path = profiles.load(file)
        except profiles.ProfileError as exc:
            raise SystemExit(f"--corpus {folder}: {exc}") from None
        case = {"name": file.stem, "file": file.name, "form": "modulus" if path.S_d is None else "six",
                "duration_s": round(float(path.duration), 1)}
        if file.with_name(f"{file.stem}.forecast.csv").exists():
            case["forecast"] = f"{file.stem}.forecast.csv"
        cases.append(case)
    return cases


def command(case: dict, config: str, mode: str, out: Path, wall: float | None = None,
            step: float | None = None, extra: tuple[str, ...] = ()) -> list[str]:
    """The command line of one job, as a user would type it (off-line with ``--wall`` where given,
    on-line with ``--step`` where given, and the ``extra`` arguments)."""
    base = [sys.executable, "-m", "desdemona"]
    if mode == "offline":
        chosen = ([] if wall is None else ["--wall", f"{wall:g}"]) + list(extra)
        return [*base, "optimize", case["file"], "--config", config, *chosen, "--out", str(out), "--overwrite",
                "--quiet", "--no-view"]
    chosen = ["--forecast", case["forecast"]] if mode == "forecast" else []
    chosen += ([] if step is None else ["--step", f"{step:g}"]) + list(extra)
    return [*base, "online", case["file"], "--config", config, "--predictor", mode, *chosen, "--out", str(out),
            "--overwrite", "--no-view"]


def run_job(case: dict, config: str, mode: str, out: str, timeout: float, wall: float | None = None,
            step: float | None = None, extra: tuple[str, ...] = ()) -> dict:
    """Run one job as its own process; its exit, wall time [s] and peak memory [MB]."""
    folder = Path(out) / f"{case['name']}--{config}--{mode}"
    start = time.perf_counter()
    process = subprocess.Popen(command(case, config, mode, folder, wall, step, extra), stdout=subprocess.PIPE,
                               stderr=subprocess.STDOUT, text=True)
    deadline, stopped, status = start + timeout, False, None
    while status is None:
        pid, wait_status, usage = os.wait4(process.pid, os.WNOHANG)
        if pid:
            status = wait_status
            break
        if not stopped and time.perf_counter() > deadline:
            process.send_signal(signal.SIGINT)  # the tool stops within a second or two, writing nothing
            stopped, deadline = True, time.perf_counter() + 30.0
        elif stopped and time.perf_counter() > deadline:
            process.kill()
        time.sleep(0.2)
    process.returncode = os.waitstatus_to_exitcode(status)
    output = process.stdout.read()
    return {"case": case["name"], "form": case["form"], "duration_s": case["duration_s"], "config": config, "mode": mode,
            "exit": "timeout" if stopped else process.returncode, "wall_s": time.perf_counter() - start,
            "peak_mb": usage.ru_maxrss / 1024.0, "load": os.getloadavg()[0], "date": time.strftime("%Y-%m-%d"),
            "folder": str(folder), "output": output[-2000:]}


def dominant_force(path: profiles.DesiredPath) -> str:
    """The force channel whose desired value varies most (fz, the modulus, for a modulus path)."""
    if path.S_d is None:
        return "fz"
    return FORCE[int(np.argmax(np.std(path.S_d[:, 3:], axis=0)))]


def felt_figures(quality: dict | None, channel: str) -> dict:
    """The table's felt figures of one summary's ``quality`` block."""
    if quality is None or quality["channels"] is None:
        return {}
    rms = quality["channels"]["rms"]
    rotation = quality["felt_rotation"]["peak_deg_s"].values()
    reversals = quality["joints"].get("reversals_per_s", {}).values()
    return {"force_rms": float(np.sqrt(sum(rms[c] ** 2 for c in FORCE))),
            "correlation": quality["channels"]["correlation"][channel],
            "lag_s": quality["channels"]["lag_s"][channel],
            "direction_rms": quality["felt_direction"]["rms_deg"],
            "direction_peak": quality["felt_direction"]["peak_deg"],
            "direction_made": quality["felt_direction"].get("made_peak_deg"),
            "rotation_peak": max((r for r in rotation if r is not None), default=None),
            "reversals": max(reversals, default=None), **suffered(quality)}


def suffered(quality: dict) -> dict:
    """What the occupant suffers, from a summary's ``quality`` (none where it predates them): the
    largest peak cross-coupled angular velocity of the standard head nods [deg/s] and MSDV_z [m/s^1.5]."""
    nods = quality.get("cross_coupling") or {}
    peaks = [nods[name]["velocity_peak_deg_s"] for name in ("pitch", "roll", "yaw") if name in nods]
    return {"cross_coupling": max(peaks, default=None), "msdv_z": (quality.get("sickness") or {}).get("msdv_z")}


def shape_thresholds(path: profiles.DesiredPath, channel: str) -> float:
    """How far the desired value of ``channel`` ranges over the path, in perception thresholds of that
    force channel: under one, no shape of it can be felt, and its correlation says little."""
    column = 3 + FORCE.index(channel)  # in S
    values = path.modulus if path.S_d is None else path.S_d[:, column]
    return float(np.ptp(values) / perception.THRESHOLDS[column])


def target_reversals(path: profiles.DesiredPath) -> float:
    """How often the desired force itself reverses [1/s]: the most of its channels (minus g on z; the
    modulus minus g), with the joints' hysteresis of 5 % of the channel's peak
    (:func:`desdemona.check.metrics.reversals_per_second`). A joint that makes a force channel reverses its
    acceleration whenever the force does: a multicopter's hover bobs at 1-2 Hz."""
    force = (path.modulus - profiles.G)[:, None] if path.S_d is None else path.S_d[:, 3:] - [0.0, 0.0, profiles.G]
    return float(np.max(metrics.reversals_per_second(path.t, force)))


def against_loop(rows: list[dict]) -> str:
    """Point 1 of the on-line issue, row by row: where an on-line row is worse than the classical loop
    of the same run (felt force RMS or peak felt rotation above it, correlation below it, the felt
    direction the machine made above the larger of 30 deg and the loop's) or reverses a joint's
    acceleration more than once a second. A correlation marked * is of a desired channel that ranges
    over less than one perception threshold (:func:`shape_thresholds`). A row marked + is one that the
    same controller with the future known (the run's ``perfect`` row of the case and configuration)
    fails as well: the cost's own trade, which no prediction lifts, rather than the prediction's. A
    row marked o is one whose off-line optimum (the run's ``offline`` row: the whole future, solved to
    convergence) is worse than this row's loop on the same measure: there point 1 asks for more than
    the optimum of the cost gives. A reversal count marked t is at most the desired force's own
    (``target_reversals`` of the row, :func:`target_reversals`): following the target takes as many.

    The felt direction is judged by the part the machine made (``made``: beyond a still level cabin's,
    :func:`desdemona.check.metrics.direction_made`), as the issue defines it: the machine "never turns the
    felt force more than 30 deg from where the target points it". Where the target itself points far
    from any force a cabin on the ground can give (a push-over's negative g: 180 deg for a still cabin,
    the loop and the MPC alike) the peak of the error is the target's, and comparing it says nothing
    of the machine; the table keeps that peak beside ``made``."""
    judged = [r for r in rows if r["mode"] != "offline" and r.get("classical_force_rms") is not None]
    if not judged:
        return ""
    loop = lambda key: lambda r: r.get("classical_" + key)  # noqa: E731
    tests = (("felt force RMS above the loop's", "force_rms", ".3f", loop("force_rms"), 1),
             ("peak felt rotation above the loop's", "rotation_peak", ".1f", loop("rotation_peak"), 1),
             ("correlation below the loop's", "correlation", ".2f", loop("correlation"), -1),
             ("felt direction made above max(30 deg, the loop's)", "direction_made", ".1f",
              lambda r: max(30.0, r.get("classical_direction_made") or 0.0), 1),
             ("more than one reversal a second", "reversals", ".2f", lambda r: 1.0, 1))
    perfect = {(r["case"], r["config"]): r for r in judged if r["mode"] == "perfect"}
    offline = {(r["case"], r["config"]): r for r in rows if r["mode"] == "offline"}
    lines, failing, used = [], set(), set()  # used: the marks given to any row
    for name, key, fmt, bound, sign in tests:
        worse = lambda r, by=None: (None not in (r.get(key), bound(by or r))  # noqa: E731
                                    and sign * (r[key] - bound(by or r)) > 0)
        hits = [r for r in judged if worse(r)]
        failing |= {id(r) for r in hits}
        marks = {id(r): ("*" if key == "correlation" and r.get("shape", 1.0) < 1.0 else "")
                 + ("+" if r["mode"] != "perfect" and worse(perfect.get((r["case"], r["config"]), {})) else "")
                 + ("o" if worse(offline.get((r["case"], r["config"]), {}), by=r) else "")  # against r's loop
                 + ("t" if key == "reversals" and r[key] <= r.get("target_reversals", 0.0) else "")
                 for r in hits}
        used.update(*marks.values())
        cells = [f"{r['case']} on {r['config']} ({r['mode']}) {format(r[key], fmt)} against {format(bound(r), fmt)}"
                 f"{marks[id(r)]}" for r in hits]
        lines.append(f"- {name}: {len(hits)} row{'s' * (len(hits) != 1)}{': ' if hits else ''}{'; '.join(cells)}")
    if any(r.get("shape", 1.0) < 1.0 for r in judged):
        lines.append("- *: the desired channel ranges over less than one perception threshold")
    legend = {"+": "so is the same controller with the future known (perfect): the cost's own trade",
              "o": "so is the off-line optimum, against the same loop: more than the cost's optimum gives",
              "t": "the desired force itself reverses at least as often: following it takes as many reversals"}
    lines += [f"- {mark}: {text}" for mark, text in legend.items() if mark in used]
    head = f"Against the classical loop, {len(judged) - len(failing)} of {len(judged)} on-line rows worse on no measure:"
    return "\n".join([head, "", *lines])


def read_result(job: dict, channel: str) -> dict:
    """A job's figures from its result folder (none where nothing was written)."""
    summary_file = Path(job["folder"]) / "summary.json"
    if job["exit"] not in (0, 4) or not summary_file.exists():
        return job
    summary = json.loads(summary_file.read_text())
    row = {**job, **felt_figures(summary["quality"], channel), "channel": channel}
    if "cycles" in summary:
        cycles = summary["cycles"]
        row.update(p99_ms=1e3 * cycles["compute_time_s"]["p99"], misses=cycles["deadline_misses"],
                   cycles=cycles["count"])
        row.update({f"classical_{k}": v for k, v in
                    felt_figures(summary["quality_classical_loop"], channel).items()})
    return row


def jitter(count: int = 2000) -> tuple[float, float]:
    """The machine's own spread of time: the same piece of work (ten 60 x 60 linear solves and 40,000
    additions in Python, about a millisecond) timed ``count`` times; its median [ms] and p99 / median.
    On a machine that shares its processor (steal time) the ratio is 2 or more, and a controller's
    p99 per cycle is then at least its median times that, whatever the code."""
    rng = np.random.default_rng(0)
    A, b = rng.normal(size=(60, 60)) + 60.0 * np.eye(60), rng.normal(size=60)
    times = np.empty(count)
    for k in range(count):
        start = time.perf_counter()
        for _ in range(10):
            np.linalg.solve(A, b)
        sum(range(40000))
        times[k] = time.perf_counter() - start
    median = float(np.median(times))
    return 1e3 * median, float(np.percentile(times, 99)) / median


def cell(value, fmt: str) -> str:
    return "-" if value is None else format(value, fmt)


def table(rows: list[dict]) -> str:
    """The markdown table of every job's row."""
    lines = ["| case | s | configuration | mode | exit | wall [s] | wall / s | peak [MB] | felt force RMS | "
             "corr | lag [s] | dir RMS / peak / made [deg] | rot peak [deg/s] | rev/s | nod x-coupling [deg/s] | "
             "MSDV_z | p99 [ms] | missed | classical: force RMS | corr | dir peak / made | rot peak | "
             "nod x-coupling | MSDV_z | MPC / classical | forecast closes |",
             "| --- " * 26 + "|"]
    for r in rows:
        ratio = (r["force_rms"] / r["classical_force_rms"]
                 if r.get("force_rms") is not None and r.get("classical_force_rms") else None)
        lines.append(
            f"| {r['case']} | {r['duration_s']:.0f} | {r['config']} | {r['mode']} | {r['exit']} | "
            f"{r['wall_s']:.1f} | {r['wall_s'] / r['duration_s']:.2f} | {r['peak_mb']:.0f} | "
            f"{cell(r.get('force_rms'), '.3f')} | {cell(r.get('correlation'), '.2f')} | {cell(r.get('lag_s'), '.2f')} | "
            f"{cell(r.get('direction_rms'), '.1f')} / {cell(r.get('direction_peak'), '.0f')} / "
            f"{cell(r.get('direction_made'), '.0f')} | "
            f"{cell(r.get('rotation_peak'), '.0f')} | {cell(r.get('reversals'), '.2f')} | "
            f"{cell(r.get('cross_coupling'), '.0f')} | {cell(r.get('msdv_z'), '.2f')} | "
            f"{cell(r.get('p99_ms'), '.1f')} | {cell(r.get('misses'), 'd')} | "
            f"{cell(r.get('classical_force_rms'), '.3f')} | {cell(r.get('classical_correlation'), '.2f')} | "
            f"{cell(r.get('classical_direction_peak'), '.0f')} / {cell(r.get('classical_direction_made'), '.0f')} | "
            f"{cell(r.get('classical_rotation_peak'), '.0f')} | "
            f"{cell(r.get('classical_cross_coupling'), '.0f')} | {cell(r.get('classical_msdv_z'), '.2f')} | "
            f"{cell(ratio, '.2f')} | {cell(r.get('forecast_closes'), '.0%')} |")
    return "\n".join(lines)


def forecast_closes(rows: list[dict]) -> None:
    """Set ``forecast_closes`` on each forecast row: (hold - forecast) / (hold - perfect) of the felt force
    RMS of the same case and configuration, where the gap is at least :data:`GAP` of hold's."""
    rms = {(r["case"], r["config"], r["mode"]): r.get("force_rms") for r in rows}
    for r in rows:
        if r["mode"] != "forecast":
            continue
        hold, perfect = rms.get((r["case"], r["config"], "hold")), rms.get((r["case"], r["config"], "perfect"))
        if None not in (hold, perfect, r.get("force_rms")) and abs(hold - perfect) >= GAP * hold:
            r["forecast_closes"] = (hold - r["force_rms"]) / (hold - perfect)


def reread(record: Path, keys, key_of) -> list[dict]:
    """The latest job of each key recorded in ``record`` (JSON lines), in the order of ``keys``; a key
    never recorded is left out. key_of : a job's key."""
    latest = {key_of(job): job for job in map(json.loads, record.read_text().splitlines())}
    return [latest[key] for key in keys if key in latest]


def recorder(record: Path, describe):
    """The ``progress`` of :func:`desdemona.runs.batch.map_jobs`: ``[count/total] describe(job)`` on
    stderr, and the job appended to ``record`` as it ends."""
    def progress(count, total, job):
        print(f"[{count}/{total}] {describe(job)}", file=sys.stderr, flush=True)
        with open(record, "a") as fh:
            fh.write(json.dumps(job) + "\n")

    return progress


def write_docs(text: str) -> None:
    """Replace the table between the markers in docs/benchmarks/real-inputs.md (append the section if missing)."""
    tables.replace_between(BEGIN, END, text, "Real inputs", DOCS)


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--corpus", type=Path, default=CORPUS,
                        help="corpus folder (the project's is built if missing), or a folder of one's own paths "
                             "(NAME.csv, read as it is)")
    parser.add_argument("--out", type=Path, default=RESULTS, help="folder of the jobs' result folders")
    parser.add_argument("--cases", nargs="+", default=None, help="only these cases (names in the index)")
    parser.add_argument("--configs", nargs="+", default=None, help="only these configurations")
    parser.add_argument("--modes", nargs="+", choices=MODES, default=MODES)
    parser.add_argument("--timeout", type=float, default=900.0, help="seconds per job before it is stopped")
    parser.add_argument("--processes", type=int, default=2)
    parser.add_argument("--dask", default=None, metavar="ADDRESS")
    parser.add_argument("--table-only", action="store_true", help="re-read the jobs of an earlier run")
    parser.add_argument("--no-docs", action="store_true", help="print the table, leave docs/benchmarks/real-inputs.md")
    parser.add_argument("--wall", type=float, default=None, metavar="M_S2",
                        help="off-line: the cost's wall before the position limits (optimize --wall; 0: "
                             "without, the formulation before it)")
    parser.add_argument("--rate", nargs="+", default=[], metavar="CONFIG=HZ",
                        help="on-line: the cycle rate of these configurations (online --step 1/HZ; "
                             "default the command's 50 Hz), e.g. dfs=100")
    parser.add_argument("--online-args", default="", metavar="ARGS",
                        help="on-line: more arguments for every job, e.g. '--perception none' to run the "
                             "formulation before a change side by side")
    parser.add_argument("--offline-args", default="", metavar="ARGS",
                        help="off-line: more arguments for every job, e.g. '--method ipopt' to run the "
                             "solver before a change side by side")
    args = parser.parse_args(argv)
    try:
        steps = {config: 1.0 / float(hz) for config, hz in (item.split("=") for item in args.rate)}
    except (ValueError, ZeroDivisionError):
        parser.error(f"--rate takes CONFIG=HZ, e.g. dfs=100, not {' '.join(args.rate)}")

    own = args.corpus.resolve() != CORPUS.resolve()
    if own and not ((args.corpus / "index.json").exists() or holds_own_paths(args.corpus)):
        parser.error(f"--corpus {args.corpus}: no paths there (no NAME.csv, no index.json); to build the corpus "
                     f"there: python benchmarks/corpus.py --out {args.corpus}")
    wanted = lambda name: args.cases is None or name in args.cases  # noqa: E731
    forecasts = {name for name in corpus.CASES if wanted(name)} if "forecast" in args.modes else set()
    cases = [c for c in corpus_cases(args.corpus, not args.table_only, forecasts) if wanted(c["name"])]
    for case in cases:
        case["file"] = str((args.corpus / case["file"]).resolve())
        if "forecast" in case:
            case["forecast"] = str((args.corpus / case["forecast"]).resolve())
    cases.sort(key=lambda c: c["duration_s"])  # the short cases' rows first: a long run shows them early
    jobs = [(case, config, mode) for case in cases for config in CONFIGS[case["form"]]
            if args.configs is None or config in args.configs for mode in args.modes
            if mode != "forecast" or "forecast" in case]
    for case in cases:
        if "forecast" in args.modes and "forecast" not in case:
            print(f"{case['name']}: no forecast beside it ({case['name']}.forecast.csv): no forecast rows",
                  file=sys.stderr)
    if own and not args.no_docs:
        print(f"--corpus {args.corpus}: not the project's corpus; its table is printed, docs/benchmarks/real-inputs.md "
              f"is left as it is", file=sys.stderr)
        args.no_docs = True
    args.out.mkdir(parents=True, exist_ok=True)
    record = args.out / "jobs.jsonl"
    load_before = os.getloadavg()
    spread_before = None if args.table_only else jitter()
    started = time.perf_counter()
    if args.table_only:
        done = reread(record, [(c["name"], config, mode) for c, config, mode in jobs],
                      lambda j: (j["case"], j["config"], j["mode"]))
    else:
        progress = recorder(record, lambda job: f"{job['case']} on {job['config']} ({job['mode']}): exit "
                                                f"{job['exit']}, {job['wall_s']:.1f} s, {job['peak_mb']:.0f} MB")
        done = batch.map_jobs(run_job, [(c, config, mode, str(args.out), args.timeout, args.wall,
                                         None if mode == "offline" else steps.get(config),
                                         tuple((args.offline_args if mode == "offline" else args.online_args).split()))
                                        for c, config, mode in jobs],
                              args.processes, args.dask, progress)
    paths = {(c["name"], c["form"]): profiles.load(c["file"]) for c in cases}
    order = {(c["name"], config, mode): k for k, (c, config, mode) in enumerate(jobs)}
    rows = sorted((read_result(j, dominant_force(paths[(j["case"], j["form"])])) for j in done),
                  key=lambda r: order[(r["case"], r["config"], r["mode"])])
    for r in rows:
        if "channel" in r:
            r["shape"] = shape_thresholds(paths[(r["case"], r["form"])], r["channel"])
            r["target_reversals"] = target_reversals(paths[(r["case"], r["form"])])
    online = {(r["case"], r["config"]): r for r in rows if r["mode"] != "offline" and "classical_force_rms" in r}
    for r in rows:  # the off-line rows beside the same classical loop
        if r["mode"] == "offline" and (r["case"], r["config"]) in online:
            r.update({k: v for k, v in online[(r["case"], r["config"])].items() if k.startswith("classical_")})
    forecast_closes(rows)
    with open(args.out / "real.csv", "w", newline="") as fh:
        keys = sorted({k for r in rows for k in r} - {"output"})
        writer = csv.DictWriter(fh, keys, extrasaction="ignore")
        writer.writeheader()
        writer.writerows(rows)
    load_after = os.getloadavg()
    text = table(rows)
    verdict = against_loop(rows)
    if verdict:
        text += "\n\n" + verdict
    loads = [r["load"] for r in rows if "load" in r]
    during = f"; 1-minute load average at the jobs' ends {min(loads):.1f}-{max(loads):.1f}" if loads else ""
    dates = sorted({r.get("date", "") for r in rows} - {""})
    if args.table_only:
        text = f"Measured {', '.join(dates) or 'earlier'} with `python benchmarks/real.py` ({len(rows)} jobs{during}).\n\n" + text
    else:
        elapsed, spread_after = time.perf_counter() - started, jitter()
        spread = "; a fixed millisecond of work: median {:.2f} ms and p99 {:.1f}x it before, {:.2f} ms and {:.1f}x after"
        text = (f"Measured {time.strftime('%Y-%m-%d')} with `python benchmarks/real.py` "
                f"({len(rows)} jobs, {args.processes} at a time, {elapsed:.0f} s in all; "
                f"load average {load_before[0]:.2f} before, {load_after[0]:.2f} after{during}"
                f"{spread.format(*spread_before, *spread_after)}).\n\n" + text)
    print(text)
    if not args.no_docs:
        write_docs(text)
    return 0


if __name__ == "__main__":
    sys.exit(main())

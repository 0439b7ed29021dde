"""Batches of off-line jobs: many profiles x configurations, on local processes or a Dask cluster.

Each job optimises one desired path on one configuration as ``optimize`` does
(:func:`desdemona.runs.solve.offline`: whole, or in windows for a long recording or with
``--window``) and writes its own result folder ``OUT/<profile>--<configuration>``; the batch ends with a table of all jobs (``OUT/batch.csv`` and
printed). Jobs are independent and deterministic (seeded), so a Dask ``distributed`` cluster gives
the same results as local processes; Dask is imported only when a scheduler address is given.
"""

from __future__ import annotations

import csv
import multiprocessing
import os
import socket
import time
from dataclasses import dataclass
from pathlib import Path

from desdemona import profiles
from desdemona.check import metrics
from desdemona.check.simulate import LimitViolation
from desdemona.cueing import sizing
from desdemona.cueing.offline import OptimizeOptions
from desdemona.machine.model import Model
from desdemona.machine.params import MachineParams
from desdemona.results import report
from desdemona.runs import session, solve
from desdemona.support import files, guard


#: [s] how long a Dask scheduler has to accept the connection (distributed's default is 30 s).
CONNECT_TIMEOUT = 3.0


@dataclass(frozen=True)
class Job:
    """One profile (built-in name or CSV file) on one configuration."""

    profile: str
    config: str
    view: bool = True  # also write view.html, the 3D replay, into the job's folder

    @property
    def folder_name(self) -> str:
        return f"{Path(self.profile).stem}--{self.config}"


@dataclass(frozen=True)
class JobResult:
    """One line of the batch table."""

    profile: str
    config: str
    status: str
    rms: float | None
    worst_use: float | None
    seconds: float
    folder: str
    message: str = ""
    felt: dict | None = None  # metrics.Metrics.key_figures of the result
    windows: int | None = None  # the windows it was solved in (1: whole)


FELT_COLUMNS = ("peak_false_rotation_deg_s", "felt_force_rms_max", "rms_modulus", "reversals_per_s_max")


def run_job(job: Job, params: MachineParams, choices: session.Choices, options: OptimizeOptions,
            out_dir: str) -> JobResult:
    """Optimise one job and write its folder; failures become a table line, not an exception.

    choices : the session's (:func:`desdemona.runs.solve.offline`, resolved for the job's path and
    configuration: whole or in windows, as ``optimize`` chooses); options : the starts, seed, workers
    and refine (its ``problem`` is the session's).
    """
    start = time.perf_counter()
    folder = Path(out_dir) / job.folder_name
    try:
        result = solve.offline(profiles.load(job.profile), Model(params, job.config), choices,
                               workers=options.workers, starts=options.starts, seed=options.seed,
                               refine=options.refine)
        report.write(result, folder, command=f"desdemona batch ({job.profile} on {job.config})", overwrite=True,
                     view=job.view)
        status = "ok" if result.converged else "not converged"
        return JobResult(job.profile, job.config, status, result.check.rms, result.check.worst_use,
                         time.perf_counter() - start, str(folder), "" if result.converged else result.solution.status,
                         result.quality.key_figures(), result.timings.get("windows", 1))
    except LimitViolation as exc:
        return JobResult(job.profile, job.config, "no safe trajectory", None, exc.check.worst_use,
                         time.perf_counter() - start, "", str(exc))
    except (ValueError, RuntimeError) as exc:
        return JobResult(job.profile, job.config, "error", None, None, time.perf_counter() - start, "", str(exc))


TABLE_COLUMNS = ("profile", "configuration", "status", "rms", "worst_use", *FELT_COLUMNS, "windows", "seconds",
                 "folder", "message")


def check_out(out_dir: str | Path, overwrite: bool = False) -> None:
    """Raise :class:`~desdemona.results.report.ReportError` unless the batch may write into ``out_dir``: a
    folder that does not exist yet or is empty, or with ``overwrite`` an earlier batch folder of ours
    (holding only its ``batch.csv`` and result folders of desdemona), whose files it replaces."""
    report.check_out_folder(out_dir, overwrite, _ours, "batch folder")


def _ours(path: Path) -> bool:
    """Whether ``path`` in a batch folder is something a batch wrote: its table or a job's result folder."""
    if path.name == "batch.csv":
        return _is_table(path)
    return path.is_dir() and not path.is_symlink() and report.is_result_folder(path)


def _is_table(path: Path) -> bool:
    """Whether ``path`` is a batch.csv of ours: its header names our first and last columns (the felt
    ones between have changed between versions)."""
    try:
        with open(path, newline="") as fh:
            header = next(csv.reader(fh), [])
        return header[:5] == list(TABLE_COLUMNS[:5]) and header[-3:] == list(TABLE_COLUMNS[-3:])
    except (OSError, UnicodeDecodeError):
        return False


def validate(jobs: list[Job], params: MachineParams, choices: session.Choices, options: OptimizeOptions,
             out_dir: str | Path, overwrite: bool = False, max_time: float | None = None) -> None:
    """Check every job before any runs: the batch's folder (:func:`check_out`), each job's
    configuration, its path (each CSV read and checked) and its session (:func:`desdemona.runs.session.offline`:
    the path suits the configuration, the choices are valid for it, the problem fits in memory and in
    its time, ``max_time`` or :func:`desdemona.cueing.sizing.time_limit`), and that its folder is free
    or an earlier result. Raises ValueError (:class:`~desdemona.profiles.ProfileError`,
    :class:`~desdemona.runs.session.ChoiceError`, :class:`~desdemona.cueing.sizing.TooLarge`,
    :class:`~desdemona.cueing.sizing.TooLong`) or :class:`~desdemona.results.report.ReportError` naming the job."""
    check_out(out_dir, overwrite)
    paths = {}
    for job in jobs:
        if job.profile not in paths:
            paths[job.profile] = profiles.load(job.profile)
        try:
            job_session = solve.resolve(paths[job.profile], Model(params, job.config), choices,
                                        workers=options.workers, starts=options.starts)
        except (session.ChoiceError, profiles.ProfileError) as exc:
            raise type(exc)(f"{job.profile} on {job.config}: {exc}") from None
        problem = job_session.options
        sizing.check_time(job_session.path, job_session.model.config, problem.h_u, problem.solver, options.starts,
                          job_session.workers, job_session.window, max_time)
        folder = Path(out_dir) / job.folder_name
        report.check_replaceable(folder, protect=[job.profile] if Path(job.profile).is_file() else [])


def run_batch(jobs: list[Job], params: MachineParams, choices: session.Choices, options: OptimizeOptions,
              out_dir: str | Path, processes: int = 2, dask_address: str | None = None, progress=None,
              overwrite: bool = False, max_time: float | None = None) -> list[JobResult]:
    """Run every job, on ``processes`` local processes or on the Dask scheduler at ``dask_address``;
    ``choices`` and ``options`` as in :func:`run_job`; ``overwrite``: replace an earlier batch in
    ``out_dir`` (:func:`check_out`).

    Every job is validated (:func:`validate`, each within ``max_time``) before anything runs. progress : optional
    ``progress(done, total, job_result)`` told as each job ends. Returns the jobs' lines in the order
    given and writes them to ``OUT/batch.csv``. Interrupted, it stops the local workers (or cancels the
    cluster's jobs); the jobs done by then keep their folders, and ``batch.csv`` lists them with the
    others as "interrupted" (the :class:`~desdemona.support.guard.Interrupted` raised says so).
    """
    if dask_address is not None:
        reach_scheduler(dask_address)
    validate(jobs, params, choices, options, out_dir, overwrite, max_time)
    out = Path(out_dir)
    created = not out.exists()
    try:
        out.mkdir(parents=True, exist_ok=True)
    except OSError as exc:
        raise report.ReportError(f"{out}: cannot create it: {exc.strerror or exc}") from None
    results: list[JobResult | None] = [None] * len(jobs)
    try:
        map_jobs(run_job, [(job, params, choices, options, str(out)) for job in jobs], processes,
                 dask_address, progress, results)
    except guard.Interrupted as exc:
        done = sum(r is not None for r in results)
        if done == 0:
            if created and not any(out.iterdir()):
                out.rmdir()  # interrupted before any job finished: leave nothing behind
            raise
        _write_table(out, [r or JobResult(j.profile, j.config, "interrupted", None, None, 0.0, "")
                           for j, r in zip(jobs, results)])
        exc.message = (f"interrupted ({exc.name}): stopped; {done} of {len(jobs)} jobs were done, their folders "
                       f"and {out / 'batch.csv'} are kept (the others are marked 'interrupted')")
        raise
    except BaseException:
        if created and not any(out.iterdir()):
            out.rmdir()
        raise
    _write_table(out, results)
    return results


def _write_table(out: Path, results: list[JobResult]) -> None:
    """Write ``out/batch.csv`` whole or not at all (a temporary file renamed into place)."""
    with files.beside(out / "batch.csv") as tmp:
        with open(tmp, "w", newline="") as fh:
            writer = csv.writer(fh)
            writer.writerow(TABLE_COLUMNS)
            for r in results:
                felt = [None if r.felt is None else r.felt[c] for c in FELT_COLUMNS]
                writer.writerow([r.profile, r.config, r.status, r.rms, r.worst_use, *felt, r.windows,
                                 f"{r.seconds:.3f}", r.folder, r.message])
        with guard.deferred():
            os.replace(tmp, out / "batch.csv")


def reach_scheduler(address: str, timeout: float = CONNECT_TIMEOUT) -> None:
    """Refuse, with :class:`session.ChoiceError`, a ``tcp://host:port`` Dask scheduler address where nothing
    accepts a connection within ``timeout`` [s]; before Dask is imported (seconds) or anything is
    validated, so that a wrong address is one line at once, not a half-minute wait and a traceback.
    Other schemes (tls://, inproc://) are left to Dask's own connect, also bounded by ``timeout``."""
    scheme, _, rest = address.rpartition("://")
    if scheme not in ("", "tcp"):
        return
    host, _, port = rest.rpartition(":")
    try:
        with socket.create_connection((host.strip("[]") or "127.0.0.1", int(port)), timeout=timeout):
            pass
    except ValueError:
        raise session.ChoiceError(f"--dask {address}: give the scheduler as tcp://HOST:PORT, e.g. "
                                  "tcp://127.0.0.1:8786") from None
    except OSError as exc:
        raise session.ChoiceError(f"--dask {address}: no Dask scheduler there "
                                  f"({exc.strerror or exc or 'no answer'}); start one with 'dask scheduler' "
                                  "or drop --dask to run on this computer's processes") from None


def map_jobs(function, args: list[tuple], processes: int = 2, dask_address: str | None = None, progress=None,
             results: list | None = None) -> list:
    """``function(*a)`` for every tuple ``a`` of ``args``, on ``processes`` local processes (spawned) or
    on the Dask scheduler at ``dask_address``; the results in the order of ``args``.

    ``function`` must be importable by the workers (a module's top-level function). progress : optional
    ``progress(done, total, result)`` told as each call ends. results : a list of ``len(args)`` Nones
    filled as calls end, for a caller that keeps what was done when the run is interrupted; leaving
    early stops the local workers (or cancels the cluster's calls).
    """
    results = [None] * len(args) if results is None else results

    def done(index, result):
        results[index] = result
        if progress is not None:
            progress(sum(r is not None for r in results), len(args), result)

    if dask_address is not None:
        from distributed import Client, as_completed

        try:
            client = Client(dask_address, timeout=CONNECT_TIMEOUT)
        except OSError as exc:  # distributed's own wait for the scheduler, bounded
            raise session.ChoiceError(f"--dask {dask_address}: no Dask scheduler answered ({exc})") from None
        with client:
            futures = [client.submit(function, *a, pure=False) for a in args]
            index = {f.key: i for i, f in enumerate(futures)}
            try:
                for future in as_completed(futures):
                    done(index[future.key], future.result())
            except BaseException:
                client.cancel(futures)
                raise
    else:
        context = multiprocessing.get_context("spawn")
        # leaving the block terminates the workers, also when the run is interrupted
        with context.Pool(max(1, min(processes, len(args))), initializer=guard.worker_signals,
                          initargs=(True,)) as pool:
            for i, result in pool.imap_unordered(_indexed_call, [(i, function, a) for i, a in enumerate(args)]):
                done(i, result)
            guard.finish(pool)
    return results


def _indexed_call(item):
    index, function, args = item
    return index, function(*args)


def table(results: list[JobResult]) -> str:
    """The batch's printed table: per job its status, RMS, worst limit use, what is felt (peak false
    rotation [deg/s], worst felt force error RMS [m/s^2], most acceleration reversals per second) and
    the windows it was solved in (1: whole) and its time; a second line gives the units (RMS: weighted as the run's --weights, mixed units)."""
    def cell(value, fmt):
        return "-" if value is None else format(value, fmt)

    lines = [f"{'profile':<18}{'configuration':<18}{'status':<20}{'RMS':>10}{'worst use':>11}{'false rot':>11}"
             f"{'felt f':>9}{'rev/s':>9}{'windows':>9}{'time [s]':>10}",
             f"{'':<56}{'weighted':>10}{'1 = limit':>11}{'[deg/s]':>11}{'[m/s^2]':>9}"]
    for r in results:
        felt = r.felt or {}
        lines.append(f"{r.profile:<18}{r.config:<18}{r.status:<20}{cell(r.rms, '.4g'):>10}"
                     f"{cell(r.worst_use, '.4f'):>11}{cell(metrics.shown(felt.get('peak_false_rotation_deg_s')), '.3g'):>11}"
                     f"{cell(felt.get('felt_force_rms_max'), '.3g'):>9}"
                     f"{cell(felt.get('reversals_per_s_max'), '.3g'):>9}{cell(r.windows, 'd'):>9}{r.seconds:>10.2f}")
        if r.message:
            lines.append(f"    {r.message}")
    return "\n".join(lines)

"""Batches of off-line jobs: many profiles x configurations, on local processes or a Dask cluster.

Each job optimises one desired path on one configuration and writes its own result folder
``OUT/<profile>--<configuration>``; the batch ends with a table of all jobs (``OUT/batch.csv`` and
printed). Jobs are independent and deterministic (seeded), so a Dask ``distributed`` cluster gives
the same results as local processes; Dask is imported only when a scheduler address is given.
"""

from __future__ import annotations

import csv
import dataclasses
import multiprocessing
import time
from dataclasses import dataclass
from pathlib import Path

from desdemona import guard, profiles, report, sizing
from desdemona.configs import get_configuration
from desdemona.model import Model
from desdemona.offline import OptimizeOptions, optimize
from desdemona.params import MachineParams
from desdemona.simulate import LimitViolation


@dataclass(frozen=True)
class Job:
    """One profile (built-in name or CSV file) on one configuration."""

    profile: str
    config: str

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


FELT_COLUMNS = ("peak_false_rotation_deg_s", "felt_force_rms_max", "rms_modulus", "sign_changes_per_s_max")


def run_job(job: Job, params: MachineParams, options: OptimizeOptions, out_dir: str, weights=None,
            gain: float = 1.0) -> JobResult:
    """Optimise one job and write its folder; failures become a table line, not an exception.

    weights : a spec of :func:`profiles.weights_for`, resolved for the job's path (after its ``gain``),
    "auto" for the configuration's default (:attr:`Configuration.default_weights`), or None for
    ``options.problem.weights``.
    """
    start = time.perf_counter()
    folder = Path(out_dir) / job.folder_name
    try:
        config = get_configuration(job.config)
        path = config.cue_path(profiles.load(job.profile).with_gain(gain))
        if weights is not None:
            spec = config.default_weights if weights == "auto" else weights
            problem = dataclasses.replace(options.problem, weights=tuple(profiles.weights_for(spec, path)))
            options = dataclasses.replace(options, problem=problem)
        result = optimize(path, Model(params, job.config), options)
        report.write(result, folder, command=f"desdemona batch ({job.profile} on {job.config})", overwrite=True)
        status = "ok" if result.converged else "not converged"
        return JobResult(job.profile, job.config, status, result.check.rms, result.check.worst_use,
                         time.perf_counter() - start, str(folder), "" if result.converged else result.solution.status,
                         result.quality.key_figures())
    except LimitViolation as exc:
        return JobResult(job.profile, job.config, "no safe trajectory", None, exc.check.worst_use,
                         time.perf_counter() - start, "", str(exc))
    except (ValueError, RuntimeError) as exc:
        return JobResult(job.profile, job.config, "error", None, None, time.perf_counter() - start, "", str(exc))


def validate(jobs: list[Job], params: MachineParams, options: OptimizeOptions, out_dir: str | Path) -> None:
    """Check every job before any runs: its configuration, its path (each CSV read and checked), that
    the path suits the configuration, that the problem fits in memory, and that its folder is free or
    an earlier result. Raises ValueError (:class:`~desdemona.profiles.ProfileError`,
    :class:`~desdemona.sizing.TooLarge`) or :class:`~desdemona.report.ReportError` naming the job."""
    paths = {}
    for job in jobs:
        config = get_configuration(job.config)
        if job.profile not in paths:
            paths[job.profile] = profiles.load(job.profile)
        path = paths[job.profile]
        if not config.takes_modulus and path.S_d is None:
            raise profiles.ProfileError(f"{job.profile}: gives only the modulus t,M; configuration "
                                        f"{config.name!r} needs the full path t,wx,wy,wz,fx,fy,fz")
        if not options.problem.h_u <= path.duration:
            raise profiles.ProfileError(f"{job.profile}: h_u {options.problem.h_u:g} s is longer than the path "
                             f"({path.duration:g} s)")
        sizing.check_fits(path, config, options.problem, options.workers)
        folder = Path(out_dir) / job.folder_name
        report.check_replaceable(folder, protect=[job.profile] if Path(job.profile).is_file() else [])


def run_batch(jobs: list[Job], params: MachineParams, options: OptimizeOptions, out_dir: str | Path,
              processes: int = 2, dask_address: str | None = None, weights=None, gain: float = 1.0,
              progress=None) -> list[JobResult]:
    """Run every job, on ``processes`` local processes or on the Dask scheduler at ``dask_address``;
    ``weights`` and ``gain`` as in :func:`run_job`.

    Every job is validated (:func:`validate`) before anything runs. progress : optional
    ``progress(done, total, job_result)`` told as each job ends. Returns the jobs' lines in the order
    given and writes them to ``OUT/batch.csv``. Interrupted, it stops the local workers (or cancels the
    cluster's jobs) and writes no table.
    """
    validate(jobs, params, options, out_dir)
    out = Path(out_dir)
    created = not out.exists()
    out.mkdir(parents=True, exist_ok=True)
    try:
        results = _run(jobs, [(job, params, options, str(out), weights, gain) for job in jobs], processes,
                       dask_address, progress)
    except BaseException:
        if created and not any(out.iterdir()):
            out.rmdir()  # interrupted before any job finished: leave nothing behind
        raise
    with open(out / "batch.csv", "w", newline="") as fh:
        writer = csv.writer(fh)
        writer.writerow(["profile", "configuration", "status", "rms", "worst_use", *FELT_COLUMNS, "seconds",
                         "folder", "message"])
        for r in results:
            felt = [None if r.felt is None else r.felt[c] for c in FELT_COLUMNS]
            writer.writerow([r.profile, r.config, r.status, r.rms, r.worst_use, *felt, f"{r.seconds:.3f}",
                             r.folder, r.message])
    return results


def _run(jobs, args, processes, dask_address, progress) -> list[JobResult]:
    results: list[JobResult | None] = [None] * len(jobs)

    def done(index, result):
        results[index] = result
        if progress is not None:
            progress(sum(r is not None for r in results), len(jobs), result)

    if dask_address is not None:
        from distributed import Client, as_completed

        with Client(dask_address) as client:
            futures = [client.submit(run_job, *a, pure=False) for a in args]
            index = {f.key: i for i, f in enumerate(futures)}
            try:
                for future in as_completed(futures):
                    done(index[future.key], future.result())
            except BaseException:
                client.cancel(futures)
                raise
    else:
        context = multiprocessing.get_context("spawn")
        # leaving the block terminates the workers, also when the batch is interrupted
        with context.Pool(max(1, min(processes, len(jobs))), initializer=guard.worker_signals,
                          initargs=(True,)) as pool:
            for i, result in pool.imap_unordered(_indexed_job, list(enumerate(args))):
                done(i, result)
            guard.finish(pool)
    return results


def _indexed_job(item):
    index, args = item
    return index, run_job(*args)


def table(results: list[JobResult]) -> str:
    """The batch's printed table: per job its status, RMS, worst limit use, what is felt (peak false
    rotation [deg/s], worst felt force error RMS [m/s^2], most acceleration reversals per second) and
    its time."""
    def cell(value, fmt):
        return "-" if value is None else format(value, fmt)

    lines = [f"{'profile':<18}{'configuration':<18}{'status':<20}{'RMS':>10}{'worst use':>11}{'false rot':>11}"
             f"{'felt f':>9}{'flips/s':>9}{'time [s]':>10}"]
    for r in results:
        felt = r.felt or {}
        lines.append(f"{r.profile:<18}{r.config:<18}{r.status:<20}{cell(r.rms, '.4g'):>10}"
                     f"{cell(r.worst_use, '.4f'):>11}{cell(felt.get('peak_false_rotation_deg_s'), '.3g'):>11}"
                     f"{cell(felt.get('felt_force_rms_max'), '.3g'):>9}"
                     f"{cell(felt.get('sign_changes_per_s_max'), '.3g'):>9}{r.seconds:>10.2f}")
        if r.message:
            lines.append(f"    {r.message}")
    return "\n".join(lines)

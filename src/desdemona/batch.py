"""Batches of off-line jobs: many profiles x configurations, on local processes or a Dask cluster.

Each job optimises one desired path on one configuration and writes its own result folder
``OUT/<profile>--<configuration>``; the batch ends with a table of all jobs (``OUT/batch.csv`` and
printed). Jobs are independent and deterministic (seeded), so a Dask ``distributed`` cluster gives
the same results as local processes; Dask is imported only when a scheduler address is given.
"""

from __future__ import annotations

import concurrent.futures
import csv
import dataclasses
import multiprocessing
import time
from dataclasses import dataclass
from pathlib import Path

from desdemona import profiles, report
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


def load_path(profile: str) -> profiles.DesiredPath:
    return profiles.get_profile(profile) if profile in profiles.PROFILES else profiles.read_csv(profile)


def run_job(job: Job, params: MachineParams, options: OptimizeOptions, out_dir: str, weights=None,
            gain: float = 1.0) -> JobResult:
    """Optimise one job and write its folder; failures become a table line, not an exception.

    weights : a spec of :func:`profiles.weights_for`, resolved for the job's path (after its ``gain``),
    or None for ``options.problem.weights``.
    """
    start = time.perf_counter()
    folder = Path(out_dir) / job.folder_name
    try:
        path = load_path(job.profile).with_gain(gain)
        if weights is not None:
            problem = dataclasses.replace(options.problem, weights=tuple(profiles.weights_for(weights, path)))
            options = dataclasses.replace(options, problem=problem)
        result = optimize(path, Model(params, job.config), options)
        report.write(result, folder, command=f"desdemona batch ({job.profile} on {job.config})", overwrite=True)
        return JobResult(job.profile, job.config, "ok", result.check.rms, result.check.worst_use,
                         time.perf_counter() - start, str(folder))
    except LimitViolation as exc:
        return JobResult(job.profile, job.config, "no safe trajectory", None, exc.check.worst_use,
                         time.perf_counter() - start, "", str(exc))
    except (ValueError, RuntimeError) as exc:
        return JobResult(job.profile, job.config, "error", None, None, time.perf_counter() - start, "", str(exc))


def run_batch(jobs: list[Job], params: MachineParams, options: OptimizeOptions, out_dir: str | Path,
              processes: int = 2, dask_address: str | None = None, weights=None,
              gain: float = 1.0) -> list[JobResult]:
    """Run every job, on ``processes`` local processes or on the Dask scheduler at ``dask_address``;
    ``weights`` and ``gain`` as in :func:`run_job`.

    Profiles and configurations are validated before anything runs. Returns the jobs' lines in the
    order given and writes them to ``OUT/batch.csv``.
    """
    for job in jobs:
        get_configuration(job.config)
        if job.profile not in profiles.PROFILES and not Path(job.profile).is_file():
            profiles.get_profile(job.profile)  # raises, naming the built-in profiles
    out = Path(out_dir)
    out.mkdir(parents=True, exist_ok=True)
    args = [(job, params, options, str(out), weights, gain) for job in jobs]
    if dask_address is not None:
        from distributed import Client

        with Client(dask_address) as client:
            futures = [client.submit(run_job, *a, pure=False) for a in args]
            results = client.gather(futures)
    else:
        context = multiprocessing.get_context("spawn")
        with concurrent.futures.ProcessPoolExecutor(max(1, processes), mp_context=context) as pool:
            results = list(pool.map(run_job, *zip(*args)))
    with open(out / "batch.csv", "w", newline="") as fh:
        writer = csv.writer(fh)
        writer.writerow(["profile", "configuration", "status", "rms", "worst_use", "seconds", "folder", "message"])
        for r in results:
            writer.writerow([r.profile, r.config, r.status, r.rms, r.worst_use, f"{r.seconds:.3f}", r.folder,
                             r.message])
    return results


def table(results: list[JobResult]) -> str:
    lines = [f"{'profile':<18}{'configuration':<18}{'status':<20}{'RMS':>10}{'worst use':>11}{'time [s]':>10}"]
    for r in results:
        rms = "-" if r.rms is None else f"{r.rms:.4g}"
        worst = "-" if r.worst_use is None else f"{r.worst_use:.4f}"
        lines.append(f"{r.profile:<18}{r.config:<18}{r.status:<20}{rms:>10}{worst:>11}{r.seconds:>10.2f}")
        if r.message:
            lines.append(f"    {r.message}")
    return "\n".join(lines)

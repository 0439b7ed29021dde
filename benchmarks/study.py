"""A design study's scale: the same study on local processes and on a local Dask cluster, timed.

    python benchmarks/study.py                          # 50 points, 2 workers each way
    python benchmarks/study.py --points 25 --workers 2  # 25 sample points x 2 recordings

The study: ``--points`` points of a Latin hypercube over the track's acceleration limit and the yaw's
rate limit, times two short built-in recordings (cosine, double-pulse) on ``yaw-track`` at ``--h-u``
0.1 s, one start each: short points, so that what is measured beside the solve (starting the workers,
sending the points, writing the folders, the table) shows. Run twice, each into a new study folder, on
one warm compiled cache:

1. ``local``: ``--workers`` local processes (:func:`desdemona.runs.batch.map_jobs`' spawned pool);
2. ``dask``: a Dask ``LocalCluster`` of ``--workers`` worker processes of one thread each on
   127.0.0.1, the study sent to its scheduler (``--dask``).

Per run: the wall time (from the plan to the table, figures not included), the throughput, the mean
time a point takes inside its worker (the session and its folder: ``run_point``'s own clock), the
overhead per point (``workers x wall - the points' own seconds``, over the points: the time a worker
spends on anything but a point), the peak resident memory of the largest worker (local: of the
waited-for children; Dask: each worker's own ``ru_maxrss``), and the load average before and after.
And what the scheduler holds: one task per point, the pickled size of a task's arguments and of its
result. The two tables must be the same but for the folders and times (checked). OpenBLAS runs one thread per
process (:func:`desdemona.support.allocator.one_blas_thread`), as the command line sets it for its
workers and Dask's workers set it by default.
"""

from __future__ import annotations

import argparse
import pickle
import resource
import sys
import tempfile
import time
from pathlib import Path

from desdemona.cueing.offline import OptimizeOptions
from desdemona.runs import session, study

RECORDINGS = ("cosine", "double-pulse")
SAMPLE = (("joints.track.acceleration_m_s2", 2.0, 6.0), ("joints.yaw.velocity_deg_s", 60.0, 155.4))
RUN_COLUMNS = ("folder", "solve_s")


def load() -> str:
    return Path("/proc/loadavg").read_text().split()[0]


def worker_peak() -> float:
    """[MB] this process' peak resident memory (Linux: ru_maxrss in kB)."""
    return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024.0


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--points", type=int, default=25, help="sample points (times 2 recordings; default 25)")
    parser.add_argument("--workers", type=int, default=2)
    parser.add_argument("--h-u", type=float, default=0.1, dest="h_u")
    args = parser.parse_args()
    from distributed import LocalCluster

    from desdemona.support import allocator

    allocator.one_blas_thread()  # as the command line does (and Dask's workers by default)
    allocator.reuse_freed_memory()

    asked = study.Study(RECORDINGS, ("yaw-track",), sample=SAMPLE, points=args.points, seed=0)
    choices, options = session.Choices(h_u=args.h_u), OptimizeOptions(starts=1)
    planned = study.plan(asked, choices, options)
    task = len(pickle.dumps((planned[0][0], planned[0][1], choices, options, "OUT")))
    result = len(pickle.dumps({"status": "ok", "message": "", "seconds": 1.0}))
    results = {}
    with tempfile.TemporaryDirectory(prefix="study-bench-") as work:
        # a warm cache: the points' libraries compiled once, before either run is timed
        study.run_study(planned, choices, options, Path(work) / "warm", args.workers)
        results["local"] = timed_local(planned, choices, options, Path(work) / "local", args.workers)
        with LocalCluster(n_workers=args.workers, threads_per_worker=1, processes=True, host="127.0.0.1",
                          dashboard_address=None) as cluster:
            results["dask"] = timed_dask(planned, choices, options, Path(work) / "dask", args.workers, cluster)
    same = all({k: v for k, v in a.items() if k not in RUN_COLUMNS} == {k: v for k, v in b.items()
                                                                       if k not in RUN_COLUMNS}
               for a, b in zip(results["local"]["rows"], results["dask"]["rows"]))
    print(f"{len(planned)} points ({args.points} sample points x {len(RECORDINGS)} recordings, yaw-track, --h-u "
          f"{args.h_u:g}, 1 start), {args.workers} workers each way; the tables the same: {same}\n")
    print("| run | wall [s] | points/s | a point in its worker [s] (solve) | overhead per point [s] "
          "| largest worker's peak RSS [MB] | load before-after |")
    print("| --- | --- | --- | --- | --- | --- | --- |")
    for name, r in results.items():
        print(f"| {name} | {r['wall']:.1f} | {r['throughput']:.2f} | {r['own']:.2f} ({r['solve']:.2f}) | "
              f"{r['overhead']:.2f} | {r['memory']:.0f} | {r['load']} |")
    print(f"\nthe scheduler holds one task per point: its arguments {task / 1024:.1f} kB pickled, its result "
          f"{result} B")
    return 0 if same else 1


def timed_local(planned, choices, options, out: Path, workers: int) -> dict:
    before = resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss
    timed = _timed(planned, choices, options, out, workers, None)
    peak = resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss
    timed["memory"] = max(peak, before) / 1024.0  # the largest child's peak, warm-up's included
    return timed


def timed_dask(planned, choices, options, out: Path, workers: int, cluster) -> dict:
    from distributed import Client

    timed = _timed(planned, choices, options, out, workers, cluster.scheduler_address)
    with Client(cluster.scheduler_address) as client:
        timed["memory"] = max(client.run(worker_peak).values())
    return timed


def _timed(planned, choices, options, out: Path, workers: int, dask: str | None) -> dict:
    """One run, as :func:`desdemona.runs.study.run_study` runs it (the folder checked, the points mapped,
    the table written), keeping each point's own seconds (its worker's clock): wall, throughput, a
    point's own seconds, the overhead."""
    from desdemona.runs import batch

    before, start = load(), time.perf_counter()
    study.check_folder(out)
    (out / "points").mkdir(parents=True)
    args = [(p, params, choices, options, str(out)) for p, params in planned]
    ran = batch.map_jobs(study.run_point, args, workers, dask)
    rows = study.table_rows(planned, out, planned, ran, "missing")
    study.write_table(out, rows)
    wall = time.perf_counter() - start
    own = [r["seconds"] for r in ran]
    return {"rows": rows, "wall": wall, "load": f"{before}-{load()}", "own": sum(own) / len(own),
            "overhead": (workers * wall - sum(own)) / len(planned), "throughput": len(planned) / wall,
            "solve": sum(r["solve_s"] for r in rows) / len(rows)}


if __name__ == "__main__":
    sys.exit(main())

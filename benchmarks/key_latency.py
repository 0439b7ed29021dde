"""Whether a shared key costs the service latency: served sessions with and without ``--key``, in
alternating pairs, on their pooled cycles.

    python benchmarks/key_latency.py                       # dfs at 100 Hz, a 120 Hz host, 6 pairs of 25 s, pinned
    python benchmarks/key_latency.py --run full-50-host60 --pairs 4 --seconds 40

One session against another differs by more than 0.2 ms at p99 with or without a key (the machine's
own noise: docs/benchmarks/real-time-service.md), so a single pair cannot show a bound that tight.
Here the runs of ``benchmarks/service.py`` (its processes, its ``--pin``: the service on a core of
its own) alternate in the order unsigned, signed, signed, unsigned, ... (so that a drift of the
machine's load over the runs falls on both alike), and the latencies (host message received to
setpoint sent) of every cycle of each kind are pooled (the folders in ``benchmarks/key-latency-results``): the p99 of the pooled cycles of each kind, and
per pair the difference of the two sessions' p99s (median and range).
"""

from __future__ import annotations

import argparse
import os
import sys

import numpy as np
import service  # benchmarks/service.py: the runs, their processes and folders


def latencies(name: str, signed: bool) -> np.ndarray:
    folder = service.RESULTS / (f"{name}-key" if signed else name) / "served"
    values = np.array([float(c["latency_s"]) for c in service._cycles(folder)])
    return 1e3 * values[np.isfinite(values)]


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--run", default="dfs-100-host120", choices=tuple(service.RUNS))
    parser.add_argument("--pairs", type=int, default=6)
    parser.add_argument("--seconds", type=float, default=25.0)
    parser.add_argument("--no-pin", action="store_true")
    args = parser.parse_args(argv)
    service.STOP = min(service.FLIGHT_END, service.START + args.seconds)
    service.RESULTS = service.HERE / "key-latency-results"  # not the folders of service.py's own table
    cores = sorted(os.sched_getaffinity(0))
    if not args.no_pin and len(cores) >= 2:
        service.PIN = (str(cores[-1]), ",".join(map(str, cores[:-1])))
    pooled = {False: [], True: []}
    p99 = {False: [], True: []}
    load = [os.getloadavg()[0]]
    for k in range(args.pairs):
        for signed in ((False, True) if k % 2 == 0 else (True, False)):
            service.serve_run(args.run, signed)
            values = latencies(args.run, signed)
            pooled[signed].append(values)
            p99[signed].append(float(np.percentile(values, 99)))
            print(f"pair {k + 1}, {'signed' if signed else 'unsigned'}: {values.size} cycles, median "
                  f"{np.median(values):.2f} ms, p99 {p99[signed][-1]:.2f} ms", flush=True)
        load.append(os.getloadavg()[0])
    differences = np.array(p99[True]) - np.array(p99[False])
    print(f"\n{args.run}, {args.pairs} pairs of {args.seconds:g} s, pinned: {service.PIN is not None}, "
          f"load {min(load):.2f}-{max(load):.2f}")
    for signed in (False, True):
        values = np.concatenate(pooled[signed])
        print(f"  {'signed' if signed else 'unsigned'}: {values.size} cycles, median {np.median(values):.3f} ms, "
              f"p99 {np.percentile(values, 99):.3f} ms (sessions' p99 {min(p99[signed]):.2f}-{max(p99[signed]):.2f})")
    print(f"  signed less unsigned, per pair's p99: median {np.median(differences):+.3f} ms, range "
          f"{differences.min():+.3f} to {differences.max():+.3f} ms")
    return 0


if __name__ == "__main__":
    sys.exit(main())

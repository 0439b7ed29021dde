"""The corpus' fighter cases off-line, warm: wall time against the recording's duration.

    python benchmarks/fighters.py                                  # this checkout
    python benchmarks/fighters.py --before OLD/src                # and an older one, side by side
    python benchmarks/fighters.py --cases f16-turn:full f16-turn-M:dfs

For each code (this checkout's ``src``, and with ``--before`` another ``src`` folder, e.g. from ``git
archive 65a7de7 | tar -x``) and each case, ``desdemona optimize benchmarks/corpus/CASE.csv --config
CONFIG`` with its defaults (four starts, on the cores' workers, windows of 30 s for the 10-minute sortie),
once untimed (``--warm`` runs: what a user's earlier run left in the cache) and once timed, in the
user's cache. The corpus is made by ``benchmarks/corpus.py``.

Printed: one markdown row per run, the wall time, its ratio to the recording's duration, the RMS the
command printed, the load average before and after. Nothing else should run meanwhile (the load says
how quiet it was). ``docs/benchmarks/fighters-off-line.md`` has the table.
"""

from __future__ import annotations

import argparse
import csv
import os
import sys
from pathlib import Path

import first_run  # benchmarks/first_run.py: one command timed (the script's own folder is on the path)

HERE = Path(__file__).resolve().parent
CORPUS = HERE / "corpus"
CASES = ("f16-turn:full", "f16-turn-M:dfs", "f16-sortie:full", "f16-sortie-M:dfs")


def duration(case: str) -> float:
    with open(CORPUS / f"{case}.csv", newline="") as f:
        times = [float(row[0]) for row in csv.reader(line for line in f if not line.startswith("#")) if row
                 and row[0] != "t"]
    return times[-1] - times[0]


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--before", type=Path, help="another checkout's src folder, timed first")
    parser.add_argument("--cases", nargs="+", default=list(CASES), metavar="CASE:CONFIG")
    parser.add_argument("--warm", type=int, default=1, help="untimed runs of each case before the timed one")
    parser.add_argument("--out", type=Path, default=HERE / "fighters-results")
    args = parser.parse_args(argv)
    cache = Path(os.environ.get("DESDEMONA_CACHE") or Path.home() / ".cache" / "desdemona")
    args.out.mkdir(parents=True, exist_ok=True)
    codes = ([("before", args.before.resolve())] if args.before else []) + [("this", first_run.HERE)]
    print("| case | config | code | wall [s] | x duration | RMS | load |\n| --- | --- | --- | --- | --- | --- | --- |")
    for item in args.cases:
        case, config = item.split(":")
        seconds = duration(case)
        for label, src in codes:
            out = args.out / f"{label}-{case}-{config}"
            argv = ["optimize", str(CORPUS / f"{case}.csv"), "--config", config, "--out", str(out), "--overwrite",
                    "--no-view", "--max-time", "7200"]
            for _ in range(args.warm):
                first_run.timed(src, cache, argv, timeout=7200)
            run = first_run.timed(src, cache, argv, timeout=7200)
            print(f"| {case} | {config} | {label} | {run['wall']:.1f} | {run['wall'] / seconds:.2f} | {run['rms']} | "
                  f"{run['load']} |", flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())

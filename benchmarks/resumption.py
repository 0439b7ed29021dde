"""Resumption after the stand-in's own stop: a served session whose service stalls, again and again.

    python benchmarks/resumption.py                        # full, 8 stalls of 0.25 s in the F-16's turn
    python benchmarks/resumption.py --config dfs --stalls 4

The three processes of a session (docs/guide/serve.md) on 127.0.0.1, as ``benchmarks/soak.py`` starts
them: the stand-in ``desdemona machine`` (its defaults: a 5 Hz position loop, noise of 1e-5 rad on the
positions it reports), ``desdemona serve`` at 50 Hz, and a JSBSim host flying the F-16's 4.6 g turn in
real time. Every ``--every`` seconds from the fifth the service is stopped (SIGSTOP) for ``--stall``
seconds, longer than the stand-in's timeout (three cycles): the stand-in brakes on its own, comes to
rest, and the service, woken, parks from where the machine measurably is and follows the host again
once the machine is back. The hour's soak met this once, after a stall of the virtual machine, and the
motion the stand-in's servo made as it followed again went 5-11 % over the jerk limit of the inner
gimbal and the cabin (docs/benchmarks/soak.md).

Judged: the stand-in's own stops and its times at rest, the service's "machine back" events, the
setpoints over a limit and the motion made over one (the stand-in's ``violations.csv``: its trip level
on the made jerk is 5 %), the worst use of the jerk limit in the motion made (1 = at the limit). The
stalls are timing faults to the stand-in (a burst of setpoints after each), and it ends having
stopped while moving: its "passed" is not the verdict here, its violations are.
The session's folders go to ``benchmarks/resumption-results/CONFIG``.
"""

from __future__ import annotations

import argparse
import csv
import json
import os
import signal
import sys
import time
from pathlib import Path

import service as service_bench  # benchmarks/service.py: the stand-in and the service started as there
import soak  # benchmarks/soak.py: its JSBSim host

HERE = Path(__file__).resolve().parent
RESULTS = HERE / "resumption-results"


def session(config: str, stalls: int, every: float, stall: float) -> dict:
    folder = RESULTS / config
    folder.mkdir(parents=True, exist_ok=True)
    serve_port = service_bench._port()
    machine, server = service_bench.start_pair(config, folder, serve_port, service_bench._port(), soak.RATE, 5,
                                               "--quiet-end", 5)
    server.stdout.readline()  # "serving ...": built, listening
    seconds = min(soak.STOP - soak.START, 5.0 + stalls * every + 5.0)
    host = soak._start_host(serve_port, soak.CONFIGS[config], seconds)
    begun = time.monotonic()
    try:
        for k in range(stalls):
            time.sleep(max(0.0, begun + 5.0 + k * every - time.monotonic()))
            os.kill(server.pid, signal.SIGSTOP)
            time.sleep(stall)
            os.kill(server.pid, signal.SIGCONT)
        host.wait(timeout=seconds + 30)
        server.wait(timeout=60)
        machine.wait(timeout=60)
    finally:
        for process in (host, server, machine):
            if process.poll() is None:
                os.kill(process.pid, signal.SIGCONT)
                process.terminate()
    return measure(folder)


def measure(folder: Path) -> dict:
    stand_in = json.loads((folder / "machine" / "summary.json").read_text())
    with open(folder / "machine" / "violations.csv", newline="") as f:
        violations = list(csv.DictReader(f))
    with open(folder / "machine" / "events.csv", newline="") as f:
        rests = [float(e["time"]) for e in csv.DictReader(f) if e["what"] == "at rest"]
    with open(folder / "served" / "events.csv", newline="") as f:
        events = list(csv.DictReader(f))
    backs = [float(e["t"]) for e in events if e["what"] == "machine back"]
    made = [v for v in violations if v["what"].startswith("made")]
    return {"own_stops": len(stand_in.get("own_stops", [])), "at_rest": len(rests), "machine_back": len(backs),
            "setpoints_over": len(violations) - len(made), "made_over": len(made),
            "worst_made_jerk": stand_in["worst_use_made"]["jerk"], "worst_made_joint": stand_in["worst_joint_made"]["jerk"],
            "violations": stand_in["violation_count"], "timing_faults": stand_in["timing_faults"]}


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--config", default="full", choices=sorted(soak.CONFIGS))
    parser.add_argument("--stalls", type=int, default=8)
    parser.add_argument("--every", type=float, default=5.5, help="seconds between stalls")
    parser.add_argument("--stall", type=float, default=0.25, help="seconds the service is stopped each time")
    args = parser.parse_args(argv)
    row = session(args.config, args.stalls, args.every, args.stall)
    print(json.dumps({"config": args.config, "stalls": args.stalls, **row,
                      "load": os.getloadavg()}, indent=1))
    return 0 if row["violations"] == 0 else 1


if __name__ == "__main__":
    sys.exit(main())

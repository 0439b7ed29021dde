"""The real-time service on one computer: a JSBSim flight in real time, served, and checked by the stand-in.

    python benchmarks/service.py                      # every run below, the table into docs/benchmarks/real-time-service.md
    python benchmarks/service.py --runs dfs-50        # one run
    python benchmarks/service.py --table-only         # re-read the folders, rewrite the table
    python benchmarks/service.py --runs dfs-50 --key  # the same run, every datagram signed (``--key``)
    python benchmarks/service.py --runs full-50-host60 --seconds 20   # a short run
    python benchmarks/service.py --pin                # the service on a core of its own (taskset)

``--pin`` gives the service the last core and the host and the stand-in the others, as a real-time
deployment gives the service a core of its own (the host and the motion system are computers of their
own there). Without it, on a 2-core machine, the stand-in that each setpoint wakes often takes the
service's core before the service has finished its cycle's bookkeeping: the send's p99 then counts
1-1.5 ms of the stand-in's work.

Each run starts three processes, as a user would (docs/guide/serve.md): the motion
system's stand-in (``desdemona machine``), the service (``desdemona serve``, the ``hold`` predictor,
ending one second after the host has gone quiet and the machine is parked) and the host
(``desdemona host jsbsim``, the flight in real time, one message a cycle, as a simulator host sends
at the motion system's rate). Runs:

- ``dfs-50``: the flight's modulus on ``dfs`` at 50 Hz;
- ``full-20``: the six channels on ``full`` at 20 Hz; ``full-20-tail`` with ``--tail-step 0.2`` (the
  plan's coarse tail in steps of 0.2 s instead of 0.1 s: half the intervals);
- ``dfs-50-lossy``: as ``dfs-50`` with 10 % of the host's datagrams dropped at random and a 1 s
  outage at 30 s of the flight: the machine must park within the time its limits allow for braking,
  and the session resume after the outage;
- ``full-50-host60``, ``full-50-host120``: ``full`` at 50 Hz, ``dfs-100-host60``, ``dfs-100-host120``:
  ``dfs`` at 100 Hz, each with the host sending at 60 or 120 Hz on its own clock, not locked to the
  service's (the latency targets of issue 75: p99 at most 10 ms on ``full`` at 50 Hz, 5 ms on ``dfs`` at
  100 Hz); ``online``, the reference, runs on the recording at the host's rate with the service's step.

Per run the table gives the end-to-end latency (host message received to setpoint sent) median and
p99, the cycles over their deadline, the datagrams dropped, the stand-in's verdict (violations of
any limit, position to jerk, or of continuity), the felt-force RMS of the served session against
``desdemona online`` with the same predictor on the imported recording of the same flight at the
host's rate (``desdemona import jsbsim --rate``), both judged against that recording, and how long parking took once the host had
ended, against the time the limits allow. The lossy run adds when it parked and when it resumed.
The machine's load average is recorded before and after, and per run over the minute it ended in.
A second table gives per run where a cycle's time goes (median and p99 of the message's wait from its
arrival to the cycle's start, and of each phase the service logs, :mod:`desdemona.service.pacing`),
with the thread's processor time over the compute: on a shared machine a p99 well above it is time
the processor was taken away, not work. With ``--key`` the three processes share
a key (made once, ``service-results/key``) and sign every datagram; such a run is written to
``NAME-key`` and is its own row of the table.
"""

from __future__ import annotations

import argparse
import csv
import json
import os
import secrets
import socket
import subprocess
import sys
import time
from pathlib import Path

import numpy as np
import tables  # benchmarks/tables.py: the script's own folder is on the path

from desdemona import Model
from desdemona.machine.plan import stopping_time
from desdemona.results.report import read_table

HERE = Path(__file__).resolve().parent
RESULTS = HERE / "service-results"
DOCS = HERE.parent / "docs" / "benchmarks" / "real-time-service.md"
BEGIN, END = "<!-- service.py table: begin -->", "<!-- service.py table: end -->"
SCRIPT, START, STOP = str(HERE / "corpus_scripts" / "f16_turn.xml"), 3.0, 58.0  # the F-16's 4.6 g turn, 55 s
FLIGHT_END = STOP  # --seconds shortens the flight (STOP)
RUNS = {  # name: (configuration, rate [Hz], modulus, lossy, the plan's tail step [s], the host's rate [Hz])
    "dfs-50": ("dfs", 50.0, True, False, 0.1, 50.0),
    "full-20": ("full", 20.0, False, False, 0.1, 20.0),
    "full-20-tail": ("full", 20.0, False, False, 0.2, 20.0),
    "dfs-50-lossy": ("dfs", 50.0, True, True, 0.1, 50.0),
    "full-50-host60": ("full", 50.0, False, False, 0.1, 60.0),
    "full-50-host120": ("full", 50.0, False, False, 0.1, 120.0),
    "dfs-100-host60": ("dfs", 100.0, True, False, 0.1, 60.0),
    "dfs-100-host120": ("dfs", 100.0, True, False, 0.1, 120.0),
}
#: The figures the service's log times per cycle (desdemona.service.pacing): the message's wait, then the phases.
PHASES = ("message_age", "preview", "qp_data", "qp", "check", "send", "prepare", "compute_cpu")
DROP, OUTAGE = 0.1, (30.0, 1.0)


def _port() -> int:
    with socket.socket(socket.AF_INET, socket.SOCK_DGRAM) as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


#: ``--pin``: the service on a core of its own (the last), every other process on the others, as a
#: real-time deployment gives it one (``taskset``); None: where the system puts them.
PIN: tuple[str, str] | None = None


def _desdemona(*args) -> list[str]:
    command = [sys.executable, "-m", "desdemona", *map(str, args)]
    if PIN is None:
        return command
    return ["taskset", "-c", PIN[0] if args[0] == "serve" else PIN[1], *command]


def start_pair(config: str, folder: Path, listen: int, send: int, rate: float, idle: float, *serve_args, both=()):
    """The stand-in (``folder/machine``, ending ``idle`` seconds after the last setpoint) and the service
    (``folder/served``, no view, ``serve_args``) on 127.0.0.1, the host's messages to ``listen``, the
    setpoints to ``send``, ``both`` given to each (a key); each one's output on its stdout (the
    service's stderr too)."""
    machine = subprocess.Popen(_desdemona("machine", "--config", config, "--listen", f"127.0.0.1:{send}",
                                          "--out", folder / "machine", "--idle", idle, *both),
                               stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    server = subprocess.Popen(_desdemona("serve", "--config", config, "--listen", f"127.0.0.1:{listen}",
                                         "--send", f"127.0.0.1:{send}", "--rate", rate, "--out", folder / "served",
                                         "--overwrite", "--no-view", *serve_args, *both),
                              stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    return machine, server


def recording(modulus: bool, rate: float) -> Path:
    """The flight imported as ``desdemona import jsbsim`` writes it, at the host's rate (the samples
    the host sends): the reference ``online`` runs on and both are judged against."""
    span = "" if STOP == FLIGHT_END else f"-{STOP - START:g}s"
    out = RESULTS / f"f16-turn{'-modulus' if modulus else ''}-{rate:g}hz{span}.csv"
    if not out.exists():
        RESULTS.mkdir(parents=True, exist_ok=True)
        subprocess.run(_desdemona("import", "jsbsim", SCRIPT, "--start", START, "--end", STOP, "--rate", rate,
                                  "--out", out, *(["--modulus"] if modulus else [])), check=True)
    return out


def key_file() -> Path:
    """The runs' shared key, made once (as ``openssl rand -hex 32`` makes one), readable by its owner only."""
    path = RESULTS / "key"
    if not path.exists():
        RESULTS.mkdir(parents=True, exist_ok=True)
        path.touch(mode=0o600)
        path.write_text(secrets.token_hex(32) + "\n")
    return path


def serve_run(name: str, signed: bool = False) -> dict:
    """One run of the three processes (``signed``: sharing a key); returns what the table needs."""
    config, rate, modulus, lossy, tail, host_rate = RUNS[name]
    folder = RESULTS / (f"{name}-key" if signed else name)
    folder.mkdir(parents=True, exist_ok=True)
    listen, send = _port(), _port()
    key = ["--key", key_file()] if signed else []
    machine, server = start_pair(config, folder, listen, send, rate, 3, "--tail-step", tail, "--quiet-end", 1.0,
                                 both=key)
    server.stdout.readline()  # "serving ...": the controller is built (and compiled), the service listens
    host = [*(["--modulus"] if modulus else []),
            *(["--drop", DROP, "--outage", f"{OUTAGE[0]},{OUTAGE[1]}"] if lossy else [])]
    subprocess.run(_desdemona("host", "jsbsim", SCRIPT, "--to", f"127.0.0.1:{listen}", "--start", START,
                              "--end", STOP, "--rate", host_rate, *host, *key), check=True)
    load = os.getloadavg()[0]  # over the last minute: while the run ran
    served_out, _ = server.communicate(timeout=120)
    try:
        machine_out, _ = machine.communicate(timeout=30)
    except subprocess.TimeoutExpired:  # it heard nothing (the service failed): stop it, keep what it says
        machine.send_signal(2)
        machine_out, _ = machine.communicate(timeout=30)
    (folder / "serve.txt").write_text(served_out)
    (folder / "machine.txt").write_text(machine_out)
    online = folder / "online"
    (folder / "load.json").write_text(json.dumps(load))
    subprocess.run(_desdemona("online", recording(modulus, host_rate), "--config", config, "--predictor", "hold",
                              "--step", 1.0 / rate, "--tail-step", tail, "--initial", "home", "--out", online, "--overwrite",
                              "--no-view"), check=True, capture_output=True)
    return {"name": folder.name, "served_rc": server.returncode, "machine_rc": machine.returncode}


def _felt_force_rms(folder: Path, recording: Path, modulus: bool, offset: float = 0.0) -> float:
    """RMS of the felt force's error |f - f_d| over the recording's span, f from a result folder's
    trajectory.csv (its time less ``offset`` on the recording's clock), f_d from the recording itself
    (a modulus along the occupant's vertical): the served session and ``online`` judged against the
    same target."""
    col, rec = read_table(folder / "trajectory.csv"), read_table(recording)
    t = col["t"] - offset
    keep = (t >= rec["t"][0]) & (t <= rec["t"][-1])
    f = np.column_stack([col[k][keep] for k in ("fx", "fy", "fz")])
    if modulus:
        f_d = np.column_stack([np.zeros(keep.sum()), np.zeros(keep.sum()), np.interp(t[keep], rec["t"], rec["M"])])
    else:
        f_d = np.column_stack([np.interp(t[keep], rec["t"], rec[k]) for k in ("fx", "fy", "fz")])
    return float(np.sqrt(np.mean(np.sum((f - f_d) ** 2, axis=1))))


def _cycles(folder: Path) -> list[dict]:
    """Every cycle of a served session (``session.csv``)."""
    with open(folder / "session.csv", newline="") as fh:
        return list(csv.DictReader(fh))


def measure(name: str, signed: bool = False) -> dict:
    """The table's row of a run, from its folders."""
    config, rate, modulus, lossy, tail, host_rate = RUNS[name]
    folder = RESULTS / (f"{name}-key" if signed else name)
    served = json.loads((folder / "served" / "summary.json").read_text())
    service = served["service"]
    stand_in = json.loads((folder / "machine" / "summary.json").read_text())
    cycles = _cycles(folder / "served")
    running = [float(c["t"]) for c in cycles if c["status"] == "running"]
    reference = recording(modulus, host_rate)
    row = {"run": name + (", signed" if signed else ""), "config": config, "rate": rate, "tail": tail,
           "host_rate": host_rate, "latency_ms": {k: 1e3 * v for k, v in service["latency_s"].items()},
           "phases_ms": _phases_ms(cycles),
           "load": json.loads((folder / "load.json").read_text()) if (folder / "load.json").exists() else None,
           "over_deadline": service["compute_over_deadline"], "cycles": service["cycles"],
           "dropped": sum(service["dropped"].values()), "violations": stand_in.get("violations", stand_in.get("counts")),
           "passed": stand_in["passed"], "received": service["received"],
           "served_rms": _felt_force_rms(folder / "served", reference, modulus, service["host_time_offset_s"]),
           "online_rms": _felt_force_rms(folder / "online", reference, modulus)}
    row.update(_parking(cycles, folder / "served", rate, Model(config=config), running[0] + OUTAGE[0] if lossy else None,
                        service["judged_span_s"][0]))
    return row


def _phases_ms(cycles: list[dict]) -> dict:
    """Median and p99 [ms] of the message's wait and of each phase over the cycles that answered a
    host message (None where the log has no such column)."""
    answered = [c for c in cycles if c["status"] == "running" and c["latency_s"] not in ("", "nan")]
    spreads = {}
    for key in PHASES:
        column = f"{key}_s"
        values = np.array([float(c[column]) for c in answered if column in c], dtype=float)
        values = values[np.isfinite(values)]
        spreads[key] = None if len(values) == 0 else {"median": 1e3 * float(np.median(values)),
                                                      "p99": 1e3 * float(np.percentile(values, 99))}
    return spreads


def _parking(cycles: list[dict], folder: Path, rate: float, model: Model, outage_at: float | None,
             judged_from: float) -> dict:
    """How the session parked: after the host's last message, the time from the first parking cycle to
    parked, against the time the limits allow from the rates and accelerations it had
    (:func:`desdemona.machine.plan.stopping_time`, and the two cycles of coming to rest); with an
    outage, when parking began after it began and when the session ran again."""
    t = np.array([float(c["t"]) for c in cycles])
    status = [c["status"] for c in cycles]
    last = max(i for i, s in enumerate(status) if s == "running")
    begin = next(i for i in range(last, len(status)) if status[i] == "parking")
    end = next((i for i in range(begin, len(status)) if status[i] == "parked"), None)
    col = read_table(folder / "trajectory.csv")  # the judged span, its time from judged_from
    k = min(int(np.searchsorted(col["t"], t[begin] - judged_from - 1e-9)), len(col["t"]) - 1)
    names, lim = model.config.joint_names, model.limits
    qd = np.array([col[f"qd_{j}"][k] for j in names])
    a = np.array([col[f"qdd_{j}"][k] for j in names])
    bound = float(np.max(stopping_time(qd, a, lim.acceleration, lim.jerk))) + 2.0 / rate
    row = {"parking_s": None if end is None else float(t[end] - t[begin]), "parking_bound_s": bound}
    if outage_at is not None:
        after = np.flatnonzero(t >= outage_at)
        parking = next(i for i in after if status[i] == "parking")
        resumed = next(i for i in after if i > parking and status[i] == "running")
        row.update(outage_at=outage_at, parking_at=float(t[parking]), resumed_at=float(t[resumed]))
    return row


def table(rows: list[dict], load: tuple) -> str:
    head = ("| run | latency median / p99 [ms] | over deadline | datagrams dropped | stand-in | felt force RMS "
            "served / online [m/s^2] | ratio | parked after the host's end [s] (limits allow) |")
    lines = [head, "|" + " --- |" * (head.count("|") - 1)]
    for r in rows:
        lat = r["latency_ms"]
        verdict = "no violation" if r["passed"] else f"violations {r['violations']}"
        host = f", host {r['host_rate']:g} Hz" if r.get("host_rate", r["rate"]) != r["rate"] else ""
        lines.append(f"| {r['run']} ({r['config']}, {r['rate']:g} Hz{host}, tail {r['tail']:g} s) | {lat['median']:.2f} / {lat['p99']:.2f} | "
                     f"{r['over_deadline']} of {r['cycles']} | {r['dropped']} | {verdict} | "
                     f"{r['served_rms']:.3f} / {r['online_rms']:.3f} | {r['served_rms'] / r['online_rms']:.3f} | "
                     f"{r['parking_s']:.2f} ({r['parking_bound_s']:.2f}) |")
    for r in rows:
        if "outage_at" in r:
            lines.append("")
            lines.append(f"{r['run']}: the host silent from {r['outage_at']:.2f} s of the session for "
                         f"{OUTAGE[1]:g} s; parking from {r['parking_at']:.2f} s, running again from "
                         f"{r['resumed_at']:.2f} s.")
    pinned = "" if len(load) < 3 or load[2] is None else (
        f"; the service on core {load[2][0]} of its own, the host and the stand-in on core {load[2][1]} (--pin)")
    measured = (f"Load average before and after: {load[0]:.2f}, {load[1]:.2f} (2 cores){pinned}; measured "
                f"{time.strftime('%Y-%m-%d')}.")
    lines += ["", *_phases_table(rows), "", measured]
    return "\n".join(lines)


def _phases_table(rows: list[dict]) -> list[str]:
    """Where each run's cycles spend their time: median / p99 [ms] of the message's wait (arrival to the
    cycle's start) and of each phase (desdemona.service.pacing) over the cycles that answered a host
    message, the thread's processor time over the compute, and the load average over the minute the
    run ended in."""
    head = ("| run | wait | preview | QP data | QP | check | send | prepared after the send | compute CPU | "
            "load (1 min) |")
    lines = ["Per cycle, median / p99 [ms]:", "", head, "|" + " --- |" * (head.count("|") - 1)]
    for r in rows:
        phases = r.get("phases_ms") or {}
        cells = ["-" if phases.get(k) is None else f"{phases[k]['median']:.2f} / {phases[k]['p99']:.2f}"
                 for k in PHASES]
        load = "-" if r.get("load") is None else f"{r['load']:.2f}"
        lines.append(f"| {r['run']} | " + " | ".join(cells) + f" | {load} |")
    return lines


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--runs", nargs="+", choices=tuple(RUNS), default=list(RUNS))
    parser.add_argument("--table-only", action="store_true")
    parser.add_argument("--key", action="store_true", help="sign every datagram with a shared key")
    parser.add_argument("--seconds", type=float, default=FLIGHT_END - START,
                        help="fly only the first SECONDS of the turn (default: all 55 s; the lossy run's outage "
                             "is at 30 s)")
    parser.add_argument("--pin", action="store_true",
                        help="the service on a core of its own, the host and the stand-in on the others (taskset)")
    args = parser.parse_args(argv)
    global STOP, PIN
    STOP = min(FLIGHT_END, START + args.seconds)
    cores = sorted(os.sched_getaffinity(0))
    if args.pin:
        if len(cores) < 2:
            parser.error("--pin needs two cores at least")
        PIN = (str(cores[-1]), ",".join(map(str, cores[:-1])))
    loads = RESULTS / "load.json"  # the machine's load while the runs ran, kept for --table-only
    if not args.table_only:
        before = os.getloadavg()[0]
        for name in args.runs:
            print(serve_run(name, args.key), flush=True)
        loads.write_text(json.dumps([before, os.getloadavg()[0], PIN]))
    rows = [measure(name, signed) for name in RUNS for signed in (False, True)
            if (RESULTS / (f"{name}-key" if signed else name) / "served" / "summary.json").exists()]
    text = table(rows, tuple(json.loads(loads.read_text())))
    print(text)
    tables.replace_between(BEGIN, END, text, "Real-time service", DOCS)
    return 0


if __name__ == "__main__":
    sys.exit(main())

"""What the operator's console costs the service: the end-to-end latency of served sessions with and
without ``--console``, with a client reading every frame.

    python benchmarks/console_latency.py [--pairs 3] [--seconds 10] [--work FOLDER]
    python benchmarks/console_latency.py --in-process [--blocks 40]

Each session runs three processes as a user would (docs/guide/serve.md): the stand-in (``desdemona
machine``), ``desdemona serve --config dfs`` at 50 Hz and ``desdemona host replay`` of the first
``--seconds`` of ``dfs-catapult`` (100 Hz samples); with the console, a fourth process reads its
stream as a page would (every frame, 25 a second). Sessions alternate, without then with, ``--pairs``
times, so that the machine's load falls on both alike. Per session it prints the latency (host message
received to setpoint sent) median and p99 from the session's summary.json and the frames the client
read; at the end the median of each kind's p99 and their difference (the console's acceptance: under
0.2 ms), with the load average before and after.

``--in-process`` isolates what the console's thread can cost the cycle's thread (they share the
interpreter's lock): one process runs a stand-in cycle at 50 Hz (waking at its time in a select, as
serve does, then 2 ms of model calls, then handing the console its snapshot) beside a console
streaming to a client in another process, in blocks of 50 cycles alternately with the console idle
(no snapshot handed) and making frames, and compares the p99 of each cycle's end after its due time;
it also times every step of the console's frames (the longest a cycle can wait on the console).
"""

from __future__ import annotations

import argparse
import json
import os
import socket
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

LOOPBACK = "127.0.0.1"
RUN = [sys.executable, "-m", "desdemona"]
# The page's stand-in: reads every frame until the stream closes, prints how many.
CLIENT = """
import sys
from websockets.sync.client import connect
frames = 0
with connect(sys.argv[1], open_timeout=60) as ws:
    for message in ws:
        frames += 1
print(frames)
"""


def _port(kind=socket.SOCK_DGRAM) -> int:
    with socket.socket(socket.AF_INET, kind) as s:
        s.bind((LOOPBACK, 0))
        return s.getsockname()[1]


def session(work: Path, name: str, profile: Path, console: bool) -> dict:
    """One served session; its latency figures [ms] and the frames a client read (None without)."""
    machine_port, serve_port, console_port = _port(), _port(), _port(socket.SOCK_STREAM)
    stand_in = subprocess.Popen([*RUN, "machine", "--config", "dfs", "--listen", f"{LOOPBACK}:{machine_port}",
                                 "--out", str(work / f"{name}-machine"), "--idle", "2", "--duration", "120"],
                                stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    extra = ["--console", f"{LOOPBACK}:{console_port}"] if console else []
    server = subprocess.Popen([*RUN, "serve", "--config", "dfs", "--listen", f"{LOOPBACK}:{serve_port}",
                               "--send", f"{LOOPBACK}:{machine_port}", "--out", str(work / name), "--horizon", "1",
                               "--quiet-end", "0.5", "--duration", "120", "--no-view", *extra],
                              stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    client = None
    try:
        for _ in range(10):
            line = server.stderr.readline()
            if "serving" in line or not line:
                break
        if console:
            client = subprocess.Popen([sys.executable, "-c", CLIENT, f"ws://{LOOPBACK}:{console_port}/stream"],
                                      stdout=subprocess.PIPE, text=True)
            time.sleep(1.0)
        subprocess.run([*RUN, "host", "replay", str(profile), "--to", f"{LOOPBACK}:{serve_port}"],
                       capture_output=True, timeout=120, check=True)
        server.communicate(timeout=120)
        frames = int(client.communicate(timeout=30)[0]) if client else None
        stand_in.communicate(timeout=30)
    finally:
        for proc in (client, server, stand_in):
            if proc is not None and proc.poll() is None:
                proc.kill()
    latency = json.loads((work / name / "summary.json").read_text())["service"]["latency_s"]
    return {"median": 1e3 * latency["median"], "p99": 1e3 * latency["p99"], "frames": frames}


def in_process(blocks: int, cycles: int = 50, h: float = 0.02) -> None:
    """The cycle's lateness (its work's end after its due time) [ms], p50 and p99, with the console
    idle and with it making frames of the cycle's snapshots, alternately ``blocks`` blocks of
    ``cycles``; and the longest step of the console's frames (the longest the cycle can wait on it)."""
    import selectors
    from collections import Counter
    from types import SimpleNamespace

    import numpy as np

    from desdemona import Model
    from desdemona.machine.plan import State
    from desdemona.service import console, protocol

    model = Model(config="dfs")
    S = model.functions["S"]
    rng = np.random.default_rng(1)
    n = model.n
    late = {False: [], True: []}
    steps = []
    live = console.Console(model, h, (LOOPBACK, 0))
    steps_of = live.frames.steps

    def timed(snaps):  # each step of the console's frames timed, as the console's thread runs them
        made = steps_of(snaps)
        while True:
            began = time.perf_counter()
            try:
                next(made)
            except StopIteration:
                return
            finally:
                steps.append(time.perf_counter() - began)
            yield

    live.frames.steps = timed
    live.start()
    client = subprocess.Popen([sys.executable, "-c", CLIENT, f"ws://{LOOPBACK}:{live.address[1]}/stream"],
                              stdout=subprocess.PIPE, text=True)
    time.sleep(1.0)
    with socket.socket(socket.AF_INET, socket.SOCK_DGRAM) as idle:
        idle.bind((LOOPBACK, 0))
        selector = selectors.DefaultSelector()
        selector.register(idle, selectors.EVENT_READ)
        start = time.monotonic() + h
        for k in range(blocks * cycles):
            on = (k // cycles) % 2 == 1
            due = start + k * h
            while (wait := due - time.monotonic()) > 0:
                selector.select(wait)
            state = State(rng.uniform(-1, 1, n), rng.uniform(-1, 1, n), rng.uniform(-1, 1, n))
            spent = time.monotonic()
            while time.monotonic() - spent < 0.002:  # the controller's model calls
                S(state[0], state[1], state[2])
            late[on].append(time.monotonic() - due)
            if on:
                row = {"t": k * h, "status": "running", "command": "plan", "reason": "", "latency_s": 0.004,
                       "compute_time_s": 0.002, "message_age_s": 0.001, "machine": "", "tracking_use": np.nan}
                live.publish(SimpleNamespace(rows=[row], starts=[state], command=(state[2], np.zeros(n)), paused=None),
                             SimpleNamespace(newest=protocol.Motion(k + 1, k * h, np.array([12.0])), t=[0.0],
                                             dropped=Counter()),
                             SimpleNamespace(newest=None, dropped=Counter()))
    live.close("the measurement ended")
    frames = client.communicate(timeout=30)[0].strip()
    print(f"the console sent {live.sent} frames, the client read {frames}")
    for on in (False, True):
        x = 1e3 * np.array(late[on])
        print(f"{'making frames' if on else 'idle'}: the cycle's end after its due time median {np.median(x):.3f} ms, "
              f"p99 {np.percentile(x, 99):.3f} ms ({len(x)} cycles)")
    x = 1e3 * np.array(steps)
    print(f"the console's steps: median {np.median(x):.3f} ms, p99 {np.percentile(x, 99):.3f} ms, "
          f"longest {x.max():.3f} ms ({len(x)} steps); load average {os.getloadavg()[0]:.1f}")


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--pairs", type=int, default=3)
    parser.add_argument("--seconds", type=float, default=10.0)
    parser.add_argument("--work", type=Path, default=None)
    parser.add_argument("--in-process", action="store_true", dest="in_process")
    parser.add_argument("--blocks", type=int, default=40)
    args = parser.parse_args(argv)
    if args.in_process:
        in_process(args.blocks)
        return 0
    from desdemona import profiles

    work = args.work or Path(tempfile.mkdtemp(prefix="console-latency-"))
    work.mkdir(parents=True, exist_ok=True)
    path = profiles.get_profile("dfs-catapult")
    keep = path.t <= args.seconds
    profile = work / "profile.csv"
    profiles.write_csv(profile, profiles.DesiredPath("catapult", path.t[keep], None, modulus=path.M_d[keep]))
    before = os.getloadavg()
    p99 = {False: [], True: []}
    for k in range(args.pairs):
        for console in (False, True):
            name = f"{'with' if console else 'without'}-{k}"
            figures = session(work, name, profile, console)
            p99[console].append(figures["p99"])
            print(f"{name}: latency median {figures['median']:.2f} ms, p99 {figures['p99']:.2f} ms"
                  + (f", {figures['frames']} frames read" if console else ""), flush=True)
    without, with_ = statistics.median(p99[False]), statistics.median(p99[True])
    print(f"p99 (median of {args.pairs}): without the console {without:.2f} ms, with it {with_:.2f} ms, "
          f"difference {with_ - without:+.2f} ms; load average {before[0]:.1f} before, {os.getloadavg()[0]:.1f} after")
    return 0


if __name__ == "__main__":
    sys.exit(main())

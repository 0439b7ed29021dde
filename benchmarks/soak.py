"""Soak and fault campaign: a long served session at 50 Hz with a JSBSim host, then the same through a lossy network.

    python benchmarks/soak.py                   # an hour on dfs and on full, then the faults; the table into docs/benchmarks/soak.md
    python benchmarks/soak.py --minutes 3       # the short form (the fault phase a third as long)
    python benchmarks/soak.py --table-only      # re-read the folders, rewrite the table

Each session runs the three processes a user runs (docs/guide/serve.md) and a relay of this script
between the host and the service, all on 127.0.0.1: the stand-in ``desdemona machine`` (its defaults:
its own timing check and safety layer), ``desdemona serve`` at 50 Hz (``--no-view``), and a JSBSim host
flying the F-16's 4.6 g turn (``corpus_scripts/f16_turn.xml``, 3-58 s of its flight) in real time again
and again (:func:`desdemona.service.hosts.jsbsim` in a loop, its sequence numbers running on).

- **steady** (``--minutes``, default 60, on ``dfs`` with the modulus and on ``full`` with six channels):
  the relay only joins the flights (each new flight's times continue the last: one stream); the
  service's and the stand-in's resident memory (RSS) sampled every minute (every ``minutes`` / 30 in a
  shorter run), the latency (host message received to setpoint sent) per sixth of the session.
- **faults** (``--fault-minutes``, default a third of ``--minutes``, at most 5): the relay loses 20 % of
  the host's datagrams, sends 5 % twice, holds 5 % back behind the next one, delays every one by up to
  30 ms (uniform), goes silent for 2 s at half time; the host process is killed (SIGKILL) and started
  afresh at a quarter and at three quarters of the time.

Judged: the stand-in's verdict (no limit exceeded, the motion it made too), every park of the service
that came to rest within the time the limits allow (:func:`desdemona.machine.plan.stopping_time` from
the commanded rates and accelerations at its first cycle, and the two cycles of coming to rest, plus
one cycle: the parked status is first seen the cycle after), memory after the first sixth against the
end. Each session's folders stay in ``benchmarks/soak-results/``; the script runs unattended and
writes the table whatever happens to one session (its row then says what failed).
"""

from __future__ import annotations

import argparse
import contextlib
import csv
import dataclasses
import heapq
import json
import os
import selectors
import signal
import socket
import subprocess
import sys
import threading
import time
from pathlib import Path

import numpy as np
import tables  # benchmarks/tables.py: the script's own folder is on the path
import service as service_bench  # benchmarks/service.py: the stand-in and the service started as there
from service import _port

HERE = Path(__file__).resolve().parent
RESULTS = HERE / "soak-results"
DOCS = HERE.parent / "docs" / "benchmarks" / "soak.md"
BEGIN, END = "<!-- soak.py table: begin -->", "<!-- soak.py table: end -->"
SCRIPT, START, STOP = str(HERE / "corpus_scripts" / "f16_turn.xml"), 3.0, 58.0
RATE = 50.0
CONFIGS = {"dfs": True, "full": False}  # configuration: the host sends the modulus alone
LOSS, DUPLICATE, REORDER, JITTER, OUTAGE = 0.20, 0.05, 0.05, 0.030, 2.0
LOOPBACK = "127.0.0.1"


# ----------------------------------------------------------------------------------------------
# the host: the flight again and again, one stream of sequence numbers


def host_loop(to: int, modulus: bool, seconds: float) -> int:
    """Fly the turn in real time to 127.0.0.1:``to`` again and again for ``seconds``; the sequence runs
    on from flight to flight (each flight's times start at 0 again: the relay joins them)."""
    from desdemona.service import hosts

    sequence, ends = 1, time.monotonic() + seconds
    try:
        while ends - time.monotonic() > 1.0:
            counts = hosts.jsbsim(SCRIPT, (LOOPBACK, to), rate=RATE, start=START,
                                  end=min(STOP, START + ends - time.monotonic()), start_sequence=sequence,
                                  modulus=modulus)
            sequence = counts["last_sequence"] + 1
    except KeyboardInterrupt:
        pass
    return 0


# ----------------------------------------------------------------------------------------------
# the relay between host and service


class Relay(threading.Thread):
    """Forwards the host's datagrams from ``listen`` to 127.0.0.1:``to``. A flight that begins again
    with the sequence running on has its times moved to continue the stream; a host whose sequence
    starts over (a new process) is passed on as it is, for the service to recognise. With ``faults``:
    loss, duplicates, reordering, jitter and an outage (:meth:`silence`), each counted."""

    def __init__(self, to: int, faults: bool, seed: int = 0):
        super().__init__(daemon=True)
        from desdemona.service import protocol

        self.protocol, self.faults = protocol, faults
        self.rx = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
        self.rx.bind((LOOPBACK, 0))
        self.port = self.rx.getsockname()[1]
        self.tx = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
        self.to = (LOOPBACK, to)
        self.random = np.random.default_rng(seed)
        self.queue: list = []  # (due, order, datagram)
        self.order = 0
        self.last = None  # (sequence in, time out) of the last motion passed on
        self.shift, self.session = 0.0, None  # added to the times; the stream's session
        self.quiet_until = 0.0
        self.counts = {"received": 0, "sent": 0, "lost": 0, "duplicated": 0, "reordered": 0, "outage": 0,
                       "flights joined": 0, "host restarts passed on": 0}
        self.stopping = threading.Event()

    def silence(self, seconds: float) -> None:
        self.quiet_until = time.monotonic() + seconds

    def stop(self) -> None:
        self.stopping.set()
        self.join(5)
        self.rx.close()
        self.tx.close()

    def run(self) -> None:
        selector = selectors.DefaultSelector()
        selector.register(self.rx, selectors.EVENT_READ)
        while not self.stopping.is_set():
            now = time.monotonic()
            while self.queue and self.queue[0][0] <= now:
                with contextlib.suppress(OSError):
                    self.tx.sendto(heapq.heappop(self.queue)[2], self.to)
                    self.counts["sent"] += 1
            wait = min(0.05, self.queue[0][0] - now) if self.queue else 0.05
            if selector.select(max(0.0, wait)):
                with contextlib.suppress(OSError):
                    self._take(self.rx.recv(65536), time.monotonic())

    def _take(self, data: bytes, now: float) -> None:
        self.counts["received"] += 1
        data = self._joined(data)
        if not self.faults:
            return self._put(now, data)
        if now < self.quiet_until:
            self.counts["outage"] += 1
            return None
        draw = self.random.random(4)
        if draw[0] < LOSS:
            self.counts["lost"] += 1
            return None
        delay = draw[1] * JITTER
        if draw[2] < REORDER:  # held back behind the next datagram (50 Hz: 20 ms apart)
            delay += 0.045
            self.counts["reordered"] += 1
        self._put(now + delay, data)
        if draw[3] < DUPLICATE:
            self.counts["duplicated"] += 1
            self._put(now + self.random.random() * JITTER, data)
        return None

    def _put(self, due: float, data: bytes) -> None:
        heapq.heappush(self.queue, (due, self.order, data))
        self.order += 1

    def _joined(self, data: bytes) -> bytes:
        """The datagram as the service gets it: a flight of the same host process (its sequence running
        on, its times and its sender's session starting afresh) moved to continue the stream, under
        the stream's session; a new host process (its sequence starting over) passed on as it is."""
        try:
            frame = self.protocol.read(data)
        except self.protocol.ProtocolError:
            return data
        message = frame.message
        if not isinstance(message, self.protocol.Motion):
            return data
        if self.last is None or message.sequence < self.last[0]:
            if self.last is not None:
                self.counts["host restarts passed on"] += 1
            self.shift, self.session = 0.0, frame.session  # a new host process: passed on as it comes
        elif message.time + self.shift <= self.last[1]:
            self.shift = self.last[1] + 1.0 / RATE - message.time  # the next flight of the same host
            self.counts["flights joined"] += 1
        self.last = (message.sequence, message.time + self.shift)
        if self.shift == 0.0 and frame.session == self.session:
            return data
        return self.protocol.pack(dataclasses.replace(message, time=message.time + self.shift), self.session)


# ----------------------------------------------------------------------------------------------
# one session


def _rss_mb(pid: int) -> float | None:
    try:
        for line in Path(f"/proc/{pid}/status").read_text().splitlines():
            if line.startswith("VmRSS:"):
                return int(line.split()[1]) / 1024.0
    except OSError:
        return None
    return None


def _start_host(port: int, modulus: bool, seconds: float) -> subprocess.Popen:
    return subprocess.Popen([sys.executable, __file__, "host", str(port), str(int(modulus)), f"{seconds:.3f}"],
                            stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)


def session(config: str, minutes: float, faults: bool) -> dict:
    """One session of ``minutes`` (see the module's notes); what it measured along the way."""
    modulus, seconds = CONFIGS[config], 60.0 * minutes
    folder = RESULTS / f"{config}-{'faults' if faults else 'steady'}"
    folder.mkdir(parents=True, exist_ok=True)
    serve_port = _port()
    machine, server = service_bench.start_pair(config, folder, serve_port, _port(), RATE, 5, "--quiet-end", 8)
    said = server.stdout.readline()  # "serving ...": built (and compiled), listening
    relay = Relay(serve_port, faults)
    relay.start()
    sample = min(60.0, seconds / 30.0)
    began = time.monotonic()
    host = _start_host(relay.port, modulus, seconds)
    plan = sorted([(0.25 * seconds, "restart"), (0.5 * seconds, "outage"), (0.75 * seconds, "restart")]) if faults else []
    rss, restarts, k = [], [], 0
    try:
        while time.monotonic() - began < seconds + 1.0 and server.poll() is None:
            now = time.monotonic() - began
            if plan and now >= plan[0][0]:
                _, what = plan.pop(0)
                if what == "outage":
                    relay.silence(OUTAGE)
                else:
                    host.kill()
                    host.wait()
                    restarts.append(now)
                    host = _start_host(relay.port, modulus, seconds - now)
            if now >= k * sample:
                rss.append({"t": now, "serve_mb": _rss_mb(server.pid), "machine_mb": _rss_mb(machine.pid)})
                k += 1
            time.sleep(0.1)
        host.wait(timeout=120)
        served_out = server.communicate(timeout=max(3600.0, 2 * seconds))[0]
        machine_out = machine.communicate(timeout=600)[0]
    finally:
        for proc in (host, server, machine):
            if proc.poll() is None:
                proc.kill()
                proc.wait()
        relay.stop()
    (folder / "serve.txt").write_text(said + (served_out or ""))
    (folder / "machine.txt").write_text(machine_out or "")
    run = {"config": config, "faults": faults, "minutes": minutes, "rss": rss, "relay": relay.counts,
           "restarts_s": restarts, "served_rc": server.returncode, "machine_rc": machine.returncode,
           "load": os.getloadavg()[0]}
    (folder / "soak.json").write_text(json.dumps(run, indent=1))
    return run


# ----------------------------------------------------------------------------------------------
# what a session shows


def _rows(file: Path) -> list[dict]:
    with open(file, newline="") as fh:
        return list(csv.DictReader(fh))


def parks(cycles: list[dict], config: str, step: float = 1.0 / RATE) -> list[dict]:
    """Every park of the session (a run of ``parking`` cycles): whether it came to rest (``parked``)
    or the host came back first, how long it took and the time its limits allow, and why (a park
    that follows the machine's own stop, "the machine is braking", is judged by the stand-in's own
    stop instead: the machine began it, earlier)."""
    from desdemona import Model
    from desdemona.machine.plan import stopping_time

    model = Model(config=config)
    names, lim, h = model.config.joint_names, model.limits, step
    status = [c["status"] for c in cycles]
    out, k = [], 0
    while k < len(status):
        if status[k] != "parking" or (k > 0 and status[k - 1] == "parking"):
            k += 1
            continue
        end = next((i for i in range(k, len(status)) if status[i] != "parking"), len(status))
        qd = np.array([float(cycles[k][f"commanded_{j}_rate"]) for j in names])
        a = np.array([float(cycles[k][f"commanded_{j}_acceleration"]) for j in names])
        bound = float(np.max(stopping_time(qd, a, lim.acceleration, lim.jerk))) + 3 * h  # see the module's notes
        rested = end < len(status) and status[end] == "parked"
        out.append({"t": float(cycles[k]["t"]), "rested": rested, "reason": cycles[k]["reason"],
                    "took_s": float(cycles[end]["t"]) - float(cycles[k]["t"]) if end < len(status) else None,
                    "bound_s": bound})
        k = end
    return out


def measure(config: str, faults: bool) -> dict:
    """The table's row of a session, from its folders."""
    folder = RESULTS / f"{config}-{'faults' if faults else 'steady'}"
    run = json.loads((folder / "soak.json").read_text())
    row = {"config": config, "faults": faults, "minutes": run["minutes"], "relay": run["relay"], "load": run["load"]}
    try:
        served = json.loads((folder / "served" / "summary.json").read_text())
        stand_in = json.loads((folder / "machine" / "summary.json").read_text())
        cycles = _rows(folder / "served" / "session.csv")
    except (OSError, ValueError) as exc:
        return {**row, "failed": f"{type(exc).__name__}: {exc}"}
    t = np.array([float(c["t"]) for c in cycles])
    latency = np.array([float(c["latency_s"]) for c in cycles])
    sixth = 60.0 * run["minutes"] / 6.0
    windows = []
    for i in range(6):
        pick = (t >= i * sixth) & (t < (i + 1) * sixth) & np.isfinite(latency)
        windows.append(None if not pick.any() else (1e3 * float(np.median(latency[pick])),
                                                    1e3 * float(np.percentile(latency[pick], 99))))
    rss = [r for r in run["rss"] if r["serve_mb"] is not None and r["machine_mb"] is not None]
    warm = next((r for r in rss if r["t"] >= sixth), rss[0] if rss else None)
    service = served.get("service", served)
    row.update(
        cycles=len(cycles), windows=windows, live=bool(served.get("live")),
        dropped=sum(service.get("dropped", {}).values()), received=service.get("received"),
        over_deadline=service.get("compute_over_deadline"),
        passed=stand_in.get("passed"), violations=stand_in.get("violation_count"),
        timing=sum((stand_in.get("timing_faults") or {}).values()), own_stops=len(stand_in.get("own_stops", [])),
        stops=[s for s in stand_in.get("own_stops", []) if s.get("at_rest") is not None],
        parks=parks(cycles, config),
        rss=None if warm is None else {k: (warm[k], rss[-1][k]) for k in ("serve_mb", "machine_mb")})
    return row


def _verdict(r: dict) -> str:
    """The stand-in's word: its violations of a limit (of what it was sent and of what it made) and
    its timing faults (a setpoint late, a gap while moving, a burst)."""
    return (f"{'passed' if r['passed'] else 'failed'}: {r['violations']} violations, {r['timing']} timing faults"
            + (f", {r['own_stops']} stops of its own" if r["own_stops"] else ""))


def table(rows: list[dict]) -> str:
    head = ("| session | cycles | latency median / p99 per sixth [ms] | p99 spread [ms] | RSS serve / stand-in "
            "after warm-up -> end [MB] | stand-in | the service's parks at rest within the limits' time | datagrams dropped |")
    lines = [head, "|" + " --- |" * (head.count("|") - 1)]
    for r in rows:
        name = f"{r['config']} {'faults' if r['faults'] else 'steady'}, {r['minutes']:g} min"
        if "failed" in r:
            lines.append(f"| {name} | failed: {r['failed']} |" + " |" * (head.count("|") - 3))
            continue
        p99 = [w[1] for w in r["windows"] if w is not None]
        lat = " · ".join("-" if w is None else f"{w[0]:.1f}/{w[1]:.1f}" for w in r["windows"])
        mem = "-" if r["rss"] is None else " / ".join(
            f"{a:.0f} -> {b:.0f} ({100 * (b - a) / a:+.1f} %)" for a, b in r["rss"].values())
        ours = [p for p in r["parks"] if not p["reason"].startswith("the machine is")]
        done = [p for p in ours if p["rested"]]
        within = sum(p["took_s"] <= p["bound_s"] + 1e-9 for p in done)
        worst = max((p["took_s"] / p["bound_s"] for p in done), default=None)
        park = f"{within} of {len(done)}" + ("" if worst is None else f" (at most {worst:.3f} of the time)") + (
            f"; {len(ours) - len(done)} ended by the host's return" if len(ours) > len(done) else "")
        stops = r["stops"]
        if stops:
            park += (f"; the stand-in's own stops: {sum(s['at_rest'] - s['start'] <= s['shortest_stop_s'] + 0.02 for s in stops)}"
                     f" of {len(stops)} within its shortest stop")
        lines.append(f"| {name} | {r['cycles']} | {lat} | {max(p99) - min(p99):.2f} | {mem} | {_verdict(r)} | "
                     f"{park} | {r['dropped']} |")
    for r in rows:
        if r.get("faults") and "failed" not in r:
            c = r["relay"]
            lines += ["", f"{r['config']} faults: the relay took {c['received']} datagrams, lost {c['lost']}, sent "
                      f"{c['duplicated']} twice, held {c['reordered']} back, dropped {c['outage']} in the "
                      f"{OUTAGE:g} s outage; the host restarted {c['host restarts passed on']} times."]
    loads = ", ".join(f"{r['load']:.2f}" for r in rows)
    lines += ["", f"Load average at each session's end: {loads} (2 cores); measured {time.strftime('%Y-%m-%d')}."]
    return "\n".join(lines)


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--minutes", type=float, default=60.0, help="each steady session's length (default 60)")
    parser.add_argument("--fault-minutes", type=float, default=None,
                        help="each fault session's length (default a third of --minutes, at most 5)")
    parser.add_argument("--configs", nargs="+", choices=tuple(CONFIGS), default=list(CONFIGS))
    parser.add_argument("--table-only", action="store_true")
    args = parser.parse_args(argv)
    faults = args.fault_minutes if args.fault_minutes is not None else min(5.0, args.minutes / 3.0)
    sessions = [(c, f) for f in (False, True) for c in args.configs]
    if not args.table_only:
        for config, fault in sessions:
            try:
                run = session(config, faults if fault else args.minutes, fault)
                print(f"{config} {'faults' if fault else 'steady'}: serve exit {run['served_rc']}, "
                      f"stand-in exit {run['machine_rc']}", flush=True)
            except Exception as exc:  # the campaign runs unattended: one session's failure is its row
                folder = RESULTS / f"{config}-{'faults' if fault else 'steady'}"
                folder.mkdir(parents=True, exist_ok=True)
                (folder / "soak.json").write_text(json.dumps({"minutes": faults if fault else args.minutes,
                                                              "relay": {}, "load": os.getloadavg()[0],
                                                              "rss": [], "error": repr(exc)}))
                print(f"{config}: {exc!r}", flush=True)
    rows = [measure(c, f) for c, f in sessions if (RESULTS / f"{c}-{'faults' if f else 'steady'}" / "soak.json").exists()]
    text = table(rows)
    print(text)
    tables.replace_between(BEGIN, END, text, "Soak and fault campaign", DOCS)
    return 0


if __name__ == "__main__":
    if len(sys.argv) == 5 and sys.argv[1] == "host":  # the host process of a session
        signal.signal(signal.SIGINT, signal.default_int_handler)
        sys.exit(host_loop(int(sys.argv[2]), bool(int(sys.argv[3])), float(sys.argv[4])))
    sys.exit(main())

"""The real FlightGear flying a bank-hold turn into ``desdemona host flightgear``, ``serve`` and the machine
stand-in, on loopback.

    python benchmarks/flightgear.py                       # dfs at 50 Hz, a 30 deg bank for 40 s
    python benchmarks/flightgear.py --config full --rate 20 --bank 45

It needs Debian's FlightGear (``apt-get install -y --no-install-recommends flightgear xvfb xauth``, about
2 minutes and 2 GB; the program is ``/usr/games/fgfs``) and flightgear-python
(``pip install 'desdemona[flightgear]'``). It is a benchmark, not a test: FlightGear takes 2 GB and most
of a core, and its first packets come 10-70 s after launch.

Five processes, as a user starts them (docs/guide/simulators.md): an X server without a screen (``Xvfb``);
the motion system's stand-in (``desdemona machine``); the service (``desdemona serve``, ending a few
seconds after the host has gone quiet and the machine is parked); the bridge (``desdemona host
flightgear``); and FlightGear, the Cessna 172 started in the air, with the scene's drawing switched off
(Mesa's software renderer crashes on it after about 45 s, and cannot draw it in real time), its native
FDM sent once a frame, and a bank-hold turn flown by FlightGear itself (``flightgear/bank-hold.xml``, a
Nasal module given with ``--config``): wings level for 30 s of simulated time, a bank of ``--bank``
degrees to the right until 70 s, level again. The bridge forwards once the first still second reads
+1 g up; the script stops it 85 s after that (``SIGINT``), ``serve`` parks the machine and writes the
session.

Written into ``--out``: the session (``session/``: trajectory, summary, ``view.html``), the stand-in's
check (``machine/``), each process's output, and ``benchmark.json``: the load average before and after,
FlightGear's packet rate, the bridge's own delay (packet received -> Motion sent), the service's latency
(Motion received -> setpoint sent), deadlines missed, the stand-in's verdict and the felt figures.
"""

from __future__ import annotations

import argparse
import json
import os
import shutil
import signal
import socket
import subprocess
import sys
import threading
import time
from pathlib import Path

import numpy as np
from service import _desdemona, _port  # benchmarks/service.py: the script's own folder is on the path

HERE = Path(__file__).resolve().parent
FGFS = "/usr/games/fgfs"
#: FlightGear's options besides the network output: what makes it run in real time under Xvfb here.
FGFS_OPTIONS = [
    "--aircraft=c172p", "--in-air", "--altitude=3000", "--vc=100", "--heading=90",
    "--prop:/engines/engine[0]/running=true", "--prop:/controls/engines/engine[0]/magnetos=3",
    "--prop:/controls/engines/engine[0]/mixture=1", "--prop:/controls/engines/engine[0]/throttle=0.85",
    "--prop:/sim/nasal-gc-threaded=true",  # no 100 ms stall every 6 s
    "--prop:/sim/rendering/draw-mask/terrain=false", "--prop:/sim/rendering/draw-mask/models=false",
    "--prop:/sim/rendering/draw-mask/aircraft=false", "--prop:/sim/rendering/draw-mask/clouds=false",
    "--prop:/sim/rendering/shaders/quality-level=0", "--disable-clouds3d", "--disable-sound",
    "--disable-splash-screen", "--disable-ai-traffic", "--disable-real-weather-fetch", "--disable-terrasync",
    "--geometry=640x480",
]
TURN_START, TURN_END, SETTLE = 30.0, 70.0, 15.0  # [s of simulated time]; level flight after the turn


def _display() -> str:
    """A display number no X server holds."""
    n = 77
    while Path(f"/tmp/.X11-unix/X{n}").exists() or Path(f"/tmp/.X{n}-lock").exists():
        n += 1
    return f":{n}"


class Monitor:
    """A second native FDM output of FlightGear, read by a thread: what was flown (bank, pitch, speed,
    altitude) beside the motion the bridge converts, decoded as the bridge decodes it."""

    def __init__(self, begun: float):
        from desdemona.service import flightgear

        self.decode, self.begun, self.rows = flightgear.decoder(), begun, []
        self.socket = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
        self.socket.bind(("127.0.0.1", 0))
        self.socket.settimeout(0.5)
        self.port = self.socket.getsockname()[1]
        self.stop = threading.Event()
        self.thread = threading.Thread(target=self._read, daemon=True)
        self.thread.start()

    def _read(self):
        while not self.stop.is_set():
            try:
                data = self.socket.recv(2048)
            except TimeoutError:
                continue
            s = self.decode(data)
            self.rows.append([time.monotonic() - self.begun, *np.degrees(s.attitude), s.speed,
                              float(np.linalg.norm(s.position)), *s.cabin()])

    def write(self, path: Path) -> dict:
        """fdm.csv, and the turn as flown: the largest bank, how long the bank was above 80 % of it, the
        felt force there, the packet rate."""
        self.stop.set()
        self.thread.join(timeout=2)
        self.socket.close()
        rows = np.array(self.rows)
        if not len(rows):
            return {}
        path.write_text("t_s,bank_deg,pitch_deg,speed_m_s,r_ecef_m,wx,wy,wz,fx,fy,fz\n" +
                        "".join(",".join(f"{x:.6g}" for x in row) + "\n" for row in rows))
        bank = rows[:, 1]
        turn = bank > 0.8 * bank.max()
        steps = np.diff(rows[:, 0])
        return {"packets_per_s": float(1.0 / np.median(steps)), "longest_gap_s": float(steps.max()),
                "bank_max_deg": float(bank.max()), "banked_s": float(np.sum(steps[turn[1:]])),
                "felt_in_turn_g": float(np.median(np.linalg.norm(rows[turn, 8:11], axis=1)) / 9.81),
                "wz_in_turn_rad_s": float(np.median(rows[turn, 7]))}


class Lines:
    """A process's output read by a thread: (seconds since the script began, line) pairs."""

    def __init__(self, proc: subprocess.Popen, begun: float):
        self.lines: list[tuple[float, str]] = []
        self.thread = threading.Thread(target=self._read, args=(proc, begun), daemon=True)
        self.thread.start()

    def _read(self, proc, begun):
        for line in proc.stdout:
            self.lines.append((time.monotonic() - begun, line.rstrip("\n")))

    def first(self, text: str, timeout: float, proc: subprocess.Popen) -> float | None:
        """When ``text`` first appeared [s], waiting up to ``timeout`` [s] for it while ``proc`` runs."""
        end = time.monotonic() + timeout
        while time.monotonic() < end and (proc.poll() is None or self.thread.is_alive()):
            hit = next((t for t, line in self.lines if text in line), None)
            if hit is not None:
                return hit
            time.sleep(0.5)
        return None

    def text(self) -> str:
        self.thread.join(timeout=10)
        return "\n".join(f"{t:8.2f}  {line}" for t, line in self.lines) + "\n"


def _start(args, out: Path, begun: float, monitor: int) -> dict:
    """The five processes, in the order a user starts them; FlightGear last."""
    fdm, listen, send = _port(), _port(), _port()
    display = _display()
    env = {**os.environ, "DISPLAY": display, "DBUS_FATAL_WARNINGS": "0", "FG_HOME": str(out / "fg-home")}
    pipe = dict(stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    procs = {"xvfb": subprocess.Popen(["Xvfb", display, "-screen", "0", "800x600x24", "-nolisten", "tcp"], **pipe)}
    procs["machine"] = subprocess.Popen(_desdemona("machine", "--config", args.config, "--listen",
                                                   f"127.0.0.1:{send}", "--out", out / "machine", "--idle", 10), **pipe)
    procs["serve"] = subprocess.Popen(_desdemona(
        "serve", "--config", args.config, "--listen", f"127.0.0.1:{listen}", "--send", f"127.0.0.1:{send}",
        "--rate", args.rate, "--timeout", args.timeout, "--out", out / "session", "--overwrite", "--quiet-end", 3.0),
        **pipe)
    procs["serve"].stdout.readline()  # "serving ...": the controller is built, the service listens
    modulus = ["--modulus"] if args.config in ("dfs", "dfs-yaw") else []
    procs["bridge"] = subprocess.Popen(_desdemona("host", "flightgear", "--listen", f"127.0.0.1:{fdm}", "--to",
                                                  f"127.0.0.1:{listen}", "--wait", 300, *modulus), **pipe)
    fgfs = [FGFS, *FGFS_OPTIONS, f"--native-fdm=socket,out,{args.fps},127.0.0.1,{fdm},udp", f"--max-fps={args.fps}",
            f"--native-fdm=socket,out,{args.fps},127.0.0.1,{monitor},udp",
            f"--config={HERE / 'flightgear' / 'bank-hold.xml'}", f"--prop:/desdemona/turn-start={TURN_START}",
            f"--prop:/desdemona/turn-end={TURN_END}", f"--prop:/desdemona/bank-deg={args.bank}"]
    (out / "fgfs-command.txt").write_text(" ".join(fgfs) + "\n")
    procs["fgfs"] = subprocess.Popen(fgfs, env=env, **pipe)
    return procs


def _stop(proc: subprocess.Popen, sig=signal.SIGINT, timeout: float = 60.0) -> None:
    if proc.poll() is None:
        proc.send_signal(sig)
        try:
            proc.wait(timeout=timeout)
        except subprocess.TimeoutExpired:
            proc.kill()
            proc.wait()


def _figures(out: Path, lines: dict, load: tuple, forwarding_at: float | None) -> dict:
    session = json.loads((out / "session" / "summary.json").read_text()) if (out / "session" / "summary.json").exists() else {}
    machine = json.loads((out / "machine" / "summary.json").read_text()) if (out / "machine" / "summary.json").exists() else {}
    bridge = [line for _, line in lines["bridge"].lines if line.startswith("forwarded")]
    felt = [line.strip() for _, line in lines["serve"].lines if "felt while following" in line]
    service = session.get("service", {})
    return {"load_before": load[0], "load_after": load[1], "forwarding_at_s": forwarding_at,
            "bridge": bridge[0] if bridge else None, "latency_s": service.get("latency_s"),
            "message_age_s": service.get("message_age_s"), "over_deadline": service.get("compute_over_deadline"),
            "cycles": service.get("cycles"), "status": service.get("status"), "received": service.get("received"),
            "dropped": service.get("dropped"), "stand_in_passed": machine.get("passed"),
            "stand_in_checked": machine.get("received"), "violations": machine.get("violations"),
            "worst_use": machine.get("worst_use"), "felt": felt[0] if felt else None,
            "view": (out / "session" / "view.html").exists()}


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", type=Path, default=HERE / "flightgear-results")
    parser.add_argument("--config", default="dfs")
    parser.add_argument("--rate", type=float, default=50.0, help="the service's rate [Hz]")
    parser.add_argument("--fps", type=int, default=60, help="FlightGear's frame and output rate [Hz]")
    parser.add_argument("--bank", type=float, default=30.0, help="the turn's bank [deg], > 0 to the right")
    parser.add_argument("--timeout", type=int, default=5,
                        help="serve's --timeout [cycles]: FlightGear on a loaded machine stalls for 0.2-0.3 s")
    args = parser.parse_args(argv)
    for tool in (FGFS, "Xvfb"):
        if shutil.which(tool) is None:
            print(f"{tool} is missing: apt-get install -y --no-install-recommends flightgear xvfb xauth", file=sys.stderr)
            return 2
    out = args.out.resolve()
    if out.exists():
        shutil.rmtree(out)
    out.mkdir(parents=True)
    begun, load_before = time.monotonic(), os.getloadavg()[0]
    monitor = Monitor(begun)
    procs = _start(args, out, begun, monitor.port)
    lines = {name: Lines(proc, begun) for name, proc in procs.items()}
    forwarding_at = None
    try:
        forwarding_at = lines["bridge"].first("the stream reads +1 g up", 300, procs["bridge"])
        if forwarding_at is not None:  # the turn begins about TURN_START after the simulation runs
            time.sleep(max(0.0, forwarding_at + TURN_END + SETTLE - (time.monotonic() - begun)))
    finally:
        _stop(procs["bridge"])
        for name in ("serve", "machine"):  # serve ends once parked and quiet; unless the host never came
            try:
                procs[name].wait(timeout=60)
            except subprocess.TimeoutExpired:
                _stop(procs[name])
        _stop(procs["fgfs"], signal.SIGTERM, 30)
        _stop(procs["xvfb"], signal.SIGTERM, 10)
        for name, got in lines.items():
            (out / f"{name}.txt").write_text(got.text())
    load_after = os.getloadavg()[0]
    figures = {**_figures(out, lines, (load_before, load_after), forwarding_at), **monitor.write(out / "fdm.csv")}
    (out / "benchmark.json").write_text(json.dumps(figures, indent=2) + "\n")
    print(json.dumps(figures, indent=2))
    return 0 if figures["stand_in_passed"] else 1


if __name__ == "__main__":
    raise SystemExit(main())

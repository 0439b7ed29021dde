"""The served cycle's compute with and without the real-time iteration's preparation, in processor time.

    python benchmarks/cycle_phases.py                 # both runs, 20 s of the F-16's turn each
    python benchmarks/cycle_phases.py --seconds 55    # the whole turn

The controller of a live session (``desdemona serve``'s options, :func:`desdemona.runs.session.live`)
is stepped over the F-16's 4.6 g turn (``benchmarks/corpus_scripts/f16_turn.xml``, as
``benchmarks/service.py`` flies it) as the service steps it: each cycle on the motion a host at its
own rate has sent so far, through the ``hold`` predictor. Each cycle is computed twice from the same
controller state: once in one shot (a copy of the controller, as before the split) and once fed into
the QP prepared after the previous cycle (:meth:`desdemona.control.mpc.MPC.prepare`); the two commands
must agree to 1e-9 (relative), and the closed loop follows the fed one. Timed with the thread's
processor time (:func:`time.thread_time`), which the machine's other processes do not inflate: what
the cycle costs, not when it ends on a shared machine. Runs: ``full`` at 50 Hz with a 60 Hz host,
``dfs`` at 100 Hz with a 120 Hz host (the two latency targets of issue 75).
"""

from __future__ import annotations

import argparse
import copy
import subprocess
import sys
import time
from pathlib import Path

import numpy as np

from desdemona import Model
from desdemona.control.mpc import MPC
from desdemona.control.predictors import predictor
from desdemona.machine.plan import State
from desdemona.profiles import DesiredPath
from desdemona.results.report import read_table
from desdemona.runs import session

HERE = Path(__file__).resolve().parent
RESULTS = HERE / "service-results"
SCRIPT, START = str(HERE / "corpus_scripts" / "f16_turn.xml"), 3.0
RUNS = {"full-50-host60": ("full", 50.0, 60.0), "dfs-100-host120": ("dfs", 100.0, 120.0)}


def _recording(modulus: bool, rate: float, seconds: float) -> DesiredPath:
    out = RESULTS / f"f16-turn{'-modulus' if modulus else ''}-{rate:g}hz-{seconds:g}s.csv"
    if not out.exists():
        RESULTS.mkdir(parents=True, exist_ok=True)
        subprocess.run([sys.executable, "-m", "desdemona", "import", "jsbsim", SCRIPT, "--start", str(START),
                        "--end", str(START + seconds), "--rate", str(rate), "--out", str(out),
                        *(["--modulus"] if modulus else [])], check=True, capture_output=True)
    col = read_table(out)
    if modulus:
        return DesiredPath("host", col["t"], None, modulus=col["M"])
    return DesiredPath("host", col["t"], np.column_stack([col[k] for k in ("wx", "wy", "wz", "fx", "fy", "fz")]))


def run(name: str, seconds: float) -> dict:
    """One run: per cycle the one-shot and the fed compute [s of processor time], the preparation's,
    the controller's phases (wall) of the fed step, and the largest difference of the commands."""
    config, rate, host_rate = RUNS[name]
    model = Model(config=config)
    modulus = model.config.takes_modulus
    options = session.live(model, channels=1 if modulus else 6, rate=rate).options
    mpc = MPC(model, options.mpc, weights=options.mpc.weights)
    path, h, predict = _recording(modulus, host_rate, seconds), 1.0 / rate, predictor("hold")
    state = State(np.zeros(model.n), np.zeros(model.n), np.zeros(model.n))
    rows = []
    for k in range(round(path.t[-1] / h)):
        seen = path.t <= k * h + 1e-9  # what the host has sent by the cycle's time
        if seen.sum() < 2:
            continue
        received = DesiredPath("host", path.t[seen], None if modulus else path.S_d[seen],
                               modulus=path.M_d[seen] if modulus else None)
        cpu = time.thread_time()
        preview = predict(model.config.cue_path(received), float(received.t[-1]), mpc.options.horizon)
        cpu_preview = time.thread_time() - cpu
        cpu = time.thread_time()
        expected = copy.copy(mpc).step(state, preview)
        cpu_one = time.thread_time() - cpu
        cpu = time.thread_time()
        mpc.prepare(state)
        cpu_prepare = time.thread_time() - cpu
        cpu = time.thread_time()
        command = mpc.step(state, preview)
        cpu_fed = time.thread_time() - cpu
        scale = 1.0 + np.abs(expected.sequence)
        rows.append((cpu_preview, cpu_one, cpu_prepare, cpu_fed, float(np.max(np.abs(command.sequence - expected.sequence) / scale)),
                     *(mpc.timings[key] for key in ("preview", "qp_data", "qp", "check"))))
        state = state.advance(command.sequence[0], h, command.jerks[0])
    table = np.array(rows)
    return {"name": name, "cycles": len(rows), "refreshed": mpc._rti.refreshed, "worst_difference": float(table[:, 4].max()),
            "cpu_ms": {key: (1e3 * float(np.median(table[:, i])), 1e3 * float(np.percentile(table[:, i], 99)))
                       for i, key in enumerate(("predictor", "one shot", "prepare", "fed"))},
            "phases_ms": {key: (1e3 * float(np.median(table[:, 5 + i])), 1e3 * float(np.percentile(table[:, 5 + i], 99)))
                          for i, key in enumerate(("preview", "qp_data", "qp", "check"))}}


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--runs", nargs="+", choices=tuple(RUNS), default=list(RUNS))
    parser.add_argument("--seconds", type=float, default=20.0)
    args = parser.parse_args(argv)
    for name in args.runs:
        r = run(name, args.seconds)
        cpu = ", ".join(f"{k} {m:.2f} / {p:.2f}" for k, (m, p) in r["cpu_ms"].items())
        phases = ", ".join(f"{k} {m:.2f} / {p:.2f}" for k, (m, p) in r["phases_ms"].items())
        print(f"{name}: {r['cycles']} cycles, processor time median / p99 [ms]: {cpu}; the fed step's phases "
              f"(wall): {phases}; refreshed {r['refreshed']}; commands agree to {r['worst_difference']:.1e}", flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())

"""Fingerprint of every benchmark row and the tests' closed loops: the proof that a refactor changed nothing.

A refactor that must not change any result is accepted when this script, run before and after it,
shows every RMS, iteration count and command bit for bit identical. Record a baseline from a frozen
copy of the code before the refactor, then one from the refactored code, and compare:

    git archive HEAD --prefix=snap/ | tar -x -C /tmp                      # a frozen copy, /tmp/snap/src
    python benchmarks/fingerprint.py --src /tmp/snap/src --out /tmp/fingerprint-before.json
    ... refactor ...
    python benchmarks/fingerprint.py --src src --out /tmp/fingerprint-after.json
    python benchmarks/fingerprint.py --compare /tmp/fingerprint-before.json /tmp/fingerprint-after.json
    python benchmarks/fingerprint.py --compare /tmp/fingerprint-before.json /tmp/fingerprint-after.json \
        --ignore 'online:metrics.rms_weighted,online:metrics.rms_weighted_classical'

``--compare`` prints, per case, every key whose value differs (and the keys present on one side only)
and exits 1 if anything differs, 0 if the two are identical. ``--ignore`` takes comma-separated
``fnmatch`` patterns of keys to leave out of the comparison, each matched against the whole dotted key
(``metrics.rms_weighted``) and against its last part (``rms_weighted``), and a key matching a whole
group leaves out what is under it (``quality``); a pattern ``CASES:KEYS`` applies only to the cases
whose name matches ``CASES`` or whose command is ``CASES`` (``online:metrics.rms_weighted``: every
on-line case, the real inputs' too, for an intended change of how the on-line RMS is judged). In
patterns ``*`` and ``?`` are wildcards, ``[...]`` a set of characters (``[[]`` for a bracket).
``--cases PATTERN ...`` runs only some cases, ``--list`` lists them with their commands,
``--repeat-online`` runs every on-line case a second time and exits 1 if its fingerprint differs.

Every case is the command a user types, run as its own process (``python -m desdemona ...``, with
``--no-view --overwrite --out <tmp>/<case>``, and ``--quiet`` where the command has it), so that the
fingerprint depends only on the command-line interface, never on module names inside the package.
``--src DIR`` puts DIR first on the processes' PYTHONPATH (the package imported is DIR's, not the
installed one). The processes run with one BLAS/OpenMP thread (``OMP_NUM_THREADS=1``,
``OPENBLAS_NUM_THREADS=1``, ``MKL_NUM_THREADS=1``) so that a parallel reduction's order cannot vary,
and compiled stage functions come from the usual cache (``$DESDEMONA_CACHE``; a library is keyed by
the SHA-256 of its C source, so a stale one is never used). The few inputs that are not built-in
paths are made with the command line too: the built-in catapult cut to its first 4 s (the tests'
short catapult), dfs-catapult cut to 3 s, the roller coaster cut to 15 s, by ``desdemona profiles
NAME --csv`` and keeping the rows up to that time, and benchmarks/offline.py's 10 s periodic path
(written by this script); their SHA-256 is recorded (the pseudo-case ``inputs``). The
real inputs are files of the corpus (``benchmarks/corpus``, built by ``python benchmarks/corpus.py
--out benchmarks/corpus``).

Per case the fingerprint holds the exit code, every entry of the result's summary.json (flattened to
dotted keys: ``metrics.rms_weighted``, ``solver.iterations``, ``solver.starts[0].iterations``,
``cycles.sources.shifted`` ...: the RMS values, worst limit use, solver status and iterations, the
fallbacks on-line, the quality metrics, the options and parameters used), the SHA-256 of
``trajectory.csv`` (the commanded joint trajectory: "the command"), of ``classical.csv`` where the
folder has it, and of ``cycles.csv`` without its compute-time column (the time, source and fallback
reason of every cycle). Left out because they vary from run to run: the command line string
(``command``: it holds the temporary folder), ``versions``, ``solver.timings_s``, every start's
``solve_time``, ``cycles.compute_time_s`` (median, p99, max) and the compute-time column of
cycles.csv, and every file that holds a date or timings (trajectory.mat, the figures). The wall time
of each case is kept under ``_wall_s``, which ``--compare`` never compares.

A run that the machine's state ends, not the code, is run again (up to 3 times, 30 s apart; the
count is kept under ``_retries``): one killed by a signal (the out-of-memory killer), or refused
(exit 2) because its size check found too little memory available at that moment (the check reads
MemAvailable, which other work on the machine can drain: seen once, "0.0 GB are available").

On-line results depend on timing through the per-cycle deadline (a plan computed too slowly is
replaced by a fallback), so every on-line case passes ``--deadline 100``: no plan is ever late, and
the run is deterministic (``cycles.deadline_misses`` is recorded and is 0).
"""

from __future__ import annotations

import argparse
import fnmatch
import hashlib
import json
import math
import os
import subprocess
import sys
import tempfile
import time
from pathlib import Path

HERE = Path(__file__).resolve().parent
CORPUS = HERE / "corpus"

# Dotted keys of summary.json that vary from run to run (fnmatch patterns on the whole key).
EXCLUDED = ("command", "versions", "versions.*", "solver.timings_s", "solver.timings_s.*",
            "solver.starts*.solve_time", "cycles.compute_time_s", "cycles.compute_time_s.*")
RETRIES, RETRY_PAUSE = 3, 30.0  # a run ended by the machine's state (transient) is run again
ONLINE = ["--deadline", "100"]  # no plan is ever late: the fallbacks do not depend on the machine's speed

# Inputs made with the command line: (file name, built-in path, keep the rows with t <= this [s]).
INPUTS = [("catapult-4s.csv", "catapult", 4.0), ("dfs-catapult-3s.csv", "dfs-catapult", 3.0),
          ("roller-coaster-15s.csv", "roller-coaster", 15.0)]


def periodic(duration: float) -> str:
    """benchmarks/offline.py's scaling path as CSV text: f_x = 3 sin(0.8 t), f_y = 5 cos(0.5 t), 100 Hz."""
    lines = ["# periodic: benchmarks/offline.py's scaling path\n", "# weights: 0,0,0,1,1,0\n", "t,wx,wy,wz,fx,fy,fz\n"]
    for k in range(round(duration / 0.01) + 1):
        t = k * 0.01
        lines.append(f"{t!r},0.0,0.0,0.0,{3.0 * math.sin(0.8 * t)!r},{5.0 * math.cos(0.5 * t)!r},9.81\n")
    return "".join(lines)


def corpus(name: str) -> str:
    return str(CORPUS / name)


# (case name, command after "desdemona"). Inputs: "{in}/NAME" is a file of INPUTS.
CASES: list[tuple[str, list[str]]] = [
    # --- off-line: the README's jobs and benchmarks/offline.py's rows -------------------------------
    ("offline-catapult-yaw-track-cabin", ["optimize", "catapult", "--config", "yaw-track-cabin"]),
    ("offline-catapult-yaw-track-cabin-fatrop", ["optimize", "catapult", "--config", "yaw-track-cabin",
                                                 "--method", "fatrop", "--starts", "1"]),
    ("offline-catapult-yaw-track-cabin-thesis", ["optimize", "catapult", "--config", "yaw-track-cabin",
                                                 "--method", "thesis", "--starts", "1"]),
    ("offline-cosine-toy-ipopt", ["optimize", "cosine", "--config", "yaw-track", "--base", "thesis-toy",
                                  "--h-u", "0.1", "--starts", "1"]),
    ("offline-cosine-toy-fatrop", ["optimize", "cosine", "--config", "yaw-track", "--base", "thesis-toy",
                                   "--h-u", "0.1", "--starts", "1", "--method", "fatrop"]),
    ("offline-cosine-toy-thesis", ["optimize", "cosine", "--config", "yaw-track", "--base", "thesis-toy",
                                   "--method", "thesis"]),
    ("offline-catapult-yaw-track-perception", ["optimize", "catapult", "--config", "yaw-track",
                                               "--perception", "thesis"]),
    ("offline-catapult-thesis-setting", ["optimize", "catapult", "--weights", "path", "--initial", "free",
                                         "--final", "none"]),
    ("offline-catapult-yaw-track-cabin-given", ["optimize", "catapult", "--config", "yaw-track-cabin",
                                                "--initial", "given", "--initial-state", "0,-1.5,0;0,0,0",
                                                "--starts", "1"]),
    ("offline-catapult-full", ["optimize", "catapult", "--config", "full", "--starts", "1"]),
    ("offline-catapult-full-gain", ["optimize", "catapult", "--config", "full", "--gain", "0.5",
                                    "--weights", "1,1,1,3,1,1", "--starts", "1"]),
    ("offline-car-lap-full", ["optimize", "car-lap", "--config", "full", "--h-u", "0.05", "--starts", "1"]),
    ("offline-dfs-catapult", ["optimize", "dfs-catapult", "--config", "dfs", "--starts", "2"]),
    ("offline-roller-coaster-15s-dfs", ["optimize", "{in}/roller-coaster-15s.csv", "--config", "dfs",
                                        "--starts", "1"]),
    ("offline-cosine-toy-fatrop-8-starts", ["optimize", "cosine", "--config", "yaw-track", "--base",
                                            "thesis-toy", "--h-u", "0.1", "--starts", "8", "--method", "fatrop"]),
    ("offline-periodic-10s-yaw-track-cabin", ["optimize", "{in}/periodic-10s.csv", "--config", "yaw-track-cabin",
                                              "--starts", "1"]),
    ("offline-double-pulse-yaw-track-cabin", ["optimize", "double-pulse", "--config", "yaw-track-cabin",
                                              "--starts", "1"]),
    ("offline-catapult-full-refine", ["optimize", "catapult", "--config", "full", "--refine", "--starts", "1"]),
    ("offline-roller-coaster-dfs", ["optimize", "roller-coaster", "--config", "dfs", "--starts", "1"]),
    # --- on-line: the closed loops of tests/test_online.py, test_dfs.py, test_api.py -----------------
    ("online-dfs-catapult-h1-s0.05", ["online", "dfs-catapult", "--config", "dfs", "--horizon", "1",
                                      "--step", "0.05", "--predictor", "perfect"]),
    ("online-dfs-catapult-h1-s0.05-nlp", ["online", "dfs-catapult", "--config", "dfs", "--horizon", "1",
                                          "--step", "0.05", "--method", "nlp"]),
    ("online-dfs-catapult-h1-s0.1", ["online", "dfs-catapult", "--config", "dfs", "--horizon", "1",
                                     "--step", "0.1"]),
    ("online-dfs-catapult-session", ["online", "dfs-catapult", "--config", "dfs", "--horizon", "2",
                                     "--step", "0.02"]),
    ("online-dfs-catapult-session-hold", ["online", "dfs-catapult", "--config", "dfs", "--horizon", "2",
                                          "--step", "0.02", "--predictor", "hold"]),
    ("online-dfs-catapult-session-steady", ["online", "dfs-catapult", "--config", "dfs", "--horizon", "2",
                                            "--step", "0.02", "--initial", "steady"]),
    ("online-dfs-catapult-recorded-hold", ["online", "dfs-catapult-recorded", "--config", "dfs",
                                           "--horizon", "2", "--step", "0.02", "--predictor", "hold"]),
    ("online-roller-coaster-15s-dfs", ["online", "{in}/roller-coaster-15s.csv", "--config", "dfs",
                                       "--horizon", "1", "--step", "0.05"]),
    ("online-dfs-catapult-3s-given", ["online", "{in}/dfs-catapult-3s.csv", "--config", "dfs", "--step", "0.05",
                                      "--horizon", "1", "--initial", "given", "--initial-state",
                                      "0,0.1,0,0;1.2,0,0,0"]),
    ("online-catapult-dfs-yaw-thesis-timing", ["online", "catapult", "--config", "dfs-yaw", "--horizon", "1",
                                               "--step", "0.1", "--replan", "0.4", "--delay"]),
    ("online-catapult-dfs-yaw-nlp-replan-hold", ["online", "catapult", "--config", "dfs-yaw", "--horizon", "1",
                                                 "--step", "0.1", "--replan", "0.4", "--method", "nlp",
                                                 "--predictor", "hold"]),
    ("online-catapult-dfs-thesis-timing", ["online", "catapult", "--config", "dfs", "--horizon", "1",
                                           "--step", "0.1", "--replan", "0.4", "--delay"]),
    ("online-catapult-4s-yaw-track-cabin", ["online", "{in}/catapult-4s.csv", "--config", "yaw-track-cabin",
                                            "--horizon", "1", "--step", "0.05"]),
    ("online-catapult-4s-yaw-track-cabin-h2-hold", ["online", "{in}/catapult-4s.csv", "--config",
                                                    "yaw-track-cabin", "--horizon", "2", "--step", "0.05",
                                                    "--predictor", "hold"]),
    ("online-catapult-4s-yaw-track-cabin-h2-home", ["online", "{in}/catapult-4s.csv", "--config",
                                                    "yaw-track-cabin", "--horizon", "2", "--step", "0.05",
                                                    "--initial", "home"]),
    ("online-catapult-4s-yaw-track-felt", ["online", "{in}/catapult-4s.csv", "--config", "yaw-track",
                                           "--step", "0.1"]),
    ("online-catapult-4s-yaw-track-path-weights", ["online", "{in}/catapult-4s.csv", "--config", "yaw-track",
                                                   "--step", "0.1", "--weights", "path"]),
    ("online-cosine-full-steady", ["online", "cosine", "--config", "full", "--horizon", "2", "--step", "0.05",
                                   "--initial", "steady"]),
    ("online-cosine-full-hold", ["online", "cosine", "--config", "full", "--horizon", "2", "--step", "0.05",
                                 "--predictor", "hold"]),
    # --- on-line: rows of benchmarks/online.py ------------------------------------------------------
    ("online-roller-coaster-dfs-session", ["online", "roller-coaster", "--config", "dfs", "--horizon", "2",
                                           "--step", "0.02"]),
    ("online-dfs-catapult-dfs-yaw-session", ["online", "dfs-catapult", "--config", "dfs-yaw", "--horizon", "2",
                                             "--step", "0.02"]),
    ("online-dfs-catapult-dfs-yaw-thesis-timing-k0", ["online", "dfs-catapult", "--config", "dfs-yaw",
                                                      "--horizon", "1", "--step", "0.1", "--replan", "0.4",
                                                      "--delay", "--reach", "1"]),
    ("online-double-pulse-yaw-track", ["online", "double-pulse", "--config", "yaw-track", "--horizon", "2",
                                       "--step", "0.05"]),
    ("online-catapult-full", ["online", "catapult", "--config", "full", "--horizon", "2", "--step", "0.05"]),
    ("online-catapult-yaw-track-cabin-linear", ["online", "catapult", "--config", "yaw-track-cabin",
                                                "--horizon", "2", "--step", "0.05", "--predictor", "linear"]),
    ("online-catapult-yaw-track-reach-2", ["online", "catapult", "--config", "yaw-track", "--horizon", "2",
                                           "--reach", "2", "--step", "0.05"]),
    ("online-roller-coaster-15s-route", ["online", "{in}/roller-coaster-15s.csv", "--config", "dfs",
                                         "--horizon", "2", "--step", "0.05", "--predictor", "route",
                                         "--reference", "roller-coaster"]),
    ("online-car-lap-full", ["online", "car-lap", "--config", "full", "--horizon", "2", "--step", "0.05"]),
    # --- real inputs: short rows of benchmarks/real.py (the corpus) ----------------------------------
    ("real-rudder-kick-yaw-track-cabin-offline", ["optimize", corpus("b737-rudder-kick.csv"),
                                                  "--config", "yaw-track-cabin"]),
    ("real-rudder-kick-yaw-track-cabin-hold", ["online", corpus("b737-rudder-kick.csv"),
                                               "--config", "yaw-track-cabin", "--predictor", "hold"]),
    ("real-rudder-kick-full-perfect", ["online", corpus("b737-rudder-kick.csv"), "--config", "full",
                                       "--predictor", "perfect"]),
    ("real-rudder-kick-dfs-offline", ["optimize", corpus("b737-rudder-kick-M.csv"), "--config", "dfs"]),
    ("real-rudder-kick-dfs-hold", ["online", corpus("b737-rudder-kick-M.csv"), "--config", "dfs",
                                   "--predictor", "hold"]),
    ("real-doublet-yaw-track-cabin-offline", ["optimize", corpus("c172-doublet.csv"), "--config",
                                              "yaw-track-cabin"]),
    ("real-doublet-dfs-offline", ["optimize", corpus("c172-doublet-M.csv"), "--config", "dfs"]),
    ("real-doublet-dfs-hold", ["online", corpus("c172-doublet-M.csv"), "--config", "dfs", "--predictor", "hold"]),
    ("real-doublet-yaw-track-cabin-hold", ["online", corpus("c172-doublet.csv"), "--config",
                                           "yaw-track-cabin", "--predictor", "hold"]),
    ("real-doublet-yaw-track-cabin-perfect", ["online", corpus("c172-doublet.csv"), "--config",
                                              "yaw-track-cabin", "--predictor", "perfect"]),
]


def sha256(data: bytes) -> str:
    return hashlib.sha256(data).hexdigest()


def environment(src: str | None) -> dict:
    env = dict(os.environ)
    if src:
        env["PYTHONPATH"] = os.pathsep.join([str(Path(src).resolve()), *filter(None, [env.get("PYTHONPATH")])])
    for name in ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS"):
        env[name] = "1"
    return env


def desdemona(args: list[str], env: dict, cwd: Path) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-m", "desdemona", *args], env=env, cwd=cwd,
                          capture_output=True, text=True, check=False)


def make_inputs(folder: Path, env: dict) -> dict:
    """The inputs of INPUTS, written into ``folder``; their fingerprint."""
    record = {}
    for name, builtin, end in INPUTS:
        full = folder / f"full-{name}"
        done = desdemona(["profiles", builtin, "--csv", str(full), "--overwrite"], env, folder)
        if done.returncode != 0:
            raise SystemExit(f"desdemona profiles {builtin} --csv: exit {done.returncode}\n{done.stderr}")
        kept, header = [], False
        for line in full.read_text().splitlines(keepends=True):
            if line.startswith("#") or not header:
                header = header or not line.startswith("#")
                kept.append(line)
            elif float(line.split(",", 1)[0]) <= end + 1e-9:
                kept.append(line)
        (folder / name).write_text("".join(kept))
        record[f"{name}#sha256"] = sha256((folder / name).read_bytes())
        record[f"{name}#rows"] = len(kept)
    (folder / "periodic-10s.csv").write_text(periodic(10.0))
    record["periodic-10s.csv#sha256"] = sha256((folder / "periodic-10s.csv").read_bytes())
    return record


def flatten(value, prefix: str = "") -> dict:
    """Dotted keys of a JSON value; lists of scalars stay whole, lists of objects get [i]."""
    if isinstance(value, dict):
        out = {}
        for key, item in value.items():
            out.update(flatten(item, f"{prefix}.{key}" if prefix else str(key)))
        return out
    if isinstance(value, list) and any(isinstance(v, (dict, list)) for v in value):
        out = {}
        for i, item in enumerate(value):
            out.update(flatten(item, f"{prefix}[{i}]"))
        return out
    return {prefix: value}


def excluded(key: str) -> bool:
    return any(fnmatch.fnmatchcase(key, p) for p in EXCLUDED)


def cycles_fingerprint(file: Path) -> str:
    """SHA-256 of cycles.csv without its compute-time column (t, source, reason of every cycle)."""
    lines = file.read_text().splitlines()
    names = lines[0].split(",")
    keep = [i for i, n in enumerate(names) if n != "compute_time_s"]
    text = []
    for line in lines:
        # the reason is the last column, quoted, and may hold commas: split only the first fields
        fields = line.split(",", len(names) - 1)
        text.append(",".join(fields[i] for i in keep if i < len(fields)))
    return sha256("\n".join(text).encode())


def full_command(args: list[str], work: Path, name: str) -> list[str]:
    """The case's command line after "desdemona", as it is run: inputs in ``work/inputs``, result in
    ``work/name``."""
    full = [a.replace("{in}", str(work / "inputs")) for a in args]
    full += ["--no-view", "--overwrite", "--out", str(work / name)]
    if full[0] == "optimize":
        full.append("--quiet")
    if full[0] == "online":
        full += ONLINE
    return full


def last_line(text: str) -> str:
    return (text.strip().splitlines() or [""])[-1]


def transient(done: subprocess.CompletedProcess) -> bool:
    """Whether a run ended by the machine's state rather than the code: killed by a signal (the
    out-of-memory killer), or refused because too little memory was available at that moment (the
    size check reads MemAvailable, which other work on the machine can drain)."""
    return done.returncode < 0 or (done.returncode == 2 and "memory" in last_line(done.stderr))


def fingerprint_case(name: str, args: list[str], work: Path, env: dict) -> dict:
    out = work / name
    full = full_command(args, work, name)
    for attempt in range(RETRIES + 1):
        start = time.perf_counter()
        done = desdemona(full, env, work)
        wall = time.perf_counter() - start
        if not transient(done) or attempt == RETRIES:
            break
        print(f"    {name}: exit {done.returncode} ({last_line(done.stderr)}): the machine's state, not the "
              f"code; again in {RETRY_PAUSE:g} s", file=sys.stderr, flush=True)
        time.sleep(RETRY_PAUSE)
    record = {"exit": done.returncode, "_wall_s": round(wall, 2), "_retries": attempt,
              "_command": "desdemona " + " ".join(full).replace(str(work), "<tmp>")}
    summary_file = out / "summary.json"
    if done.returncode not in (0, 4) or not summary_file.exists():
        record["error"] = last_line(done.stderr)
        return record
    summary = json.loads(summary_file.read_text())
    record.update({k: v for k, v in sorted(flatten(summary).items()) if not excluded(k)})
    for file in ("trajectory.csv", "classical.csv"):
        if (out / file).exists():
            record[f"{file}#sha256"] = sha256((out / file).read_bytes())
    if (out / "cycles.csv").exists():
        record["cycles.csv[t,source,reason]#sha256"] = cycles_fingerprint(out / "cycles.csv")
    return record


def selected(patterns: list[str] | None) -> list[tuple[str, list[str]]]:
    if not patterns:
        return CASES
    return [c for c in CASES if any(fnmatch.fnmatchcase(c[0], p) for p in patterns)]


def run(args) -> int:
    env = environment(args.src)
    cases = selected(args.cases)
    result = {"_about": {"src": str(Path(args.src).resolve()) if args.src else None,
                         "date": time.strftime("%Y-%m-%d %H:%M:%S"), "python": sys.executable},
              "cases": {}}
    started = time.perf_counter()
    nondeterministic = []
    with tempfile.TemporaryDirectory(prefix="desdemona-fingerprint-") as tmp:
        work = Path(tmp)
        (work / "inputs").mkdir()
        result["cases"]["inputs"] = make_inputs(work / "inputs", env)
        for k, (name, command) in enumerate(cases, 1):
            record = fingerprint_case(name, command, work, env)
            result["cases"][name] = record
            line = f"[{k}/{len(cases)}] {name}: exit {record['exit']}, {record['_wall_s']:.1f} s"
            if args.repeat_online and command[0] == "online":
                again = fingerprint_case(name, command, work, env)
                diff = differences(record, again, [])
                record["_repeat_wall_s"] = again["_wall_s"]
                line += f"; again {again['_wall_s']:.1f} s: " + ("identical" if not diff else f"{len(diff)} DIFFERENCES")
                if diff:
                    nondeterministic.append(name)
                    for d in diff:
                        print("    " + d, file=sys.stderr)
            if "error" in record:
                line += f" ({record['error']})"
            print(line, file=sys.stderr, flush=True)
    result["_about"]["wall_s"] = round(time.perf_counter() - started, 1)
    if args.repeat_online:
        result["_about"]["nondeterministic_online"] = nondeterministic
    print(f"{len(cases)} cases in {result['_about']['wall_s']:.0f} s", file=sys.stderr)
    text = json.dumps(result, indent=1, sort_keys=True)
    if args.out:
        Path(args.out).write_text(text + "\n")
    else:
        print(text)
    return 1 if nondeterministic else 0


def ignored(case: str, kind: str, key: str, patterns: list[str]) -> bool:
    """Whether ``key`` of ``case`` (whose command is ``kind``: optimize, online) is left out."""
    if key.startswith("_"):
        return True
    last = key.rsplit(".", 1)[-1]
    for pattern in patterns:
        cases, _, keys = pattern.rpartition(":")
        if cases and not (fnmatch.fnmatchcase(case, cases) or cases == kind):
            continue
        if fnmatch.fnmatchcase(key, keys) or fnmatch.fnmatchcase(last, keys) or key.startswith(keys + "."):
            return True
    return False


def same(a, b) -> bool:
    return json.dumps(a, sort_keys=True) == json.dumps(b, sort_keys=True)  # NaN equals NaN, 0.0 is not -0.0


def differences(a: dict, b: dict, patterns: list[str], case: str = "") -> list[str]:
    kind = (a.get("_command") or b.get("_command") or "desdemona -").split()[1]
    lines = []
    failed = ("error" in a) != ("error" in b)  # one run wrote no result: its error, not every key it lacks
    lacking = 0
    for key in sorted(set(a) | set(b)):
        if ignored(case, kind, key, patterns):
            continue
        if failed and key not in ("exit", "error") and (key not in a or key not in b):
            lacking += 1
            continue
        if key not in a:
            lines.append(f"{key}: only in the second: {b[key]!r}")
        elif key not in b:
            lines.append(f"{key}: only in the first: {a[key]!r}")
        elif not same(a[key], b[key]):
            lines.append(f"{key}: {a[key]!r} -> {b[key]!r}")
    if lacking:
        lines.append(f"({lacking} keys of the result present only in the {'first' if 'error' in b else 'second'})")
    return lines


def compare(first: str, second: str, patterns: list[str]) -> int:
    a, b = (json.loads(Path(f).read_text())["cases"] for f in (first, second))
    differing = 0
    for case in list(a) + [c for c in b if c not in a]:
        if case not in b or case not in a:
            print(f"{case}: only in the {'first' if case in a else 'second'} file")
            differing += 1
            continue
        lines = differences(a[case], b[case], patterns, case)
        if lines:
            differing += 1
            count = sum(not line.startswith("(") for line in lines)
            print(f"{case}: {count} difference(s)")
            for line in lines:
                print(f"    {line}")
    print(f"{len(set(a) | set(b))} cases: " + (f"{differing} differ" if differing else "identical")
          + (f" (ignoring {', '.join(patterns)})" if patterns else ""))
    return 1 if differing else 0


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0],
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--src", default=None, metavar="DIR",
                        help="put DIR first on the PYTHONPATH of the desdemona processes (e.g. /tmp/snap/src)")
    parser.add_argument("--out", default=None, metavar="FILE", help="write the fingerprint here (default: print)")
    parser.add_argument("--cases", nargs="+", default=None, metavar="PATTERN", help="only the cases matching these")
    parser.add_argument("--list", action="store_true", help="list the cases and their commands")
    parser.add_argument("--repeat-online", action="store_true",
                        help="run every on-line case twice; exit 1 if a second run differs")
    parser.add_argument("--compare", nargs=2, metavar=("A.json", "B.json"), default=None,
                        help="compare two fingerprints: exit 1 if anything differs")
    parser.add_argument("--ignore", default="", metavar="PATTERNS",
                        help="with --compare: comma-separated keys (fnmatch; CASES:KEYS for some cases only)")
    args = parser.parse_args(argv)
    if args.compare:
        return compare(*args.compare, [p for p in args.ignore.split(",") if p])
    if args.list:
        for name, command in selected(args.cases):
            print(f"{name:48s} desdemona {' '.join(full_command(command, Path('<tmp>'), name))}")
        return 0
    return run(args)


if __name__ == "__main__":
    sys.exit(main())

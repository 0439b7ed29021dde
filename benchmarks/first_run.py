"""A new user's first runs, timed: on a fresh compiled cache, after one limit changed, and once the
cache holds what the first run left to build in the background.

    python benchmarks/first_run.py                                 # this checkout
    python benchmarks/first_run.py --before OLD/src               # and an older one, side by side

For each code (this checkout's ``src``, and with ``--before`` another ``src`` folder, e.g. from ``git
archive be2a292 | tar -x``) and each case, in a cache of its own made empty for it:

1. ``first``: ``desdemona optimize PROFILE --config CONFIG --starts 1`` on the empty cache;
2. ``limit``: the same with ``--params`` a copy of the built-in parameters with the yaw's torque limit
   changed (300 -> 290 kN m), right after;
3. ``later``: the first command again, once what the runs started in the background has finished
   (at most ``--wait`` seconds).

Wall time and the CPU time of the command and the processes it waited for (the compiler; not what it
left running in the background), the load average before and after each, the printed RMS and status.
Nothing else should run meanwhile: the numbers are only as quiet as the machine (the load says it).
"""

from __future__ import annotations

import argparse
import os
import re
import resource
import subprocess
import sys
import tempfile
import time
from pathlib import Path

HERE = Path(__file__).resolve().parents[1] / "src"
CASES = (("catapult", "full"), ("catapult", "yaw-track-cabin"))


def load() -> str:
    return Path("/proc/loadavg").read_text().split()[0] if Path("/proc/loadavg").exists() else "-"


def timed(src: Path, cache: Path, argv: list[str], timeout: float) -> dict:
    """One command's wall and CPU seconds, the load before and after, and its printed result line."""
    env = {**os.environ, "PYTHONPATH": str(src), "DESDEMONA_CACHE": str(cache)}
    before, start = resource.getrusage(resource.RUSAGE_CHILDREN), time.perf_counter()
    load_before = load()
    done = subprocess.run([sys.executable, "-m", "desdemona", *argv], env=env, capture_output=True, text=True,
                          timeout=timeout, check=False)
    wall, after = time.perf_counter() - start, resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = after.ru_utime + after.ru_stime - before.ru_utime - before.ru_stime
    line = next((s for s in done.stdout.splitlines() if "RMS =" in s), done.stderr.strip()[-200:])
    rms = re.search(r"RMS = ([0-9.]+)", line)
    if done.returncode not in (0, 4):  # why, in the table
        print(f"<!-- exit {done.returncode}: {done.stderr.strip()[-600:]} -->", flush=True)
    return {"exit": done.returncode, "wall": wall, "cpu": cpu, "load": f"{load_before}-{load()}",
            "rms": rms.group(1) if rms else "-", "solver": "Solve_Succeeded" in line}


def settled(cache: Path, wait: float) -> float:
    """Seconds waited for the cache's background builds (their ``.building`` markers) to end."""
    start = time.perf_counter()
    while any(cache.glob("*.building")) and time.perf_counter() - start < wait:
        time.sleep(2.0)
    return time.perf_counter() - start


def changed_limit(src: Path, folder: Path) -> Path:
    """A copy of the built-in parameters with the yaw's torque limit 290 kN m instead of 300."""
    text = (src / "desdemona" / "data" / "default.toml").read_text()
    yaw = text.index("[joints.yaw]")
    torque = text.index("torque_kN_m = 300.0", yaw)
    file = folder / "changed-limit.toml"
    file.write_text(text[:torque] + "torque_kN_m = 290.0" + text[torque + len("torque_kN_m = 300.0"):])
    return file


def command(profile: str, config: str, out: Path, *extra: str) -> list[str]:
    """The timed command, into a result folder of its own."""
    return ["optimize", profile, "--config", config, "--starts", "1", *extra, "--out", str(out)]


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--before", type=Path, help="another checkout's src folder, timed first")
    parser.add_argument("--wait", type=float, default=600.0, help="at most this long for background builds [s]")
    parser.add_argument("--timeout", type=float, default=900.0, help="per command [s]")
    parser.add_argument("--cases", nargs="+", default=[f"{p}:{c}" for p, c in CASES], metavar="PROFILE:CONFIG")
    args = parser.parse_args(argv)
    codes = ([("before", args.before.resolve())] if args.before else []) + [("this", HERE)]
    print("| code | case | run | exit | wall [s] | CPU [s] | load (1 min) | RMS | converged |")
    print("| --- | --- | --- | --- | --- | --- | --- | --- | --- |")
    with tempfile.TemporaryDirectory(prefix="desdemona-first-run-") as work:
        work = Path(work)
        for case in args.cases:
            profile, config = case.split(":")
            for label, src in codes:
                cache = work / f"cache-{label}-{config}"
                cache.mkdir()
                runs = [("first", command(profile, config, work / f"out-{label}-{config}-first")),
                        ("limit", command(profile, config, work / f"out-{label}-{config}-limit",
                                          "--params", str(changed_limit(src, work))))]
                for name, argv_run in runs:
                    row = timed(src, cache, argv_run, args.timeout)
                    print(f"| {label} | {profile} on {config} | {name} | {row['exit']} | {row['wall']:.1f} | "
                          f"{row['cpu']:.1f} | {row['load']} | {row['rms']} | {row['solver']} |", flush=True)
                waited = settled(cache, args.wait)
                row = timed(src, cache, command(profile, config, work / f"out-{label}-{config}-later"), args.timeout)
                print(f"| {label} | {profile} on {config} | later (after {waited:.0f} s) | {row['exit']} | "
                      f"{row['wall']:.1f} | {row['cpu']:.1f} | {row['load']} | {row['rms']} | {row['solver']} |",
                      flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())

"""The screenshots of the result view in docs/guide/results.md, taken in headless chromium.

    python benchmarks/screenshots.py [--out docs/images] [--work FOLDER]

Runs the catapult quick start and an on-line `dfs` run (into ``--work``, default a temporary folder),
writes each one's view.html and saves ``view-catapult.png`` and ``view-dfs-online.png`` into ``--out``;
then serves the first seconds of ``dfs-catapult`` (the stand-in, ``serve --console`` and a replay host,
as docs/guide/serve.md runs them) and saves the operator's console as ``console-dfs.png``.
Needs the test extras and Debian's chromium and chromium-driver (as the view's tests do).
"""

from __future__ import annotations

import argparse
import socket
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from desdemona import profiles
from desdemona.cli import main
from desdemona.results import view

# (image, command, time shown [s], view mode)
SHOTS = (
    ("view-catapult.png", ["optimize", "catapult", "--config", "yaw-track-cabin", "--quiet"], 2.0, "orbit"),
    ("view-dfs-online.png", ["online", "dfs-catapult", "--config", "dfs"], 4.5, "follow"),
)
SIZE = (1500, 820)  # CSS pixels of the page


def shoot(folder: Path, image: Path, t: float, mode: str, driver) -> Path:
    page = view.write(folder)
    driver.execute_cdp_cmd("Emulation.setDeviceMetricsOverride",
                           {"width": SIZE[0], "height": SIZE[1], "deviceScaleFactor": 1, "mobile": False})
    driver.get(page.resolve().as_uri())
    driver.execute_script("const v = window.desdemonaView; v.setView(arguments[1]); v.seek(arguments[0]);", t, mode)
    errors = [e for e in driver.get_log("browser") if e["level"] == "SEVERE"]
    if errors:
        raise RuntimeError(f"{page}: console errors: {errors}")
    image.write_bytes(driver.get_screenshot_as_png())
    return image


def _port(kind=socket.SOCK_DGRAM) -> int:
    with socket.socket(socket.AF_INET, kind) as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def shoot_console(work: Path, image: Path, driver, seconds: float = 3.0) -> Path:
    """The operator's console ``seconds`` into a served ``dfs-catapult`` (all on 127.0.0.1)."""
    run = [sys.executable, "-m", "desdemona"]
    path = profiles.get_profile("dfs-catapult")
    profile = work / "catapult.csv"
    keep = path.t <= seconds + 3.0
    profiles.write_csv(profile, profiles.DesiredPath("catapult", path.t[keep], None, modulus=path.M_d[keep]))
    machine, listen, console = _port(), _port(), _port(socket.SOCK_STREAM)
    procs = [subprocess.Popen([*run, "machine", "--config", "dfs", "--listen", f"127.0.0.1:{machine}", "--out",
                               str(work / "console-machine"), "--idle", "2", "--duration", "120"],
                              stdout=subprocess.DEVNULL)]
    try:
        procs.append(subprocess.Popen([*run, "serve", "--config", "dfs", "--listen", f"127.0.0.1:{listen}", "--send",
                                       f"127.0.0.1:{machine}", "--out", str(work / "console-session"), "--quiet-end",
                                       "0.5", "--duration", "120", "--no-view", "--console", f"127.0.0.1:{console}"],
                                      stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True))
        for _ in range(10):
            if "serving" in procs[1].stderr.readline():
                break
        driver.execute_cdp_cmd("Emulation.setDeviceMetricsOverride",
                               {"width": SIZE[0], "height": SIZE[1], "deviceScaleFactor": 1, "mobile": False})
        driver.get(f"http://127.0.0.1:{console}/")
        procs.append(subprocess.Popen([*run, "host", "replay", str(profile), "--to", f"127.0.0.1:{listen}"],
                                      stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL))
        frame = "const f = window.consoleState && window.consoleState.frame; return f && f.received"
        end = time.monotonic() + 60
        while time.monotonic() < end and (driver.execute_script(frame) or 0) < 100 * seconds:
            time.sleep(0.1)
        image.write_bytes(driver.get_screenshot_as_png())
        for proc in procs[::-1]:
            proc.wait(timeout=60)
    finally:
        for proc in procs:
            if proc.poll() is None:
                proc.kill()
    return image


def run(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", type=Path, default=Path("docs/images"))
    parser.add_argument("--work", type=Path, default=None, help="folder for the runs (default: a temporary one)")
    args = parser.parse_args(argv)
    args.out.mkdir(parents=True, exist_ok=True)
    with tempfile.TemporaryDirectory() as tmp:
        work = args.work or Path(tmp)
        work.mkdir(parents=True, exist_ok=True)
        driver = view.headless_browser(*SIZE)
        try:
            for image, command, t, mode in SHOTS:
                folder = work / Path(image).stem
                code = main([*command, "--out", str(folder), "--overwrite"])
                if code not in (0, 4):
                    return code
                print(shoot(folder, args.out / image, t, mode, driver))
            print(shoot_console(work, args.out / "console-dfs.png", driver))
        finally:
            driver.quit()
    return 0


if __name__ == "__main__":
    sys.exit(run())

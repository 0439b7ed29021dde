"""The screenshots of the result view in docs/guide/results.md, taken in headless chromium.

    python benchmarks/screenshots.py [--out docs/images] [--work FOLDER]

Runs the catapult quick start and an on-line `dfs` run (into ``--work``, default a temporary folder),
writes each one's view.html and saves ``view-catapult.png`` and ``view-dfs-online.png`` into ``--out``.
Needs the test extras and Debian's chromium and chromium-driver (as the view's tests do).
"""

from __future__ import annotations

import argparse
import sys
import tempfile
from pathlib import Path

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
        finally:
            driver.quit()
    return 0


if __name__ == "__main__":
    sys.exit(run())

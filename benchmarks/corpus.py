"""The real-input corpus: flights from JSBSim's shipped scripts and aircraft (and two F-16 scripts of
our own in ``benchmarks/corpus_scripts/``), as desired paths a benchmark can read.

    python benchmarks/corpus.py                      # writes benchmarks/corpus/ (not committed)
    python benchmarks/corpus.py --out some/folder --cases f16-turn b737-runway
    python benchmarks/corpus.py --cases c172-doublet --forecasts   # with the aircraft's own forecasts

Each case is written in the six-channel form (``NAME.csv``: ``t,wx,wy,wz,fx,fy,fz``, what the pilot
feels in the cabin frame) and the modulus form (``NAME-M.csv``: ``t,M``, for ``dfs``), made as
``desdemona import jsbsim SCRIPT --start A --end B`` makes them (100 Hz, anti-alias filtered, ``#
source:`` lines). Each is cropped to a physically sane stretch: some shipped scripts start with a
drop onto the runway (9 g for a few samples) or end in a spin (hundreds of g); every case stays
below 10 g, checked here. ``index.json`` lists one entry per file: ``name``, ``file`` (relative to
the folder), ``form`` (``six`` or ``modulus``), ``duration_s``, ``peak_g``, ``source``,
``description``; and how long the build took.

With ``--forecasts`` each case also gets the forecasts its aircraft's own model makes
(``NAME.forecast.csv``, ``NAME-M.forecast.csv``, the format of :mod:`desdemona.profiles.forecast`, for
``desdemona online --predictor forecast``): every :data:`FORECAST_EVERY` s the model is run
:data:`FORECAST_SECONDS` ahead from its state with the pilot's controls held
(:func:`desdemona.profiles.jsbsim.forecast_from_jsbsim`); the index entry names it as ``forecast``.

Only simulated flights: the corpus is built without network access, and a public recorded ride or
drive (an IMU log of a car, a coaster, a flight) would need a download. A log of one's own goes in
with ``desdemona import log``.

Needs the jsbsim package (``pip install '.[jsbsim]'``). JSBSim runs as fast as it computes: the whole
corpus takes a few seconds.
"""

from __future__ import annotations

import argparse
import hashlib
import json
import sys
import time
from pathlib import Path

import numpy as np

from desdemona import profiles
from desdemona.profiles import convert, jsbsim
from desdemona.profiles.forecast import write_forecast

HERE = Path(__file__).resolve().parent
SCRIPTS = HERE / "corpus_scripts"
SANE_G = 10.0  # [g] a case above this is a transient or a crash, not a motion to cue
#: How often the model is run ahead for a forecast [s]: each run ahead (4 s of a 120 Hz model plus the
#: filter's margin) takes a fork and about 20 ms, so every 0.1 s is 0.2 s of computing per second of
#: flight (2 minutes for a 10-minute case); every cycle (0.02 s) would be five times that. The
#: controller plans every 0.02 s on the latest forecast, at most 0.1 s old.
FORECAST_EVERY = 0.1
#: How far each forecast reaches [s]: the longest default horizon (desdemona.control.mpc.default_horizon, 4 s
#: where the track moves); the predictor takes what its horizon needs.
FORECAST_SECONDS = 4.0

#: name: (script (a shipped name or a file of ours), start [s], end [s], what it is)
CASES = {
    "b747-takeoff": ("B747_script1", 25.0, 145.0,
                     "747 take-off: the roll at full power, rotation, lift-off and the first climb"),
    "b737-runway": ("b737_runway_new", 5.0, 90.0,
                    "737 ground test: engines spool up, roll to about 60 kt, hard braking to a stop"),
    "b737-steady-turn": ("737_cruise_steady_turn", 6.0, 100.0,
                         "737 at cruise in a steady coordinated right turn, 30 deg of bank (1.15 g)"),
    # the script trims again at 20 s, which sets the aircraft back to its initial state in one step:
    # no motion a pilot feels, so the crop ends before it
    "c172-doublet": ("c172_elevator_doublet", 3.0, 19.9,
                     "C172 at 4,000 ft: an elevator doublet (one sine period of full elevator at 5-7 s) "
                     "and the motion after it, up to the script's re-trim at 20 s"),
    "b737-rudder-kick": ("rudder_kick", 1.0, 20.0,
                         "737 from trimmed flight: rudder and aileron ramped to the stop (a rudder kick)"),
    "c172-takeoff": ("c1723", 3.0, 60.0,
                     "C172 take-off under the heading-hold autopilot: brake release, a swerving roll, "
                     "lift-off and climb"),
    "f16-turn": (SCRIPTS / "f16_turn.xml", 3.0, 58.0,
                 "F-16 at 420 kt, 15,000 ft: roll-in to a level 4.5 g right turn held for 40 s, roll-out"),
    "f16-sortie": (SCRIPTS / "f16_sortie.xml", 5.0, 605.0,
                   "F-16, 10 minutes: level legs, turns both ways asked at 2-5 g, pull-ups and push-overs, "
                   "a break-turn reversal, S-turns"),
    "b747-climb": ("B747_script1", 60.0, 660.0,
                   "747, 10 minutes: the take-off roll, lift-off and the climb-out at full power"),
}


def build(out: Path, names: list[str] | None = None, forecasts: bool = False) -> dict:
    """Write the cases (all, or ``names``), with ``forecasts`` their forecasts too, and ``index.json``
    into ``out``; returns the index."""
    out.mkdir(parents=True, exist_ok=True)
    entries, timings = [], {}
    started = time.perf_counter()
    for name, (script, start, end, what) in CASES.items():
        if names is not None and name not in names:
            continue
        tic = time.perf_counter()
        forecast = None
        if forecasts:
            path, comments, forecast = jsbsim.forecast_from_jsbsim(script, start, end, FORECAST_EVERY, FORECAST_SECONDS)
        else:
            path, comments = jsbsim.from_jsbsim(script, start, end)
        peak = float(np.max(path.M_d)) / profiles.G
        if peak > SANE_G:
            raise SystemExit(f"corpus case {name}: peak {peak:.1f} g is above {SANE_G:g} g; crop it differently")
        source = f"JSBSim {Path(str(script)).stem}, {start:g}-{end:g} s of sim time"
        modulus = ["source: modulus |f| only"]
        for form, version, suffix, extra, ahead in (
                ("six", path, "", [], forecast),
                ("modulus", profiles.modulus_version(path), "-M", modulus,
                 None if forecast is None else forecast.map(profiles.modulus_version))):
            file = f"{name}{suffix}.csv"
            convert.write_path(out / file, version, comments + extra, overwrite=True)
            entries.append({"name": name, "file": file, "form": form, "duration_s": round(path.duration, 6),
                            "peak_g": round(peak, 3), "source": source, "description": what})
            if ahead is not None:
                entries[-1]["forecast"] = f"{name}{suffix}.forecast.csv"
                note = (f"forecasts of {file}: every {FORECAST_EVERY:g} s the aircraft's model run "
                        f"{FORECAST_SECONDS:g} s ahead with the pilot's controls held")
                write_forecast(out / entries[-1]["forecast"], ahead, [note, *comments, *extra])
        timings[name] = round(time.perf_counter() - tic, 3)
    earlier = out / "index.json"
    if names is not None and earlier.exists():  # the other cases stay as they were built
        kept = json.loads(earlier.read_text())
        entries = [e for e in kept["cases"] if e["name"] not in names] + entries
        timings = {**{k: v for k, v in kept["case_s"].items() if k not in names}, **timings}
    index = {"cases": entries, "build_s": round(time.perf_counter() - started, 2), "case_s": timings,
             "definition": definition()}
    earlier.write_text(json.dumps(index, indent=1) + "\n")
    return index


def definition() -> str:
    """A fingerprint of what the corpus is made from (this script and our JSBSim scripts): a corpus
    built from another definition is stale (``benchmarks/real.py`` builds it again)."""
    digest = hashlib.sha256(Path(__file__).read_bytes())
    for script in sorted(SCRIPTS.glob("*.xml")):
        digest.update(script.read_bytes())
    return digest.hexdigest()[:16]


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description="Build the real-input corpus (JSBSim flights as desired paths).")
    parser.add_argument("--out", type=Path, default=HERE / "corpus", help="folder to write (default: benchmarks/corpus)")
    parser.add_argument("--cases", nargs="+", default=None, choices=tuple(CASES), help="only these cases")
    parser.add_argument("--forecasts", action="store_true",
                        help="also the aircraft's own forecasts (NAME.forecast.csv), its model run ahead")
    args = parser.parse_args(argv)
    index = build(args.out, args.cases, args.forecasts)
    for entry in index["cases"]:
        if entry["form"] == "six":
            print(f"{entry['name']:<18} {entry['duration_s']:7.1f} s  peak {entry['peak_g']:5.2f} g  "
                  f"{index['case_s'][entry['name']]:5.2f} s  {entry['description']}")
    print(f"{len(index['cases'])} files in {args.out}, built in {index['build_s']:.1f} s")
    return 0


if __name__ == "__main__":
    sys.exit(main())

"""Desired paths from a JSBSim flight: what the pilot feels, turned into the cabin frame.

JSBSim (https://github.com/JSBSim-Team/jsbsim, pip ``jsbsim``, an optional extra) runs one of its
shipped scripts (by name, from its ``scripts/`` folder) or a script file of the user's as fast as it
computes. The path is the specific force at the pilot station, ``accelerations/n-pilot-{x,y,z}-norm``
[g, body axes x forward, y right, z down], and the body rates ``velocities/{p,q,r}-rad_sec``, turned
into the cabin frame by :data:`.convert.R_CABIN_BODY` (DESIGN.md, "Vehicle data in").
"""

from __future__ import annotations

import contextlib
import difflib
import os
import sys
import tempfile
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from desdemona.profiles import convert
from desdemona.profiles.path import DesiredPath, G, ProfileError

INSTALL_HINT = "pip install 'desdemona[jsbsim]' (or, in a source checkout, pip install '.[jsbsim]')"
#: Default sample rate of the written path [Hz]: JSBSim steps at 120 Hz; 100 Hz keeps every motion cue
#: (below about 10 Hz) with a tenfold margin and a round time step.
DEFAULT_RATE = 100.0
#: Simulated past the crop's end so that the zero-phase filter has no edge inside the crop [s].
FILTER_MARGIN = 1.0
FORCE = ("accelerations/n-pilot-x-norm", "accelerations/n-pilot-y-norm", "accelerations/n-pilot-z-norm")
RATES = ("velocities/p-rad_sec", "velocities/q-rad_sec", "velocities/r-rad_sec")
ATTITUDE = ("attitude/phi-rad", "attitude/theta-rad")
#: Set to 1 by JSBSim when a trim (a script's ``simulation/do_simple_trim`` event) has succeeded.
TRIMMED = "simulation/trim-completed"
# The default start of a flight without a trim: the end of its start-up transient (the aircraft
# dropping onto its gear, the model's first steps). Settled from the first sample after which, for
# SETTLE_SECONDS, the specific force changes by less than SETTLE_JERK and the body rates by less than
# SETTLE_ALPHA from step to step (a settled JSBSim run stays below 1 m/s^3 and 0.1 rad/s^2; the settling
# jumps by hundreds of m/s^3); looked for in the first SETTLE_WITHIN s only (later motion is the
# flight's own), else the first sample.
SETTLE_SECONDS = 0.5   # [s]
SETTLE_JERK = 5.0      # [m/s^3]
SETTLE_ALPHA = 0.5     # [rad/s^2]
SETTLE_WITHIN = 10.0   # [s]
#: Still, for the convention check [rad/s]: a simulation has no gyro noise; slower than any turn that
#: banks the aircraft by more than the check's tolerance.
STILL_RATE = np.radians(0.2)


def _jsbsim():
    try:
        import jsbsim
    except ImportError:
        raise ProfileError(f"importing a JSBSim flight needs the jsbsim package: {INSTALL_HINT}") from None
    return jsbsim


def shipped_scripts() -> list[str]:
    """The names of the scripts that ship with the jsbsim package (file names without ``.xml``)."""
    folder = Path(_jsbsim().get_default_root_dir()) / "scripts"
    return sorted(p.stem for p in folder.glob("*.xml"))


def script_file(script: str | Path) -> Path:
    """A script file of the user's, or a shipped script by name (with or without ``.xml``)."""
    given = Path(script)
    if given.suffix.lower() == ".xml" and given.is_file():
        return given
    folder = Path(_jsbsim().get_default_root_dir()) / "scripts"
    for candidate in (folder / f"{given.name}.xml", folder / given.name):
        if candidate.is_file():
            return candidate
    if given.is_file():
        return given
    names = shipped_scripts()
    close = difflib.get_close_matches(given.stem, names, n=8, cutoff=0.4)
    close += [n for n in names if n not in close][: max(0, 5 - len(close))]
    raise ProfileError(f"JSBSim script {str(script)!r}: neither a file nor a shipped script; shipped are "
                       f"e.g. {', '.join(close)} ({len(names)} in all: desdemona import jsbsim --list)")


@dataclass(frozen=True)
class Flight:
    """A JSBSim run sampled after every step (none before the first: the model has not computed its
    accelerations yet): ``t`` (N,) [s] of sim time, ``omega_body`` (N, 3) [rad/s] (p, q, r), ``f_body``
    (N, 3) [m/s^2] at the pilot station, body axes (x forward, y right, z down), ``attitude`` (N, 2)
    [rad] bank and pitch (phi, theta), ``trimmed`` (N,) bool: a trim has completed (:data:`TRIMMED`);
    ``ahead``: the runs ahead with the controls held (:func:`fly`), (t [s], rows (n, 9): t, p, q, r, the
    pilot station's force [g], phi, theta) each; ``reset``: where the script set its clock back to run
    again (a series of runs, c172_elevation_test's), the sim time [s] its first run ended, which is all
    that is kept; None where it did not."""

    script: Path
    aircraft: str
    version: str
    t: np.ndarray
    omega_body: np.ndarray
    f_body: np.ndarray
    attitude: np.ndarray
    trimmed: np.ndarray | None = None
    ahead: tuple = ()
    reset: float | None = None


@contextlib.contextmanager
def _quiet(log_path: str):
    """JSBSim's own printing (its banner, script ``notify`` events, messages from C++) goes to
    ``log_path`` instead of this process's stdout and stderr: redirected at the file descriptors and,
    as the jsbsim module may hand C++'s output to Python's ``sys.stdout``, there too."""
    sys.stdout.flush()
    sys.stderr.flush()
    saved = os.dup(1), os.dup(2)
    with open(log_path, "wb") as sink, open(log_path.replace(".log", ".py.log"), "w") as text_sink:
        os.dup2(sink.fileno(), 1)
        os.dup2(sink.fileno(), 2)
        try:
            with contextlib.redirect_stdout(text_sink), contextlib.redirect_stderr(text_sink):
                yield
        finally:
            sys.stdout.flush()
            sys.stderr.flush()
            _flush_c_stdio()  # C++ std::cout writes through C's stdout buffer: empty it into the sink
            os.dup2(saved[0], 1)
            os.dup2(saved[1], 2)
            os.close(saved[0])
            os.close(saved[1])


def _flush_c_stdio() -> None:
    import ctypes

    try:
        ctypes.CDLL(None).fflush(None)
    except (OSError, AttributeError):  # no C library to reach (not on this platform): nothing buffered there
        pass


def _initialization_file(script: Path, root: Path, aircraft: str, initialize: str) -> str:
    """The script's initial-condition file as JSBSim wants it (relative to the aircraft's folder): one
    next to the script is found too, so a user's script can start its aircraft where it likes."""
    if not initialize or (root / "aircraft" / aircraft / f"{initialize}.xml").is_file():
        return ""
    local = script.resolve().parent / (initialize if initialize.endswith(".xml") else f"{initialize}.xml")
    if not local.is_file():
        return ""
    return os.path.relpath(local, root / "aircraft" / aircraft)


def _script_use(script: Path) -> tuple[str, str]:
    """(aircraft, initialize) of a script's ``<use>`` element."""
    import xml.etree.ElementTree as ET

    try:
        use = ET.parse(script).getroot().find("use")
    except (ET.ParseError, OSError) as exc:
        raise ProfileError(f"JSBSim script {script}: not readable XML: {exc}") from None
    if use is None or not use.get("aircraft"):
        raise ProfileError(f"JSBSim script {script}: no <use aircraft=...> element")
    return use.get("aircraft"), use.get("initialize", "")


def script_setup(script: str | Path) -> tuple[Path, Path, str, str]:
    """What JSBSim needs to load a script (a shipped one by name, or a file): its resolved path (JSBSim
    reads a relative one from its own root folder), JSBSim's root folder, the script's aircraft and its
    initialization file."""
    path = script_file(script).resolve()
    root = Path(_jsbsim().get_default_root_dir())
    aircraft, initialize = _script_use(path)
    return path, root, aircraft, _initialization_file(path, root, aircraft, initialize)


def fly(script: str | Path, end: float | None = None, ahead: tuple[np.ndarray, float] | None = None) -> Flight:
    """Run a JSBSim script (a shipped one by name, or a file) as fast as it computes, up to its own end
    or ``end`` [s] of sim time, sampling every step. JSBSim's printing is silenced.

    ``ahead`` = (times [s of sim time], seconds): at the step nearest each time, the model is
    also run ``seconds`` ahead with the pilot's controls held (:func:`_run_ahead`), into ``Flight.ahead``."""
    jsbsim = _jsbsim()
    path, root, aircraft, init = script_setup(script)
    rows = []
    failure = None
    with tempfile.TemporaryDirectory() as tmp:
        log = os.path.join(tmp, "jsbsim.log")
        with _quiet(log):
            try:
                fdm = jsbsim.FGFDMExec(str(root))
                fdm.set_debug_level(0)
                fdm.set_output_path(tmp)  # a script's <output> files go here, not into JSBSim's folder
                loaded = fdm.load_script(str(path), 0.0, init) if init else fdm.load_script(str(path))
                if not loaded:
                    failure = "JSBSim could not load it"
                else:
                    fdm.disable_output()
                    fdm.run_ic()
                    manager = fdm.get_property_manager()
                    props = [manager.get_node(name) for name in RATES + FORCE + ATTITUDE]
                    trimmed = manager.get_node(TRIMMED)  # None if this JSBSim has no such property
                    times, seconds = (np.zeros(0), 0.0) if ahead is None else (np.asarray(ahead[0]), ahead[1])
                    past_end, runs, issued, reset = _script_end(path) + 1.0, [], 0, None
                    while fdm.run():  # sampled after each step: before the first, no accelerations
                        t, half_step = fdm.get_sim_time(), 0.5 * fdm.get_delta_t()
                        if rows and t < rows[-1][0] - half_step:  # the script reset the run
                            reset = rows[-1][0]
                            break
                        rows.append([t, *(node.get_double_value() for node in props),
                                     trimmed.get_double_value() if trimmed is not None else 0.0])
                        if issued < len(times) and t >= times[issued] - half_step:  # the step nearest it
                            runs.append((t, _run_ahead(fdm, props, seconds, past_end)))
                            issued = int(np.searchsorted(times, t + half_step, side="right"))
                        if end is not None and t > end:
                            break
            except (jsbsim.BaseError, OSError) as exc:  # a trim that fails, a file that does not exist, ...
                at = f" at t = {rows[-1][0]:.2f} s" if rows else ""
                failure = f"{type(exc).__name__}{at}: {' '.join(str(exc).split())}"
        if failure is not None:
            said = [line.strip() for name in (log, log.replace(".log", ".py.log")) if os.path.exists(name)
                    for line in Path(name).read_text(errors="replace").splitlines() if line.strip()]
            detail = f"{failure} ({said[-1]})" if said and not rows else failure
            raise ProfileError(f"JSBSim script {path}: cannot be run: {detail}")
    data = np.array(rows)
    if len(data) < 2:
        raise ProfileError(f"JSBSim script {path}: ran no time")
    keep = np.concatenate([np.diff(data[:, 0]) > 0, [True]])  # a trim may repeat a time: its last sample
    data = data[keep]
    return Flight(path, aircraft, jsbsim.__version__, data[:, 0], data[:, 1:4], data[:, 4:7] * G, data[:, 7:9],
                  data[:, 9] > 0.5, tuple(runs), reset)


def _run_ahead(fdm, nodes, seconds: float, past_end: float) -> np.ndarray:
    """The model run ``seconds`` ahead from its present state with the pilot's controls held: rows (n, 1 +
    len(nodes)) of sim time and the nodes' values after each step.

    JSBSim cannot copy a running model, so the process forks: the child is the model as it is now. It
    holds the controls by running without the script: its clock is set past the script's end
    (``past_end`` [s]), before which FGScript::RunScript returns without processing any event (a ramp
    under way stops where it is; the aircraft's own systems, an autopilot among them, keep running), and
    no model of the shipped aircraft reads the clock. It steps, sends its samples through a pipe and
    exits; a run that fails ends early, with what it ran."""
    read_end, write_end = os.pipe()
    pid = os.fork()
    if pid == 0:  # the child: never returns
        try:
            os.close(read_end)
            now, dt = fdm.get_sim_time(), fdm.get_delta_t()
            fdm.set_sim_time(past_end)
            rows = []
            try:
                for k in range(1, int(np.ceil(seconds / dt - 1e-9)) + 1):
                    fdm.run()
                    rows.append([now + k * dt, *(node.get_double_value() for node in nodes)])
            except Exception:  # noqa: BLE001, S110 -- a diverged run ahead: what it ran is the forecast
                pass
            with os.fdopen(write_end, "wb") as sink:
                sink.write(np.asarray(rows, dtype="<f8").tobytes())
        finally:
            os._exit(0)
    os.close(write_end)
    with os.fdopen(read_end, "rb") as source:
        data = source.read()
    os.waitpid(pid, 0)
    return np.frombuffer(data, dtype="<f8").reshape(-1, 1 + len(nodes))


def _script_end(script: Path) -> float:
    """The end time [s] of a script's ``<run>``."""
    import xml.etree.ElementTree as ET

    return float(ET.parse(script).getroot().find("run").get("end"))


def default_start(flight: Flight) -> tuple[float, str]:
    """Where a flight is settled, the path's start when none is given, and why: the first sample after
    the script's first trim in the run, else the end of the start-up transient (see
    :data:`SETTLE_SECONDS`), else the first sample."""
    t = flight.t
    if flight.trimmed is not None and np.any(flight.trimmed):
        return float(t[int(np.argmax(flight.trimmed))]), "after the script's trim"
    dt = np.diff(t)
    with np.errstate(over="ignore", invalid="ignore"):  # a diverged flight: not calm (refused later)
        calm = ((np.linalg.norm(np.diff(flight.f_body, axis=0), axis=1) < SETTLE_JERK * dt)
                & (np.linalg.norm(np.diff(flight.omega_body, axis=0), axis=1) < SETTLE_ALPHA * dt))
    w = int(np.ceil(SETTLE_SECONDS / float(np.median(dt))))
    if len(calm) >= w:
        settled = np.lib.stride_tricks.sliding_window_view(calm, w).all(axis=1)
        settled &= t[: len(settled)] <= t[0] + SETTLE_WITHIN
        if np.any(settled):
            return float(t[int(np.argmax(settled))]), "settled after the start-up transient"
    return float(t[0]), "the first step"


def from_jsbsim(script: str | Path, start: float | None = None, end: float | None = None,
                rate: float | None = None, modulus: bool = False) -> tuple[DesiredPath, list[str]]:
    """The desired path of a JSBSim flight from ``start`` to ``end`` [s of sim time], resampled to
    ``rate`` [Hz] (None: :data:`DEFAULT_RATE`) with an anti-alias filter, its time 0 at ``start``; with
    ``modulus`` its ``t,M`` form. Returns the path and its ``source:`` comment lines.

    ``start`` None: where the flight is settled (:func:`default_start`: after the script's first trim in
    the run, else after the start-up transient), the filter seeing nothing before it; an explicit
    ``start`` is kept as given. ``end`` None: the script's own.

    Refused (:class:`ProfileError`): an unknown script, a crop outside the flight, a specific force above
    :data:`.convert.CRASH_G` g or not a number (a diverged simulation) anywhere in the crop (raw samples),
    a still stretch that does not read +1 g up (the convention check; it looks only at stretches whose
    |f| is within :data:`.convert.MAGNITUDE_TOLERANCE` of 1 g, a ballistic or weightless stretch being no
    rest, and JSBSim's units its own; a flight without one is not checked).
    """
    rate = _rate(rate)
    return _path_of(fly(script, None if end is None else end + FILTER_MARGIN), start, end, rate, modulus)


def _rate(rate: float | None) -> float:
    rate = DEFAULT_RATE if rate is None else float(rate)
    if not rate > 0:
        raise ProfileError(f"--rate {rate:g}: must be a positive number of samples per second")
    return rate


def forecast_from_jsbsim(script: str | Path, start: float, end: float, every: float, seconds: float,
                         rate: float | None = None):
    """The desired path of a JSBSim flight from ``start`` to ``end`` [s of sim time] (as
    :func:`from_jsbsim`), its ``source:`` lines, and the forecasts its own model makes of it
    (:class:`~desdemona.profiles.forecast.Forecast`, on the path's clock): every ``every`` seconds of the
    crop, the model run ``seconds`` ahead from its state with the pilot's controls held (the script's
    later events not run, :func:`_run_ahead`), converted as the path is."""
    from desdemona.profiles.forecast import Forecast

    rate = _rate(rate)
    times = start + every * np.arange(int(np.floor((end - start) / every + 1e-9)) + 1)
    flight = fly(script, end + FILTER_MARGIN, ahead=(times, seconds + FILTER_MARGIN))
    path, comments = _path_of(flight, start, end, rate, False)
    blocks = [_forecast_of(flight, t, rows, start, seconds, rate) for t, rows in flight.ahead if t <= end + 1e-9]
    return path, comments, Forecast.of(blocks)


def _forecast_of(flight: Flight, t_issue: float, rows: np.ndarray, start: float, seconds: float, rate: float):
    """(t0, t, S) of one run ahead on the path's clock: the last :data:`FILTER_MARGIN` s of the flight and
    the run ahead, turned into the cabin frame and resampled as :func:`from_jsbsim` does (on the path's
    grid), from the issue time to ``seconds`` after it."""
    past = (flight.t >= t_issue - FILTER_MARGIN) & (flight.t <= t_issue + 1e-9)
    t = np.r_[flight.t[past], rows[:, 0]]
    omega = convert.turn_to_cabin(np.vstack([flight.omega_body[past], rows[:, 1:4]]), convert.R_CABIN_BODY)
    f = convert.turn_to_cabin(np.vstack([flight.f_body[past], rows[:, 4:7] * G]), convert.R_CABIN_BODY)
    t, X = convert.uniform_grid(t, np.column_stack([omega, f]))
    t, X = convert.resample(t, X, rate, start + np.ceil((t[0] - start) * rate - 1e-6) / rate)
    present = [np.interp(t_issue, t, X[:, i]) for i in range(6)]
    keep = (t > t_issue + 1e-9) & (t <= t_issue + seconds + 1e-9)
    return t_issue - start, np.r_[t_issue, t[keep]] - start, np.vstack([present, X[keep]])


def _path_of(flight: Flight, start: float | None, end: float | None, rate: float,
             modulus: bool) -> tuple[DesiredPath, list[str]]:
    """The desired path of a flown flight and its ``source:`` lines (:func:`from_jsbsim`)."""
    name = flight.script.stem
    omega = convert.turn_to_cabin(flight.omega_body, convert.R_CABIN_BODY)
    f = convert.turn_to_cabin(flight.f_body, convert.R_CABIN_BODY)
    if start is not None and not start < flight.t[-1]:
        raise ProfileError(f"JSBSim script {name}: --start {start:g} s is past its end at {flight.t[-1]:.4g} s")
    lo, why = (float(start), "as given") if start is not None else default_start(flight)
    if start is None and end is not None and not end > lo:
        raise ProfileError(f"JSBSim script {name}: it is settled from {lo:.4g} s ({why}), after --end {end:g}; "
                           f"give a later --end or a --start")
    t_raw, f_raw = convert.crop(flight.t, f, lo, end, f"JSBSim script {name}")
    convert.check_no_crash(t_raw + lo, f_raw, f"JSBSim script {name}")
    use = slice(None) if start is not None else flight.t >= lo - 1e-9  # the default: no transient filtered in
    t, X = convert.resample(*convert.uniform_grid(flight.t[use], np.column_stack([omega, f])[use]), rate, lo)
    t, X = convert.crop(t, X, lo, end, f"JSBSim script {name}")
    g_ratio = np.linalg.norm(X[:, 3:], axis=1) / G
    near_1g = (g_ratio >= convert.MAGNITUDE_TOLERANCE[0]) & (g_ratio <= convert.MAGNITUDE_TOLERANCE[1])
    still = convert.find_still(t, X[:, :3], X[:, 3:], STILL_RATE, usable=near_1g)
    if still is not None:  # the accelerometer agrees with the attitude (a check of the axes turn)
        during = (flight.t >= lo + still.t0) & (flight.t <= lo + still.t1)
        phi, theta = flight.attitude[during].mean(axis=0)
        convert.check_convention(still, up=convert.up_from_attitude(phi, theta))
    span, step = f"{lo:g}-{lo + t[-1]:.6g} s", float(np.median(np.diff(flight.t)))  # the flight's own step
    description = f"JSBSim {name} ({flight.aircraft}), pilot station, {span} of sim time"
    path = convert.make_path(name, t, X[:, :3], X[:, 3:], description, modulus)
    comments = [f"source: JSBSim {flight.version} script {flight.script.name} ({'shipped with JSBSim' if _shipped(flight.script) else 'a script file'}), aircraft {flight.aircraft}",
                "source: pilot station specific force accelerations/n-pilot-{x,y,z}-norm and body rates "
                "velocities/{p,q,r}-rad_sec, body (forward,right,down) -> cabin (right,forward,up)",
                f"source: crop {span} of sim time (t = 0 here; start {why}), "
                f"{convert.filter_note(1 / step, rate)}"
                + ("; modulus |f| only" if modulus else "")]
    if end is not None and end > flight.t[-1] + step:
        comments.append(f"warning: --end {end:g} s is past the script's end at {flight.t[-1]:.4g} s of sim time: "
                        f"the path ends there")
    if flight.reset is not None:
        comments.append(f"warning: the script sets its clock back at {flight.reset:.4g} s of sim time to run "
                        f"again (a series of runs): its first run only")
    return path, comments


def _shipped(script: Path) -> bool:
    return script.resolve().parent == (Path(_jsbsim().get_default_root_dir()) / "scripts").resolve()

"""The 3D replay of a result: one self-contained HTML page (``view.html``) that opens from disk.

The page shows the machine moving as the chain of eq. A.7 moves it, world z up::

    H_world_cabin = Rz(q1) T(0, q2, 0) T(0, 0, q3) Rx(q4) Rz(q5) Ry(q6)

one nested group per joint (yaw arm, track carriage, heave, outer gimbal ring, inner gimbal ring, cabin
with the occupant's head), sized from the result's machine parameters, with the felt specific force
(S's f, cabin frame) drawn as an arrow at the head beside the desired one (S_d's f, or ``(0, 0, M_d)``
where the path gives only the modulus). Beside it, on one time cursor: S against S_d per channel (and M
against M_d), the felt-direction error and the felt rotation against their thresholds
(:mod:`desdemona.check.metrics`), and each free joint's use of its limits (1 = at a limit). An on-line result's
classical loop (``classical.csv``) moves as a second, faded machine.

three.js (the scene) and uPlot (the plots) are vendored under ``data/vendor`` with their licences and
inlined, so the page makes no request. The joint positions are kept at the precision of
trajectory.csv; above :data:`MAX_FRAMES` samples the animation is thinned (the plots never are).

The page exposes ``window.desdemonaView`` for scripts and tests: ``seek(t)``, ``pose()`` (``{t, q:
{joint: value}}``, linear between samples, so exact at a sample time), ``cabinMatrix()`` (the drawn
cabin's H_world_cabin, 16 numbers row by row), ``play()``, ``pause()``, ``setSpeed(x)``,
``setView("orbit" | "cabin")``, ``showClassical(bool)``.
"""

from __future__ import annotations

import html
import json
import math
import os
import re
import shutil
from importlib import resources
from pathlib import Path

import numpy as np

from desdemona._version import __version__
from desdemona.check import metrics
from desdemona.check.simulate import LIMITED, uses_over_time
from desdemona.machine.params import JOINT_NAMES
from desdemona.occupant import perception
from desdemona.profiles import CHANNELS
from desdemona.results import folder as result_folder
from desdemona.results.folder import ReportError
from desdemona.support import files

VIEW_FILE = "view.html"
CLASSICAL_FILE = "classical.csv"  # an on-line result's classical loop, columns as trajectory.csv
MAX_FRAMES = 12_000  # animation samples kept; beyond, every k-th (the plots keep all)
PLOT_DIGITS = 6  # significant digits of plotted values (the joint positions keep full precision)
LIMIT_KINDS = ("position", "velocity", "acceleration", "effort", "power")
_VENDOR = ("vendor/three.min.js", "vendor/uPlot.iife.min.js", "vendor/uPlot.min.css")
# The mark in the head of every page of ours: `view --out FILE --overwrite` replaces only a file carrying it.
MARK = '<meta name="generator" content="desdemona view'


class ViewError(ReportError):
    """The result folder cannot be shown; the message says which file and why (the command exits 2)."""


def _numbers(values, digits: int | None = None) -> str:
    """A JSON array of floats: shortest round-trip text (``digits`` None) or ``digits`` significant
    digits; NaN and infinities as null."""
    fmt = repr if digits is None else (lambda x: f"{x:.{digits}g}")
    return "[" + ",".join(fmt(float(x)) if math.isfinite(x) else "null" for x in np.asarray(values, float)) + "]"


class _Raw(str):
    """Text already in JSON form (a number array), spliced into the page's data as it is."""


def _json(value) -> str:
    if isinstance(value, _Raw):
        return str(value)
    if isinstance(value, dict):
        return "{" + ",".join(f"{json.dumps(str(k))}:{_json(v)}" for k, v in value.items()) + "}"
    if isinstance(value, (list, tuple)):
        return "[" + ",".join(_json(v) for v in value) + "]"
    if isinstance(value, float) and not math.isfinite(value):
        return "null"
    return json.dumps(value)


def _block(col: dict, prefix: str) -> np.ndarray | None:
    keys = [f"{c}{prefix}" for c in CHANNELS]
    return np.column_stack([col[k] for k in keys]) if all(k in col for k in keys) else None


def _vestibular(summary: dict) -> perception.VestibularModel:
    name = (summary.get("quality") or {}).get("vestibular_model")
    return perception.get_model(name) if name in perception.MODELS else perception.thesis_model()


def limit_use(col: dict, limits: dict, joints) -> dict[str, dict]:
    """Use of each limit per joint over time, (K,) arrays, 1 = at the limit (as
    :func:`desdemona.check.simulate.limit_use` measures it, per sample): ``{joint: {"worst": ..., kind: ...}}``.

    col : trajectory.csv's columns; limits : summary.json's ``parameters.joints``; joints : the free
    joints (a held joint's brake is not a motor limit)."""
    out = {}
    for j in joints:
        lim = limits[j]
        values = {key: col[f"{key}_{j}"][:, None] for key in LIMITED if f"{key}_{j}" in col}
        bounds = {kind: np.array([lim[kind]], dtype=float) for kind in LIMITED.values()
                  if kind != "position" and lim.get(kind)}
        if lim.get("position") is not None:
            bounds["position"] = tuple(np.array([b], dtype=float) for b in lim["position"])
        uses = {kind: use[:, 0] for kind, use in uses_over_time(values, bounds).items()}
        uses["worst"] = np.max(np.vstack([np.zeros(len(col["t"])), *uses.values()]), axis=0)
        out[j] = uses
    return out


def geometry(params: dict) -> dict:
    """Sizes [m] of the drawn machine from the machine parameters: the track's and heave's travel, the
    gimbal rings' radii from their bodies' inertia (a thin ring, I = m r^2 / 2 about a diameter) and the
    cabin's box from its inertia (a solid box), nested so that each fits inside the next."""
    joints, bodies = params["joints"], params.get("bodies") or {}

    def travel(name, default):
        pos = joints.get(name, {}).get("position")
        return [float(pos[0]), float(pos[1])] if pos is not None else list(default)

    def ring(body, axis, default):
        b = bodies.get(body)
        if not b or b.get("mass_kg", 0) <= 0:
            return default
        return min(3.0, max(0.6, math.sqrt(2.0 * b["inertia_kg_m2"][axis][axis] / b["mass_kg"])))

    cabin = [1.6, 1.9, 1.6]
    b = bodies.get("cabin")
    if b and b.get("mass_kg", 0) > 0:
        d = [b["inertia_kg_m2"][i][i] for i in range(3)]
        sides = [6.0 * (d[(i + 1) % 3] + d[(i + 2) % 3] - d[i]) / b["mass_kg"] for i in range(3)]
        if all(s > 0 for s in sides):
            cabin = [min(3.0, max(0.8, math.sqrt(s))) for s in sides]
    inner = max(ring("inner_gimbal", 1, 1.3), 0.5 * math.hypot(cabin[1], cabin[2]) + 0.12,
                0.5 * math.hypot(cabin[0], cabin[2]) + 0.12)
    outer = max(ring("outer_gimbal", 0, 1.5), inner + 0.18)
    return {"track": travel("track", (-4.0, 4.0)), "heave": travel("heave", (-1.0, 1.0)),
            "cabin": cabin, "inner_ring": inner, "outer_ring": outer,
            "head_offset": list(params.get("head_offset_m") or (0.0, 0.0, 0.0)),
            "gravity": float(params.get("gravity_m_s2") or 9.81)}


def _motion(col: dict, every: int, desired: bool = True) -> dict:
    """What the animation needs of one trajectory: t, q per joint (full precision), f and (``desired``)
    f_d [m/s^2]."""
    n = len(col["t"])
    pick = np.unique(np.r_[np.arange(0, n, every), n - 1])  # every k-th sample and the last
    out = {"t": _Raw(_numbers(col["t"][pick])),
           "q": {j: _Raw(_numbers(col[f"q_{j}"][pick])) for j in JOINT_NAMES}}
    S, S_d = _block(col, ""), _block(col, "_d")
    if S is not None:
        out["f"] = [_Raw(_numbers(S[pick, 3 + i], PLOT_DIGITS)) for i in range(3)]
    if not desired:
        pass
    elif S_d is not None:
        out["f_d"] = [_Raw(_numbers(S_d[pick, 3 + i], PLOT_DIGITS)) for i in range(3)]
    elif "M_d" in col:
        zero = np.zeros_like(col["M_d"][pick])
        out["f_d"] = [_Raw(_numbers(zero)), _Raw(_numbers(zero)), _Raw(_numbers(col["M_d"][pick], PLOT_DIGITS))]
    return out


def _plots(col: dict, summary: dict, joints, baseline: bool = False) -> dict:
    """What the plots need of one trajectory, every sample; of a ``baseline`` (drawn faded beside the
    result) only S, M and the felt direction."""
    t, S, S_d = col["t"], _block(col, ""), _block(col, "_d")
    vestibular = _vestibular(summary)
    out = {"t": _Raw(_numbers(t, 9))}
    if S is not None:
        out["S"] = [_Raw(_numbers(S[:, i], PLOT_DIGITS)) for i in range(6)]
        f_d = None if S_d is None else S_d[:, 3:]
        out["direction_deg"] = _Raw(_numbers(np.degrees(metrics.direction_error(S[:, 3:], f_d)), PLOT_DIGITS))
        if len(t) > 1 and not baseline:
            rotation = np.degrees(metrics.felt_rotation(S, S_d, metrics.step_of(t), vestibular))
            out["rotation_deg_s"] = [_Raw(_numbers(np.abs(rotation[:, i]), PLOT_DIGITS)) for i in range(3)]
    if S_d is not None and not baseline:
        out["S_d"] = [_Raw(_numbers(S_d[:, i], PLOT_DIGITS)) for i in range(6)]
    for key in ("M",) if baseline else ("M", "M_d"):
        if key in col:
            out[key] = _Raw(_numbers(col[key], PLOT_DIGITS))
    if not baseline:
        # per joint the worst use and which limit it is (an index into LIMIT_KINDS)
        use = limit_use(col, summary["parameters"]["joints"], joints)
        kinds = {j: np.argmax(np.vstack([u.get(k, np.zeros_like(t)) for k in LIMIT_KINDS]), axis=0) for j, u in use.items()}
        out["use"] = {"kinds": list(LIMIT_KINDS), "worst": {j: _Raw(_numbers(u["worst"], 3)) for j, u in use.items()},
                      "kind": {j: _Raw("[" + ",".join(map(str, k)) + "]") for j, k in kinds.items()}}
    return out


def scene_data(col: dict, summary: dict, classical: dict | None = None) -> dict:
    """The page's data: the machine's sizes, the motion to animate and the series to plot.

    col, classical : columns of trajectory.csv and of the classical loop's (:func:`desdemona.results.folder.read_table`);
    summary : the result's summary.json."""
    missing = [n for n in ["t", *(f"q_{j}" for j in JOINT_NAMES)] if n not in col]
    if missing:
        raise ViewError(f"trajectory.csv has no column {missing[0]!r}")
    joints = list(summary["configuration"]["free_joints"])
    vestibular = _vestibular(summary)
    every = max(1, math.ceil(len(col["t"]) / MAX_FRAMES))
    path, config = summary.get("path") or {}, summary.get("configuration") or {}
    data = {
        "title": f"{path.get('name', 'result')} on {config.get('name', '?')}",
        "method": summary.get("method") or "",
        "joints": list(JOINT_NAMES), "free": joints,
        "kinds": {j: summary["parameters"]["joints"][j]["kind"] for j in JOINT_NAMES},
        "geometry": geometry(summary["parameters"]),
        "thresholds": {"direction_deg": math.degrees(metrics.direction_threshold(vestibular.thresholds)),
                       "rotation_deg_s": [math.degrees(x) for x in vestibular.thresholds[:3]],
                       "vestibular": vestibular.name},
        "motion": _motion(col, every),
        "plots": _plots(col, summary, joints),
    }
    if classical is not None:
        every = max(1, math.ceil(len(classical["t"]) / MAX_FRAMES))
        data["classical"] = {"motion": _motion(classical, every, desired=False),
                             "plots": _plots(classical, summary, joints, baseline=True)}
    return data


def _asset(name: str) -> str:
    return resources.files("desdemona").joinpath("data", name).read_text(encoding="utf-8")


def _script(text: str) -> str:
    """Code safe inside a <script> element: no closing tag (only ever in a string, regular expression or
    comment of the inlined code, where the escaped form means the same)."""
    return re.sub(r"</(script)", r"<\\/\1", text, flags=re.IGNORECASE)


def fill(template: str, script: str, title: str, data: dict) -> str:
    """The page of ``template`` (its style and markup, under ``data/``) in the shell ``page.html``, with
    the vendored three.js and uPlot, the machine's drawing (``scene.js``), the page's own ``script``
    and its ``data`` (JSON) inlined: a page that makes no request but its own. Also the live
    console's (:mod:`desdemona.service.console`)."""
    three, uplot, uplot_css = (_asset(name) for name in _VENDOR)
    parts = {"GENERATOR": html.escape(f"desdemona view {__version__}"),  # first: it is the first in the head
             "TITLE": html.escape(title), "STYLE": uplot_css, "UPLOT": _script(uplot), "THREE": _script(three),
             "SCENE": _script(_asset("scene.js")), "DATA": _json(data).replace("<", "\\u003c"),
             "VIEW": _script(_asset(script))}
    css, body = _asset(template).split("<!-- markup -->\n", 1)
    text = _asset("page.html").replace("@@CSS@@", css, 1).replace("@@BODY@@", body, 1)
    for key, value in parts.items():
        text = text.replace(f"@@{key}@@", value, 1)
    return text


def page(col: dict, summary: dict, classical: dict | None = None) -> str:
    """The self-contained HTML page of a result (see the module's notes)."""
    data = scene_data(col, summary, classical)
    return fill("view.html", "view.js", f"desdemona: {data['title']}", data)


def page_of_folder(folder: str | Path) -> str:
    """:func:`page` of a result folder (its trajectory.csv, summary.json and, where present,
    classical.csv)."""
    folder = Path(folder)
    result_folder.refuse_batch_folder(folder, "view")
    try:
        summary = result_folder.read_summary(folder)
        col = result_folder.read_table(folder / "trajectory.csv")
        classical = result_folder.read_table(folder / CLASSICAL_FILE) if (folder / CLASSICAL_FILE).exists() else None
    except ReportError as exc:
        raise ViewError(str(exc)) from None
    return page(col, summary, classical)


def is_page(path: str | Path) -> bool:
    """Whether the file ``path`` is a page written by :func:`write` (its head carries :data:`MARK`)."""
    try:
        with open(path, encoding="utf-8", errors="replace") as fh:
            return MARK in fh.read(4096)
    except OSError:
        return False


def check_out(folder: str | Path, out: str | Path | None, overwrite: bool = False) -> tuple[Path, str]:
    """Where :func:`write` may put the page of ``folder`` and how: ``"own"`` (the folder's own
    view.html, ``out`` None or naming it, always the tool's to replace), ``"new"`` (an .html file outside
    every result folder, absent) or ``"ours"`` (with ``overwrite``, such a file that is an earlier page
    of ours, :func:`is_page`). Anything else is a :class:`ViewError`, raised before any work."""
    own = Path(folder) / VIEW_FILE
    if out is None or Path(out).resolve() == own.resolve():
        return own, "own"
    out = Path(out)
    parent = out.resolve().parent
    if out.suffix.lower() != ".html":
        raise ViewError(f"{out}: --out must name an .html file (the page), e.g. {out.with_suffix('.html').name}")
    in_result = all((parent / name).exists() for name in ("summary.json", "trajectory.csv"))
    if in_result or result_folder.is_result_folder(parent):
        raise ViewError(f"{out}: is inside the result folder {parent}, where view writes only its own "
                        f"{VIEW_FILE} ('desdemona view {parent}'); choose a file elsewhere")
    if out.exists() or out.is_symlink():
        if not overwrite:
            raise ViewError(f"{out}: already exists; choose another file or add --overwrite")
        if out.is_symlink() or not out.is_file() or not is_page(out):
            raise ViewError(f"{out}: --overwrite replaces only a page written by desdemona view, and this is not "
                            f"one; left as it is: choose another file")
        return out, "ours"
    if not parent.is_dir():
        raise ViewError(f"{out}: the folder {parent} does not exist")
    return out, "new"


def _put(out: Path, text: str, kind: str) -> None:
    """Write ``text`` to a temporary file beside ``out`` and rename it into place (never half-written):
    over the folder's own page (``kind`` "own"), over an earlier page of ours only while it still is
    one ("ours"), else only while ``out`` is still absent ("new")."""
    try:
        with files.beside(out) as tmp:
            tmp.write_text(text, encoding="utf-8")
            _move(tmp, out, kind)
    except OSError as exc:
        raise ViewError(f"{out}: cannot write: {exc.strerror or exc}") from None


def _move(tmp: Path, out: Path, kind: str) -> None:
    """Rename the written page onto ``out`` as :func:`_put`'s ``kind`` allows."""
    if kind == "own" or (kind == "ours" and is_page(out)):
        os.replace(tmp, out)
    elif kind == "new" and not (out.exists() or out.is_symlink()):
        try:
            os.link(tmp, out)  # fails if out appeared meanwhile: never replaced
        except FileExistsError:
            raise ViewError(f"{out}: appeared while the page was written; left as it is") from None
        except OSError:  # no hard links on this file system
            os.replace(tmp, out)
    else:
        raise ViewError(f"{out}: changed while the page was written; left as it is: choose another file")


def write(folder: str | Path, out: str | Path | None = None, overwrite: bool = False) -> Path:
    """Write the view of the result folder ``folder`` to ``out`` (default ``folder/view.html``, the
    folder's own page, always replaced); any other ``out`` as :func:`check_out` allows it."""
    result_folder.refuse_batch_folder(folder, "view")
    out, kind = check_out(folder, out, overwrite)
    _put(out, page_of_folder(folder), kind)
    return out


class NoBrowser(RuntimeError):
    """selenium, chromium or chromedriver is not installed."""


def headless_browser(width: int = 1600, height: int = 900, network: bool = False):
    """A headless Debian chromium driven by selenium through the installed chromedriver (Selenium
    Manager never downloads one); WebGL by SwiftShader; the browser's console kept for ``get_log``
    (and, with ``network``, its network requests: ``get_log("performance")``).
    For the tests and the documentation's screenshots: selenium is a test extra, not a dependency.
    Raises :class:`NoBrowser` where any is missing."""
    try:
        from selenium import webdriver
        from selenium.webdriver.chrome.service import Service
    except ImportError:
        raise NoBrowser("selenium is not installed (pip install '.[test]')") from None
    binary = shutil.which("chromium") or shutil.which("chromium-browser")
    driver = shutil.which("chromedriver")
    if binary is None or driver is None:
        raise NoBrowser("no headless browser: install Debian's chromium and chromium-driver "
                        "(apt-get install chromium chromium-driver) to test the view in a browser")
    options = webdriver.ChromeOptions()
    options.binary_location = binary
    for arg in ("--headless=new", "--no-sandbox", "--disable-dev-shm-usage", "--use-gl=angle",
                "--use-angle=swiftshader", "--enable-unsafe-swiftshader", f"--window-size={width},{height}",
                "--hide-scrollbars", "--disable-extensions", "--no-first-run"):
        options.add_argument(arg)
    options.set_capability("goog:loggingPrefs", {"browser": "ALL", **({"performance": "ALL"} if network else {})})
    return webdriver.Chrome(service=Service(executable_path=driver), options=options)

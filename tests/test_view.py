"""The 3D replay page (desdemona.results.view): self-contained, full-precision joint data, and, in a real
headless browser (Debian's chromium and chromedriver with selenium; skipped where they are missing), a
page that loads without a console error, shows the pose of trajectory.csv at the cursor, draws the
chain of eq. A.7 (the drawn cabin's pose equals kinematics.cabin_pose) and is not blank."""

from __future__ import annotations

import io
import json
import re
from pathlib import Path

import numpy as np
import pytest

from desdemona.machine import kinematics
from desdemona.machine.params import JOINT_NAMES, default_params
from desdemona.results import report, view

CHANNELS = ("wx", "wy", "wz", "fx", "fy", "fz")


def _motion(t, seed):
    """Smooth joint motion (K, 6) of seeded random sinusoids, with its exact rates and accelerations."""
    rng = np.random.default_rng(seed)
    amp = rng.uniform(0.2, 1.0, 6) * np.array([2.0, 3.0, 0.8, 1.2, 1.2, 1.2])
    w = rng.uniform(0.3, 1.5, 6)
    phase = rng.uniform(0, 2 * np.pi, 6)
    arg = np.outer(t, w) + phase
    return amp * np.sin(arg), amp * w * np.cos(arg), -amp * w**2 * np.sin(arg)


def _table(t, seed, params):
    q, qd, qdd = _motion(t, seed)
    S = np.asarray(kinematics.S(q, qd, qdd, params.gravity), float).reshape(len(t), 6)
    S_d = S + 0.3 * np.sin(t)[:, None]
    limits = params.to_dict()["joints"]
    tau = 0.3 * np.array([limits[j]["effort"] for j in JOINT_NAMES]) * np.sin(t)[:, None]
    cols = {"t": t}
    for label, values in (("q", q), ("qd", qd), ("qdd", qdd), ("tau", tau), ("power", tau * qd)):
        cols.update({f"{label}_{j}": values[:, i] for i, j in enumerate(JOINT_NAMES)})
    cols.update({c: S[:, i] for i, c in enumerate(CHANNELS)})
    cols.update({f"{c}_d": S_d[:, i] for i, c in enumerate(CHANNELS)})
    cols["M"], cols["M_d"] = np.linalg.norm(S[:, 3:], axis=1), np.linalg.norm(S_d[:, 3:], axis=1)
    return cols


def _write_csv(path: Path, cols: dict) -> None:
    with open(path, "w") as fh:
        fh.write("# units: SI\n" + ",".join(cols) + "\n")
        np.savetxt(fh, np.column_stack(list(cols.values())), delimiter=",", fmt="%.10g")


def make_result(folder: Path, duration: float = 4.0, rate: float = 50.0, classical: bool = True) -> Path:
    """A result folder of the whole machine moving (every joint free), as `online` writes one."""
    params = default_params()
    folder.mkdir(parents=True)
    t = np.arange(round(duration * rate) + 1) / rate
    _write_csv(folder / "trajectory.csv", _table(t, 7, params))
    if classical:
        _write_csv(folder / view.CLASSICAL_FILE, _table(t, 8, params))
    summary = {"format": "desdemona result", "path": {"name": "wobble"},
               "configuration": {"name": "full", "free_joints": list(JOINT_NAMES)},
               "quality": {"vestibular_model": "thesis"}, "parameters": params.to_dict()}
    (folder / "summary.json").write_text(json.dumps(summary))
    return folder


def add_session(folder: Path, delay: float = 0.03, rate: float = 50.0) -> Path:
    """A served session's session.csv beside the result: each cycle's command (trajectory.csv's joints)
    and the newest State's measured joints, measured ``delay`` late and a little off, as serve logs them."""
    cols = report.read_table(folder / "trajectory.csv")
    t = cols["t"][:: max(1, round(len(cols["t"]) / (cols["t"][-1] * rate)))]
    names = ["t", "status", "command", "message_age_s", "latency_s", "compute_time_s", "reason", "machine",
             "tracking_use"]
    names += [f"commanded_{j}_{q}" for q in ("position", "rate", "acceleration") for j in JOINT_NAMES]
    names += [f"measured_{j}_{q}" for q in ("position", "rate") for j in JOINT_NAMES] + ["measured_at"]
    lines = [",".join(names)]
    for k, tk in enumerate(t):
        at = max(0.0, tk - delay)
        command = [np.interp(tk, cols["t"], cols[f"{q}_{j}"]) for q in ("q", "qd", "qdd") for j in JOINT_NAMES]
        measured = [np.interp(at, cols["t"], cols[f"{q}_{j}"]) + 2e-3 + 1e-3 * np.sin(7 * at)
                    for q in ("q", "qd") for j in JOINT_NAMES]
        cells = [f"{tk:.6g}", "running", "plan", "0.001", "0.002", "0.003", '""', "following", f"{0.2 + 0.1 * np.sin(tk):.6g}"]
        lines.append(",".join(cells + [f"{v:.10g}" for v in command + measured] + [f"{at:.6g}"]))
    (folder / view.SESSION_FILE).write_text("\n".join(lines) + "\n")
    return folder


@pytest.fixture(scope="module")
def result(tmp_path_factory):
    return add_session(make_result(tmp_path_factory.mktemp("view") / "run"))


def _data(text: str) -> dict:
    found = re.search(r'<script type="application/json" id="desdemona-data">(.*?)</script>', text, re.S)
    return json.loads(found.group(1))


def test_page_is_self_contained_and_small(tmp_path):
    """Everything inlined: no script, style, font or image from anywhere; a 60 s result at 50 Hz with
    its classical loop stays well under 5 MB."""
    folder = make_result(tmp_path / "long", duration=60.0, rate=50.0)
    text = view.write(folder).read_text()
    assert re.search(r"<script[^>]*\bsrc\s*=", text, re.I) is None
    assert re.search(r"<link[^>]*rel=[\"']?stylesheet", text, re.I) is None
    assert re.search(r"(src|href)\s*=\s*[\"']?\s*(https?:)?//", text, re.I) is None
    assert re.search(r"url\(\s*[\"']?\s*(https?:)?//|@import|@font-face", text, re.I) is None
    assert len(text.encode()) < 5e6, len(text.encode())
    assert len(_data(text)["plots"]["t"]) == 3001  # the plots keep every sample


def test_joint_data_keep_the_precision_of_the_trajectory(result):
    data = _data(view.page_of_folder(result))
    cols = report.read_table(result / "trajectory.csv")
    assert data["motion"]["t"] == cols["t"].tolist()
    for j in JOINT_NAMES:
        assert data["motion"]["q"][j] == cols[f"q_{j}"].tolist()
    assert data["classical"]["motion"]["q"]["yaw"] == report.read_table(result / view.CLASSICAL_FILE)["q_yaw"].tolist()


def test_a_long_result_thins_the_animation_not_the_plots(result, monkeypatch):
    monkeypatch.setattr(view, "MAX_FRAMES", 50)
    data = _data(view.page_of_folder(result))
    cols = report.read_table(result / "trajectory.csv")
    t = data["motion"]["t"]
    assert len(t) <= 51 and t[0] == cols["t"][0] and t[-1] == cols["t"][-1]
    k = cols["t"].tolist().index(t[1])
    assert data["motion"]["q"]["cabin"][1] == cols["q_cabin"][k]
    assert len(data["plots"]["t"]) == len(cols["t"])


def test_limit_use_is_one_at_each_limit():
    limits = default_params().to_dict()["joints"]
    track = limits["track"]
    col = {"t": np.arange(3.0), "q_track": np.array([track["position"][1], 0.0, track["position"][0]]),
           "qd_track": np.array([0.0, track["velocity"], 0.0]), "qdd_track": np.zeros(3),
           "tau_track": np.array([0.0, 0.0, -track["effort"] / 2]), "power_track": np.zeros(3)}
    use = view.limit_use(col, limits, ["track"])["track"]
    assert np.allclose(use["position"], [1.0, 0.0, 1.0])
    assert np.allclose(use["worst"], [1.0, 1.0, 1.0])
    assert np.allclose(use["effort"], [0.0, 0.0, 0.5])


def test_a_folder_that_is_no_result_is_refused(tmp_path):
    with pytest.raises(view.ViewError, match="summary.json"):
        view.page_of_folder(tmp_path)


# ---- in a real browser ----

@pytest.fixture(scope="module")
def browser():
    try:
        driver = view.headless_browser()
    except view.NoBrowser as exc:
        pytest.skip(str(exc))
    yield driver
    driver.quit()


@pytest.fixture(scope="module")
def loaded(browser, result):
    from selenium.webdriver.support.ui import WebDriverWait

    page = view.write(result)
    browser.get(page.resolve().as_uri())
    # the page's module script runs after the load event; on a busy machine that takes seconds
    WebDriverWait(browser, 60).until(lambda d: d.execute_script(
        "return !!(window.desdemonaView && window.desdemonaView.ready)"))
    return browser


def test_page_loads_without_console_error(loaded):
    hook = loaded.execute_script("return window.desdemonaView && {ready: window.desdemonaView.ready, "
                                 "webgl: window.desdemonaView.webgl}")
    errors = [e for e in loaded.get_log("browser") if e["level"] == "SEVERE"]
    assert errors == []
    assert hook == {"ready": True, "webgl": True}


def test_pose_at_the_cursor_is_the_trajectory(loaded, result):
    cols = report.read_table(result / "trajectory.csv")
    classical = report.read_table(result / view.CLASSICAL_FILE)
    for k in (0, 77, len(cols["t"]) - 1):
        t = float(cols["t"][k])
        pose = loaded.execute_script("return window.desdemonaView.seek(arguments[0])", t)
        assert pose["t"] == pytest.approx(t, abs=1e-12)
        q = np.array([cols[f"q_{j}"][k] for j in JOINT_NAMES])
        assert np.allclose([pose["q"][j] for j in JOINT_NAMES], q, rtol=0, atol=1e-6)
        # the drawn chain is eq. A.7: the cabin's world pose is kinematics' H_world_cabin
        drawn = np.array(loaded.execute_script("return window.desdemonaView.cabinMatrix()")).reshape(4, 4)
        assert np.allclose(drawn, kinematics.cabin_pose(q), atol=1e-9)
        # the arrows at the head: the felt and desired specific force, turned from the cabin to the world
        arrows = loaded.execute_script("return window.desdemonaView.arrows()")
        R = kinematics.cabin_pose(q)[:3, :3]
        for name, suffix in (("felt", ""), ("desired", "_d")):
            f = R @ np.array([cols[f"{c}{suffix}"][k] for c in ("fx", "fy", "fz")])
            assert np.allclose(arrows[name], f / np.linalg.norm(f), atol=1e-5)
        # the classical loop's faded machine follows its own trajectory
        ghost = loaded.execute_script("return window.desdemonaView.pose('classical')")
        assert np.allclose([ghost["q"][j] for j in JOINT_NAMES], [classical[f"q_{j}"][k] for j in JOINT_NAMES],
                           rtol=0, atol=1e-6)
        drawn = np.array(loaded.execute_script("return window.desdemonaView.cabinMatrix('classical')")).reshape(4, 4)
        assert np.allclose(drawn, kinematics.cabin_pose([classical[f"q_{j}"][k] for j in JOINT_NAMES]), atol=1e-9)
    # between samples, linear
    t = 0.5 * (cols["t"][10] + cols["t"][11])
    pose = loaded.execute_script("return window.desdemonaView.seek(arguments[0])", t)
    assert pose["q"]["yaw"] == pytest.approx(0.5 * (cols["q_yaw"][10] + cols["q_yaw"][11]), abs=1e-9)


def test_the_measured_machine_is_drawn_beside_the_commanded_one(loaded, result):
    """A served session's measured machine: at the cursor, its drawn pose is the joints the log says
    were measured there (and the chain of eq. A.7 from them); it can be hidden; the plots show the
    tracking error."""
    with open(result / view.SESSION_FILE) as fh:
        header = fh.readline().strip().split(",")
        rows = [line.strip().split(",") for line in fh]
    assert loaded.execute_script("return window.desdemonaView.hasMeasured")
    for k in (2, 40, len(rows) - 1):
        row = dict(zip(header, rows[k]))
        at = float(row["measured_at"])
        loaded.execute_script("window.desdemonaView.seek(arguments[0])", at)
        measured = loaded.execute_script("return window.desdemonaView.pose('measured')")
        q = np.array([float(row[f"measured_{j}_position"]) for j in JOINT_NAMES])
        assert measured["t"] == pytest.approx(at, abs=1e-12)
        assert np.allclose([measured["q"][j] for j in JOINT_NAMES], q, rtol=0, atol=1e-6)
        drawn = np.array(loaded.execute_script("return window.desdemonaView.cabinMatrix('measured')")).reshape(4, 4)
        assert np.allclose(drawn, kinematics.cabin_pose(q), atol=1e-9)
        commanded = loaded.execute_script("return window.desdemonaView.pose()")
        assert not np.allclose([commanded["q"][j] for j in JOINT_NAMES], q, atol=1e-4)  # two machines, apart
    assert loaded.execute_script("return window.desdemonaView.showMeasured(false)") is False
    assert loaded.execute_script("return window.desdemonaView.showMeasured(true)") is True
    titles = loaded.execute_script("return [...document.querySelectorAll('.u-title')].map((e) => e.textContent)")
    assert "tracking error: the measured machine less the command" in titles
    assert [e for e in loaded.get_log("browser") if e["level"] == "SEVERE"] == []


def test_play_and_views(loaded):
    loaded.execute_script("const v = window.desdemonaView; v.seek(v.start); v.setSpeed(4); v.play();")
    from selenium.webdriver.support.ui import WebDriverWait

    WebDriverWait(loaded, 10).until(lambda d: d.execute_script("return window.desdemonaView.pose().t") > 0.2)
    t = loaded.execute_script("window.desdemonaView.pause(); return window.desdemonaView.pose().t")
    assert t == loaded.execute_script("return window.desdemonaView.pose().t")  # paused
    assert loaded.execute_script("return window.desdemonaView.setSpeed(10)") == 4  # 0.1x to 4x
    for v in ("cabin", "follow", "orbit"):
        loaded.execute_script("window.desdemonaView.setView(arguments[0])", v)
    assert [e for e in loaded.get_log("browser") if e["level"] == "SEVERE"] == []


def test_screenshot_is_not_blank(loaded):
    import matplotlib.image

    loaded.execute_script("window.desdemonaView.seek(1.0)")
    pixels = matplotlib.image.imread(io.BytesIO(loaded.get_screenshot_as_png()), format="png")[..., :3]
    stage = pixels[60:-60, 40:pixels.shape[1] // 2]  # the 3D view, left of the plots
    assert pixels.std() > 0.05
    assert stage.std() > 0.02
    assert len(np.unique((stage * 255).astype(np.uint8).reshape(-1, 3), axis=0)) > 50


def test_online_folder_keeps_the_classical_loop_and_its_view(tmp_path, capsys):
    """`online` writes classical.csv (the baseline the summary judges) and view.html with both machines;
    `view --out` writes the page elsewhere."""
    from desdemona.cli import main

    out = tmp_path / "live"
    assert main(["online", "dfs-catapult", "--config", "dfs-yaw", "--horizon", "1", "--step", "0.1", "--replan",
                 "0.4", "--delay", "--out", str(out)]) in (0, 4)
    summary = json.loads((out / "summary.json").read_text())
    classical = report.read_table(out / view.CLASSICAL_FILE)
    own = report.read_table(out / "trajectory.csv")
    assert np.array_equal(classical["t"], own["t"])
    rms = np.sqrt(np.mean((classical["M"] - classical["M_d"]) ** 2))
    assert rms == pytest.approx(summary["metrics"]["rms_modulus_classical_loop"], rel=0.02)
    data = _data((out / view.VIEW_FILE).read_text())
    assert data["classical"]["motion"]["q"]["yaw"] == classical["q_yaw"].tolist()
    assert main(["view", str(out), "--out", str(tmp_path / "page.html")]) == 0
    assert (tmp_path / "page.html").read_text() == (out / view.VIEW_FILE).read_text()
    assert main(["view", str(tmp_path / "nothing")]) == 2


# ---- `view --out` never replaces what it did not write; a batch folder is named as one ----

def _files(folder: Path) -> dict[str, bytes]:
    return {p.name: p.read_bytes() for p in folder.iterdir()}


def test_view_out_never_replaces_a_file_it_did_not_write(tmp_path, capsys):
    """A user's page, the result's own files (with or without --overwrite), a non-.html file and a page
    inside a result folder are refused in one line naming the file, and left as they were."""
    from desdemona.cli import main

    folder = make_result(tmp_path / "run", classical=False)
    view.write(folder)
    mine = tmp_path / "mine.html"
    mine.write_text("<html>my notes</html>")
    before = _files(folder)
    for out in (mine, folder / "trajectory.csv", folder / "summary.json", tmp_path / "page.txt",
                tmp_path / "page", folder / "other.html"):
        for extra in ([], ["--overwrite"]):
            assert main(["view", str(folder), "--out", str(out), *extra]) == 2, (out, extra)
            err = capsys.readouterr().err
            assert err.count("\n") == 1 and str(out) in err, err
    assert mine.read_text() == "<html>my notes</html>"
    assert _files(folder) == before
    assert sorted(p.name for p in tmp_path.iterdir()) == ["mine.html", "run"]  # no page.txt, no temporary


def test_view_overwrite_replaces_an_earlier_page_of_ours(tmp_path, capsys):
    from desdemona.cli import main

    folder = make_result(tmp_path / "run", classical=False)
    page = tmp_path / "page.html"
    assert main(["view", str(folder), "--out", str(page)]) == 0
    assert view.MARK in page.read_text()[:1000] and view.is_page(page)
    assert main(["view", str(folder), "--out", str(page)]) == 2
    err = capsys.readouterr().err
    assert "already exists" in err and "--overwrite" in err
    page.write_text(page.read_text() + "<!-- old -->")
    assert main(["view", str(folder), "--out", str(page), "--overwrite"]) == 0
    assert "<!-- old -->" not in page.read_text() and view.is_page(page)
    # the result's own page: always the tool's to redraw, by default or named
    (folder / view.VIEW_FILE).write_text("stale")
    assert main(["view", str(folder)]) == 0 and view.is_page(folder / view.VIEW_FILE)
    assert main(["view", str(folder), "--out", str(folder / view.VIEW_FILE)]) == 0
    # a page without the mark (not ours, or written before the mark) is not replaced
    page.write_text(page.read_text().replace(view.MARK, "<meta name=\"generator\" content=\"someone"))
    text = page.read_text()
    assert main(["view", str(folder), "--out", str(page), "--overwrite"]) == 2
    assert "only a page written by desdemona view" in capsys.readouterr().err
    assert page.read_text() == text
    assert sorted(p.name for p in tmp_path.iterdir()) == ["page.html", "run"]


def test_page_is_never_half_written(tmp_path, monkeypatch):
    """The page goes to a temporary file beside it; a failure while writing leaves nothing behind and the
    earlier page as it was."""
    folder = make_result(tmp_path / "run", classical=False)
    page = view.write(folder, tmp_path / "page.html")
    text = page.read_text()

    def broken(*args, **kwargs):
        raise OSError(28, "No space left on device")

    monkeypatch.setattr(view.os, "replace", broken)
    with pytest.raises(view.ViewError, match="No space left"):
        view.write(folder, page, overwrite=True)
    assert page.read_text() == text
    assert sorted(p.name for p in tmp_path.iterdir()) == ["page.html", "run"]


def test_view_and_plot_on_a_batch_folder_name_its_job_folders(tmp_path, capsys):
    from desdemona.cli import main

    batch = tmp_path / "runs"
    job = make_result(batch / "cosine--full", classical=False)
    (batch / "batch.csv").write_text("path,configuration,status,folder\ncosine,full,ok,cosine--full\n")
    for argv in (["view", str(batch)], ["plot", str(batch)], ["view", str(batch), "--out", str(tmp_path / "p.html")]):
        assert main(argv) == 2
        err = capsys.readouterr().err
        assert err.count("\n") == 1 and "is a batch folder" in err and str(job) in err, err
        assert "Errno" not in err
    assert not (tmp_path / "p.html").exists()

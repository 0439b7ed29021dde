"""A served session's result folder written as it goes (:class:`desdemona.service.sessionlog.LiveLog`
with :class:`desdemona.service.livetrajectory.LiveTrajectory`): left by a killed service, it is read by
``plot``, ``view`` and ``compare`` up to its last written cycle, and says so in one line."""

import json
import os

import numpy as np
import pytest

from desdemona.machine.model import Model
from desdemona.results import compare, folder, report, view
from desdemona.service.livetrajectory import LiveTrajectory, desired_of
from desdemona.service.sessionlog import TIMED, LiveLog

STEP = 0.02


class _Host:
    name, description, duration, weights = "host", "motion received by serve", None, [1.0] * 6


def _killed_session(tmp_path, config: str, channels: int, cycles: int = 23):
    """A log of ``cycles`` cycles of a machine spinning up, never closed (as SIGKILL leaves it), with
    a row half-written at the end of trajectory.csv."""
    model = Model(config=config)
    out = tmp_path / "session"
    log = LiveLog(out, model.config.joint_names, report.RESULT_FORMAT, trajectory=LiveTrajectory(model, channels, 5),
                  description={**report.run_description(_Host(), model.config), "parameters": model.params.to_dict()})
    rows = []
    for k in range(cycles):
        t = k * STEP
        q, qd, qdd = np.full(model.n, 0.05 * t**2), np.full(model.n, 0.1 * t), np.full(model.n, 0.1)
        desired = np.r_[0.0, 0.0, 0.0, 0.5, 0.0, 9.81 + t] if channels == 6 else np.r_[9.81 + t]
        log.cycle({"t": t, "status": "running", "command": "plan", "message_age_s": 0.001, "latency_s": 0.002,
                   "compute_time_s": 0.003, "reason": "", "machine": "following", "tracking_use": 0.1,
                   **dict.fromkeys(TIMED, 0.0005)},
                  (q, qd, qdd), (q, qd, t - 0.05), [(0.5, "command pause", "")], desired)
        rows.append((t, q, qd, qdd, desired))
    with open(out / "trajectory.csv", "a") as fh:
        fh.write("0.46,0.1,0.")  # killed in the middle of a write
    return model, out, rows


@pytest.mark.parametrize("config,channels", [("dfs", 1), ("full", 6)])
def test_a_killed_sessions_folder_is_read_to_its_last_written_cycle(tmp_path, config, channels):
    model, out, rows = _killed_session(tmp_path, config, channels)
    written = 20  # whole batches of 5: the last 3 cycles were held when it was killed
    traj, summary = report.load(out)
    assert summary["live"] and len(traj.t) == written
    assert traj.t[-1] == pytest.approx(rows[written - 1][0])
    # what the rows say is the physics of the commanded motion against what the host asked
    _, q, qd, qdd, desired = rows[written - 1]
    assert traj.S[-1] == pytest.approx(model.S(q, qd, qdd), rel=1e-8, abs=1e-9)
    assert traj.tau[-1] == pytest.approx(model.tau(q, qd, qdd), rel=1e-8, abs=1e-9)
    S_d, M_d = desired_of(desired, model.config.aligned)
    assert traj.M_d[-1] == pytest.approx(M_d) and traj.M[-1] == pytest.approx(np.linalg.norm(traj.S[-1, 3:]))
    if S_d is not None:
        assert traj.S_d[-1] == pytest.approx(S_d)
    assert folder.live_note(out) == (f"{out}: session ended without closing at t = {traj.t[-1]:.3f} s; "
                                     "read up to its last cycle")
    assert "desdemona view" in view.page_of_folder(out)
    (entry,) = compare.load_results([out])
    assert entry.metrics.duration_s == pytest.approx(traj.t[-1]) and np.isfinite(entry.metrics.modulus_rms)
    # the session's own rows (every cycle, flushed each) and events are there too
    lines = (out / "session.csv").read_text().splitlines()
    assert len(lines) == 1 + len(rows) and "measured_yaw_position" in lines[0]
    assert (out / "events.csv").read_text().splitlines()[1].startswith("0.5,command pause")


def test_a_running_session_is_said_to_be_running(tmp_path):
    _, out, _ = _killed_session(tmp_path, "dfs", 1, cycles=6)
    (out.parent / f".{out.name}.desdemona-lock").write_text(f"{os.getpid()}\ndesdemona serve\n")
    assert folder.live_note(out).startswith(f"{out}: session still running (process {os.getpid()}), written up to "
                                            "t = 0.080 s")
    summary = json.loads((out / "summary.json").read_text())
    summary.pop("live")
    (out / "summary.json").write_text(json.dumps(summary))
    assert folder.live_note(out) is None  # a whole result says nothing

"""`desdemona import log`: a logged motion in any declared units and axes gives the same path; the
convention check names the likely mistake; bad input is one message, exit 2, nothing written."""

import math
import os
import re
from datetime import datetime, timedelta

import numpy as np
import pytest

from desdemona import profiles
from desdemona.cli import main
from desdemona.profiles import clock, convert
from desdemona.profiles.log import STANDARD_GRAVITY, LogFormat, from_log, head_force
from desdemona.profiles.path import G, ProfileError

RATE = 200.0  # [Hz] of the synthetic logs


def bump(t, t0, t1):
    """A smooth 0 -> 1 -> 0 bump over [t0, t1] (raised cosine)."""
    x = np.clip((t - t0) / (t1 - t0), 0.0, 1.0)
    return 0.5 * (1.0 - np.cos(2.0 * np.pi * x))


def motion(still=2.0):
    """A vehicle still for ``still`` s, then a right turn and a brake: t (N,), omega_cabin and f_cabin
    (N, 3) in the cabin frame (x right, y forward, z up)."""
    t = np.arange(0.0, still + 6.0, 1.0 / RATE)
    turn, brake = bump(t, still, still + 3.0), bump(t, still + 3.0, still + 5.5)
    omega = np.column_stack([0.02 * turn, 0.05 * brake, -0.3 * turn])  # wz < 0: turning right
    f = np.column_stack([0.3 * G * turn, -0.6 * G * brake, G + 0.05 * G * turn])
    return t, omega, f


def write_log(file, t, omega, f, axes, accel_unit, rate_unit, time_unit="s", names=("t", "ax", "ay", "az", "p", "q", "r")):
    """The motion as a log would hold it: in the log's axes (v_log = R^T v_cabin) and units."""
    R = convert.axes_rotation(axes)
    scale_f = {"g": 1.0 / STANDARD_GRAVITY, "m/s2": 1.0}[accel_unit]
    scale_w = {"deg/s": 180.0 / math.pi, "rad/s": 1.0}[rate_unit]
    scale_t = {"s": 1.0, "ms": 1000.0}[time_unit]
    data = np.column_stack([t * scale_t, f @ R * scale_f, omega @ R * scale_w])
    with open(file, "w") as out:
        out.write("# a synthetic log\n" + ",".join(names) + "\n")
        for row in data:
            out.write(",".join(repr(float(x)) for x in row) + "\n")
    return file


CONVENTIONS = [  # axes of the log's x, y, z; accel unit; rate unit; time unit
    (("forward", "right", "down"), "g", "deg/s", "s"),
    (("right", "forward", "up"), "m/s2", "rad/s", "s"),
    (("up", "left", "back"), "g", "rad/s", "ms"),
    (("left", "back", "up"), "m/s2", "deg/s", "s"),
]


def test_every_convention_gives_the_same_path(tmp_path):
    t, omega, f = motion()
    paths = []
    for k, (axes, accel, rates, time_unit) in enumerate(CONVENTIONS):
        names = ("time", "a1", "a2", "a3", "w1", "w2", "w3") if k % 2 else ("t", "ax", "ay", "az", "p", "q", "r")
        log = write_log(tmp_path / f"log{k}.csv", t, omega, f, axes, accel, rates, time_unit, names)
        out = tmp_path / f"path{k}.csv"
        argv = ["import", "log", str(log), "--axes", ",".join(axes), "--accel-unit", accel, "--rate-unit", rates,
                "--time-unit", time_unit, "--out", str(out)]
        if k % 2:
            argv += ["--time", "time", "--accel", "a1,a2,a3", "--rates", "w1,w2,w3"]
        assert main(argv) == 0
        paths.append(profiles.load(out))
    for path in paths[1:]:
        np.testing.assert_allclose(path.t, paths[0].t, atol=1e-9)
        np.testing.assert_allclose(path.S_d, paths[0].S_d, rtol=1e-9, atol=1e-9)
    # the log's own rate is above 100 Hz: resampled to 100 Hz through the filter, close to the truth
    np.testing.assert_allclose(np.diff(paths[0].t), 0.01, atol=1e-12)
    truth = np.column_stack([omega, f])[::2]
    np.testing.assert_allclose(paths[0].S_d, truth[: len(paths[0].t)], atol=1e-3 * G)
    text = (tmp_path / "path2.csv").read_text()
    assert "# source: log log2.csv" in text and "up,left,back" in text and "convention check passed" in text


def test_semicolons_tabs_and_decimal_commas_give_the_same_path(tmp_path, capsys):
    """A log exported with semicolons and decimal commas (a European spreadsheet's, phyphox's "CSV
    (Semicolon, decimal comma)"), or with tabs, quoted names with spaces and parentheses, gives the same
    path as with commas; a bad cell is still named by its line and column."""
    t, omega, f = motion()
    names = ("Time (s)", "Acceleration x (m/s^2)", "Acceleration y (m/s^2)", "Acceleration z (m/s^2)",
             "Gyroscope x (rad/s)", "Gyroscope y (rad/s)", "Gyroscope z (rad/s)")
    plain = write_log(tmp_path / "plain.csv", t, omega, f, ("right", "forward", "up"), "m/s2", "rad/s", names=names)
    lines = plain.read_text().splitlines()
    quoted = ";".join(f'"{n}"' for n in names)
    (tmp_path / "semi.csv").write_text("\n".join(["# exported by phyphox, 2026", quoted] + [
        line.replace(",", ";").replace(".", ",") for line in lines[2:]]) + "\n")
    (tmp_path / "tab.csv").write_text("\n".join([lines[0], quoted.replace(";", "\t")] + [
        line.replace(",", "\t") for line in lines[2:]]) + "\n")
    assert "0,01;" in (tmp_path / "semi.csv").read_text()
    args = ["--time", names[0], "--accel", ",".join(names[1:4]), "--rates", ",".join(names[4:]),
            "--axes", "right,forward,up", "--accel-unit", "m/s2", "--rate-unit", "rad/s"]
    paths = []
    for name in ("plain", "semi", "tab"):
        assert main(["import", "log", str(tmp_path / f"{name}.csv"), *args, "--out", str(tmp_path / f"{name}-path.csv")]) == 0
        paths.append(profiles.load(tmp_path / f"{name}-path.csv"))
    for path in paths[1:]:
        np.testing.assert_array_equal(path.t, paths[0].t)
        np.testing.assert_array_equal(path.S_d, paths[0].S_d)
    capsys.readouterr()
    bad = (tmp_path / "semi.csv").read_text().splitlines()
    bad[9] = bad[9].replace(";", ";x", 1)
    (tmp_path / "bad.csv").write_text("\n".join(bad) + "\n")
    assert main(["import", "log", str(tmp_path / "bad.csv"), *args, "--out", str(tmp_path / "x.csv")]) == 2
    err = capsys.readouterr().err
    assert "line 10: column 'Acceleration x (m/s^2)': 'x" in err and not (tmp_path / "x.csv").exists()


def test_an_x_plane_data_file_reads_as_the_same_motion(tmp_path):
    """X-Plane's Data.txt: cells split by '|' and padded, names that hold a comma ('Gload,axial'),
    given to --accel and --rates separated by ';': the same path as the plain log."""
    t, omega, f = motion()
    axes = ("forward", "right", "down")
    plain = write_log(tmp_path / "plain.csv", t, omega, f, axes, "g", "rad/s")
    names = ["_real,_time", "Gload,axial", "Gload,_side", "Gload,norml", "____P,rad/s", "____Q,rad/s", "____R,rad/s"]
    rows = [line.split(",") for line in plain.read_text().splitlines()[2:]]
    (tmp_path / "Data.txt").write_text("".join(f"{n:>14}|" for n in names) + " \n" + "".join(
        "".join(f"{cell:>14}|" for cell in row) + " \n" for row in rows))
    args = ["--accel-unit", "g", "--rate-unit", "rad/s", "--axes", ",".join(axes)]
    assert main(["import", "log", str(plain), *args, "--out", str(tmp_path / "a.csv")]) == 0
    assert main(["import", "log", str(tmp_path / "Data.txt"), *args, "--time", names[0], "--accel",
                 ";".join(names[1:4]), "--rates", ";".join(names[4:]), "--out", str(tmp_path / "b.csv")]) == 0
    np.testing.assert_array_equal(profiles.load(tmp_path / "b.csv").S_d, profiles.load(tmp_path / "a.csv").S_d)


def test_crop_and_modulus(tmp_path):
    t, omega, f = motion()
    log = write_log(tmp_path / "log.csv", t, omega, f, ("forward", "right", "down"), "m/s2", "rad/s")
    out = tmp_path / "m.csv"
    assert main(["import", "log", str(log), "--accel-unit", "m/s2", "--rate-unit", "rad/s", "--start", "2",
                 "--end", "5", "--rate", "50", "--modulus", "--out", str(out)]) == 0
    path = profiles.load(out)
    assert path.S_d is None and path.t[0] == 0.0 and path.t[-1] == pytest.approx(3.0) and len(path.t) == 151
    k = np.searchsorted(t, 2.0 + path.t)
    np.testing.assert_allclose(path.M_d, np.linalg.norm(f[k], axis=1), atol=0.01)


def test_lever_arm_adds_centripetal_and_tangential_force():
    """A constant yaw rate: the head 1 m to the right of the sensor feels omega^2 r towards the centre;
    a yaw rate growing at alpha adds alpha x r."""
    t = np.arange(0.0, 4.0, 1.0 / RATE)
    w, alpha = 0.5, 0.2
    omega = np.column_stack([0 * t, 0 * t, w + alpha * t])
    f = np.tile([0.0, 0.0, G], (len(t), 1))
    r = np.array([1.0, 0.0, 0.0])
    f_head = head_force(omega, f, r, RATE)
    inner = slice(200, 600)  # away from the filter's ends
    np.testing.assert_allclose(f_head[inner, 0], -(w + alpha * t[inner]) ** 2, rtol=1e-9)
    np.testing.assert_allclose(f_head[inner, 1], alpha, rtol=1e-6)  # alpha x r = alpha z x x = alpha y
    np.testing.assert_allclose(f_head[inner, 2], G)


def test_lever_arm_in_the_logs_axes(tmp_path):
    t, omega, f = motion()
    log = write_log(tmp_path / "log.csv", t, omega, f, ("forward", "right", "down"), "m/s2", "rad/s")
    base = from_log(log, LogFormat())[0]
    moved = from_log(log, LogFormat(lever_arm=(0.0, 1.0, 0.0)))[0]  # 1 m to the right
    turning = np.argmax(np.abs(base.S_d[:, 2]))
    w = base.S_d[turning, :3]
    expected = np.cross(w, np.cross(w, [1.0, 0.0, 0.0]))[0]
    assert moved.S_d[turning, 3] - base.S_d[turning, 3] == pytest.approx(expected, rel=0.02)
    np.testing.assert_allclose(moved.S_d[:150], base.S_d[:150], atol=1e-6)  # still: nothing changes


@pytest.mark.parametrize("mistake, declared, words", [
    ("g declared as m/s^2", dict(accel_unit="g", declared_unit="m/s2"), "in g but declared as m/s^2"),
    ("m/s^2 declared as g", dict(accel_unit="m/s2", declared_unit="g"), "in m/s^2 but declared as g"),
    ("z up declared down", dict(axes=("forward", "left", "up"), declared_axes="forward,right,down"),
     "declared down"),
    ("a swapped axis", dict(axes=("down", "right", "back"), declared_axes="forward,right,down"),
     "which axis is vertical?"),
])
def test_convention_check_names_the_mistake(tmp_path, capsys, mistake, declared, words):
    t, omega, f = motion()
    axes = declared.get("axes", ("forward", "right", "down"))
    unit = declared.get("accel_unit", "m/s2")
    log = write_log(tmp_path / "log.csv", t, omega, f, axes, unit, "rad/s")
    out = tmp_path / "x.csv"
    assert main(["import", "log", str(log), "--axes", declared.get("declared_axes", ",".join(axes)),
                 "--accel-unit", declared.get("declared_unit", unit), "--rate-unit", "rad/s", "--out", str(out)]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and words in err, mistake
    assert list(tmp_path.iterdir()) == [log]


def test_kinematic_acceleration_is_not_specific_force(tmp_path, capsys):
    t, omega, f = motion()
    log = write_log(tmp_path / "log.csv", t, omega, f - [0.0, 0.0, G], ("right", "forward", "up"), "m/s2", "rad/s")
    assert main(["import", "log", str(log), "--axes", "right,forward,up", "--accel-unit", "m/s2", "--rate-unit",
                 "rad/s", "--out", str(tmp_path / "x.csv")]) == 2
    assert "kinematic acceleration, not specific force?" in capsys.readouterr().err
    # without rates the check reads the longest steady stretch: here a held 0.3 g brake, not the rest
    t = np.arange(0.0, 12.0, 1.0 / RATE)
    brake = np.clip(t - 1.0, 0.0, 1.0) - np.clip(t - 9.0, 0.0, 1.0)
    f = np.column_stack([0 * t, -0.3 * G * brake, 0 * t])
    log = write_log(tmp_path / "linear.csv", t, 0 * f, f, ("right", "forward", "up"), "m/s2", "rad/s")
    assert main(["import", "log", str(log), "--rates", "none", "--modulus", "--accel-unit", "m/s2", "--out",
                 str(tmp_path / "x.csv")]) == 2
    err = capsys.readouterr().err
    assert "|f| = 0.30 g, far below 1 g at rest: kinematic acceleration" in err and "TotalAcceleration.csv" in err


def test_left_handed_axes_are_refused(tmp_path, capsys):
    t, omega, f = motion()
    log = write_log(tmp_path / "log.csv", t, omega, f, ("forward", "right", "down"), "m/s2", "rad/s")
    assert main(["import", "log", str(log), "--axes", "forward,right,up", "--accel-unit", "m/s2", "--rate-unit",
                 "rad/s", "--out", str(tmp_path / "x.csv")]) == 2
    err = capsys.readouterr().err
    assert "left-handed" in err and err.count("\n") == 1
    with pytest.raises(ProfileError, match="same line"):
        convert.axes_rotation(("forward", "back", "up"))


def test_every_right_handed_assignment_is_a_proper_rotation():
    names = list(convert.DIRECTIONS)
    proper = 0
    for x in names:
        for y in names:
            for z in names:
                try:
                    R = convert.axes_rotation((x, y, z))
                except ProfileError:
                    continue
                proper += 1
                np.testing.assert_allclose(R.T @ R, np.eye(3))
                assert np.linalg.det(R) == pytest.approx(1.0)
    assert proper == 24  # the rotation group of the cube


def test_still_force_against_the_attitude():
    """Still (or in steady straight flight) the force points along the world's up: cabin +z when level,
    tilted by the attitude otherwise; the check holds it against the attitude where that is known."""
    for phi, theta in [(0.0, 0.0), (0.3, -0.2), (-1.0, 0.7)]:
        up = convert.up_from_attitude(phi, theta)
        # the world's up, (0, 0, -1) in NED, turned into body axes (x forward, y right, z down), then cabin
        R_body_ned = (np.array([[1, 0, 0], [0, np.cos(phi), np.sin(phi)], [0, -np.sin(phi), np.cos(phi)]])
                      @ np.array([[np.cos(theta), 0, -np.sin(theta)], [0, 1, 0], [np.sin(theta), 0, np.cos(theta)]]))
        np.testing.assert_allclose(up, convert.R_CABIN_BODY @ R_body_ned @ [0.0, 0.0, -1.0], atol=1e-12)
    pitched = convert.Still(0.0, 1.0, G * convert.up_from_attitude(0.0, np.radians(40.0)))  # a steep climb
    convert.check_convention(pitched, up=convert.up_from_attitude(0.0, np.radians(40.0)))
    with pytest.raises(ProfileError, match="which axis is vertical"):
        convert.check_convention(pitched)


def test_no_still_stretch_needs_no_check(tmp_path, capsys):
    t = np.arange(0.0, 6.0, 1.0 / RATE)
    omega = np.column_stack([0.2 * np.sin(t), 0.1 + 0 * t, -0.3 * np.cos(0.7 * t)])  # never still
    f = np.column_stack([0 * t, 0.1 * G * np.sin(2 * t), G + 0 * t])
    log = write_log(tmp_path / "log.csv", t, omega, f, ("forward", "right", "down"), "g", "deg/s")
    out = tmp_path / "x.csv"
    argv = ["import", "log", str(log), "--accel-unit", "g", "--rate-unit", "deg/s", "--out", str(out)]
    assert main(argv) == 2
    err = capsys.readouterr().err
    assert "convention check cannot run" in err and "--no-check" in err and not out.exists()
    assert main(argv + ["--no-check"]) == 0
    np.testing.assert_allclose(profiles.load(out).S_d[:, 3:].mean(axis=0), [0.0, 0.0, G], atol=0.1)
    assert "convention check skipped" in out.read_text()


def test_missing_columns_are_named_with_the_logs_own(tmp_path, capsys):
    t, omega, f = motion()
    log = write_log(tmp_path / "log.csv", t, omega, f, ("forward", "right", "down"), "g", "deg/s",
                    names=("time", "ax", "ay", "az", "gx", "gy", "gz"))
    out = tmp_path / "x.csv"
    assert main(["import", "log", str(log), "--accel-unit", "g", "--rate-unit", "deg/s", "--out", str(out)]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "'t', 'p', 'q', 'r'" in err and "time, ax, ay, az, gx, gy, gz" in err
    assert not out.exists()


def test_bad_rows_and_time(tmp_path, capsys):
    log = tmp_path / "log.csv"
    log.write_text("t,ax,ay,az,p,q,r\n0,0,0,-1,0,0,0\n0.1,0,x,-1,0,0,0\n")
    assert main(["import", "log", str(log), "--accel-unit", "g", "--rate-unit", "deg/s", "--out",
                 str(tmp_path / "x.csv")]) == 2
    assert "line 3" in capsys.readouterr().err
    log.write_text("t,ax,ay,az,p,q,r\n0,0,0,-1,0,0,0\n0.1,0,0,-1,0,0,0\n0.1,0,0,-1,0,0,0\n")
    assert main(["import", "log", str(log), "--accel-unit", "g", "--rate-unit", "deg/s", "--out",
                 str(tmp_path / "x.csv")]) == 2
    err = capsys.readouterr().err
    assert "does not increase" in err and "interleaved" not in err
    # two IMUs' rows interleaved, each pair at one instant (ArduPilot's IMU messages, instances 0 and 1)
    rows = [f"{0.01 * (k // 2):.2f},0,0,-1,0,0,0" for k in range(400)]
    log.write_text("t,ax,ay,az,p,q,r\n" + "\n".join(rows) + "\n")
    assert main(["import", "log", str(log), "--accel-unit", "g", "--rate-unit", "deg/s", "--out",
                 str(tmp_path / "x.csv")]) == 2
    assert "so on 200 of its 399 steps: the rows of two sensors interleaved" in capsys.readouterr().err
    assert sorted(p.name for p in tmp_path.iterdir()) == ["log.csv"]


def test_rates_in_deg_s_declared_as_rad_s_are_not_written(tmp_path, capsys):
    """A turn of 17 deg/s logged in deg/s and declared rad/s reads 17 rad/s for over a second: refused,
    naming --rate-unit, and nothing is written (it was written before, and `online` then ran it). Its
    gyros turn gravity's direction far faster than its accelerometer sees it turn, which names the unit
    before the rates' size does."""
    t, omega, f = motion()
    log = write_log(tmp_path / "log.csv", t, omega, f, ("right", "forward", "up"), "m/s2", "deg/s")
    out = tmp_path / "x.csv"
    argv = ["import", "log", str(log), "--axes", "right,forward,up", "--accel-unit", "m/s2", "--out", str(out)]
    assert main(argv + ["--rate-unit", "rad/s"]) == 2
    err = capsys.readouterr().err
    # the gyros turn gravity's direction 57.3 times as fast as the accelerometer sees it (profiles.turns)
    assert "log.csv: the rates turn gravity's direction" in err and "--rate-unit deg/s" in err
    assert sorted(p.name for p in tmp_path.iterdir()) == ["log.csv"]
    assert main(argv + ["--rate-unit", "deg/s"]) == 0


def test_milliseconds_declared_as_seconds_are_refused(tmp_path, capsys):
    """A 100 Hz log with t in ms (0, 10, 20, ...) read as seconds would be a 0.1 Hz path of hours: refused
    at import, pointing to --time-unit ms, by the CSV reader's rule; declared as ms it imports."""
    t = np.arange(0.0, 8.0, 0.01)
    omega, f = np.zeros((len(t), 3)), np.tile([0.0, 0.0, G], (len(t), 1))
    log = write_log(tmp_path / "log.csv", t, omega, f, ("right", "forward", "up"), "m/s2", "rad/s", "ms")
    out = tmp_path / "x.csv"
    argv = ["import", "log", str(log), "--axes", "right,forward,up", "--accel-unit", "m/s2", "--rate-unit", "rad/s",
            "--out", str(out)]
    assert main(argv) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "looks like milliseconds" in err and "--time-unit ms" in err
    assert "divide it by 1000" not in err and not out.exists()
    assert main(argv + ["--time-unit", "ms"]) == 0
    assert profiles.load(out).duration == pytest.approx(7.99)


def test_one_g_reading_converts_with_standard_gravity(tmp_path):
    """A sensor's g unit is standard gravity, 9.80665 m/s^2 (not the simulator's G = 9.81)."""
    t = np.arange(0.0, 3.0, 0.01)
    log = tmp_path / "log.csv"
    log.write_text("t,ax,ay,az,p,q,r\n" + "".join(f"{float(x)!r},0,0,-1,0,0,0\n" for x in t))
    path = from_log(log, LogFormat(accel_unit="g"))[0]
    np.testing.assert_allclose(path.S_d[:, 5], 9.80665, rtol=1e-12)


def accelerometer_log(file, t, f, axes, scale=1.0):
    """The force alone, as a phone or a ride's logger records it: time and three readings [g]."""
    readings = f @ convert.axes_rotation(axes) * scale / STANDARD_GRAVITY
    with open(file, "w") as out:
        out.write(" ,time,x,y,z\n" + "".join(",".join(["", *(repr(float(v)) for v in (ti, *row))]) + "\n"
                                            for ti, row in zip(t, readings)))
    return file


def test_an_accelerometer_alone_gives_the_modulus_in_any_axes(tmp_path):
    """A log of readings without rates, its sensor in a pocket (no axis up): the modulus form, the same
    whatever axes are declared, and the still check reads only |f|."""
    t, _, f = motion()
    log = accelerometer_log(tmp_path / "ride.txt", t, f, ("up", "left", "back"))  # lying on its side
    paths = []
    for k, axes in enumerate(("forward,right,down", "up,left,back")):
        out = tmp_path / f"m{k}.csv"
        assert main(["import", "log", str(log), "--time", "time", "--accel", "x,y,z", "--accel-unit", "g",
                     "--rates", "none", "--axes", axes, "--modulus", "--out", str(out)]) == 0
        paths.append(profiles.load(out))
        assert "rates none" in out.read_text() and "convention check passed" in out.read_text()
    np.testing.assert_allclose(paths[0].M_d, paths[1].M_d, rtol=1e-12)
    k = np.searchsorted(t, paths[0].t)
    np.testing.assert_allclose(paths[0].M_d, np.linalg.norm(f[k], axis=1), atol=1e-3 * G)


def test_a_scale_off_sensor_reads_1_g_where_still_with_to_g(tmp_path, capsys):
    t, _, f = motion()
    log = accelerometer_log(tmp_path / "ride.txt", t, f, ("forward", "right", "down"), scale=0.94)
    out = tmp_path / "m.csv"
    argv = ["import", "log", str(log), "--time", "time", "--accel", "x,y,z", "--accel-unit", "g", "--rates", "none",
            "--modulus", "--out", str(out)]
    assert main(argv) == 0
    np.testing.assert_allclose(profiles.load(out).M_d[:100], 0.94 * G, rtol=1e-6)
    assert main(argv + ["--to-g", "--overwrite"]) == 0
    path = profiles.load(out)
    np.testing.assert_allclose(path.M_d[:100], G, rtol=1e-6)
    k = np.searchsorted(t, path.t)
    np.testing.assert_allclose(path.M_d, np.linalg.norm(f[k], axis=1), atol=1e-3 * G)
    assert "scaled by 1.0638 to read 1 g where still (--to-g)" in out.read_text()
    capsys.readouterr()
    assert main(argv + ["--to-g", "--no-check", "--overwrite"]) == 2
    assert "--to-g" in capsys.readouterr().err


@pytest.mark.parametrize("extra, words", [
    ([], "add --modulus"),  # six channels need the rates
    (["--modulus", "--lever-arm", "0,0,1"], "--lever-arm needs the angular rates"),
])
def test_a_log_without_rates_gives_only_the_modulus(tmp_path, capsys, extra, words):
    t, _, f = motion()
    log = accelerometer_log(tmp_path / "ride.txt", t, f, ("forward", "right", "down"))
    out = tmp_path / "x.csv"
    assert main(["import", "log", str(log), "--time", "time", "--accel", "x,y,z", "--accel-unit", "g", "--rates",
                 "none", "--out", str(out), *extra]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and words in err and not out.exists()


def test_rates_need_their_unit(tmp_path, capsys):
    t, omega, f = motion()
    log = write_log(tmp_path / "log.csv", t, omega, f, ("forward", "right", "down"), "g", "deg/s")
    out = tmp_path / "x.csv"
    assert main(["import", "log", str(log), "--accel-unit", "g", "--out", str(out)]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "--rate-unit" in err and "p,q,r" in err and "--rates none" in err
    assert not out.exists()


def scaled_to_g(tmp_path, t, level, seed):
    """Import a noisy upright log of ``level`` [g] at times ``t`` without rates, with --to-g: the factor
    it was scaled by, and the path."""
    noise = np.random.default_rng(seed).normal(0.0, 0.01, size=(len(t), 3))
    f = (np.column_stack([0 * t, 0 * t, level]) + noise) * G
    log = accelerometer_log(tmp_path / "ride.txt", t, f, ("forward", "right", "down"))
    out = tmp_path / "m.csv"
    assert main(["import", "log", str(log), "--time", "time", "--accel", "x,y,z", "--accel-unit", "g", "--rates",
                 "none", "--modulus", "--to-g", "--out", str(out)]) == 0
    return float(out.read_text().split("scaled by ")[1].split()[0]), profiles.load(out)


def test_without_rates_the_rest_is_the_longest_steady_stretch(tmp_path):
    """Without rates a steady pull looks still too: 5 s at rest at 0.95 g, then 2 s held at 1.15 g
    and 2 s at 2 g, all with the same noise. The stillest stretch relative to its size is the 2 g one
    (refused as a wrong scale), the rest is the longest: --to-g scales by 1 / 0.95."""
    t = np.arange(0.0, 13.0, 1.0 / 50.0)
    level = np.select([t < 5.0, (t >= 6.0) & (t < 8.0), (t >= 9.0) & (t < 11.0)], [0.95, 1.15, 2.0], 1.05)
    factor, path = scaled_to_g(tmp_path, t, level, seed=0)
    assert factor == pytest.approx(1.0 / 0.95 * G / STANDARD_GRAVITY, rel=2e-3)
    np.testing.assert_allclose(np.median(path.M_d[:200]), G, rtol=2e-3)


def test_a_gap_in_the_log_is_not_taken_for_a_rest(tmp_path):
    """A log with 28 s missing between two readings of 1.5 g: the grid bridges the gap with a straight
    line, as steady as a rest and longer than the real one after it; the check reads the real one."""
    before, after = np.arange(0.0, 2.0, 1.0 / 20.0), np.arange(30.0, 38.0, 1.0 / 20.0)
    level = np.concatenate([1.0 + 0.5 * before / 2.0,  # pulled up to 1.5 g when the log stops
                            np.where(after < 30.5, 1.5, np.where(after < 34.0, 0.95, 1.3 + 0.2 * np.sin(after)))])
    factor, _ = scaled_to_g(tmp_path, np.concatenate([before, after]), level, seed=1)
    # the rest is read over its stillest second: 21 samples of 1 % noise, their mean within 0.22 % (one
    # sigma) of the level; imported at its own rate, the log is not filtered (3 sigma)
    assert factor == pytest.approx(1.0 / 0.95 * G / STANDARD_GRAVITY, rel=7e-3)


def test_a_gap_within_the_crop_is_imported_with_a_warning(tmp_path, capsys):
    """0.55 s without a reading in a 20 Hz log (11 steps) is bridged, and said: on stderr and in the file;
    the same log cropped before the gap, or without it, says nothing."""
    t = np.arange(0.0, 12.0, 0.05)
    f = np.column_stack([0 * t, 0.2 * G * np.sin(t), G + 0 * t])
    full = accelerometer_log(tmp_path / "full.txt", t, f, ("forward", "right", "down"))
    holed = accelerometer_log(tmp_path / "holed.txt", t[(t < 6.0) | (t > 6.45)], f[(t < 6.0) | (t > 6.45)],
                              ("forward", "right", "down"))
    base = ["import", "log", "--time", "time", "--accel", "x,y,z", "--accel-unit", "g", "--rates", "none", "--modulus"]
    for log, crop, said in ((holed, [], True), (holed, ["--end", "5"], False), (full, [], False)):
        out = tmp_path / f"{log.stem}{len(crop)}.csv"
        assert main([*base[:2], str(log), *base[2:], *crop, "--out", str(out)]) == 0
        err = capsys.readouterr().err
        assert ("no reading for 0.55 s from 5.95 s" in err) == said
        assert ("# warning: no reading for 0.55 s" in out.read_text()) == said
        assert profiles.load(out).M_d is not None  # the warning is a comment the reader skips


def dataset_log(file, t, omega, f, axes, origin=1.4e9):
    """The motion as an IMU dataset (EuRoC's layout) holds it: the header a ``#`` comment, time in
    nanoseconds from 1970, rates [rad/s] before forces [m/s^2], in the sensor's axes."""
    R = convert.axes_rotation(axes)
    with open(file, "w") as out:
        out.write("#timestamp [ns],w_RS_S_x [rad s^-1],w_RS_S_y [rad s^-1],w_RS_S_z [rad s^-1],"
                  "a_RS_S_x [m s^-2],a_RS_S_y [m s^-2],a_RS_S_z [m s^-2]\n")
        for ti, w, a in zip(t, omega @ R, f @ R):
            out.write(f"{round(origin * 1e9) + round(ti * 1e9)}," + ",".join(repr(float(x)) for x in (*w, *a)) + "\n")
    return file


DATASET = ["--accel", "a_RS_S_x [m s^-2],a_RS_S_y [m s^-2],a_RS_S_z [m s^-2]", "--rates",
           "w_RS_S_x [rad s^-1],w_RS_S_y [rad s^-1],w_RS_S_z [rad s^-1]", "--accel-unit", "m/s2",
           "--rate-unit", "rad/s", "--time-unit", "ns", "--axes", "up,right,forward"]


def test_a_datasets_layout_reads_as_the_same_motion(tmp_path, capsys):
    """A header in a ``#`` comment above the rows and a nanosecond clock from 1970 (EuRoC's, ROS's):
    the same path as the plain log, its times as exact; the crop and its messages in the log's clock."""
    t, omega, f = motion()
    plain = write_log(tmp_path / "plain.csv", t, omega, f, ("up", "right", "forward"), "m/s2", "rad/s")
    assert main(["import", "log", str(plain), "--accel-unit", "m/s2", "--rate-unit", "rad/s", "--axes",
                 "up,right,forward", "--out", str(tmp_path / "a.csv")]) == 0
    log = dataset_log(tmp_path / "imu.csv", t, omega, f, ("up", "right", "forward"))
    for time in ("#timestamp [ns]", "timestamp [ns]"):  # as the file shows it, or as the header's name
        out = tmp_path / "b.csv"
        assert main(["import", "log", str(log), "--time", time, *DATASET, "--overwrite", "--out", str(out)]) == 0
        a, b = profiles.load(tmp_path / "a.csv"), profiles.load(out)
        np.testing.assert_allclose(b.t, a.t, atol=1e-12)  # the ns clock read as integers: as exact as the plain
        np.testing.assert_allclose(b.S_d, a.S_d, atol=1e-9)
    assert "# source: crop 1400000000-1400000007.99 s" in out.read_text()
    argv = ["import", "log", str(log), "--time", "timestamp [ns]", *DATASET, "--out", str(tmp_path / "c.csv")]
    assert main(argv + ["--start", "1400000001.5", "--end", "1400000004"]) == 0
    assert profiles.load(tmp_path / "c.csv").duration == pytest.approx(2.5)
    assert main(argv + ["--start", "5", "--overwrite"]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "--start 5: outside the log, which runs from 1400000000 s to 1400000007.99 s" in err


@pytest.mark.parametrize("decimals", [3, 5])
def test_seconds_from_1970_with_decimals_keep_every_sample(tmp_path, decimals):
    """A clock of seconds since 1970 written with decimals (a spreadsheet's or pandas' export): float64
    keeps a quarter of a microsecond there, so read as floats its steps wandered, the log was put on a
    grid of their median and lost its last sample. Read as counts of the last decimal: the plain log's
    path, every sample."""
    t, omega, f = motion()
    axes = ("up", "right", "forward")
    plain = write_log(tmp_path / "plain.csv", t, omega, f, axes, "m/s2", "rad/s")
    epoch = write_log(tmp_path / "epoch.csv", t, omega, f, axes, "m/s2", "rad/s")
    rows = epoch.read_text().splitlines()
    rows[2:] = [f"{1691185678.25 + k / RATE:.{decimals}f}," + row.split(",", 1)[1] for k, row in enumerate(rows[2:])]
    epoch.write_text("\n".join(rows) + "\n")
    paths = []
    for log in (plain, epoch):
        out = tmp_path / f"{log.stem}-path.csv"
        assert main(["import", "log", str(log), "--accel-unit", "m/s2", "--rate-unit", "rad/s", "--axes",
                     ",".join(axes), "--out", str(out)]) == 0
        paths.append(profiles.load(out))
    assert len(paths[1].t) == len(paths[0].t) == 800  # 200 Hz read, at most 100 Hz written
    np.testing.assert_allclose(paths[1].t, paths[0].t, atol=1e-12)
    np.testing.assert_allclose(paths[1].S_d, paths[0].S_d, atol=1e-9)


def test_a_clock_is_counted_in_its_last_decimal():
    counts = clock.Counts()
    for cell in ("5", "5.25", "-0.5", "+7.1"):
        counts.add(cell)
    values, decimals = counts.counts()
    assert decimals == 2 and values.tolist() == [500, 525, -50, 710] and values.dtype == np.int64
    for odd in ("1.7e9", "0.1234567891", "12:00", "9" * 20):  # floats, more than nine decimals, no number, beyond int64
        counts = clock.Counts()
        for cell in ("1", odd):
            counts.add(cell)
        assert counts.counts() is None, odd


def test_rows_without_a_header_are_refused(tmp_path, capsys):
    """Numbers where the header should be, with no comment above naming as many columns: one line."""
    t, omega, f = motion()
    log = dataset_log(tmp_path / "imu.csv", t, omega, f, ("up", "right", "forward"))
    lines = log.read_text().splitlines()
    for k, (text, words) in enumerate((([lines[0] + ",extra", *lines[1:]], "line 2: numbers where the header "
                                        "should be: the '#' comment at line 1 names 8 columns, the rows have 7"),
                                       (lines[1:], "line 1: numbers where the header should be;"))):
        bad = tmp_path / f"bad{k}.csv"
        bad.write_text("\n".join(text) + "\n")
        assert main(["import", "log", str(bad), "--time", "timestamp [ns]", *DATASET, "--out",
                     str(tmp_path / "x.csv")]) == 2
        err = capsys.readouterr().err
        assert err.count("\n") == 1 and words in err
    assert not (tmp_path / "x.csv").exists()
    # a blank line and another comment between the header and the rows are no matter
    (tmp_path / "spaced.csv").write_text("\n".join([lines[0], "", "# units as named", *lines[1:]]) + "\n")
    assert main(["import", "log", str(tmp_path / "spaced.csv"), "--time", "timestamp [ns]", *DATASET, "--out",
                 str(tmp_path / "x.csv")]) == 0


def test_a_time_unit_declared_wrong_is_refused_naming_the_right_one(tmp_path, capsys):
    """A 100 Hz log in microseconds: declared as ms it is a 2 Hz-or-slower log of hours, as ns a 100 kHz
    log of 8 ms; in nanoseconds declared as seconds a log of days. Each is refused in one line naming
    the unit it is in; declared right it imports."""
    t = np.arange(0.0, 8.0, 0.01)
    omega, f = np.zeros((len(t), 3)), np.tile([0.0, 0.0, G], (len(t), 1))
    for factor, declared, words in ((1e6, "ms", "read as ms"), (1e6, "ns", "sampled at 100 kHz"), (1e9, "s", "days")):
        log = write_log(tmp_path / "log.csv", t * factor / 1000.0, omega, f, ("right", "forward", "up"), "m/s2",
                        "rad/s", "ms")
        argv = ["import", "log", str(log), "--axes", "right,forward,up", "--accel-unit", "m/s2", "--rate-unit",
                "rad/s", "--out", str(tmp_path / "x.csv"), "--time-unit"]
        assert main(argv + [declared]) == 2
        err = capsys.readouterr().err
        right = {1e6: "us", 1e9: "ns"}[factor]
        assert err.count("\n") == 1 and words in err and f"declare --time-unit {right}" in err
        assert not (tmp_path / "x.csv").exists()
        assert main(argv + [right, "--overwrite"]) == 0
        assert profiles.load(tmp_path / "x.csv").duration == pytest.approx(7.99)
        (tmp_path / "x.csv").unlink()


def test_a_gyros_bias_is_named_and_taken_off_with_zero_rates(tmp_path, capsys):
    """A resting gyro reading (0.5, 4, -2) deg/s with noise: the check names the bias and --zero-rates;
    with it the rates are the motion's, the bias in the source line; with --rates none it is refused."""
    t, omega, f = motion(still=3.0)
    bias = np.radians([0.5, 4.0, -2.0])
    noise = np.random.default_rng(3).normal(0.0, np.radians(0.1), omega.shape)
    log = dataset_log(tmp_path / "imu.csv", t, omega + bias + noise, f, ("up", "right", "forward"))
    argv = ["import", "log", str(log), "--time", "timestamp [ns]", *DATASET, "--out", str(tmp_path / "x.csv")]
    assert main(argv) == 2
    err = capsys.readouterr().err
    read = lambda text, words: [float(x) for x in re.search(words + r" \(([^)]*)\) deg/s", text)[1].split(",")]  # noqa: E731
    assert err.count("\n") == 1 and "--zero-rates takes it off" in err
    np.testing.assert_allclose(read(err, "rates read a steady"), [0.5, 4.0, -2.0], atol=0.03)
    assert main(argv + ["--zero-rates"]) == 0
    path = profiles.load(tmp_path / "x.csv")
    np.testing.assert_allclose(path.S_d[:, :3], omega[::2][: len(path.t)], atol=np.radians(0.3))
    np.testing.assert_allclose(read((tmp_path / "x.csv").read_text(), "rates less their bias"), [0.5, 4.0, -2.0],
                               atol=0.03)
    # a bias beyond a gyro's, or rates in deg/s declared as rad/s: named, with what to check
    for rates, words in (((omega + bias + noise) * 4.0, "more than a gyro's bias (10 deg/s): a steady turn, or the "
                          "rates in deg/s declared as rad/s?"),
                         ((omega + noise) * 180.0 / math.pi, "read as deg/s the rates are still")):
        wrong = dataset_log(tmp_path / "wrong.csv", t, rates, f, ("up", "right", "forward"))
        for extra in ([], ["--zero-rates"]):  # --zero-rates cannot take it off either, and says why
            assert main(["import", "log", str(wrong), *argv[3:], "--overwrite", *extra]) == 2
            assert words in capsys.readouterr().err
    for extra, words in ((["--rates", "none", "--modulus"], "--zero-rates needs the angular rates"),
                         (["--no-check"], "--zero-rates reads the still stretch")):
        assert main(argv + ["--zero-rates", "--overwrite", *extra]) == 2
        assert words in capsys.readouterr().err


def test_a_sensor_mounted_at_an_angle_is_levelled(tmp_path):
    """The sensor pitched 15 deg on the vehicle: its still force reads 15 deg off up (within the check);
    --level turns forces and rates back onto the vehicle's, the motion's own."""
    t, omega, f = motion()
    c, s = math.cos(math.radians(15.0)), math.sin(math.radians(15.0))
    pitch = np.array([[1.0, 0.0, 0.0], [0.0, c, -s], [0.0, s, c]])  # about the cabin's x (right)
    log = dataset_log(tmp_path / "imu.csv", t, omega @ pitch, f @ pitch, ("up", "right", "forward"))
    argv = ["import", "log", str(log), "--time", "timestamp [ns]", *DATASET]
    assert main(argv + ["--out", str(tmp_path / "tilted.csv")]) == 0
    assert main(argv + ["--level", "--out", str(tmp_path / "level.csv")]) == 0
    tilted, level = profiles.load(tmp_path / "tilted.csv"), profiles.load(tmp_path / "level.csv")
    truth = np.column_stack([omega, f])[::2][: len(level.t)]
    np.testing.assert_allclose(level.S_d, truth, atol=1e-3 * G)
    assert np.abs(tilted.S_d - truth).max() > 0.2 * G
    assert "turned by 15 deg so that the force reads straight up" in (tmp_path / "level.csv").read_text()


def test_level_reads_the_rest_not_a_later_steady_acceleration(tmp_path, capsys):
    """A car at rest for 3 s, then speeding up at a steady 1.5 m/s^2 for 5 s with no turn: to an
    accelerometer as still as a rest on a slope, and here stiller (the rest's readings are noisy, the
    pull's not). --level reads the rest, the first still stretch, and warns of the other, 8.7 deg off."""
    t = np.arange(0.0, 14.0, 1.0 / RATE)
    pull = np.clip(t - 3.5, 0.0, 1.0) - np.clip(t - 9.5, 0.0, 1.0)  # up by 4.5 s, down after 9.5 s
    omega = np.zeros((len(t), 3))
    f = np.column_stack([0 * t, 1.5 * pull, G + 0 * t])
    rest = (t < 3.0)[:, None] * np.random.default_rng(3).normal(0.0, 0.05, (len(t), 3))
    log = dataset_log(tmp_path / "imu.csv", t, omega, f + rest, ("up", "right", "forward"))
    assert main(["import", "log", str(log), "--time", "timestamp [ns]", *DATASET, "--level",
                 "--out", str(tmp_path / "x.csv")]) == 0
    path = profiles.load(tmp_path / "x.csv")
    assert np.abs(path.S_d[(path.t > 5.0) & (path.t < 9.0), 3:] - [0.0, 1.5, G]).max() < 0.01
    err = capsys.readouterr().err
    angle = re.search(r"the first still stretch; from 1400000004.\d+ s to \S+ s it is as still but reads ([0-9.]+) deg", err)
    assert float(angle[1]) == pytest.approx(math.degrees(math.atan(1.5 / G)), abs=0.05)


def test_zero_rates_reads_the_rest_not_a_later_steady_curve(tmp_path):
    """A car at rest for 3 s, then a long steady curve (2.9 deg/s, 0.13 g): the curve is as steady as
    the rest, its rate as constant as a bias. --zero-rates reads the rest, the first still stretch, and
    the curve keeps its rate and force."""
    t = np.arange(0.0, 25.0, 1.0 / RATE)
    ramp = np.clip(t - 7.0, 0.0, 1.0)
    omega = np.column_stack([0 * t, 0 * t, -np.radians(2.9) * ramp])  # turning right
    f = np.column_stack([1.25 * ramp, 0 * t, G + 0 * t])
    rng = np.random.default_rng(5)
    noisy = omega + rng.normal(0.0, np.radians(0.2), omega.shape), f + rng.normal(0.0, 0.05, f.shape)
    log = dataset_log(tmp_path / "imu.csv", t, *noisy, ("up", "right", "forward"))
    assert main(["import", "log", str(log), "--time", "timestamp [ns]", *DATASET, "--zero-rates",
                 "--out", str(tmp_path / "x.csv")]) == 0
    path = profiles.load(tmp_path / "x.csv")
    curve = path.t > 10.0
    assert np.degrees(np.mean(path.S_d[curve, 2])) == pytest.approx(-2.9, abs=0.1)
    assert np.mean(path.S_d[curve, 3]) == pytest.approx(1.25, abs=0.05)
    bias = re.search(r"rates less their bias \(([^)]*)\) deg/s.*read still from ([0-9.]+) s", (tmp_path / "x.csv").read_text())
    assert np.all(np.abs([float(x) for x in bias[1].split(",")]) < 0.1) and float(bias[2]) - 1.4e9 < 6.0


def test_a_sensor_tilted_beyond_the_check_is_named_and_levelled(tmp_path, capsys):
    """Pitched 35 deg: beyond the check's 30 deg for a vehicle on a slope, refused as a tilt (not as g
    along another axis) pointing to --level, which takes up to 60 deg."""
    t, omega, f = motion()
    c, s = math.cos(math.radians(35.0)), math.sin(math.radians(35.0))
    pitch = np.array([[1.0, 0.0, 0.0], [0.0, c, -s], [0.0, s, c]])
    log = dataset_log(tmp_path / "imu.csv", t, omega @ pitch, f @ pitch, ("up", "right", "forward"))
    argv = ["import", "log", str(log), "--time", "timestamp [ns]", *DATASET, "--out", str(tmp_path / "x.csv")]
    assert main(argv) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "the force is 35 deg from up" in err and "--level turns a sensor" in err
    assert "e-1" not in err.split("reads (")[1].split(")")[0]  # round-off prints as 0
    assert main(argv + ["--level"]) == 0
    np.testing.assert_allclose(profiles.load(tmp_path / "x.csv").S_d, np.column_stack([omega, f])[::2][:800],
                               atol=1e-3 * G)


def dated_log(file, t, omega, f, axes, first="2023-08-04 17:47:58-04:00", sep=" ", layout=None):
    """The motion with its time as ISO 8601 dates and times from ``first`` (a pandas export's, a phone
    logger's; or in the strftime ``layout``), in the log's axes, forces [m/s^2] and rates [rad/s]."""
    R = convert.axes_rotation(axes)
    start = datetime.fromisoformat(first)
    with open(file, "w") as out:
        out.write("time,ax,ay,az,p,q,r\n")
        for ti, a, w in zip(t, f @ R, omega @ R):
            moment = start + timedelta(seconds=float(ti))
            when = moment.isoformat(sep=sep) if layout is None else moment.strftime(layout)[:-3]  # ms
            out.write(when + "," + ",".join(repr(float(x)) for x in (*a, *w)) + "\n")
    return file


DATED = ["--time", "time", "--accel-unit", "m/s2", "--rate-unit", "rad/s", "--axes", "left,up,forward"]


def test_a_log_stamped_with_dates_reads_as_the_same_motion(tmp_path, capsys):
    """A time column of ISO 8601 dates and times, with a UTC offset or without one (taken as UTC): the
    same path as the plain log; the crop given as dates, its messages and source line in UTC."""
    t, omega, f = motion()
    axes = ("left", "up", "forward")
    plain = write_log(tmp_path / "plain.csv", t, omega, f, axes, "m/s2", "rad/s")
    assert main(["import", "log", str(plain), *DATED[2:], "--out", str(tmp_path / "a.csv")]) == 0
    a = profiles.load(tmp_path / "a.csv")
    for k, (first, layout) in enumerate((("2023-08-04 17:47:58-04:00", None), ("2023-08-04T21:47:58", None),
                                         ("2023-08-04T21:47:58", "%d-%b-%Y %H:%M:%S.%f"))):  # MATLAB's
        log = dated_log(tmp_path / f"dated{k}.csv", t, omega, f, axes, first, sep=first[10], layout=layout)
        out = tmp_path / f"b{k}.csv"
        assert main(["import", "log", str(log), *DATED, "--out", str(out)]) == 0
        b = profiles.load(out)
        np.testing.assert_allclose(b.t, a.t, atol=1e-9)
        np.testing.assert_allclose(b.S_d, a.S_d, atol=1e-9)  # dates read as whole microseconds: exact
        assert "# source: crop 2023-08-04T21:47:58+00:00 to 2023-08-04T21:48:05.990+00:00" in out.read_text()
    argv = ["import", "log", str(tmp_path / "dated0.csv"), *DATED, "--out", str(tmp_path / "c.csv")]
    assert main(argv + ["--start", "2023-08-04 17:48:00-04:00", "--end", "2023-08-04T21:48:03Z"]) == 0
    assert profiles.load(tmp_path / "c.csv").duration == pytest.approx(3.0)
    assert "columns time time [date and time]" in (tmp_path / "c.csv").read_text()
    # its rates in a file of their own on the same clock, as seconds since 1970: the same path
    epoch = write_log(tmp_path / "rates.csv", t + 1691185678.0, omega, f, axes, "m/s2", "rad/s",
                      names=("time", "ax", "ay", "az", "p", "q", "r"))
    assert main(argv[:3] + ["--rates-file", str(epoch)] + argv[3:-1] + [str(tmp_path / "d.csv")]) == 0
    np.testing.assert_allclose(profiles.load(tmp_path / "d.csv").S_d, a.S_d, atol=1e-4)
    for extra, words in ((["--start", "2023-08-04 17:00:00-04:00"], "--start 2023-08-04T21:00:00+00:00: outside the "
                           "log, which runs from 2023-08-04T21:47:58+00:00 to 2023-08-04T21:48:05.990+00:00"),
                         (["--start", "3"], "of its own clock (give --start as a date and time, as the log's)"),
                         (["--start", "2023-08-04T21:48:03Z", "--end", "2023-08-04T21:48:00Z"], "--start 2023-08-04T21:48"
                          ":03+00:00 and --end 2023-08-04T21:48:00+00:00: the end must be after the start"),
                         (["--axes", "forward,right,down"], "still from 2023-08-04T21:47:5"),  # the check's, in UTC too
                         (["--start", "after lunch"], "'after lunch': give seconds, or a date and time"),
                         (["--time-unit", "ms"], "column 'time' holds dates and times, read as seconds since 1970: "
                          "drop --time-unit ms")):
        assert main(argv + extra + ["--overwrite"]) == 2
        err = capsys.readouterr().err
        assert words in err.splitlines()[-1]  # the last line: argparse's own error follows its usage


def test_a_cell_that_cannot_be_read_is_named_by_its_column(tmp_path, capsys):
    t, omega, f = motion()
    log = dated_log(tmp_path / "dated.csv", t, omega, f, ("left", "up", "forward"))
    lines = log.read_text().splitlines()
    for k, (row, words) in enumerate(((lines[5].replace("2023-08-04 ", "2023-08-4x "), "line 6: column 'time': "
                                       "'2023-08-4x 17:47:58.020000-04:00' is not a date and time as the first row's"),
                                      (lines[5].replace(",", ",x,", 1).rsplit(",", 1)[0],
                                       "line 6: column 'ax': 'x' is not a number"),
                                      (lines[5].rsplit(",", 1)[0], "line 6: column 'r': no value"),
                                      # local times beside ones with their offset: hours apart, read as UTC
                                      (lines[5].replace("-04:00,", ",", 1), "line 6: column 'time': '2023-08-04 "
                                       "17:47:58.020000' has no UTC offset, the first row's has one"))):
        bad = tmp_path / f"bad{k}.csv"
        bad.write_text("\n".join([*lines[:5], row, *lines[6:]]) + "\n")
        assert main(["import", "log", str(bad), *DATED, "--out", str(tmp_path / "x.csv")]) == 2
        err = capsys.readouterr().err
        assert err.count("\n") == 1 and words in err
    excel = tmp_path / "excel.csv"  # a spreadsheet's dates are not ISO 8601: the message shows the form read
    excel.write_text("\n".join([lines[0]] + [line.replace("2023-08-04 ", "04.08.2023 ") for line in lines[1:]]) + "\n")
    assert main(["import", "log", str(excel), *DATED, "--out", str(tmp_path / "x.csv")]) == 2
    assert "is not a number, nor a date and time (ISO 8601's 2023-08-04 17:47:58-04:00, MATLAB's" in capsys.readouterr().err
    assert not (tmp_path / "x.csv").exists()


def test_a_slow_log_on_a_clock_from_1970_or_declared_is_not_taken_for_milliseconds(tmp_path, capsys):
    """A phone's log of a drive averaged to a row a second, stamped in seconds since 1970: in its unit
    (in milliseconds its clock would read January 1970), imported with a warning and interpolated to
    10 Hz, which every command reads. The same rows from t = 0 are taken for milliseconds unless
    --time-unit s is declared, and then give the same path; a clock declared in seconds that steps
    10 s is still refused as milliseconds, and a path asked at 2 Hz or slower is refused."""
    t = np.arange(0.0, 61.0)
    turn, brake = bump(t, 10.0, 30.0), bump(t, 35.0, 50.0)
    omega = np.column_stack([0 * t, 0 * t, 0.2 * turn])
    f = np.column_stack([-0.2 * G * turn, -0.3 * G * brake, np.full_like(t, G)])
    axes = ("right", "forward", "up")
    args = ["--axes", "right,forward,up", "--accel-unit", "m/s2", "--rate-unit", "rad/s"]
    epoch = write_log(tmp_path / "drive.csv", t + 1691185678.0, omega, f, axes, "m/s2", "rad/s")
    out = tmp_path / "x.csv"
    assert main(["import", "log", str(epoch), *args, "--out", str(out)]) == 0
    err = capsys.readouterr().err
    assert "warning: the log has a reading every 1 s: what changes faster than 0.5 Hz" in err
    path = profiles.load(out)
    assert len(path.t) == 601 and path.duration == pytest.approx(60.0)
    np.testing.assert_allclose(path.S_d[::10, 5], f[:, 2], atol=1e-9)  # interpolated between the readings
    assert np.max(np.abs(path.S_d[::10, 3] - f[:, 0])) < 0.05 * G  # through the filter at its native rate
    assert main(["import", "log", str(epoch), *args, "--rate", "2", "--out", str(tmp_path / "y.csv")]) == 2
    assert "--rate 2: give more than 2 samples per second" in capsys.readouterr().err
    # declared as milliseconds it is a log of 0.06 s (the drive's hour, 6.3 s, passed the check too): a warning
    assert main(["import", "log", str(epoch), *args, "--time-unit", "ms", "--no-check", "--out",
                 str(tmp_path / "y.csv")]) == 0
    err = capsys.readouterr().err
    assert ("column 't' read as ms starts 1970-01-20T13:46:25.678+00:00; read as s it starts "
            "2023-08-04T21:47:58+00:00: if its clock counts from 1970, declare --time-unit s") in err
    (tmp_path / "y.csv").unlink()
    zero = write_log(tmp_path / "zero.csv", t, omega, f, axes, "m/s2", "rad/s")
    assert main(["import", "log", str(zero), *args, "--out", str(tmp_path / "z.csv")]) == 2
    err = capsys.readouterr().err
    assert "looks like milliseconds" in err and "at most every 2 s: declare --time-unit s" in err
    # declared in seconds, the same clock from 0 is taken as such: the path of the clock from 1970
    assert main(["import", "log", str(zero), *args, "--time-unit", "s", "--out", str(tmp_path / "z.csv")]) == 0
    assert "warning: the log has a reading every 1 s" in capsys.readouterr().err
    np.testing.assert_array_equal(profiles.load(tmp_path / "z.csv").S_d, path.S_d)
    # ... up to a step of 2 s: a clock of milliseconds declared as seconds steps further
    ms = write_log(tmp_path / "ms.csv", t * 10.0, omega, f, axes, "m/s2", "rad/s")
    assert main(["import", "log", str(ms), *args, "--time-unit", "s", "--out", str(tmp_path / "m.csv")]) == 2
    err = capsys.readouterr().err
    assert "looks like milliseconds: 61 samples every 10 s" in err and "declare --time-unit ms" in err
    assert "declare --time-unit s" not in err
    assert sorted(p.name for p in tmp_path.iterdir()) == ["drive.csv", "ms.csv", "x.csv", "z.csv", "zero.csv"]


def phone_logs(folder, t, omega, f, axes, shift=0.004, origin=1707663721.0):
    """The motion as a phone logger writes it: the accelerometer and the gyroscope each to a file of
    its own (``time`` in ns since 1970, ``seconds_elapsed``, then ``z,y,x``), the gyroscope read
    ``shift`` s after each accelerometer reading."""
    R = convert.axes_rotation(axes)
    for name, values, lag in (("TotalAcceleration.csv", f @ R, 0.0), ("Gyroscope.csv", omega @ R, shift)):
        late = t + lag
        with open(folder / name, "w") as out:
            out.write("time,seconds_elapsed,z,y,x\n")
            for ti, v in zip(late, values if lag == 0 else np.column_stack(
                    [np.interp(late, t, values[:, i]) for i in range(3)])):
                cells = [repr(float(x)) for x in v[::-1]]  # z, y, x
                out.write(f"{round((origin + ti) * 1e9)},{float(ti)!r}," + ",".join(cells) + "\n")
    return folder / "TotalAcceleration.csv", folder / "Gyroscope.csv"


def test_rates_from_a_second_file_read_as_one_log(tmp_path, capsys):
    """A phone logger's accelerometer and gyroscope files, each at its own instants: the rates are
    interpolated onto the accelerometer's times, the same path as one log holding both. A rates file
    on another clock, one with a gap, and an --out that is a file being read are refused."""
    t, omega, f = motion()
    axes = ("right", "up", "back")
    plain = write_log(tmp_path / "plain.csv", t, omega, f, axes, "m/s2", "rad/s")
    assert main(["import", "log", str(plain), "--accel-unit", "m/s2", "--rate-unit", "rad/s", "--axes",
                 ",".join(axes), "--out", str(tmp_path / "a.csv")]) == 0
    accel, gyro = phone_logs(tmp_path, t, omega, f, axes)
    argv = ["import", "log", str(accel), "--rates-file", str(gyro), "--time", "time", "--time-unit", "ns",
            "--accel", "x,y,z", "--rates", "x,y,z", "--accel-unit", "m/s2", "--rate-unit", "rad/s", "--axes",
            ",".join(axes), "--out"]
    assert main(argv + [str(tmp_path / "b.csv")]) == 0
    a, b = profiles.load(tmp_path / "a.csv"), profiles.load(tmp_path / "b.csv")
    assert a.duration - 0.011 < b.duration < a.duration  # the span both files cover: from the second reading
    np.testing.assert_allclose(b.S_d, a.sample(b.t + 0.005), atol=1e-3)  # 1e-3: a half step's interpolation
    assert "rates x,y,z [rad/s] from Gyroscope.csv" in (tmp_path / "b.csv").read_text()
    elapsed = ["--time", "seconds_elapsed", "--time-unit", "s"]  # the logger's other clock, from its start
    assert main(argv[:5] + elapsed + argv[9:] + [str(tmp_path / "c.csv")]) == 0
    c = profiles.load(tmp_path / "c.csv")
    np.testing.assert_allclose(c.S_d, a.sample(c.t + 0.005), atol=1e-3)
    lines = gyro.read_text().splitlines()
    (tmp_path / "late.csv").write_text("\n".join([lines[0]] + [
        f"{int(line.split(',')[0]) + 10 ** 12},{line.split(',', 1)[1]}" for line in lines[1:]]) + "\n")
    (tmp_path / "gap.csv").write_text("\n".join(lines[:400] + lines[700:]) + "\n")
    for bad, words in (("late.csv", "no common second; is column 'time' the same clock in both?"),
                       ("gap.csv", "gap.csv: no rate reading for 1.51 s from 1707663722.994 s")):
        assert main(argv[:4] + [str(tmp_path / bad)] + argv[5:] + [str(tmp_path / "x.csv")]) == 2
        err = capsys.readouterr().err
        assert err.count("\n") == 1 and words in err
    os.link(accel, tmp_path / "linked.csv")  # the same file under another name
    for out in (str(gyro), str(accel), str(tmp_path / "linked.csv")):  # without --overwrite too: the refusal that holds
        assert main(argv + [out]) == 2
        assert "is the log being read" in capsys.readouterr().err
    for same in (accel, tmp_path / "linked.csv"):
        assert main(argv[:4] + [str(same)] + argv[5:] + [str(tmp_path / "x.csv")]) == 2
        assert "is the accelerometer's log itself; name the gyroscope's file" in capsys.readouterr().err
    (tmp_path / "linked.csv").unlink()
    # a gyroscope read for part of the log, or once a second: imported, with a warning
    for name, kept, words in (("part.csv", [lines[0]] + lines[1001:], "the rates of part.csv cover 1707663726.004 s "
                               "to 1707663728.995 s of the log's 1707663721 s to 1707663728.995 s: the path is cut"),
                              ("slow.csv", [lines[0]] + lines[1::200], "slow.csv has a rate reading every 1 s")):
        (tmp_path / name).write_text("\n".join(kept) + "\n")
        assert main(argv[:4] + [str(tmp_path / name)] + argv[5:9] + ["--no-check"] + argv[9:] +
                    [str(tmp_path / f"{name}.out.csv")]) == 0
        assert words in capsys.readouterr().err
    # a gyroscope on a clock in ms beside the accelerometer's in ns: the unit is declared for both
    (tmp_path / "ms.csv").write_text("\n".join([lines[0]] + [
        f"{int(line.split(',')[0]) // 10 ** 6},{line.split(',', 1)[1]}" for line in lines[1:]]) + "\n")
    assert main(argv[:4] + [str(tmp_path / "ms.csv")] + argv[5:] + [str(tmp_path / "x.csv")]) == 2
    assert "--time-unit is the unit of both files' clocks" in capsys.readouterr().err
    assert main(argv[:9] + ["--accel", "x,y,z", "--rates", "none", "--accel-unit", "m/s2", "--modulus", "--out",
                            str(tmp_path / "x.csv")]) == 2
    assert "--rates-file holds the angular rates" in capsys.readouterr().err
    assert not (tmp_path / "x.csv").exists() and lines == gyro.read_text().splitlines()


def test_an_iphones_inertial_force_is_turned_with_inertial(tmp_path, capsys):
    """Apple's Core Motion (and Sensor Logger on an iPhone by default) gives the inertial force, -1 g up
    at rest: every accelerometer sign turned, the rates as they are. No right-handed choice of axes turns
    all three, so the check's refusal names --inertial, and with it the path is the plain log's."""
    t, omega, f = motion()
    axes = ("right", "up", "back")
    plain = write_log(tmp_path / "plain.csv", t, omega, f, axes, "m/s2", "rad/s")
    iphone = write_log(tmp_path / "iphone.csv", t, omega, -f, axes, "m/s2", "rad/s")
    argv = ["--accel-unit", "m/s2", "--rate-unit", "rad/s", "--axes", ",".join(axes), "--out"]
    assert main(["import", "log", str(plain), *argv, str(tmp_path / "a.csv")]) == 0
    assert main(["import", "log", str(iphone), *argv, str(tmp_path / "b.csv")]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "-1 g, the force points down" in err and "(an iPhone's Core Motion): --inertial" in err
    assert "the default" not in err
    # a phone lying flat, read in the default axes (forward,right,down): its own axes named first
    phone = write_log(tmp_path / "phone.csv", t, omega, f, ("right", "forward", "up"), "m/s2", "rad/s")
    assert main(["import", "log", str(phone), *argv[:4], "--out", str(tmp_path / "c.csv")]) == 2
    err = capsys.readouterr().err
    assert ("(declared forward,right,down for the log's x,y,z, the default, a vehicle's body axes; a phone lying "
            "flat, screen up, its top forward: --axes right,forward,up); or, where the axes are right") in err
    assert main(["import", "log", str(iphone), "--inertial", *argv, str(tmp_path / "b.csv")]) == 0
    np.testing.assert_allclose(profiles.load(tmp_path / "b.csv").S_d, profiles.load(tmp_path / "a.csv").S_d,
                               atol=1e-12)
    assert "accel ax,ay,az [m/s2, inertial: sign turned]" in (tmp_path / "b.csv").read_text()

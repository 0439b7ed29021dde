"""`desdemona import jsbsim`: a JSBSim flight as the pilot feels it, in the cabin frame (short crops of
shipped scripts; JSBSim computes 100 s of flight in about 0.25 s)."""

import sys
import tempfile
from pathlib import Path

import numpy as np
import pytest

from desdemona import profiles
from desdemona.cli import main
from desdemona.profiles import convert, jsbsim
from desdemona.profiles.path import G

pytest.importorskip("jsbsim")


def test_body_to_cabin_is_a_proper_rotation_and_level_reads_one_g_up():
    R = convert.R_CABIN_BODY
    np.testing.assert_allclose(R @ R.T, np.eye(3))
    assert np.linalg.det(R) == pytest.approx(1.0)
    # level flight: n_z = -1 in body axes (x forward, y right, z down)
    np.testing.assert_allclose(R @ np.array([0.0, 0.0, -G]), [0.0, 0.0, G])
    # forward is cabin +y, right is cabin +x; a right turn (r > 0 in body axes) has wz < 0
    np.testing.assert_allclose(R @ [1.0, 0.0, 0.0], [0.0, 1.0, 0.0])
    np.testing.assert_allclose(R @ [0.0, 1.0, 0.0], [1.0, 0.0, 0.0])
    assert (R @ [0.0, 0.0, 0.3])[2] < 0


@pytest.fixture(scope="module")
def runway(tmp_path_factory):
    """The 737 ground test: engines, a roll to ~60 kt, hard braking (0-60 s)."""
    out = tmp_path_factory.mktemp("jsbsim") / "runway.csv"
    assert main(["import", "jsbsim", "b737_runway_new", "--end", "60", "--out", str(out)]) == 0
    return out


def test_runway_reads_back_still_then_braking(runway):
    path = profiles.load(runway)
    assert path.S_d is not None and path.t[0] == 0.0
    start = 60.0 - path.t[-1]  # the default start: after the script's on-ground trim at 0.26 s
    assert 0.2 < start < 0.3
    np.testing.assert_allclose(np.diff(path.t), 0.01, atol=1e-9)  # the default 100 Hz
    still = (path.t > 10) & (path.t < 40)  # standing on the runway, engines spooling
    np.testing.assert_allclose(path.S_d[still, 3:].mean(axis=0), [0.0, 0.0, G], atol=0.1)
    np.testing.assert_allclose(path.S_d[still, :3], 0.0, atol=1e-3)
    braking = path.t > path.t[-1] - 1.0
    assert path.S_d[braking, 4].min() < -2.0  # braking pushes the pilot forward: f_y < 0


def test_runway_carries_its_source(runway):
    text = runway.read_text()
    sources = [line for line in text.splitlines() if line.startswith("# source:")]
    assert len(sources) == 3
    joined = " ".join(sources)
    for word in ("b737_runway_new", "aircraft 737", "JSBSim 1.", "crop 0.258333-59.9983 s", "start after the "
                 "script's trim", "100 Hz"):
        assert word in joined


def test_runway_path_is_accepted_by_optimize(runway, tmp_path):
    crop = tmp_path / "braking.csv"
    assert main(["import", "jsbsim", "b737_runway_new", "--start", "54", "--end", "60", "--out", str(crop)]) == 0
    assert main(["optimize", str(crop), "--config", "yaw-track", "--h-u", "0.5", "--starts", "1",
                 "--out", str(tmp_path / "run"), "--quiet"]) == 0
    assert (tmp_path / "run" / "summary.json").exists()


def test_coordinated_right_turn(tmp_path):
    """The 737's steady turn (bank about 30 deg, turning right): more than 1 g along the occupant's
    vertical, no side force, yaw rate negative (clockwise seen from above)."""
    out = tmp_path / "turn.csv"
    assert main(["import", "jsbsim", "737_cruise_steady_turn", "--start", "10", "--end", "14", "--out", str(out)]) == 0
    S = profiles.load(out).S_d
    assert np.all(S[:, 5] > 1.1 * G)
    np.testing.assert_allclose(S[:, 3], 0.0, atol=0.05 * G)
    assert np.all(S[:, 2] < -0.01)


def test_crop_starts_at_zero_and_modulus_form(tmp_path):
    out = tmp_path / "m.csv"
    assert main(["import", "jsbsim", "737_cruise_steady_turn", "--start", "10", "--end", "12", "--rate", "50",
                 "--modulus", "--out", str(out)]) == 0
    path = profiles.load(out)
    assert path.S_d is None
    assert path.t[0] == 0.0 and path.t[-1] == pytest.approx(2.0) and len(path.t) == 101
    np.testing.assert_allclose(path.M_d, 1.151 * G, rtol=0.01)
    assert "t,M" in out.read_text().splitlines()[4]
    assert "crop 10-12 s of sim time (t = 0 here; start as given)" in out.read_text()  # an explicit start is kept


def test_runway_default_start_is_settled_on_its_gear(runway):
    """Before its on-ground trim the 737 drops onto its gear (up to 1.6 g at 0.1-0.3 s), and the sample
    before JSBSim's first step reads 0 g: the default start is after the trim, 1 g up from t = 0."""
    path = profiles.load(runway)
    np.testing.assert_allclose(path.S_d[0, 3:], [0.0, 0.0, G], atol=0.1)
    assert np.abs(path.S_d[path.t < 1.0, 3:] - [0.0, 0.0, G]).max() < 0.1


def test_no_sample_before_the_first_step():
    flight = jsbsim.fly("b737_runway_new", 0.5)
    assert flight.t[0] == pytest.approx(1 / 120, rel=1e-3)
    assert flight.trimmed is not None and not flight.trimmed[0] and flight.trimmed[-1]


def test_steady_turn_default_start_is_after_its_trim(tmp_path):
    """737_cruise_steady_turn flies at 0.65 g until its script trims it at 5.1 s."""
    out = tmp_path / "turn.csv"
    assert main(["import", "jsbsim", "737_cruise_steady_turn", "--end", "7", "--out", str(out)]) == 0
    S = profiles.load(out).S_d
    assert np.all(S[:, 5] > 1.1 * G)
    assert "crop 5.11646-" in out.read_text() and "start after the script's trim" in out.read_text()


def _flight(t, f, omega):
    return jsbsim.Flight(Path("x.xml"), "x", "0", t, omega, f, np.zeros((len(t), 2)), np.zeros(len(t), bool))


def test_default_start_without_a_trim_is_after_the_settling():
    """No trim: the first time from which the force and the rates stop jumping for SETTLE_SECONDS."""
    t = np.arange(1, 600) / 120
    f = np.tile([0.0, 0.0, -G], (len(t), 1))
    f[t < 0.3, 2] = -G * (1 + 0.6 * np.sin(40 * t[t < 0.3]))  # dropping onto the gear: jumps of ~0.2 g a step
    omega = np.zeros((len(t), 3))
    start, why = jsbsim.default_start(_flight(t, f, omega))
    assert 0.29 < start < 0.31 and "transient" in why
    f[:, 2] = -G * (1 + 0.6 * np.sin(40 * t))  # never settled within the run: the first sample
    assert jsbsim.default_start(_flight(t, f, omega))[0] == t[0]
    trimmed = _flight(t, f, omega)
    trimmed.trimmed[240:] = True
    assert jsbsim.default_start(trimmed) == (t[240], "after the script's trim")


def test_ballistic_flight_is_no_still_stretch(tmp_path):
    """A ball in free fall reads 0 g, still: not the 'kinematic acceleration' mistake of a log; the
    convention check skips a stretch far from 1 g."""
    out = tmp_path / "ball.csv"
    assert main(["import", "jsbsim", "ball", "--end", "5", "--out", str(out)]) == 0
    np.testing.assert_allclose(profiles.load(out).S_d[:, 3:], 0.0, atol=1e-6)


def test_diverged_simulation_is_named(tmp_path, capsys):
    """cannonball's force turns NaN at 217 s (after a runaway to 3.7e5 g): the simulation diverged."""
    out = tmp_path / "x.csv"
    assert main(["import", "jsbsim", "cannonball", "--start", "200", "--end", "230", "--out", str(out)]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "simulation diverged" in err and "t = 217.1" in err and "nan g" not in err
    assert not out.exists()
    t = np.arange(5.0)
    f = np.tile([0.0, 0.0, G], (5, 1))
    f[3] = np.nan
    with pytest.raises(profiles.ProfileError, match="diverged.*from t = 3.00 s"):
        convert.check_no_crash(t, f, "x")
    f[1] = [0.0, 0.0, 50 * G]  # a crash 2 s before: a crash, the divergence said too
    with pytest.raises(profiles.ProfileError, match="reaches 50 g at t = 1.00 s.*diverges later"):
        convert.check_no_crash(t, f, "x")


def test_jsbsim_printing_is_silenced(tmp_path, capfd):
    """The script's notify events print on JSBSim's C++ stdout: none of it reaches the command's."""
    out = tmp_path / "quiet.csv"
    assert main(["import", "jsbsim", "737_cruise_steady_turn", "--start", "5", "--end", "7", "--out", str(out)]) == 0
    captured = capfd.readouterr()
    assert captured.out.splitlines() == [captured.out.splitlines()[0]] and str(out) in captured.out
    assert "JSBSim" not in captured.out and captured.err == ""


def test_own_script_with_initial_conditions_beside_it(tmp_path):
    """A user's script file, its aircraft started in the air from an initialisation file next to it."""
    (tmp_path / "air.xml").write_text(
        '<?xml version="1.0"?>\n<initialize name="air">\n  <vt unit="KTS"> 96.0 </vt>\n'
        '  <latitude unit="DEG"> 47.0 </latitude>\n  <longitude unit="DEG"> 122.0 </longitude>\n'
        '  <psi unit="DEG"> 0.0 </psi>\n  <altitude unit="FT"> 4000.0 </altitude>\n'
        '  <gamma unit="DEG"> 0.0 </gamma>\n  <running> -1 </running>\n</initialize>\n')
    (tmp_path / "level.xml").write_text(
        '<?xml version="1.0"?>\n<runscript name="level">\n  <use aircraft="c172x" initialize="air"/>\n'
        '  <run start="0.0" end="8" dt="0.00833333">\n    <event name="trim">\n'
        '      <condition> simulation/sim-time-sec gt 0.5 </condition>\n'
        '      <set name="simulation/do_simple_trim" value="1"/>\n      <notify/>\n    </event>\n'
        '  </run>\n</runscript>\n')
    out = tmp_path / "level.csv"
    assert main(["import", "jsbsim", str(tmp_path / "level.xml"), "--start", "4", "--out", str(out)]) == 0
    S = profiles.load(out).S_d
    np.testing.assert_allclose(S[:, 3:].mean(axis=0), [0.0, 0.0, G], atol=0.3)  # flying level, in the air


def test_unknown_script_lists_shipped_ones(tmp_path, capsys):
    out = tmp_path / "x.csv"
    assert main(["import", "jsbsim", "no_such_script", "--out", str(out)]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "no_such_script" in err
    assert sum(name in err for name in jsbsim.shipped_scripts()) >= 3
    assert "--list" in err and not out.exists()


def test_list_shipped_scripts(capsys):
    assert main(["import", "jsbsim", "--list"]) == 0
    names = capsys.readouterr().out.split()
    assert "b737_runway_new" in names and "737_cruise_steady_turn" in names


def test_crash_is_refused_naming_time_and_value(tmp_path, capsys):
    """f16_test spins into hundreds of g after about 2 minutes."""
    out = tmp_path / "crash.csv"
    assert main(["import", "jsbsim", "f16_test", "--start", "110", "--end", "135", "--out", str(out)]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and " g at t = 1" in err and "20 g" in err
    assert not out.exists() and list(tmp_path.iterdir()) == []


def test_existing_output_is_kept(tmp_path, capsys):
    out = tmp_path / "x.csv"
    out.write_text("mine\n")
    assert main(["import", "jsbsim", "737_cruise_steady_turn", "--end", "3", "--out", str(out)]) == 2
    assert "already exists" in capsys.readouterr().err and out.read_text() == "mine\n"
    assert main(["import", "jsbsim", "737_cruise_steady_turn", "--start", "10", "--end", "11", "--out", str(out),
                 "--overwrite"]) == 0
    assert profiles.load(out).duration == pytest.approx(1.0)


def test_without_jsbsim_says_how_to_get_it(tmp_path, capsys, monkeypatch):
    monkeypatch.setitem(sys.modules, "jsbsim", None)  # import jsbsim raises ImportError
    assert main(["import", "jsbsim", "b737_runway_new", "--out", str(tmp_path / "x.csv")]) == 2
    err = capsys.readouterr().err
    assert "pip install 'desdemona[jsbsim]'" in err and not (tmp_path / "x.csv").exists()


def test_script_output_files_are_not_written(tmp_path, monkeypatch):
    """737_cruise asks for an <output> CSV file: JSBSim would write it into its own folder (or here)."""
    import jsbsim as package

    root = Path(package.get_default_root_dir())
    before = set(root.iterdir())
    monkeypatch.chdir(tmp_path)
    assert main(["import", "jsbsim", "737_cruise", "--start", "1", "--end", "2", "--out", "c.csv"]) == 0
    assert set(root.iterdir()) == before and [p.name for p in tmp_path.iterdir()] == ["c.csv"]


def test_a_script_that_runs_again_gives_its_first_run(tmp_path, capsys):
    """c172_elevation_test sets its clock back to 0 after 300 s to take off again from another
    elevation (a series of runs): its first run is the path, and the warning says so (it was refused
    with 'nothing between 0.31 s and 0 s', the crop read on a clock gone back)."""
    out = tmp_path / "elevation.csv"
    assert main(["import", "jsbsim", "c172_elevation_test", "--out", str(out)]) == 0
    err = capsys.readouterr().err
    assert "warning: the script sets its clock back at 300 s of sim time to run again" in err
    path = profiles.load(out)
    assert path.duration == pytest.approx(299.69, abs=0.01) and np.all(np.diff(path.t) > 0)
    assert "# warning: the script sets its clock back" in out.read_text()


def test_an_end_past_the_scripts_end_is_told(tmp_path, capsys):
    """``--end`` beyond the script's last step (c1723 flies 200 s) gives the whole flight, and says so
    on stderr and in the file instead of passing it over."""
    out = tmp_path / "c1723.csv"
    assert main(["import", "jsbsim", "c1723", "--end", "60000", "--out", str(out)]) == 0
    assert "warning: --end 60000 s is past the script's end at 200 s of sim time" in capsys.readouterr().err
    assert "# warning: --end 60000 s" in out.read_text()
    assert profiles.load(out).duration == pytest.approx(199.69, abs=0.01)


def test_a_flight_in_real_time_ends_where_its_script_runs_again():
    """The real-time host's flight (``host jsbsim``) of the same script stops at the clock's reset too:
    its samples stay in time order, as the stream's interpolation needs."""
    from desdemona.service import hosts

    lib = jsbsim._jsbsim()
    path, root, _, init = jsbsim.script_setup("c172_elevation_test")
    with tempfile.TemporaryDirectory() as tmp, jsbsim._quiet(str(Path(tmp) / "jsbsim.log")):
        flight = hosts._Flight(hosts._open(lib, root, path, init, tmp), lib, None)
        flight.advance(400.0)
    assert flight.ended.startswith("the script's clock going back at 300 s to run again")
    assert np.all(np.diff(flight.t) > 0) and flight.t[-1] == pytest.approx(300.0, abs=0.01)

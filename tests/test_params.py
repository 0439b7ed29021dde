"""Parameter files: defaults, overrides, units, and one clear error per kind of mistake."""

import math

import numpy as np
import pytest

from desdemona import ParameterError, default_params, load_params, thesis_toy_params


def write(tmp_path, text):
    path = tmp_path / "params.toml"
    path.write_text(text)
    return path


def test_defaults_match_the_documented_table():
    p = default_params()
    deg = math.pi / 180
    np.testing.assert_allclose(p.velocity_max, [155.4 * deg, 3.2, 2.2, 180 * deg, 180 * deg, 180 * deg])
    np.testing.assert_allclose(p.acceleration_max, [45 * deg, 5, 5, 90 * deg, 90 * deg, 90 * deg])
    np.testing.assert_allclose(p.effort_max, [300e3, 200e3, 70e3, 20e3, 15e3, 10e3])
    np.testing.assert_allclose(p.power_max, [600e3, 300e3, 150e3, 40e3, 30e3, 20e3])
    np.testing.assert_array_equal(p.position_min, [-np.inf, -4, -1, -np.inf, -np.inf, -np.inf])
    assert [b.mass for b in p.bodies[1:]] == [2000, 1500, 800, 500, 1200]
    assert p.bodies[0].inertia[2][2] == 40000
    assert p.bodies[5].com == (0.0, 0.0, -0.2)


def test_thesis_toy_set():
    p = thesis_toy_params()
    assert (p.bodies[0].mass, p.bodies[0].inertia[2][2], p.bodies[1].mass, p.bodies[1].inertia[2][2]) == (1, 1, 2, 2)
    assert all(b.mass == 0 for b in p.bodies[2:])


def test_user_file_overrides_a_subset_in_its_own_units(tmp_path):
    path = write(tmp_path, """
        [joints.yaw]
        velocity_rad_s = 2.0
        [joints.track]
        position_mm = [-3500, 3500]
        force_N = 150000
        [bodies.cabin]
        mass_t = 1.4
        inertia_kg_m2 = [[600, 10, 0], [10, 500, 0], [0, 0, 600]]
    """)
    p = load_params(path)
    d = default_params()
    assert p.joints[0].velocity == 2.0
    assert p.joints[0].acceleration == d.joints[0].acceleration
    assert p.joints[1].position == (-3.5, 3.5)
    assert p.joints[1].effort == 150000.0
    assert p.bodies[5].mass == 1400.0
    assert p.bodies[5].inertia[0][1] == 10.0
    assert p.bodies[5].com == d.bodies[5].com


def test_base_key_selects_builtin_set(tmp_path):
    assert load_params(write(tmp_path, 'base = "thesis-toy"')).bodies[1].mass == 2.0


def test_simplified_moves_centres_of_mass_to_origins():
    p = default_params().simplified()
    assert all(b.com == (0.0, 0.0, 0.0) for b in p.bodies)
    assert p.bodies[5].mass == 1200


@pytest.mark.parametrize("text, key, fragment", [
    ("[joints.yaw]\nvelocty_deg_s = 100", "joints.yaw.velocty_deg_s", "unknown key"),
    ("[joints.yawn]\nvelocity_deg_s = 100", "joints.yawn", "unknown name"),
    ("gravty_m_s2 = 9.8", "gravty_m_s2", "unknown key"),
    ("[joints.track]\nvelocity = 3.0", "joints.track.velocity", "no unit"),
    ("[joints.track]\nvelocity_deg_s = 3.0", "joints.track.velocity_deg_s", "not a unit of linear velocity"),
    ("[joints.yaw]\nforce_kN = 3.0", "joints.yaw.force_kN", "revolute joint has a torque limit"),
    ("[joints.yaw]\nvelocity_deg_s = 'fast'", "joints.yaw.velocity_deg_s", "expected a number"),
    ("[joints.yaw]\nvelocity_deg_s = -10", "joints.yaw.velocity_deg_s", "must be > 0"),
    ("[joints.track]\nposition_m = [4, -4]", "joints.track.position_m", "less than max"),
    ("[joints.track]\nposition_m = [4]", "joints.track.position_m", "shape"),
    ("[bodies.cabin]\nmass_kg = -1200", "bodies.cabin.mass_kg", "must be >= 0"),
    ("[bodies.cabin]\ninertia_kg_m2 = [600, -500, 600]", "bodies.cabin.inertia_kg_m2", "positive semi-definite"),
    ("[bodies.cabin]\ninertia_kg_m2 = [100, 100, 600]", "bodies.cabin.inertia_kg_m2", "not the inertia of a rigid body"),
    ("[bodies.cabin]\ninertia_kg_m2 = [[1, 2, 0], [0, 1, 0], [0, 0, 1]]", "bodies.cabin.inertia_kg_m2", "not symmetric"),
    ("gravity_m_s2 = 981", "gravity_m_s2", "[0, 30]"),
    ("head_offset_m = [0, 0, 50]", "head_offset_m", "[-3, 3]"),
    ("base = 'mars'", "base", "unknown parameter set"),
    ("[bodies.cabin]\ncom_m = [0, 0, nan]", "bodies.cabin.com_m", "not a finite number"),
])
def test_bad_file_gives_one_error_naming_the_key(tmp_path, text, key, fragment):
    path = write(tmp_path, text)
    with pytest.raises(ParameterError) as info:
        load_params(path)
    message = str(info.value)
    assert str(path) in message and key in message and fragment in message


def test_unreadable_files(tmp_path):
    with pytest.raises(ParameterError, match="not found"):
        load_params(tmp_path / "missing.toml")
    with pytest.raises(ParameterError, match="not valid TOML"):
        load_params(write(tmp_path, "[joints.yaw\nvelocity_deg_s = 1"))


def test_to_dict_is_plain_json(tmp_path):
    import json

    data = json.loads(json.dumps(default_params().to_dict()))
    assert data["joints"]["track"]["position"] == [-4.0, 4.0]
    assert data["joints"]["yaw"]["position"] is None

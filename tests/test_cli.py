"""The command line: exit codes, messages and the model summary."""

from desdemona.cli import main


def test_model_summary(capsys):
    assert main(["model", "--config", "full"]) == 0
    out = capsys.readouterr().out
    assert "configuration 'full'" in out
    assert "q6 cabin" in out and "f_cabin" in out and "inertia eigenvalues" in out


def test_model_toy_yaw_track(capsys):
    assert main(["model", "--config", "yaw-track", "--base", "thesis-toy"]) == 0
    out = capsys.readouterr().out
    assert "'thesis-toy'" in out and "held at" in out


def test_unknown_configuration_lists_valid_ones(capsys):
    assert main(["model", "--config", "nope"]) == 2
    err = capsys.readouterr().err
    assert "unknown configuration 'nope'" in err
    for name in ("dfs", "yaw-track", "yaw-track-cabin", "full"):
        assert name in err


def test_bad_parameter_file(tmp_path, capsys):
    path = tmp_path / "p.toml"
    path.write_text("[joints.track]\nvelocity = 3\n")
    assert main(["model", "--params", str(path)]) == 2
    assert "joints.track.velocity" in capsys.readouterr().err

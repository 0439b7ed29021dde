"""Configurations are data: outside the machine's folder code asks a configuration what it can do,
never which joint indices it frees or what it is called (STYLE.md, point 10).

The scan reads the code (its syntax tree, so messages, help texts and docstrings may name
configurations) of every module outside ``desdemona/machine`` and fails on:

- reading a configuration's ``free`` or ``fixed`` (``1 in config.free``, ``free.index(4)``,
  ``config.free[:1] != (0,)``, ``config.fixed[1]``): where a joint sits among the free ones, or
  whether it moves, is :class:`~desdemona.machine.configs.Configuration`'s to say (``config.track``,
  ``config.moves_track``, ``config.held``);
- a comparison with a configuration's name, as a literal (``name in ("dfs", "dfs-yaw")``) or as
  ``config.name`` / ``summary["configuration"]["name"]``.
"""

from __future__ import annotations

import ast
import re
from pathlib import Path

from desdemona.machine.configs import CONFIGURATIONS

PACKAGE = Path(__file__).resolve().parents[1] / "src" / "desdemona"
NAMED = re.compile(r"config\w*\.name\b|\[\s*['\"]configuration['\"]\s*\]\s*\[\s*['\"]name['\"]\s*\]")


def _names_a_configuration(node: ast.expr, source: str) -> bool:
    if isinstance(node, ast.Constant):
        return node.value in CONFIGURATIONS
    if isinstance(node, (ast.Tuple, ast.List, ast.Set)):
        return any(_names_a_configuration(e, source) for e in node.elts)
    return bool(NAMED.search(ast.get_source_segment(source, node) or ""))


def index_tests(package: Path) -> list[str]:
    """Each place outside ``package/machine`` that reads a configuration's joint indices or held
    positions, or compares a configuration's name: "file:line: code"."""
    found = set()
    for file in sorted(package.rglob("*.py")):
        if file.relative_to(package).parts[0] == "machine":
            continue
        source = file.read_text()
        for node in ast.walk(ast.parse(source)):
            if isinstance(node, ast.Attribute) and node.attr in ("free", "fixed"):
                what = node
            elif isinstance(node, ast.Compare) and any(
                    _names_a_configuration(side, source) for side in (node.left, *node.comparators)):
                what = node
            else:
                continue
            found.add((str(file.relative_to(package)), what.lineno, ast.get_source_segment(source, what)))
    return [f"{file}:{line}: {code}" for file, line, code in sorted(found)]


def test_no_joint_index_or_configuration_name_outside_the_machine():
    found = index_tests(PACKAGE)
    assert not found, ("code outside desdemona/machine tests a joint index or a configuration's name; "
                       "ask the Configuration what it can do instead:\n" + "\n".join(found))


def test_the_scan_finds_what_it_forbids(tmp_path):
    """The scan fails on each kind of test it forbids, and passes the same words in strings."""
    (tmp_path / "machine").mkdir()
    (tmp_path / "machine" / "configs.py").write_text("k = config.free.index(1)\n")
    (tmp_path / "bad.py").write_text(
        "def f(config, model, summary, free):\n"
        "    a = 1 in config.free\n"
        "    b = model.config.fixed[1]\n"
        "    c = summary['configuration']['name'] in ('dfs', 'dfs-yaw')\n"
        "    d = model.config.name == 'full'\n"
        "    e = config.name != other\n"
        "    return a, b, c, d, e\n")
    (tmp_path / "good.py").write_text(
        '"""On ``dfs``: config.free[0] == 0."""\n'
        "def g(config):\n"
        "    message = f'not {config.name}; try dfs or full'\n"
        "    return config.track if config.moves_track else message\n")
    found = index_tests(tmp_path)
    assert [line.split(":")[:2] for line in found] == [["bad.py", str(k)] for k in (2, 3, 4, 5, 6)]


#: A configuration declared in machine/configs.py alone (its one entry of CONFIGURATIONS), which no
#: other module names: the commands run it with what it says it can do.
NEW = "yaw-heave-cabin"


def test_a_new_configuration_is_one_declaration(tmp_path):
    """``yaw-heave-cabin`` (yaw q1, heave q3, cabin yaw q5; the track held at -4 m) is declared in
    machine/configs.py and named nowhere else in the package, and ``optimize``, ``online``, ``view`` and
    ``batch`` run it: exit 0, their files written, the independent check passed (every limit kept
    on a grid finer than the solver's). Bounded: the 5 s cosine, 50 intervals, one start; on-line a
    1 s horizon at 10 Hz."""
    import csv
    import json

    from desdemona.cli import main

    named = [str(f.relative_to(PACKAGE)) for f in PACKAGE.rglob("*") if f.is_file()
             and f.suffix in (".py", ".toml", ".js", ".html") and NEW in f.read_text()]
    assert named == ["machine/configs.py"]
    config = CONFIGURATIONS[NEW]
    assert (config.turns_arm, config.moves_track, config.moves_heave, config.tilts_cabin) == (True, False, True, False)
    assert config.turns_cabin_only and config.held == {1: -4.0, 3: 0.0, 5: 0.0}

    quick = ["cosine", "--config", NEW, "--no-view"]
    assert main(["optimize", *quick, "--starts", "1", "--h-u", "0.1", "--out", str(tmp_path / "off")]) == 0
    assert main(["online", *quick, "--horizon", "1", "--step", "0.1", "--out", str(tmp_path / "on")]) == 0
    for folder in ("off", "on"):
        summary = json.loads((tmp_path / folder / "summary.json").read_text())
        assert summary["configuration"]["name"] == NEW
        assert summary["configuration"]["free_joints"] == ["yaw", "heave", "inner_gimbal"]
        assert summary["metrics"]["limits_kept"] is True
        assert (tmp_path / folder / "trajectory.csv").stat().st_size > 0
        assert (tmp_path / folder / "joints.png").stat().st_size > 0
    assert (tmp_path / "on" / "classical.csv").stat().st_size > 0  # the washout ran beside the MPC
    assert main(["view", str(tmp_path / "on")]) == 0
    assert "<html" in (tmp_path / "on" / "view.html").read_text()[:2000].lower()

    out = tmp_path / "batch"
    assert main(["batch", "cosine", "--configs", NEW, "--starts", "1", "--h-u", "0.1", "--processes", "1",
                 "--no-view", "--out", str(out)]) == 0
    with open(out / "batch.csv", newline="") as fh:
        rows = list(csv.DictReader(fh))
    assert [(r["configuration"], r["status"]) for r in rows] == [(NEW, "ok")]
    job = json.loads((out / f"cosine--{NEW}" / "summary.json").read_text())
    assert job["metrics"]["limits_kept"] is True and float(rows[0]["worst_use"]) <= 1.0 + 1e-6


def test_a_held_position_is_moved_by_the_configuration_and_only_a_held_one():
    import pytest

    config = CONFIGURATIONS["dfs"]
    track = next(iter(config.held))
    moved = config.held_moved(track, 0.25)
    assert moved.held[track] == config.held[track] + 0.25
    assert {j: p for j, p in moved.held.items() if j != track} == {j: p for j, p in config.held.items() if j != track}
    with pytest.raises(ValueError, match="is not held"):
        config.held_moved(config.free[0], 0.1)

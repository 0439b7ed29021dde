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

"""The package's layout: modules in layers, each importing only from its own layer and those below;
no module over 600 lines and no function over 80 (the argparse table aside), so that one idea stays
in one place and reads on a screen or two."""

import ast
from pathlib import Path

import desdemona

PACKAGE = Path(desdemona.__file__).parent

#: The layers, lowest first: a module may import from its own layer and those below, never above.
LAYERS = (
    ("foundations", {"_version", "_casadi", "allocator", "guard", "files", "params", "perception", "plan"}),
    ("desired paths", {"profiles"}),
    ("the machine", {"kinematics", "dynamics", "configs", "model", "compiled", "blasfeo"}),
    ("the cueing problem, its baselines and its check",
     {"problem", "assembly", "transcription", "realtime", "sizing", "classical", "washout", "thesis", "predictors", "simulate", "metrics"}),
    ("solvers and sessions", {"offline", "windows", "mpc", "online", "session"}),
    ("results", {"figures", "report", "view", "compare"}),
    ("commands and the real-time service", {"batch", "cli", "service", "__main__", "__init__"}),
)
LAYER = {module: k for k, (_, modules) in enumerate(LAYERS) for module in modules}
LONG_FUNCTIONS = {"build_parser"}  # the argparse table


def _modules():
    for path in sorted(PACKAGE.rglob("*.py")):
        parts = path.relative_to(PACKAGE).with_suffix("").parts
        yield parts[0], path  # a subpackage's files count as the subpackage


def _imports(tree) -> set[str]:
    """The package's top-level modules a module imports (at its top or inside a function)."""
    found = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.ImportFrom) and node.level == 0 and node.module:
            parts = node.module.split(".")
            if parts[0] == "desdemona":
                found.update(parts[1:2] or [a.name for a in node.names])
        elif isinstance(node, ast.Import):
            found.update(a.name.split(".")[1] for a in node.names if a.name.startswith("desdemona."))
    return found


def test_every_module_has_a_layer():
    assert {module for module, _ in _modules()} == set(LAYER)


def test_no_module_imports_from_a_layer_above_its_own():
    upward = []
    for module, path in _modules():
        for target in _imports(ast.parse(path.read_text())) - {module}:
            if target in LAYER and LAYER[target] > LAYER[module]:
                upward.append(f"{path.relative_to(PACKAGE)} imports {target} ({LAYERS[LAYER[target]][0]})")
    assert not upward, "\n".join(upward)


def test_modules_and_functions_stay_short():
    long = []
    for _, path in _modules():
        text = path.read_text()
        if text.count("\n") > 600:
            long.append(f"{path.relative_to(PACKAGE)}: {text.count(chr(10))} lines")
        for node in ast.walk(ast.parse(text)):
            if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef)) and node.name not in LONG_FUNCTIONS:
                if node.end_lineno - node.lineno + 1 > 80:
                    long.append(f"{path.relative_to(PACKAGE)}:{node.lineno} {node.name}: "
                                f"{node.end_lineno - node.lineno + 1} lines")
    assert not long, "\n".join(long)


def test_ci_runs_the_readme_s_test_command():
    """``.ci/run`` runs the very command the README gives for the tests, so that what CI passes is
    what a newcomer runs."""
    root = Path(__file__).resolve().parents[1]
    command = (root / "README.md").read_text().split("Install the test extras")[1].split("```")[1].strip()
    assert command.startswith("pip install '.[test]' && pytest")
    assert command in (root / ".ci" / "run").read_text().splitlines()

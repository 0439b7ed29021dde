"""The package's layout: the folders are the layers, each module importing only from its own folder
and the folders below, with no import cycle; no module over 600 lines and no function over 80 (the
argparse table aside), so that one idea stays in one place and reads on a screen or two."""

import ast
from pathlib import Path

import desdemona

PACKAGE = Path(desdemona.__file__).parent

#: The folders of the package, lowest first: a module may import from its own folder and those below.
#: Each folder's ``__init__`` says what it holds; the package's docstring draws the whole.
LAYERS = ("support", "occupant", "profiles", "machine", "check", "baselines", "cueing", "control", "results",
          "runs", "service", "cli")
#: The modules of the top: the version, the public API (re-exported names, loaded lazily) and ``-m``.
TOP = {"_version", "__init__", "__main__"}
LONG_FUNCTIONS = {"build_parser"}  # the argparse table


def _modules():
    """(dotted name, path) of every module of the package."""
    for path in sorted(p for p in PACKAGE.rglob("*.py") if "data" not in p.relative_to(PACKAGE).parts):
        parts = path.relative_to(PACKAGE).with_suffix("").parts
        yield ".".join(parts), path


def _folder(module: str) -> str:
    return module.split(".")[0]


def _imports(module: str, tree, known: set[str]) -> set[str]:
    """The package's modules ``module`` imports (at its top or inside a function), dotted below
    ``desdemona``; ``from desdemona.x import y`` counts as ``x.y`` where that is a module (in ``known``),
    else ``x``."""
    found = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.ImportFrom) and node.module:
            if node.level:
                raise AssertionError(f"{module}: a relative import (from {'.' * node.level}{node.module})")
            if node.module == "desdemona" or node.module.startswith("desdemona."):
                base = node.module.split(".")[1:]
                for alias in node.names:
                    name = ".".join([*base, alias.name])
                    found.add(name if name in known or f"{name}.__init__" in known else ".".join(base) or "__init__")
        elif isinstance(node, ast.Import):
            found.update(a.name.split(".", 1)[1] for a in node.names if a.name.startswith("desdemona."))
    return found - {module}


def _graph() -> dict[str, set[str]]:
    modules = dict(_modules())
    return {module: _imports(module, ast.parse(path.read_text()), set(modules)) for module, path in modules.items()}


def test_every_module_is_in_a_layer_folder():
    folders = {p.name for p in PACKAGE.iterdir() if p.is_dir() and (p / "__init__.py").exists()}
    assert folders == set(LAYERS)
    loose = {m for m, _ in _modules() if "." not in m} - TOP
    assert not loose, f"modules outside the layer folders: {sorted(loose)}"


def test_no_module_imports_from_a_layer_above_its_own():
    rank = {name: k for k, name in enumerate(LAYERS)}
    upward = []
    for module, targets in _graph().items():
        if module in TOP:
            continue
        for target in targets:
            if target == "_version":  # below everything: it imports nothing
                continue
            if target in TOP or rank[_folder(target)] > rank[_folder(module)]:
                upward.append(f"{module} imports {target}")
    assert not upward, "\n".join(sorted(upward))


def test_no_import_cycle():
    """Not even through an import inside a function or for type checking only: a cycle is two modules
    that cannot be understood apart. A package's ``__init__`` that re-exports is left out (it is the
    names' index, not a concept)."""
    graph = {m: {t for t in ts if not t.endswith("__init__") and t not in LAYERS} for m, ts in _graph().items()}
    state, cycles = {}, []

    def visit(node, stack):
        state[node] = "open"
        for target in sorted(graph.get(node, ())):
            if state.get(target) == "open":
                cycles.append(" -> ".join([*stack[stack.index(target):], target]))
            elif target not in state:
                visit(target, [*stack, target])
        state[node] = "done"

    for module in sorted(graph):
        if module not in state:
            visit(module, [module])
    assert not cycles, "\n".join(cycles)


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


def test_every_public_name_resolves_from_the_top():
    """What the README documents as the Python API, and what tools that read result folders import
    (``from desdemona import perception, metrics``), loads from ``desdemona`` whatever the folders."""
    for name in desdemona.__all__:
        assert getattr(desdemona, name) is not None, name
    from desdemona import metrics, perception  # noqa: F401  (modules, not only names)

    assert perception.THRESHOLDS is not None and callable(metrics.of_trajectory)

"""The documentation a user follows: every command of the README's table runs, and every place the
code or the README points into ``docs/`` exists, down to the anchor, so that a page renamed or a
section's anchor dropped fails here rather than leaving a reader at a dead end."""

import re
import shlex
from pathlib import Path

import pytest

from desdemona.cli import main
from desdemona.cli.options import build_parser

ROOT = Path(__file__).resolve().parents[1]
DOCS = ROOT / "docs"
README = ROOT / "README.md"
#: A pointer into the docs: a page and, after ``#``, an anchor the page declares as ``{#anchor}``.
CITATION = re.compile(r"docs/((?:[\w-]+/)*[\w.-]+\.md)(?:#([\w-]+))?")
#: The README's commands that run for real here, in a second or two each; the others are parsed whole
#: (every option and choice as the command reads it) and show their ``--help``, as a real run of them
#: takes minutes, a server or a JSBSim flight.
RUN = {"profiles", "model"}
GROUPS = {"import", "host"}  # commands whose second word names the command


def _readme_commands() -> list[str]:
    return re.findall(r"^\| `(desdemona [^`]+)` \|", README.read_text(), re.M)


def _exit_code(argv: list[str]) -> int:
    try:
        return main(argv)
    except SystemExit as exc:  # argparse's --help and its refusals
        return exc.code


def _commands(parser, prefix=()) -> set[tuple[str, ...]]:
    """Every command the parser knows, as its words: ``("optimize",)``, ``("import", "log")``."""
    found = set()
    for action in parser._actions:
        if isinstance(action.choices, dict):
            for name, sub in action.choices.items():
                inner = _commands(sub, (*prefix, name))
                found |= inner or {(*prefix, name)}
    return found


def test_the_readme_is_short_and_it_and_the_reference_name_every_command():
    assert len(README.read_text().splitlines()) <= 250
    named = set()
    for command in _readme_commands():
        argv = shlex.split(command)[1:]
        named.add(tuple(argv[:2] if argv[0] in GROUPS else argv[:1]))
    assert named == _commands(build_parser())
    reference = (DOCS / "reference" / "commands.md").read_text()
    assert {tuple(words.split()) for words in re.findall(r"^<!-- help: ([\w ]+) -->$", reference, re.M)} == named


@pytest.mark.parametrize("command", _readme_commands())
def test_every_command_of_the_readme_runs(command, tmp_path, monkeypatch, capsys):
    argv = shlex.split(command)[1:]
    monkeypatch.chdir(tmp_path)  # what a command writes stays in the test's folder
    if argv[0] in RUN:
        assert _exit_code(argv) == 0, capsys.readouterr().err
    else:
        build_parser().parse_args(argv)  # exits 2, naming the option, where the README's line is wrong
        words = argv[:2] if argv[0] in GROUPS else argv[:1]
        assert _exit_code([*words, "--help"]) == 0
    assert capsys.readouterr().out.strip()


def test_every_command_line_the_docs_show_is_one_the_command_takes():
    """The lines a reader copies from the README and the guide (code blocks, comments after ``#`` left
    out) parse as the command parses them: a renamed option or choice fails here. The measurements'
    pages keep the commands as they were run."""
    parser, lines = build_parser(), []
    for page in [README, *sorted(DOCS.rglob("*.md"))]:
        if DOCS / "benchmarks" not in page.parents:
            for block in re.findall(r"```[a-z]*\n(.*?)```", page.read_text(), re.S):
                lines += [line.split(" #")[0] for line in block.splitlines() if line.startswith("desdemona ")]
    assert len(lines) > 20
    for line in lines:
        parser.parse_args(shlex.split(line)[1:])  # exits 2, naming the option, where a line is wrong


def _citations():
    """(file, line number, page, anchor) of every pointer into the docs in the code, the tests, the
    benchmarks and the README."""
    files = [*sorted((ROOT / "src").rglob("*.py")), *sorted((ROOT / "tests").glob("*.py")),
             *sorted((ROOT / "benchmarks").glob("*.py")), README]
    for path in files:
        for number, line in enumerate(path.read_text().splitlines(), 1):
            for match in CITATION.finditer(line):
                yield path.relative_to(ROOT), number, match.group(1), match.group(2)


def test_every_pointer_into_the_docs_resolves_to_a_page_and_its_anchor():
    cited = list(_citations())
    assert len(cited) > 40  # the measurements behind the defaults are cited where the defaults are
    broken = []
    for path, number, page, anchor in cited:
        target = DOCS / page
        if not target.is_file():
            broken.append(f"{path}:{number}: docs/{page} does not exist")
        elif anchor and f"{{#{anchor}}}" not in target.read_text():
            broken.append(f"{path}:{number}: docs/{page} declares no anchor {{#{anchor}}}")
    assert not broken, "\n".join(broken)


def test_the_code_cites_a_measurement_by_its_page_not_its_title():
    """A quoted title breaks silently when the section is renamed; the page's path does not."""
    titles = [re.match(r"# (.*?) \{#", page.read_text()).group(1) for page in sorted((DOCS / "benchmarks").glob("*.md"))
              if page.name != "index.md"]
    quoted = []
    for path in [*sorted((ROOT / "src").rglob("*.py")), *sorted((ROOT / "tests").glob("*.py"))]:
        text = re.sub(r"\s*\n\s*(?:#:?\s*)?", " ", path.read_text())  # a title may be broken over lines
        quoted += [f"{path.relative_to(ROOT)}: {q}{title}{q}" for title in titles for q in "\"'"
                   if f"{q}{title}{q}" in text]
    assert not quoted, "\n".join(quoted)

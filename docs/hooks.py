"""What the site needs beyond Markdown, run by ``mkdocs build`` (``mkdocs.yml``: ``hooks``, and the
Python handler's ``extensions``).

- ``<!-- readme -->`` (the home page) becomes the README, its links into ``docs/`` made relative to
  the site, so the quick start and its measured times are written once.
- ``<!-- configurations -->`` becomes the table of the configurations the package declares.
- Each ``<!-- help: COMMAND -->`` line of a page becomes that command's ``--help``, as the installed
  ``desdemona`` prints it, so the reference of the commands cannot drift from the options.
- The docstrings cross-reference in Sphinx's roles (``:func:`~desdemona.profiles.load```); the site
  shows each as code, the name as Sphinx would show it (``load`` with the ``~``). A docstring's
  pointer into the docs (``docs/benchmarks/placed-start.md``) becomes a link to that page (the API
  pages are all in ``docs/api/``).
"""

from __future__ import annotations

import os
import re
from pathlib import Path

import griffe

ROOT = Path(__file__).resolve().parents[1]
HELP = re.compile(r"^<!-- help: ([\w ]*?) -->$", re.M)
CITATION = re.compile(r"(?<![\w/`])docs/((?:[\w-]+/)*[\w.-]+\.md(?:#[\w-]+)?)")
ROLE = re.compile(r":(?:py:)?(?:func|meth|class|mod|data|attr|exc|obj|const):`(~?)([^`]+)`")


def _help(command: str) -> str:
    """The ``--help`` of ``desdemona COMMAND`` (sub-commands separated by spaces), 100 columns wide."""
    os.environ["COLUMNS"] = "100"  # argparse wraps its help to $COLUMNS
    from desdemona.cli.options import build_parser

    parser = build_parser()
    for word in command.split():
        action = next(a for a in parser._actions if a.choices and word in a.choices)
        parser = action.choices[word]
    return f"```text\n{parser.format_help().rstrip()}\n```"


def _readme() -> str:
    """The README without its title (the page has its own), links into ``docs/`` relative to the site."""
    text = (ROOT / "README.md").read_text().split("\n", 1)[1]
    return text.replace("](docs/", "](")


def _configurations() -> str:
    from desdemona.machine.configs import CONFIGURATIONS

    rows = []
    for name, config in CONFIGURATIONS.items():
        joints = ", ".join(f"`{j}`" for j in config.joint_names)
        rows.append(f"| `{name}` | {joints} | {config.description.replace('|', '&#124;')} |")
    return "\n".join(["| configuration | free joints | what it is |", "| --- | --- | --- |", *rows])


def on_page_markdown(markdown: str, **kwargs) -> str:
    markdown = markdown.replace("<!-- readme -->", _readme())
    if "<!-- configurations -->" in markdown:
        markdown = markdown.replace("<!-- configurations -->", _configurations())
    return HELP.sub(lambda m: _help(m.group(1)), markdown)


def plain_roles(text: str) -> str:
    """Sphinx's roles as Markdown code: ``:func:`~a.b``` -> ```b```, ``:mod:`a.b``` -> ```a.b```."""
    def code(m):
        name = m.group(2).lstrip(".")
        return f"`{name.rsplit('.', 1)[-1] if m.group(1) else name}`"
    return ROLE.sub(code, text)


class SphinxRoles(griffe.Extension):
    """Rewrites each docstring's Sphinx roles before the handler renders it."""

    def on_instance(self, *, obj, **kwargs) -> None:
        if obj.docstring is not None:
            text = plain_roles(obj.docstring.value)
            obj.docstring.value = CITATION.sub(lambda m: f"[docs/{m.group(1)}](../{m.group(1)})", text)

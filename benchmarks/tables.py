"""Tables the benchmark scripts keep in the pages of docs/benchmarks/, each between its two marker lines."""

from __future__ import annotations

from pathlib import Path

DOCS = Path(__file__).resolve().parent.parent / "docs" / "benchmarks" / "index.md"


def replace_between(begin: str, end: str, text: str, heading: str, docs: Path = DOCS) -> None:
    """Put ``text`` between the lines ``begin`` and ``end`` of ``docs``; where they are missing, append a
    section ``heading`` holding them."""
    doc = docs.read_text()
    if begin in doc:
        head, rest = doc.split(begin, 1)
        doc = head + begin + "\n" + text + "\n" + end + rest.split(end, 1)[1]
    else:
        doc = doc.rstrip() + f"\n\n## {heading}\n\n{begin}\n{text}\n{end}\n"
    docs.write_text(doc)

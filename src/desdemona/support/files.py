"""Files written whole or not at all: written beside their place, then renamed into it."""

from __future__ import annotations

import contextlib
import os
import tempfile
from pathlib import Path


@contextlib.contextmanager
def beside(out: str | Path):
    """A temporary file in ``out``'s folder (so that renaming it onto ``out`` is atomic), named
    ``.NAME.*.tmp``, with the permissions a plain ``open()`` would give it (``mkstemp`` makes it
    private). Yields its path; the caller writes it and renames it into place (``os.replace``, or
    ``os.link`` where ``out`` must not exist yet). Whatever is left of it is removed at the end, also
    on an error or an interrupt. Raises OSError where the folder cannot be written in."""
    out = Path(out)
    fd, tmp = tempfile.mkstemp(prefix=f".{out.name}.", suffix=".tmp", dir=out.absolute().parent)
    os.close(fd)
    try:
        umask = os.umask(0)
        os.umask(umask)
        os.chmod(tmp, 0o666 & ~umask)
        yield Path(tmp)
    finally:
        if os.path.exists(tmp):
            os.unlink(tmp)


def same_file(a: str | Path, b: str | Path) -> bool:
    """Whether ``a`` and ``b`` are one file that exists, under whatever names (a symbolic or a hard link,
    a relative path): :func:`os.path.samefile`, False where either does not exist."""
    try:
        return os.path.samefile(a, b)
    except OSError:
        return False

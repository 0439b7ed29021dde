"""A session's record at flat memory: the rows of its cycles and of the host's messages kept in
memory a block at a time, the older blocks written to a temporary file (beside the session's
results where it has a folder: a system whose temporary folder is in memory, tmpfs, would otherwise
hold them in memory after all).

A session of an hour at 100 Hz has 360,000 cycles. Kept as Python objects (a dict of the cycle's
columns, the command's arrays, the host's message) they cost about 1.4 kB a cycle: +500 MB over the
hour, where the service must run with flat memory (a machine's controller runs for days). A
:class:`Spilled` keeps the rows of its last two blocks in memory (what the cycles ask for: the
setpoints in flight, the host's last second) and pickles each older block to an unnamed temporary
file (removed by the system when the file is closed or the process ends, killed or not). The whole
is read back once, when the session is judged after its end.

Writing a block costs about 1 ms for :data:`BLOCK` rows (measured: 0.9 ms for 1,000 cycle rows,
0.1 ms for 1,000 stacked arrays), once every :data:`BLOCK` cycles, after the cycle's send.
"""

from __future__ import annotations

import bisect
import os
import pickle
import tempfile

import numpy as np

#: Rows per block: two blocks are in memory (10-20 s of cycles at 100-50 Hz).
BLOCK = 1000


class Spilled:
    """A list that only grows (``append``), of which the rows of the last one or two blocks are
    in memory: indexed (an int or a slice) there, anything before raises IndexError; ``iter()``,
    :meth:`array` and :func:`numpy.asarray` give every row, the spilled ones read back (with
    ``keep=False`` the older blocks are dropped instead: only the recent rows are ever asked for);
    :attr:`head` is the first row. Rows of NumPy arrays of one shape are stacked as they are spilled."""

    def __init__(self, block: int | None = None, keep: bool = True, directory=None):
        block = BLOCK if block is None else block
        if block < 1:
            raise ValueError(f"block {block}: at least one row")
        self.block, self.keep = block, keep  # keep=False: older blocks are dropped, not written
        self.directory = directory  # where the file goes (None, or not there: the system's temporary folder)
        self.first = 0  # the index of the first row in memory
        self.head = None  # the first row, kept aside
        self._older: list = []  # the block before the one being filled
        self._recent: list = []
        self._file = None

    def append(self, row) -> None:
        if len(self) == 0:
            self.head = row
        self._recent.append(row)
        if len(self._recent) >= self.block:
            self._spill(self._older)
            self.first += len(self._older)
            self._older, self._recent = self._recent, []

    def _spill(self, rows: list) -> None:
        if not rows or not self.keep:
            return
        if self._file is None:
            there = self.directory if self.directory is not None and os.path.isdir(self.directory) else None
            self._file = tempfile.TemporaryFile(prefix=".desdemona-record-", dir=there)  # noqa: SIM115 -- kept open, closed by close()
        stack = isinstance(rows[0], np.ndarray) and all(
            isinstance(r, np.ndarray) and r.shape == rows[0].shape for r in rows)
        pickle.dump(np.stack(rows) if stack else rows, self._file, protocol=pickle.HIGHEST_PROTOCOL)

    def __len__(self) -> int:
        return self.first + len(self._older) + len(self._recent)

    def __bool__(self) -> bool:
        return len(self) > 0

    def _memory(self, k: int) -> int:
        if k < self.first:
            raise IndexError(f"row {k} was written out: rows {self.first} to {len(self) - 1} are in memory")
        return k - self.first

    def __getitem__(self, key):
        size = len(self)
        if isinstance(key, slice):
            start, stop, step = key.indices(size)
            if start >= stop:
                return []
            lo, hi, older = self._memory(start), stop - self.first, len(self._older)
            if lo >= older:  # within the block being filled: no copy of the older one
                return self._recent[lo - older:hi - older:step]
            return (self._older[lo:] + self._recent)[:hi - lo:step]
        k = key + size if key < 0 else key
        if not 0 <= k < size:
            raise IndexError(f"row {key} of {size}")
        i = self._memory(k)
        return self._older[i] if i < len(self._older) else self._recent[i - len(self._older)]

    def after(self, value) -> int:
        """Of rows that increase, the index of the first in memory above ``value``
        (:func:`bisect.bisect_right` over the rows in memory)."""
        return bisect.bisect_right(self, value, lo=self.first)

    def __iter__(self):
        if not self.keep and self.first:
            raise IndexError(f"rows 0 to {self.first - 1} were dropped (keep=False)")
        if self._file is not None:
            self._file.seek(0)
            while True:
                try:
                    block = pickle.load(self._file)
                except EOFError:
                    break
                yield from block
            self._file.seek(0, 2)  # appended to again after the reading
        yield from self._older
        yield from self._recent

    def array(self) -> np.ndarray:
        """Every row, as one array."""
        return np.array(list(self))

    def __array__(self, dtype=None, copy=None):
        rows = self.array()
        return rows if dtype is None else rows.astype(dtype)

    def close(self) -> None:
        """The temporary file closed (the system removes it); the rows in memory stay."""
        if self._file is not None:
            self._file.close()
            self._file = None

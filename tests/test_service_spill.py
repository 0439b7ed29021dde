"""A session's record at flat memory (desdemona.service.spill): rows kept a block at a time, the
older blocks written to a temporary file and read back whole at the end."""

import os
import tracemalloc
from pathlib import Path

import numpy as np
import pytest

from desdemona.service.spill import Spilled


def _row(k: int) -> dict:
    return {"t": 0.01 * k, "status": "running", "latency_s": 1e-3 * (k % 7), "reason": ""}


def test_every_row_comes_back_in_order_and_the_recent_ones_are_indexed():
    rows, commands = Spilled(block=100), Spilled(block=100)
    for k in range(1234):
        rows.append(_row(k))
        commands.append(np.full(4, float(k)))
    assert len(rows) == 1234 and rows.first == 1100 and rows.head == _row(0)
    assert list(rows) == [_row(k) for k in range(1234)]  # the spilled blocks read back, then memory
    np.testing.assert_array_equal(np.asarray(commands), np.repeat(np.arange(1234.0)[:, None], 4, axis=1))
    assert rows[-1] == _row(1233) and rows[1100] == _row(1100) and rows[-34:] == [_row(k) for k in range(1200, 1234)]
    with pytest.raises(IndexError, match="row 1099 was written out: rows 1100 to 1233 are in memory"):
        rows[1099]
    with pytest.raises(IndexError):
        rows[1234]
    rows.append(_row(1234))  # appended to after a reading: still in order
    assert list(rows)[-2:] == [_row(1233), _row(1234)]
    rows.close()
    commands.close()


def test_times_are_searched_among_the_rows_in_memory():
    t = Spilled(block=10)
    for k in range(95):
        t.append(0.1 * k)
    assert t.after(0.1 * 90 - 1e-9) == 90 and t.after(-1.0) == t.first == 80


def test_a_record_that_keeps_only_the_recent_rows_drops_the_rest():
    starts = Spilled(block=10, keep=False)
    for k in range(35):
        starts.append(k)
    assert starts[-1] == 34 and starts[20] == 20 and len(starts) == 35
    with pytest.raises(IndexError, match="dropped"):
        list(starts)


def test_memory_stays_flat_as_a_long_session_is_recorded():
    """An hour at 100 Hz is 360,000 cycles: recorded here at a tenth of that, the memory held after
    36,000 cycles is that after 12,000 (within a block's worth), where a list would have tripled."""
    rows, commands = Spilled(), Spilled()
    tracemalloc.start()
    try:
        held = []
        for k in range(36_000):
            rows.append({**_row(k), "compute_time_s": 2e-3, "qp_s": 1e-3, "machine": "following"})
            commands.append(np.full(8, 1e-3 * k))
            if k in (11_999, 35_999):
                held.append(tracemalloc.get_traced_memory()[0])
    finally:
        tracemalloc.stop()
    assert held[1] < held[0] + 500_000, held  # two blocks of ~1,000 rows are about 1.5 MB
    assert len(list(rows)) == 36_000 and np.asarray(commands).shape == (36_000, 8)
    rows.close()
    commands.close()


def test_the_written_blocks_go_to_the_folder_given_and_leave_nothing(tmp_path):
    """Beside the session's results (not the system's temporary folder, which may be in memory), as a
    file without a name: nothing is left there, closed or killed."""
    rows = Spilled(block=2, directory=tmp_path)
    for k in range(7):
        rows.append(k)
    link = Path(f"/proc/self/fd/{rows._file.fileno()}")
    if link.exists():  # Linux: where the open file is
        assert os.readlink(link).startswith(str(tmp_path))
    assert list(rows) == list(range(7)) and list(tmp_path.iterdir()) == []
    rows.close()
    assert list(tmp_path.iterdir()) == []

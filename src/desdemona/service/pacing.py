"""When a cycle of :mod:`desdemona.service.serve` starts, and what its phases cost.

**Starting on the host's message.** Cycle k belongs to the machine's time k h and may start anywhere
in its window, within half a cycle of k h: the motion system plays its setpoint at its place on the
setpoints' time line whenever within the window it came (:mod:`desdemona.service.drive`). A host sends
at its own rate and on its own clock. A message that came before the window opened (while the last
cycle computed, or between two cycles) is stale by the time the window opens; where the host's next
message is due well before the window closes (a host that sends faster than the service, or at its
rate with its messages just before the windows open), the cycle waits for it and answers it at once:
the setpoint then carries motion younger by up to a cycle, and the latency from the message to the
setpoint is the cycle's compute alone. Where the next message is not due in time (a slower host), the
cycle starts with the stale one as the window opens, as it always did. :func:`newer_due` decides.

**A cycle with nothing new** (a host slower than the service: at 60 Hz into 100 Hz, two cycles in
five) follows the last plan's next step, without a QP (:meth:`desdemona.control.mpc.MPC.follow`): a
fraction of a millisecond instead of a plan's. It starts as its window opens where the host's next
message is not due within the window, else it waits for that message until the window closes
(:func:`begins`). A cycle that solved a QP with nothing new at its window's close made the host's
next message, arriving then, wait for it (p99 of the wait 4.8 ms, of the latency 8.8 ms on ``dfs`` at
100 Hz with a 60 Hz host; docs/benchmarks/real-time-service.md).

**The phases of a cycle** (:data:`PHASES`, seconds, in the session's ``session.csv`` and summarised in
its ``summary.json``): the preview (the predictor over what the host sent, and the stage data of the
plan), the QP's data (linearising the plan: on the hot path only where nothing was prepared), the QP
(the solver), the check (the controller's of its command over the cycle, and the service's own), the
send; and after the send, off the hot path, the preparation of the next cycle's QP
(:meth:`desdemona.control.mpc.MPC.prepare`). The wait, from the message's arrival to the cycle's start,
is the log's ``message_age_s``; ``compute_cpu_s`` is the thread's processor time over the cycle's compute,
to tell a slow cycle from one the machine's other processes took the processor from.
"""

from __future__ import annotations

import contextlib
import gc
import itertools
import math
import socket
import statistics
import struct
import time

#: How many of the host's last arrivals give its period (the median of their gaps).
ARRIVALS = 16
#: A newer message is waited for only where it is due this share of a cycle before the window closes:
#: room for the host's jitter (a message that comes after the window closed leaves the cycle to
#: start there, with the stale one).
MARGIN = 0.25
#: Linux's SO_TIMESTAMPNS (not in Python's socket module): the kernel stamps each datagram with the
#: time it was received, so a message that came while a cycle computed is timed from its arrival, not
#: from when the service read it.
SO_TIMESTAMPNS = 35
#: The phases of a cycle, in order: each a column ``{phase}_s`` of ``session.csv``.
PHASES = ("preview", "qp_data", "qp", "check", "send", "prepare")


def host_period(arrivals: list[float]) -> float:
    """The host's period [s] from its last :data:`ARRIVALS` arrival times [s] (any clock); inf
    before it has sent enough to tell."""
    if len(arrivals) <= ARRIVALS // 2:
        return math.inf
    recent = arrivals[-ARRIVALS - 1:]
    return statistics.median(b - a for a, b in itertools.pairwise(recent))


def newer_due(arrivals: list[float], opens: float, closes: float) -> bool:
    """Whether a cycle whose window is [``opens``, ``closes``] (clock times [s]), holding a message
    that arrived at ``arrivals[-1]`` before the window opened, should wait for the host's next
    message: it is due (one host period later) at least :data:`MARGIN` of a cycle before the window
    closes."""
    if not (arrivals and math.isfinite(opens) and arrivals[-1] < opens):
        return False
    return arrivals[-1] + host_period(arrivals) <= closes - MARGIN * (closes - opens)


def begins(arrivals: list[float], fresh: bool, opens: float, closes: float) -> float:
    """When a cycle whose window is [``opens``, ``closes``] (clock times [s]) starts, short of a new
    message: a fresh message (one not yet answered) is answered as the window opens, unless it came
    before and the host's next is due in the window (:func:`newer_due`: the cycle waits for that);
    with nothing fresh, the cycle waits for a message due in the window (the host's next, one period
    after its last) and otherwise starts as the window opens, following the last plan
    (:meth:`desdemona.control.mpc.MPC.follow`): its processor time is then spent away from when the
    host's next message comes, which a cycle at the window's close would make wait (a host slower
    than the service). No margin here: a message due just before the close that comes just after it
    waits for the short cycle that follows the plan; one the cycle had not waited for would wait for
    the next window."""
    if fresh:
        return closes if newer_due(arrivals, opens, closes) else opens
    due = arrivals[-1] + host_period(arrivals) if arrivals else math.inf
    if not (math.isfinite(due) and math.isfinite(opens)):  # the host's period not known yet: as always
        return closes
    return closes if due <= closes else opens


def stamped(sock: socket.socket) -> socket.socket:
    """``sock`` with the kernel's receive time on every datagram, where the system has it."""
    try:
        sock.setsockopt(socket.SOL_SOCKET, SO_TIMESTAMPNS, 1)
    except OSError:  # not Linux: datagrams are timed when read
        pass
    return sock


def datagrams(sock: socket.socket, on_error):
    """The datagrams waiting on a non-blocking ``sock``: (data, sender, age [s]) each, the age since the
    kernel received it (0 where it was not stamped, :func:`stamped`); ``on_error(exc)`` is told of a
    socket error (an ICMP error for an earlier send: not a message)."""
    while True:
        try:
            data, ancillary, _, sender = sock.recvmsg(65536, socket.CMSG_SPACE(16))
        except (BlockingIOError, InterruptedError):
            return
        except OSError as exc:
            on_error(exc)
            continue
        yield data, sender, age(ancillary)


def received(sock: socket.socket, size: int) -> tuple[bytes, tuple, float]:
    """One datagram from ``sock`` (blocking as the socket does): (data, sender, age [s] since the
    kernel received it, 0 where it was not stamped: :func:`stamped`)."""
    data, ancillary, _, sender = sock.recvmsg(size, socket.CMSG_SPACE(16))
    return data, sender, age(ancillary)


def age(ancillary) -> float:
    """The seconds since the kernel received a datagram, from its ``ancillary`` data (0 without the
    kernel's stamp)."""
    for level, kind, stamp in ancillary:
        if level == socket.SOL_SOCKET and kind == SO_TIMESTAMPNS and len(stamp) >= 16:
            seconds, nanoseconds = struct.unpack("qq", stamp[:16])
            return max(0.0, time.time() - (seconds + 1e-9 * nanoseconds))
    return 0.0


def timed(function, *args):
    """(``function(*args)``, the seconds it took)."""
    began = time.perf_counter()
    result = function(*args)
    return result, time.perf_counter() - began


def phases(timings: dict | None, send: float, cpu: float) -> dict:
    """A cycle's columns: its phases [s] (:data:`PHASES`; NaN where it did not plan, and the
    preparation, which comes after) from ``timings`` (the controller's, with the service's own
    ``service_preview`` and ``guard``, or None), ``send`` [s], and ``compute_cpu_s``, the thread's
    processor time since ``cpu`` (:func:`time.thread_time`)."""
    row = {f"{phase}_s": math.nan for phase in PHASES}
    if timings is not None:
        row.update(preview_s=timings["service_preview"] + timings["preview"], qp_data_s=timings["qp_data"],
                   qp_s=timings["qp"], check_s=timings["check"] + timings["guard"])
    return {**row, "send_s": send, "compute_cpu_s": time.thread_time() - cpu}


def close(row: dict, timings: dict | None, send: float, cpu: float, prepare, state, followed: bool = False) -> None:
    """After a cycle's send: its ``row`` given its phases (:func:`phases`), and where it planned or
    ``followed`` the last plan, the next cycle's QP prepared from ``state``, where the command leaves
    the machine (``prepare(state)``, :meth:`desdemona.control.mpc.MPC.prepare`), off the hot path, its
    time the row's ``prepare_s``."""
    row.update(phases(timings, send, cpu))
    if timings is not None or followed:
        row["prepare_s"] = timed(prepare, state)[1]


class Collector:
    """Python's collection of garbage cycles, off the cycles' hot path (:func:`collected`).

    Left to itself the interpreter collects when allocations pass its thresholds, wherever that
    falls: in a served session on ``full`` a collection of every generation took 25-45 ms (78,000
    objects: the controller's CasADi functions, NumPy and the rest), once every few minutes, inside
    a cycle (a 27.8 ms cycle in the soak, benchmarks/soak.py: a deadline missed). Here what exists
    when the session begins is frozen (:func:`gc.freeze`: never scanned again, still freed when no
    longer referenced), automatic collection is off, and :meth:`__call__`, after each cycle's send,
    collects as the interpreter would (the youngest generation once 700 allocations are pending,
    the next every 10th time, all every 100th), over what the session made since: 0.05-0.2 ms with
    two blocks of a session's record in memory (desdemona.service.spill)."""

    def __init__(self):
        self.runs = 0

    def __call__(self) -> None:
        if gc.get_count()[0] < gc.get_threshold()[0]:
            return
        self.runs += 1
        gc.collect(2 if self.runs % 100 == 0 else 1 if self.runs % 10 == 0 else 0)


@contextlib.contextmanager
def collected():
    """Within the block, garbage collected only when the :class:`Collector` it gives is called; the
    interpreter's own collection as it was after."""
    enabled = gc.isenabled()
    gc.collect()
    gc.freeze()
    gc.disable()
    try:
        yield Collector()
    finally:
        gc.unfreeze()
        if enabled:
            gc.enable()

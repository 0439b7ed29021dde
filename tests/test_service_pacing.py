"""When a served cycle starts (desdemona.service.pacing): a stale message waits for the host's next
one only where that is due within the cycle's window; datagrams are timed from their arrival."""

import socket
import time

import numpy as np
import pytest

from desdemona.service import pacing

H = 0.02  # the service's cycle [s], 50 Hz


def _arrivals(rate: float, last: float, count: int = 20) -> list[float]:
    """A host's arrival times at ``rate`` [Hz], the last at ``last`` [s]."""
    return list(last - np.arange(count)[::-1] / rate)


def test_a_faster_host_s_next_message_is_waited_for():
    """A 60 Hz host into a 50 Hz service: a message 3 ms before the window opened is stale, and the
    next one comes 13.7 ms into the window (6.3 ms before it closes, more than a quarter of a cycle):
    wait for it."""
    opens = 1.0
    assert pacing.newer_due(_arrivals(60.0, opens - 0.003), opens, opens + H)
    assert pacing.host_period(_arrivals(60.0, 0.0)) == pytest.approx(1 / 60.0)


def test_a_slower_host_s_stale_message_is_answered_as_the_window_opens():
    """A 60 Hz host into a 100 Hz service: its next message is not due within the 10 ms window, so the
    one that came is answered at once; nor is one waited for that came inside the window, or before the
    host's period is known."""
    opens, h = 1.0, 0.01
    assert not pacing.newer_due(_arrivals(60.0, opens - 0.001), opens, opens + h)
    assert not pacing.newer_due(_arrivals(120.0, opens + 0.001), opens, opens + H)
    assert not pacing.newer_due(_arrivals(120.0, opens - 0.001, count=5), opens, opens + H)
    assert not pacing.newer_due([], opens, opens + H)


def test_a_host_at_the_service_s_rate_just_before_the_window_is_answered_unless_its_next_is_due_in_time():
    """A host at the service's own rate whose messages come just before the windows open: 1 ms before,
    its next would come 1 ms before the window closes, too late to count on; 10 ms before, it comes 10
    ms into the window, and is waited for."""
    opens = 1.0
    assert not pacing.newer_due(_arrivals(50.0, opens - 0.001), opens, opens + H)
    assert pacing.newer_due(_arrivals(50.0, opens - 0.010), opens, opens + H)


def test_a_cycle_with_nothing_new_starts_as_its_window_opens_unless_the_host_s_next_is_due_in_it():
    """A 60 Hz host into a 100 Hz service, its last message answered: where the next is due after the
    10 ms window closes, the cycle (which follows the last plan) starts as the window opens, leaving the
    processor free when the message comes; where it is due within the window, even just before its
    close, the cycle waits for it (until the close). A fresh message is answered as before (newer_due)."""
    opens, h = 1.0, 0.01
    assert pacing.begins(_arrivals(60.0, opens - 0.005), False, opens, opens + h) == opens  # due at +11.7 ms
    assert pacing.begins(_arrivals(60.0, opens - 0.008), False, opens, opens + h) == opens + h  # due at +8.7 ms
    assert pacing.begins(_arrivals(60.0, opens - 0.0068), False, opens, opens + h) == opens + h  # at +9.9 ms
    assert pacing.begins(_arrivals(60.0, opens - 0.001), True, opens, opens + h) == opens
    assert pacing.begins(_arrivals(60.0, opens - 0.003), True, opens, opens + H) == opens + H
    assert pacing.begins([], False, opens, opens + h) == opens + h  # no host yet: as it always did
    assert pacing.begins(_arrivals(60.0, opens - 0.005, count=5), False, opens, opens + h) == opens + h  # its period unknown
    assert pacing.begins(_arrivals(60.0, opens - 0.001), False, np.inf, opens) == opens  # stopping


def test_datagrams_are_timed_from_their_arrival_not_from_their_reading():
    """A datagram read 50 ms after it came is 50 ms old (the kernel's receive time), and the phases'
    row has every phase's column. The kernel turns its receive stamps on a moment after the first
    socket asks (until then a datagram is stamped as it is read, age 0): three tries."""
    with socket.socket(socket.AF_INET, socket.SOCK_DGRAM) as rx, socket.socket(socket.AF_INET, socket.SOCK_DGRAM) as tx:
        rx.bind(("127.0.0.1", 0))
        pacing.stamped(rx).setblocking(False)
        ages, errors = [], []
        for _ in range(3):
            tx.sendto(b"motion", rx.getsockname())
            time.sleep(0.05)
            read = list(pacing.datagrams(rx, errors.append))
            assert [data for data, _, _ in read] == [b"motion"]
            ages.append(read[0][2])
    assert max(ages) >= 0.045 and max(ages) < 5.0 and not errors, ages
    row = pacing.phases(None, 1e-4, time.thread_time())
    assert set(row) == {f"{phase}_s" for phase in pacing.PHASES} | {"compute_cpu_s"} and np.isnan(row["qp_s"])


def test_garbage_is_collected_after_the_send_not_where_allocations_fall():
    """Within a session the interpreter collects nothing on its own; the collector, called after each
    send, frees garbage cycles once its threshold of allocations is pending, over what the session
    made since it began (not the objects frozen then), and the interpreter's collection is back after."""
    import gc
    import weakref

    class Node:
        pass

    was = gc.isenabled()
    with pacing.collected() as collect:
        assert not gc.isenabled() and gc.get_freeze_count() > 0
        node = Node()
        node.self = node  # a cycle: only the collector frees it
        alive = weakref.ref(node)
        del node
        collect()  # few allocations pending: nothing done
        assert alive() is not None
        kept = [[] for _ in range(gc.get_threshold()[0] + 10)]  # allocations pending past the threshold
        collect()
        assert alive() is None and gc.get_count()[0] < 10
        began = time.perf_counter()
        for _ in range(100):  # every generation once in a hundred: over what was made since the freeze
            kept += [[] for _ in range(gc.get_threshold()[0] + 10)]
            collect()
        assert time.perf_counter() - began < 1.0
    assert gc.isenabled() == was and gc.get_freeze_count() == 0

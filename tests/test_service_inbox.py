"""Who may move the machine (desdemona.service.inbox, .signing, .drops): the issue's three findings
replayed against the service's inbox now fail the attacker; with a key, unsigned, forged, altered and
replayed datagrams are dropped and counted; drop reasons stay a fixed, small set and their lines on
stderr are rate-limited. The inbox is fed datagrams directly, on a clock of the test's own: nothing
here waits on real time."""

import os
import socket

import numpy as np
import pytest

from desdemona.cli import main
from desdemona.service import protocol, signing
from desdemona.service.drops import Drops
from desdemona.service.inbox import Inbox

HOST = ("127.0.0.1", 40001)
OTHER = ("127.0.0.1", 40002)
KEY = bytes(range(32))
LOST_AFTER = 0.1  # [s]: the session's timeout (5 cycles at 50 Hz)
NOW = 1.8e9  # [s, Unix time] the signatures' clock in these tests


@pytest.fixture
def sock():
    with socket.socket(socket.AF_INET, socket.SOCK_DGRAM) as s:
        s.bind(("127.0.0.1", 0))
        yield s


def motion(sequence: int, M: float = 9.81, time: float | None = None) -> protocol.Motion:
    return protocol.Motion(sequence, 0.01 * sequence if time is None else time, np.array([M]))


def inbox_of(sock, key=None) -> Inbox:
    box = Inbox(sock, 1, clock=lambda: 0.0, lost_after=LOST_AFTER, key=key)
    box.incoming.clock = lambda: NOW
    return box


def host_stream(box: Inbox, outgoing, sequences, start: float = 0.0, sender=HOST) -> None:
    """The host's messages of ``sequences``, 10 ms apart from ``start`` [s]."""
    for k, sequence in enumerate(sequences):
        box.take(outgoing.pack(motion(sequence)), start + 0.01 * k, sender)


def test_another_port_continuing_the_hosts_sequence_is_not_used(sock):
    """The issue's first finding: 100 datagrams from another port, continuing the host's sequence,
    were all used. Now they are dropped while the host is alive, and counted as from another sender."""
    box, host, intruder = inbox_of(sock), signing.Outgoing(), signing.Outgoing()
    host_stream(box, host, range(1, 11))
    for k in range(100):
        box.take(intruder.pack(motion(11 + k, M=25.0)), 0.1 + 0.0005 * k, OTHER)
    host_stream(box, host, range(11, 16), start=0.15)
    assert box.dropped == {"sender": 100}
    assert len(box.values) == 15 and max(v[0] for v in box.values) == 9.81  # none of the intruder's 25 m/s^2


def test_a_spoofed_high_sequence_does_not_silence_the_host(sock):
    """The second finding: one datagram with sequence 0xFFFFFFFE from another port made the real host's
    next messages stale. Now it is dropped and the host's next messages are used."""
    box, host = inbox_of(sock), signing.Outgoing()
    host_stream(box, host, range(1, 6))
    box.take(protocol.pack(motion(0xFFFFFFFE, M=25.0, time=1e6)), 0.05, OTHER)
    host_stream(box, host, range(6, 11), start=0.06)
    assert box.dropped == {"sender": 1} and box.newest.sequence == 10 and len(box.t) == 10


def test_an_old_datagram_after_a_pause_is_stale_not_a_restart(sock):
    """The third finding: sequence 3 arriving after a 0.3 s pause was taken as a restarted host and its
    25 m/s^2 cued. A restart is a new session in the header; an old number of the same session is
    stale however long the silence, with or without a session block; a replaced session is never taken again."""
    for session in (7, None):
        box = inbox_of(sock)
        old = protocol.pack(motion(3, M=25.0), session)
        for k in range(1, 11):
            box.take(protocol.pack(motion(k), session), 0.01 * k, HOST)
        box.take(old, 0.1 + 0.3, HOST)  # after the host was declared lost
        assert box.dropped == {"stale": 1} and box.newest.sequence == 10
        assert all(v[0] == 9.81 for v in box.values)


def test_a_restart_is_a_new_session_taken_at_once_its_times_continuing(sock):
    box, first = inbox_of(sock), signing.Outgoing(session=1)
    host_stream(box, first, range(1, 21))  # 0.01 ... 0.2 s of the host's clock
    again = signing.Outgoing(session=2)
    host_stream(box, again, range(1, 6), start=0.25)  # from the start, 0.05 s later, within the timeout
    assert not box.dropped and len(box.t) == 25 and np.all(np.diff(box.t) > 0)
    np.testing.assert_allclose(box.t[20] - box.t[19], 0.06, atol=1e-9)  # its silence, on the session's clock
    box.take(first.pack(motion(21, M=25.0)), 0.31, HOST)  # the old session, late: never again
    box.take(first.pack(motion(22, M=25.0)), 0.31 + 2 * LOST_AFTER, HOST)  # not even once the host is lost
    assert box.dropped == {"sender": 2} and all(v[0] == 9.81 for v in box.values)


def test_another_sender_becomes_the_host_only_once_the_host_is_lost(sock):
    box, host, successor = inbox_of(sock), signing.Outgoing(), signing.Outgoing()
    host_stream(box, host, range(1, 6))
    box.take(successor.pack(motion(1)), 0.04 + LOST_AFTER / 2, OTHER)
    assert box.dropped == {"sender": 1}
    box.take(successor.pack(motion(2)), 0.04 + 1.5 * LOST_AFTER, OTHER)
    assert box.host[:2] == OTHER and len(box.t) == 6
    host_stream(box, host, range(6, 8), start=0.25)  # the first host, back: replaced by the other one
    assert box.dropped == {"sender": 3}


def test_with_a_key_unsigned_forged_altered_and_replayed_datagrams_are_dropped_and_counted(sock):
    box = inbox_of(sock, KEY)
    host = signing.Outgoing(KEY, clock=lambda: NOW)
    signed = [host.pack(motion(k)) for k in range(1, 6)]
    for k, data in enumerate(signed[:3]):
        box.take(data, 0.01 * k, HOST)
    altered = bytearray(signed[3])
    altered[32:40] = np.array([25.0]).tobytes()  # the modulus changed on the way
    forger = signing.Outgoing(bytes(32), clock=lambda: NOW + 1)  # the wrong key
    attacks = [protocol.pack(motion(4, M=25.0)), protocol.pack(motion(4, M=25.0), 5), bytes(altered),
               forger.pack(motion(4, M=25.0)), signed[2], signed[0]]
    for data in attacks:
        box.take(data, 0.035, HOST)
    box.take(signed[3], 0.04, HOST)
    box.take(signed[4], 0.05, HOST)
    assert box.dropped == {"unsigned": 2, "forged": 2, "replayed": 2}
    assert [v[0] for v in box.values] == [9.81] * 5 and box.newest.sequence == 5


def test_with_a_key_a_restart_may_come_from_another_port_an_old_session_may_not(sock):
    box = inbox_of(sock, KEY)
    clock = iter(NOW + 0.001 * np.arange(100)).__next__
    first, again = signing.Outgoing(KEY, clock=clock), signing.Outgoing(KEY, clock=clock)
    recorded = [first.pack(motion(k)) for k in range(1, 4)]
    for k, data in enumerate(recorded[:2]):
        box.take(data, 0.01 * k, HOST)
    box.take(again.pack(motion(1)), 0.02, OTHER)  # the host restarted on a new port: signed, newer
    box.take(recorded[2], 0.03, HOST)  # the old session's last, signed and never seen: replaced
    assert box.host[:2] == OTHER and box.dropped == {"sender": 1}
    fresh = inbox_of(sock, KEY)  # a service started since: an old recording is replayed
    fresh.incoming.clock = lambda: NOW + 2 * signing.REPLAY_WINDOW
    fresh.take(recorded[0], 0.0, HOST)
    assert fresh.dropped == {"replayed": 1} and fresh.newest is None


def test_a_receiver_without_a_key_refuses_signed_datagrams(sock):
    box = inbox_of(sock)
    box.take(signing.Outgoing(KEY).pack(motion(1)), 0.0, HOST)
    assert box.dropped == {"signed": 1} and box.newest is None


def test_drop_reasons_stay_few_and_their_lines_at_most_one_a_second():
    """The issue saw 791 drops make 315 reasons and 315 lines. A flood of distinct bad values now
    makes one reason, a bounded sample, and a line per second with the count since the last."""
    lines, now = [], [0.0]
    drops = Drops(lines.append, clock=lambda: now[0])
    for k in range(791):
        now[0] = 0.002 * k  # 1.58 s
        try:
            protocol.unpack(protocol.pack(motion(1))[:-8] + np.array([1e3 + k]).tobytes())
        except protocol.ProtocolError as exc:
            drops.error(exc)
    assert dict(drops.counts) == {"absurd": 791} and len(drops.samples["absurd"]) == 5
    assert len(lines) == 2 and "(500 since 1.0 s ago)" in lines[1] and set(drops.counts) <= set(protocol.REASONS)


def test_the_signature_is_hmac_sha256_over_everything_before_its_tag():
    import hashlib
    import hmac

    data = protocol.pack(motion(1), 9, KEY, 123456789)
    assert len(data) == 40 + protocol.TRAILERS and data[7] == protocol.FLAG_SESSION | protocol.FLAG_SIGNED
    assert data[-16:] == hmac.new(KEY, data[:-16], hashlib.sha256).digest()[:16]
    frame = protocol.read(data, KEY)
    assert (frame.session, frame.timestamp, frame.message.values[0]) == (9, 123456789, 9.81)
    stamp = signing.timestamp(signing.EPOCH + 86400.0)  # a day after 2015-01-01: 8.64e9 units of 10 us
    assert stamp == 8_640_000_000


def test_a_key_file_is_refused_with_one_line_when_malformed_or_readable_by_others(tmp_path, capsys):
    good = tmp_path / "key"
    good.write_text(KEY.hex() + "\n")
    os.chmod(good, 0o600)
    assert signing.load_key(good) == KEY
    short = tmp_path / "short"
    short.write_text("abcd\n")
    os.chmod(short, 0o600)
    with pytest.raises(ValueError, match="64 hex digits"):
        signing.load_key(short)
    os.chmod(good, 0o640)
    with pytest.raises(ValueError, match=f"chmod 600 {good}"):
        signing.load_key(good)
    for argv in (["command", "estop", "--to", "127.0.0.1:9", "--key", str(good)],
                 ["host", "replay", "dfs-catapult", "--to", "127.0.0.1:9", "--key", str(short)],
                 ["machine", "--config", "dfs", "--listen", "127.0.0.1:9", "--out", str(tmp_path / "m"), "--key",
                  str(good)],
                 ["serve", "--config", "dfs", "--listen", "127.0.0.1:9", "--send", "127.0.0.1:9", "--out",
                  str(tmp_path / "s"), "--key", str(short)]):
        assert main(argv) == 2
        err = capsys.readouterr().err
        assert err.count("\n") == 1 and "--key" in err and "Traceback" not in err
    assert not (tmp_path / "m").exists() and not (tmp_path / "s").exists()  # nothing written


def test_the_machine_with_a_key_takes_signed_setpoints_only(tmp_path):
    """The stand-in for the motion system (``desdemona machine --key``): setpoints and commands
    unsigned, forged or replayed are dropped and counted, never checked or followed."""
    from desdemona.machine.model import Model
    from desdemona.service import machine
    from desdemona.service.machinelog import Files

    model = Model(config="yaw-track-cabin")
    cfg, zero = model.config, np.zeros(model.n)

    def setpoint(k):
        return protocol.Setpoint(k, 0.01 * k, "starting", "park", None, 0.01 * (k - 1), 0.01, cfg.expand(zero),
                                 cfg.expand(zero, "zero"), cfg.expand(zero, "zero"), cfg.expand(zero, "zero"))

    report = machine.Report(out=tmp_path)
    files = Files(tmp_path)
    stand_in = machine._StandIn(model, machine.MachineOptions(key=KEY), None, report, files)
    service = signing.Outgoing(KEY)
    signed = [service.pack(setpoint(k)) for k in (1, 2, 3)]
    datagrams = [signed[0], protocol.pack(setpoint(2)), signing.Outgoing(bytes(32)).pack(setpoint(2)), signed[1],
                 signed[1], protocol.pack(protocol.Command(1, 0.0, "emergency stop")), signed[2]]
    for k, data in enumerate(datagrams):
        stand_in.datagram(data, ("127.0.0.1", 40001), 0.005 * k)
    files.close()
    assert report.received == 3 and report.dropped == {"unsigned": 2, "forged": 1, "replayed": 1}
    assert stand_in.drive.status != "e-stop" and set(report.drop_samples) == set(report.dropped)


def test_the_services_link_to_the_machine_with_a_key_takes_signed_states_only():
    from desdemona.machine.model import Model
    from desdemona.service.measured import MachineLink

    model = Model(config="dfs")
    link = MachineLink(model, 0.02, HOST, lost_after=0.5, key=KEY)
    six = np.zeros(6)

    def state(k):
        return protocol.MachineState(k, 0.01 * k, "ready", "none", None, None, 0.0, six, six)

    machine, restarted = signing.Outgoing(KEY), signing.Outgoing(KEY)
    first = machine.pack(state(1))
    takes = [link.take(data, HOST, 0.0) for data in (
        first, protocol.pack(state(2)), signing.Outgoing(bytes(32)).pack(state(2)), first, machine.pack(state(2)),
        restarted.pack(state(1)), machine.pack(state(3)))]
    assert takes == ["", "unsigned", "forged", "replayed", "", "", "sender"]
    assert link.received == 3 and link.newest.sequence == 1 and link.session == restarted.session

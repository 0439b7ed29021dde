"""The motion-system stand-in (desdemona.service.machine): its checks, its servos, its own safety layer
(a stream that stops, an emergency stop, a fault) and when setpoints come. Loopback UDP only, every
run bounded in count and time."""

import csv
import json
import os
import signal
import socket
import struct
import threading
import time

import numpy as np
import pytest

from desdemona.machine.model import Model
from desdemona.machine.params import JOINT_NAMES
from desdemona.machine.plan import State, advance
from desdemona.service import machine, protocol, servo

# These tests time what they watch (a real-time loop, a prompt stop): the README runs them alone.
pytestmark = pytest.mark.realtime

STEP = 0.01
IDLE = 0.3
LIMIT = 5.0  # [s] no run in these tests lasts longer
#: The stand-in's options in these tests: a queue of 10 cycles and lateness up to 8, so that a loaded
#: computer's late thread does not make the timing the tests do not test (one test makes it wrong)
PATIENT = machine.MachineOptions(timeout=10, late=8.0)


@pytest.fixture(scope="module")
def model():
    return Model(config="yaw-track-cabin")  # free: yaw, track, inner_gimbal; held: heave, outer_gimbal, cabin


def free_port() -> int:
    with socket.socket(socket.AF_INET, socket.SOCK_DGRAM) as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def setpoint(model, sequence, q, qd, a, j, status="running", source="plan", cycle_time=0.0, step=STEP):
    """A setpoint of free-joint values, the held joints at their fixed positions and at rest."""
    cfg = model.config
    return protocol.Setpoint(sequence, cycle_time, status, source, sequence, cycle_time, step,
                             cfg.expand(np.asarray(q, float)), cfg.expand(np.asarray(qd, float), "zero"),
                             cfg.expand(np.asarray(a, float), "zero"), cfg.expand(np.asarray(j, float), "zero"))


def motion(model, jerks, step=STEP, q0=None):
    """Setpoints of an exact motion from rest: one per row of ``jerks`` (N, n), each cycle advanced
    with plan's State.advance (the accelerations continuous)."""
    n = model.n
    state = State(np.zeros(n) if q0 is None else np.asarray(q0, float), np.zeros(n), np.zeros(n))
    out = []
    for k, j in enumerate(np.asarray(jerks, float)):
        out.append(setpoint(model, k + 1, state.q, state.qd, state.a, j, cycle_time=k * step))
        state = state.advance(state.a, step, j)
    return out


def brake_motion(model):
    """Track and yaw accelerate at 0.9 of their jerk limits, hold, brake and come to rest."""
    J = 0.9 * model.limits.jerk * np.array([1.0, 1.0, 0.0])
    zero = np.zeros(model.n)
    profile = [J] * 10 + [zero] * 10 + [-J] * 20 + [zero] * 10 + [J] * 10
    return motion(model, profile)


def serve(model, tmp_path, datagrams, idle=IDLE, duration=LIMIT, name="out", after=None, at=None, options=None,
          extra=()):
    """Run the machine on a free loopback port while a thread sends ``datagrams`` (bytes), each at its
    offset of ``at`` [s] after the machine is ready (default: a setpoint at its cycle_time, anything
    else at once); ``extra``: (offset, datagram, source host) sent from other sockets. ``after`` is
    called by the thread once all are sent. The States the machine sends back are collected. Returns
    the report, the run's wall time and the States."""
    port = free_port()
    ready = threading.Event()
    states = []
    if at is None:
        at, clock = [], 0.0
        for data in datagrams:
            try:
                message = protocol.unpack(data)
                clock = max(clock, message.cycle_time) if isinstance(message, protocol.Setpoint) else clock
            except protocol.ProtocolError:
                pass
            at.append(clock)

    def send():
        if not ready.wait(LIMIT):
            return
        with socket.socket(socket.AF_INET, socket.SOCK_DGRAM) as s:
            s.bind(("127.0.0.1", 0))
            s.setblocking(False)
            start = time.monotonic()
            plan = sorted([(when, data, None) for when, data in zip(at, datagrams)] + list(extra), key=lambda x: x[0])
            for when, data, host in plan:
                while (delay := start + when - time.monotonic()) > 0:
                    time.sleep(min(delay, 0.002))
                if host is None:
                    s.sendto(data, ("127.0.0.1", port))
                else:
                    with socket.socket(socket.AF_INET, socket.SOCK_DGRAM) as other:
                        other.bind((host, 0))
                        other.sendto(data, ("127.0.0.1", port))
            if after is not None:
                after()
            end = time.monotonic() + LIMIT
            while time.monotonic() < end and not finished.is_set():
                try:
                    states.append(protocol.unpack(s.recv(4096)))
                except BlockingIOError:
                    time.sleep(0.005)

    finished = threading.Event()
    sender = threading.Thread(target=send, daemon=True)
    sender.start()
    started = time.monotonic()
    report = machine.run(model, ("127.0.0.1", port), tmp_path / name, idle=idle, duration=duration,
                         ready=ready.set, options=options or PATIENT)
    elapsed = time.monotonic() - started
    time.sleep(0.05)
    finished.set()
    sender.join(LIMIT)
    assert not sender.is_alive()
    return report, elapsed, states


def read_csv(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def test_clean_motion_passes_and_writes_files(model, tmp_path):
    points = brake_motion(model)
    last = points[-1]
    end = State(last.position, last.rate, last.acceleration).advance(last.acceleration, STEP, last.jerk)
    assert np.allclose(end.qd, 0.0, atol=1e-12) and np.allclose(end.a, 0.0, atol=1e-12)  # at rest again
    report, elapsed, _ = serve(model, tmp_path, [protocol.pack(p) for p in points])
    assert report.passed and machine.exit_code(report) == 0, report.describe()
    assert report.received == len(points) and report.dropped == {} and report.gaps == 0
    assert report.stopped == "idle" and elapsed < LIMIT
    assert 0.85 < report.worst["jerk"] <= 1.0 and report.worst_joint["jerk"] in ("yaw", "track")
    assert 0.0 < report.worst["effort"] < 1.0 and 0.0 < report.worst["rate"] < 1.0
    out = tmp_path / "out"
    assert sorted(p.name for p in out.iterdir()) == sorted(machine.FILES)  # no temporary left
    rows = read_csv(out / "setpoints.csv")
    assert len(rows) == len(points)
    assert [int(r["sequence"]) for r in rows] == [p.sequence for p in points]
    assert all(f"{name}_{q}" in rows[0] for name in JOINT_NAMES for q in ("position", "rate", "acceleration", "jerk"))
    assert float(rows[20]["track_position"]) == points[20].position[1]  # written exactly
    assert read_csv(out / "violations.csv") == []
    summary = json.loads((out / "summary.json").read_text())
    assert summary["received"] == len(points) and summary["passed"] and summary["violation_count"] == 0
    assert summary["first_cycle_time"] == 0.0 and summary["last_cycle_time"] == pytest.approx(59 * STEP)
    assert summary["statuses"] == {"running": len(points)} and summary["config"] == "yaw-track-cabin"
    # an earlier output of its own is replaced
    again, _, _ = serve(model, tmp_path, [protocol.pack(p) for p in points[:5]])
    assert again.received == 5 and len(read_csv(out / "setpoints.csv")) == 5


def _position(model):
    return [setpoint(model, 1, [0.0, 4.1, 0.0], [0, 0, 0], [0, 0, 0], [0, 0, 0])]


def _position_in_cycle(model):
    # within range at the setpoint, beyond it 10 ms later: 3.99 m + 2 m/s * 0.01 s = 4.01 m
    return [setpoint(model, 1, [0.0, 3.99, 0.0], [0, 2.0, 0], [0, 0, 0], [0, 0, 0])]


def _jerk(model):
    return [setpoint(model, 1, [0.0, 0.0, 0.0], [0, 0, 0], [0, 0, 0], [2.0 * model.limits.jerk[0], 0, 0])]


def _continuity(model):
    points = motion(model, [[0, 1.0, 0]] * 4)
    p = points[3]
    points[3] = protocol.Setpoint(p.sequence, p.time, p.status, p.source, p.answers, p.cycle_time, p.step,
                                  p.position + np.array([0, 0.1, 0, 0, 0, 0]), p.rate, p.acceleration, p.jerk)
    return points


def _held(model):
    p = setpoint(model, 1, [0.0, 0.0, 0.0], [0, 0, 0], [0, 0, 0], [0, 0, 0])
    position = p.position.copy()
    position[2] = 0.1  # heave, held at 0 m in yaw-track-cabin
    return [protocol.Setpoint(1, 0.0, "running", "plan", 1, 0.0, STEP, position, p.rate, p.acceleration, p.jerk)]


@pytest.mark.parametrize("make, joint, what, sequence", [
    (_position, "track", "position", 1),
    (_position_in_cycle, "track", "position", 1),
    (_jerk, "yaw", "jerk", 1),
    (_continuity, "track", "continuity", 4),
    (_held, "heave", "held", 1),
], ids=["position", "position-within-cycle", "jerk", "continuity", "held"])
def test_a_violation_is_reported_with_its_joint_and_kind(model, tmp_path, make, joint, what, sequence):
    points = make(model)
    report, _, _ = serve(model, tmp_path, [protocol.pack(p) for p in points])
    assert report.received == len(points) and report.dropped == {}
    assert not report.passed and machine.exit_code(report) == 1
    # of the setpoints
    found = [(v.joint, v.what, v.sequence) for v in report.violations if not v.what.startswith("made")]
    assert found == [(joint, what, sequence)], report.describe()
    assert report.counts[what] == 1
    rows = read_csv(tmp_path / "out" / "violations.csv")
    assert [(r["joint"], r["what"], int(r["sequence"])) for r in rows if not r["what"].startswith("made")] == [
        (joint, what, sequence)]
    summary = json.loads((tmp_path / "out" / "summary.json").read_text())
    assert summary["violations"][what] == 1 and not summary["passed"]
    # never followed: the stand-in's own layer brakes instead, and the motion it made keeps every limit
    assert report.refused.get("refused: over a limit", 0) == 1, report.refused
    assert not [v for v in report.violations if v.what.startswith("made")], report.describe()
    if what == "position":
        assert report.violations[0].limit == 4.0 and report.violations[0].value > 4.0
        assert report.worst["position"] > 1.0


def test_a_sequence_gap_checks_only_the_limits(model, tmp_path):
    points = motion(model, [[0, 1.0, 0]] * 3 + [[0, -1.0, 0]] * 6 + [[0, 1.0, 0]] * 3)  # from rest to rest
    kept = points[:2] + points[4:]  # 3 and 4 lost: 5 does not continue 2, and that is not a violation
    report, _, _ = serve(model, tmp_path, [protocol.pack(p) for p in kept])
    assert report.passed, report.describe()
    assert [e.what for e in report.events].count("bridged") == 1  # the drive followed 5 back over 3 and 4
    assert report.received == len(kept) and report.gaps == 1 and report.missing == 2
    assert json.loads((tmp_path / "out" / "summary.json").read_text())["gaps"] == 1


def test_invalid_datagrams_are_dropped_and_never_checked(model, tmp_path):
    good = motion(model, [[0, 0.0, 0]] * 3)  # at rest: the stream may end
    # every bad one would be a violation (track at 10 m) if it were checked as a setpoint
    bad = protocol.pack(setpoint(model, 2, [0.0, 10.0, 0.0], [0, 0, 0], [0, 0, 0], [0, 0, 0]))
    wrong_magic = struct.pack("<I", 0x12345678) + bad[4:]
    nan = bytearray(bad)
    nan[-8:] = struct.pack("<d", float("nan"))  # the cabin's jerk
    older = protocol.pack(setpoint(model, 1, [0.0, 10.0, 0.0], [0, 0, 0], [0, 0, 0], [0, 0, 0]))
    duplicate = bad  # sequence 2 again, once 2 was received
    host = protocol.pack(protocol.Motion(7, 0.0, np.zeros(6)))
    datagrams = [protocol.pack(good[0]), b"garbage", bad[:-5], wrong_magic, bytes(nan), b"",
                 protocol.pack(good[1]), duplicate, older, host, protocol.pack(good[2])]
    report, _, _ = serve(model, tmp_path, datagrams)
    assert report.passed and machine.exit_code(report) == 0, report.describe()
    assert report.received == 3 and report.gaps == 0 and report.datagrams == len(datagrams)
    assert report.dropped == {"truncated": 2, "length": 1, "magic": 1, "not finite": 1, "stale": 2, "kind": 1}
    assert report.worst["position"] < 0.01  # track near 0 m: nothing of the 10 m ones was measured
    rows = read_csv(tmp_path / "out" / "setpoints.csv")
    assert [int(r["sequence"]) for r in rows] == [1, 2, 3]
    summary = json.loads((tmp_path / "out" / "summary.json").read_text())
    assert summary["dropped"]["stale"] == 2 and summary["received"] == 3
    assert summary["dropped_sample"]["stale"] == ["setpoint sequence 2 after 2", "setpoint sequence 1 after 2"]


def test_it_stops_by_itself_after_idle_seconds_of_silence(model, tmp_path):
    report, elapsed, _ = serve(model, tmp_path, [protocol.pack(motion(model, [[0, 0, 0]])[0])], idle=0.5, duration=8.0)
    assert report.stopped == "idle" and report.received == 1
    assert 0.5 <= elapsed < 2.5


def test_it_stops_after_duration_without_any_datagram(model, tmp_path):
    report, elapsed, _ = serve(model, tmp_path, [], idle=0.1, duration=0.4)
    assert report.stopped == "duration" and report.received == 0 and report.passed
    assert 0.4 <= elapsed < 2.0
    assert (tmp_path / "out" / "summary.json").exists()


@pytest.mark.skipif(threading.current_thread() is not threading.main_thread(), reason="signals reach the main thread")
def test_an_interrupt_stops_the_machine_writes_what_it_has_and_returns(model, tmp_path):
    """SIGINT while the joints move: the fastest stop, the rest of the stream refused, and the run ends
    once the machine is at rest, its files whole."""
    points = brake_motion(model)

    def interrupt():
        os.kill(os.getpid(), signal.SIGINT)

    report, elapsed, _ = serve(model, tmp_path, [protocol.pack(p) for p in points[:21]], idle=LIMIT,
                               duration=LIMIT, name="cut", after=interrupt)
    assert report.stopped == "interrupted (SIGINT)" and elapsed < LIMIT - 1
    assert not report.ended_moving and [s.why for s in report.stops] == ["emergency stop (SIGINT to the stand-in)"]
    stop = report.stops[0]
    assert stop.rest is not None and stop.rest - stop.start <= stop.bound + 0.01
    assert report.passed and report.counts["made acceleration"] == 0, report.describe()
    assert len(read_csv(tmp_path / "cut" / "setpoints.csv")) == report.received
    assert json.loads((tmp_path / "cut" / "summary.json").read_text())["stopped"] == "interrupted (SIGINT)"


def test_it_refuses_a_folder_that_is_not_its_own(model, tmp_path):
    foreign = tmp_path / "foreign"
    foreign.mkdir()
    (foreign / "notes.txt").write_text("mine")
    with pytest.raises(ValueError, match="foreign"):
        machine.run(model, ("127.0.0.1", free_port()), foreign, idle=0.1, duration=0.2)
    assert sorted(p.name for p in foreign.iterdir()) == ["notes.txt"]
    with pytest.raises(ValueError, match="idle"):
        machine.run(model, ("127.0.0.1", free_port()), tmp_path / "new", idle=0.0, duration=0.2)


def test_a_cycle_is_checked_where_a_position_turns(model):
    # track from 3.98 m at 0.5 m/s braking at 5 m/s^2 over 0.17 s: it turns at 4.005 m after 0.1 s
    # and is back at 3.98 m and -0.35 m/s at the end: within range at both ends, not between
    sp = setpoint(model, 1, [0.0, 3.98, 0.0], [0, 0.5, 0], [0, -5.0, 0], [0, 0, 0], step=0.17)
    violations, use = machine.Checker(model).check(sp, None, 0.0)
    assert [(v.joint, v.what) for v in violations] == [("track", "position")]
    assert violations[0].value == pytest.approx(4.005, abs=1e-12) and violations[0].limit == 4.0
    assert "0.1 s into the cycle" in violations[0].detail
    assert use["position"][1] == pytest.approx(4.005 / 4.0, abs=1e-12) and use["acceleration"][1] == 1.0


def test_the_servo_follows_a_continuous_reference_exactly_and_a_jump_as_a_critically_damped_loop():
    """Against scipy's integration of e'' + 2 w e' + w^2 e = 0 after a jump, and the reference itself
    where it is continuous: y = r exactly (the delay is the drive's clock, not the servo's)."""
    from scipy.integrate import solve_ivp

    limits = servo.JointLimits(*(np.full(6, x) for x in (-np.inf, np.inf, 3.0, 2.0, 5.0)))
    omega = 2 * np.pi * 5.0
    q, qd, a, j = np.full(6, 0.3), np.zeros(6), np.zeros(6), np.full(6, 0.5)  # from where the joints stand
    joints = servo.Joints(q, limits, omega)
    joints.follow(0.0, q, qd, a, j)
    t = np.linspace(0.0, 0.5, 11)
    y, yd, ydd, yddd = joints.motion(t)
    ref_q, ref_qd = advance(q, qd, a, t[:, None], j)
    np.testing.assert_allclose(y, ref_q, atol=1e-15)
    np.testing.assert_allclose(yd, ref_qd, atol=1e-15)
    np.testing.assert_allclose(ydd, a + j * t[:, None], atol=1e-15)
    # a jump of the reference by 1 mm and 0.01 /s at 0.5 s: the error decays as the loop's ODE says
    joints.follow(0.5, ref_q[-1] + 1e-3, ref_qd[-1] + 1e-2, a + j * 0.5, j)
    s = np.linspace(0.0, 0.3, 7)
    y, yd, ydd, _ = joints.motion(0.5 + s)
    ode = solve_ivp(lambda _, x: [x[1], -2 * omega * x[1] - omega**2 * x[0]], (0, 0.3), [-1e-3, -1e-2], t_eval=s,
                    rtol=1e-11, atol=1e-14)
    rq, rqd = advance(ref_q[-1] + 1e-3, ref_qd[-1] + 1e-2, a + j * 0.5, s[:, None], j)
    np.testing.assert_allclose(y[:, 0] - rq[:, 0], ode.y[0], atol=1e-11)
    np.testing.assert_allclose(yd[:, 0] - rqd[:, 0], ode.y[1], atol=1e-9)


def test_a_plan_started_on_a_noisy_measurement_goes_over_the_jerk_limit_one_started_on_the_hold_does_not():
    """Why the service holds before it plans again (measured.SETTLE): a setpoint 1e-5 rad (the
    stand-in's noise) off where the joints stand is a step the servo takes with a jerk of 2 w^3 x the
    step (closed form, the error y - r = step decaying); started at the jerk limit, the motion made goes 10 % over it (the hour's soak:
    6.6-7.0 against 6.28). Held there first for SETTLE s, the same plan's start goes over by under 1 %."""
    from desdemona.service.measured import SETTLE

    limits = servo.JointLimits(*(np.full(6, x) for x in (-np.inf, np.inf, 1.0, 1.0, 2 * np.pi)))
    omega, step, zero = 2 * np.pi * servo.BANDWIDTH_HZ, 1e-5, np.zeros(6)
    at_limit = limits.jerk.copy()
    t = np.linspace(0.0, 0.1, 2001)

    joints = servo.Joints(np.zeros(6), limits, omega)
    joints.follow(0.0, zero - step, zero, zero, at_limit)  # the plan at once, from the measurement below
    jerk = joints.motion(t)[3]
    assert jerk[0, 0] == pytest.approx(at_limit[0] + 2 * omega**3 * step, rel=1e-12)
    assert np.max(np.abs(jerk)) > 1.09 * limits.jerk[0]

    joints = servo.Joints(np.zeros(6), limits, omega)
    joints.follow(0.0, zero - step, zero, zero, zero)  # the service's hold, there
    assert np.max(np.abs(joints.motion(t)[3])) == pytest.approx(2 * omega**3 * step, rel=1e-9)  # at rest: 10 %
    joints.follow(SETTLE, *joints.reference_at(SETTLE), at_limit)  # then the plan, on the reference it follows
    assert np.max(np.abs(joints.motion(SETTLE + t)[3])) < 1.01 * limits.jerk[0]


def test_the_brake_is_the_fastest_stop_within_the_limits():
    """From the arm at speed and accelerating: rest within the shortest stop of continuous time (plus
    a brake step's round-off), acceleration and jerk never beyond their limits, and the rate never
    turning back."""
    limits = servo.JointLimits.of(Model(config="dfs").params)
    joints = servo.Joints(np.zeros(6), limits, 2 * np.pi * 5.0)
    qd0, a0 = np.array([2.5, 0, 0, 1.0, -2.0, 0.5]), np.array([0.3, 0, 0, 0.5, 0.0, -1.0])
    joints.place(0.0, np.zeros(6), qd0, a0)
    bound = limits.stopping_time(qd0, a0)
    joints.brake(0.0)
    t, rates, accelerations = 0.0, [], []
    while not joints.brake_to(t) and t < 2 * bound:
        t += 0.01
        _, qd, a, _ = joints.now(t)
        rates.append(qd)
        accelerations.append(a)
    assert t <= bound + 0.02
    rates, accelerations = np.array(rates), np.array(accelerations)
    assert np.all(np.abs(accelerations) <= limits.acceleration * (1 + 1e-9))
    # never back through zero, but by the discrete brake's last steps (3e-4 rad/s seen: 0.02 deg/s)
    assert np.all(rates * np.sign(qd0) >= -1e-3)
    assert np.all(np.abs(np.diff(accelerations, axis=0)) <= limits.jerk * 0.01 * (1 + 1e-9))


def test_a_stream_that_ends_while_moving_is_braked_and_never_a_pass(model, tmp_path):
    """The setpoints stop with the track and yaw moving: the stand-in brakes to rest on its own within
    the shortest stop, keeps every limit, writes the motion to its last sample, and fails the run."""
    points = brake_motion(model)[:25]
    report, _, states = serve(model, tmp_path, [protocol.pack(p) for p in points])
    assert report.ended_moving and not report.passed and machine.exit_code(report) == 1
    assert [s.why for s in report.stops] == ["no setpoint in time while moving: braking on its own"]
    stop = report.stops[0]
    assert stop.rest is not None and stop.rest - stop.start <= stop.bound + 0.01
    assert report.counts == {k: 0 for k in machine.KINDS}, report.describe()
    rows = read_csv(tmp_path / "out" / "motion.csv")
    assert float(rows[-1]["t"]) >= stop.rest and abs(float(rows[-1]["track_rate"])) < 1e-3
    events = [r["what"] for r in read_csv(tmp_path / "out" / "events.csv")]
    assert events[:3] == ["following", "braking", "at rest"] and "stopped" in events
    statuses = [s.status for s in states if isinstance(s, protocol.MachineState)]
    assert statuses[0] in ("ready", "following") and "braking" in statuses and statuses[-1] == "stopped"
    summary = json.loads((tmp_path / "out" / "summary.json").read_text())
    assert summary["ended_moving"] and summary["own_stops"][0]["at_rest"] == stop.rest


def test_an_emergency_stop_command_stops_and_only_a_reset_clears_it(model, tmp_path):
    points = brake_motion(model)
    estop = protocol.pack(protocol.Command(1, 0.0, "emergency stop"))
    reset = protocol.pack(protocol.Command(2, 0.0, "reset"))
    stranger = protocol.pack(protocol.Command(3, 0.0, "reset"))
    extra = [(0.15, estop, None), (0.3, stranger, "127.0.0.2"), (0.45, reset, None)]
    report, _, states = serve(model, tmp_path, [protocol.pack(p) for p in points], extra=extra)
    assert [s.why for s in report.stops] == ["emergency stop (a Command)"]
    stop = report.stops[0]
    assert stop.rest is not None and stop.rest - stop.start <= stop.bound + 0.01
    assert report.refused.get("refused: e-stop", 0) > 0 and report.dropped == {"sender": 1}
    whats = [e.what for e in report.events]
    assert whats.index("e-stop") < whats.index("at rest") < whats.index("ready")  # reset once at rest
    assert not report.ended_moving and report.violation_count == 0, report.describe()
    statuses = [s.status for s in states]
    assert "e-stop" in statuses and statuses[-1] in ("ready", "following", "stopped")


def test_an_injected_fault_is_reported_with_its_joint_and_refuses_motion(model, tmp_path):
    points = brake_motion(model)
    options = machine.MachineOptions(timeout=10, late=8.0, fault=(0.2, JOINT_NAMES.index("track")))
    report, _, states = serve(model, tmp_path, [protocol.pack(p) for p in points], options=options)
    faults = [s for s in states if s.status == "fault"]
    assert faults and all(s.fault == "drive" and s.fault_joint == 1 for s in faults)
    assert [s.why for s in report.stops] == ["drive fault on track"] and report.refused.get("refused: fault", 0) > 0
    rows = read_csv(tmp_path / "out" / "motion.csv")
    assert rows[-1]["status"] == "fault" and rows[-1]["fault_joint"] == "1"


def test_when_setpoints_come_late_or_in_a_burst_is_a_timing_fault(model, tmp_path):
    points = motion(model, [[0, 0, 0]] * 20)  # at rest: only the timing is wrong
    at = [p.cycle_time + (4 * STEP if k >= 5 else 0.0) for k, p in enumerate(points)]  # 4 cycles late from 5 on
    for k in range(10, 15):
        at[k] = at[10]  # five at once
    options = machine.MachineOptions(timeout=6, late=1.5)
    report, _, _ = serve(model, tmp_path, [protocol.pack(p) for p in points], at=at, options=options)
    assert report.timing["late"] >= 1 and report.timing["burst"] == 1, report.describe()
    assert report.latest >= 3.5 * STEP and not report.passed
    assert report.counts == {k: 0 for k in machine.KINDS}


def test_setpoints_from_a_second_sender_are_dropped(model, tmp_path):
    points = motion(model, [[0, 0, 0]] * 5)
    intruder = protocol.pack(setpoint(model, 100, [0.0, 1.0, 0.0], [0, 0, 0], [0, 0, 0], [0, 0, 0]))
    report, _, _ = serve(model, tmp_path, [protocol.pack(p) for p in points], extra=[(0.02, intruder, "127.0.0.2")])
    assert report.dropped == {"sender": 1} and report.received == 5

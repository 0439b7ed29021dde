"""What the service takes of the machine's States (desdemona.service.measured): hostile or bad datagrams
dropped and counted, never acted on; the tracking error against the commanded motion where the State
says the joints were; the tolerances from the limits. No network: datagrams handed over directly."""

import struct

import numpy as np
import pytest

from desdemona.machine.model import Model
from desdemona.machine.plan import State
from desdemona.service import protocol
from desdemona.service.measured import BAND, CYCLES, MachineLink, commanded_at

MACHINE = ("127.0.0.1", 5501)
H = 0.02


@pytest.fixture(scope="module")
def model():
    return Model(config="dfs")


def state(model, sequence, q, qd, applied=1, applied_time=0.0, status="following"):
    cfg = model.config
    return protocol.MachineState(sequence, 0.01 * sequence, status, "none", None, applied, applied_time,
                                 cfg.expand(np.asarray(q, float)), cfg.expand(np.asarray(qd, float), "zero"))


def test_bad_and_hostile_states_are_dropped_and_counted_never_taken(model):
    link = MachineLink(model, H, MACHINE, lost_after=0.5)
    good = protocol.pack(state(model, 5, [0.1, 0, 0, 0], [1.0, 0, 0, 0]))
    nan = bytearray(good)
    struct.pack_into("<d", nan, 36, float("nan"))
    old_version = bytearray(good)
    struct.pack_into("<H", old_version, 4, 1)
    bad = [(good, ("10.0.0.9", 5501), "sender"), (good[:-3], MACHINE, "length"), (bytes(nan), MACHINE, "not finite"),
           (bytes(old_version), MACHINE, "version"),
           (protocol.pack(protocol.Command(1, 0.0, "reset")), MACHINE, "kind")]
    for data, sender, reason in bad:
        assert link.take(data, sender, 1.0) == reason
    assert link.newest is None and link.received == 0 and sum(link.dropped.values()) == len(bad)
    assert link.take(good, MACHINE, 1.0) == "" and link.newest.sequence == 5
    older = protocol.pack(state(model, 4, [9.0, 0, 0, 0], [0, 0, 0, 0]))
    assert link.take(older, MACHINE, 1.1) == "stale"
    assert link.newest.sequence == 5 and link.received == 1  # the older one was never taken
    assert not link.lost(1.4) and link.lost(1.6)


def test_the_tracking_error_is_taken_where_the_state_says_the_joints_were(model):
    """A machine that follows the commands exactly, 30 ms late, shows no error; one 0.01 rad off
    shows that, as its share of the tolerance (two cycles at the yaw's rate limit)."""
    n = model.n
    starts, u, jerks = [], [], []
    s = State(np.zeros(n), np.zeros(n), np.zeros(n))
    for _ in range(50):
        starts.append(s)
        u.append(s.a)
        jerks.append(np.r_[1.0, 0.0, 0.0, 0.0])
        s = s.advance(s.a, H, jerks[-1])
    commanded = commanded_at(starts, u, jerks, H)
    q, qd = commanded(0.47)  # where the commands had the joints 0.47 s on the setpoints' line
    link = MachineLink(model, H, MACHINE, lost_after=0.5)
    link.take(protocol.pack(state(model, 1, q, qd, applied=24, applied_time=0.47)), MACHINE, 0.5)
    tracking = link.tracking(commanded)
    assert tracking.use < 1e-12 and tracking.status == "following"
    link.take(protocol.pack(state(model, 2, q + np.r_[0.01, 0, 0, 0], qd, applied=24, applied_time=0.47)),
              MACHINE, 0.5)
    tracking = link.tracking(commanded)
    tolerance = CYCLES * H * model.limits.velocity[0]
    assert tracking.error[0][0] == pytest.approx(0.01) and tracking.use == pytest.approx(0.01 / tolerance)
    assert tracking.use > BAND  # beyond the noise: the next plan starts from the measured machine

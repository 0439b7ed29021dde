"""The service plans from the measured machine (issue of the machine in the loop, point 2): where the
machine is off the command within its tolerance, the cycle's state is carried to where it measurably
is, once. The States of setpoints already in flight were commanded on the line before the carry;
judged against it, they show the same error again, and carrying it each cycle would run the
commanded motion away from the machine (found in a soak on a loaded computer: a park that sped
the arm up)."""

import numpy as np
import pytest

from desdemona.machine.model import Model
from desdemona.machine.plan import State
from desdemona.service import protocol
from desdemona.service.measured import BAND, SETTLE, Tracking
from desdemona.service.serve import _Session

H = 0.02  # [s] the session's step
IN_FLIGHT = 4  # setpoints sent and not yet applied when a State is measured


class _Machine:
    """A machine that stands still ``offset`` [rad] off the service's first command on its first free
    joint; its States report the setpoint applied IN_FLIGHT cycles ago, and the tracking error
    against what the service commanded for that setpoint (as :meth:`MachineLink.tracking` measures it,
    only for setpoints at or after the session's ``trusted_from``)."""

    def __init__(self, session: _Session, offset: float):
        self.session, self.offset = session, offset
        self.commanded: list[float] = []  # the first free joint's commanded position per setpoint
        self.newest = None
        n = session.model.n
        self.tolerance = np.full(n, 1.0), np.full(n, 1.0)

    def lost(self, now: float) -> bool:
        return False

    def tracking(self, commanded) -> Tracking:
        applied = self.newest.applied
        error = np.zeros(self.session.model.n), np.zeros(self.session.model.n)
        if applied >= self.session.trusted_from:
            error[0][0] = self.offset - self.commanded[applied - 1]
        use = float(np.max(np.abs(error[0]) / self.tolerance[0]))
        return Tracking(error, use, "following", self.newest)

    def cycle(self, k: int) -> None:
        """The service sends setpoint k (its state's position), and a State comes back."""
        self.session.rows.append({})
        self.commanded.append(float(self.session.state.q[0]))
        applied = max(k - IN_FLIGHT, 1)
        self.newest = protocol.MachineState(k, k * H, "following", "none", None, applied, applied * H,
                                            np.zeros(6), np.zeros(6))


def test_an_offset_is_carried_once_not_every_cycle_it_stays_in_flight():
    model = Model(config="dfs")
    session = _Session(model, controller=None, h=H, guard_use=None)
    session.state = State(np.zeros(model.n), np.zeros(model.n), np.zeros(model.n))
    offset = 0.3  # within the tolerance (1), beyond the noise band: carried
    assert BAND < offset < 1.0
    machine = _Machine(session, offset)
    for k in range(1, 60):
        machine.cycle(k)
        assert session.observe(machine, k * H, k * H) == ""
    # the service's state is where the machine is, and stays there
    assert session.state.q[0] == offset
    assert session.reanchored == 1


class _StoppedMachine:
    """A machine that stopped on its own at ``where`` and reports it with noise; it follows the
    service's hold once told to (:meth:`follows`), IN_FLIGHT setpoints behind."""

    def __init__(self, session: _Session, where: np.ndarray, seed: int = 0):
        self.session, self.where, self.rng = session, where, np.random.default_rng(seed)
        self.status, self.newest, self.arrived = "braking", None, 0.0
        self.measurements: list[np.ndarray] = []

    def lost(self, now: float) -> bool:
        return False

    def tracking(self, commanded) -> Tracking:
        zero = np.zeros(self.session.model.n)
        return Tracking((zero, zero), 0.0, self.status, self.newest)

    def measured(self, now: float):
        return self.measurements[-1], np.zeros_like(self.where)

    def cycle(self, k: int) -> None:
        self.session.rows.append({})
        self.measurements.append(self.where + self.rng.normal(0.0, 1e-5, self.where.shape))
        applied = k - IN_FLIGHT if self.status == "following" else None
        self.newest = protocol.MachineState(k, k * H, self.status, "none", None, applied, 0.0,
                                            np.zeros(6), np.zeros(6))


def test_after_a_stop_of_its_own_the_service_plans_only_once_the_machine_has_followed_its_hold():
    """The machine braked on its own and stands (measured with noise): the service holds where it
    was last measured until the machine follows that hold, for SETTLE s; only then does it plan
    again, from the hold the machine follows (not from a newer noisy measurement: a plan started a
    noise's step off where the machine stands goes over the jerk limit,
    test_a_plan_started_on_a_noisy_measurement_goes_over_the_jerk_limit_one_started_on_the_hold_does_not)."""
    model = Model(config="full")

    class _Controller:
        def forget(self):
            pass

    session = _Session(model, controller=_Controller(), h=H, guard_use=None)
    where = np.linspace(0.1, 0.6, model.n)
    machine = _StoppedMachine(session, where)
    machine.cycle(1)
    assert session.observe(machine, H, H) == "the machine is braking"
    session.status = "parked"  # as park() leaves it at rest
    machine.status = "stopped"
    for k in range(2, 5):  # holding on its own: the hold moves to where it is measured
        machine.cycle(k)
        assert session.observe(machine, k * H, k * H) == "the machine is braking"
        np.testing.assert_array_equal(session.state.q, machine.measurements[-1])
    held, follows_from = session.state.q.copy(), session.trusted_from + IN_FLIGHT  # its first State about it
    machine.status = "following"  # it took the hold (a State about a setpoint before it is not counted)
    k += 1
    back = None
    for k in range(k, k + 40):
        machine.cycle(k)
        why = session.observe(machine, k * H, k * H)
        if not why:
            back = k
            break
        assert why == "the machine is braking"
        np.testing.assert_array_equal(session.state.q, held)  # followed: the hold no longer moves
    assert back is not None and (back - follows_from) * H == pytest.approx(SETTLE, abs=H)
    assert [e[1] for e in session.events][-1] == "machine back"
    np.testing.assert_array_equal(session.state.q, held)
    assert not np.array_equal(held, machine.measurements[-1])  # the newest measurement is not where it plans

"""The service plans from the measured machine (issue of the machine in the loop, point 2): where the
machine is off the command within its tolerance, the cycle's state is carried to where it measurably
is, once. The States of setpoints already in flight were commanded on the line before the carry;
judged against it, they show the same error again, and carrying it each cycle would run the
commanded motion away from the machine (found in a soak on a loaded computer: a park that sped
the arm up)."""

import numpy as np

from desdemona.machine.model import Model
from desdemona.machine.plan import State
from desdemona.service import protocol
from desdemona.service.measured import BAND, Tracking
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

"""The ``trajectory.csv`` of a served session written as it goes (:class:`LiveTrajectory`), so that a
service that is killed leaves a result folder ``plot``, ``view`` and ``compare`` read up to its last
written cycle (:func:`desdemona.results.folder.live_note` says how far).

One row per cycle from the first host message on: the commanded motion at the cycle's start (the
positions, rates and accelerations of :meth:`Setpoint <desdemona.service.protocol.Setpoint>`), what it
makes felt there (S, eq. 3.2) and the free joints' torques and power (eq. A.26), against what the host's
newest message asked for at that cycle (held until the next). The rows are computed and appended a
batch at a time (``every`` cycles, one write and one flush), after the cycle's setpoint has gone, so
the latency is not touched. No perceived columns: the vestibular filters belong to the whole run,
which replaces this file when the session ends (the judged trajectory on its fine grid)."""

from __future__ import annotations

import os

import numpy as np

from desdemona.check.simulate import Trajectory, trajectory_table

UNITS = "units: SI (s, rad, m, rad/s, m/s, rad/s^2, m/s^2, N*m, N, W); written as the session went"


def desired_of(values, aligned: bool) -> tuple[np.ndarray | None, float]:
    """(S_d (6,) or None, M_d) of a host message's ``values``: six channels as they are; a modulus alone
    along the cabin's +z on an ``aligned`` configuration (as
    :meth:`~desdemona.machine.configs.Configuration.cue_path` cues it), else only as M_d."""
    values = np.asarray(values, float)
    if len(values) == 6:
        return values, float(np.linalg.norm(values[3:]))
    if aligned:
        return np.r_[np.zeros(5), values[0]], float(values[0])
    return None, float(values[0])


class LiveTrajectory:
    """trajectory.csv of the session in ``model`` for a host sending ``channels`` values, appended every
    ``every`` cycles (:meth:`add`, :meth:`flush`)."""

    def __init__(self, model, channels: int, every: int = 5):
        self.model, self.every = model, max(1, int(every))
        self.with_S_d = channels == 6 or model.config.aligned
        self.rows: list[tuple] = []
        self.fd: int | None = None

    def begin(self, file) -> None:
        """Start ``file`` with the units and the column names (those of the whole result, less the
        perceived ones)."""
        names, _ = trajectory_table(self._trajectory([]), self.model.config)
        zero = np.zeros(self.model.n)
        self._trajectory([(0.0, zero, zero, zero, np.zeros(6), 0.0)])  # the first evaluation's cost: here, not in a cycle
        self.fd = os.open(file, os.O_WRONLY | os.O_CREAT | os.O_TRUNC, 0o644)
        os.write(self.fd, f"# {UNITS}\n{','.join(names)}\n".encode())

    def add(self, t: float, q, qd, qdd, desired) -> None:
        """The cycle at ``t`` [s]: its commanded q, qd, qdd (free joints) and the host's ``desired`` values."""
        self.rows.append((t, q, qd, qdd, *desired_of(desired, self.model.config.aligned)))
        if len(self.rows) >= self.every:
            self.flush()

    def flush(self) -> None:
        """The rows held so far, computed and appended in one write (a SIGKILL leaves whole rows)."""
        if not self.rows or self.fd is None:
            return
        _, table = trajectory_table(self._trajectory(self.rows), self.model.config)
        text = "".join(",".join(f"{v:.10g}" for v in row) + "\n" for row in table)
        os.write(self.fd, text.encode())
        self.rows = []

    def close(self) -> None:
        self.flush()
        if self.fd is not None:
            os.close(self.fd)
            self.fd = None

    def _trajectory(self, rows) -> Trajectory:
        n = self.model.n
        t = np.array([r[0] for r in rows], float)
        q, qd, qdd = (np.array([r[i] for r in rows], float).reshape(-1, n) for i in (1, 2, 3))
        S = self.model.S(q, qd, qdd).reshape(-1, 6) if rows else np.zeros((0, 6))
        tau = self.model.tau(q, qd, qdd).reshape(-1, n) if rows else np.zeros((0, n))
        S_d = np.array([r[4] for r in rows], float).reshape(-1, 6) if self.with_S_d else None
        return Trajectory(t=t, q=q, qd=qd, qdd=qdd, tau=tau, power=tau * qd, S=S, S_d=S_d,
                          M=np.linalg.norm(S[:, 3:], axis=1), M_d=np.array([r[5] for r in rows], float))

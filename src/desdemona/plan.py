"""A joint plan: piecewise-constant accelerations from an initial state (thesis 4.2, 5.3).

Every optimiser and controller of desdemona commands the free joints' accelerations qdd, held over
the intervals of a control grid. Between two nodes the motion is then the exact double integral::

    q(t_k + s) = q_k + qd_k s + qdd_k s^2 / 2,    qd(t_k + s) = qd_k + qdd_k s.

:func:`advance` is the one place this formula lives; it takes floats, NumPy arrays and CasADi symbols
alike, so the optimisers' transcription, the MPC's limit check, the plant simulation and the
independent check all use the same definition. :class:`Plan` is the value every off-line result,
closed-loop run and baseline returns: the grid, the initial state and the accelerations, evaluated at
any time with :meth:`Plan.at`.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np


def advance(q, qd, qdd, s):
    """Position and rate after ``s`` seconds with ``qdd`` held: the exact double integral.

    q, qd, qdd : (n,) or broadcastable arrays [rad | m, /s, /s^2], or CasADi expressions; s [s].
    Returns (q + qd s + qdd s^2 / 2, qd + qdd s).
    """
    return q + qd * s + 0.5 * qdd * s * s, qd + qdd * s


def node_states(q0, qd0, u, h) -> tuple[np.ndarray, np.ndarray]:
    """Positions and rates (N + 1, n) at the nodes of accelerations ``u`` (N, n) held for ``h`` [s]
    each (a scalar, or (N, 1) steps), from (q0, qd0): the intervals' :func:`advance` summed up."""
    u = np.asarray(u, dtype=float)
    qd = np.vstack([qd0, qd0 + np.cumsum(u * h, axis=0)])
    steps, _ = advance(0.0, qd[:-1], u, h)
    return np.vstack([q0, q0 + np.cumsum(steps, axis=0)]), qd


def start_state(state, n: int) -> tuple[np.ndarray, np.ndarray]:
    """(q0, qd0), each (n,), from ``state`` = (positions, rates) of n joints, or rest at the centre
    (zeros) where ``state`` is None. A clear error unless both are n finite numbers."""
    if state is None:
        return np.zeros(n), np.zeros(n)
    q0, qd0 = (np.asarray(v, dtype=float).reshape(-1) for v in state)
    if q0.shape != (n,) or qd0.shape != (n,) or not (np.all(np.isfinite(q0)) and np.all(np.isfinite(qd0))):
        raise ValueError(f"an initial state needs {n} finite positions and {n} finite rates, one per free joint")
    return q0, qd0


@dataclass(frozen=True, eq=False)
class Plan:
    """Accelerations ``u`` held per interval of ``t_nodes`` from the state (q0, qd0).

    t_nodes : (N + 1,) control grid [s]; q0, qd0 : (n,) initial positions and rates of the free joints;
    u : (N, n) joint accelerations, u[k] held from t_nodes[k] to t_nodes[k + 1].
    """

    t_nodes: np.ndarray
    q0: np.ndarray
    qd0: np.ndarray
    u: np.ndarray

    def __post_init__(self):
        for name in ("t_nodes", "q0", "qd0", "u"):
            object.__setattr__(self, name, np.asarray(getattr(self, name), dtype=float))
        if self.u.ndim != 2 or len(self.t_nodes) != len(self.u) + 1:
            raise ValueError(f"a plan needs (N + 1,) nodes and (N, n) accelerations, got "
                             f"{self.t_nodes.shape} and {self.u.shape}")

    @property
    def n(self) -> int:
        """Number of joints."""
        return self.u.shape[1]

    @property
    def duration(self) -> float:
        return float(self.t_nodes[-1] - self.t_nodes[0])

    def nodes(self) -> tuple[np.ndarray, np.ndarray]:
        """Positions and rates (N + 1, n) at the nodes, accumulated exactly."""
        return node_states(self.q0, self.qd0, self.u, np.diff(self.t_nodes)[:, None])

    def at(self, times) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Positions, rates and accelerations (K, n) at ``times`` (K,) [s].

        Each time belongs to the interval that starts at or before it (the last node to the last
        interval); it is reached from that interval's node state.
        """
        q_nodes, qd_nodes = self.nodes()
        times = np.asarray(times, dtype=float)
        k = np.clip(np.searchsorted(self.t_nodes, times, side="right") - 1, 0, len(self.u) - 1)
        qdd = self.u[k]
        q, qd = advance(q_nodes[k], qd_nodes[k], qdd, (times - self.t_nodes[k])[:, None])
        return q, qd, qdd

    def states(self) -> np.ndarray:
        """Node states (N + 1, 2n): positions then rates."""
        return np.hstack(self.nodes())

"""What one cycle of the on-line controller returns (:class:`Command`), and the horizon a session uses
by default (:func:`default_horizon`): values that :mod:`desdemona.control.mpc` produces and the
closed loop, the service and the reports read; what one of its solves gives (:class:`_Solved`)."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Literal, NamedTuple

import numpy as np


@dataclass(frozen=True)
class Command:
    """What one cycle returns: the joint accelerations of its steps, and why.

    sequence : (r, n) accelerations at the start of each step, r = ``options.replan_steps``;
    source : "mpc" (this cycle's plan), "shifted" (the previous plan), "brake" (no plan left);
    compute_time [s] of the cycle; reason : why a fallback was used ("" for "mpc");
    jerk : (r, n) the accelerations' rate of change over each step (None: held constant).
    """

    sequence: np.ndarray
    source: Literal["mpc", "shifted", "brake"]
    compute_time: float
    reason: str = ""
    jerk: np.ndarray | None = None

    @property
    def jerks(self) -> np.ndarray:
        """(r, n) jerks of the steps (zeros where the accelerations are held)."""
        return np.zeros_like(self.sequence) if self.jerk is None else self.jerk

    @property
    def qdd(self) -> np.ndarray:
        """(n,) the first step's accelerations."""
        return self.sequence[0]


def default_horizon(config) -> float:
    """The horizon a session uses when none is given [s]: 2 s where only the yaw and the gimbals
    move (dfs), 4 s where the track does, whose position must be planned further ahead than the cue
    (docs/benchmarks/default-horizon.md). A session's plans reach at least this far whatever the horizon
    (``MPCOptions.reach``)."""
    return 4.0 if config.moves_track else 2.0


class _Solved(NamedTuple):
    """What one solve of :class:`MPC` gives: the plan (accelerations, jerks) per interval, whether the
    solver succeeded, its time [s], the start's positions and (IPOPT only) the cost."""

    plan: tuple[np.ndarray, np.ndarray]
    success: bool
    elapsed: float
    start: np.ndarray
    cost: float | None

"""The Desdemona model for one configuration: every model function on the free joints only.

``Model(params, config)`` is the value every layer below the command line takes: the parameters and
the configuration, resolved once. Its CasADi Functions of the free joints (``model.functions``, built
once per parameters and configuration by :func:`desdemona.machine.dynamics.functions`) serve the optimisers
with exact derivatives.
Its methods evaluate the same Functions on floats, arrays or CasADi symbols.
"""

from __future__ import annotations

import functools
from dataclasses import dataclass

import casadi as ca
import numpy as np

from desdemona.machine import dynamics
from desdemona.machine.configs import Configuration, Limits, get_configuration
from desdemona.machine.params import MachineParams, default_params
from desdemona.machine.plan import advance
from desdemona.support.symbolic import call


@dataclass(frozen=True, init=False)
class Model:
    """Desdemona restricted to the free joints of a configuration.

    params : machine parameters (``params.simplified()`` for the thesis' simplified dynamics, 5.7).
    config : a :class:`Configuration` or its name (``dfs``, ``yaw-track``, ``yaw-track-cabin``, ``full``).

    Every method takes free-joint vectors: ``q, qd, qdd`` of shape (n,) or (N, n), or CasADi symbols.
    """

    params: MachineParams
    config: Configuration

    def __init__(self, params: MachineParams | None = None, config: str | Configuration = "full"):
        object.__setattr__(self, "params", default_params() if params is None else params)
        object.__setattr__(self, "config", get_configuration(config))

    @property
    def n(self) -> int:
        return self.config.n

    @property
    def functions(self) -> dict[str, ca.Function]:
        """CasADi Functions of the free joints: S, omega_cabin, f_cabin, modulus, tau, power, M, C, N,
        forward, kinetic_energy, potential_energy."""
        return dynamics.functions(self.params, self.config)

    @functools.cached_property
    def prismatic(self) -> np.ndarray:
        """(n,) True where a free joint moves along a line (the track, the heave), False where it turns."""
        prismatic = np.array([self.params.joints[i].kind == "prismatic" for i in self.config.free])
        prismatic.setflags(write=False)
        return prismatic

    @functools.cached_property
    def limits(self) -> Limits:
        """Limits of the free joints (SI): position_min/max, velocity, acceleration, effort, power.
        Built once (a controller reads them several times a cycle; building them took 0.07 ms), its
        arrays read-only, as every reader shares them."""
        limits = self.config.limits(self.params)
        for name in ("position_min", "position_max", "velocity", "acceleration", "effort", "power", "jerk"):
            getattr(limits, name).setflags(write=False)
        return limits

    def S(self, q, qd, qdd):
        """(6,) path (omega_cabin [rad/s], f_cabin [m/s^2]) in cabin coordinates (eq. 3.2)."""
        return call(self.functions["S"], q, qd, qdd)

    def omega_cabin(self, q, qd):
        """(3,) cabin angular velocity in cabin coordinates [rad/s]."""
        return call(self.functions["omega_cabin"], q, qd)

    def f_cabin(self, q, qd, qdd):
        """(3,) specific force at the head in cabin coordinates [m/s^2] (eq. A.18, A.19)."""
        return call(self.functions["f_cabin"], q, qd, qdd)

    def modulus(self, q, qd, qdd):
        """(1,) modulus of the specific force M = |f| [m/s^2] (eq. 7.2)."""
        return call(self.functions["modulus"], q, qd, qdd)

    def tau(self, q, qd, qdd):
        """(n,) free joints' torques and forces [N*m | N] (eq. A.26)."""
        return call(self.functions["tau"], q, qd, qdd)

    def power(self, q, qd, qdd):
        """(n,) free joints' power tau_i * qd_i [W] (section A.4)."""
        return call(self.functions["power"], q, qd, qdd)

    def mass_matrix(self, q):
        """(n, n) inertia of the free joints (eq. A.20)."""
        return call(self.functions["M"], q, matrix=True)

    def coriolis_matrix(self, q, qd):
        """(n, n) Coriolis matrix of the free joints (eq. A.23)."""
        return call(self.functions["C"], q, qd, matrix=True)

    def gravity_vector(self, q):
        """(n,) conservative forces on the free joints (eq. A.22)."""
        return call(self.functions["N"], q)

    def forward_dynamics(self, q, qd, tau):
        """(n,) free joints' accelerations for torques ``tau`` (eq. A.27)."""
        return call(self.functions["forward"], q, qd, tau)

    @functools.lru_cache(maxsize=8)
    def step_limit_use(self, h: float) -> ca.Function:
        """``(q, qd, qdd, jerk) -> use`` of every limit (1 = at the limit) over a step of ``h`` seconds
        from acceleration ``qdd`` changing at ``jerk``, at its ends and its middle: the guard a
        controller applies before it commands.

        Positions are cubics, rates parabolas and accelerations lines in time, torque and power smooth
        over the step: the independent check of :mod:`desdemona.check.simulate` verifies the whole run on a
        10x finer grid. A bounded position counts as 1 + how far outside its range, as a share of the
        range. Jerk counts where the machine limits it.
        """
        lim, n = self.limits, self.n
        q, qd, qdd, jerk = (ca.SX.sym(k, n) for k in ("q", "qd", "qdd", "jerk"))
        uses = []
        if lim.smooth:
            uses.append(ca.fabs(jerk) / ca.DM(lim.jerk))
        bounded = lim.bounded
        lo, hi = lim.position_min[bounded], lim.position_max[bounded]
        for s in (0.0, 0.5 * h, h):
            qs, qds = advance(q, qd, qdd, s, jerk)
            a = qdd + jerk * s
            tau = self.functions["tau"](qs, qds, a)
            uses += [ca.fabs(a) / ca.DM(lim.acceleration), ca.fabs(qds) / ca.DM(lim.velocity),
                     ca.fabs(tau) / ca.DM(lim.effort), ca.fabs(tau * qds) / ca.DM(lim.power)]
            if bounded:
                outside = ca.fmax(ca.DM(lo) - qs[bounded], qs[bounded] - ca.DM(hi)) / ca.DM(hi - lo)
                uses.append(1.0 + outside)
        return ca.Function("limit_use", [q, qd, qdd, jerk], [ca.vertcat(*uses)])

    def kinetic_energy(self, q, qd):
        return call(self.functions["kinetic_energy"], q, qd)

    def potential_energy(self, q):
        return call(self.functions["potential_energy"], q)

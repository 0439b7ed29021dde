"""Rigid-body dynamics of Desdemona by Euler-Lagrange (appendix A.4).

    tau = M(q) qdd + C(q, qd) qd + N(q)                                          (eq. A.26)

- M(q) = sum_i J_i^T G_i J_i (eq. A.20), with J_i the body Jacobian of frame i (twist order
  (omega, v), body coordinates) and G_i the body's generalised inertia about its frame origin, which
  carries the centre-of-mass offset (section A.5).
- N(q) = dV/dq with V = sum_i m_i g z_com,i(q) (eq. A.21, A.22): gravity acts through the heave and,
  with off-centre masses, through the gimbals.
- C(q, qd) from the Christoffel symbols of M (eq. A.23), so that M_dot - 2C is skew-symmetric.
- Joint power P_i = tau_i qd_i (section A.4); forward dynamics qdd = M^-1 (tau - C qd - N) by a linear
  solve (eq. A.27).

All functions take the full six-joint state (floats, (N, 6) arrays or CasADi symbols) and a
:class:`~desdemona.params.MachineParams`; :class:`desdemona.model.Model` restricts them to the free
joints of a configuration. The thesis' simplified dynamics (section 5.7) is ``params.simplified()``.
"""

from __future__ import annotations

import functools

import casadi as ca

from desdemona._casadi import call
from desdemona.kinematics import N_JOINTS, angular_velocities, frames
from desdemona.params import MachineParams


@functools.lru_cache(maxsize=None)
def dynamics_functions(params: MachineParams) -> dict[str, ca.Function]:
    """CasADi Functions of the full chain: ``M(q)``, ``C(q, qd)``, ``N(q)``, ``tau(q, qd, qdd)``,
    ``kinetic_energy(q, qd)``, ``potential_energy(q)``, ``forward(q, qd, tau)``."""
    q, qd, qdd, tau = (ca.SX.sym(name, N_JOINTS) for name in ("q", "qd", "qdd", "tau"))
    chain = frames(q)
    omegas = angular_velocities(q, qd)
    M = ca.SX.zeros(N_JOINTS, N_JOINTS)
    V = 0
    for (R, p), omega, body in zip(chain, omegas, params.bodies):
        twist = ca.vertcat(R.T @ omega, R.T @ ca.jtimes(p, q, qd))  # body twist (omega, v), eq. A.12
        J = ca.jacobian(twist, qd)  # twist is linear in qd: this is the body Jacobian
        M += J.T @ ca.DM(body.spatial_inertia()) @ J
        com_world = p + R @ ca.DM(body.com)
        V += body.mass * params.gravity * com_world[2]
    M = 0.5 * (M + M.T)  # exact already; removes round-off asymmetry of the summed products
    N = ca.gradient(V, q)
    # Christoffel symbols of the first kind (eq. A.23): C_ij = sum_k c_ijk qd_k.
    dM = [ca.jacobian(M[:, j], q) for j in range(N_JOINTS)]  # dM[j][i, k] = dM_ij / dq_k
    C = ca.SX.zeros(N_JOINTS, N_JOINTS)
    for i in range(N_JOINTS):
        for j in range(N_JOINTS):
            C[i, j] = 0.5 * sum((dM[j][i, k] + dM[k][i, j] - dM[j][k, i]) * qd[k] for k in range(N_JOINTS))
    T = 0.5 * qd.T @ M @ qd
    tau_expr = M @ qdd + C @ qd + N
    forward = ca.solve(M, tau - C @ qd - N)
    return {
        "M": ca.Function("M", [q], [M], ["q"], ["M"]),
        "C": ca.Function("C", [q, qd], [C], ["q", "qd"], ["C"]),
        "N": ca.Function("N", [q], [N], ["q"], ["N"]),
        "tau": ca.Function("tau", [q, qd, qdd], [tau_expr], ["q", "qd", "qdd"], ["tau"]),
        "kinetic_energy": ca.Function("kinetic_energy", [q, qd], [T], ["q", "qd"], ["T"]),
        "potential_energy": ca.Function("potential_energy", [q], [V], ["q"], ["V"]),
        "forward": ca.Function("forward", [q, qd, tau], [forward], ["q", "qd", "tau"], ["qdd"]),
    }


def mass_matrix(q, params: MachineParams):
    """(6, 6) joint-space inertia M(q) (eq. A.20). q : (6,) [rad | m]. Units kg, kg*m, kg*m^2."""
    return call(dynamics_functions(params)["M"], q, matrix=True)


def coriolis_matrix(q, qd, params: MachineParams):
    """(6, 6) Coriolis and centrifugal matrix C(q, qd) of eq. A.23 (Christoffel form)."""
    return call(dynamics_functions(params)["C"], q, qd, matrix=True)


def gravity_vector(q, params: MachineParams):
    """(6,) conservative joint forces N(q) = dV/dq (eq. A.22) [N*m | N]."""
    return call(dynamics_functions(params)["N"], q)


def inverse_dynamics(q, qd, qdd, params: MachineParams):
    """(6,) or (N, 6) joint torques and forces tau = M qdd + C qd + N (eq. A.26) [N*m | N]."""
    return call(dynamics_functions(params)["tau"], q, qd, qdd)


def forward_dynamics(q, qd, tau, params: MachineParams):
    """(6,) joint accelerations qdd = M^-1 (tau - C qd - N) (eq. A.27), by a linear solve."""
    return call(dynamics_functions(params)["forward"], q, qd, tau)


def kinetic_energy(q, qd, params: MachineParams):
    """Kinetic energy 1/2 qd^T M(q) qd [J]."""
    return call(dynamics_functions(params)["kinetic_energy"], q, qd)


def potential_energy(q, params: MachineParams):
    """Potential energy V(q) = sum_i m_i g z_com,i (eq. A.21) [J]."""
    return call(dynamics_functions(params)["potential_energy"], q)

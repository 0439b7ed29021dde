"""Rigid-body dynamics of Desdemona by Euler-Lagrange (appendix A.4).

    tau = M(q) qdd + C(q, qd) qd + N(q)                                          (eq. A.26)

- M(q) = sum_i J_i^T G_i J_i (eq. A.20), with J_i the body Jacobian of frame i (twist order
  (omega, v), body coordinates) and G_i the body's generalised inertia about its frame origin, which
  carries the centre-of-mass offset (section A.5).
- N(q) = dV/dq with V = sum_i m_i g z_com,i(q) (eq. A.21, A.22): gravity acts through the heave and,
  with off-centre masses, through the gimbals.
- tau from Lagrange's equation (eq. A.24, A.25) by automatic differentiation of the Lagrangian:
  tau = d/dt dL/dqd - dL/dq = M qdd + (dM/dq . qd) qd - d(qd^T M qd / 2)/dq + dV/dq, which equals
  eq. A.26 and is a third the size of the Christoffel-matrix product, which matters inside optimisers.
- C(q, qd) from the Christoffel symbols of M (eq. A.23), so that M_dot - 2C is skew-symmetric.
- Joint power P_i = tau_i qd_i (section A.4); forward dynamics qdd = M^-1 (tau - C qd - N) by a linear
  solve (eq. A.27).

:func:`functions` builds every model function of a configuration once (cached per parameters and
configuration): the held joints enter as constants. The module-level functions below take the full
six-joint state (floats, (N, 6) arrays or CasADi symbols) and a :class:`~desdemona.machine.params.MachineParams`;
:class:`desdemona.machine.model.Model` evaluates the same Functions on the free joints of a configuration. The thesis' simplified dynamics (section 5.7) is ``params.simplified()``.
"""

from __future__ import annotations

import functools

import casadi as ca

from desdemona.machine.configs import CONFIGURATIONS, Configuration
from desdemona.machine.kinematics import body_motion, frames, path_expression
from desdemona.machine.params import MachineParams
from desdemona.support.symbolic import call


def energy_expressions(q, qd, Q, Qd, params: MachineParams) -> tuple[ca.SX, ca.SX]:
    """Mass matrix M (eq. A.20) and potential energy V (eq. A.21) as SX expressions.

    q, qd : SX symbols of the moving joints; Q, Qd : (6,) joint positions and rates as expressions of
    them (held joints constant, at rest). M is n x n in the moving joints.
    """
    n = q.numel()
    M = ca.SX.zeros(n, n)
    V = 0
    for (R, p), motion, body in zip(frames(Q), body_motion(Q, Qd), params.bodies):
        J = ca.jacobian(ca.vertcat(motion["omega"], motion["v"]), qd)  # body Jacobian (twist is linear in qd)
        M += J.T @ ca.DM(body.spatial_inertia()) @ J
        V += body.mass * params.gravity * (p + R @ ca.DM(body.com))[2]
    return 0.5 * (M + M.T), V  # symmetric already; removes round-off asymmetry of the summed products


def christoffel_matrix(M, q, qd) -> ca.SX:
    """Coriolis matrix of eq. A.23: C_ij = 1/2 sum_k (dM_ij/dq_k + dM_ik/dq_j - dM_kj/dq_i) qd_k."""
    n = q.numel()
    dM = [ca.jacobian(M[:, j], q) for j in range(n)]  # dM[j][i, k] = dM_ij / dq_k
    C = ca.SX.zeros(n, n)
    for i in range(n):
        for j in range(n):
            C[i, j] = 0.5 * sum((dM[j][i, k] + dM[k][i, j] - dM[j][k, i]) * qd[k] for k in range(n))
    return C


@functools.lru_cache(maxsize=None)
def functions(params: MachineParams, config: Configuration) -> dict[str, ca.Function]:
    """Every model function on the free joints of ``config``, built once per (params, config).

    CasADi Functions of the free joints: ``S``, ``omega_cabin``, ``f_cabin``, ``modulus`` (kinematics,
    eq. A.18, A.19, 7.2), ``tau``, ``power`` (eq. A.26), ``M``, ``C``, ``N`` (eq. A.20-A.23),
    ``forward`` (eq. A.27), ``kinetic_energy``, ``potential_energy``. The ``full`` configuration gives
    the whole chain.
    """
    n = config.n
    q, qd, qdd, tau = (ca.SX.sym(name, n) for name in ("q", "qd", "qdd", "tau"))
    # Build on the reduced chain directly: held joints enter as constants, so their terms fold away
    # and the expressions the optimisers differentiate stay small.
    Q, Qd, Qdd = config.expand(q), config.expand(qd, "zero"), config.expand(qdd, "zero")
    S = path_expression(Q, Qd, Qdd, params.gravity, params.head_offset)
    M, V = energy_expressions(q, qd, Q, Qd, params)
    # Lagrange's equation in the free joints: the rows of eq. A.26 with held joints at rest.
    torque = lagrange_torque(M, V, q, qd, qdd)
    bias = lagrange_torque(M, V, q, qd, ca.SX.zeros(n))
    expressions = {
        "S": ([q, qd, qdd], S),
        "omega_cabin": ([q, qd], S[:3]),
        "f_cabin": ([q, qd, qdd], S[3:]),
        "modulus": ([q, qd, qdd], ca.norm_2(S[3:])),
        "tau": ([q, qd, qdd], torque),
        "power": ([q, qd, qdd], torque * qd),
        "M": ([q], M),
        "C": ([q, qd], christoffel_matrix(M, q, qd)),
        "N": ([q], ca.gradient(V, q)),
        "forward": ([q, qd, tau], ca.solve(M, tau - bias)),
        "kinetic_energy": ([q, qd], 0.5 * qd.T @ M @ qd),
        "potential_energy": ([q], V),
    }
    names = {"q": q, "qd": qd, "qdd": qdd, "tau": tau}
    result = {}
    for name, (args, expr) in expressions.items():
        arg_names = [next(k for k, v in names.items() if v is a) for a in args]
        result[name] = ca.Function(name, args, [expr], arg_names, [name])
    return result


def _whole_chain(params: MachineParams) -> dict[str, ca.Function]:
    return functions(params, CONFIGURATIONS["full"])


def lagrange_torque(M, V, q, qd, qdd):
    """tau = d/dt (dL/dqd) - dL/dq for L = qd^T M(q) qd / 2 - V(q) (eq. A.24, A.25), as SX expressions.

    M : (n, n) and V : scalar expressions of the SX symbol q; qd, qdd : SX symbols or expressions.
    """
    momentum = M @ qd
    return ca.cse(M @ qdd + ca.jtimes(momentum, q, qd) - ca.gradient(0.5 * ca.dot(qd, momentum), q)
                  + ca.gradient(V, q))


def mass_matrix(q, params: MachineParams):
    """(6, 6) joint-space inertia M(q) (eq. A.20). q : (6,) [rad | m]. Units kg, kg*m, kg*m^2."""
    return call(_whole_chain(params)["M"], q, matrix=True)


def coriolis_matrix(q, qd, params: MachineParams):
    """(6, 6) Coriolis and centrifugal matrix C(q, qd) of eq. A.23 (Christoffel form)."""
    return call(_whole_chain(params)["C"], q, qd, matrix=True)


def gravity_vector(q, params: MachineParams):
    """(6,) conservative joint forces N(q) = dV/dq (eq. A.22) [N*m | N]."""
    return call(_whole_chain(params)["N"], q)


def inverse_dynamics(q, qd, qdd, params: MachineParams):
    """(6,) or (N, 6) joint torques and forces tau = M qdd + C qd + N (eq. A.26) [N*m | N]."""
    return call(_whole_chain(params)["tau"], q, qd, qdd)


def forward_dynamics(q, qd, tau, params: MachineParams):
    """(6,) joint accelerations qdd = M^-1 (tau - C qd - N) (eq. A.27), by a linear solve."""
    return call(_whole_chain(params)["forward"], q, qd, tau)


def kinetic_energy(q, qd, params: MachineParams):
    """Kinetic energy 1/2 qd^T M(q) qd [J]."""
    return call(_whole_chain(params)["kinetic_energy"], q, qd)


def potential_energy(q, params: MachineParams):
    """Potential energy V(q) = sum_i m_i g z_com,i (eq. A.21) [J]."""
    return call(_whole_chain(params)["potential_energy"], q)

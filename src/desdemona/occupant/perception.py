"""Vestibular perception models: semicircular canals and otoliths (thesis chapter 6).

A :class:`VestibularModel` maps the path ``S = (omega_cabin, f_cabin)`` at the head to the *perceived*
path: three canal channels (roll x, pitch y, yaw z; input angular velocity [rad/s]) and three otolith
channels (x, y, z; input specific force [m/s^2]), each a linear single-input single-output filter
applied per axis. Every channel is a transfer function in factored form::

    H(s) = gain * s^k * prod_i (1 + tau_zero_i s) / prod_j (1 + tau_pole_j s)

available as a continuous state-space system, exactly discretised with a zero-order hold, applied to a
whole S time series, and as CasADi expressions whose states an optimiser can carry.

Parameter sets (all normalised so perceived = actual where the sense works, see below):

- ``thesis`` (the thesis' own, section 6.3-6.4):
  otoliths eq. 6.5 with table 6.2: K (1 + tau_n s) / ((1 + tau_1 s)(1 + tau_2 s)), tau_n = 1 s,
  tau_1 = 0.5 s, tau_2 = 0.016 s; scaled to unit gain as omega -> 0 as the thesis does (K = 3.4 ips
  per m/s^2 becomes 1), so a steady specific force is perceived as it is.
  Canals eq. 6.2/6.3 with table 6.1: K (1 + tau_L s) / ((1 + tau_1 s)(1 + tau_2 s)) from angular
  acceleration, times the lead filter s / (s / alpha + 1) that turns angular velocity into the canal
  input; tau_L = 0.11 s, tau_1 = 5.9 s, tau_2 = 0.005 s, alpha a parameter (default 500 rad/s, above
  the simulator's bandwidth as the thesis asks). The canal's gain from angular velocity is zero at DC
  (a constant rotation is not felt), so "unit gain as omega -> 0" cannot hold; we choose K = tau_1,
  which makes the velocity gain 1 on the plateau 1/tau_1 << omega << 1/tau_L where the canals act as
  angular-velocity sensors. A perceived rotation is then in rad/s, on the same scale as the otolith
  channels' m/s^2 and as the Telban-Cardullo canal below, whose mid-band gain is 1 by construction.
- ``telban-cardullo``: canals tau_L tau_A s^2 / ((1 + tau_L s)(1 + tau_S s)(1 + tau_A s)) with
  tau_L = 6.1 / 5.3 / 10.2 s (roll / pitch / yaw), tau_S = 0.1 s and adaptation tau_A = 30 s; otoliths
  after Young & Meiry, K (1 + tau_A s) / ((1 + tau_L s)(1 + tau_S s)) with K = 0.4, tau_A = 13.2 s,
  tau_L = 5.33 s, tau_S = 0.66 s, scaled to unit DC gain (``normalised=False`` keeps K = 0.4).
  Source: R. J. Telban and F. M. Cardullo, "Motion cueing algorithm development: human-centered
  linear and nonlinear approaches", NASA CR-2005-213747, 2005; L. R. Young and J. L. Meiry, "A
  revised dynamic otolith model", Aerospace Medicine 39, 1968.

- ``canals``: the thesis canal's adaptation alone, tau_1 s / (1 + tau_1 s) with tau_1 = 5.9 s, and the
  otoliths transparent (:func:`canals_model`): what an on-line plan can carry cheaply.

Perception thresholds (:data:`THRESHOLDS`): angular velocity 3.0 / 3.6 / 2.6 deg/s (roll / pitch /
yaw), specific force 0.17 / 0.17 / 0.28 m/s^2 (x / y / z), from D. B. Reid and M. A. Nahon, "Flight
simulation motion-base drive algorithms, part 1", UTIAS report 296, 1985, as used by Telban and Cardullo.
"""

from __future__ import annotations

import functools
import math
from dataclasses import dataclass

import casadi as ca
import numpy as np
import scipy.linalg
import scipy.signal

CHANNEL_NAMES = ("canal roll (x)", "canal pitch (y)", "canal yaw (z)",
                 "otolith x", "otolith y", "otolith z")

#: Perception thresholds per channel of S: [rad/s] x3, [m/s^2] x3 (Reid & Nahon 1985).
THRESHOLDS = np.array([math.radians(3.0), math.radians(3.6), math.radians(2.6), 0.17, 0.17, 0.28])


@dataclass(frozen=True)
class Channel:
    """One SISO vestibular filter, H(s) = gain s^k prod(1 + tz s) / prod(1 + tp s).

    gain : the gain in front [output unit / input unit * s^k]; s_power : k >= 0;
    zeros, poles : time constants [s] of the first-order factors, all > 0.
    """

    name: str
    gain: float
    s_power: int
    zeros: tuple[float, ...]
    poles: tuple[float, ...]

    def __post_init__(self):
        for label, taus in (("zero", self.zeros), ("pole", self.poles)):
            for tau in taus:
                if not (math.isfinite(tau) and tau > 0.0):
                    raise ValueError(f"{self.name}: {label} time constant {tau!r} s must be a positive number")
        if not math.isfinite(self.gain) or self.gain == 0.0:
            raise ValueError(f"{self.name}: gain {self.gain!r} must be finite and non-zero")
        if self.s_power + len(self.zeros) > len(self.poles):
            raise ValueError(f"{self.name}: improper transfer function (more zeros than poles)")

    def frequency_response(self, w) -> np.ndarray:
        """H(j w) from the factored form, w [rad/s] (array)."""
        s = 1j * np.asarray(w, dtype=float)
        h = self.gain * s ** self.s_power
        for tau in self.zeros:
            h = h * (1.0 + tau * s)
        for tau in self.poles:
            h = h / (1.0 + tau * s)
        return h

    def polynomials(self) -> tuple[np.ndarray, np.ndarray]:
        """Numerator and denominator coefficients in s, highest power first."""
        num = np.array([self.gain])
        for tau in self.zeros:
            num = np.polymul(num, [tau, 1.0])
        num = np.polymul(num, np.r_[1.0, np.zeros(self.s_power)])
        den = np.array([1.0])
        for tau in self.poles:
            den = np.polymul(den, [tau, 1.0])
        return num, den

    def state_space(self) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
        """Continuous (A, B, C, D) realisation, scaled to unit leading denominator coefficient; a
        static channel (no poles: H = gain) has no state."""
        if not self.poles:
            return np.zeros((0, 0)), np.zeros((0, 1)), np.zeros((1, 0)), np.array([[self.gain]])
        num, den = self.polynomials()
        return scipy.signal.tf2ss(num / den[0], den / den[0])

    def step_response(self, t) -> np.ndarray:
        """Analytic continuous step response at times t >= 0, by partial fractions of H(s)/s.

        Valid for distinct poles; used to check the discretisation.
        """
        t = np.asarray(t, dtype=float)
        poles = [-1.0 / tau for tau in self.poles]
        y = np.full_like(t, self.frequency_response(0.0).real if self.s_power == 0 else 0.0)
        for i, p in enumerate(poles):
            # residue of H(s)/s at s = p: (1 + tau_i s) = tau_i (s - p)
            rest = self.gain * p ** (self.s_power - 1) / self.poles[i]
            for tau in self.zeros:
                rest *= 1.0 + tau * p
            for j, tau in enumerate(self.poles):
                if j != i:
                    rest /= 1.0 + tau * p
            y = y + rest * np.exp(p * t)
        return y


@dataclass(frozen=True)
class DiscreteSystem:
    """x[k+1] = Ad x[k] + Bd u[k], y[k] = C x[k] + D u[k]: all six channels, block diagonal.

    u, y : (6,) S and perceived S; x : (nx,) the filters' states; dt : step [s].
    """

    Ad: np.ndarray
    Bd: np.ndarray
    C: np.ndarray
    D: np.ndarray
    dt: float

    def steady_gain(self) -> np.ndarray:
        """(nx, 6) matrix G with x = G u the state a constant input u holds still (x = Ad x + Bd u)."""
        return np.linalg.solve(np.eye(len(self.Ad)) - self.Ad, self.Bd)

    def steady_state(self, u) -> np.ndarray:
        """The state that a constant input ``u`` holds still."""
        return self.steady_gain() @ np.asarray(u, dtype=float)

    def simulate(self, u, x0=None) -> tuple[np.ndarray, np.ndarray]:
        """Outputs (N, 6) and states (N + 1, nx) for inputs u (N, 6), from x0 (default: steady for u[0])."""
        u = np.asarray(u, dtype=float)
        x = self.steady_state(u[0]) if x0 is None else np.asarray(x0, dtype=float)
        states = np.empty((len(u) + 1, len(self.Ad)))
        states[0] = x
        a = np.diag(self.Ad)
        if np.array_equal(self.Ad, np.diag(a)):
            # uncoupled states (first-order channels): one recursion per state, not one step per sample
            drive = u @ self.Bd.T
            for i, decay in enumerate(a):
                states[1:, i] = scipy.signal.lfilter([1.0], [1.0, -decay], drive[:, i], zi=[decay * x[i]])[0]
        else:
            for k in range(len(u)):
                states[k + 1] = self.Ad @ states[k] + self.Bd @ u[k]
        y = states[:-1] @ self.C.T + u @ self.D.T
        return y, states

    def casadi_step(self) -> ca.Function:
        """CasADi Function ``(x, u) -> (x_next, y)``, for optimisers that carry the filter states."""
        x, u = ca.SX.sym("x", len(self.Ad)), ca.SX.sym("u", 6)
        return ca.Function("perception_step", [x, u],
                           [ca.DM(self.Ad) @ x + ca.DM(self.Bd) @ u, ca.DM(self.C) @ x + ca.DM(self.D) @ u],
                           ["x", "u"], ["x_next", "y"])


@dataclass(frozen=True)
class VestibularModel:
    """Six channels in the order of S: canals (roll x, pitch y, yaw z), otoliths (x, y, z).

    thresholds : (6,) the smallest perceived difference a person notices per channel [rad/s] x3,
    [m/s^2] x3; by default those of Reid & Nahon (:data:`THRESHOLDS`).
    """

    name: str
    channels: tuple[Channel, ...]
    thresholds: tuple[float, ...] = tuple(THRESHOLDS)

    def state_space(self) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
        """Continuous block-diagonal (A, B, C, D) from S (6,) to perceived S (6,)."""
        parts = [c.state_space() for c in self.channels]
        A = scipy.linalg.block_diag(*[p[0] for p in parts])
        B = scipy.linalg.block_diag(*[p[1] for p in parts])
        C = scipy.linalg.block_diag(*[p[2] for p in parts])
        D = scipy.linalg.block_diag(*[p[3] for p in parts])
        return A, B, C, D

    @property
    def n_states(self) -> int:
        return sum(len(c.poles) for c in self.channels)

    @property
    def diagonal(self) -> bool:
        """Whether every channel is static or of first order, so that its states do not couple and
        the discretisation has a closed form in the step (:meth:`casadi_discrete`)."""
        return all(len(c.poles) <= 1 for c in self.channels)

    def casadi_discrete(self, dt) -> tuple[ca.SX, ca.SX]:
        """(Ad, Bd) of :meth:`discretize` as CasADi expressions of the step ``dt`` (a symbol), for a
        :attr:`diagonal` model: x' = a x + b u holds over dt as x+ = e^(a dt) x + (e^(a dt) - 1) / a b u."""
        if not self.diagonal:
            raise ValueError(f"perception model {self.name!r}: a step that varies needs first-order channels")
        A, B, _, _ = self.state_space()
        a = np.diag(A)
        decay = ca.exp(ca.DM(a) * dt)
        return ca.diag(decay), ca.diag((decay - 1.0) / ca.DM(a)) @ ca.DM(B)

    @functools.lru_cache(maxsize=8)
    def discretize(self, dt: float) -> DiscreteSystem:
        """Exact zero-order-hold discretisation at step ``dt`` [s] (matrix exponential)."""
        if not (math.isfinite(dt) and dt > 0.0):
            raise ValueError(f"step dt = {dt!r} s must be a positive number")
        A, B, C, D = self.state_space()
        nx, nu = B.shape
        block = np.zeros((nx + nu, nx + nu))
        block[:nx, :nx], block[:nx, nx:] = A, B
        E = scipy.linalg.expm(block * dt)
        return DiscreteSystem(Ad=E[:nx, :nx], Bd=E[:nx, nx:], C=C, D=D, dt=float(dt))

    def casadi_ode(self) -> ca.Function:
        """CasADi Function ``(x, u) -> (x_dot, y)`` of the continuous model, for integrators."""
        A, B, C, D = (ca.DM(m) for m in self.state_space())
        x, u = ca.SX.sym("x", self.n_states), ca.SX.sym("u", 6)
        return ca.Function("perception_ode", [x, u], [A @ x + B @ u, C @ x + D @ u],
                           ["x", "u"], ["x_dot", "y"])

    def perceive(self, S, dt: float, x0=None) -> np.ndarray:
        """Perceived path (N, 6) of a path S (N, 6) sampled at step dt [s], inputs held over each step.

        The filters start in the steady state of S[0] unless ``x0`` is given, so a level cabin at
        rest (f = (0, 0, g)) perceives exactly that from the first sample.
        """
        S = np.asarray(S, dtype=float)
        if S.ndim != 2 or S.shape[1] != 6:
            raise ValueError(f"S has shape {S.shape}, expected (N, 6)")
        return self.discretize(dt).simulate(S, x0)[0]


def thesis_model(alpha: float = 500.0) -> VestibularModel:
    """The thesis' canals (eq. 6.3, table 6.1) and otoliths (eq. 6.5, table 6.2), normalised.

    alpha : pole of the lead filter s / (s / alpha + 1) [rad/s], above the simulator's bandwidth.
    """
    if not (math.isfinite(alpha) and alpha > 0.0):
        raise ValueError(f"lead filter alpha = {alpha!r} rad/s must be a positive number")
    tau_L, tau_1, tau_2 = 0.11, 5.9, 0.005
    canals = tuple(Channel(CHANNEL_NAMES[i], gain=tau_1, s_power=1, zeros=(tau_L,),
                           poles=(tau_1, tau_2, 1.0 / alpha)) for i in range(3))
    otoliths = tuple(Channel(CHANNEL_NAMES[3 + i], gain=1.0, s_power=0, zeros=(1.0,), poles=(0.5, 0.016))
                     for i in range(3))
    return VestibularModel("thesis", canals + otoliths)


def telban_cardullo_model(normalised: bool = True) -> VestibularModel:
    """Telban-Cardullo canals and Young-Meiry otoliths (NASA CR-2005-213747)."""
    tau_S, tau_A = 0.1, 30.0
    canals = tuple(Channel(CHANNEL_NAMES[i], gain=tau_L * tau_A, s_power=2, zeros=(),
                           poles=(tau_L, tau_S, tau_A)) for i, tau_L in enumerate((6.1, 5.3, 10.2)))
    K = 1.0 if normalised else 0.4
    otoliths = tuple(Channel(CHANNEL_NAMES[3 + i], gain=K, s_power=0, zeros=(13.2,), poles=(5.33, 0.66))
                     for i in range(3))
    return VestibularModel("telban-cardullo", canals + otoliths)


def canals_model(tau: float = 5.9) -> VestibularModel:
    """The canals' adaptation alone: tau s / (1 + tau s) per axis, the otoliths transparent.

    The thesis' canal (eq. 6.3, table 6.1) with its dominant time constant tau_1 = 5.9 s kept and the
    rest left out: the zero at tau_L = 0.11 s and the poles at 0.005 s and 1 / alpha act above 1 Hz,
    where a jerk-limited motion has little left. A steady rotation fades from what is felt in about
    tau; a change of the rotation felt in the cabin (a spin-up, or the arm's spin turned into the
    cabin's roll or pitch by its gimbals) is felt as it is. One state per canal, none per otolith: an
    on-line plan weighs rotation as the person feels it at 3 states more than without a model
    (docs/benchmarks/canals-in-the-on-line-cost.md), and its grid may vary (:attr:`VestibularModel.diagonal`).
    """
    if not (math.isfinite(tau) and tau > 0.0):
        raise ValueError(f"canal time constant tau = {tau!r} s must be a positive number")
    canals = tuple(Channel(CHANNEL_NAMES[i], gain=tau, s_power=1, zeros=(), poles=(tau,)) for i in range(3))
    otoliths = tuple(Channel(CHANNEL_NAMES[3 + i], gain=1.0, s_power=0, zeros=(), poles=()) for i in range(3))
    return VestibularModel("canals", canals + otoliths)


MODELS = {"thesis": thesis_model, "telban-cardullo": telban_cardullo_model, "canals": canals_model}


def judging(model: VestibularModel | None) -> VestibularModel:
    """The model a result's felt figures are computed through: ``model``, or the thesis' model where it
    is None or :func:`canals_model`, which leaves out what the canals do above 1 Hz and what the
    otoliths do at all, and is a cost, not a yardstick."""
    return thesis_model() if model is None or model.name == "canals" else model


def get_model(name: str) -> VestibularModel:
    """The perception model called ``name``, with its default parameters."""
    if name not in MODELS:
        raise ValueError(f"unknown perception model {name!r}; valid: {', '.join(MODELS)}")
    return MODELS[name]()


def below_threshold(difference, thresholds=THRESHOLDS) -> np.ndarray:
    """Which samples of a (perceived) difference of paths are too small to be felt.

    difference : (N, 6) or (6,) in the units of S; thresholds : (6,) per channel.
    Returns a boolean array of the same shape: True where |difference| < threshold.
    """
    return np.abs(np.asarray(difference, dtype=float)) < np.asarray(thresholds, dtype=float)

"""The thesis' own optimiser (chapters 4-5), reproduced on purpose as it was: the baseline of off-line speed.

Unknowns qdd per control interval (and optionally the initial state, 5.2), Runge-Kutta integration
on the step h_itr, the cost as a sum over the samples of S_d (eq. 4.1, 4.3), limits as barrier terms
in the cost (quadratic, eq. B.13 / 4.7, or the 'if' barrier of eq. 5.2), a trust-region
least-squares solver with finite-difference Jacobian (scipy ``least_squares``), an iteration cap and
the stop on a small change of the cost (5.4), and seeded random multi-start (4.7).
"""

from __future__ import annotations

import math
import time
from dataclasses import dataclass
from typing import Literal

import numpy as np
import scipy.optimize

from desdemona.machine.model import Model
from desdemona.machine.plan import Plan, advance
from desdemona.profiles import DesiredPath


@dataclass(frozen=True)
class ThesisOptions:
    """The thesis method's settings (chapters 4-5).

    h_u : control step [s]; h_itr : Runge-Kutta step [s]; h_S : step of the cost samples [s], None for
    the path's own samples (the thesis: h_S = 0.1 s, h_itr = 0.05 s, section 5.3); barrier : "quadratic" (eq. B.13 with
    a, b, c of 4.7) or "if" (eq. 5.2, starting at ``onset`` of each limit); barrier_weight : weight of
    the 'if' barrier per sample; optimize_initial : include q(0), qd(0) in the unknowns (5.2);
    max_iter : iteration cap (40 in 4.7); min_cost_change : stop when the cost changes less (0.1 in
    5.4); starts, seed : seeded random multi-start.
    """

    h_u: float = 0.1
    h_itr: float = 0.05
    h_S: float | None = 0.1
    barrier: Literal["quadratic", "if"] = "if"
    barrier_weight: float = 100.0
    onset: float = 3.7 / 4.0
    quadratic: tuple[float, float, float] = (0.1, 1e-3, 1e-5)
    optimize_initial: bool = True
    max_iter: int = 40
    min_cost_change: float = 0.1
    starts: int = 1
    seed: int = 0


@dataclass(frozen=True)
class ThesisRun:
    """One start of the thesis method."""

    plan: Plan
    cost: float
    iterations: int
    evaluations: int
    solve_time: float
    message: str


class ThesisProblem:
    """The residual vector of eq. 4.3/4.4 plus barriers, for a model and a desired path."""

    def __init__(self, model: Model, path: DesiredPath, options: ThesisOptions):
        self.model, self.path, self.options = model, path, options
        self.N = max(1, int(round(path.duration / options.h_u)))
        self.t_nodes = path.t[0] + options.h_u * np.arange(self.N + 1)
        # cost samples every h_S (5.3), on the path's own grid when h_S is None
        end = min(self.t_nodes[-1], path.t[-1])
        self.samples = (path.t[path.t <= end + 1e-12] if options.h_S is None
                        else path.t[0] + options.h_S * np.arange(int(round((end - path.t[0]) / options.h_S)) + 1))
        self.weights = np.sqrt(np.asarray(path.weights, float))
        # Runge-Kutta on h_itr, then states at the samples (5.3): the step fits the control grid
        self.steps = max(1, int(math.ceil(options.h_u / options.h_itr - 1e-9)))

    def unpack(self, z):
        n = self.model.n
        if self.options.optimize_initial:
            return z[:n], z[n:2 * n], z[2 * n:].reshape(self.N, n)
        return np.zeros(n), np.zeros(n), z.reshape(self.N, n)

    def pack(self, q0, qd0, u):
        u = np.asarray(u, float).ravel()
        return np.r_[q0, qd0, u] if self.options.optimize_initial else u

    def states(self, q0, qd0, u):
        """States at the cost samples: Runge-Kutta on h_itr, then from the last node to each sample.

        For the double integrator with qdd held, the classical RK4 step reduces algebraically to
        q+ = q + h qd + h^2 qdd / 2, qd+ = qd + h qdd (its stages are k1 = (qd, u), k2 = k3 =
        (qd + h u / 2, u), k4 = (qd + h u, u)); it is applied here to all steps at once with
        cumulative sums, the same numbers as stepping, without Python-loop overhead. The step is
        written out in the RK4 reduction's own order of operations rather than through
        :func:`desdemona.machine.plan.advance`: the method differentiates by finite differences, which turn a
        change of round-off into a different run (measured: 22 instead of 24 iterations on 4.7), and
        this baseline must reproduce its published figures to the bit.
        """
        h = self.options.h_u / self.steps
        steps = np.repeat(u, self.steps, axis=0)
        qd_all = np.vstack([qd0, qd0 + np.cumsum(h * steps, axis=0)])
        q_all = np.vstack([q0, q0 + np.cumsum(h * qd_all[:-1] + 0.5 * h * h * steps, axis=0)])
        q_nodes, qd_nodes = q_all[:: self.steps], qd_all[:: self.steps]
        k = np.clip(np.searchsorted(self.t_nodes, self.samples, side="right") - 1, 0, self.N - 1)
        q, qd = advance(q_nodes[k], qd_nodes[k], u[k], (self.samples - self.t_nodes[k])[:, None])
        return q, qd, u[k]

    def residuals(self, z) -> np.ndarray:
        q0, qd0, u = self.unpack(z)
        q, qd, qdd = self.states(q0, qd0, u)
        model, lim, o = self.model, self.model.limits, self.options
        S = model.S(q, qd, qdd)
        tau = model.tau(q, qd, qdd)
        if model.config.modulus_cost:
            error = (np.linalg.norm(S[:, 3:], axis=1) - self.path.sample_modulus(self.samples))[:, None]
        else:
            error = (S - self.path.sample(self.samples)) * self.weights
        parts = [error.ravel()]
        if o.barrier == "quadratic":
            a, b, c = o.quadratic
            prismatic = model.prismatic
            parts.append((math.sqrt(a) * q[:, prismatic]).ravel())
            parts.append((np.where(prismatic, math.sqrt(c), math.sqrt(b)) * tau).ravel())
        else:
            bounded = np.isfinite(lim.position_max)
            for value, limit in ((q[:, bounded], lim.position_max[bounded]), (qd, lim.velocity),
                                 (qdd, lim.acceleration), (tau, lim.effort),
                                 (tau * qd, lim.power)):
                x = value / limit
                over = np.abs(x) > o.onset
                parts.append((math.sqrt(o.barrier_weight) * np.where(over, x**2 - o.onset**2, 0.0)).ravel())
        return np.concatenate(parts)

    def random_start(self, rng: np.random.Generator) -> np.ndarray:
        lim = self.model.limits
        lo = np.where(np.isfinite(lim.position_min), 0.5 * lim.position_min, -np.pi)
        hi = np.where(np.isfinite(lim.position_max), 0.5 * lim.position_max, np.pi)
        n = self.model.n
        q0 = rng.uniform(lo, hi)
        qd0 = rng.uniform(-0.5, 0.5, n) * lim.velocity
        u = rng.uniform(-0.2, 0.2, (self.N, n)) * lim.acceleration
        return self.pack(q0, qd0, u)

    def solve(self, z0) -> ThesisRun:
        o = self.options
        history, why = [], []

        def stop(intermediate_result):
            # 5.4: stop when the cost (with barriers) changes by less than min_cost_change
            history.append(2.0 * intermediate_result.cost)
            if len(history) >= o.max_iter:
                why.append(f"iteration cap ({o.max_iter})")
                raise StopIteration
            if len(history) > 1 and abs(history[-2] - history[-1]) < o.min_cost_change:
                why.append(f"cost change below {o.min_cost_change:g} (5.4)")
                raise StopIteration

        start = time.perf_counter()
        result = scipy.optimize.least_squares(self.residuals, z0, jac="2-point", method="trf",
                                              callback=stop, max_nfev=50 * o.max_iter)
        elapsed = time.perf_counter() - start
        q0, qd0, u = self.unpack(result.x)
        if not o.optimize_initial:
            q0, qd0 = np.zeros(self.model.n), np.zeros(self.model.n)
        message = f"stopped: {why[0]}" if why else str(result.message)
        return ThesisRun(Plan(self.t_nodes.copy(), q0, qd0, u), float(2.0 * result.cost), len(history),
                         int(result.nfev), elapsed, message)


def optimize_thesis(path: DesiredPath, model: Model, options: ThesisOptions = ThesisOptions()):
    """Run the thesis method from ``options.starts`` seeded random starts; every run, best first by cost.

    The runs are not checked here: the caller checks them with :func:`desdemona.check.simulate.check`, as it
    does ours, because barrier terms do not guarantee the limits.
    """
    problem = ThesisProblem(model, path, options)
    rng = np.random.default_rng(options.seed)
    runs = [problem.solve(problem.random_start(rng)) for _ in range(options.starts)]
    return problem, sorted(runs, key=lambda r: r.cost)

"""The price of every limit: what the felt error would gain if a limit of the machine moved (thesis 3.2, 3.4, 4.2).

The off-line problem keeps every limit of eq. 3.3-3.5 (the constraints of eq. 3.7, discretised as eq. 4.2) as a hard constraint
on its nodes and sub-step points. At an optimum each constraint that binds carries a multiplier: the
rate at which the optimal cost J would change if its bound moved (the sensitivity theorem of
nonlinear programming: dJ/db = -lambda for the bound b that is active, in CasADi's sign convention,
lambda > 0 at an upper bound, < 0 at a lower one). A limit of the machine sets many bounds at once,
one per node or sub-step point, some of them backed off by terms that depend on another limit (a
position bound by A h^2 / 8, a rate bound by J h^2 / 8, :meth:`~desdemona.cueing.transcription.CueingProblem._bounds`),
so its price sums the multipliers of every bound it sets, each times that bound's derivative.

Definitions (per limit family and free joint):

- the relaxation: the limit L raised by 10 %, L -> 1.1 L (a position range [lo, hi] widened by 10 % of
  its half-range at both ends; torque and power: the constraint tau / tau_max <= 1 becomes <= 1.1);
- ``cost_slope``: dJ/d(epsilon) at epsilon = 0 for L -> (1 + epsilon) L, from the multipliers;
- the felt error E = sqrt(J): the optimiser's cost is the time mean of the weighted squared felt
  error (eq. 3.6, 5.1; with a perception model of the perceived error, chapter 6; on ``dfs-yaw`` of the
  modulus error, eq. 7.3) plus a small regularisation, so E is the weighted RMS the optimiser sees;
- ``price``: the first-order fall of E when the limit is relaxed by 10 %,
  ``price = -0.1 * cost_slope / (2 E)`` [the unit of the felt error: m/s^2 of weighted RMS]. Positive
  where relaxing helps; zero where the limit never binds; it may be slightly negative for a limit
  that also sets a back-off (a larger acceleration limit backs the positions off further);
- where in time it binds: the spans of the grid whose bounds carry a multiplier of at least
  :data:`BINDS` times the cost, each node or sub-step point standing for the half-steps around it,
  each jerk (the control of an interval) for its interval.

The held positions of the joints a configuration holds (``held_position``): the price of moving the
held joint by 10 % of its half-travel (or 18 deg, a tenth of half a turn, where it has no travel),
signed: positive where moving it up (to larger q) lowers the felt error. The held position is a
constant of the model functions, not a bound: its derivative is that of the Lagrangian at the
optimum (the envelope theorem), taken by a forward difference of the problem's own stage and
terminal functions rebuilt with the held position moved (:func:`held_slopes`).
"""

from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass

import numpy as np

from desdemona.cueing.formulation import WALL_WIDTH, Formulation
from desdemona.cueing.transcription import CueingProblem
from desdemona.machine.configs import Configuration
from desdemona.machine.model import Model
from desdemona.machine.params import JOINT_NAMES, MachineParams
from desdemona.machine.plan import advance

#: The families of limits, as summary.json names them (eq. 3.3-3.5, the jerk of the smooth plans).
FAMILIES = ("position", "rate", "acceleration", "jerk", "torque", "power")
HELD = "held_position"
#: The relaxation a price is quoted for: 10 % of the limit.
RELAXATION = 0.1
#: A bound binds where its multiplier's share of the cost slope is at least this share of the cost J.
BINDS = 1e-6
#: The step of a held position's forward difference, as a share of the move a price is quoted for.
HELD_STEP = 1e-5


@dataclass(frozen=True)
class LimitPrice:
    """One limit's price. family : one of :data:`FAMILIES` or ``held_position``; joint : its name;
    limit : the limit [SI] (a position: its half-range; held: the held position); cost_slope :
    dJ/d(epsilon); price : the felt error's first-order fall per 10 % [m/s^2]; spans : ((from, to), ...)
    [s] where it binds."""

    family: str
    joint: str
    limit: float
    cost_slope: float
    price: float
    spans: tuple[tuple[float, float], ...] = ()

    @property
    def binds_s(self) -> float:
        """How long it binds [s]."""
        return float(sum(b - a for a, b in self.spans))

    def to_dict(self) -> dict:
        return {"price": self.price, "binds_s": self.binds_s, "binds_from_s": [a for a, _ in self.spans],
                "binds_to_s": [b for _, b in self.spans], "limit": self.limit, "cost_slope": self.cost_slope}


@dataclass(frozen=True)
class Ledger:
    """Where the prices come from, entry by entry, for :func:`combined`: per (family, joint) the
    contributions to dJ/d(epsilon) (arrays), their spans (from, to) [s] and whether each is a bound
    that can bind (the cost's own dependence cannot); and the cost's share per stage (the stage costs
    and the terminal's, and their mid-times) [s]."""

    entries: dict
    costs: np.ndarray
    cost_times: np.ndarray


@dataclass(frozen=True)
class LimitPrices:
    """Every limit's price of one off-line optimum. cost : J; felt_error : sqrt(J); duration [s];
    ledger : the entries behind them (:class:`Ledger`), None where combined."""

    prices: tuple[LimitPrice, ...]
    cost: float
    felt_error: float
    duration: float
    ledger: Ledger | None = dataclasses.field(default=None, repr=False, compare=False)

    def to_dict(self) -> dict:
        """``{family: {joint: {"price", "binds_s", "binds_from_s", "binds_to_s", "limit", "cost_slope"}}}``,
        the ``limit_prices`` of summary.json."""
        out: dict = {}
        for p in self.prices:
            out.setdefault(p.family, {})[p.joint] = p.to_dict()
        return out

    def ranked(self) -> list[LimitPrice]:
        """The prices from the dearest limit down."""
        return sorted(self.prices, key=lambda p: -abs(p.price))

    def table(self, rows: int = 8) -> list[str]:
        """The dearest ``rows`` limits that bind, one line each, for the printed result."""
        lines = []
        for p in self.ranked()[:rows]:
            if abs(p.price) < 5e-5 and not p.spans:  # shown as 0 and binding nowhere: none further is dearer
                break
            share = p.binds_s / self.duration if self.duration > 0 else 0.0
            if p.family == HELD:  # signed: moved up (to a larger position), or down where negative
                lines.append(f"{p.family:>13} {p.joint:<13} {p.price:+9.4f} m/s^2 per 10 % moved up, held at {p.limit:g}")
                continue
            lines.append(f"{p.family:>13} {p.joint:<13} {p.price:+9.4f} m/s^2 per 10 %, binds "
                         f"{p.binds_s:6.2f} s ({share:4.0%}) in {len(p.spans)} span{'s' * (len(p.spans) != 1)}")
        return lines


def limit_prices(problem, solution, held: bool = True) -> LimitPrices | None:
    """Every limit's price (module docstring) at ``solution`` of ``problem`` (a
    :class:`~desdemona.cueing.transcription.CueingProblem`), from its multipliers; None where the
    solution has none. ``held``: also the held positions' (:func:`held_slopes`)."""
    if solution.lam_x is None or solution.lam_g is None:
        return None
    terms = _variable_terms(problem, np.asarray(solution.lam_x)) + _constraint_terms(problem, np.asarray(solution.lam_g))
    entries: dict = {}
    for family, j, c, lo, hi in terms:
        entries.setdefault((family, j), []).append((c, lo, hi, np.ones(c.size, bool)))
    mid = problem.t_nodes[:-1] + 0.5 * problem.steps  # the cost's own parts, per stage
    for (family, j), c in _cost_terms(problem, solution).items():
        entries.setdefault((family, j), []).append((c, mid, mid, np.zeros(c.size, bool)))
    data = (problem.stage_data(), None if problem.terminal is None else problem.terminal_data())
    costs, _ = _lagrangian(problem, problem, solution, data)
    if held:
        for joint, slopes in held_slopes(problem, solution, data):
            entries[(HELD, joint)] = [(slopes, np.r_[mid, problem.t_nodes[-1]], np.r_[mid, problem.t_nodes[-1]], np.zeros(slopes.size, bool))]
    ledger = Ledger({key: tuple(np.concatenate(parts) for parts in zip(*rows)) for key, rows in entries.items()},
                    costs, np.r_[mid, problem.t_nodes[-1]])
    return _priced(problem.model, [(ledger, 0.0, math.inf, 1.0)], float(problem.t_nodes[0]), float(problem.t_nodes[-1]))


def combined(model, pieces, start: float, end: float) -> LimitPrices | None:
    """The prices of a plan stitched from the optima of windows (:mod:`desdemona.cueing.windows`):
    ``pieces`` = (prices, offset [s], kept until [s, the window's own time], the window's duration) of
    each. Each window's cost is a mean over its own duration, the whole's over ``end - start``: the
    kept entries of each window weigh its duration's share. A window's prices see its own start fixed,
    so a combined price leaves out how moving a limit changes where the later windows start."""
    if any(p is None or p.ledger is None for p, *_ in pieces):
        return None
    return _priced(model, [(p.ledger, offset, kept, duration / (end - start)) for p, offset, kept, duration in pieces],
                   start, end)


def _priced(model, pieces, start: float, end: float) -> LimitPrices:
    """The prices of the ledgers' kept entries: ``pieces`` = (ledger, offset, kept until, weight)."""
    cost = float(sum(weight * np.sum(ledger.costs[ledger.cost_times <= kept + 1e-9]) for ledger, _, kept, weight in pieces))
    error = math.sqrt(max(cost, 0.0))
    scale = RELAXATION / (2.0 * error) if error > 0 else 0.0
    lim, names, params = model.limits, model.config.joint_names, model.params
    values = {"position": 0.5 * (lim.position_max - lim.position_min), "rate": lim.velocity,
              "acceleration": lim.acceleration, "jerk": lim.jerk, "torque": lim.effort, "power": lim.power}
    keys = [(family, j, name, float(values[family][j])) for family in FAMILIES for j, name in enumerate(names)
            if np.isfinite(values[family][j])]
    keys += [(HELD, joint, JOINT_NAMES[joint], float(model.config.held[joint])) for joint, _ in held_moves(model.config, params)
             if (HELD, joint) in pieces[0][0].entries]
    prices = []
    for family, j, name, limit in keys:
        slope, lows, highs = 0.0, [], []
        for ledger, offset, kept, weight in pieces:
            c, lo, hi, bound = ledger.entries.get((family, j), (np.zeros(0),) * 4)
            keep = 0.5 * (lo + hi) <= kept + 1e-9
            slope += weight * float(np.sum(c[keep]))
            binding = keep & bound & (np.abs(c) >= BINDS * max(float(np.sum(ledger.costs)), 1e-12))
            lows.append(lo[binding] + offset)
            highs.append(hi[binding] + offset)
        spans = () if family == HELD else _merged(np.concatenate(lows), np.concatenate(highs), start, end)
        prices.append(LimitPrice(family, name, limit, slope, -slope * scale, spans))
    ledger = pieces[0][0] if len(pieces) == 1 else None
    return LimitPrices(tuple(prices), cost, error, end - start, ledger)


def _cost_terms(problem, solution) -> dict:
    """{(family, joint): dJ/d(epsilon) per stage (N,)} of the cost's own dependence on the limits (the envelope
    theorem's explicit part): the regularisation weighs each acceleration against its limit and each
    jerk against its own (:meth:`~desdemona.cueing.formulation.Formulation._residuals`), so a term
    c (u / L)^2 changes by -2 c per unit epsilon; the wall before the position limits
    (:attr:`~desdemona.cueing.formulation.ProblemOptions.wall`) moves and widens with the range
    (:func:`_wall_terms`)."""
    lim, o, n = problem.model.limits, problem.options, problem.model.n
    weights = problem.steps[:, None] / problem.path.duration
    accelerations = solution.x[:-1, 2 * n:3 * n] if problem.smooth else solution.u
    terms = {}
    for j in range(n):
        terms[("acceleration", j)] = -2.0 * o.regularisation * weights[:, 0] * (accelerations[:, j] / lim.acceleration[j]) ** 2
        if problem.smooth:
            terms[("jerk", j)] = -2.0 * problem.jerk_weight * weights[:, 0] * (solution.u[:, j] / lim.jerk[j]) ** 2
    for key, wall in _wall_terms(problem, solution).items():
        terms[key] = terms.get(key, 0.0) + wall
    return terms


def _wall_terms(problem, solution) -> dict:
    """{("position", joint): dJ/d(epsilon) per stage (N,)} of the wall before each bounded joint's ends
    (:meth:`~desdemona.cueing.formulation.Formulation._wall`: ``wall (depth / width)^2`` at each sub-step
    point, weighed by the trapezoid rule), the range widened by epsilon times its half at both ends:
    the wall's start moves out by (half - width) epsilon and its width grows by width epsilon."""
    o, lim, n = problem.options, problem.model.limits, problem.model.n
    if not (o.wall > 0 and lim.bounded):
        return {}
    x, jerk = solution.x[:-1], solution.u if problem.smooth else None
    a = x[:, 2 * n:3 * n] if problem.smooth else solution.u
    s = problem.steps[:, None, None] * problem.fractions[None, :, None]  # (N, points, 1)
    q, _ = advance(x[:, None, :n], x[:, None, n:2 * n], a[:, None, :], s, None if jerk is None else jerk[:, None, :])
    points, m = len(problem.fractions), problem.m
    trapezoid = np.full(points, 1.0 / m)
    if points == m + 1:
        trapezoid[0] = trapezoid[-1] = 0.5 / m
    weights = trapezoid[None, :] * (problem.steps / problem.path.duration)[:, None]
    if points != m + 1:  # the first point's weight (the stages' data)
        weights[:, 0] *= problem.with_steps(np.zeros((0, problem.N)))[1]
    terms = {}
    for j in lim.bounded:
        low, high = lim.position_min[j], lim.position_max[j]
        half, width = 0.5 * (high - low), WALL_WIDTH * (high - low)
        depth = np.maximum(0.0, q[:, :, j] - (high - width)) + np.maximum(0.0, (low + width) - q[:, :, j])
        r = depth / width
        moved = np.where(depth > 0, -(half - width) / width, 0.0) - r  # dr / d(epsilon)
        terms[("position", j)] = np.sum(weights * 4.0 * o.wall ** 2 * r ** 3 * moved, axis=1)
    return terms


def _contribution(lam, d_lower, d_upper):
    """-dJ/d(epsilon) share of each bound: the multiplier of the side that is active times its bound's
    derivative (CasADi: lambda > 0 at the upper bound, < 0 at the lower)."""
    return -(np.maximum(lam, 0.0) * d_upper + np.minimum(lam, 0.0) * d_lower)


def _variable_terms(problem, lam_x) -> list:
    """(family, joint, contributions, from, to) of the bounds on the variables: positions, rates,
    accelerations at the nodes and the controls (jerks, or accelerations without jerk limits), each
    with the back-offs other limits set; entries the start or end fixes (lbx = ubx) are no limits."""
    n, N, nx, m = problem.model.n, problem.N, problem.nx, problem.m
    nw, lim, steps = nx + problem.nu, problem.model.limits, problem.steps
    h = problem.node_steps()
    t = problem.t_nodes
    node_lo, node_hi = t - 0.5 * np.r_[0.0, steps], t + 0.5 * np.r_[steps, 0.0]
    free = problem.lbx != problem.ubx
    nodes, intervals = np.arange(N + 1) * nw, np.arange(N) * nw + nx
    terms = []

    def add(family, j, index, d, lo, hi, back=None):
        ones = np.ones(len(index))
        lam = np.where(free[index], lam_x[index], 0.0)
        terms.append((family, j, _contribution(lam, -d * ones, d * ones), lo, hi))
        if back is not None:  # (family, the bound's derivative toward the inside)
            terms.append((back[0], j, _contribution(lam, back[1], -back[1]), lo, hi))

    half = 0.5 * (lim.position_max - lim.position_min)
    for j in range(n):
        if j in lim.bounded:  # position bounds, backed off by A (h / m)^2 / 8
            add("position", j, nodes + j, half[j], node_lo, node_hi, ("acceleration", lim.acceleration[j] * (h / m) ** 2 / 8))
        if problem.smooth:
            add("rate", j, nodes + n + j, lim.velocity[j], node_lo, node_hi, ("jerk", lim.jerk[j] * h ** 2 / 8))
            add("acceleration", j, nodes + 2 * n + j, lim.acceleration[j], node_lo, node_hi)
            add("jerk", j, intervals + j, lim.jerk[j], t[:-1], t[1:])
        else:
            add("rate", j, nodes + n + j, lim.velocity[j], node_lo, node_hi)
            add("acceleration", j, intervals + j, lim.acceleration[j], t[:-1], t[1:])
    return terms


def _constraint_terms(problem, lam_g) -> list:
    """(family, joint, contributions, from, to) of the path constraints, stage by stage (the layout
    of :meth:`~desdemona.cueing.transcription.CueingProblem._build_nlp`), and of the terminal node."""
    n, N, nx, m = problem.model.n, problem.N, problem.nx, problem.m
    lim, steps, t = problem.model.limits, problem.steps, problem.t_nodes
    bounded = np.asarray(lim.bounded, dtype=int)
    half = 0.5 * (lim.position_max - lim.position_min)
    stride = nx + problem.n_path
    starts = problem.n_initial + np.arange(N) * stride + nx  # each stage's first path row
    h_node = problem.node_steps()
    terms, offset = [], 0
    for family in problem.families:
        rows = family.expression.numel()
        index = starts[:, None] + offset + np.arange(rows)[None, :]  # (N, rows)
        lam = lam_g[index]
        r = np.arange(rows)
        if family.name == "position":  # inner sub-step points, backed off by A (h_k / m)^2 / 8
            joints = bounded[r % len(bounded)]
            at = t[:-1, None] + steps[:, None] * (1 + r // len(bounded))[None, :] / m
            width = (steps / (2 * m))[:, None]
            _bound_terms(terms, "position", joints, lam, half[joints], at - width, at + width,
                         ("acceleration", lim.acceleration[joints] * (steps[:, None] / m) ** 2 / 8))
        elif family.name == "stopping":  # where each bounded joint stops, from the interval's end
            joints = bounded[r % len(bounded)]
            lo, hi = np.broadcast_to((t[1:] - 0.5 * steps)[:, None], lam.shape), np.broadcast_to(
                (t[1:] + 0.5 * np.r_[steps[1:], 0.0])[:, None], lam.shape)
            _bound_terms(terms, "position", joints, lam, half[joints], lo, hi,
                         ("acceleration", lim.acceleration[joints] * (h_node[1:, None] / m) ** 2 / 8))
        elif family.name == "rate":  # the rate a joint settles at
            joints = r % n
            at = np.broadcast_to(t[1:, None], lam.shape)
            _bound_terms(terms, "rate", joints, lam, lim.velocity[joints], at, at)
        else:  # torque and power over their limits at the sub-step points: relaxed, the bound 1 -> 1 + epsilon
            joints, points = r % n, r // n
            at = t[:-1, None] + steps[:, None] * problem.fractions[points][None, :]
            width = (steps / (2 * m))[:, None]
            _bound_terms(terms, "torque" if family.name == "effort" else "power", joints, lam,
                         np.ones(rows), at - width, at + width)
        offset += rows
    if problem.n_terminal:  # the last node's torques, then powers
        end = problem.n_initial + N * stride
        lam = lam_g[end:end + problem.n_terminal][None, :]
        r = np.arange(problem.n_terminal)
        at = np.full((1, problem.n_terminal), t[-1])
        names = np.where(r < n, "torque", "power")
        for family in ("torque", "power"):
            keep = names == family
            _bound_terms(terms, family, r[keep] % n, lam[:, keep], np.ones(keep.sum()), at[:, keep] - 0.5 * steps[-1] / m,
                         at[:, keep])
    return terms


def _bound_terms(terms, family, joints, lam, d, lo, hi, back=None) -> None:
    """Append (family, joint, ...) terms of rows (N, rows) bounded symmetrically, the bound moving by
    ``d`` (rows,) per unit epsilon; ``back`` = (family, (N, rows) the back-off's derivative)."""
    lo, hi = np.broadcast_to(lo, lam.shape), np.broadcast_to(hi, lam.shape)
    shares = _contribution(lam, -np.broadcast_to(d, lam.shape), np.broadcast_to(d, lam.shape))
    backs = None if back is None else _contribution(lam, np.broadcast_to(back[1], lam.shape),
                                                    -np.broadcast_to(back[1], lam.shape))
    for j in np.unique(joints):
        cols = joints == j
        terms.append((family, int(j), shares[:, cols].ravel(), lo[:, cols].ravel(), hi[:, cols].ravel()))
        if backs is not None:
            terms.append((back[0], int(j), backs[:, cols].ravel(), lo[:, cols].ravel(), hi[:, cols].ravel()))


def _merged(lo, hi, start: float, end: float) -> tuple[tuple[float, float], ...]:
    """The union of the spans [lo_i, hi_i] within [start, end], as sorted disjoint (from, to) pairs."""
    if lo.size == 0:
        return ()
    order = np.argsort(lo)
    spans: list[list[float]] = []
    for a, b in zip(np.clip(lo[order], start, end), np.clip(hi[order], start, end)):
        if spans and a <= spans[-1][1] + 1e-9:
            spans[-1][1] = max(spans[-1][1], float(b))
        else:
            spans.append([float(a), float(b)])
    return tuple((round(a, 9), round(b, 9)) for a, b in spans)


def relaxed(model, family: str, joint: str, share: float):
    """The model with one limit relaxed by ``share`` (0.01: 1 %) as :func:`limit_prices` quotes it: the
    limit times 1 + share, a position range widened by ``share`` of its half-range at both ends, a
    held position moved up by ``share`` / 10 % of its move (:func:`held_moves`). For the finite
    differences that check the prices."""
    params, config = model.params, model.config
    index = JOINT_NAMES.index(joint)
    if family == HELD:
        move = dict(held_moves(config, params))[index]
        return Model(params, config.held_moved(index, share / RELAXATION * move))
    limits = params.joints[index]
    if family == "position":
        lo, hi = limits.position
        widen = share * 0.5 * (hi - lo)
        changed = dataclasses.replace(limits, position=(lo - widen, hi + widen))
    else:
        field = {"rate": "velocity", "torque": "effort"}.get(family, family)
        changed = dataclasses.replace(limits, **{field: getattr(limits, field) * (1.0 + share)})
    joints = tuple(changed if i == index else j for i, j in enumerate(params.joints))
    return Model(dataclasses.replace(params, joints=joints), config)


# ----------------------------------------------------------------------------------------------
# the held positions


def held_moves(config: Configuration, params: MachineParams) -> list[tuple[int, float]]:
    """(joint, move) of each held joint: 10 % of its half-travel, or a tenth of half a turn [rad]
    where it has no travel."""
    moves = []
    for joint in sorted(config.held):
        limits = params.joints[joint]
        half = math.pi if limits.position is None else 0.5 * (limits.position[1] - limits.position[0])
        moves.append((joint, RELAXATION * half))
    return moves


def held_slopes(problem, solution, data) -> list[tuple[int, np.ndarray]]:
    """(joint, dJ/d(epsilon) per stage and the terminal node (N + 1,)) of each held joint, epsilon the
    move over 10 % of it (:func:`relaxed`): the derivative of the Lagrangian f + lambda_g' g at the
    optimum (the variable bounds do not depend on a held position) with respect to the held position,
    by a forward difference of :data:`HELD_STEP` times its move (one model rebuilt per held joint:
    its truncation error, the cost's curvature over that step, is a ten-thousandth of the one-sided
    1 % move's). ``data``: the stages' and the terminal's (:func:`_lagrangian`)."""
    config, params = problem.model.config, problem.model.params
    base, out = np.sum(_lagrangian(problem, problem, solution, data), axis=0), []
    for joint, move in held_moves(config, params):
        step = HELD_STEP * move
        moved = Formulation(Model(params, config.held_moved(joint, step)), problem.path, problem.options)
        slopes = (np.sum(_lagrangian(moved, problem, solution, data), axis=0) - base) / step
        out.append((joint, slopes * move / RELAXATION))
    return out


def _lagrangian(formulation, problem, solution, data) -> tuple[np.ndarray, np.ndarray]:
    """The cost f and the multiplied rows lambda_g' g of ``formulation`` at ``solution`` of ``problem``
    (the same layout, its stages' and terminal ``data``), per stage and the terminal node (N + 1,)
    each: the stage costs and path rows, the terminal node's, and the start's filter rows with the
    first stage (gaps are linear in the states and do not depend on the model)."""
    x, u, N, nx = solution.x, solution.u, problem.N, problem.nx
    _, L, g = formulation.stage.map(N)(x[:-1].T, u.T, data[0])
    lam, stride = np.asarray(solution.lam_g), nx + problem.n_path
    rows = (problem.n_initial + np.arange(N)[:, None] * stride + nx + np.arange(problem.n_path)[None, :]).T
    cost, multiplied = np.r_[np.asarray(L).ravel(), 0.0], np.r_[np.sum(lam[rows] * np.asarray(g), axis=0), 0.0]
    if formulation.terminal is not None:
        L_end, g_end = formulation.terminal(x[-1], data[1])
        end = problem.n_initial + N * stride
        cost[-1], multiplied[-1] = float(L_end), float(lam[end:end + problem.n_terminal] @ np.asarray(g_end).ravel())
    if problem.n_initial:
        residual = CueingProblem.initial_constraint(formulation)(x[0], u[0])
        multiplied[0] += float(lam[nx:nx + problem.n_initial] @ np.asarray(residual).ravel())
    return cost, multiplied

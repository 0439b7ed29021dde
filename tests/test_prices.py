"""The price of every limit: the multipliers' first-order change of the cost against real re-solves
with the limit moved (finite differences), and what a limit that never binds costs."""

import math

import numpy as np
import pytest

from desdemona import Model, profiles
from desdemona.cueing import prices
from desdemona.cueing.formulation import ProblemOptions
from desdemona.cueing.offline import initial_guesses
from desdemona.cueing.transcription import CueingProblem

#: Measured on this case (docs/benchmarks/limit-prices.md): the multipliers' slope and the finite
#: difference of two converged solves differ by 1-2.5 % with the limit moved by 1 %, and by five
#: times that at 5 %: the cost's curvature in the bound, an error linear in the move, which the
#: central difference over -1 % and +1 % cancels (0.02 % there).
AT_1, AT_5, CENTRAL = 0.04, 0.16, 0.005


@pytest.fixture(scope="module")
def solved(params):
    """The 3 s catapult on yaw-track from rest to the centre at 0.1 s: the track's rate and travel,
    its jerk and the cabin's held tilt all bind (a fraction of a second a solve)."""
    model = Model(params, "yaw-track")
    path = profiles.catapult(duration=3.0)
    options = ProblemOptions(h_u=0.1, initial="rest", final="centre", wall=1.0)
    problem = CueingProblem(model, path, options)
    _, x, u = initial_guesses(problem, 1, 0)[0]
    solution = problem.solve(x, u)
    assert solution.success
    return model, path, options, solution, prices.limit_prices(problem, solution)


def _resolved_cost(model, path, options, solution, family, joint, share):
    problem = CueingProblem(prices.relaxed(model, family, joint, share), path, options)
    again = problem.solve(solution.x, solution.u, warm=solution)
    assert again.success
    return again.cost


@pytest.mark.parametrize("family, joint", [("rate", "track"), ("position", "track"), ("jerk", "track"),
                                           ("held_position", "outer_gimbal")])
def test_the_price_is_the_cost_slope_of_real_solves(solved, family, joint):
    model, path, options, solution, found = solved
    price = found.to_dict()[family][joint]
    assert price["cost_slope"] < 0 and price["price"] > 0  # relaxing it lowers the felt error
    costs = {share: _resolved_cost(model, path, options, solution, family, joint, share) for share in (0.01, 0.05, -0.01)}
    error = {share: abs((costs[share] - solution.cost) / share / price["cost_slope"] - 1.0) for share in (0.01, 0.05)}
    assert error[0.01] <= AT_1 and error[0.05] <= AT_5
    central = (costs[0.01] - costs[-0.01]) / 0.02
    assert central == pytest.approx(price["cost_slope"], rel=CENTRAL)
    # the price is the felt error's first-order fall per 10 %: -0.1 dJ / (2 sqrt(J))
    assert price["price"] == pytest.approx(-0.1 * price["cost_slope"] / (2 * math.sqrt(solution.cost)))


def test_a_limit_that_never_binds_costs_nothing_and_binds_nowhere(solved):
    *_, solution, found = solved
    table = found.to_dict()
    assert set(table) == {*prices.FAMILIES, prices.HELD}
    torque = table["torque"]["yaw"]  # the catapult's yaw torque stays far inside its 300 kN m
    assert abs(torque["price"]) < 1e-6 and torque["binds_s"] == 0.0 and torque["binds_from_s"] == []
    assert table["held_position"]["heave"]["price"] == 0.0  # the height changes no felt force
    rate = table["rate"]["track"]
    assert rate["binds_s"] > 0 and len(rate["binds_from_s"]) == len(rate["binds_to_s"]) >= 1
    assert all(0.0 <= a <= b <= 3.0 for a, b in zip(rate["binds_from_s"], rate["binds_to_s"]))
    assert np.isfinite([p.price for p in found.prices]).all()

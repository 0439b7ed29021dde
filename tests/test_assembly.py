"""The NLP's derivatives assembled from one stage's (:mod:`desdemona.cueing.assembly`) are CasADi's own
derivatives of the whole NLP, entry for entry: the constraint Jacobian, the cost's gradient and the
Lagrangian's Hessian (its upper triangle for IPOPT, whole for fatrop), with jerk limits and a terminal
stage, on S and on the modulus, with the path as constants and as the NLP's parameter."""

import casadi as ca
import numpy as np
import pytest

from desdemona import Model, profiles
from desdemona.cueing.assembly import concatenated
from desdemona.cueing.formulation import ProblemOptions
from desdemona.cueing.transcription import CueingProblem


@pytest.mark.parametrize("config, solver", [("full", "ipopt"), ("full", "fatrop"), ("dfs", "ipopt"),
                                            ("yaw-track-cabin", "fatrop")])
def test_the_assembled_derivatives_are_casadis_own(params, config, solver):
    model = Model(params, config)
    path = model.config.cue_path(profiles.catapult(level=15.0, push=0.5, quiet=0.2, duration=1.0))
    problem = CueingProblem(model, path, ProblemOptions(h_u=0.1, solver=solver, compile=False, expand=False,
                                                        limit_curvature=True))
    assert problem.terminal is not None and problem.path_parameter == (solver == "fatrop")
    nlp = problem.nlp
    w, p = nlp["x"], nlp.get("p", ca.MX(0, 1))
    lam_f, lam_g = ca.MX.sym("lam_f"), ca.MX.sym("lam_g", nlp["g"].numel())
    own = ca.Function("own", [w, p, lam_f, lam_g], [
        ca.jacobian(nlp["g"], w), ca.gradient(nlp["f"], w), ca.hessian(lam_f * nlp["f"] + ca.dot(lam_g, nlp["g"]), w)[0]])
    rng = np.random.default_rng(3)
    x = 0.1 * rng.standard_normal(w.numel())
    lam = rng.standard_normal(lam_g.numel())
    pv = problem.p if problem.p is not None else np.zeros(0)
    jac, grad, hess = (ca.DM(m).full() for m in own(x, pv, 0.7, lam))
    hess = hess if solver == "fatrop" else np.triu(hess)
    derivatives = problem.derivatives
    got = {"jac": ca.DM(derivatives["jac_g"](x, pv)[1]).full(),
           "grad": ca.DM(derivatives["grad_f"](x, pv)[1]).full(),
           "hess": ca.DM(derivatives["hess_lag"](x, pv, 0.7, lam)).full()}
    for name, want in (("jac", jac), ("grad", grad), ("hess", hess)):
        np.testing.assert_allclose(got[name], want, rtol=1e-9, atol=1e-9 * max(1.0, np.abs(want).max()), err_msg=name)


def test_concatenated_lays_the_pieces_nonzeros_in_order_and_counts_them():
    a, b = ca.MX.sym("a", ca.Sparsity.lower(2)), ca.MX.sym("b")
    pattern = ca.diagcat(ca.Sparsity.lower(2), ca.Sparsity.dense(1, 1))
    f = ca.Function("f", [a, b], [concatenated([a, b], pattern)])
    np.testing.assert_array_equal(ca.DM(f(ca.DM(ca.Sparsity.lower(2), [1, 2, 3]), 4)).full(),
                                  [[1, 0, 0], [2, 3, 0], [0, 0, 4]])
    with pytest.raises(AssertionError, match="do not fill"):
        concatenated([a], pattern)

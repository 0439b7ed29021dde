"""The cueing NLP's exact derivatives, assembled from one stage's (thesis 4.2, 5.3).

:class:`desdemona.cueing.transcription.CueingProblem` transcribes the problem by direct multiple shooting,
its decision vector in stage order x0, u0, x1, u1, ..., xN. One stage is differentiated symbolically
(:func:`stage_functions`) and mapped over the horizon; :func:`derivatives` assembles the NLP's
Jacobian, gradient and Hessian of the Lagrangian from the mapped blocks, without slicing them stage
by stage: in stage order the block-diagonal Hessian's nonzeros are the blocks' own one after the
other, and the Jacobian's are too, each state's column led by the +1 of its gap row in the stage
before (:func:`concatenated`). So the C source of the NLP (compiled for fatrop) does not grow with
the intervals beyond the sparsity of its outputs.
"""

from __future__ import annotations

import casadi as ca
import numpy as np

# the stages' functions are independent: mapped on two threads (the stage itself too, in transcription),
# on one in a worker process of a multi-start (CueingProblem.threads): two workers of two threads each
# on two cores took 37 s for the F-16 turn's capped start on `full`, of one thread each 31 s
MAP_MODE, MAP_THREADS = "thread", 2


def stage_functions(prob) -> dict[str, ca.Function]:
    """One stage's functions of ``prob`` (a :class:`~desdemona.cueing.transcription.CueingProblem`): ``stage`` itself, the upper triangle of its Lagrangian's Hessian
    ``hess`` and the Jacobian ``jac`` of its gaps and path constraints, the cost and its gradient
    ``grad``; ``hess0`` and ``jac0`` for the first stage where it also carries an initial constraint
    (with perception). Without one the first stage's are the others' (:func:`first_stage`): the same
    code compiled twice took a third of the stage library's compile on ``full``."""
    nx, nu, ni = prob.nx, prob.nu, prob.n_initial
    x, u = ca.SX.sym("x", nx), ca.SX.sym("u", nu)
    d = ca.SX.sym("d", prob.stage.size1_in(2))
    x_next, L, g = prob.stage(x, u, d)
    init = prob.initial_constraint()(x, u)
    xu = ca.vertcat(x, u)
    sigma, l_gap, l_init, l_path = (ca.SX.sym(k, m) for k, m in
                                    (("sigma", 1), ("l_gap", nx), ("l_init", ni), ("l_path", g.numel())))
    # the position families lead each stage's g, the torque and power limits follow
    curved = g.numel() if prob.limit_curvature else sum(
        f.expression.numel() for f in prob.families if f.name in ("position", "stopping", "rate"))
    gaps, limits = -ca.dot(l_gap, x_next), ca.dot(l_path[:curved], g[:curved])
    J = ca.jacobian(ca.vertcat(-x_next, g), xu)
    functions = {"stage": prob.stage, "jac": ca.Function("stage_jac", [x, u, d], [J]),
                 "grad": ca.Function("stage_grad", [x, u, d], [L, ca.gradient(L, xu)])}
    if ni:
        functions["jac0"] = ca.Function("stage_jac0", [x, u, d], [ca.jacobian(ca.vertcat(-x_next, init, g), xu)])
    # per Hessian: (a term given as a matrix, the rest of the Lagrangian, differentiated)
    hessians = {"hess": (None, sigma * L + gaps + limits)}
    if prob.gauss_newton_first:  # the cost is sum(r^2): 2 J_r^T J_r, without the residuals' curvature
        J_r = ca.jacobian(prob.residual(x, u, d), xu)
        hessians["hess_gn"] = (2 * sigma * ca.mtimes(J_r.T, J_r), gaps + limits)
    for key, (given, rest) in hessians.items():
        H = ca.hessian(rest, xu)[0]
        functions[key] = ca.Function(f"stage_{key}", [x, u, d, sigma, l_gap, l_path],
                                     [ca.triu(H if given is None else given + H)])
        if ni:
            H0 = ca.hessian(rest + ca.dot(l_init, init), xu)[0]
            functions[key + "0"] = ca.Function(f"stage_{key}0", [x, u, d, sigma, l_gap, l_init, l_path],
                                               [ca.triu(H0 if given is None else given + H0)])
    if prob.terminal is not None:  # its Hessian (of the cost, and of the limits with limit_curvature)
        d = ca.SX.sym("d", prob.terminal.size1_in(1))
        L, g = prob.terminal(x, d)
        l_end = ca.SX.sym("l_end", g.numel())
        lagrangian = sigma * L + (ca.dot(l_end, g) if prob.limit_curvature else 0)
        functions.update(terminal=prob.terminal,
                         terminal_hess=ca.Function("terminal_hess", [x, d, sigma, l_end],
                                                   [ca.triu(ca.hessian(lagrangian, x)[0])]),
                         terminal_jac=ca.Function("terminal_jac", [x, d], [ca.jacobian(g, x)]),
                         terminal_grad=ca.Function("terminal_grad", [x, d], [L, ca.gradient(L, x)]))
    return functions


def first_stage(stage: dict[str, ca.Function], key: str) -> ca.Function:
    """The first stage's function ``key`` (``jac``, ``hess``, ``hess_gn``): its own where it carries an
    initial constraint (which the Hessian's takes the multipliers of), else the other stages'."""
    return stage.get(key + "0", stage[key])


def derivatives(prob, w, p, XU, data, data_end, stage: dict[str, ca.Function]) -> dict[str, ca.Function]:
    """Exact Jacobian of the constraints ``jac_g``, gradient of the cost ``grad_f`` and Hessian of the
    Lagrangian ``hess_lag`` (``hess_gn`` too, with a Gauss-Newton first phase), assembled from the
    stages' functions (:func:`stage_functions`) over the decision vector ``w``, the parameter ``p``,
    its stage-order view ``XU`` and the stages' ``data`` and the terminal's ``data_end``.

    The gap constraints x_{k+1} - F(x_k, u_k) are linear in x_{k+1}, so in stage order the Hessian
    is block diagonal and the Jacobian block bidiagonal. Differentiating one stage symbolically and
    mapping the result over the horizon is three to four times faster to evaluate than
    differentiating through the mapped stage (measured on the full configuration). Neither is
    sliced stage by stage (:func:`concatenated`), so the NLP's C source does not grow with the
    intervals.
    """
    N, nx, nw = prob.N, prob.nx, prob.nx + prob.nu
    X, U = XU[:nx, :], XU[nx:, :]
    end, terminal = w[N * nw:], prob.terminal is not None
    # The Jacobian's nonzeros, column by column: a stage's own, each state's column led by the +1 of
    # its gap row in the stage before (the first stage's states have none).
    jac_end = stage["terminal_jac"](end, data_end) if terminal else ca.MX(0, nx)
    pieces = [first_stage(stage, "jac")(X[:, 0], U[:, 0], data[:, 0])]
    if N > 1:
        led = _composed(stage["jac"], lambda J: _gap_led(J, nx), "stage_jac_led")
        pieces.append(led.map(N - 1, MAP_MODE, prob.threads)(X[:, 1:], U[:, 1:], data[:, 1:]))
    pieces.append(_gap_led(jac_end, nx))
    blocks = [pieces[0].sparsity(), *[stage["jac"].sparsity_out(0)] * (N - 1), jac_end.sparsity()]
    jacobian = concatenated(pieces, _jacobian_sparsity(blocks, nx, nw))
    L_all, grad_all = stage["grad"].map(N, MAP_MODE, prob.threads)(X, U, data)
    f, grad_end = ca.sum2(L_all), ca.MX(nx, 1)
    if terminal:
        L_end, grad_end = stage["terminal_grad"](end, data_end)
        f += L_end
    gradient = ca.densify(ca.vertcat(ca.vec(grad_all), grad_end))
    functions = {
        "grad_f": ca.Function("nlp_grad_f", [w, p], [f, gradient], ["x", "p"], ["f", "grad_f_x"]),
        "hess_lag": lagrangian_hessian(prob, w, p, XU, data, data_end, stage, "hess"),
        "jac_g": ca.Function("nlp_jac_g", [w, p], [prob.nlp["g"], jacobian], ["x", "p"], ["g", "jac_g_x"]),
    }
    if "hess_gn" in stage:
        functions["hess_gn"] = lagrangian_hessian(prob, w, p, XU, data, data_end, stage, "hess_gn")
    return functions


def lagrangian_hessian(prob, w, p, XU, data, data_end, stage, key: str) -> ca.Function:
    """The Hessian of the Lagrangian, block diagonal in stage order: the first stage's ``key + "0"``,
    the others' ``key`` mapped, the terminal stage's. Its upper triangle, as IPOPT takes it; whole
    for fatrop, each block made whole in its stage. In stage order its nonzeros are the blocks',
    one block after the other."""
    N, nx, nw, ni, npath = prob.N, prob.nx, prob.nx + prob.nu, prob.n_initial, prob.n_path
    if prob.options.solver == "fatrop":
        stage = {k: _composed(stage[k], ca.triu2symm, f"{stage[k].name()}_whole")
                 for k in (key, key + "0", "terminal_hess") if k in stage}
    lam_f, lam_g = ca.MX.sym("lam_f"), ca.MX.sym("lam_g", prob.nlp["g"].numel())
    X, U = XU[:nx, :], XU[nx:, :]
    l0 = lam_g[: nx + ni + npath]
    multipliers = (l0[:nx], l0[nx:nx + ni], l0[nx + ni:]) if key + "0" in stage else (l0[:nx], l0[nx:])
    pieces = [first_stage(stage, key)(X[:, 0], U[:, 0], data[:, 0], lam_f, *multipliers)]
    if N > 1:
        rest = ca.reshape(lam_g[nx + ni + npath: lam_g.numel() - prob.n_terminal], nx + npath, N - 1)
        pieces.append(stage[key].map(N - 1, MAP_MODE, prob.threads)(
            X[:, 1:], U[:, 1:], data[:, 1:], ca.repmat(lam_f, 1, N - 1), rest[:nx, :], rest[nx:, :]))
    l_end = lam_g[lam_g.numel() - prob.n_terminal:]
    pieces.append(stage["terminal_hess"](w[N * nw:], data_end, lam_f, l_end) if prob.terminal is not None
                  else ca.MX(nx, nx))
    sparsity = ca.diagcat(pieces[0].sparsity(), *[stage[key].sparsity_out(0)] * (N - 1),
                          pieces[-1].sparsity())
    return ca.Function("nlp_hess_l", [w, p, lam_f, lam_g], [concatenated(pieces, sparsity)],
                       ["x", "p", "lam_f", "lam_g"], ["hess_gamma_x_x"])


def concatenated(pieces: list[ca.MX], sparsity: ca.Sparsity) -> ca.MX:
    """The matrix of ``sparsity`` whose nonzeros are those of ``pieces``, one piece after the other,
    each in its own order. Slicing the mapped stage outputs block by block instead gave C source that
    grows with the intervals (the NLP's for fatrop: 7 s to compile at 1,200 intervals on `full`,
    against 2 s this way, most of it its outputs' sparsity)."""
    assert sum(piece.nnz() for piece in pieces) == sparsity.nnz(), "the pieces do not fill the sparsity"
    return ca.sparsity_cast(ca.vertcat(*[_nonzeros(piece) for piece in pieces]), sparsity)


def _nonzeros(matrix: ca.MX) -> ca.MX:
    """The nonzeros of ``matrix`` as a column, without a copy."""
    return ca.sparsity_cast(matrix, ca.Sparsity.dense(matrix.nnz(), 1))


def _gap_led(J: ca.MX, nx: int) -> ca.MX:
    """The nonzeros of a stage's Jacobian J, column by column, each of its first ``nx`` columns (the
    states) led by a 1 (the +I of that state in the stage before's gap rows)."""
    colind = J.sparsity().colind()
    index = []
    for c in range(J.size2()):
        index += ([c] if c < nx else []) + list(range(nx + colind[c], nx + colind[c + 1]))
    return ca.vertcat(ca.DM.ones(nx), _nonzeros(J))[index]


def _composed(function: ca.Function, after, name: str) -> ca.Function:
    """``function`` (of one output) with ``after`` applied to its output: a stage's Jacobian gap-led
    (:func:`_gap_led`), its Hessian's upper triangle made whole, each in its stage, mapped."""
    inputs = [ca.MX.sym(function.name_in(i), function.sparsity_in(i)) for i in range(function.n_in())]
    return ca.Function(name, inputs, [after(function(*inputs))])


def _jacobian_sparsity(blocks: list[ca.Sparsity], nx: int, nw: int) -> ca.Sparsity:
    """The constraint Jacobian's: the stages' blocks down the diagonal (the first stage's, the others',
    the terminal one), nw columns each but the last, and the +I of each stage's next state in the
    stage's gap rows."""
    rows, cols, tops, top = [], [], [], 0
    for k, block in enumerate(blocks):
        r, c = (np.asarray(v, dtype=np.int64) for v in block.get_triplet())
        rows.append(r + top)
        cols.append(c + k * nw)
        tops.append(top)
        top += block.size1()
    gap = np.arange(nx)
    rows += [tops[k] + gap for k in range(len(blocks) - 1)]
    cols += [(k + 1) * nw + gap for k in range(len(blocks) - 1)]
    return ca.Sparsity.triplet(top, (len(blocks) - 1) * nw + nx, np.concatenate(rows).tolist(),
                               np.concatenate(cols).tolist())

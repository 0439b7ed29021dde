"""One real-time iteration of a parametric cueing problem (thesis chapter 7): the Gauss-Newton QP of
the problem's own residuals, linearised at the last plan, solved once per cycle by a structure-exploiting
QP solver (:class:`RealTimeIteration`)."""

from __future__ import annotations

import time

import casadi as ca
import numpy as np

from desdemona.cueing import blasfeo, compiled
from desdemona.cueing.transcription import Bounds, CueingProblem
from desdemona.support.symbolic import bound

# The real-time iteration's QP data is compiled to machine code (:mod:`desdemona.cueing.compiled`) as the graph
# it is built as: one stage function called once per interval, so the C source stays small. Measured
# on 2026-12-02, 4 s horizon on full at 50 Hz (56 intervals): 0.43-0.48 ms a cycle, compiled in 3 s,
# against 3.4 ms flattened and interpreted and 8.6 ms flattened and compiled at -O0 (the straight-line
# code of 740,000 instructions); the same numbers bit for bit (docs/benchmarks/compiled-qp-data.md). Below
# RTI_COMPILE_WORK instructions of the flat graph the virtual machine is as fast (yaw-track-cabin's
# 112,000: 0.3 ms either way) and nothing is compiled.
RTI_FLAGS = ("-O2", "-fPIC", "-shared")
RTI_COMPILE_WORK = 150_000


class RealTimeIteration:
    """The Gauss-Newton QP of one real-time iteration of a parametric :class:`CueingProblem`: a data
    Function (``data``) and a conic solver (``qp``, CasADi's ``qp_solver`` plugin).

    Cost: sum of squared stage residuals r (the problem's own), Hessian 2 J_r^T J_r (convex, so
    active-set solvers such as daqp apply), gradient 2 J_r^T r; constraints linearised with their
    exact Jacobian; all at the linearisation point w and the preview p. ``compile``: evaluate the QP's
    data compiled to machine code (:data:`RTI_FLAGS`; None: from :data:`RTI_COMPILE_WORK` instructions
    on, where a C compiler is found), else flattened to one SX graph in CasADi's virtual machine."""

    def __init__(self, prob: CueingProblem, qp_solver: str = "hpipm", compile: bool | None = None):
        N, nx, nu = prob.N, prob.nx, prob.nu
        nw = nx + nu
        x, u = ca.SX.sym("x", nx), ca.SX.sym("u", nu)
        d = ca.SX.sym("d", prob.stage.size1_in(2))
        r = prob.residual(x, u, d)
        J = ca.jacobian(r, ca.vertcat(x, u))
        stage = ca.Function("stage_gn", [x, u, d], [2.0 * J.T @ J, 2.0 * J.T @ r])
        w, p = prob.nlp["x"], prob.nlp["p"]
        XU = ca.reshape(w[: N * nw], nw, N)
        data = ca.reshape(p, d.numel(), N)
        H_blocks, g_blocks = stage.map(N, "serial")(XU[:nx, :], XU[nx:, :], data)
        # a tiny diagonal keeps the QP strictly convex in directions the cost does not see
        H = ca.diagcat(*[H_blocks[:, k * nw:(k + 1) * nw] for k in range(N)], ca.MX(nx, nx))
        H = H + 1e-9 * ca.MX.eye(N * nw + nx)
        gradient = ca.vertcat(ca.vec(g_blocks), ca.MX.zeros(nx))
        g, A = prob.derivatives["jac_g"](w, p)
        graph = ca.Function("qp_data", [w, p], [H, gradient, A, g])
        # The preparation's data (:meth:`prepare`): per stage the gradient's derivative in the desired
        # values v, 2 J^T dr/dv, and the piece of the residuals the preview is on, (dr/dv, r - dr/dv v).
        # The residuals are affine in v on each piece (the felt rotation's band is a dead zone in
        # it) and the constraints do not see v: on the same piece, H and A are the prepared ones and
        # the gradient for another preview is exact from its derivative.
        values = d[prob.n_head:]  # the desired values; the head (lengths, weights) is the stage's own
        dr = ca.jacobian(r, values)
        x_next, _, g_stage = prob.stage(x, u, d)
        self.splits = ca.jacobian(dr, values).is_zero() and not ca.depends_on(ca.vertcat(x_next, g_stage), values)
        dgrad = ca.Function("stage_dgrad", [x, u, d], [ca.densify(2.0 * J.T @ dr)])
        piece = ca.Function("stage_piece", [x, u, d], [ca.vertcat(ca.vec(ca.densify(dr)), r - dr @ values)])
        M = dgrad.map(N, "serial")(XU[:nx, :], XU[nx:, :], data)
        pieces = piece.map(N, "serial")(XU[:nx, :], XU[nx:, :], data)
        qp_data, prepared_data, piece_data = self._evaluated(
            [graph, ca.Function("qp_dgradient", [w, p], [M]), ca.Function("qp_piece", [w, p], [ca.vec(pieces)])], compile)
        self.piece_data = piece_data
        self._stage_data, self._N, self._head, self._nw = d.numel(), N, prob.n_head, nw
        options = {"error_on_fail": False, "print_time": False}
        if qp_solver == "hpipm":
            blasfeo.load()  # its linear algebra built for this processor, where it can be (desdemona.cueing.blasfeo)
            # HPIPM exploits the stage structure (measured: 0.8 ms for the 2 s dfs horizon at 50 Hz in
            # its speed_abs mode, 1.1 ms in speed, against 38 ms for dense daqp on the same QP); it must
            # be told the stages' sizes.
            ng = prob.n_path
            options.update(N=N, nx=[nx] * (N + 1), nu=[nu] * N + [0], ng=[ng + prob.n_initial] + [ng] * (N - 1) + [0],
                           hpipm={"iter_max": 50, "mode": "speed_abs", "res_g_max": 1e-6, "res_b_max": 1e-8,
                                  "res_d_max": 1e-8, "res_m_max": 1e-7})
        elif qp_solver == "qpoases":
            options.update(printLevel="none")
        elif qp_solver == "osqp":
            options["osqp"] = {"verbose": False, "eps_abs": 1e-7, "eps_rel": 1e-7, "max_iter": 4000}
        qp = ca.conic("rti", qp_solver, {"h": qp_data.sparsity_out(0), "a": qp_data.sparsity_out(2)}, options)
        self.data, self.qp, self.prepared_data = qp_data, qp, prepared_data
        self._buffers()
        self.timings = {"qp_data": 0.0, "qp": 0.0}  # the last solve's [s]: the QP's data and the QP solver
        self._ready = None  # what prepare() left for feedback(): (p it linearised at, the gradient's blocks, the pieces)
        self.refreshed = 0  # fed previews whose QP data was evaluated afresh (feedback)

    @staticmethod
    def _evaluated(graphs: list[ca.Function], compile: bool | None) -> list[ca.Function]:
        """The graphs flattened to SX (interpreted: the mapped graph spends more time slicing than
        computing, 0.22 -> 0.10 ms for the 2 s dfs horizon at 50 Hz; building the flat graph takes
        0.01-0.1 s), or compiled (see :data:`RTI_COMPILE_WORK`)."""
        flat = [graph.expand() for graph in graphs]
        if compile is True or (compile is None and flat[0].n_instructions() >= RTI_COMPILE_WORK):
            return compiled.compiled(graphs, RTI_FLAGS) or flat
        return flat

    def _buffers(self) -> None:
        """Arrays the two Functions read and write in place, through CasADi's FunctionBuffer, so that
        no argument or result is converted: H and A pass from the data to the QP without leaving
        them. Measured on 2026-12-03, one cycle's QP repeated 500 times: on ``dfs`` at 100 Hz (56
        intervals) 2.7 -> 1.4 ms median a step, on ``full`` at 50 Hz (46 intervals) 6.5-6.9 -> 5.0-5.1
        ms, the same bits (docs/benchmarks/real-time-iteration-without-conversions.md)."""
        data, qp = self.data, self.qp
        self._w, self._p = np.zeros(data.nnz_in(0)), np.zeros(data.nnz_in(1))
        self._out = [np.zeros(data.nnz_out(i)) for i in range(data.n_out())]
        self._qp_in = {name: np.zeros(qp.nnz_in(name)) for name in qp.name_in()}
        self._qp_in["h"], self._qp_in["a"] = self._out[0], self._out[2]
        self._qp_out = {name: np.zeros(qp.nnz_out(name)) for name in qp.name_out()}
        # the gradient's structural zeros (the end state's) are not among the data's nonzeros
        self._gradient_rows = np.asarray(data.sparsity_out(1).row(), dtype=int)
        self._data_buffer, self._eval_data = bound(data, {0: self._w, 1: self._p}, dict(enumerate(self._out)))
        self._blocks, self._piece = np.zeros(self.prepared_data.nnz_out(0)), np.zeros(self.piece_data.nnz_out(0))
        self._prepared_buffer, self._eval_prepared = bound(self.prepared_data, {0: self._w, 1: self._p}, {0: self._blocks})
        self._piece_buffer, self._eval_piece = bound(self.piece_data, {0: self._w, 1: self._p}, {0: self._piece})

    def _qp_buffer(self):
        """A new buffer of the QP's arrays for each solve (0.05-0.09 ms): HPIPM's plugin depends on
        work memory that CasADi's plain call hands it fresh, and from a kept buffer it solved another
        QP from the second call on. Every result is bound: the plugin writes them all."""
        return bound(self.qp, self._qp_in, self._qp_out)

    def __call__(self, w, p, bounds: Bounds, share: float = 1.0) -> tuple[np.ndarray, bool]:
        """One QP step from the linearisation point ``w`` for the parameter ``p``: the new point, and
        whether the QP solver succeeded.

        share : the share of the QP's step taken, in (0, 1]. The QP's constraints are linear, so a
        point between ``w`` and the QP's solution keeps each one that both ends keep."""
        start = time.perf_counter()
        self._w[:], self._p[:] = w, p
        self._eval_data()
        self._qp_in["g"][self._gradient_rows] = self._out[1]
        self._bounds(bounds)
        self._ready = None
        return self._solve(share, start)

    def prepare(self, w, p, bounds: Bounds) -> None:
        """The preparation phase of the real-time iteration (Diehl, Bock and Schloeder, 2005): the QP
        linearised at ``w`` within ``bounds``, everything but what the desired path changes, before the
        preview is known, for the preview of ``p`` (the last one: what the next is most like; its
        head, the stages' lengths and weights, is every preview's). :meth:`feedback` then takes the
        cycle's preview."""
        self._w[:], self._p[:] = w, p
        self._eval_data()
        self._qp_in["g"][self._gradient_rows] = self._out[1]
        self._bounds(bounds)
        blocks = piece = None
        if self.splits:
            self._eval_prepared()
            self._eval_piece()
            blocks, piece = self._blocks.reshape(self._N, self._stage_data - self._head, self._nw).copy(), self._piece.copy()
        self._ready = (self._p.copy(), blocks, piece)

    def feedback(self, p, share: float = 1.0) -> tuple[np.ndarray, bool]:
        """The feedback phase: the step of the QP :meth:`prepare` built, for the parameter ``p``; as
        ``self(w, p, bounds, share)`` would give from the same point, to round-off. Where ``p``'s
        preview puts a residual on another piece (across the felt rotation's band), or the residuals
        are not piecewise affine in it (:attr:`splits` False), the QP's data is evaluated afresh at the
        prepared point (:attr:`refreshed` counts them): the same step, with less prepared."""
        start = time.perf_counter()
        p_lin, blocks, piece = self._ready
        self._ready = None
        self._p[:] = p
        if blocks is not None:
            self._eval_piece()
            if np.allclose(self._piece, piece, rtol=1e-12, atol=1e-12):
                change = (self._p - p_lin).reshape(self._N, self._stage_data)[:, self._head:]
                self._qp_in["g"][: self._N * self._nw] += np.einsum("kdi,kd->ki", blocks, change).ravel()
                return self._solve(share, start)
        self.refreshed += 1
        self._eval_data()
        self._qp_in["g"][self._gradient_rows] = self._out[1]
        return self._solve(share, start)

    @property
    def ready(self) -> bool:
        """A QP is prepared (:meth:`prepare`) and not yet solved."""
        return self._ready is not None

    def _bounds(self, bounds: Bounds) -> None:
        g, into = self._out[3], self._qp_in
        np.subtract(bounds.lbg, g, out=into["lba"])
        np.subtract(bounds.ubg, g, out=into["uba"])
        np.subtract(bounds.lbx, self._w, out=into["lbx"])
        np.subtract(bounds.ubx, self._w, out=into["ubx"])

    def _solve(self, share: float, start: float) -> tuple[np.ndarray, bool]:
        buffer, solve = self._qp_buffer()
        began = time.perf_counter()
        solve()
        self.timings = {"qp_data": began - start, "qp": time.perf_counter() - began}
        return self._w + share * self._qp_out["x"], bool(buffer.stats()["success"])

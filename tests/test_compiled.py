"""Compiled stage functions: the same numbers as interpreted, one library per machine and
configuration for every path, a cache that is reused, and a quiet fallback without a compiler; and the
off-line cost, now assembled from stages without their ends and a terminal stage, is still the
trapezoid rule over the whole grid."""

import os
import sys
import time
import warnings

import casadi as ca
import numpy as np
import pytest

from desdemona import Model, profiles
from desdemona.check.simulate import evaluate_plan
from desdemona.cueing import assembly, compiled, transcription
from desdemona.cueing.formulation import ProblemOptions
from desdemona.cueing.offline import initial_guesses
from desdemona.cueing.transcription import CueingProblem
from desdemona.machine.plan import Plan
from desdemona.support import guard

needs_compiler = pytest.mark.skipif(compiled.compiler() is None, reason="no C compiler")


@pytest.fixture
def cache(tmp_path, monkeypatch):
    monkeypatch.setenv("DESDEMONA_CACHE", str(tmp_path / "cache"))
    return tmp_path / "cache"


def short(duration=1.0, **kw):
    return profiles.catapult(level=15.0, push=0.5, quiet=0.2, duration=duration, **kw)


def point(problem, seed=0):
    x, u = initial_guesses(problem, 1, seed)[0][1:]
    w = problem.pack(x, u)
    return w + 0.01 * np.random.default_rng(seed).standard_normal(w.shape)


@needs_compiler
def test_compiled_stages_give_the_interpreted_numbers(params, cache):
    model = Model(params, "full")
    fast = CueingProblem(model, short(), ProblemOptions(h_u=0.1, compile=True))
    slow = CueingProblem(model, short(), ProblemOptions(h_u=0.1, compile=False))
    assert fast.compiled and not slow.compiled
    w = point(slow)
    lam = np.random.default_rng(1).standard_normal(slow.nlp["g"].numel())
    for name, args in (("grad_f", [w, []]), ("jac_g", [w, []]), ("hess_lag", [w, [], 0.7, lam])):
        for a, b in zip(fast.derivatives[name].call(args), slow.derivatives[name].call(args)):
            a, b = ca.DM(a).full(), ca.DM(b).full()
            np.testing.assert_allclose(a, b, rtol=1e-12, atol=1e-12 * max(1.0, np.abs(b).max()))


@needs_compiler
def test_one_library_serves_every_path_and_later_runs(params, cache):
    model = Model(params, "full")
    first = CueingProblem(model, short(), ProblemOptions(h_u=0.1, compile=True))
    libraries = list(cache.glob("stages-*.so"))
    assert first.compiled and len(libraries) == 1
    stamp = libraries[0].stat().st_mtime_ns
    # another duration and other weights: path data, not code; found in the cache and used even
    # where compiling would not pay by itself
    other = short(duration=1.5)
    other = profiles.DesiredPath("other", other.t, other.S_d, weights=(0, 0, 0, 1, 2, 1))
    second = CueingProblem(model, other, ProblemOptions(h_u=0.1))
    assert second.N * assembly.stage_functions(second)["jac"].n_instructions() < 2_000_000
    assert second.compiled
    assert list(cache.glob("stages-*.so")) == libraries
    assert libraries[0].stat().st_mtime_ns == stamp
    assert not list(cache.glob(".compiling-*"))  # no work folder left behind
    # another machine setting is other code
    CueingProblem(Model(params.simplified(), "full"), short(), ProblemOptions(h_u=0.1, compile=True))
    assert len(list(cache.glob("stages-*.so"))) == 2


@needs_compiler
def test_fatrop_takes_the_stage_assembled_derivatives_compiled(params, cache, monkeypatch, tmp_path):
    """fatrop differentiates nothing itself: on the NLP's functions compiled with the derivatives
    assembled here (the Lagrangian's gradient beside its Hessian left at zero) it takes the same
    iterates as on CasADi's own derivatives of the NLP, to the optimum IPOPT finds; the stage
    library goes to the cache, the NLP's own library nowhere."""
    monkeypatch.setattr("tempfile.tempdir", str(tmp_path))
    told = []  # an optimised compile takes long: the command line is told as it begins and ends
    model, path = Model(params, "yaw-track-cabin"), short(duration=1.5)
    options = ProblemOptions(h_u=0.1, solver="fatrop", expand=False)
    # (BLASFEO, where this process has not loaded it yet, is built into this test's cache and told too)
    stages = lambda: [line for line in told if line.startswith("compiling the stage functions")]  # noqa: E731
    with guard.reporting(None, tell=told.append):
        fast = CueingProblem(model, path, options)
        assert len(stages()) == 2 and stages()[1].endswith(" s")
        assert CueingProblem(model, short(duration=2.0), options).compiled and len(stages()) == 2  # cached
    slow = CueingProblem(model, path, ProblemOptions(h_u=0.1, solver="fatrop", expand=False, compile=False))
    ipopt = CueingProblem(model, path, ProblemOptions(h_u=0.1, expand=False, compile=False))
    assert fast.compiled and not slow.compiled and fast.limit_curvature
    x, u = initial_guesses(fast, 1, 0)[0][1:]
    a, b, c = (problem.solve(x, u) for problem in (fast, slow, ipopt))
    assert a.success and b.success and c.success
    assert a.iterations == b.iterations
    np.testing.assert_allclose(a.x, b.x, atol=1e-9 * max(1.0, np.abs(b.x).max()))
    assert a.cost == pytest.approx(c.cost, rel=1e-6)
    assert len(list(cache.glob("stages-*.so"))) == 1
    assert not list(tmp_path.glob("desdemona-*"))  # the NLP's library, loaded, is gone
    # on more than three joints IPOPT leaves the limits' curvature out, fatrop keeps it
    assert not CueingProblem(Model(params, "full"), short(), ProblemOptions(h_u=0.1, compile=False)).limit_curvature


@needs_compiler
def test_paths_of_as_many_intervals_share_one_fatrop_solver(params, cache):
    """With fatrop the path is the compiled NLP's parameter: another path of as many intervals takes the
    solver already built (no library compiled, no set-up again, as the windows of a long recording
    do), and solves its own path, as a solver of its own does; another length gets its own."""
    model, options = Model(params, "yaw-track-cabin"), ProblemOptions(h_u=0.1, solver="fatrop", expand=False)
    path = short(duration=1.5)
    other = profiles.DesiredPath("other", path.t, 0.5 * path.S_d, weights=path.weights)
    transcription.FATROP_SOLVERS.clear()
    first, second = CueingProblem(model, path, options), CueingProblem(model, other, options)
    assert second.solver is first.solver and len(transcription.FATROP_SOLVERS) == 1
    x, u = initial_guesses(second, 1, 0)[0][1:]
    shared, mine = second.solve(x, u), first.solve(x, u)
    transcription.FATROP_SOLVERS.clear()
    own = CueingProblem(model, other, options).solve(x, u)
    assert shared.success and own.success and shared.iterations == own.iterations
    np.testing.assert_allclose(shared.x, own.x, atol=1e-9 * max(1.0, np.abs(own.x).max()))
    assert abs(mine.cost - shared.cost) > 1e-3 * shared.cost  # the first path's optimum is another
    assert CueingProblem(model, short(duration=2.0), options).solver is not first.solver
    assert len(transcription.FATROP_SOLVERS) == 2


@needs_compiler
def test_a_stored_fatrop_solver_is_loaded_by_a_later_run(params, cache, monkeypatch):
    """A window's fatrop solver is kept in the cache, serialized beside its NLP's library: a later run
    (here this process, its solvers forgotten) loads it instead of setting fatrop up again, and solves
    to the same iterates. A file that no longer loads is built again, with a warning; a problem not
    stored leaves nothing in the cache."""
    model, options = Model(params, "yaw-track-cabin"), ProblemOptions(h_u=0.1, solver="fatrop", expand=False)
    path = short(duration=1.5)
    transcription.FATROP_SOLVERS.clear()
    built = CueingProblem(model, path, options, stored=True)
    kept = sorted(file.name.split("-")[0] for file in cache.iterdir() if file.name.startswith(("nlp-", "solver-")))
    assert kept == ["nlp", "solver"] and not list(cache.glob(".*"))  # and no temporary file left
    x, u = initial_guesses(built, 1, 0)[0][1:]
    first = built.solve(x, u)
    transcription.FATROP_SOLVERS.clear()
    with monkeypatch.context() as patched:
        patched.setattr(ca, "nlpsol", lambda *args, **kw: pytest.fail("fatrop was set up again"))
        again = CueingProblem(model, path, options, stored=True).solve(x, u)
    assert again.success and again.iterations == first.iterations
    np.testing.assert_array_equal(again.x, first.x)
    next(cache.glob("solver-*")).write_bytes(b"not a solver")
    transcription.FATROP_SOLVERS.clear()
    with pytest.warns(RuntimeWarning, match="did not load"):
        rebuilt = CueingProblem(model, path, options, stored=True)
    assert rebuilt.solve(x, u).iterations == first.iterations
    before = sorted(cache.iterdir())
    CueingProblem(model, short(duration=2.0), options)
    assert sorted(cache.iterdir()) == before
    # a cache that takes no new files (shared, read-only): the solver is built, and nothing is kept
    monkeypatch.setattr(compiled, "writable", lambda: False)
    unkept = CueingProblem(model, short(duration=2.5), options, stored=True)
    assert unkept.solve(*initial_guesses(unkept, 1, 0)[0][1:]).success
    assert sorted(cache.iterdir()) == before


@needs_compiler
def test_a_long_whole_path_keeps_its_solver_and_the_cache_keeps_the_most_recently_used(params, cache, monkeypatch):
    """Left to choose (stored=None), a problem of STORED_FROM intervals or more keeps its fatrop
    solver (its set-up grows with the square of the intervals: 10.7 s of the F-16 turn's build on
    `full`, 1.3 s loaded), a shorter one does not. The cache keeps the SOLVERS_KEPT most recently
    used solvers with their NLP's libraries and removes older ones, and nothing else."""
    model, options = Model(params, "yaw-track-cabin"), ProblemOptions(h_u=0.1, solver="fatrop", expand=False)
    transcription.FATROP_SOLVERS.clear()
    monkeypatch.setattr(transcription, "STORED_FROM", 20)
    CueingProblem(model, short(duration=1.5), options, stored=None)  # 15 intervals
    assert not list(cache.glob("solver-*"))
    CueingProblem(model, short(duration=2.5), options, stored=None)  # 25
    assert len(list(cache.glob("solver-*"))) == 1
    folder = cache / "bound"
    folder.mkdir()
    for k in range(6):
        for name in (f"solver-{k:024d}.casadi.gz", f"nlp-{k:024d}.so"):
            (folder / name).write_bytes(b"x")
            os.utime(folder / name, (1000.0 + k, 1000.0 + k))
    (folder / "stages-000.so").write_bytes(b"x")  # not a solver: never removed here
    compiled._forget_solvers(folder, kept=4)
    assert sorted(f.name for f in folder.iterdir()) == sorted(
        [f"solver-{k:024d}.casadi.gz" for k in range(2, 6)] + [f"nlp-{k:024d}.so" for k in range(2, 6)]
        + ["stages-000.so"])


def test_small_problems_are_not_compiled(params, cache):
    problem = CueingProblem(Model(params, "yaw-track-cabin"), short(), ProblemOptions(h_u=0.1))
    assert not problem.compiled
    assert not cache.exists()


def test_without_a_compiler_the_stages_stay_interpreted(params, cache, monkeypatch):
    monkeypatch.setenv("CC", "no-such-compiler-here")
    with pytest.warns(RuntimeWarning, match="no C compiler"):
        problem = CueingProblem(Model(params, "full"), short(), ProblemOptions(h_u=0.1, compile=True))
    assert not problem.compiled
    x, u = initial_guesses(problem, 1, 0)[0][1:]
    assert np.isfinite(problem.solve(x, u).cost)


@needs_compiler
def test_a_failing_compiler_leaves_nothing_behind(params, cache, monkeypatch, tmp_path):
    failing = tmp_path / "cc"
    failing.write_text("#!/bin/sh\necho 'cc: broken toolchain' >&2\nexit 1\n")
    failing.chmod(0o755)
    monkeypatch.setenv("CC", str(failing))
    with pytest.warns(RuntimeWarning, match="broken toolchain"):
        problem = CueingProblem(Model(params, "full"), short(), ProblemOptions(h_u=0.1, compile=True))
    assert not problem.compiled
    assert os.listdir(cache) == []


def test_the_offline_cost_is_the_trapezoid_rule_over_the_whole_grid(params):
    """With continuous accelerations the stages leave their ends out and the last node has a stage
    of its own: at a gap-free point the cost is the trapezoid rule of the weighted squared error on
    every sub-step point, plus the acceleration and jerk terms."""
    model = Model(params, "yaw-track-cabin")
    path = short(duration=1.2)
    problem = CueingProblem(model, path, ProblemOptions(h_u=0.1, initial="free"))
    assert problem.terminal_stage and problem.n_terminal == 2 * model.n
    x, u = initial_guesses(problem, 1, 0)[0][1:]
    n, lim = model.n, model.limits
    plan = Plan(problem.t_nodes, x[0, :n], x[0, n:2 * n], x[:-1, 2 * n:3 * n], u)
    t = np.r_[problem.sub_times().ravel(), problem.t_nodes[-1]]
    traj = evaluate_plan(model, path, plan, t)
    error = np.sum(problem.cost_weights * (traj.S - traj.S_d) ** 2, axis=1)
    T, h = path.duration, problem.steps
    expected = np.trapezoid(error, t) / T
    expected += problem.options.regularisation * np.sum(h[:, None] * (plan.u / lim.acceleration) ** 2) / T
    expected += problem.jerk_weight * np.sum(h[:, None] * (plan.jerk / lim.jerk) ** 2) / T
    states = np.column_stack([*plan.at(problem.t_nodes)])
    w = problem.pack(states, plan.jerk)
    cost = float(ca.Function("f", [problem.nlp["x"]], [problem.nlp["f"]])(w))
    assert cost == pytest.approx(expected, rel=1e-9)


def test_the_last_node_is_limited(params):
    """The terminal stage bounds the torques and powers at the last node."""
    problem = CueingProblem(Model(params, "full"), short(), ProblemOptions(h_u=0.1, compile=False))
    rows = slice(problem.nlp["g"].numel() - problem.n_terminal, None)
    np.testing.assert_array_equal(problem.lbg[rows], -1.0)
    np.testing.assert_array_equal(problem.ubg[rows], 1.0)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        online = CueingProblem(Model(params, "full"), short(), ProblemOptions(h_u=0.1), parametric=True)
    assert online.n_terminal == 0 and not online.compiled


def test_the_real_time_iterations_qp_data_compiled_gives_the_same_numbers():
    """The QP data of the on-line controller compiled as its graph (one stage function per interval)
    gives what the interpreted flat graph gives."""
    from desdemona.control.mpc import MPC, MPCOptions
    from desdemona.cueing.realtime_iteration import RealTimeIteration

    problem = MPC(Model(config="yaw-track-cabin"), MPCOptions(horizon=1.0, step=0.05)).problem
    machine = RealTimeIteration(problem, compile=True).data
    flat = RealTimeIteration(problem, compile=False).data
    assert machine.class_name() == "External" and flat.class_name() == "SXFunction"
    rng = np.random.default_rng(3)
    w, p = rng.normal(size=problem.nlp["x"].numel()), rng.normal(size=problem.nlp["p"].numel())
    for a, b in zip(machine(w, p), flat(w, p)):
        np.testing.assert_allclose(np.asarray(ca.densify(a)), np.asarray(ca.densify(b)), rtol=1e-12, atol=1e-12)


def _tiny() -> list[ca.Function]:
    x = ca.SX.sym("x", 3)
    return [ca.Function("tiny", [x], [ca.sin(x[0]) * x[1] + x[2] ** 3])]


def _settled(cache, seconds=120.0) -> bool:
    """Whether the cache's background builds ended within ``seconds`` (polled, bounded)."""
    for _ in range(int(seconds / 0.2)):
        if not list(cache.glob("*.building")):
            return True
        time.sleep(0.2)
    return False


@needs_compiler
def test_an_optimised_library_is_compiled_in_the_background_for_later_runs(cache, monkeypatch):
    """A first run waits only for the quick library (-O0); the optimised one appears in the cache
    from a process of its own, a later run takes it, and both compute the same."""
    monkeypatch.setattr(compiled, "OPTIMISED", "later")
    optimised = ("-O1", "-fPIC", "-shared")
    functions = _tiny()
    first = compiled.build(functions, optimised)
    assert first == compiled.library(functions, compiled.FLAGS)[1]  # the quick one, now
    assert _settled(cache)
    later = compiled.build(functions, optimised)
    assert later == compiled.library(functions, optimised)[1] and later.exists() and later != first
    assert sorted(p.name for p in cache.iterdir()) == sorted([first.name, later.name])  # nothing else left
    x = [0.3, -1.2, 0.7]
    a, b = (float(ca.external("tiny", str(path))(x)) for path in (first, later))
    assert a == pytest.approx(b, rel=1e-15) and a == pytest.approx(float(functions[0](x)), rel=1e-15)
    # told to wait (the benchmarks): the optimised library at once, nothing in the background
    monkeypatch.setattr(compiled, "OPTIMISED", "now")
    y = ca.SX.sym("y", 3)
    other = [ca.Function("tiny", [y], [2.0 * y[0]])]
    assert compiled.build(other, optimised) == compiled.library(other, optimised)[1]
    assert not list(cache.glob("*.building"))


def test_a_background_process_is_started_once(tmp_path):
    """Of two runs that ask for the same background work at once, one starts it; once it has ended
    (its marker gone), the next ask starts it again."""
    marker = tmp_path / "work.building"
    command = [sys.executable, "-c", "import sys, time, pathlib; time.sleep(1.0); pathlib.Path(sys.argv[1]).unlink()",
               str(marker)]
    compiled.start_once(marker, command)
    pid = marker.read_text()
    compiled.start_once(marker, command)
    assert marker.read_text() == pid  # the first still runs: not started again
    assert _settled(tmp_path, 30.0)
    compiled.start_once(marker, command)
    assert marker.read_text() not in ("", pid)
    assert _settled(tmp_path, 30.0)

"""HPIPM and fatrop on BLASFEO built for this processor (desdemona.cueing.blasfeo): the controller's commands
and fatrop's off-line solution equal those of CasADi's own build to round-off, the library is the one
the process runs on, the build is cached, and every reason not to use it falls back to CasADi's build,
leaving nothing behind."""

import json
import os
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from desdemona.cueing import blasfeo, compiled

needs_build = pytest.mark.skipif(blasfeo.unavailable() is not None,
                                 reason=f"BLASFEO is not built here: {blasfeo.unavailable()}")

# A few cycles of the dfs controller on a ramp of the modulus, from rest: every QP has active bounds
# (the one-way arm, the acceleration's limits at the spin-up) and the plans build on each other.
COMMANDS = """
import json, numpy as np
from desdemona.cueing import blasfeo
from desdemona.machine.model import Model
from desdemona.control.mpc import MPC, MPCOptions
mpc = MPC(Model(None, "dfs"), MPCOptions(horizon=1.0))
t = np.linspace(0.0, 1.0, 51)
state = (np.zeros(4), np.zeros(4), np.zeros(4))
out = []
for k in range(5):
    command = mpc.step(state, (t, 9.81 + 3.0 * np.minimum(t + 0.02 * k, 0.5)))
    out.append(command.jerks.tolist())
print(json.dumps({"status": blasfeo.status(), "jerks": out}))
"""

# fatrop off-line from one guess on a short catapult on `full` (CasADi's own derivatives: nothing compiled)
FATROP = """
import json
from desdemona import Model, profiles
from desdemona.cueing import blasfeo
from desdemona.cueing.offline import initial_guesses
from desdemona.cueing.formulation import ProblemOptions
from desdemona.cueing.transcription import CueingProblem
path = profiles.catapult(level=15.0, push=0.5, quiet=0.2, duration=1.5)
problem = CueingProblem(Model(None, "full"), path, ProblemOptions(h_u=0.1, solver="fatrop", compile=False))
solution = problem.solve(*initial_guesses(problem, 1, 0)[0][1:])
print(json.dumps({"status": blasfeo.status(), "success": solution.success, "iterations": solution.iterations,
                  "x": solution.x.tolist()}))
"""


def commands(env: dict, script: str = COMMANDS) -> dict:
    done = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, timeout=300,
                          env={**os.environ, **env})
    assert done.returncode == 0, done.stderr
    return json.loads(done.stdout.strip().splitlines()[-1])


@needs_build
def test_the_controller_commands_the_same_on_either_build():
    ours, casadi = commands({}), commands({"DESDEMONA_BLASFEO": "generic"})
    assert ours["status"].startswith(f"BLASFEO {blasfeo.VERSION} for AVX2")
    assert casadi["status"] == "CasADi's generic BLASFEO (DESDEMONA_BLASFEO=generic)"
    a, b = np.array(ours["jerks"]), np.array(casadi["jerks"])
    assert np.abs(a).max() > 0.1  # the ramp moves the machine
    np.testing.assert_allclose(a, b, rtol=0, atol=1e-7 * np.abs(b).max())


@needs_build
def test_fatrop_solves_the_same_on_either_build():
    ours, casadi = commands({}, FATROP), commands({"DESDEMONA_BLASFEO": "generic"}, FATROP)
    assert ours["status"].startswith(f"BLASFEO {blasfeo.VERSION} for AVX2")
    assert casadi["status"] == "CasADi's generic BLASFEO (DESDEMONA_BLASFEO=generic)"
    assert ours["success"] and casadi["success"] and ours["iterations"] == casadi["iterations"]
    a, b = np.array(ours["x"]), np.array(casadi["x"])
    np.testing.assert_allclose(a, b, rtol=0, atol=1e-6 * np.abs(b).max())


@needs_build
def test_the_process_runs_on_the_library_it_built():
    status = blasfeo.load()
    assert status == blasfeo.status()
    folder = blasfeo.build()
    assert status == f"BLASFEO {blasfeo.VERSION} for AVX2 ({folder})"
    assert [Path(p).parent for p in blasfeo._mapped("libblasfeo")] == [folder]
    assert blasfeo._mapped("libfatrop")  # fatrop loaded with it, bound to it
    assert blasfeo.load() is status  # once per process


@needs_build
def test_the_build_is_kept_and_reused(monkeypatch, tmp_path):
    folder = blasfeo.build()  # the suite's cache holds it already (conftest)
    stamp = (folder / "libblasfeo.so.0").stat().st_mtime_ns
    monkeypatch.setattr(blasfeo, "_compile", None)  # nothing may be compiled again
    assert blasfeo.build() == folder
    assert (folder / "libblasfeo.so.0").stat().st_mtime_ns == stamp
    assert sorted(p.name for p in folder.iterdir()) == ["libblasfeo.so.0", "libcasadi_conic_hpipm.so", "libhpipm.so"]


@pytest.mark.skipif(compiled.compiler() is None, reason="no C compiler")
def test_a_failed_build_leaves_nothing(monkeypatch, tmp_path):
    monkeypatch.setenv("DESDEMONA_CACHE", str(tmp_path / "cache"))
    monkeypatch.setenv("CC", "false")
    with pytest.raises(subprocess.SubprocessError, match="false exited 1"):
        blasfeo.build()
    assert list((tmp_path / "cache").iterdir()) == []


def test_the_reasons_to_keep_casadis_build(monkeypatch):
    monkeypatch.setenv("DESDEMONA_BLASFEO", "generic")
    assert blasfeo.unavailable() == "DESDEMONA_BLASFEO=generic"
    monkeypatch.delenv("DESDEMONA_BLASFEO")
    monkeypatch.setattr(compiled, "cpu_flags", lambda: {"sse2", "avx"})
    if sys.platform.startswith("linux") and blasfeo.platform.machine() == "x86_64":
        assert blasfeo.unavailable() == "the processor lacks AVX2 or FMA"
    monkeypatch.setattr(compiled, "cpu_flags", lambda: {"avx2", "fma"})
    monkeypatch.setattr(blasfeo, "VERSION", "0.0.0")
    if sys.platform.startswith("linux") and blasfeo.platform.machine() == "x86_64":
        assert "linked against another BLASFEO than 0.0.0" in blasfeo.unavailable()


def test_the_sources_are_whole():
    """Every source the build compiles is kept, with the licence that lets it be."""
    manifest = (blasfeo.SOURCES / "sources.txt").read_text().split()
    assert len(manifest) == 82
    assert all((blasfeo.SOURCES / source).is_file() for source in manifest)
    assert "BSD" in (blasfeo.SOURCES / "LICENSE.txt").read_text() or "Redistribution" in \
        (blasfeo.SOURCES / "LICENSE.txt").read_text()

"""Shared fixtures."""

import fcntl
import os

import pytest

from desdemona import default_params, thesis_toy_params
from desdemona.cueing import blasfeo, compiled


@pytest.fixture(scope="session")
def params():
    return default_params()


@pytest.fixture(scope="session")
def toy():
    return thesis_toy_params()


@pytest.fixture(scope="session", autouse=True)
def compiled_cache(tmp_path_factory):
    """Libraries compiled during the tests go to a folder of their own, not the user's cache. BLASFEO is
    built there first (about 15 s), so that no server started by a test spends its start-up on it.

    Under pytest-xdist the workers of one run share that folder (each library is compiled once and
    renamed into place whole, so a worker reads another's), and one of them builds BLASFEO while the
    others wait for it. Nothing is compiled in the background for later runs (the folder goes with
    the run), so a test that asks for an optimised library gets the quick one."""
    base = tmp_path_factory.getbasetemp()
    if os.environ.get("PYTEST_XDIST_WORKER"):
        base = base.parent  # the run's folder, above each worker's own
    cache = base / "compiled"
    cache.mkdir(exist_ok=True)
    before = os.environ.get("DESDEMONA_CACHE")
    os.environ["DESDEMONA_CACHE"] = str(cache)
    optimised, compiled.OPTIMISED = compiled.OPTIMISED, "never"
    if blasfeo.unavailable() is None:
        with open(base / "compiled.lock", "w") as lock:
            fcntl.flock(lock, fcntl.LOCK_EX)
            blasfeo.build()
    yield
    compiled.OPTIMISED = optimised
    if before is None:
        os.environ.pop("DESDEMONA_CACHE", None)
    else:
        os.environ["DESDEMONA_CACHE"] = before

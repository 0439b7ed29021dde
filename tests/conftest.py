"""Shared fixtures."""

import os

import pytest

from desdemona import blasfeo, default_params, thesis_toy_params


@pytest.fixture(scope="session")
def params():
    return default_params()


@pytest.fixture(scope="session")
def toy():
    return thesis_toy_params()


@pytest.fixture(scope="session", autouse=True)
def compiled_cache(tmp_path_factory):
    """Libraries compiled during the tests go to a folder of their own, not the user's cache. BLASFEO is
    built there first (about 15 s), so that no server started by a test spends its start-up on it."""
    before = os.environ.get("DESDEMONA_CACHE")
    os.environ["DESDEMONA_CACHE"] = str(tmp_path_factory.mktemp("compiled"))
    if blasfeo.unavailable() is None:
        blasfeo.build()
    yield
    if before is None:
        os.environ.pop("DESDEMONA_CACHE", None)
    else:
        os.environ["DESDEMONA_CACHE"] = before

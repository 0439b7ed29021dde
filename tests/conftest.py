"""Shared fixtures."""

import pytest

from desdemona import default_params, thesis_toy_params


@pytest.fixture(scope="session")
def params():
    return default_params()


@pytest.fixture(scope="session")
def toy():
    return thesis_toy_params()

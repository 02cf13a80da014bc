"""pytest setup: the module from the build tree (PYTHONPATH, set by ctest) and the program."""
import os

import pytest

SOURCE_DIR = os.environ.get("SIGHTLINE_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", ".."))


@pytest.fixture
def binary():
    path = os.environ.get("SIGHTLINE_BINARY")
    if not path or not os.path.exists(path):
        pytest.skip("SIGHTLINE_BINARY is not set (ctest sets it)")
    return path


@pytest.fixture
def source_dir():
    return SOURCE_DIR

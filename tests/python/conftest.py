"""Shared fixtures of the Python module's tests (spec/python.md): the built
CLI, the source tree, and the module itself from the build tree."""
import os
import pathlib

import pytest

SOURCE = pathlib.Path(__file__).resolve().parents[2]

# Under AddressSanitizer ctest preloads its runtime for this interpreter
# (tests/python/python.cmake); the CLI run from here links its own.
os.environ.pop("LD_PRELOAD", None)


@pytest.fixture(scope="session")
def cli():
    """The bccmis binary of the same build (BCCMIS_CLI, set by ctest)."""
    path = os.environ.get("BCCMIS_CLI")
    if not path:
        pytest.fail("BCCMIS_CLI is not set: run these tests through ctest (label python)")
    return path


@pytest.fixture(scope="session")
def source():
    return SOURCE

import os
import subprocess

import pytest

import cordgrasp


@pytest.fixture(scope="session")
def mug():
    return cordgrasp.load_mesh("mug")


@pytest.fixture(scope="session")
def hand():
    return cordgrasp.load_hand()


@pytest.fixture(scope="session")
def cli():
    """Path of the built `cordgrasp` command (ctest sets CORDGRASP_EXE)."""
    exe = os.environ.get("CORDGRASP_EXE")
    if not exe or not os.path.exists(exe):
        pytest.skip("CORDGRASP_EXE not set")
    return exe


def run(*args):
    return subprocess.run(args, check=True, capture_output=True, text=True)

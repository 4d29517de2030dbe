"""Shared fixtures: the command-line binary the module's results are compared with."""
import os
import subprocess

import pytest


@pytest.fixture(scope="session")
def cli():
    """Runs dfvn-sample (DFVN_SAMPLE, set by ctest) with stdin closed; returns its stdout, fails on error."""
    binary = os.environ.get("DFVN_SAMPLE")
    if not binary:
        pytest.fail("DFVN_SAMPLE is not set (ctest sets it to the built dfvn-sample)")

    def run(*args):
        done = subprocess.run([binary, *map(str, args)], stdin=subprocess.DEVNULL, capture_output=True, text=True)
        assert done.returncode == 0, f"dfvn-sample {' '.join(map(str, args))}: {done.stderr}"
        return done.stdout

    return run

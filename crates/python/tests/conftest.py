"""Shared helpers: the command line to compare with, found as the repository builds it."""

import csv
import io
import os
import pathlib
import subprocess

import pytest

REPOSITORY = pathlib.Path(__file__).resolve().parents[3]


@pytest.fixture(scope="session")
def newtonlab_cli():
    """The `newtonlab` binary (NEWTONLAB_BIN, or the repository's release build)."""
    binary = pathlib.Path(os.environ.get("NEWTONLAB_BIN", REPOSITORY / "target" / "release" / "newtonlab"))
    if not binary.is_file():
        pytest.fail(f"{binary} is missing: build it with `cargo build --release` (or set NEWTONLAB_BIN)")

    def call(*args):
        done = subprocess.run([str(binary), *args], capture_output=True, text=True, check=True)
        return list(csv.reader(io.StringIO(done.stdout)))

    return call

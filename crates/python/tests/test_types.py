"""The type stubs accept what a student writes: mypy --strict-ish on a typed file of
ordinary uses (a column's .max(), a text column as list[str], the builder's returns)."""

import pathlib
import subprocess
import sys

import pytest

HERE = pathlib.Path(__file__).parent


def test_mypy_accepts_the_ordinary_uses():
    pytest.importorskip("mypy")
    done = subprocess.run(
        [sys.executable, "-m", "mypy", "--no-incremental", "--disallow-untyped-calls",
         "--warn-return-any", str(HERE / "typed" / "uses.py")],
        capture_output=True, text=True,
    )
    assert done.returncode == 0, done.stdout + done.stderr


def test_the_typed_file_runs():
    done = subprocess.run([sys.executable, str(HERE / "typed" / "uses.py")], capture_output=True, text=True)
    assert done.returncode == 0, done.stderr

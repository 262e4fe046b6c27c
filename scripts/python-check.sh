#!/usr/bin/env bash
# NewtonLab in Python, as its users get it: a wheel built by maturin and installed into a
# fresh virtual environment, its pytest suite (which compares with the command line at
# target/release/newtonlab, built by `cargo test --release`), the notebooks executed
# headless, and the README's one command, `pip install ./crates/python`, in a fresh
# environment of its own. Needs python3 with venv, and the package registry (PyPI).
set -euo pipefail
cd "$(dirname "$0")/.."

fresh() {
    rm -rf "$1"
    python3 -m venv "$1"
    "$1/bin/pip" install --quiet --upgrade pip
}

echo "== the wheel (maturin build --release), into a fresh virtual environment"
venv=target/python-venv
fresh "$venv"
"$venv/bin/pip" install --quiet "maturin>=1.9,<2"
rm -rf target/wheels
"$venv/bin/maturin" build --release --quiet -m crates/python/Cargo.toml -o target/wheels
wheel=$(ls target/wheels/newtonlab-*.whl)
"$venv/bin/pip" install --quiet "$wheel[test]"

echo "== pytest crates/python/tests"
NEWTONLAB_BIN="$PWD/target/release/newtonlab" "$venv/bin/python" -m pytest -q crates/python/tests

echo "== the notebooks, executed (examples/notebooks/*.ipynb)"
"$venv/bin/python" - <<'PY'
import pathlib

import nbclient
import nbformat

for path in sorted(pathlib.Path("examples/notebooks").glob("*.ipynb")):
    notebook = nbformat.read(path, as_version=4)
    nbclient.NotebookClient(notebook, timeout=600, kernel_name="python3").execute()
    print(f"{path}: {sum(c.cell_type == 'code' for c in notebook.cells)} code cells ran")
PY

echo "== the README's command in a fresh environment: pip install ./crates/python"
readme=target/python-readme
fresh "$readme"
"$readme/bin/pip" install --quiet ./crates/python
"$readme/bin/python" -c 'import newtonlab; t = newtonlab.run("example:projectile", until=1.0); print("import newtonlab:", len(t), "rows")'

#!/usr/bin/env bash
# Everything CI checks, in the order a developer wants to hear about it: formatting,
# lints (warnings are errors), docs, then the tests in release mode (the physics tests
# run millions of steps; release also shares one build with the CLI and benches), then
# the Python package from a fresh virtual environment (scripts/python-check.sh).
set -euo pipefail
cd "$(dirname "$0")/.."

echo "== cargo fmt --check"
cargo fmt --all -- --check
cargo fmt --manifest-path crates/python/Cargo.toml -- --check

echo "== cargo clippy (warnings are errors)"
cargo clippy --workspace --all-targets --release -- -D warnings

echo "== cargo clippy for Python (crates/python, a workspace of its own)"
cargo clippy --manifest-path crates/python/Cargo.toml --all-targets --release -- -D warnings

echo "== cargo clippy for the web (wasm32: the browser-only code)"
rustup target add wasm32-unknown-unknown >/dev/null 2>&1 || true
cargo clippy --release -p newtonlab_app --lib --target wasm32-unknown-unknown -- -D warnings

echo "== cargo doc (warnings are errors)"
RUSTDOCFLAGS="-D warnings" cargo doc --workspace --no-deps --release --quiet

echo "== cargo test --release"
cargo test --workspace --release

echo "== Python: scripts/python-check.sh"
scripts/python-check.sh

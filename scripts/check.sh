#!/usr/bin/env bash
# Everything CI checks, in the order a developer wants to hear about it: formatting,
# lints (warnings are errors), docs, then the tests in release mode (the physics tests
# run millions of steps; release also shares one build with the CLI and benches).
set -euo pipefail
cd "$(dirname "$0")/.."

echo "== cargo fmt --check"
cargo fmt --all -- --check

echo "== cargo clippy (warnings are errors)"
cargo clippy --workspace --all-targets --release -- -D warnings

echo "== cargo clippy for the web (wasm32: the browser-only code)"
rustup target add wasm32-unknown-unknown >/dev/null 2>&1 || true
cargo clippy --release -p newtonlab_app --lib --target wasm32-unknown-unknown -- -D warnings

echo "== cargo doc (warnings are errors)"
RUSTDOCFLAGS="-D warnings" cargo doc --workspace --no-deps --release --quiet

echo "== cargo test --release"
cargo test --workspace --release

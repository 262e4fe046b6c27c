#!/usr/bin/env bash
# Builds NewtonLab for the browser into a folder of static files (index.html, the .wasm
# and its JavaScript) that any web server can host: default target/web.
#
# Needs only the package registries: the wasm32 target comes from rustup, and
# wasm-bindgen-cli is installed with cargo at exactly the version in Cargo.lock (the
# generated JavaScript and the library must match). No tool downloads a binary.
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:-target/web}

rustup target add wasm32-unknown-unknown >/dev/null
version=$(awk '/^name = "wasm-bindgen"$/ { getline; gsub(/"/, "", $3); print $3; exit }' Cargo.lock)
if [ "$(wasm-bindgen --version 2>/dev/null | awk '{print $2}')" != "$version" ]; then
    echo "installing wasm-bindgen-cli $version"
    # Not --locked: with it, a locked dependency version is missing from the registry.
    cargo install wasm-bindgen-cli --version "$version"
fi

cargo build --release --lib -p newtonlab_app --target wasm32-unknown-unknown
rm -rf "$out"
mkdir -p "$out"
wasm-bindgen --target web --no-typescript --out-dir "$out" \
    target/wasm32-unknown-unknown/release/newtonlab_app.wasm
cp web/index.html "$out/"
wasm=$(stat -c %s "$out/newtonlab_app_bg.wasm")
gzipped=$(gzip -9 -c "$out/newtonlab_app_bg.wasm" | wc -c)
echo "built $out: newtonlab_app_bg.wasm $((wasm / 1024)) KiB, $((gzipped / 1024)) KiB gzipped"
echo "serve it with: python3 -m http.server 8080 --bind 127.0.0.1 --directory $out"

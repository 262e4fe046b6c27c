#!/usr/bin/env bash
# Mutation testing of the physics crate with cargo-mutants: every plausible one-line bug
# (a sign, an operator, a constant, a function returning a default) is injected in turn
# and the physics tests must fail. On demand, not in CI: about 25 s per mutant on the
# 2-core machine, some 3,400 mutants for the whole physics (a day). Settings:
# .cargo/mutants.toml. Results: mutants.out/ (caught.txt, missed.txt, timeout.txt).
#
#   scripts/mutants.sh                                   everything configured
#   scripts/mutants.sh -f 'crates/physics/src/forces/*'  one module
#   scripts/mutants.sh --iterate                         skip mutants caught last time
#
# Missed mutants are either killed by a new test against theory or listed, with the
# reason they cannot matter, in docs/testing.md.
set -euo pipefail
cd "$(dirname "$0")/.."
command -v cargo-mutants >/dev/null 2>&1 || cargo install cargo-mutants --locked
exec cargo mutants -p physics "$@"

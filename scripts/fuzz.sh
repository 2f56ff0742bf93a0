#!/usr/bin/env bash
# Runs the host-session fuzz target (fuzz/fuzz_targets/session.rs) under libFuzzer with
# cargo-fuzz on the stable toolchain, starting from the committed corpus.
#
#   scripts/fuzz.sh [SECONDS]           # default 60; findings land in fuzz/artifacts/session/
#   scripts/fuzz.sh SECONDS --smoke     # new inputs go to a scratch directory, the
#                                       # committed corpus only seeds (CI's smoke run)
#
# Reproduce a finding with `cd fuzz && RUSTC_BOOTSTRAP=1 cargo fuzz run session FILE`.
set -euo pipefail
cd "$(dirname "$0")/../fuzz"
command -v cargo-fuzz >/dev/null || cargo install cargo-fuzz --locked
seconds=${1:-60}
corpora=(corpus/session)
# One input that runs for minutes is a finding too (libFuzzer's default allows 20).
limits=(-timeout=300)
if [ "${2:-}" = "--smoke" ]; then
    scratch=$(mktemp -d)
    trap 'rm -rf "$scratch"' EXIT
    corpora=("$scratch" corpus/session)
    limits=(-timeout=60)
fi
# cargo-fuzz passes nightly-only flags to rustc; RUSTC_BOOTSTRAP lets stable take them.
RUSTC_BOOTSTRAP=1 cargo fuzz run session "${corpora[@]}" -- \
    -max_total_time="$seconds" "${limits[@]}" -rss_limit_mb=4096 -print_final_stats=1

#!/usr/bin/env bash
# Runs a fuzz target under libFuzzer with cargo-fuzz on the stable toolchain, starting
# from its committed corpus: `session` (host sessions, fuzz/fuzz_targets/session.rs) or
# `restore` (damaged snapshots restored and carried on, fuzz/fuzz_targets/restore.rs).
#
#   scripts/fuzz.sh [SECONDS] [--smoke] [TARGET]   # default 60 s of `session`; findings
#                                                  # land in fuzz/artifacts/TARGET/
#   --smoke: new inputs go to a scratch directory, the committed corpus only seeds
#            (CI's smoke run)
#
# Reproduce a finding with `cd fuzz && RUSTC_BOOTSTRAP=1 cargo fuzz run TARGET FILE`.
set -euo pipefail
cd "$(dirname "$0")/../fuzz"
command -v cargo-fuzz >/dev/null || cargo install cargo-fuzz --locked
seconds=${1:-60}
smoke=
target=session
for arg in "${@:2}"; do
    case "$arg" in
        --smoke) smoke=1 ;;
        *) target=$arg ;;
    esac
done
corpora=("corpus/$target")
# One input that runs for minutes is a finding too (libFuzzer's default allows 20).
limits=(-timeout=300)
if [ -n "$smoke" ]; then
    scratch=$(mktemp -d)
    trap 'rm -rf "$scratch"' EXIT
    corpora=("$scratch" "corpus/$target")
    limits=(-timeout=60)
fi
# cargo-fuzz passes nightly-only flags to rustc; RUSTC_BOOTSTRAP lets stable take them.
RUSTC_BOOTSTRAP=1 cargo fuzz run "$target" "${corpora[@]}" -- \
    -max_total_time="$seconds" "${limits[@]}" -rss_limit_mb=4096 -print_final_stats=1

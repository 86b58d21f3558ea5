#!/usr/bin/env bash
# Instructions callgrind counts in one `simulate_prepared` (`loco-dev`'s `run_fingerprint`: a 500 m
# run at 200 km/h), repeatable on a shared machine where wall time is not. Prints the tool's
# output (metrics, fingerprints) and the instruction count; the callgrind file is kept for
# `callgrind_annotate`.
#
# usage: scripts/bench/callgrind_run.sh [fastsim|fastrip|table] [S_high|S_low] [curve|study_curve]
#        (arguments as `crates/loco-dev/src/bin/run_fingerprint.rs`; CALLGRIND_OUT sets the file, default
#        target/callgrind.<arguments>.out)
set -euo pipefail
cd "$(dirname "$0")/../.."
cargo build --release -q -p loco-dev --bin run_fingerprint
name=$(IFS=_; echo "${*:-fastsim}")
out=${CALLGRIND_OUT:-target/callgrind.$name.out}
log=$(mktemp)
valgrind --tool=callgrind --toggle-collect='*simulate_prepared*' --callgrind-out-file="$out" \
    target/release/run_fingerprint "$@" 2>"$log"
echo "instructions in simulate_prepared: $(grep -o 'Collected : [0-9]*' "$log" | grep -o '[0-9]*$')"
echo "callgrind file: $out"
rm -f "$log"

#!/usr/bin/env bash
# Installs loco with its development tools and runs every check: formatting, lints, the Rust tests,
# the type stubs against the native module, the documentation build, Chromium for the report page's
# browser test (from apt when missing), and pytest. This is the README's test command and what
# CI runs (.ci/run).
set -euo pipefail
cd "$(dirname "$0")/../.."

step() { printf '\n=== %s ===\n' "$*"; }

step "install (pip, editable, release build of the native module)"
python3 -m pip install --quiet --disable-pip-version-check -e '.[dev]'

step "rustfmt"
cargo fmt --all --check

step "clippy"
cargo clippy --workspace --all-targets --release -- -D warnings
# The contact recorder and its replay tool exist only with their feature.
cargo clippy -p loco-core -p loco-dev --all-targets --release --features loco-dev/record-contacts -- -D warnings

step "cargo test"
cargo test --workspace --release
cargo test -p loco-core --release --features record-contacts --lib contact_recording

step "loco-batch binary (compared with loco.run_batch by pytest)"
cargo build --release -p loco-batch

step "ruff"
python3 -m ruff check python tests scripts experiments
python3 -m ruff format --check python tests scripts experiments

step "mypy"
python3 -m mypy
python3 -m mypy.stubtest loco._loco

step "documentation (mkdocs, warnings and broken links are errors; into build/site/)"
# (not --quiet: it hides the warnings that strict mode counts, so a broken link would pass)
NO_MKDOCS_2_WARNING=1 python3 -m mkdocs build --strict

step "Chromium (the report page's browser test drives the distribution's package)"
if ! command -v chromium >/dev/null 2>&1; then
    if command -v apt-get >/dev/null 2>&1; then
        export DEBIAN_FRONTEND=noninteractive
        apt-get update -qq >/dev/null
        apt-get install -y -qq --no-install-recommends chromium >/dev/null
    else
        echo "chromium not found and no apt-get: tests/api/test_report_page.py will fail" >&2
    fi
fi

step "pytest"
# -m "": every test, the slow ones too (a plain `pytest` leaves them out, see pyproject.toml).
python3 -m pytest tests -m ""

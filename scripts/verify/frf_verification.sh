#!/usr/bin/env bash
# The frequency response against the time domain, full matrix: every scenario (S_low, S_norm, S_high), yaw damper (YD1, YD2, FSD),
# irregularity channel and wavelength (20, 40, 70, 150 m) at 200 km/h, 0.2 mm: the time-domain
# steady-state amplitude and phase against the linear frequency response. Prints one line per case.
# FRF_STEP and FRF_CONTACT_STEP set the linearisation steps (Hertz side, across the contact;
# default: LinearisationSettings's); FRF_CONTACT_STEP=5e-5 runs the candidate two groups.
set -euo pipefail
cd "$(dirname "$0")/../.."
cargo test -p loco-core --release --test verification -- --ignored --nocapture \
    frequency_response::sinusoidal_full_matrix frequency_response::cross_level

//! Dampers: Maxwell elements, the frequency-selective (FSD) yaw damper, hydraulic model, bench.

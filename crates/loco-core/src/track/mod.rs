//! Track irregularities: spectra, synthesis, measured files.

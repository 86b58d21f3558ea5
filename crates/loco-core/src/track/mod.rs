//! Track irregularities: spectra, synthesis, measured files.
//!
//! - [`spectrum`]: TB/T 3352-2014 and German low/high-interference target PSDs.
//! - [`synthesis`]: seeded synthesis of the four irregularities over a wavelength band.
//! - [`measured`]: measured irregularity CSV files (validated, resampled).
//! - [`irregularity`]: [`TrackIrregularity`], what the vehicle model reads with
//!   [`TrackIrregularity::at`]: left and right rail lateral and vertical positions and their
//!   derivatives along the track. Each wheelset calls it at its own distance, so the time
//!   delays between axles follow from the geometry.

pub mod design;
pub mod design_input;
pub mod irregularity;
pub mod measured;
pub mod spectrum;
pub mod synthesis;

pub use design::{CurveDirection, DesignPoint, DesignSection, TrackDesign};
pub use irregularity::{RailIrregularity, TrackIrregularity, TrackOrigin};
pub use measured::{load_csv, parse_csv, MeasuredParams};
pub use spectrum::{Channel, TrackSpectrum};
pub use synthesis::{synthesize, SynthesisParams};

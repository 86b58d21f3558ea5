//! Ride and stability metrics: PSD, Sperling index, bogie frame stability, comfort.

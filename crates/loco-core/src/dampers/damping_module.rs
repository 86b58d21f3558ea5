//! A damping module whose force makes the frequency valve's pressure: the FSD's closed (c2) or
//! open (c1) module, a damper in series with a spring and a mass at their node.

/// A damping module whose force makes the pressure: c (N·s/m; c2 closed, c1 open) in series
/// with k (N/m), mass m (kg) at the node.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ClosedModule {
    pub damping_nspm: f64,
    pub stiffness_npm: f64,
    pub mass_kg: f64,
}

impl ClosedModule {
    /// Force amplitude (N) for a sine stroke of amplitude `x` (m) at `omega` (rad/s).
    pub fn force_amplitude(&self, omega: f64, x: f64) -> f64 {
        let (c, k, m) = (self.damping_nspm, self.stiffness_npm, self.mass_kg);
        // |k·(iωc - mω²)/(k - mω² + iωc)|
        let num = k * (c * c * omega * omega + (m * omega * omega).powi(2)).sqrt();
        let den = ((k - m * omega * omega).powi(2) + (omega * c).powi(2)).sqrt();
        x * num / den
    }
}

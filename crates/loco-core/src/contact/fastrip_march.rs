//! The FASTSIM march along FaStrip's strips (see [`super::fastrip`]): FASTSIM with three
//! flexibilities and the elliptic bound, [`LANES`] strips in lockstep (the strips are independent,
//! so the CPU overlaps the serial chain of each), with the slip-zone sums FaStrip needs.
//! Lengths along a strip are in units of its half-length a_j (u = x/a_j), tractions in Pa.

/// Strips integrated together in the hot loop (as in FASTSIM).
pub(super) const LANES: usize = 4;

/// Per-strip inputs of the FASTSIM march, [`LANES`] strips at a time.
#[derive(Debug, Clone, Copy, Default)]
pub(super) struct Lanes {
    /// Strip centre y_j (m).
    pub(super) y: [f64; LANES],
    /// Strip half-length a_j (m; 0 for padding).
    pub(super) a_j: [f64; LANES],
    /// FASTSIM's increments per unit of u = x/a_j (Pa): a_j ∂p_x/∂x, and of a_j ∂p_y/∂x its
    /// constant and u-proportional parts.
    pub(super) gx: [f64; LANES],
    pub(super) gy0: [f64; LANES],
    pub(super) gy1: [f64; LANES],
    pub(super) bound_j: [f64; LANES],
    /// x_i/a_j · nx/2 + 1/2 (–).
    pub(super) slip_offset: [f64; LANES],
}

/// The FASTSIM march's state and sums (Pa): traction p, slip-zone sums q (traction on the bound
/// weighted by the slip fraction; `qyu` of u·p_y) and wb (slip fraction × bound), FASTSIM's own
/// sums s for the fallback.
#[derive(Debug, Clone, Copy, Default)]
pub(super) struct LaneState {
    pub(super) px: [f64; LANES],
    pub(super) py: [f64; LANES],
    pub(super) qx: [f64; LANES],
    pub(super) qy: [f64; LANES],
    pub(super) qyu: [f64; LANES],
    pub(super) wb: [f64; LANES],
    pub(super) sx: [f64; LANES],
    pub(super) sy: [f64; LANES],
    pub(super) syu: [f64; LANES],
}

/// An element of a strip, in units of the strip's half-length a_j.
#[derive(Debug, Clone, Copy)]
pub(super) struct Element {
    /// Centre u_k = x_k/a_j.
    pub(super) u: f64,
    /// Pressure shape √(1 − u_k²).
    pub(super) shape: f64,
    /// u_k·nx/2, for the slip fraction.
    pub(super) e: f64,
    /// Step from the previous centre (the leading edge for the first), u_{k−1} − u_k.
    pub(super) du: f64,
    /// Midpoint of that step.
    pub(super) u_mid: f64,
}

/// FASTSIM over `elements` for [`LANES`] strips; `SLIP`: accumulate the slip-zone sums,
/// `FALLBACK`: FASTSIM's own sums.
#[inline(always)]
pub(super) fn march<const SLIP: bool, const FALLBACK: bool>(
    elements: &[Element],
    lanes: &Lanes,
    st: &mut LaneState,
) {
    for e in elements {
        for l in 0..LANES {
            st.px[l] -= e.du * lanes.gx[l];
            st.py[l] -= e.du * (lanes.gy0[l] + e.u_mid * lanes.gy1[l]);
            let bound = lanes.bound_j[l] * e.shape;
            let norm = (st.px[l] * st.px[l] + st.py[l] * st.py[l])
                .sqrt()
                .max(f64::MIN_POSITIVE);
            // Finite even for p = 0 (where it multiplies zero tractions).
            let to_bound = (bound / norm).min(f64::MAX);
            if SLIP {
                let w = (lanes.slip_offset[l] - e.e).clamp(0.0, 1.0);
                let wt = w * to_bound;
                let ty = wt * st.py[l];
                st.qx[l] += wt * st.px[l];
                st.qy[l] += ty;
                st.qyu[l] += ty * e.u;
                st.wb[l] += w * bound;
            }
            let scale = to_bound.min(1.0);
            st.px[l] *= scale;
            st.py[l] *= scale;
            if FALLBACK {
                st.sx[l] += st.px[l];
                st.sy[l] += st.py[l];
                st.syu[l] += e.u * st.py[l];
            }
        }
    }
}

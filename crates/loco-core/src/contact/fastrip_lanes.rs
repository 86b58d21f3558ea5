//! FaStrip's work per strip (see [`super::fastrip`]), [`LANES`] strips at a time in SIMD lanes
//! ([`Simd`], as FASTSIM's, `G` groups of `W` lanes, `W·G = LANES`): the strip theory's slip
//! length and direction, the FASTSIM march along the strips (three flexibilities, the elliptic
//! bound) with the slip-zone sums FaStrip needs, and the strip solution's bound check. The strips
//! are independent, so a group's serial chains (a square root and a division per element)
//! overlap with the other groups'; written with plain per-strip arrays the compiler kept the
//! set-up scalar. Every lane does the scalar code's IEEE operations in its order (no fused
//! multiply-add), so the bits do not depend on `W`. Lengths along a strip are in units of its
//! half-length a_j (u = x/a_j), tractions in Pa.

use super::fastrip::{Call, StripLanes};
use super::fastsim_lanes::{Lanes as Simd, INSIDE_BOUND};
use std::f64::consts::PI;

/// Strips integrated together: the default grid's 10 strips and 2 empty ones, three AVX
/// registers (six SSE2 ones) whose chains overlap.
pub(super) const LANES: usize = 12;

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

/// `LANES` per-strip values as `G` registers of `W` lanes.
#[inline(always)]
fn pack<const W: usize, const G: usize>(a: &[f64; LANES]) -> [Simd<W>; G] {
    std::array::from_fn(|g| Simd(std::array::from_fn(|l| a[W * g + l])))
}

/// The registers' lanes back as `LANES` per-strip values.
#[inline(always)]
fn unpack<const W: usize, const G: usize>(v: &[Simd<W>; G]) -> [f64; LANES] {
    std::array::from_fn(|l| v[l / W].0[l % W])
}

/// FASTSIM over `elements` for [`LANES`] strips, `G` groups of `W` lanes of one SIMD register
/// each (`W·G = LANES`); `SLIP`: accumulate the slip-zone sums, `FALLBACK`: FASTSIM's own sums.
/// The state lives in registers for the march ([`Simd`] values, as in FASTSIM's lanes) and every
/// lane does the scalar code's IEEE operations in its order, so the bits do not depend on `W`.
#[inline(always)]
pub(super) fn march<const SLIP: bool, const FALLBACK: bool, const W: usize, const G: usize>(
    elements: &[Element],
    lanes: &Lanes,
    st: &mut LaneState,
) {
    let (gx, gy0, gy1) = (
        pack::<W, G>(&lanes.gx),
        pack::<W, G>(&lanes.gy0),
        pack::<W, G>(&lanes.gy1),
    );
    let (bound_j, slip_offset) = (
        pack::<W, G>(&lanes.bound_j),
        pack::<W, G>(&lanes.slip_offset),
    );
    let (mut px, mut py) = (pack::<W, G>(&st.px), pack::<W, G>(&st.py));
    let (mut qx, mut qy, mut qyu, mut wb) = (
        pack::<W, G>(&st.qx),
        pack::<W, G>(&st.qy),
        pack::<W, G>(&st.qyu),
        pack::<W, G>(&st.wb),
    );
    let (mut sx, mut sy, mut syu) = (
        pack::<W, G>(&st.sx),
        pack::<W, G>(&st.sy),
        pack::<W, G>(&st.syu),
    );
    let (floor, cap, one) = (
        Simd::splat(f64::MIN_POSITIVE),
        Simd::splat(f64::MAX),
        Simd::splat(1.0),
    );
    let inside = Simd::splat(INSIDE_BOUND);
    for e in elements {
        let (du, u_mid, shape) = (
            Simd::splat(e.du),
            Simd::splat(e.u_mid),
            Simd::splat(e.shape),
        );
        let (u, e_e) = (Simd::splat(e.u), Simd::splat(e.e));
        for g in 0..G {
            px[g] = px[g] - du * gx[g];
            py[g] = py[g] - du * (gy0[g] + u_mid * gy1[g]);
            let bound = bound_j[g] * shape;
            let norm2 = px[g] * px[g] + py[g] * py[g];
            // Ahead of the slip zones the scale is all that is read: exactly 1 where every lane
            // is inside the bound (as in FASTSIM's lanes), so the root and division are skipped.
            if SLIP || !norm2.all_le(bound * bound * inside) {
                // Finite even for p = 0 (where it multiplies zero tractions).
                let to_bound = bound.div(norm2.sqrt().max(floor)).min(cap);
                if SLIP {
                    let w = (slip_offset[g] - e_e).clamp(0.0, 1.0);
                    let wt = w * to_bound;
                    let ty = wt * py[g];
                    qx[g] = qx[g] + wt * px[g];
                    qy[g] = qy[g] + ty;
                    qyu[g] = qyu[g] + ty * u;
                    wb[g] = wb[g] + w * bound;
                }
                let scale = to_bound.min(one);
                px[g] = px[g] * scale;
                py[g] = py[g] * scale;
            }
            if FALLBACK {
                sx[g] = sx[g] + px[g];
                sy[g] = sy[g] + py[g];
                syu[g] = syu[g] + u * py[g];
            }
        }
    }
    st.px = unpack(&px);
    st.py = unpack(&py);
    st.qx = unpack(&qx);
    st.qy = unpack(&qy);
    st.qyu = unpack(&qyu);
    st.wb = unpack(&wb);
    st.sx = unpack(&sx);
    st.sy = unpack(&sy);
    st.syu = unpack(&syu);
}

/// The strip theory of [`LANES`] strips: slip half-length d (m; d = a_j means full slip) and the
/// unit direction (κ, λ) of the adhesion zone's rigid slip.
#[derive(Debug, Clone, Copy, Default)]
pub(super) struct StripSolutions {
    pub(super) d: [f64; LANES],
    pub(super) kappa: [f64; LANES],
    pub(super) lambda: [f64; LANES],
}

/// The march's inputs and the strip theory for the strips of `group` (`nx` elements per strip).
#[inline(always)]
pub(super) fn strip_lanes<const W: usize, const G: usize>(
    group: &StripLanes,
    k: &Call,
    nx: f64,
) -> (Lanes, StripSolutions) {
    let (eta, half_length, inv_half) = (
        pack::<W, G>(&group.eta),
        pack::<W, G>(&group.half_length),
        pack::<W, G>(&group.inv_half_length),
    );
    let s = Simd::<W>::splat;
    let (a, b, inv_a) = (s(k.a), s(k.b), s(k.inv_a));
    let (xi_s, eta_s, phi_s, d_factor) = (s(k.xi_s), s(k.eta_s), s(k.phi_s), s(k.d_factor));
    let (one, zero, floor) = (s(1.0), s(0.0), s(1e-20));
    let (two, half, nx) = (s(2.0), s(0.5), s(nx));
    let unit_spin = k.unit_spin;
    let (mut lanes, mut sol) = (Lanes::default(), StripSolutions::default());
    for g in 0..G {
        let y = eta[g] * b;
        let a_j = half_length[g] * a;
        let gx = a_j * (s(k.slope_x.0) - y * s(k.slope_x.1));
        let gy1 = a_j * a_j * s(k.slope_y.1);
        let u = xi_s - phi_s * y * inv_a;
        let disc = eta_s * eta_s + (one - phi_s * phi_s) * u * u;
        let d_raw = (disc.max(zero).sqrt() + eta_s * phi_s) * d_factor;
        // Partial slip where the discriminant is not negative and 0 ≤ d < a_j (and |φ'| ≠ 1):
        // an invalid slip length becomes +∞, which no strip takes.
        let valid = disc.map2(d_raw, |ds, dr| {
            if ds >= 0.0 && dr >= 0.0 {
                dr
            } else {
                f64::INFINITY
            }
        });
        let d = valid.map2(a_j, |dr, aj| if !unit_spin && dr < aj { dr } else { aj });
        let v = eta_s + phi_s * d * inv_a;
        let inv = one.div((u * u + v * v).max(floor).sqrt());
        // x_i/a_j · nx/2 + 1/2: an element's slip fraction is this minus its u_k·nx/2.
        let slip_offset = (two * d - a_j) * inv_a * inv_half[g] * half * nx + half;
        let lane_values = [
            (&mut lanes.y, y),
            (&mut lanes.a_j, a_j),
            (&mut lanes.gx, gx),
            (&mut lanes.gy0, a_j * s(k.slope_y.0)),
            (&mut lanes.gy1, gy1),
            (&mut lanes.bound_j, s(k.bound_peak) * half_length[g]),
            (&mut lanes.slip_offset, slip_offset),
            (&mut sol.d, d),
            (&mut sol.kappa, u * inv),
            (&mut sol.lambda, v * inv),
        ];
        for (out, value) in lane_values {
            out[W * g..W * (g + 1)].copy_from_slice(&value.0);
        }
    }
    (lanes, sol)
}

/// Per strip, whether the strip theory's adhesion tractions exceed μ p0 at an element centre
/// (CONTACT's validity check of the strip solution; read only for strips with adhesion), for the
/// strips of half-lengths `a_j` (m) on an ellipse of semi-axis `a` (m). One square root and no
/// division per element: with S_c = s_c/a, S_a = s_a/a and the unit direction,
/// |p|² a² = (κ² + λ²) s_c² + (κ² + λ_a²) s_a² − 2 (κ² + λ λ_a) s_c s_a (λ_a = λ − φ'), compared
/// with a². Strip by strip, with two roots, two divisions and an early exit, it cost more than
/// the march.
#[inline(always)]
pub(super) fn exceeds_bound<const W: usize, const G: usize>(
    elements: &[Element],
    a: f64,
    a_j: &[f64; LANES],
    sol: &StripSolutions,
    phi_s: f64,
) -> [bool; LANES] {
    let (a_j, d) = (pack::<W, G>(a_j), pack::<W, G>(&sol.d));
    let (kappa, lambda) = (pack::<W, G>(&sol.kappa), pack::<W, G>(&sol.lambda));
    let (zero, two, phi_s) = (Simd::splat(0.0), Simd::splat(2.0), Simd::splat(phi_s));
    let lambda_a: [Simd<W>; G] = std::array::from_fn(|g| lambda[g] - phi_s);
    let kappa2: [Simd<W>; G] = std::array::from_fn(|g| kappa[g] * kappa[g]);
    let c_c: [Simd<W>; G] = std::array::from_fn(|g| kappa2[g] + lambda[g] * lambda[g]);
    let c_a: [Simd<W>; G] = std::array::from_fn(|g| kappa2[g] + lambda_a[g] * lambda_a[g]);
    let c_ca: [Simd<W>; G] = std::array::from_fn(|g| two * (kappa2[g] + lambda[g] * lambda_a[g]));
    let r2: [Simd<W>; G] = std::array::from_fn(|g| (a_j[g] - d[g]) * (a_j[g] - d[g]));
    let x_i: [Simd<W>; G] = std::array::from_fn(|g| two * d[g] - a_j[g]);
    let a2 = a * a;
    let mut exceeds = [false; LANES];
    for e in elements {
        let u = Simd::splat(e.u);
        for g in 0..G {
            let x = u * a_j[g];
            let sc2 = (a_j[g] * a_j[g] - x * x).max(zero);
            let xd = x - d[g];
            let sa2 = (r2[g] - xd * xd).max(zero);
            let p2 = c_c[g] * sc2 + c_a[g] * sa2 - c_ca[g] * (sc2 * sa2).sqrt();
            for l in 0..W {
                exceeds[W * g + l] |= (x.0[l] > x_i[g].0[l]) & (p2.0[l] > a2);
            }
        }
    }
    exceeds
}

/// Adds the strips' forces to `f` = (F_x, F_y, M_z) (N, N, N·m), strip after strip in the order
/// of the scalar sums: the adhesion zone (Sichani's closed form: the bound's circular segment
/// ahead of x_i minus the adhesion semi-ellipse, radius a_j − d, centre d), then the slip zone
/// (FASTSIM's directions, the exact magnitude ∫ μ p_n over the zone); a strip whose strip
/// solution `exceeds` the bound (read with `FALLBACK`) adds FASTSIM's own sums instead. All but
/// the arc cosine of the segment's angle is computed in the lanes.
#[allow(clippy::too_many_arguments)]
#[inline(always)]
pub(super) fn add_strip_forces<const FALLBACK: bool, const W: usize, const G: usize>(
    lanes: &Lanes,
    sol: &StripSolutions,
    st: &LaneState,
    exceeds: &[bool; LANES],
    k: &Call,
    nx: f64,
    f: &mut [f64; 3],
) {
    let (a_j, d, y) = (
        pack::<W, G>(&lanes.a_j),
        pack::<W, G>(&sol.d),
        pack::<W, G>(&lanes.y),
    );
    let s = Simd::<W>::splat;
    let (one, two, three, half_pi) = (s(1.0), s(2.0), s(3.0), s(0.5 * PI));
    // The segment's angle θ (cos θ = x_i/a_j) and its first moment a_j³ sin³θ / 3.
    let cos_t: [Simd<W>; G] =
        std::array::from_fn(|g| (two * d[g] - a_j[g]).div(a_j[g]).clamp(-1.0, 1.0));
    let sin_t: [Simd<W>; G] = std::array::from_fn(|g| (one - cos_t[g] * cos_t[g]).sqrt());
    let moment: [Simd<W>; G] = std::array::from_fn(|g| {
        (a_j[g] * a_j[g] * a_j[g] * sin_t[g] * sin_t[g] * sin_t[g]).div(three)
    });
    let (cos_t, sin_t, moment) = (unpack(&cos_t), unpack(&sin_t), unpack(&moment));
    let adhesion: [bool; LANES] = std::array::from_fn(|l| sol.d[l] < lanes.a_j[l]);
    let (mut c0, mut c1) = ([0.0; LANES], [0.0; LANES]);
    for l in 0..LANES {
        if adhesion[l] {
            let a = lanes.a_j[l];
            c0[l] = 0.5 * a * a * (cos_t[l].acos() - sin_t[l] * cos_t[l]);
            c1[l] = moment[l];
        }
    }
    let (c0, c1) = (pack::<W, G>(&c0), pack::<W, G>(&c1));
    let (kappa, lambda, phi_s) = (
        pack::<W, G>(&sol.kappa),
        pack::<W, G>(&sol.lambda),
        s(k.phi_s),
    );
    let (qx, qy, qyu, wb) = (
        pack::<W, G>(&st.qx),
        pack::<W, G>(&st.qy),
        pack::<W, G>(&st.qyu),
        pack::<W, G>(&st.wb),
    );
    let (scale, zero) = (s(k.strip_scale), s(0.0));
    let mut terms = [[zero; G]; 9];
    for g in 0..G {
        let r = a_j[g] - d[g];
        let a0 = half_pi * r * r;
        let a1 = d[g] * a0;
        let lambda_a = lambda[g] - phi_s;
        let gx = kappa[g] * (c0[g] - a0);
        let gy = lambda[g] * c0[g] - lambda_a * a0;
        let gm = lambda[g] * c1[g] - lambda_a * a1;
        terms[0][g] = gx * scale;
        terms[1][g] = gy * scale;
        terms[2][g] = (gm - y[g] * gx) * scale;
        let w = ((half_pi * a_j[g] * a_j[g] - c0[g]) * scale).div(wb[g]);
        terms[3][g] = qx[g] * w;
        terms[4][g] = qy[g] * w;
        terms[5][g] = (a_j[g] * qyu[g] - y[g] * qx[g]) * w;
        if FALLBACK {
            let (sx, sy, syu) = (
                pack::<W, G>(&st.sx),
                pack::<W, G>(&st.sy),
                pack::<W, G>(&st.syu),
            );
            let area = (two * a_j[g]).div(s(nx)) * s(k.dy);
            terms[6][g] = sx[g] * area;
            terms[7][g] = sy[g] * area;
            terms[8][g] = (a_j[g] * syu[g] - y[g] * sx[g]) * area;
        }
    }
    let terms = terms.map(|t| unpack(&t));
    for l in 0..LANES {
        let zones: &[usize] = if FALLBACK && adhesion[l] && exceeds[l] {
            &[6]
        } else {
            match (adhesion[l], st.wb[l] > 0.0) {
                (true, true) => &[0, 3],
                (true, false) => &[0],
                (false, true) => &[3],
                (false, false) => &[],
            }
        };
        for &z in zones {
            for (i, sum) in f.iter_mut().enumerate() {
                *sum += terms[z + i][l];
            }
        }
    }
}

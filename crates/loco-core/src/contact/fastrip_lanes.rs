//! FaStrip's work per strip (see [`super::fastrip`]) in SIMD registers ([`Register`], FASTSIM's
//! [`Simd`] lanes): the strip theory's slip length and direction, the FASTSIM march along the
//! strips (three flexibilities, the elliptic bound) with the slip-zone sums FaStrip needs, the
//! strip solution's bound check and the zones' forces. A pass holds [`LANES`] strips as `G`
//! registers of `W` lanes and a tail register of `T` (`W·G + T = LANES`): with AVX two 256-bit
//! registers and one 128-bit one, as FASTSIM's strips, because the divider takes a 256-bit root
//! or division in twice the time of a 128-bit one. The registers' chains (a root and a division
//! per element) overlap. Every lane does the scalar code's IEEE operations in its order (no fused
//! multiply-add), so the bits do not depend on the layout. Lengths along a strip are in units of
//! its half-length a_j (u = x/a_j), tractions in Pa.

use super::fastrip::{Call, StripLanes};
use super::fastsim_lanes::{inside_test, Lanes as Simd, INSIDE_BOUND};
use std::f64::consts::PI;

/// Strips of one pass: the default grid's 10.
pub(super) const LANES: usize = 10;

/// An element of a strip, in units of the strip's half-length a_j.
#[derive(Debug, Clone, Copy)]
pub(super) struct Element {
    /// Centre u_k = x_k/a_j.
    pub(super) u: f64,
    /// Pressure shape √(1 − u_k²).
    pub(super) shape: f64,
    /// shape²·[`INSIDE_BOUND`]: with a strip's bound_j² the projection's skip test in one
    /// product (as in FASTSIM's lanes).
    pub(super) inside: f64,
    /// u_k·nx/2, for the slip fraction.
    pub(super) e: f64,
    /// Step from the previous centre (the leading edge for the first), u_{k−1} − u_k.
    pub(super) du: f64,
    /// Midpoint of that step.
    pub(super) u_mid: f64,
}

impl Element {
    /// The element of centre `u` after the previous centre `previous` (1 for the first), on a
    /// strip of `nx` elements.
    pub(super) fn new(u: f64, previous: f64, nx: usize) -> Self {
        let shape = (1.0 - u * u).sqrt();
        Self {
            u,
            shape,
            inside: shape * shape * INSIDE_BOUND,
            e: 0.5 * u * nx as f64,
            du: previous - u,
            u_mid: 0.5 * (previous + u),
        }
    }
}

/// `W` strips of a pass: their march inputs, strip solutions and march state.
#[derive(Debug, Clone, Copy)]
pub(super) struct Register<const W: usize> {
    /// Strip centre y_j (m).
    y: Simd<W>,
    /// Strip half-length a_j (m; 0 for padding).
    a_j: Simd<W>,
    /// FASTSIM's increments per unit of u = x/a_j (Pa): a_j ∂p_x/∂x, and of a_j ∂p_y/∂x its
    /// constant and u-proportional parts.
    gx: Simd<W>,
    gy0: Simd<W>,
    gy1: Simd<W>,
    /// Traction bound on the strip's centre line (Pa) and its skip-test square.
    bound_j: Simd<W>,
    inside_j: Simd<W>,
    /// x_i/a_j · nx/2 + 1/2 (–): an element's slip fraction is this minus its u_k·nx/2.
    slip_offset: Simd<W>,
    /// The strip theory: slip half-length d (m; d = a_j is full slip) and the unit direction
    /// (κ, λ) of the adhesion zone's rigid slip.
    d: Simd<W>,
    kappa: Simd<W>,
    lambda: Simd<W>,
    /// The march: traction p, slip-zone sums q (traction on the bound weighted by the slip
    /// fraction; `qyu` of u·p_y) and wb (slip fraction × bound), FASTSIM's own sums s for the
    /// fallback (Pa).
    px: Simd<W>,
    py: Simd<W>,
    qx: Simd<W>,
    qy: Simd<W>,
    qyu: Simd<W>,
    wb: Simd<W>,
    sx: Simd<W>,
    sy: Simd<W>,
    syu: Simd<W>,
    /// The first element with a slip fraction in any of the register's strips (the element
    /// count where it has none): the slip-zone sums start there, and ahead of it only the
    /// projection runs, where some strip leaves the bound.
    first_slip: usize,
}

/// A register's forces per lane: (F_x, F_y, M_z) of the adhesion zone, of the slip zone and of
/// FASTSIM's own sums (N, N, N·m), and which zones a lane adds, in the order of the scalar sums.
pub(super) struct RegisterForces<const W: usize> {
    terms: [[f64; W]; 9],
    zones: [&'static [usize]; W],
}

impl<const W: usize> Register<W> {
    /// Strips `first..first + W` of `pass`: the march's inputs and the strip theory, for
    /// `elements` per strip.
    #[inline(always)]
    pub(super) fn new(pass: &StripLanes, first: usize, k: &Call, elements: usize) -> Self {
        let take = |a: &[f64; LANES]| {
            let mut lanes = [0.0; W];
            lanes.copy_from_slice(&a[first..first + W]);
            Simd(lanes)
        };
        let (eta, half_length, inv_half) = (
            take(&pass.eta),
            take(&pass.half_length),
            take(&pass.inv_half_length),
        );
        let s = Simd::<W>::splat;
        let (a, b, inv_a) = (s(k.a), s(k.b), s(k.inv_a));
        let (xi_s, eta_s, phi_s, d_factor) = (s(k.xi_s), s(k.eta_s), s(k.phi_s), s(k.d_factor));
        let (one, zero, floor) = (s(1.0), s(0.0), s(1e-20));
        let nx = elements as f64;
        let (two, half, nx_lanes) = (s(2.0), s(0.5), s(nx));
        let y = eta * b;
        let a_j = half_length * a;
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
        let unit_spin = k.unit_spin;
        let d = valid.map2(a_j, |dr, aj| if !unit_spin && dr < aj { dr } else { aj });
        let v = eta_s + phi_s * d * inv_a;
        let inv = one.div((u * u + v * v).max(floor).sqrt());
        let slip_offset = (two * d - a_j) * inv_a * inv_half * half * nx_lanes + half;
        let bound_j = s(k.bound_peak) * half_length;
        let mut inside_j = bound_j;
        for v in &mut inside_j.0 {
            *v = inside_test(*v);
        }
        let mut first_slip = elements;
        for l in 0..W {
            if half_length.0[l] > 0.0 {
                // Element k's slip fraction is clamp(c − u_k·nx/2, 0, 1) with u_k·nx/2 =
                // nx/2 − k − 1/2, so k − X with X = nx/2 − 1/2 − c. Every k ≤ ⌊X⌋ − 1 is at
                // least 1 below X and has none whatever the rounding; k = ⌊X⌋ may round to a
                // sliver and is summed. (`as` truncates: the floor of a non-negative number.)
                let before = (0.5 * nx - 0.5 - slip_offset.0[l]).max(0.0);
                first_slip = first_slip.min(before as usize);
            }
        }
        Self {
            y,
            a_j,
            gx: a_j * (s(k.slope_x.0) - y * s(k.slope_x.1)),
            gy0: a_j * s(k.slope_y.0),
            gy1: a_j * a_j * s(k.slope_y.1),
            bound_j,
            inside_j,
            slip_offset,
            d,
            kappa: u * inv,
            lambda: v * inv,
            px: zero,
            py: zero,
            qx: zero,
            qy: zero,
            qyu: zero,
            wb: zero,
            sx: zero,
            sy: zero,
            syu: zero,
            first_slip,
        }
    }

    /// One element of FASTSIM's march; with `slip`, the slip-zone sums too, with `FALLBACK`
    /// FASTSIM's own sums.
    #[inline(always)]
    pub(super) fn step<const FALLBACK: bool>(&mut self, e: &Element, slip: bool) {
        let (du, u_mid, shape) = (
            Simd::splat(e.du),
            Simd::splat(e.u_mid),
            Simd::splat(e.shape),
        );
        let u = Simd::splat(e.u);
        self.px = self.px - du * self.gx;
        self.py = self.py - du * (self.gy0 + u_mid * self.gy1);
        let norm2 = self.px * self.px + self.py * self.py;
        // Ahead of the slip zones the scale is all that is read: exactly 1 where every lane is
        // inside the bound by more than rounding (FASTSIM's test), so the root and division are
        // skipped.
        if slip || !norm2.all_le(self.inside_j * Simd::splat(e.inside)) {
            let bound = self.bound_j * shape;
            // Finite even for p = 0 (where it multiplies zero tractions).
            let to_bound = bound
                .div(norm2.sqrt().max(Simd::splat(f64::MIN_POSITIVE)))
                .min(Simd::splat(f64::MAX));
            if slip {
                let w = (self.slip_offset - Simd::splat(e.e)).clamp(0.0, 1.0);
                let wt = w * to_bound;
                let ty = wt * self.py;
                self.qx = self.qx + wt * self.px;
                self.qy = self.qy + ty;
                self.qyu = self.qyu + ty * u;
                self.wb = self.wb + w * bound;
            }
            let scale = to_bound.min(Simd::splat(1.0));
            self.px = self.px * scale;
            self.py = self.py * scale;
        }
        if FALLBACK {
            self.sx = self.sx + self.px;
            self.sy = self.sy + self.py;
            self.syu = self.syu + u * self.py;
        }
    }

    /// Per strip, whether the strip theory's adhesion tractions exceed μ p0 at an element centre
    /// (CONTACT's validity check of the strip solution; read only for strips with adhesion), on
    /// an ellipse of semi-axis `a` (m). One square root and no division per element: with S_c =
    /// s_c/a, S_a = s_a/a and the unit direction, |p|² a² = (κ² + λ²) s_c² + (κ² + λ_a²) s_a² −
    /// 2 (κ² + λ λ_a) s_c s_a (λ_a = λ − φ'), compared with a².
    // The lane index runs over several per-lane arrays in lockstep.
    #[allow(clippy::needless_range_loop)]
    #[inline(always)]
    pub(super) fn exceeds_bound(&self, elements: &[Element], a: f64, phi_s: f64) -> [bool; W] {
        let (a_j, d, kappa, lambda) = (self.a_j, self.d, self.kappa, self.lambda);
        let (zero, two) = (Simd::splat(0.0), Simd::splat(2.0));
        let lambda_a = lambda - Simd::splat(phi_s);
        let kappa2 = kappa * kappa;
        let c_c = kappa2 + lambda * lambda;
        let c_a = kappa2 + lambda_a * lambda_a;
        let c_ca = two * (kappa2 + lambda * lambda_a);
        let r2 = (a_j - d) * (a_j - d);
        let x_i = two * d - a_j;
        let a2 = a * a;
        let mut exceeds = [false; W];
        for e in elements {
            let x = Simd::splat(e.u) * a_j;
            let sc2 = (a_j * a_j - x * x).max(zero);
            let xd = x - d;
            let sa2 = (r2 - xd * xd).max(zero);
            let p2 = c_c * sc2 + c_a * sa2 - c_ca * (sc2 * sa2).sqrt();
            for l in 0..W {
                exceeds[l] |= (x.0[l] > x_i.0[l]) & (p2.0[l] > a2);
            }
        }
        exceeds
    }

    /// The strips' forces: the adhesion zone (Sichani's closed form: the bound's circular
    /// segment ahead of x_i minus the adhesion semi-ellipse, radius a_j − d, centre d), the slip
    /// zone (FASTSIM's directions, the exact magnitude ∫ μ p_n over the zone) and, with
    /// `FALLBACK`, FASTSIM's own sums, which a strip whose strip solution `exceeds` the bound
    /// adds instead. The segment's arc cosine too runs in lanes ([`acos`]).
    #[allow(clippy::needless_range_loop)]
    #[inline(always)]
    pub(super) fn forces<const FALLBACK: bool>(
        &self,
        k: &Call,
        nx: f64,
        exceeds: &[bool; W],
    ) -> RegisterForces<W> {
        let (a_j, d, y) = (self.a_j, self.d, self.y);
        let s = Simd::<W>::splat;
        let (one, two, three, half_pi) = (s(1.0), s(2.0), s(3.0), s(0.5 * PI));
        // The segment's angle θ (cos θ = x_i/a_j) and its first moment a_j³ sin³θ / 3.
        let cos_t = (two * d - a_j).div(a_j).clamp(-1.0, 1.0);
        let sin_t = (one - cos_t * cos_t).sqrt();
        let moment = (a_j * a_j * a_j * sin_t * sin_t * sin_t).div(three);
        let adhesion: [bool; W] = std::array::from_fn(|l| d.0[l] < a_j.0[l]);
        let theta = acos(cos_t);
        let (mut c0, mut c1) = (s(0.0), s(0.0));
        for l in 0..W {
            if adhesion[l] {
                let a = a_j.0[l];
                c0.0[l] = 0.5 * a * a * (theta.0[l] - sin_t.0[l] * cos_t.0[l]);
                c1.0[l] = moment.0[l];
            }
        }
        let scale = s(k.strip_scale);
        let r = a_j - d;
        let a0 = half_pi * r * r;
        let a1 = d * a0;
        let lambda_a = self.lambda - s(k.phi_s);
        let gx = self.kappa * (c0 - a0);
        let gy = self.lambda * c0 - lambda_a * a0;
        let gm = self.lambda * c1 - lambda_a * a1;
        let w = ((half_pi * a_j * a_j - c0) * scale).div(self.wb);
        let mut terms = [s(0.0); 9];
        terms[0] = gx * scale;
        terms[1] = gy * scale;
        terms[2] = (gm - y * gx) * scale;
        terms[3] = self.qx * w;
        terms[4] = self.qy * w;
        terms[5] = (a_j * self.qyu - y * self.qx) * w;
        if FALLBACK {
            let area = (two * a_j).div(s(nx)) * s(k.dy);
            terms[6] = self.sx * area;
            terms[7] = self.sy * area;
            terms[8] = (a_j * self.syu - y * self.sx) * area;
        }
        let zones = std::array::from_fn(|l| -> &'static [usize] {
            if FALLBACK && adhesion[l] && exceeds[l] {
                &[6]
            } else {
                match (adhesion[l], self.wb.0[l] > 0.0) {
                    (true, true) => &[0, 3],
                    (true, false) => &[0],
                    (false, true) => &[3],
                    (false, false) => &[],
                }
            }
        });
        RegisterForces {
            terms: terms.map(|t| t.0),
            zones,
        }
    }
}

/// The arc cosine of every lane (`x` in [−1, 1]), two at a time by `wide`'s vectorised `acos`
/// (Agner Fog's vector class library: a rational approximation, within a few ulp of the libm
/// function), so that both builds and every register width give the same bits.
#[inline(always)]
pub(super) fn acos<const W: usize>(x: Simd<W>) -> Simd<W> {
    let mut out = x;
    for pair in out.0.chunks_mut(2) {
        let mut two = [0.0; 2];
        two[..pair.len()].copy_from_slice(pair);
        let theta = wide::f64x2::from(two).acos().to_array();
        pair.copy_from_slice(&theta[..pair.len()]);
    }
    out
}

impl<const W: usize> Register<W> {
    /// Adds the register's strips' forces to `f` = (F_x, F_y, M_z), lane after lane, after the
    /// march over `elements`.
    #[inline(always)]
    fn add_forces<const FALLBACK: bool>(&self, elements: &[Element], k: &Call, f: &mut [f64; 3]) {
        let exceeds = if FALLBACK {
            self.exceeds_bound(elements, k.a, k.phi_s)
        } else {
            [false; W]
        };
        let forces = self.forces::<FALLBACK>(k, elements.len() as f64, &exceeds);
        for l in 0..W {
            forces.add_lane(l, f);
        }
    }
}

impl<const W: usize> RegisterForces<W> {
    /// Adds lane `l`'s zones to `f` = (F_x, F_y, M_z).
    #[inline(always)]
    fn add_lane(&self, l: usize, f: &mut [f64; 3]) {
        for &z in self.zones[l] {
            for (i, sum) in f.iter_mut().enumerate() {
                *sum += self.terms[z + i][l];
            }
        }
    }
}

/// One pass of [`LANES`] strips (`pass`, `elements` per strip) through FaStrip, its forces added
/// to `f` strip after strip: `G` registers of `W` lanes and a tail of `T` (`W·G + T = LANES`);
/// `FALLBACK`: |φ'| > 1, FASTSIM's own sums and the bound check.
#[inline(always)]
pub(super) fn pass<const FALLBACK: bool, const W: usize, const G: usize, const T: usize>(
    strips: &StripLanes,
    elements: &[Element],
    k: &Call,
    f: &mut [f64; 3],
) {
    const { assert!(W * G + T == LANES) };
    let n = elements.len();
    // A loop, not `from_fn`, whose closure the AVX compilation called per register (FASTSIM's
    // lanes).
    let mut regs = [Register::<W>::new(strips, 0, k, n); G];
    for (g, reg) in regs.iter_mut().enumerate().skip(1) {
        *reg = Register::new(strips, W * g, k, n);
    }
    let mut tail = Register::<T>::new(strips, W * G, k, n);
    for (index, e) in elements.iter().enumerate() {
        for reg in &mut regs {
            reg.step::<FALLBACK>(e, index >= reg.first_slip);
        }
        tail.step::<FALLBACK>(e, index >= tail.first_slip);
    }
    for reg in &regs {
        reg.add_forces::<FALLBACK>(elements, k, f);
    }
    tail.add_forces::<FALLBACK>(elements, k, f);
}

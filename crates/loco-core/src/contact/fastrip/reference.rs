//! FaStrip's strips as they ran before their passes of ten (twelve strips per pass in three
//! registers, the slip-zone sums from the pass's first slipping element), kept as the bit-for-bit reference of
//! [`super::super::fastrip_lanes`], which must give the same forces for any grid and input. One
//! change: the segment's arc cosine is the lanes' vectorised one, not libm's.

use super::super::fastrip::{Call, Fastrip};
use super::super::fastrip_lanes::{acos, Element, LANES as NEW_LANES};
use super::super::kalker::CreepForces;
use crate::contact::fastsim_lanes::INSIDE_BOUND;
use crate::simd::Lanes as Simd;
use std::f64::consts::PI;

/// Geometry of [`LANES`] strips in units of (a, b), as [`super::super::fastrip::StripLanes`].
#[derive(Debug, Clone, Copy, Default)]
struct StripLanes {
    eta: [f64; LANES],
    half_length: [f64; LANES],
    inv_half_length: [f64; LANES],
}

/// FaStrip's forces for the per-call constants `k` of `solver`, the old way.
pub(in crate::contact) fn creep_forces<const FALLBACK: bool>(
    solver: &Fastrip,
    k: &Call,
) -> CreepForces {
    // The solver's own strips and elements, the strips regrouped twelve to a pass.
    let ny = solver.params().ny;
    let strip = |j: usize| &solver.strips[j / NEW_LANES];
    let strips: Vec<StripLanes> = (0..ny.div_ceil(LANES))
        .map(|group| {
            let mut lanes = StripLanes::default();
            for lane in 0..LANES {
                let j = group * LANES + lane;
                if j < ny {
                    let (from, l) = (strip(j), j % NEW_LANES);
                    lanes.eta[lane] = from.eta[l];
                    lanes.half_length[lane] = from.half_length[l];
                    lanes.inv_half_length[lane] = from.inv_half_length[l];
                }
            }
            lanes
        })
        .collect();
    let elements = &solver.elements;
    let nx = elements.len() as f64;
    let mut f = [0.0; 3];
    for group in &strips {
        let (lanes, sol) = strip_lanes::<2, 6>(group, k, nx);
        let mut first_slip = elements.len();
        for l in 0..LANES {
            if group.half_length[l] > 0.0 {
                let before = (0.5 * nx - 1.5 - lanes.slip_offset[l]).max(0.0);
                first_slip = first_slip.min(before as usize);
            }
        }
        let mut state = LaneState::default();
        let (ahead, behind) = elements.split_at(first_slip.min(elements.len()));
        march::<false, FALLBACK, 2, 6>(ahead, &lanes, &mut state);
        march::<true, FALLBACK, 2, 6>(behind, &lanes, &mut state);
        let exceeds = if FALLBACK {
            exceeds_bound::<2, 6>(elements, k.a, &lanes.a_j, &sol, k.phi_s)
        } else {
            [false; LANES]
        };
        add_strip_forces::<FALLBACK, 2, 6>(&lanes, &sol, &state, &exceeds, k, nx, &mut f);
    }
    let [fx, fy, mz] = f;
    CreepForces { fx, fy, mz }
}

/// Strips of one pass, in three AVX registers or six SSE2 ones (the body below is the old file,
/// its item comments left out).
const LANES: usize = 12;

#[derive(Debug, Clone, Copy, Default)]
struct Lanes {
    y: [f64; LANES],
    a_j: [f64; LANES],
    gx: [f64; LANES],
    gy0: [f64; LANES],
    gy1: [f64; LANES],
    bound_j: [f64; LANES],
    slip_offset: [f64; LANES],
}

#[derive(Debug, Clone, Copy, Default)]
struct LaneState {
    px: [f64; LANES],
    py: [f64; LANES],
    qx: [f64; LANES],
    qy: [f64; LANES],
    qyu: [f64; LANES],
    wb: [f64; LANES],
    sx: [f64; LANES],
    sy: [f64; LANES],
    syu: [f64; LANES],
}

#[inline(always)]
fn pack<const W: usize, const G: usize>(a: &[f64; LANES]) -> [Simd<W>; G] {
    std::array::from_fn(|g| Simd(std::array::from_fn(|l| a[W * g + l])))
}

#[inline(always)]
fn unpack<const W: usize, const G: usize>(v: &[Simd<W>; G]) -> [f64; LANES] {
    std::array::from_fn(|l| v[l / W].0[l % W])
}

#[inline(always)]
fn march<const SLIP: bool, const FALLBACK: bool, const W: usize, const G: usize>(
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
            if SLIP || !norm2.all_le(bound * bound * inside) {
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

#[derive(Debug, Clone, Copy, Default)]
struct StripSolutions {
    d: [f64; LANES],
    kappa: [f64; LANES],
    lambda: [f64; LANES],
}

#[inline(always)]
fn strip_lanes<const W: usize, const G: usize>(
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

#[inline(always)]
fn exceeds_bound<const W: usize, const G: usize>(
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

#[allow(clippy::too_many_arguments)]
#[inline(always)]
fn add_strip_forces<const FALLBACK: bool, const W: usize, const G: usize>(
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
            c0[l] = 0.5 * a * a * (acos(Simd([cos_t[l]])).0[0] - sin_t[l] * cos_t[l]);
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

//! The AVX lanes of `super::turn`: four bodies' wrenches turned in one register.
//!
//! The wrenches are rows of six numbers per body; four rows are transposed into six registers
//! (one per component, a body per lane), turned with `super::turn`'s IEEE operations in its
//! order, and transposed back. The functions are `unsafe fn`s enabling AVX, called only from
//! [`turn_groups`], whose caller has checked the processor.

use super::{ForceLanes, W};
use crate::vehicle::model::bushing_lanes::avx::{cross, dif, sub, sum, v3};
use crate::vehicle::model::elements::Wrenches;
use std::arch::x86_64::{
    __m256d, _mm256_castpd128_pd256, _mm256_castpd256_pd128, _mm256_extractf128_pd,
    _mm256_insertf128_pd, _mm256_loadu_pd, _mm256_permute2f128_pd, _mm256_storeu_pd,
    _mm256_unpackhi_pd, _mm256_unpacklo_pd, _mm_loadu_pd, _mm_storeu_pd,
};

/// Turns the wrenches of the bodies of `groups` (bodies `W·g … W·g + 3` for group g, all of
/// them bodies) as `super::turn` does each.
#[target_feature(enable = "avx")]
pub(super) unsafe fn turn_groups(groups: &[ForceLanes], wrenches: &mut Wrenches) {
    for (q, rows) in groups.iter().zip(wrenches.chunks_exact_mut(W)) {
        let rows: &mut [[f64; 6]; W] = rows.try_into().expect("chunks of W rows");
        turn_group(q, rows);
    }
}

/// Lane l of each register: component k of row l, for k = 0 … 5.
#[target_feature(enable = "avx")]
#[inline]
unsafe fn load_columns(rows: &[[f64; 6]; W]) -> [__m256d; 6] {
    // SAFETY (the loads): each reads four numbers from `rows[l][0..4]` or two from
    // `rows[l][4..6]`, inside the row.
    let lo = rows
        .each_ref()
        .map(|r| unsafe { _mm256_loadu_pd(r.as_ptr()) });
    let hi = rows
        .each_ref()
        .map(|r| unsafe { _mm_loadu_pd(r.as_ptr().add(4)) });
    let t0 = _mm256_unpacklo_pd(lo[0], lo[1]);
    let t1 = _mm256_unpackhi_pd(lo[0], lo[1]);
    let t2 = _mm256_unpacklo_pd(lo[2], lo[3]);
    let t3 = _mm256_unpackhi_pd(lo[2], lo[3]);
    let h02 = _mm256_insertf128_pd(_mm256_castpd128_pd256(hi[0]), hi[2], 1);
    let h13 = _mm256_insertf128_pd(_mm256_castpd128_pd256(hi[1]), hi[3], 1);
    [
        _mm256_permute2f128_pd(t0, t2, 0x20),
        _mm256_permute2f128_pd(t1, t3, 0x20),
        _mm256_permute2f128_pd(t0, t2, 0x31),
        _mm256_permute2f128_pd(t1, t3, 0x31),
        _mm256_unpacklo_pd(h02, h13),
        _mm256_unpackhi_pd(h02, h13),
    ]
}

/// The inverse of [`load_columns`].
#[target_feature(enable = "avx")]
#[inline]
unsafe fn store_columns(c: [__m256d; 6], rows: &mut [[f64; 6]; W]) {
    let u0 = _mm256_unpacklo_pd(c[0], c[1]);
    let u1 = _mm256_unpackhi_pd(c[0], c[1]);
    let u2 = _mm256_unpacklo_pd(c[2], c[3]);
    let u3 = _mm256_unpackhi_pd(c[2], c[3]);
    let v0 = _mm256_unpacklo_pd(c[4], c[5]);
    let v1 = _mm256_unpackhi_pd(c[4], c[5]);
    let lo = [
        _mm256_permute2f128_pd(u0, u2, 0x20),
        _mm256_permute2f128_pd(u1, u3, 0x20),
        _mm256_permute2f128_pd(u0, u2, 0x31),
        _mm256_permute2f128_pd(u1, u3, 0x31),
    ];
    let hi = [
        _mm256_castpd256_pd128(v0),
        _mm256_castpd256_pd128(v1),
        _mm256_extractf128_pd(v0, 1),
        _mm256_extractf128_pd(v1, 1),
    ];
    for ((row, lo), hi) in rows.iter_mut().zip(lo).zip(hi) {
        // SAFETY: four numbers into `row[0..4]` and two into `row[4..6]`, inside the row.
        unsafe {
            _mm256_storeu_pd(row.as_mut_ptr(), lo);
            _mm_storeu_pd(row.as_mut_ptr().add(4), hi);
        }
    }
}

/// Four numbers of `lanes` in one register.
#[target_feature(enable = "avx")]
#[inline]
unsafe fn load(lanes: &[f64; W]) -> __m256d {
    // SAFETY: reads the four numbers of `lanes`.
    unsafe { _mm256_loadu_pd(lanes.as_ptr()) }
}

/// `super::turn` of the four bodies of `rows`, lane by lane.
#[target_feature(enable = "avx")]
#[inline]
unsafe fn turn_group(q: &ForceLanes, rows: &mut [[f64; 6]; W]) {
    let c = load_columns(rows);
    let rot = v3(&q.rot);
    let f = sub([c[0], c[1], c[2]], cross(rot, [c[0], c[1], c[2]]));
    let m = sub([c[3], c[4], c[5]], cross(rot, [c[3], c[4], c[5]]));
    let out = [
        sum(f[0], load(&q.gravity[0])),
        sum(sum(f[1], load(&q.gravity[1])), load(&q.centripetal[0])),
        sum(sum(f[2], load(&q.gravity[2])), load(&q.centripetal[1])),
        m[0],
        m[1],
        dif(m[2], load(&q.yaw_acceleration)),
    ];
    store_columns(out, rows);
}

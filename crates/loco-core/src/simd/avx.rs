//! Four lanes in one AVX register: [`Avx`], the [`Four`] lane set of the kernels' AVX copies,
//! and its number type [`F64x4`]. The only module of the crate that names processor
//! instructions, and the only `unsafe` of the SIMD kernels.
//!
//! Soundness rests on one invariant: an [`F64x4`] exists only on a processor with AVX. It is
//! made only by [`Avx`]'s methods (or from other `F64x4`s), and an [`Avx`] only by
//! [`Avx::detect`], after the processor was found to have AVX. Every operation is one IEEE
//! operation per lane (`vaddpd`, `vsubpd`, `vmulpd`; negation flips the sign bit), the scalar
//! code's; no fused multiply-add.
//!
//! The methods are `#[inline(always)]`: compiled into a kernel's AVX copy (which enables AVX),
//! the instructions are inlined there.

use super::{Four, Real};
use std::arch::x86_64::{
    __m256d, _mm256_add_pd, _mm256_castpd128_pd256, _mm256_castpd256_pd128, _mm256_extractf128_pd,
    _mm256_insertf128_pd, _mm256_loadu_pd, _mm256_mul_pd, _mm256_permute2f128_pd, _mm256_set1_pd,
    _mm256_storeu_pd, _mm256_sub_pd, _mm256_unpackhi_pd, _mm256_unpacklo_pd, _mm256_xor_pd,
    _mm_loadu_pd, _mm_storeu_pd,
};
use std::ops::{Add, Mul, Neg, Sub};

/// Proof that the processor has AVX: the lane set whose numbers are AVX registers.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Avx(());

impl Avx {
    /// The lane set, where the processor has AVX (detected once, then a cached flag).
    #[inline(always)]
    pub(crate) fn detect() -> Option<Self> {
        std::arch::is_x86_feature_detected!("avx").then_some(Self(()))
    }
}

/// Four numbers in one AVX register; exists only where AVX was detected.
#[derive(Debug, Clone, Copy)]
pub(crate) struct F64x4(__m256d);

macro_rules! avx_op {
    ($trait:ident, $method:ident, $intrinsic:ident) => {
        impl $trait for F64x4 {
            type Output = Self;
            #[inline(always)]
            fn $method(self, rhs: Self) -> Self {
                // SAFETY: `self` exists, so the processor has AVX (the module's invariant).
                Self(unsafe { $intrinsic(self.0, rhs.0) })
            }
        }
    };
}
avx_op!(Add, add, _mm256_add_pd);
avx_op!(Sub, sub, _mm256_sub_pd);
avx_op!(Mul, mul, _mm256_mul_pd);

impl Neg for F64x4 {
    type Output = Self;
    /// −x lane by lane: the sign bit flipped (exact, as the scalar `-x`).
    #[inline(always)]
    fn neg(self) -> Self {
        // SAFETY: `self` exists, so the processor has AVX (the module's invariant).
        Self(unsafe { _mm256_xor_pd(self.0, _mm256_set1_pd(-0.0)) })
    }
}

impl Real for F64x4 {}

impl Four for Avx {
    type V = F64x4;

    #[inline(always)]
    fn splat(self, v: f64) -> F64x4 {
        // SAFETY: `self` exists, so the processor has AVX.
        F64x4(unsafe { _mm256_set1_pd(v) })
    }

    #[inline(always)]
    fn load(self, a: &[f64; 4]) -> F64x4 {
        // SAFETY: the processor has AVX (`self` exists); the load reads the four numbers `a`
        // refers to, without alignment.
        F64x4(unsafe { _mm256_loadu_pd(a.as_ptr()) })
    }

    #[inline(always)]
    fn store(self, x: F64x4, out: &mut [f64; 4]) {
        // SAFETY: the processor has AVX (`self` exists); the store writes the four numbers
        // `out` refers to exclusively, without alignment.
        unsafe { _mm256_storeu_pd(out.as_mut_ptr(), x.0) }
    }

    /// Each row loaded whole (four and two numbers) and transposed in registers: fewer
    /// instructions than twenty-four numbers gathered one by one, the same numbers.
    #[inline(always)]
    fn rows_to_lanes(self, rows: [&[f64; 6]; 4]) -> [F64x4; 6] {
        // SAFETY: the processor has AVX (`self` exists); each load reads four numbers from
        // `row[0..4]` or two from `row[4..6]` of a row the caller's reference holds.
        unsafe {
            // Written out, not `array::map` or closures: those were left as calls in the AVX copy.
            let r = [
                _mm256_loadu_pd(rows[0].as_ptr()),
                _mm256_loadu_pd(rows[1].as_ptr()),
                _mm256_loadu_pd(rows[2].as_ptr()),
                _mm256_loadu_pd(rows[3].as_ptr()),
            ];
            let tail = [
                _mm_loadu_pd(rows[0][4..].as_ptr()),
                _mm_loadu_pd(rows[1][4..].as_ptr()),
                _mm_loadu_pd(rows[2][4..].as_ptr()),
                _mm_loadu_pd(rows[3][4..].as_ptr()),
            ];
            let (t0, t1) = (
                _mm256_unpacklo_pd(r[0], r[1]),
                _mm256_unpackhi_pd(r[0], r[1]),
            );
            let (t2, t3) = (
                _mm256_unpacklo_pd(r[2], r[3]),
                _mm256_unpackhi_pd(r[2], r[3]),
            );
            // Components 4 and 5: rows 0 and 2, rows 1 and 3 side by side, then interleaved.
            let u02 = _mm256_insertf128_pd::<1>(_mm256_castpd128_pd256(tail[0]), tail[2]);
            let u13 = _mm256_insertf128_pd::<1>(_mm256_castpd128_pd256(tail[1]), tail[3]);
            [
                F64x4(_mm256_permute2f128_pd::<0x20>(t0, t2)),
                F64x4(_mm256_permute2f128_pd::<0x20>(t1, t3)),
                F64x4(_mm256_permute2f128_pd::<0x31>(t0, t2)),
                F64x4(_mm256_permute2f128_pd::<0x31>(t1, t3)),
                F64x4(_mm256_unpacklo_pd(u02, u13)),
                F64x4(_mm256_unpackhi_pd(u02, u13)),
            ]
        }
    }

    #[inline(always)]
    fn lanes_to_rows(self, c: [F64x4; 6], rows: &mut [[f64; 6]; 4]) {
        let c = [c[0].0, c[1].0, c[2].0, c[3].0, c[4].0, c[5].0];
        // SAFETY: the processor has AVX (`self` exists); each row's stores write four numbers
        // into `row[0..4]` and two into `row[4..6]` of a row `rows` holds exclusively.
        unsafe {
            let u0 = _mm256_unpacklo_pd(c[0], c[1]);
            let u1 = _mm256_unpackhi_pd(c[0], c[1]);
            let u2 = _mm256_unpacklo_pd(c[2], c[3]);
            let u3 = _mm256_unpackhi_pd(c[2], c[3]);
            let v0 = _mm256_unpacklo_pd(c[4], c[5]);
            let v1 = _mm256_unpackhi_pd(c[4], c[5]);
            let lo = [
                _mm256_permute2f128_pd::<0x20>(u0, u2),
                _mm256_permute2f128_pd::<0x20>(u1, u3),
                _mm256_permute2f128_pd::<0x31>(u0, u2),
                _mm256_permute2f128_pd::<0x31>(u1, u3),
            ];
            let hi = [
                _mm256_castpd256_pd128(v0),
                _mm256_castpd256_pd128(v1),
                _mm256_extractf128_pd::<1>(v0),
                _mm256_extractf128_pd::<1>(v1),
            ];
            for ((row, lo), hi) in rows.iter_mut().zip(lo).zip(hi) {
                _mm256_storeu_pd(row.as_mut_ptr(), lo);
                _mm_storeu_pd(row[4..].as_mut_ptr(), hi);
            }
        }
    }
}

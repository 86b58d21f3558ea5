//! [`Four`]: how a kernel of four lanes holds its numbers, so that one generic source runs as
//! plain arrays ([`Plain`], any processor, the baseline copy) and in AVX registers
//! (`simd::avx::Avx`, the AVX copy).
//!
//! Why two lane sets and not plain arrays alone: in the bushings' kernel the compiler packed
//! the 3-vectors' components of plain arrays instead of the lanes, half of it two wide or
//! scalar, and the kernel took 1.75 times as long (perf, 12 % of a straight run against 7 %);
//! with the AVX operations named the lanes stay in their registers. Both sets do one IEEE
//! operation per lane per operation, the same ones, so the kernel's bits do not depend on the
//! set.

use super::{Lanes, Real};

/// A set of four lanes: constructors, stores and the transposes between rows and lanes.
pub(crate) trait Four: Copy {
    /// Four numbers, one per lane.
    type V: Real;
    /// `v` in every lane.
    fn splat(self, v: f64) -> Self::V;
    /// Lane `l` from `a[l]`.
    fn load(self, a: &[f64; 4]) -> Self::V;
    /// Lane `l` into `out[l]`.
    fn store(self, x: Self::V, out: &mut [f64; 4]);
    /// Four 6-vectors as six lanes: `[k]` holds component `k` of the four rows.
    fn rows_to_lanes(self, rows: [&[f64; 6]; 4]) -> [Self::V; 6];
    /// The inverse of [`Four::rows_to_lanes`].
    fn lanes_to_rows(self, c: [Self::V; 6], rows: &mut [[f64; 6]; 4]);
}

/// Four lanes as plain arrays ([`Lanes<4>`]), for any processor.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Plain;

impl Four for Plain {
    type V = Lanes<4>;
    #[inline(always)]
    fn splat(self, v: f64) -> Lanes<4> {
        Lanes::splat(v)
    }
    #[inline(always)]
    fn load(self, a: &[f64; 4]) -> Lanes<4> {
        Lanes(*a)
    }
    #[inline(always)]
    fn store(self, x: Lanes<4>, out: &mut [f64; 4]) {
        *out = x.0;
    }
    #[inline(always)]
    fn rows_to_lanes(self, rows: [&[f64; 6]; 4]) -> [Lanes<4>; 6] {
        let mut out = [Lanes([0.0; 4]); 6];
        for (k, o) in out.iter_mut().enumerate() {
            for (l, row) in rows.iter().enumerate() {
                o.0[l] = row[k];
            }
        }
        out
    }
    #[inline(always)]
    fn lanes_to_rows(self, c: [Lanes<4>; 6], rows: &mut [[f64; 6]; 4]) {
        for (k, c) in c.iter().enumerate() {
            for (l, row) in rows.iter_mut().enumerate() {
                row[k] = c.0[l];
            }
        }
    }
}

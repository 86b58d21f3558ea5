//! The core's one SIMD mechanism: kernels written once in plain safe Rust over fixed-size lane
//! arrays ([`Lanes`]), compiled twice by [`multiversion`] (for the x86_64 baseline, SSE2, and
//! for AVX) and dispatched at run time to the copy the processor can run.
//!
//! How a kernel is written: its entry is a free function carrying
//! `#[multiversion(targets("x86_64+avx"))]`; everything it calls in the hot loop is
//! `#[inline(always)]`, so it is compiled into each copy with that copy's target features and the
//! compiler packs the lanes' operations into 256-bit instructions in the AVX copy. The scalar
//! path is the same source, compiled without AVX: there is no second copy of a kernel to keep
//! in step with the first.
//!
//! Why the results are the same bits on every processor: each lane does the scalar code's IEEE
//! operations in the scalar code's order. AVX adds no fused multiply-add (that is FMA, a feature
//! the dispatch never enables), and Rust never contracts a separate multiply and add into one,
//! so packing lanes changes which instruction does an operation, never its rounding. Sums taken
//! across lanes are written out in a fixed order, never left to a reduction.
//!
//! Where the dispatch is: [`multiversion`] selects the copy once (one atomic flag afterwards).
//! On other architectures only the baseline copy exists.
//!
//! Where plain arrays are not enough: a kernel whose lanes the compiler does not keep in
//! registers (the bushings', the dampers' and the frames' 3-vector algebra) is written once over
//! a lane set [`Four`]: in its baseline copy [`Plain`] (the arrays of [`Lanes`]), in its AVX copy
//! [`Avx`] (AVX registers). `avx.rs` is the only module that names processor instructions, and
//! its `unsafe` blocks the only ones of the kernels, each with the invariant that makes it sound.

#[cfg(target_arch = "x86_64")]
mod avx;
mod four;
mod lanes;
pub(crate) mod vec3;

#[cfg(target_arch = "x86_64")]
pub(crate) use avx::Avx;
pub(crate) use four::{Four, Plain};
pub(crate) use lanes::{Lanes, Real};
pub(crate) use multiversion::multiversion;
pub(crate) use multiversion::target::target_cfg_f;

#[cfg(test)]
mod tests;

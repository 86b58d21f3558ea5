//! The lane sets against scalar `f64` arithmetic, bit for bit, on the values where rounding
//! and signs are easiest to lose: signed zeros, subnormals, infinities, NaN, huge and tiny.

use super::vec3::{cross, dot, neg};
use super::{Four, Lanes, Plain};

const SPECIAL: [f64; 12] = [
    0.0,
    -0.0,
    5e-324,
    -2.2e-308,
    1.0,
    -3.5,
    1e300,
    -1e-300,
    f64::INFINITY,
    f64::NEG_INFINITY,
    f64::NAN,
    0.1,
];

/// Every lane set's operations on four values at a time, against the scalar ones.
fn check<S: Four>(set: S, name: &str)
where
    S::V: Copy,
{
    let n = SPECIAL.len();
    for i in 0..n {
        for j in 0..n {
            let a: [f64; 4] = std::array::from_fn(|l| SPECIAL[(i + l) % n]);
            let b: [f64; 4] = std::array::from_fn(|l| SPECIAL[(j + 3 * l) % n]);
            // Kept from constant folding, whose NaNs can differ in sign from the processor's.
            let (a, b) = std::hint::black_box((a, b));
            let (x, y) = (set.load(&a), set.load(&b));
            let scalar: [[f64; 4]; 4] = [
                std::array::from_fn(|l| a[l] + b[l]),
                std::array::from_fn(|l| a[l] - b[l]),
                std::array::from_fn(|l| a[l] * b[l]),
                std::array::from_fn(|l| -a[l]),
            ];
            for (k, v) in [x + y, x - y, x * y, -x].into_iter().enumerate() {
                let mut out = [0.0; 4];
                set.store(v, &mut out);
                assert_eq!(
                    out.map(f64::to_bits),
                    scalar[k].map(f64::to_bits),
                    "{name}: operation {k} of {a:?} and {b:?}"
                );
            }
            let mut out = [0.0; 4];
            set.store(set.splat(a[0]), &mut out);
            assert_eq!(out.map(f64::to_bits), [a[0].to_bits(); 4], "{name}: splat");
        }
    }
}

#[test]
fn plain_lanes_do_the_scalar_operations() {
    check(Plain, "plain");
}

#[cfg(target_arch = "x86_64")]
#[test]
fn avx_lanes_do_the_scalar_operations() {
    if let Some(avx) = super::Avx::detect() {
        check(avx, "avx");
    }
}

/// The transposes between rows and lanes, and the 3-vector algebra over lanes, give each
/// element's scalar result (the AVX set's transposes the plain set's).
#[test]
fn transposes_and_vectors_match_one_element_at_a_time() {
    let rows: [[f64; 6]; 4] =
        std::array::from_fn(|l| std::array::from_fn(|k| SPECIAL[(5 * l + k) % 12]));
    // Kept from constant folding, whose NaNs can differ in sign from the processor's.
    let rows = std::hint::black_box(rows);
    let c = Plain.rows_to_lanes([&rows[0], &rows[1], &rows[2], &rows[3]]);
    for (l, row) in rows.iter().enumerate() {
        for k in 0..6 {
            assert_eq!(c[k].0[l].to_bits(), row[k].to_bits());
        }
        let (a, b) = ([row[0], row[1], row[2]], [row[3], row[4], row[5]]);
        let lanes = cross([c[0], c[1], c[2]], [c[3], c[4], c[5]]);
        let one = cross(a, b);
        for k in 0..3 {
            assert_eq!(lanes[k].0[l].to_bits(), one[k].to_bits());
        }
        let d: Lanes<4> = dot([c[0], c[1], c[2]], [c[3], c[4], c[5]]);
        assert_eq!(d.0[l].to_bits(), dot(a, b).to_bits());
        assert_eq!(neg([c[0], c[1], c[2]])[1].0[l].to_bits(), (-a[1]).to_bits());
    }
    let mut back = [[0.0; 6]; 4];
    Plain.lanes_to_rows(c, &mut back);
    assert_eq!(
        back.map(|r| r.map(f64::to_bits)),
        rows.map(|r| r.map(f64::to_bits))
    );
    #[cfg(target_arch = "x86_64")]
    if let Some(avx) = super::Avx::detect() {
        let v = avx.rows_to_lanes([&rows[0], &rows[1], &rows[2], &rows[3]]);
        for (k, (v, c)) in v.iter().zip(&c).enumerate() {
            let mut out = [0.0; 4];
            avx.store(*v, &mut out);
            assert_eq!(
                out.map(f64::to_bits),
                c.0.map(f64::to_bits),
                "component {k}"
            );
        }
        let mut back = [[0.0; 6]; 4];
        avx.lanes_to_rows(v, &mut back);
        assert_eq!(
            back.map(|r| r.map(f64::to_bits)),
            rows.map(|r| r.map(f64::to_bits))
        );
    }
}

use super::*;

/// One strip at a time, the plain scalar loop (FASTSIM's integration before the lanes).
fn one_strip(a_j: f64, slope_x: f64, bound_j: f64, e: &[Element], c: (f64, f64, f64)) -> [f64; 3] {
    let (eta_l2, phi, inv_l3) = c;
    let (mut px, mut py, mut sx, mut sy, mut sxpy) = (0.0, 0.0, 0.0, 0.0, 0.0);
    let mut x_prev = a_j;
    for &Element {
        u: u_k,
        shape: shape_k,
        ..
    } in e
    {
        let x = u_k * a_j;
        let h = x_prev - x;
        let x_mid = 0.5 * (x_prev + x);
        px -= h * slope_x;
        py -= h * (eta_l2 + phi * x_mid * inv_l3);
        let norm = (px * px + py * py).sqrt().max(f64::MIN_POSITIVE);
        let scale = (bound_j * shape_k / norm).min(1.0);
        px *= scale;
        py *= scale;
        sx += px;
        sy += py;
        sxpy += x * py;
        x_prev = x;
    }
    [sx, sy, sxpy]
}

#[test]
fn lanes_give_the_bits_of_one_strip_at_a_time() {
    // A small deterministic generator: strips from adhesion to full slip, with spin, and
    // empty padding strips (a_j = 0, bound 0).
    let mut state = 0x2545_f491_4f6c_dd1d_u64;
    let mut next = move || {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        (state >> 11) as f64 / (1u64 << 53) as f64
    };
    let elements: Vec<Element> = (0..10)
        .map(|k| {
            let u = 1.0 - (2 * k + 1) as f64 / 10.0;
            Element::new(u, 1.0 - u * u)
        })
        .collect();
    // Bounds where the skip test never passes or passes on zero traction only: tiny, huge,
    // negative (a negative μ), not a number, and zero.
    let special = [
        1e-150,
        1e-300,
        1e160,
        -3e8,
        f64::NAN,
        0.0,
        5e-324,
        f64::INFINITY,
    ];
    for case in 0..400 {
        let c = (
            (next() - 0.5) * 1e9,
            (next() - 0.5) * 1e12 * f64::from(case % 3 != 0),
            1e10 * (1.0 + next()),
        );
        let inputs = StripInputs {
            a_j: std::array::from_fn(|l| if l == 5 { 0.0 } else { 1e-2 * next() }),
            slope_x: std::array::from_fn(|_| (next() - 0.5) * 1e9),
            bound: std::array::from_fn(|l| match l {
                5 => 0.0,
                // Every lane of the AVX registers and of the 128-bit one in turn.
                _ if case % 4 == 1 && l == (case / 4) % 10 => special[(case / 40) % special.len()],
                _ => 1e9 * next().powi(4),
            }),
        };
        // Both lane layouts (the baseline copy's and the AVX copy's) and the dispatched call.
        let paths = [
            ("two lanes", integrate::<2, PAIRS, 0>(&inputs, &elements, c)),
            ("four lanes", integrate::<4, 2, 2>(&inputs, &elements, c)),
            (
                "dispatched",
                integrate_strips(&inputs, &elements, c.0, c.1, c.2),
            ),
        ];
        for (path, sums) in paths {
            for l in 0..2 * PAIRS {
                let want = one_strip(
                    inputs.a_j[l],
                    inputs.slope_x[l],
                    inputs.bound[l],
                    &elements,
                    c,
                );
                let got = [sums.sx[l], sums.sy[l], sums.sxpy[l]];
                assert_eq!(
                    got.map(f64::to_bits),
                    want.map(f64::to_bits),
                    "{path} case {case} lane {l}"
                );
            }
        }
    }
}

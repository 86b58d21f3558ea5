//! FaStrip's cost per contact against FASTSIM's, measured in alternating blocks so that both see
//! the same machine load (criterion times one after the other, and on a shared machine the load
//! changes between them). The target: FaStrip at most 1.5× FASTSIM on the default grid.
//!
//! `cargo run --release -p loco-dev --bin creep_cost [-- rounds]` prints, per case and grid,
//! the median time per call of each model over the rounds and the median of the per-round
//! ratios. Cases: CONTACT's `fastsim` example (a = 8 mm, b = 4 mm, N = 82 kN, μ = 0.3, η =
//! −6.25e-4, φ = 0.625 1/m, plus ξ = 1e-4 as in the `fastsim` bench; |φ'| ≈ 1.007, so FaStrip
//! takes its bound check and FASTSIM fallback) and the same with half the spin (|φ'| < 1).

use loco_core::contact::fastrip::{Fastrip, FastripParams};
use loco_core::contact::fastsim::{Fastsim, FastsimParams};
use loco_core::contact::kalker::Creepages;
use std::hint::black_box;
use std::time::Instant;

/// Calls per timed block.
const BLOCK: usize = 20_000;

fn time_block(mut call: impl FnMut() -> f64) -> f64 {
    let start = Instant::now();
    let mut sink = 0.0;
    for _ in 0..BLOCK {
        sink += call();
    }
    black_box(sink);
    start.elapsed().as_secs_f64() / BLOCK as f64 * 1e9
}

fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

fn main() {
    let rounds: usize = std::env::args()
        .nth(1)
        .map(|a| a.parse().expect("rounds: a whole number"))
        .unwrap_or(41);
    println!("case grid fastsim_ns fastrip_ns ratio (medians over {rounds} rounds)");
    for (case, spin) in [("contact_spin", 0.625), ("half_spin", 0.3125)] {
        let creep = Creepages {
            longitudinal: 1e-4,
            lateral: -6.25e-4,
            spin,
        };
        for n in [10, 20] {
            let fastsim = Fastsim::new(FastsimParams {
                nx: n,
                ny: n,
                ..FastsimParams::default()
            })
            .expect("valid grid");
            let fastrip = Fastrip::new(FastripParams {
                nx: n,
                ny: n,
                ..FastripParams::default()
            })
            .expect("valid grid");
            let args = || {
                (
                    black_box(8e-3),
                    black_box(4e-3),
                    black_box(82e3),
                    black_box(0.3),
                )
            };
            let (mut t_sim, mut t_rip, mut ratios) = (vec![], vec![], vec![]);
            for _ in 0..rounds {
                let s = time_block(|| {
                    let (a, b, n, mu) = args();
                    fastsim.creep_forces(a, b, n, mu, black_box(&creep)).fy
                });
                let r = time_block(|| {
                    let (a, b, n, mu) = args();
                    fastrip.creep_forces(a, b, n, mu, black_box(&creep)).fy
                });
                t_sim.push(s);
                t_rip.push(r);
                ratios.push(r / s);
            }
            println!(
                "{case} {n}x{n} {:.1} {:.1} {:.2}",
                median(t_sim),
                median(t_rip),
                median(ratios)
            );
        }
    }
}

//! One 500 m run at 200 km/h (`DISTANCE` m if set) with each integration scheme and step, the
//! run metrics against RK4 at 0.25 ms and the wall time (release build, one core):
//! `cargo run --release -p loco-dev --bin integrator_compare -- [S_high|S_low]
//! [parameter=value ...]`; `CURVE=study` or `CURVE=reference` runs it on that curve.

use loco_core::track::{CurveDirection, DesignSection};
use loco_core::vehicle::output::run::{Recorded, RunSettings};
use loco_core::vehicle::scenarios::scenario::Scenario;
use loco_core::vehicle::time::integrator::Integrator;

use loco_dev::study_case;

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let name = args.get(1).map_or("S_high", String::as_str);
    let parameters = study_case::parameters(args.iter().skip(2));
    let distance: f64 = std::env::var("DISTANCE").map_or(500.0, |d| d.parse().unwrap());
    let mut base = Scenario::study(name, 200.0 / 3.6, distance, 1).unwrap();
    match std::env::var("CURVE").as_deref() {
        Ok("study") => base.curve = DesignSection::study_curve(CurveDirection::Left),
        Ok("reference") => base.curve = DesignSection::reference_curve(0.1, CurveDirection::Left),
        _ => {}
    }
    let prepared = study_case::prepared(parameters, &base);
    let cases = [
        (Integrator::Rk4, 0.25e-3),
        (Integrator::Rk4, 1e-3),
        (Integrator::ExponentialRk4, 1e-3),
        (Integrator::ExponentialRk4, 2e-3),
    ];
    let mut reference = None;
    for (integrator, step) in cases {
        let scenario = Scenario {
            run: RunSettings {
                step,
                integrator,
                ..base.run
            },
            ..base.clone()
        };
        let t = std::time::Instant::now();
        let result = prepared.run(&scenario, Recorded::Metrics);
        let wall = t.elapsed().as_secs_f64();
        match result {
            Ok(r) => {
                let m = vec![
                    ("wy_max".to_string(), r.metrics.wy_max),
                    ("ayb_peak_lp".to_string(), r.metrics.ayb_peak_lp),
                    ("ayc_psd_peak".to_string(), r.metrics.ayc_psd_peak),
                ];
                let rel: Vec<String> = match &reference {
                    None => {
                        reference = Some(m.clone());
                        vec![]
                    }
                    Some(refm) => m
                        .iter()
                        .zip(refm.iter())
                        .map(|((k, v), (_, r0))| format!("{k} {:+.4}%", 100.0 * (v / r0 - 1.0)))
                        .collect(),
                };
                println!(
                    "{name} {:7} {:.2e}s steps {} rhs {} wall {:.3}s {:?} {}",
                    integrator.name(),
                    step,
                    r.statistics.steps,
                    r.statistics.rhs_evaluations,
                    wall,
                    m,
                    rel.join(" ")
                );
            }
            Err(e) => println!("{name} {} {step}: {e}", integrator.name()),
        }
    }
}

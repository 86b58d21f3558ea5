//! FaStrip's cost per contact against FASTSIM's on the contacts of a vehicle run: the study case
//! (`loco_dev::study_case`, 500 m at 200 km/h) is simulated once with FASTSIM, every
//! creep-force call's inputs are recorded (feature `record-contacts`), and the recorded calls are
//! replayed through both models on the run's grid (the default 10 × 10) and material in alternating rounds, so that both
//! see the same machine load. Prints the median time per call of each over the rounds and the
//! median of the per-round ratios (the target: FaStrip at most 1.5× FASTSIM).
//!
//! `cargo run --release -p loco-dev --features record-contacts --bin creep_replay --
//! [S_high|S_low] [rounds]`

use loco_core::contact::fastrip::{Fastrip, FastripParams};
use loco_core::contact::fastsim::{Fastsim, FastsimParams};
use loco_core::contact::kalker::CreepForces;
use loco_core::vehicle::output::run::Recorded;
use loco_core::vehicle::params::parameters::ParameterSet;
use loco_core::vehicle::rail_contact::contact_recording::{self, ContactCall};
use std::hint::black_box;
use std::time::Instant;

use loco_dev::study_case;

/// Nanoseconds per call of `model` over `calls`.
fn time_calls(calls: &[ContactCall], model: impl Fn(&ContactCall) -> CreepForces) -> f64 {
    let start = Instant::now();
    let mut sink = 0.0;
    for c in calls {
        let f = model(c);
        sink += f.fx + f.fy + f.mz;
    }
    black_box(sink);
    start.elapsed().as_secs_f64() / calls.len() as f64 * 1e9
}

fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let name = args.get(1).map_or("S_high", String::as_str);
    let rounds: usize = args.get(2).map_or(15, |r| r.parse().expect("rounds"));
    let scenario = study_case::scenario("fastsim", name, None);
    let prepared = study_case::prepared(ParameterSet::default_vehicle(), &scenario);
    let _ = contact_recording::take();
    prepared
        .run(&scenario, Recorded::Metrics)
        .expect("the study case runs");
    let calls = contact_recording::take();
    // The run's material (G derived from E and ν, as the vehicle's contact does) and grid.
    let parameters = ParameterSet::default_vehicle();
    let poisson_ratio = parameters
        .get("track.poisson_ratio")
        .expect("a vehicle key");
    let young_modulus = parameters
        .get("track.young_modulus")
        .expect("a vehicle key");
    let material = FastsimParams {
        poisson_ratio,
        shear_modulus: young_modulus / (2.0 * (1.0 + poisson_ratio)),
        ..scenario.fastsim
    };
    let fastsim = Fastsim::new(material).expect("the run's grid");
    let fastrip = Fastrip::new(FastripParams::from(material)).expect("the run's grid");
    let (mut t_sim, mut t_rip, mut ratio) = (vec![], vec![], vec![]);
    for _ in 0..rounds {
        let s = time_calls(&calls, |c| {
            fastsim.creep_forces(c.a, c.b, c.normal_force, c.mu, &c.creepages)
        });
        let r = time_calls(&calls, |c| {
            fastrip.creep_forces(c.a, c.b, c.normal_force, c.mu, &c.creepages)
        });
        t_sim.push(s);
        t_rip.push(r);
        ratio.push(r / s);
    }
    println!(
        "{name}: {} contact calls; FASTSIM {:.1} ns, FaStrip {:.1} ns per call, ratio {:.3} \
         (medians over {rounds} rounds)",
        calls.len(),
        median(t_sim),
        median(t_rip),
        median(ratio)
    );
}

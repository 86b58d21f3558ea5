//! CPU time of one simulation without its set-up: the contact table and the track are built
//! once, then the same 500 m run at 200 km/h is simulated `repeats` times in this process and
//! each run's thread CPU time is printed with the minimum and the median, and the number of
//! evaluations of the equations of motion one run takes. What a batch sample
//! costs (its metrics' channels only, `Recorded::Metrics`), without the table build that a
//! whole `run_fingerprint` or `loco-batch` process also times.
//!
//! `cargo run --release -p loco-dev --bin sim_time -- [fastsim|fastrip|table]
//! [S_high|S_low] [straight|curve|study_curve] [repeats] [metrics|every]`
//!
//! `metrics` (the default) records the metrics' channels only, as a batch sample does; `every`
//! records every channel at the output rate, as `simulate` does for a time history.
//!
//! To compare two versions of the code on a shared machine, build this example in both and run
//! them alternately several times (the minimum is the least disturbed run); the machine's speed
//! drifts by ±10 % within an hour, so only such pairs resolve a few per cent.

use loco_core::vehicle::output::run::Recorded;
use loco_core::vehicle::params::parameters::ParameterSet;

use loco_dev::study_case;

/// This thread's CPU time, s (the run is single-threaded, so wall time would add other
/// processes' share of the core).
fn thread_cpu_seconds() -> f64 {
    let mut t = libc::timespec {
        tv_sec: 0,
        tv_nsec: 0,
    };
    // SAFETY: `clock_gettime` writes one timespec into the valid, exclusively borrowed `t`.
    unsafe { libc::clock_gettime(libc::CLOCK_THREAD_CPUTIME_ID, &mut t) };
    t.tv_sec as f64 + t.tv_nsec as f64 * 1e-9
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let track_kind = args.get(3).map(String::as_str);
    if let Some(other) = track_kind.filter(|k| !["straight", "curve", "study_curve"].contains(k)) {
        panic!("unknown track `{other}`: straight, curve or study_curve");
    }
    let scenario = study_case::scenario(
        args.get(1).map_or("fastsim", String::as_str),
        args.get(2).map_or("S_high", String::as_str),
        track_kind,
    );
    let repeats: usize = args.get(4).map_or(9, |r| r.parse().expect("repeats"));
    let recorded = match args.get(5).map_or("metrics", String::as_str) {
        "metrics" => Recorded::Metrics,
        "every" => Recorded::Every,
        other => panic!("unknown recording `{other}`: metrics or every"),
    };
    let prepared = study_case::prepared(ParameterSet::default_vehicle(), &scenario);
    let mut times = Vec::with_capacity(repeats);
    let mut evaluations = 0;
    for _ in 0..repeats {
        let start = thread_cpu_seconds();
        let result = prepared.run(&scenario, recorded).unwrap();
        times.push(thread_cpu_seconds() - start);
        evaluations = result.statistics.rhs_evaluations;
        std::hint::black_box(result);
    }
    let ms: Vec<String> = times.iter().map(|t| format!("{:.1}", t * 1e3)).collect();
    times.sort_by(f64::total_cmp);
    println!(
        "runs (ms) {}; min {:.1} ms, median {:.1} ms; {evaluations} right-hand side evaluations",
        ms.join(" "),
        times[0] * 1e3,
        times[times.len() / 2] * 1e3
    );
}

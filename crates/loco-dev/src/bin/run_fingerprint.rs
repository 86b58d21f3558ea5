//! One 500 m run at 200 km/h (the `vehicle` bench's `run_500m_200kmh`), printing its metrics and a
//! fingerprint of every output sample's bits: the same fingerprint before and after a change means
//! the change kept the results bit for bit. Also the program callgrind counts instructions of.
//!
//! `cargo run --release -p loco-dev --bin run_fingerprint -- [fastsim|fastrip|table]
//! [S_high|S_low] [prepare|curve|study_curve]` (`prepare`: build contact and track only, to
//! subtract set-up cost; `curve`: the same run on the design of `experiments/curve_cost.py`, a 60 m
//! transition into R = 1200 m with 100 mm cant, about 290 mm of cant deficiency at 200 km/h, to
//! count what the curve terms cost against the straight run; `study_curve`: R = 3000 m with
//! 60 mm cant, about 97 mm of deficiency, a case of the curving study).
//!
//! `fingerprint` hashes the channels recorded before the curving channels were added (so the
//! number stays comparable across that change); `curving_fingerprint` hashes the curving
//! channels (`vehicle::output::wheel_channels`), which are outputs only and cannot change the solution;
//! `accelerometer_fingerprint` the channels of kind `accelerometer`, outputs only too.

use loco_core::vehicle::model::structure::VehicleStructure;
use loco_core::vehicle::output::channel_set::{ChannelKind, ChannelSet};
use loco_core::vehicle::output::run::Recorded;
use loco_core::vehicle::output::wheel_channels::{
    wheel_channel, wheelset_channel, WheelsetQuantity, CURVING_WHEEL_QUANTITIES,
};
use loco_core::vehicle::params::parameters::ParameterSet;
use std::collections::HashSet;

use loco_dev::study_case;

/// FNV-1a over the bits of every sample of `channels`.
fn fnv<'a>(channels: impl Iterator<Item = &'a Vec<f64>>) -> u64 {
    let mut hash: u64 = 0xcbf2_9ce4_8422_2325;
    for channel in channels {
        for v in channel {
            for byte in v.to_bits().to_le_bytes() {
                hash = (hash ^ byte as u64).wrapping_mul(0x0100_0000_01b3);
            }
        }
    }
    hash
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let track_kind = args.get(3).map(String::as_str);
    let name = args.get(2).map_or("S_high", String::as_str);
    let scenario = study_case::scenario(
        args.get(1).map_or("fastsim", String::as_str),
        name,
        track_kind,
    );
    let prepared = study_case::prepared(ParameterSet::default_vehicle(), &scenario);
    if args.get(3).is_some_and(|a| a == "prepare") {
        return;
    }
    let result = prepared.run(&scenario, Recorded::Every).unwrap();
    let mut curving: HashSet<String> = (0..4)
        .map(|w| wheelset_channel(w, WheelsetQuantity::GuidingForce))
        .collect();
    for w in 0..4 {
        for side in 0..2 {
            for q in CURVING_WHEEL_QUANTITIES {
                curving.insert(wheel_channel(w, side, q));
            }
        }
    }
    let structure = VehicleStructure::new(ParameterSet::default_vehicle()).unwrap();
    let accelerometers: HashSet<String> = ChannelSet::new(&structure)
        .unwrap()
        .names_of_kind(ChannelKind::Accelerometer)
        .into_iter()
        .collect();
    let out = &result.output;
    let is_curving = |i: &usize| curving.contains(&out.names[*i]);
    let is_accelerometer = |i: &usize| accelerometers.contains(&out.names[*i]);
    let all = 0..out.channels.len();
    let hash = fnv(all
        .clone()
        .filter(|i| !is_curving(i) && !is_accelerometer(i))
        .map(|i| &out.channels[i]));
    let curving_hash = fnv(all.clone().filter(is_curving).map(|i| &out.channels[i]));
    let accelerometer_hash = fnv(all.filter(is_accelerometer).map(|i| &out.channels[i]));
    let m = &result.metrics;
    println!("creep {} scenario {name}", scenario.creep.name());
    println!("wy_max {:.17e}", m.wy_max);
    println!("ayb_peak_lp {:.17e}", m.ayb_peak_lp);
    println!("ayc_psd_peak {:.17e}", m.ayc_psd_peak);
    println!("rhs_evaluations {}", result.statistics.rhs_evaluations);
    println!("fingerprint {hash:016x}");
    println!("curving_fingerprint {curving_hash:016x}");
    println!("accelerometer_fingerprint {accelerometer_hash:016x}");
}

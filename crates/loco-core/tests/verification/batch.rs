//! The batch engine: the same numbers as single runs, bit-identical for any thread count, failed
//! samples flagged without stopping the batch, input errors naming the row and column.

use crate::record::Record;
use loco_core::batch::{run_batch, BatchMonitor, BatchSpec, SampleStatus};
use loco_core::vehicle::params::parameters::ParameterSet;
use loco_core::vehicle::runs::simulate::simulate;
use loco_core::vehicle::scenarios::scenario::Scenario;
use loco_core::LocoError;
use std::sync::atomic::Ordering;

/// 5.3 s of running at 200 km/h: just over one 5 s Sperling segment, so every metric is defined.
const DISTANCE: f64 = 295.0;
const SPEED: f64 = 200.0 / 3.6;

fn spec(names: &[&str], values: Vec<f64>) -> BatchSpec {
    BatchSpec {
        base: ParameterSet::default_vehicle(),
        scenario: Scenario::study("S_high", SPEED, DISTANCE, 7).unwrap(),
        names: names.iter().map(|s| s.to_string()).collect(),
        values,
        per_sample_track: false,
        track_streams: None,
        histories: vec![1],
    }
}

fn bits(v: &[f64]) -> Vec<u64> {
    v.iter().map(|x| x.to_bits()).collect()
}

#[test]
fn bit_identical_on_one_and_two_threads_and_equal_to_single_runs() {
    // Two samples of the study box and one at another speed.
    let s = spec(
        &["C_sx", "K_py", "speed"],
        vec![8e5, 3.5e6, SPEED, 2e5, 8e6, SPEED, 1.2e6, 2e6, 160.0 / 3.6],
    );
    let one = run_batch(&s, 1, &BatchMonitor::default()).unwrap();
    let monitor = BatchMonitor::default();
    let two = run_batch(&s, 2, &monitor).unwrap();
    assert_eq!(monitor.done.load(Ordering::Relaxed), 3);
    assert_eq!(one.n_failed(), 0, "{:?}", one.messages);
    assert_eq!(bits(&one.metrics), bits(&two.metrics));
    assert!(one.metrics.iter().all(|v| v.is_finite()));

    // Row 1 is the same run as a single simulation with those parameters.
    let mut p = ParameterSet::default_vehicle();
    p.set("C_sx", 2e5).unwrap();
    p.set("K_py", 8e6).unwrap();
    let single = simulate(p, &s.scenario).unwrap();
    assert_eq!(bits(one.row(1)), bits(&single.metrics.values()));
    assert_eq!(one.histories.len(), 1);
    let (i, h) = &one.histories[0];
    assert_eq!(*i, 1);
    assert_eq!(bits(&h.time), bits(&single.output.time));
    assert_eq!(h.channels.len(), single.output.channels.len());

    // Row 0, whose histories are not returned, records only its metrics' channels
    // (`Recorded::Metrics`): the same metrics as a single run that records every channel.
    let mut p = ParameterSet::default_vehicle();
    p.set("C_sx", 8e5).unwrap();
    p.set("K_py", 3.5e6).unwrap();
    let single = simulate(p, &s.scenario).unwrap();
    assert_eq!(bits(one.row(0)), bits(&single.metrics.values()));
    let differing = |a: &[f64], b: &[f64]| {
        bits(a)
            .iter()
            .zip(bits(b))
            .filter(|(x, y)| **x != *y)
            .count()
    };
    Record::new("batch_bit_identity", file!())
        .count("samples", 3)
        .count("metric_values", one.metrics.len())
        .within(
            "differing_one_vs_two_threads",
            differing(&one.metrics, &two.metrics) as f64,
            "",
            1,
            "=",
            0.0,
        )
        .within(
            "differing_batch_vs_single_run",
            differing(one.row(0), &single.metrics.values()) as f64,
            "",
            1,
            "=",
            0.0,
        )
        .check();
}

#[test]
fn per_sample_tracks_differ_and_stay_deterministic() {
    let mut s = spec(&["C_sx"], vec![8e5, 8e5]);
    s.per_sample_track = true;
    s.histories.clear();
    let a = run_batch(&s, 2, &BatchMonitor::default()).unwrap();
    let b = run_batch(&s, 1, &BatchMonitor::default()).unwrap();
    assert_eq!(bits(&a.metrics), bits(&b.metrics));
    // Same parameters, different tracks (streams 0 and 1): different responses.
    assert_ne!(a.row(0)[1], a.row(1)[1]);
}

#[test]
fn given_track_streams_draw_the_whole_batchs_tracks() {
    // A chunk of a campaign (samples 1 and 0 of the design, in that order) gets the tracks the
    // whole batch gives those samples.
    let mut whole = spec(&["C_sx"], vec![8e5, 8e5]);
    whole.per_sample_track = true;
    whole.histories.clear();
    let a = run_batch(&whole, 2, &BatchMonitor::default()).unwrap();
    let chunk = BatchSpec {
        track_streams: Some(vec![1, 0]),
        ..whole.clone()
    };
    let b = run_batch(&chunk, 2, &BatchMonitor::default()).unwrap();
    assert_eq!(bits(b.row(0)), bits(a.row(1)));
    assert_eq!(bits(b.row(1)), bits(a.row(0)));
    let wrong = BatchSpec {
        track_streams: Some(vec![0]),
        ..whole
    };
    let e = run_batch(&wrong, 1, &BatchMonitor::default()).unwrap_err();
    assert!(e.to_string().contains("track_streams"), "{e}");
}

#[test]
fn a_diverging_sample_is_flagged_and_the_rest_completes() {
    // A primary spring a million times stiffer than the real one puts an axle-box mode far
    // beyond RK4's stability limit at the 1 ms step: that sample diverges.
    // Far outside the physical range, so the research value has to be allowed explicitly.
    let mut s = spec(
        &["primary.axle_box_spring_vertical_stiffness"],
        vec![1.5e7, 1.5e13, 1.5e7],
    );
    s.base
        .allow_out_of_range("primary.axle_box_spring_vertical_stiffness")
        .unwrap();
    let out = run_batch(&s, 2, &BatchMonitor::default()).unwrap();
    assert_eq!(out.status[0], SampleStatus::Ok);
    // Refused at the equilibrium, before it blows up: the step is too long for that mode.
    assert_eq!(
        out.status[1],
        SampleStatus::InvalidParameter,
        "{}",
        out.messages[1]
    );
    assert_eq!(out.status[2], SampleStatus::Ok);
    assert!(out.row(1).iter().all(|v| v.is_nan()));
    assert!(out.messages[1].contains("`step`"));
    assert_eq!(out.n_failed(), 1);
    assert_eq!(
        out.summary(),
        vec![(SampleStatus::Ok, 2), (SampleStatus::InvalidParameter, 1)]
    );
    assert_eq!(bits(out.row(0)), bits(out.row(2)));
    Record::new("batch_failed_sample", file!())
        .count("samples", out.status.len())
        .label("failed_status", out.status[1].name())
        .count("failed_status_code", out.status[1].code() as usize)
        .count(
            "failed_nan_metrics",
            out.row(1).iter().filter(|v| v.is_nan()).count(),
        )
        .count(
            "completed",
            out.status
                .iter()
                .filter(|s| **s == SampleStatus::Ok)
                .count(),
        )
        .check();
}

#[test]
fn input_errors_name_row_and_column_before_running() {
    let e = run_batch(
        &spec(&["C_sx", "K_px"], vec![8e5, 1.5e7, 8e5, -1.0]),
        1,
        &BatchMonitor::default(),
    )
    .unwrap_err();
    let text = e.to_string();
    assert!(matches!(e, LocoError::OutOfRange { .. }), "{text}");
    assert!(
        text.contains("row 1") && text.contains("column 1") && text.contains("K_px"),
        "{text}"
    );
    // A fractional count is refused before running, naming the cell.
    let e = run_batch(
        &spec(&["secondary.lateral_dampers_per_bogie"], vec![2.0, 0.4]),
        1,
        &BatchMonitor::default(),
    )
    .unwrap_err();
    let text = e.to_string();
    assert!(matches!(e, LocoError::InvalidParameter { .. }), "{text}");
    assert!(
        text.contains("row 1") && text.contains("whole number"),
        "{text}"
    );
    let e = run_batch(
        &spec(&["C_sy"], vec![f64::NAN]),
        1,
        &BatchMonitor::default(),
    )
    .unwrap_err();
    assert!(e.to_string().contains("row 0"), "{e}");
    let e = run_batch(&spec(&["C_sz"], vec![1.0]), 1, &BatchMonitor::default()).unwrap_err();
    assert!(e.to_string().contains("C_sz"), "{e}");
    let mut s = spec(&["C_sx"], vec![8e5]);
    s.histories = vec![3];
    assert!(run_batch(&s, 1, &BatchMonitor::default()).is_err());
}

#[test]
fn cancelled_batch_reports_interrupted() {
    let monitor = BatchMonitor::default();
    monitor.cancel.store(true, Ordering::Relaxed);
    let e = run_batch(&spec(&["C_sx"], vec![8e5, 8e5]), 2, &monitor).unwrap_err();
    assert_eq!(e, LocoError::Interrupted);
}

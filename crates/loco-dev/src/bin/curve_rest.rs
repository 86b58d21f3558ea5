//! A diagnosis: is every body at rest in a steady curve, and if not, what rings? Runs the
//! S_norm locomotive on perfect track (the balanced reference curve, R = 1200 m with 100 mm cant,
//! or straight) to `start` m, then records every step's accelerations over `window` m and prints
//! per body group the largest, its coordinate and the three largest peaks of its spectrum.
//! `modes` adds the state matrix at the running state (finite differences, as
//! `vehicle::analysis::linearise` does at the static equilibrium) and its modes of 20-150 Hz with less
//! than 10 % damping, each with the bodies that share its kinetic energy; `table` prints the
//! contact table around the leading wheelsets' −7.8 mm instead.
//!
//! `cargo run --release -p loco-dev --bin curve_rest -- [start] [window] [curve|straight|table] [modes]`
//!
//! Found with it: the traction rods' 49 Hz modes had 0.13 % damping before their nodes had any
//! (`traction_rod.bushing_damping_time`); the ringing did not depend on the table's step.
use loco_core::track::{CurveDirection, DesignSection};
use loco_core::vehicle::analysis::stiffest_mode::stable_step;
use loco_core::vehicle::curving::track_frame::CurvedTrack;
use loco_core::vehicle::model::layout::*;
use loco_core::vehicle::model::structure::VehicleStructure;
use loco_core::vehicle::output::run::{integrate, Flow};
use loco_core::vehicle::params::parameters::ParameterSet;
use loco_core::vehicle::scenarios::scenario::{
    build_track, curve_design, start_distance, Scenario, TrackSpec,
};
use loco_core::vehicle::scenarios::scenario_contact::build_wheel_rail;
use loco_core::vehicle::system::simulation::VehicleSystem;
use loco_core::vehicle::system::statics::{static_equilibrium, StaticsSettings};
use std::sync::Arc;

fn groups() -> Vec<(String, Vec<usize>)> {
    let mut g = vec![("carbody".to_string(), (CARBODY + Y..CARBODY + 6).collect())];
    for b in 0..N_BOGIES {
        g.push((
            format!("frame{}", b + 1),
            (frame(b) + Y..frame(b) + 6).collect(),
        ));
    }
    for w in 0..N_WHEELSETS {
        g.push((
            format!("ws{}", w + 1),
            vec![
                wheelset(w) + Y,
                wheelset(w) + Z,
                wheelset(w) + ROLL,
                wheelset(w) + YAW,
            ],
        ));
    }
    g.push((
        "motors".into(),
        (0..4).flat_map(|w| motor(w) + Y..motor(w) + 6).collect(),
    ));
    g.push((
        "shafts".into(),
        (0..4)
            .flat_map(|w| hollow_shaft(w)..hollow_shaft(w) + 3)
            .collect(),
    ));
    g.push((
        "rods".into(),
        (0..2)
            .flat_map(|b| traction_rod(b)..traction_rod(b) + 2)
            .collect(),
    ));
    g.push(("arms".into(), (82..90).collect()));
    g
}

fn main() {
    let a: Vec<String> = std::env::args().collect();
    let start: f64 = a.get(1).map_or(300.0, |s| s.parse().unwrap());
    let window: f64 = a.get(2).map_or(2.0, |s| s.parse().unwrap());
    let straight = a.get(3).is_some_and(|s| s == "straight");
    let cant = 0.1;
    let speed = (9.81 * cant / (2.0 * 0.7465) * 1200.0f64).sqrt();
    let mut scenario = Scenario::study("S_norm", speed, start, 0).unwrap();
    scenario.track = TrackSpec::Perfect;
    let structure = Arc::new(VehicleStructure::new(ParameterSet::default_vehicle()).unwrap());
    let wr = Arc::new(build_wheel_rail(&structure.parameters, &scenario).unwrap());
    println!("table step {:e}", wr.table().step());
    if a.get(3).is_some_and(|s| s == "table") {
        print_table(wr.table());
        return;
    }
    let track = Arc::new(build_track(&scenario, &structure).unwrap());
    let mut system = VehicleSystem::new(
        structure.clone(),
        wr.clone(),
        track,
        speed,
        start_distance(&structure),
        None,
        scenario.run.step,
    )
    .unwrap();
    if !straight {
        let sections = DesignSection::reference_curve(cant, CurveDirection::Left);
        let design = Arc::new(curve_design(&wr, &sections).unwrap());
        system.curve = Some(Arc::new(CurvedTrack::new(design, &structure)));
    }
    let eq = static_equilibrium(&mut system, &StaticsSettings::default()).unwrap();
    let step = stable_step(&system, &eq, scenario.run.step).unwrap();
    let mut y = eq.state;
    let pre = (start / speed / step).round() as usize;
    let steps = (window / speed / step).round() as usize;
    println!("V {speed:.3} m/s, step {step:e} s, {steps} steps");
    let mut hist: Vec<Vec<f64>> = vec![Vec::new(); N_DOF];
    let mut pos: Vec<Vec<f64>> = vec![Vec::new(); N_DOF];
    let mut at_start = Vec::new();
    integrate(
        &mut system,
        &mut y,
        step,
        pre + steps,
        None,
        |n, _, _, _| Ok(if n >= pre { Flow::Observe } else { Flow::Step }),
        |_, _, yy, dy| {
            if at_start.is_empty() {
                at_start = yy.to_vec();
            }
            for i in 0..N_DOF {
                hist[i].push(dy[N_DOF + i]);
                pos[i].push(yy[i]);
            }
        },
    )
    .unwrap();
    for w in 0..4 {
        let q = &at_start;
        println!(
            "ws{}: y {:.6e} z {:.4e} roll {:.4e} yaw {:.4e}",
            w + 1,
            q[wheelset(w) + Y],
            q[wheelset(w) + Z],
            q[wheelset(w) + ROLL],
            q[wheelset(w) + YAW]
        );
    }
    if a.get(4).is_some_and(|s| s == "modes") {
        modes(&mut system, &y, (pre + steps) as f64 * step);
    }
    let g = groups();
    let names = dof_names();
    for (name, dofs) in &g {
        let (mut worst, mut at, mut mean_worst) = (0.0f64, 0, 0.0f64);
        for &i in dofs {
            let m = hist[i].iter().fold(0.0f64, |x, v| x.max(v.abs()));
            let mean = hist[i].iter().sum::<f64>() / hist[i].len() as f64;
            mean_worst = mean_worst.max(mean.abs());
            if m > worst {
                worst = m;
                at = i;
            }
        }
        // Dominant frequency of the worst coordinate by zero crossings of acc − mean.
        let h = &hist[at];
        let mean = h.iter().sum::<f64>() / h.len() as f64;
        let crossings = h
            .windows(2)
            .filter(|p| (p[0] - mean) * (p[1] - mean) < 0.0)
            .count();
        let f = crossings as f64 / 2.0 / (h.len() as f64 * step);
        let p = &pos[at];
        let pm = p.iter().sum::<f64>() / p.len() as f64;
        let amp = p.iter().fold(0.0f64, |x, v| x.max((v - pm).abs()));
        let top = spectrum_peaks(h, mean, step);
        println!(
            "{name:8} max|acc| {worst:.3e} at {:24} mean {mean_worst:.2e} ~{f:.0} Hz, disp amp {amp:.2e} peaks {}",
            names[at], top.join(" ")
        );
    }
}

/// Finite-difference state matrix at (t, y), its eigenvalues in 20–150 Hz, each mode's shape by
/// inverse iteration and the bodies sharing its kinetic energy.
fn modes(system: &mut VehicleSystem, y0: &[f64], t: f64) {
    use loco_core::vehicle::analysis::linearise::{eigenvalues, LinearisationSettings};
    use loco_core::vehicle::time::integrator::OdeSystem;
    use nalgebra::{Complex, DMatrix, DVector};
    let n = system.dimension();
    let settings = LinearisationSettings::default();
    let mut a = vec![0.0; n * n];
    let mut y = y0.to_vec();
    let (mut plus, mut minus) = (vec![0.0; n], vec![0.0; n]);
    for j in 0..n {
        let h = settings.state_step(j, y0[j]);
        y[j] = y0[j] + h;
        system.derivatives(t, &y, &mut plus);
        y[j] = y0[j] - h;
        system.derivatives(t, &y, &mut minus);
        y[j] = y0[j];
        for i in 0..n {
            a[i * n + j] = (plus[i] - minus[i]) / (2.0 * h);
        }
    }
    let ev = eigenvalues(&a, n).unwrap();
    let mut list: Vec<_> = ev
        .into_iter()
        .filter(|e| e.im > 1e-6)
        .map(|e| {
            (
                e,
                e.im / (2.0 * std::f64::consts::PI),
                -e.re / e.re.hypot(e.im),
            )
        })
        .filter(|m| (20.0..150.0).contains(&m.1) && m.2 < 0.1)
        .collect();
    list.sort_by(|x, y| x.1.total_cmp(&y.1));
    let am = DMatrix::from_row_slice(n, n, &a).map(|v| Complex::new(v, 0.0));
    let structure = system.structure.clone();
    for (lambda, f, zeta) in list {
        let shifted = &am
            - DMatrix::<Complex<f64>>::identity(n, n) * (lambda * Complex::new(1.0 + 1e-9, 0.0));
        let lu = shifted.lu();
        let mut v = DVector::from_element(n, Complex::new(1.0, 0.0));
        for _ in 0..3 {
            v = lu.solve(&v).unwrap();
            let norm = v.norm();
            v /= Complex::new(norm, 0.0);
        }
        let re: Vec<f64> = v.iter().map(|c| c.re).collect();
        let im: Vec<f64> = v.iter().map(|c| c.im).collect();
        let e = loco_core::vehicle::analysis::modes::mode_energy(&structure, &re, &im).unwrap();
        let mut share: Vec<(f64, usize)> =
            e.bodies.iter().enumerate().map(|(i, &s)| (s, i)).collect();
        share.sort_by(|x, y| y.0.total_cmp(&x.0));
        let top: Vec<String> = share
            .iter()
            .take(4)
            .map(|&(s, i)| {
                let m = e.motions[i];
                let k = (0..6).max_by(|&x, &y| m[x].total_cmp(&m[y])).unwrap();
                format!(
                    "{} {:.0}% ({})",
                    structure.bodies[i].name,
                    100.0 * s,
                    loco_core::vehicle::analysis::modes::MOTIONS[k]
                )
            })
            .collect();
        println!("mode {f:7.2} Hz zeta {zeta:.5}: {}", top.join(", "));
    }
}

/// The contact table's rows from −8.4 to −7.2 mm, each wheel at the rigid roll and its layers.
fn print_table(t: &loco_core::contact::table::ContactTable) {
    for k in -84..=-72 {
        let yy = k as f64 * 1e-4;
        let r = t.lookup(yy);
        for side in [1usize, 0] {
            for off in [-1e-3, 0.0, 1e-3] {
                let l = t.lookup_wheel(yy, side, r.roll + off);
                let mut line = format!(
                    "y {:+.1} mm s{side} roll {:+.5e} off {off:+.0e} rise {:+.5e}:",
                    yy * 1e3,
                    r.roll,
                    l.rise
                );
                for (k, p) in l.contact.points.iter().enumerate() {
                    if let Some(p) = p {
                        line += &format!(
                            " [{k}] gap {:.4e} ang {:.4} lat {:.5} wy {:.5}",
                            p.gap, p.contact_angle, p.lateral, p.wheel_y
                        );
                    }
                }
                println!("{line}");
            }
        }
    }
}

/// The three largest local peaks (Hz, amplitude) of the spectrum of `h − mean` (Hann window),
/// `h` sampled every `step` s.
fn spectrum_peaks(h: &[f64], mean: f64, step: f64) -> Vec<String> {
    use std::f64::consts::PI;
    let n = h.len();
    let spec: Vec<(f64, f64)> = (1..n / 2)
        .map(|k| {
            let (mut re, mut im) = (0.0, 0.0);
            for (j, v) in h.iter().enumerate() {
                let hann = 0.5 - 0.5 * (2.0 * PI * j as f64 / n as f64).cos();
                let phase = 2.0 * PI * (k * j) as f64 / n as f64;
                re += (v - mean) * hann * phase.cos();
                im -= (v - mean) * hann * phase.sin();
            }
            (k as f64 / (n as f64 * step), 4.0 * re.hypot(im) / n as f64)
        })
        .collect();
    let mut peaks: Vec<(f64, f64)> = (1..spec.len().saturating_sub(1))
        .filter(|&k| spec[k].1 > spec[k - 1].1 && spec[k].1 >= spec[k + 1].1)
        .map(|k| spec[k])
        .collect();
    peaks.sort_by(|a, b| b.1.total_cmp(&a.1));
    peaks
        .iter()
        .take(3)
        .map(|(f, a)| format!("{f:.0}Hz:{a:.1e}"))
        .collect()
}

//! The output channels of a run as one built object: for each channel its name, unit, kind and
//! probe (how its value is read from a state and the forces of the evaluation that gave its
//! derivatives). Built once per vehicle structure; the same object names the channels
//! ([`ChannelSet::names`]) and records them ([`ChannelSet::sample`]), so names and values cannot
//! fall out of order, and a channel's kind is read from the object, not guessed from its name.
//!
//! Order: carbody floor lateral and vertical acceleration at the two Sperling points (floor above
//! each bogie centre, `carbody.sperling_point_lateral_offset` to the left), bogie frame lateral
//! acceleration at the frame centre and above each wheelset, wheelset lateral displacement and
//! yaw, wheel-rail forces Q, Y and Y/Q of all eight wheels, the damper channels
//! ([`DAMPER_CHANNELS`]), then the curving channels (per wheel ΔQ/Q0, T·γ, contact angle, flange
//! contact; per wheelset ΣY; named in [`crate::vehicle::output::wheel_channels`]), then what accelerometers at
//! the carbody floor and frame points read (`…_accelerometer_y_…`, kind `accelerometer`,
//! [`crate::vehicle::output::accelerometer`]). Channels added later are appended so every older channel keeps its
//! position.

use crate::error::{LocoError, Result};
use crate::vehicle::model::kinematics::point_motion;
use crate::vehicle::model::layout::*;
use crate::vehicle::model::structure::VehicleStructure;
use crate::vehicle::model::suspension::DamperRole;
use crate::vehicle::output::accelerometer::BodyAxes;
use crate::vehicle::output::wheel_channels::{
    wheel_channel, wheelset_channel, WheelQuantity, WheelsetQuantity, CURVING_WHEEL_QUANTITIES,
    WHEELSET_MOTION_QUANTITIES, WHEEL_FORCE_QUANTITIES,
};
use crate::vehicle::system::simulation::VehicleSystem;

pub use super::channel::{Channel, ChannelKind, Probe};

/// The damper channels, in order: the force of the yaw and secondary lateral dampers, the valve
/// of the yaw dampers, then the force of the primary and secondary vertical dampers (added
/// later, so appended to keep the positions of the older channels), then the strokes of the
/// yaw and secondary lateral dampers (the frequency response's outputs).
const DAMPER_CHANNELS: [(&[DamperRole], ChannelKind); 4] = [
    (
        &[DamperRole::Yaw, DamperRole::SecondaryLateral],
        ChannelKind::DamperForce,
    ),
    (&[DamperRole::Yaw], ChannelKind::DamperValve),
    (
        &[DamperRole::PrimaryVertical, DamperRole::SecondaryVertical],
        ChannelKind::DamperForce,
    ),
    (
        &[DamperRole::Yaw, DamperRole::SecondaryLateral],
        ChannelKind::DamperStroke,
    ),
];

/// Every output channel of a vehicle structure, in recording order.
#[derive(Debug, Clone, PartialEq)]
pub struct ChannelSet {
    channels: Vec<Channel>,
    /// The channels' probes, in order, kept apart so the sampling loop reads a dense array.
    probes: Vec<Probe>,
    /// Mean static wheel load Q0, N: the vehicle's weight over its eight wheels (for ΔQ/Q0).
    static_load: f64,
}

impl ChannelSet {
    /// The channels of a vehicle of structure `s`.
    pub fn new(s: &VehicleStructure) -> Result<Self> {
        let carbody = &s.sections.carbody;
        let floor = carbody.floor_height - s.bodies[BODY_CARBODY].position[2];
        let side = carbody.sperling_point_lateral_offset;
        let along = carbody.sperling_point_longitudinal_offset;
        let mut channels = Vec::new();
        // The measuring points: (name's body part, axis letter, place tag, body, point, component),
        // the carbody floor's lateral and vertical at the two Sperling points, the frames'
        // lateral at the centre and above each wheelset.
        let mut points = Vec::new();
        for (x, tag) in [(along, "front"), (-along, "rear")] {
            for (axis, component) in [("y", Y), ("z", Z)] {
                let place = (tag.to_string(), BODY_CARBODY, [x, side, floor], component);
                points.push(("carbody_floor".to_string(), axis, place));
            }
        }
        for b in 0..N_BOGIES {
            let frame = format!("frame{}", b + 1);
            let body = body_frame(b);
            points.push((frame.clone(), "y", ("centre".into(), body, [0.0; 3], Y)));
            for w in 2 * b..2 * b + 2 {
                let dx = s.layout.wheelset_x[w] - s.layout.bogie_x[b];
                let place = (format!("wheelset{}", w + 1), body, [dx, 0.0, 0.0], Y);
                points.push((frame.clone(), "y", place));
            }
        }
        for (at, axis, (tag, body, point, component)) in &points {
            channels.push(Channel {
                name: format!("{at}_a{axis}_{tag}"),
                unit: "m/s²",
                probe: Probe::Acceleration {
                    body: *body,
                    point: *point,
                    component: *component,
                },
            });
        }
        for w in 0..N_WHEELSETS {
            for q in WHEELSET_MOTION_QUANTITIES {
                let (unit, probe) = match q {
                    WheelsetQuantity::Yaw => ("rad", Probe::WheelsetYaw(w)),
                    _ => ("m", Probe::WheelsetLateral(w)),
                };
                let name = wheelset_channel(w, q);
                channels.push(Channel { name, unit, probe });
            }
        }
        let wheels = |channels: &mut Vec<Channel>, quantities: &[WheelQuantity]| {
            for w in 0..N_WHEELSETS {
                for side in 0..2 {
                    for &quantity in quantities {
                        channels.push(Channel {
                            name: wheel_channel(w, side, quantity),
                            unit: quantity.unit(),
                            probe: Probe::Wheel { w, side, quantity },
                        });
                    }
                }
            }
        };
        wheels(&mut channels, &WHEEL_FORCE_QUANTITIES);
        for (roles, kind) in DAMPER_CHANNELS {
            for &role in roles {
                for (i, placement) in s.suspension.dampers.iter().enumerate() {
                    if placement.role != role {
                        continue;
                    }
                    let name = &placement.name;
                    channels.push(match kind {
                        ChannelKind::DamperValve => Channel {
                            name: format!("{name}_valve"),
                            unit: "–",
                            probe: Probe::DamperValve(i),
                        },
                        ChannelKind::DamperStroke => Channel {
                            name: format!("{name}_stroke"),
                            unit: "m",
                            probe: Probe::DamperStroke(i),
                        },
                        _ => Channel {
                            name: format!("{name}_force"),
                            unit: "N",
                            probe: Probe::DamperForce(i),
                        },
                    });
                }
            }
        }
        wheels(&mut channels, &CURVING_WHEEL_QUANTITIES);
        for w in 0..N_WHEELSETS {
            channels.push(Channel {
                name: wheelset_channel(w, WheelsetQuantity::GuidingForce),
                unit: "N",
                probe: Probe::GuidingForce(w),
            });
        }
        // What accelerometers at the same points read, appended after the older channels.
        for (at, axis, (tag, body, point, component)) in points {
            channels.push(Channel {
                name: format!("{at}_accelerometer_{axis}_{tag}"),
                unit: "m/s²",
                probe: Probe::Accelerometer {
                    body,
                    point,
                    component,
                },
            });
        }
        Ok(Self {
            probes: channels.iter().map(|c| c.probe).collect(),
            channels,
            static_load: s.total_mass() * s.gravity / (2 * N_WHEELSETS) as f64,
        })
    }

    /// The set of only the channels called `names`, in recording order (a run that needs no
    /// more than its metrics records their channels alone). An unknown name is an error.
    pub fn only(self, names: &[&str]) -> Result<Self> {
        if let Some(missing) = names
            .iter()
            .find(|n| !self.channels.iter().any(|c| c.name == **n))
        {
            return Err(LocoError::input(
                "channels",
                format!("no channel `{missing}`"),
            ));
        }
        let channels: Vec<Channel> = self
            .channels
            .into_iter()
            .filter(|c| names.contains(&c.name.as_str()))
            .collect();
        Ok(Self {
            probes: channels.iter().map(|c| c.probe).collect(),
            channels,
            static_load: self.static_load,
        })
    }

    /// The channels, in recording order.
    pub fn channels(&self) -> &[Channel] {
        &self.channels
    }

    /// Number of channels.
    pub fn len(&self) -> usize {
        self.channels.len()
    }

    /// Whether the set is empty (never, for a built vehicle).
    pub fn is_empty(&self) -> bool {
        self.channels.is_empty()
    }

    /// The channel names, in recording order.
    pub fn names(&self) -> Vec<String> {
        self.channels.iter().map(|c| c.name.clone()).collect()
    }

    /// Names of the channels of kind `kind`, in recording order.
    pub fn names_of_kind(&self, kind: ChannelKind) -> Vec<String> {
        self.channels
            .iter()
            .filter(|c| c.kind() == kind)
            .map(|c| c.name.clone())
            .collect()
    }

    /// One sample of every channel, in order, from state `y` and its derivatives `dy` (the
    /// system's wheel and damper forces must be those of the evaluation that gave `dy`). The one
    /// recording function: the runs record it and the frequency response linearises it.
    pub fn sample(&self, system: &VehicleSystem, y: &[f64], dy: &[f64], mut push: impl FnMut(f64)) {
        let s = &system.structure;
        let acc = &dy[N_DOF..2 * N_DOF];
        // The accelerometers of one body follow each other: its acceleration and axes are formed
        // once for them.
        let mut axes: Option<(usize, [f64; 6], BodyAxes)> = None;
        for probe in &self.probes {
            push(match *probe {
                Probe::Acceleration {
                    body,
                    point,
                    component,
                } => point_motion(&s.bodies[body].map.apply(acc), point)[component],
                Probe::WheelsetLateral(w) => y[wheelset(w) + Y],
                Probe::WheelsetYaw(w) => y[wheelset(w) + YAW],
                Probe::Wheel { w, side, quantity } => {
                    quantity.value(&system.wheel_forces[w][side], self.static_load)
                }
                Probe::GuidingForce(w) => {
                    let [left, right] = &system.wheel_forces[w];
                    left.lateral + right.lateral
                }
                Probe::DamperForce(i) => system.damper_forces[i],
                Probe::DamperValve(i) => system.discrete[i].scale_factor,
                Probe::DamperStroke(i) => {
                    // On a curve the dampers act in the reference frame (`track_frame`).
                    let states = match system.curve {
                        Some(_) => &system.frame_work.states,
                        None => &system.body_states,
                    };
                    system.dampers[i].stroke(states).0
                }
                Probe::Accelerometer {
                    body,
                    point,
                    component,
                } => {
                    let (_, motion, frame) = match axes {
                        Some(cached) if cached.0 == body => cached,
                        _ => {
                            let fresh = (
                                body,
                                s.bodies[body].map.apply(acc),
                                BodyAxes::of(system, y, body),
                            );
                            axes = Some(fresh);
                            fresh
                        }
                    };
                    frame.reading(point_motion(&motion, point))[component]
                }
            });
        }
    }
}

#[cfg(test)]
mod tests;

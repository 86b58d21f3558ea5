//! The rails' plane under each wheelset, kept from one evaluation to the next and reused when
//! the next reads the same distance at the same speed.
//!
//! Why: the exponential RK4 evaluates its second and third stages at the same time (t + h/2),
//! and a step's first stage at the time of its predecessor's last (t + h), so every other
//! evaluation reads the track at the distances of the one before. The track's Hermite look-up
//! and the plane (its roll's series, the rates) cost about 260 instructions per wheelset. The
//! key is the distance and the speed bit for bit, and the track and contact they came from are
//! held, so neither can be freed and another take its address: a reused plane is the very one
//! that would be computed.

use crate::track::TrackIrregularity;
use crate::vehicle::model::layout::N_WHEELSETS;
use crate::vehicle::rail_contact::rail_plane::RailPlane;
use crate::vehicle::rail_contact::wheel_rail::WheelRail;
use std::sync::Arc;

/// A plane and what it was computed at: distance (m) and speed (m/s), as bits.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Kept {
    distance: u64,
    speed: u64,
    plane: RailPlane,
}

/// The last plane of each wheelset (see the module's documentation).
#[derive(Debug, Clone, Default)]
pub(crate) struct RailPlanes {
    /// The track and the contact the kept planes come from.
    sources: Option<(Arc<TrackIrregularity>, Arc<WheelRail>)>,
    last: [Option<Kept>; N_WHEELSETS],
}

impl RailPlanes {
    /// The plane of `track` at `distance` (m) for wheelset `w` of `wheel_rail` running at
    /// `speed` (m/s): the kept one if it was computed at the same distance and speed.
    #[inline]
    pub(crate) fn plane(
        &mut self,
        track: &Arc<TrackIrregularity>,
        wheel_rail: &Arc<WheelRail>,
        w: usize,
        distance: f64,
        speed: f64,
    ) -> RailPlane {
        let same_sources = matches!(&self.sources,
            Some((t, c)) if Arc::ptr_eq(t, track) && Arc::ptr_eq(c, wheel_rail));
        if !same_sources {
            self.sources = Some((track.clone(), wheel_rail.clone()));
            self.last = [None; N_WHEELSETS];
        }
        let (distance_bits, speed_bits) = (distance.to_bits(), speed.to_bits());
        match self.last[w] {
            Some(kept) if kept.distance == distance_bits && kept.speed == speed_bits => kept.plane,
            _ => {
                let plane = wheel_rail.rail_plane(&track.at(distance), speed);
                self.last[w] = Some(Kept {
                    distance: distance_bits,
                    speed: speed_bits,
                    plane,
                });
                plane
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::vehicle::params::parameters::ParameterSet;
    use crate::vehicle::scenarios::scenario::Scenario;
    use crate::vehicle::scenarios::scenario_contact::shared_wheel_rail;

    /// A track of `n` nodes 0.25 m apart with every channel a different sine (and its slope).
    fn track(n: usize, phase: f64) -> Arc<TrackIrregularity> {
        let channel = |c: usize, slope: bool| -> Vec<f64> {
            (0..n)
                .map(|i| {
                    let arg = 0.3 * i as f64 * (c + 1) as f64 + phase;
                    1e-3 * if slope { arg.cos() } else { arg.sin() }
                })
                .collect()
        };
        let values = std::array::from_fn(|c| channel(c, false));
        let slopes = std::array::from_fn(|c| channel(c, true));
        Arc::new(TrackIrregularity::from_channels(0.25, &values, &slopes, 0.0, None).unwrap())
    }

    #[test]
    fn a_kept_plane_is_the_one_computed_afresh() {
        let p = ParameterSet::default_vehicle();
        let contact =
            shared_wheel_rail(&p, &Scenario::study("S_high", 55.0, 300.0, 1).unwrap()).unwrap();
        let other =
            shared_wheel_rail(&p, &Scenario::study("S_low", 55.0, 300.0, 1).unwrap()).unwrap();
        let (first, second) = (track(200, 0.0), track(200, 0.7));
        let mut planes = RailPlanes::default();
        // Stages as the time loop asks for them: repeated distances, a speed that changes at a
        // kept distance, a distance one bit away, another track and another contact.
        let asks = [
            (&first, &contact, 10.0, 55.0),
            (&first, &contact, 10.0, 55.0),
            (&first, &contact, 10.0, 54.0),
            (&first, &contact, f64::from_bits(10f64.to_bits() + 1), 54.0),
            (&first, &contact, 10.0, 54.0),
            (&second, &contact, 10.0, 54.0),
            (&second, &other, 10.0, 54.0),
            (&second, &other, 10.0, 54.0),
            (&first, &other, 10.0, 54.0),
        ];
        for (k, &(track, wheel_rail, distance, speed)) in asks.iter().enumerate() {
            for w in 0..N_WHEELSETS {
                let s = distance + 2.5 * w as f64;
                let kept = planes.plane(track, wheel_rail, w, s, speed);
                let fresh = wheel_rail.rail_plane(&track.at(s), speed);
                assert_eq!(
                    format!("{kept:?}"),
                    format!("{fresh:?}"),
                    "ask {k} wheelset {w}"
                );
            }
        }
    }
}

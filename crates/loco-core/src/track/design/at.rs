//! The design at a distance: which piece holds it, and the alignment and cant there.
//!
//! Why a hint: the track frames read the design at every station twice per step, and the
//! binary search over the pieces was a fifth of each look-up although a station stays in one
//! piece for thousands of look-ups. [`TrackDesign::at_from`] checks the piece of the station's
//! last look-up first and searches only when it no longer holds the distance; it takes exactly
//! the piece the search would (tested), so the point is the same bits.

use super::{roll_of, DesignPoint, TrackDesign};

impl TrackDesign {
    /// The design at distance `s` (m).
    pub fn at(&self, s: f64) -> DesignPoint {
        self.at_piece(s, self.piece_of(s))
    }

    /// The design at distance `s` (m), as [`Self::at`]; `hint` is the piece of an earlier
    /// look-up (any value will do) and is left at `s`'s piece.
    #[inline(always)]
    pub fn at_from(&self, s: f64, hint: &mut usize) -> DesignPoint {
        if !self.holds(*hint, s) {
            *hint = self.piece_of(s);
        }
        self.at_piece(s, *hint)
    }

    /// The piece whose values hold at `s` (m): the last one starting at or before `s`, the
    /// first if none does (before the design, or `s` NaN).
    pub(super) fn piece_of(&self, s: f64) -> usize {
        self.pieces.partition_point(|p| p.start <= s).max(1) - 1
    }

    /// Whether [`Self::piece_of`] of `s` is `i`: the starts increase (every length is
    /// positive), so `i` is it when it starts at or before `s` (or is the first) and the next
    /// does not (or there is none). A NaN `s` is before no start, as in the search.
    #[inline]
    fn holds(&self, i: usize, s: f64) -> bool {
        i < self.pieces.len()
            && (i == 0 || self.pieces[i].start <= s)
            && self
                .pieces
                .get(i + 1)
                .is_none_or(|next| next.start > s || s.is_nan())
    }

    /// The design at `s` (m) in piece `i` ([`Self::piece_of`] of `s`). Inlined into the track
    /// frames' loop over the stations: called, it spent a tenth of its instructions saving and
    /// restoring registers.
    #[inline(always)]
    fn at_piece(&self, s: f64, i: usize) -> DesignPoint {
        let p = &self.pieces[i];
        // Beyond the design's ends the end values continue: no gradients there.
        let (sigma, gradients) = if s < 0.0 {
            (0.0, false)
        } else if s > self.end {
            (self.end - p.start, false)
        } else {
            (s - p.start, true)
        };
        let (heading0, integral0) = p.heading_at(sigma);
        // Heading and its integral continue with the end curvature beyond the ends.
        let extra = s - p.start - sigma;
        let kappa_end = p.kappa + p.kappa_slope * sigma;
        let heading = heading0 + kappa_end * extra;
        let heading_integral = integral0 + heading0 * extra + 0.5 * kappa_end * extra * extra;
        let (c0, c1) = p.run_off;
        let along = (p.start + sigma).clamp(c0, c1) - c0;
        let in_run_off = gradients && (c0..c1).contains(&s);
        let (roll, cos2) = match p.fixed_roll {
            Some(fixed) => fixed,
            None => roll_of(p.cant + p.cant_slope * along, self.half_distance),
        };
        DesignPoint {
            curvature: kappa_end,
            curvature_rate: if gradients { p.kappa_slope } else { 0.0 },
            roll,
            roll_rate: if in_run_off {
                p.cant_slope / (2.0 * self.half_distance) * cos2
            } else {
                0.0
            },
            heading,
            heading_integral,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::super::{CurveDirection, DesignSection};
    use super::*;

    #[test]
    fn a_hinted_look_up_takes_the_searched_piece_and_gives_the_same_bits() {
        let design = TrackDesign::new(
            &[
                DesignSection::Straight { length: 10.0 },
                DesignSection::Transition {
                    length: 60.0,
                    cant_run_off: Some(40.0),
                },
                DesignSection::Curve {
                    length: 100.0,
                    radius: 800.0,
                    cant: 0.1,
                    direction: CurveDirection::Left,
                },
                DesignSection::Transition {
                    length: 50.0,
                    cant_run_off: None,
                },
            ],
            0.75,
            100.0,
        )
        .unwrap();
        let n = design.pieces.len();
        // Forward in small steps, the pieces' starts and the values either side of them, the
        // ends, back again, jumps, and what is not a distance.
        // The neighbours of a distance ≥ 0 (`f64::next_up` is newer than the crate's Rust).
        let up = |x: f64| f64::from_bits(x.to_bits() + 1);
        let down = |x: f64| match x {
            0.0 => -f64::from_bits(1),
            _ => f64::from_bits(x.to_bits() - 1),
        };
        let mut distances: Vec<f64> = (-40..=2600).map(|k| 0.1 * k as f64).collect();
        for p in &design.pieces {
            let s = p.start;
            distances.extend([s, down(s), up(s), s, down(s)]);
        }
        let end = design.length();
        distances.extend([end, up(end), down(end), 1e9, -1e9, 0.0, -0.0]);
        distances.extend([f64::NAN, f64::INFINITY, f64::NEG_INFINITY, 65.0, 5.0, 200.0]);
        distances.extend((0..400).rev().map(|k| 0.7 * k as f64));
        let bits = |p: DesignPoint| {
            [
                p.curvature,
                p.curvature_rate,
                p.roll,
                p.roll_rate,
                p.heading,
                p.heading_integral,
            ]
            .map(f64::to_bits)
        };
        let mut carried = 0;
        for &s in &distances {
            let expected = design.at(s);
            assert_eq!(
                bits(design.at_from(s, &mut carried)),
                bits(expected),
                "s {s}"
            );
            assert_eq!(carried, design.piece_of(s), "s {s}");
            for start in 0..n + 2 {
                let mut hint = start;
                assert_eq!(bits(design.at_from(s, &mut hint)), bits(expected), "s {s}");
                assert_eq!(hint, design.piece_of(s), "s {s} hint {start}");
            }
        }
    }
}

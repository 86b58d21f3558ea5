//! Sparse rows that share their columns, evaluated together.
//!
//! Why: the exponential scheme's propagator is a (2r × 5r) map whose rows come in groups with
//! the same non-zero columns (the six outputs of one wheelset's bearings read the same fifteen
//! inputs), applied five times per step. One sparse row at a time loads each column index and
//! input once per row, with a bounds check, for one multiply and one add. A group loads them once
//! for all its rows, whose sums then run side by side in SIMD lanes. Each row's sum is still
//! `Iterator::sum`'s: from −0, term by term in increasing column order, no fused multiply-add,
//! so the outputs are the same bits as the rows' one by one.

use super::stiff_linear_part::Sparse;

/// Rows of one group evaluated together; a group of more rows is split.
const LANES: usize = 8;

/// Up to [`LANES`] rows with the same columns.
#[derive(Debug, Clone)]
struct Group {
    /// Output index of each row (lane).
    rows: Vec<usize>,
    /// The shared columns, increasing.
    columns: Vec<usize>,
    /// Per column, each row's coefficient (0 in the lanes without a row, whose sums are dropped).
    coefficients: Vec<[f64; LANES]>,
}

/// Sparse rows grouped by their columns.
#[derive(Debug, Clone, Default)]
pub struct RowGroups {
    groups: Vec<Group>,
    /// Rows that share their columns with no other: (output index, row).
    single: Vec<(usize, Sparse)>,
}

impl RowGroups {
    /// The groups of `rows` (each a sparse row with increasing columns).
    pub fn new(rows: &[Sparse]) -> Self {
        let mut patterns: Vec<(Vec<usize>, Vec<usize>)> = Vec::new();
        for (i, row) in rows.iter().enumerate() {
            let columns: Vec<usize> = row.iter().map(|&(j, _)| j).collect();
            match patterns.iter_mut().find(|(c, _)| *c == columns) {
                Some((_, members)) => members.push(i),
                None => patterns.push((columns, vec![i])),
            }
        }
        let mut out = Self::default();
        for (columns, members) in patterns {
            if members.len() == 1 {
                out.single.push((members[0], rows[members[0]].clone()));
                continue;
            }
            for chunk in members.chunks(LANES) {
                let coefficients = (0..columns.len())
                    .map(|k| {
                        let mut c = [0.0; LANES];
                        for (lane, &i) in chunk.iter().enumerate() {
                            c[lane] = rows[i][k].1;
                        }
                        c
                    })
                    .collect();
                out.groups.push(Group {
                    rows: chunk.to_vec(),
                    columns: columns.clone(),
                    coefficients,
                });
            }
        }
        out
    }

    /// `out[i] = Σ_j row_i[j] · x[j]` for every row `i` (the rows' outputs only).
    #[inline]
    pub fn apply(&self, x: &[f64], out: &mut [f64]) {
        for g in &self.groups {
            let mut sums = [-0.0; LANES];
            for (&j, c) in g.columns.iter().zip(&g.coefficients) {
                let xj = x[j];
                for (s, c) in sums.iter_mut().zip(c) {
                    *s += c * xj;
                }
            }
            for (&i, s) in g.rows.iter().zip(sums) {
                out[i] = s;
            }
        }
        for (i, row) in &self.single {
            out[*i] = row.iter().map(|&(j, c)| c * x[j]).sum();
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn groups_give_the_bits_of_one_row_at_a_time() {
        // Ten rows on one pattern (a group of eight and one of two), one alone, one empty; the
        // inputs hold zeros of both signs, so that a sum's start (−0) shows.
        let pattern = [1, 4, 5, 9];
        let mut rows: Vec<Sparse> = (0..10)
            .map(|r| {
                let c = |k: usize| ((r * 7 + k * 3) as f64 * 0.61).sin() * 10f64.powi(k as i32);
                pattern
                    .iter()
                    .enumerate()
                    .map(|(k, &j)| (j, c(k)))
                    .collect()
            })
            .collect();
        rows.push(vec![(0, 2.5), (9, -1.0)]);
        rows.push(vec![]);
        let groups = RowGroups::new(&rows);
        assert_eq!(groups.groups.len(), 2);
        for x in [
            (0..10).map(|i| (i as f64 * 1.3).cos()).collect::<Vec<_>>(),
            vec![-0.0; 10],
            (0..10)
                .map(|i| if i % 2 == 0 { 0.0 } else { -0.0 })
                .collect(),
        ] {
            let mut out = vec![f64::NAN; rows.len()];
            groups.apply(&x, &mut out);
            for (row, o) in rows.iter().zip(&out) {
                let expected: f64 = row.iter().map(|&(j, c)| c * x[j]).sum();
                assert_eq!(o.to_bits(), expected.to_bits());
            }
        }
    }
}

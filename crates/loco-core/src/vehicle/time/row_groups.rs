//! Sparse rows that share their columns, evaluated together.
//!
//! Why: the exponential scheme's propagator is a (2r × 5r) map whose rows come in groups with
//! the same non-zero columns (the six outputs of one wheelset's bearings read the same fifteen
//! inputs), applied five times per step. One sparse row at a time loads each column index and
//! input once per row, with a bounds check, for one multiply and one add. A group loads them once
//! for all its rows, whose sums then run side by side in SIMD lanes. Each row's sum is still
//! `Iterator::sum`'s: from −0, term by term in increasing column order, no fused multiply-add,
//! so the outputs are the same bits as the rows' one by one.

use crate::simd::multiversion;

/// A sparse row or column: (coordinate index, coefficient).
pub type Sparse = Vec<(usize, f64)>;

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
        apply_copy(self, x, out);
    }

    /// [`Self::apply`] for any processor.
    #[inline(always)]
    fn apply_plain(&self, x: &[f64], out: &mut [f64]) {
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

/// [`RowGroups::apply_plain`] in the baseline and the AVX copy (the module `simd`'s dispatch):
/// the eight lanes of a group in AVX's two four-wide registers instead of SSE2's four two-wide
/// ones, the same multiplies and adds per lane, so the same bits.
#[multiversion(targets("x86_64+avx"))]
fn apply_copy(rows: &RowGroups, x: &[f64], out: &mut [f64]) {
    rows.apply_plain(x, out);
}

/// Rows of the same length evaluated four at a time, each lane with its own columns.
///
/// Why: the springs' deflection rows `J` and the dampers' elongation rows read different
/// coordinates (their own wheelset's, their own bogie's), so they share no columns, but come in
/// rows of equal length (a wheelset's three rows have 5, 3 and 3 terms, as the other
/// wheelsets'). Four such rows take their `k`-th terms in one step. Each lane's sum is its row's
/// own, from −0 term by term in the row's order; lanes without a row are dropped.
#[derive(Debug, Clone, Default)]
pub struct LaneRows {
    groups: Vec<LaneGroup>,
    /// One more than the largest column of any lane (padding included): the length `x` must
    /// have at least, checked once per call instead of at each of the four loads per term.
    min_len: usize,
}

#[derive(Debug, Clone)]
struct LaneGroup {
    /// Index of each row (lane) among the rows; up to four.
    rows: Vec<usize>,
    /// Per term: each lane's column and coefficient (column 0, coefficient 0 in empty lanes).
    columns: Vec<[usize; 4]>,
    coefficients: Vec<[f64; 4]>,
}

impl LaneRows {
    /// The lanes of `rows`: rows of one length four at a time, in the rows' order.
    pub fn new(rows: &[Sparse]) -> Self {
        let mut lengths: Vec<usize> = rows.iter().map(Vec::len).collect();
        lengths.sort_unstable();
        lengths.dedup();
        let mut groups = Vec::new();
        for len in lengths {
            let members: Vec<usize> = (0..rows.len()).filter(|&i| rows[i].len() == len).collect();
            for chunk in members.chunks(4) {
                let mut columns = vec![[0; 4]; len];
                let mut coefficients = vec![[0.0; 4]; len];
                for (lane, &i) in chunk.iter().enumerate() {
                    for (k, &(j, c)) in rows[i].iter().enumerate() {
                        columns[k][lane] = j;
                        coefficients[k][lane] = c;
                    }
                }
                groups.push(LaneGroup {
                    rows: chunk.to_vec(),
                    columns,
                    coefficients,
                });
            }
        }
        let min_len = groups
            .iter()
            .flat_map(|g| g.columns.iter().flatten())
            .map(|&j| j + 1)
            .max()
            .unwrap_or(0);
        Self { groups, min_len }
    }

    /// Calls `f(i, Σ_k c_ik · x[j_ik])` for every row `i` (rows in no particular order).
    #[inline(always)]
    pub fn for_each(&self, x: &[f64], mut f: impl FnMut(usize, f64)) {
        // The gathers were a third of the exponential scheme's own work with their bounds
        // checks; every column is below `min_len` (by construction), so one check covers them.
        assert!(
            x.len() >= self.min_len,
            "LaneRows: input shorter than its columns"
        );
        let load = |j: usize| x[j];
        for g in &self.groups {
            let mut sums = [-0.0; 4];
            for (j, c) in g.columns.iter().zip(&g.coefficients) {
                let xj = [load(j[0]), load(j[1]), load(j[2]), load(j[3])];
                for ((s, c), xj) in sums.iter_mut().zip(c).zip(xj) {
                    *s += c * xj;
                }
            }
            for (&i, s) in g.rows.iter().zip(sums) {
                f(i, s);
            }
        }
    }

    /// `out[i] = Σ_k c_ik · x[j_ik]` for every row `i`.
    #[inline]
    pub fn apply(&self, x: &[f64], out: &mut [f64]) {
        self.for_each(x, |i, s| out[i] = s);
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
            let mut plain = vec![f64::NAN; rows.len()];
            groups.apply_plain(&x, &mut plain);
            assert_eq!(
                out.iter().map(|v| v.to_bits()).collect::<Vec<_>>(),
                plain.iter().map(|v| v.to_bits()).collect::<Vec<_>>()
            );
            for (row, o) in rows.iter().zip(&out) {
                let expected: f64 = row.iter().map(|&(j, c)| c * x[j]).sum();
                assert_eq!(o.to_bits(), expected.to_bits());
            }
        }
    }

    #[test]
    fn lanes_give_the_bits_of_one_row_at_a_time() {
        // Nine rows of lengths 1 to 3 on their own columns (groups of four, padded lanes), and
        // an empty one; inputs with zeros of both signs.
        let mut rows: Vec<Sparse> = (0..9)
            .map(|r| {
                (0..1 + r % 3)
                    .map(|k| ((r * 3 + k * 5) % 10, ((r + k) as f64 * 0.83).sin()))
                    .collect()
            })
            .collect();
        rows.push(vec![]);
        let lanes = LaneRows::new(&rows);
        for x in [
            (0..10).map(|i| (i as f64 * 1.3).cos()).collect::<Vec<_>>(),
            (0..10)
                .map(|i| if i % 2 == 0 { 0.0 } else { -0.0 })
                .collect(),
        ] {
            let mut out = vec![f64::NAN; rows.len()];
            lanes.apply(&x, &mut out);
            for (row, o) in rows.iter().zip(&out) {
                let expected: f64 = row.iter().map(|&(j, c)| c * x[j]).sum();
                assert_eq!(o.to_bits(), expected.to_bits());
            }
        }
    }
}

//! The stiff linear part of the equations of motion, integrated exactly by
//! [`crate::vehicle::time::exponential_rk4`]: a few linear springs far stiffer than the rest of the vehicle.
//!
//! Why: the gearbox bearings hold the hollow shaft in the motor's gearbox with 2·10⁹ N/m axially
//! and 4·10⁸ N·m/rad in tilt; against the hollow shaft's small roll and yaw inertias (120 kg·m²)
//! these make modes at 230–330 Hz, and RK4's stability limit (ω·h ≤ 2√2) holds every run to
//! steps under 1.4 ms, although nothing the study measures moves faster than ≈ 40 Hz and the rest
//! of the vehicle (wheelsets on their Hertz contact included) is stable with 2 ms. The springs
//! are linear in the coordinates: `z = J q` are their deflections (m, rad), `K` their stiffnesses
//! (N/m, N·m/rad), their generalized force is `−Jᵀ K z`, and with the constant mass matrix the
//! accelerations they cause are `−B z`, `B = M⁻¹ Jᵀ K`. Their motion is a small linear system,
//! `z̈ = −J B z + J q̈_rest`, whose exact solution under a forcing polynomial in time is one
//! matrix exponential per step length, computed once per run.

use crate::util::kept::Kept;
use crate::vehicle::model::layout::N_DOF;
use crate::vehicle::model::mass::MassMatrix;
use crate::vehicle::model::structure::VehicleStructure;
use crate::vehicle::model::suspension::GEARBOX_BEARINGS;
use crate::vehicle::time::row_groups::{LaneRows, RowGroups, Sparse};
use nalgebra::DMatrix;

/// Linear springs on coordinate combinations `z = J q` with a constant mass matrix.
#[derive(Debug, Clone)]
pub struct StiffLinearPart {
    /// Number of coordinates `q` (the state is `[q | q̇ | other states]`).
    n_dof: usize,
    /// Rows of `J`: deflection per coordinate (m/m, m/rad, rad/rad).
    rows: Vec<Sparse>,
    /// The same rows in lanes, for [`Self::deflections`].
    row_lanes: LaneRows,
    /// Columns of `B = M⁻¹ Jᵀ K`: acceleration per unit deflection, 1/s² (or m/(s²·rad)).
    response: Vec<Sparse>,
    /// Columns of `G = B (J B)⁻¹`: with it `P = G J` projects a motion onto the part that
    /// deflects the springs (`J P = J`, `P B = B`); the rest, `(I − P) q`, deflects none and
    /// feels no force of theirs.
    projection: Vec<Sparse>,
    /// One more than the largest output index of `response` and `projection`: the length
    /// their outputs must have, checked once per call instead of at every term (the terms'
    /// bounds checks were a fifth of the scheme's own work).
    min_len: usize,
    /// `J B`, the deflections' own stiffness over mass (r×r), 1/s².
    own: DMatrix<f64>,
    /// `(J B)⁻¹`, s².
    own_inverse: DMatrix<f64>,
}

/// The exact solution of the stiff part over a time `tau` under a forcing polynomial in time:
/// `[∫z; Y](τ)` from `[z0; ż0; h0; h1; h2]`, where the deflections' forcing is
/// `h(t) = h0 + h1·t + h2·t²/2` (the rest of the accelerations seen through `J`) and
/// `Y = (J B)⁻¹ ∫₀^τ ż dt' − ∫∫z`, what the springs' part adds to the coordinates through `B`
/// (`P ∫ q̇ = G ∫ ż`, the springs' accelerations `−B ∫∫z`).
#[derive(Debug, Clone)]
pub struct Propagator {
    /// Time the propagator covers, s.
    pub tau: f64,
    /// The (2r × 5r) map by rows, its zeros left out (the bearings of different wheelsets do not
    /// meet in the mass matrix, and the exponential keeps the blocks apart exactly), grouped by
    /// their columns (a wheelset's rows read the same inputs).
    rows: RowGroups,
}

impl StiffLinearPart {
    /// The part made of the springs `rows` (rows of `J` over `n_dof` coordinates) with
    /// `stiffness` (N/m or N·m/rad each), for the mass matrix whose solve is `solve`.
    pub fn new(
        n_dof: usize,
        rows: Vec<Sparse>,
        stiffness: &[f64],
        solve: impl Fn(&[f64], &mut [f64]),
    ) -> Self {
        let r = rows.len();
        let mut response = Vec::with_capacity(r);
        let mut force = vec![0.0; n_dof];
        let mut column = vec![0.0; n_dof];
        for (row, k) in rows.iter().zip(stiffness) {
            force.fill(0.0);
            for &(j, c) in row {
                force[j] += c * k;
            }
            solve(&force, &mut column);
            response.push(sparse(&column));
        }
        let own = DMatrix::from_fn(r, r, |i, j| dot_sparse(&rows[i], &response[j]));
        // Independent deflections of springs with positive stiffness and a positive definite
        // mass matrix make `J M⁻¹ Jᵀ K` invertible.
        let own_inverse = own
            .clone()
            .try_inverse()
            .expect("the stiff springs' deflections are independent");
        let projection = (0..r)
            .map(|c| {
                let mut column = vec![0.0; n_dof];
                for (k, b) in response.iter().enumerate() {
                    for &(i, v) in b {
                        column[i] += v * own_inverse[(k, c)];
                    }
                }
                sparse(&column)
            })
            .collect::<Vec<Sparse>>();
        let min_len = response
            .iter()
            .chain(&projection)
            .flatten()
            .map(|&(i, _)| i + 1)
            .max()
            .unwrap_or(0);
        Self {
            min_len,
            n_dof,
            row_lanes: LaneRows::new(&rows),
            rows,
            response,
            projection,
            own,
            own_inverse,
        }
    }

    /// Number of stiff deflections `r`.
    pub fn len(&self) -> usize {
        self.rows.len()
    }

    /// Whether there are none.
    pub fn is_empty(&self) -> bool {
        self.rows.is_empty()
    }

    /// Angular frequencies of the springs on their own (rad/s, ascending): `√λ` of `J B`, the
    /// modes of the deflections with everything else free, which the exact solution covers.
    pub fn frequencies(&self) -> Vec<f64> {
        let mut omega: Vec<f64> = self
            .own
            .complex_eigenvalues()
            .iter()
            .map(|l| l.re.max(0.0).sqrt())
            .collect();
        omega.sort_by(f64::total_cmp);
        omega
    }

    /// Number of coordinates.
    pub fn n_dof(&self) -> usize {
        self.n_dof
    }

    /// `out = J x` (r values) for coordinates (or velocities, or accelerations) `x`.
    #[inline]
    pub fn deflections(&self, x: &[f64], out: &mut [f64]) {
        self.row_lanes.apply(x, out);
    }

    /// `out += scale · B z` (accelerations, 1/s² times the deflections' units).
    #[inline]
    pub fn add_response(&self, z: &[f64], scale: f64, out: &mut [f64]) {
        add_columns(&self.response, self.min_len, z, scale, out);
    }

    /// `out += scale · G u`: the motion (or velocity) in the springs' part that has the
    /// deflections (or rates) `u`.
    #[inline]
    pub fn add_projection(&self, u: &[f64], scale: f64, out: &mut [f64]) {
        add_columns(&self.projection, self.min_len, u, scale, out);
    }

    /// `Jᵀ K J` (N/m, N·m/rad; n_dof × n_dof): the part's stiffness in the coordinates, which
    /// the stable-step check takes out of the Jacobian. From `M B = Jᵀ K`: `Jᵀ K J = M B J`.
    pub fn stiffness_matrix(&self, mass: &MassMatrix) -> DMatrix<f64> {
        let n = self.n_dof;
        let mut b = DMatrix::zeros(n, self.len());
        for (c, column) in self.response.iter().enumerate() {
            for &(i, v) in column {
                b[(i, c)] = v;
            }
        }
        let mut j = DMatrix::zeros(self.len(), n);
        for (r, row) in self.rows.iter().enumerate() {
            for &(k, c) in row {
                j[(r, k)] += c;
            }
        }
        let m = DMatrix::from_fn(n, n, |i, k| mass.get(i, k));
        m * b * j
    }

    /// The exact propagator over `tau` (s): the matrix exponential of the deflections' system
    /// augmented with their integrals and the forcing polynomial (Van Loan, IEEE Trans.
    /// Automatic Control 23, 1978: integrals of matrix exponentials as one larger exponential).
    /// The blocks are scaled to the time `tau` first (`ż·τ`, `∫z/τ`, `h·τ²`, ...), so that
    /// all entries of the exponentiated matrix are of order (ω·τ)² at most.
    ///
    /// Kept for reuse ([`crate::util::kept`]): a batch's samples share the bearings and the mass
    /// matrix, and the exponentials cost 1.2 % of a 500 m run.
    pub fn propagator(&self, tau: f64) -> Propagator {
        static KEPT: Kept<Propagator> = Kept::new(8);
        let key = format!("{:?} {:?} {tau:?}", self.own, self.own_inverse);
        (*KEPT.get_or_build(key, || self.build_propagator(tau))).clone()
    }

    fn build_propagator(&self, tau: f64) -> Propagator {
        let r = self.len();
        // Blocks: 0 z, 1 ż, 2 ∫z, 3 ∫∫z, 4 h, 5 ḣ, 6 ḧ; scale σ_b (scaled block = σ_b · block).
        let sigma = [
            1.0,
            tau,
            1.0 / tau,
            1.0 / (tau * tau),
            tau * tau,
            tau.powi(3),
            tau.powi(4),
        ];
        // d(σ_to x_to)/ds = τ · σ_to/σ_from · (σ_from x_from) for each term x_to' = c·x_from.
        let mut a = DMatrix::zeros(7 * r, 7 * r);
        let identity = |to: usize, from: usize, a: &mut DMatrix<f64>| {
            let f = tau * sigma[to] / sigma[from];
            for i in 0..r {
                a[(to * r + i, from * r + i)] = f;
            }
        };
        identity(0, 1, &mut a);
        identity(1, 4, &mut a);
        identity(2, 0, &mut a);
        identity(3, 2, &mut a);
        identity(4, 5, &mut a);
        identity(5, 6, &mut a);
        let f = tau * sigma[1] / sigma[0];
        for i in 0..r {
            for j in 0..r {
                a[(r + i, j)] = -f * self.own[(i, j)];
            }
        }
        let phi = a.exp();
        let (out_blocks, in_blocks) = ([2, 3], [0, 1, 4, 5, 6]);
        let mut map = DMatrix::from_fn(2 * r, 5 * r, |i, j| {
            let (bo, bi) = (out_blocks[i / r], in_blocks[j / r]);
            phi[(bo * r + i % r, bi * r + j % r)] * sigma[bi] / sigma[bo]
        });
        // Y = (J B)⁻¹ (τ ż0 + τ²/2 h0 + τ³/6 h1 + τ⁴/24 h2) − ∫∫z.
        let weights = [
            0.0,
            tau,
            tau.powi(2) / 2.0,
            tau.powi(3) / 6.0,
            tau.powi(4) / 24.0,
        ];
        for i in 0..r {
            for j in 0..5 * r {
                map[(r + i, j)] *= -1.0;
                map[(r + i, j)] += weights[j / r] * self.own_inverse[(i, j % r)];
            }
        }
        let rows: Vec<Sparse> = (0..2 * r)
            .map(|i| sparse(&map.row(i).iter().copied().collect::<Vec<_>>()))
            .collect();
        Propagator {
            tau,
            rows: RowGroups::new(&rows),
        }
    }
}

impl Propagator {
    /// `out = [∫z; Y](τ)` (2r) from `input = [z0; ż0; h0; h1; h2]` (5r).
    #[inline]
    pub fn apply(&self, input: &[f64], out: &mut [f64]) {
        self.rows.apply(input, out);
    }
}

/// The non-zero entries of `x`.
fn sparse(x: &[f64]) -> Sparse {
    x.iter()
        .enumerate()
        .filter(|(_, v)| **v != 0.0)
        .map(|(i, v)| (i, *v))
        .collect()
}

/// `out += scale · Σ_c columns[c] · x[c]`; every output index of `columns` is below `min_len`.
#[inline]
fn add_columns(columns: &[Sparse], min_len: usize, x: &[f64], scale: f64, out: &mut [f64]) {
    assert!(
        out.len() >= min_len,
        "StiffLinearPart: output shorter than its columns"
    );
    for (column, &xc) in columns.iter().zip(x) {
        let s = scale * xc;
        for &(i, b) in column {
            out[i] += b * s;
        }
    }
}

fn dot_sparse(row: &Sparse, column: &Sparse) -> f64 {
    let mut s = 0.0;
    for &(j, c) in row {
        if let Some(&(_, b)) = column.iter().find(|(i, _)| *i == j) {
            s += c * b;
        }
    }
    s
}

/// The gearbox bearings' axial and tilting stiffness (roll and yaw of the hollow shaft in the
/// motor), the vehicle's stiffest springs. Their radial stiffness is in series with the soft
/// six-link coupling and stays with the rest; so do the corotational and preload terms of the
/// bearings, which are products of small motions and the bearings' static load.
pub fn gearbox_bearings(structure: &VehicleStructure) -> StiffLinearPart {
    let mut rows = Vec::new();
    let mut stiffness = Vec::new();
    for bearing in structure
        .suspension
        .bushings
        .iter()
        .filter(|b| b.name.starts_with(GEARBOX_BEARINGS))
    {
        // Deflection of B against A per coordinate: axial displacement, relative roll and yaw.
        let mut deflection: [Sparse; 3] = Default::default();
        for (j, motion) in structure.relative_motion_per_coordinate(&bearing.at) {
            for (k, value) in [motion[1], motion[3], motion[5]].into_iter().enumerate() {
                if value != 0.0 {
                    deflection[k].push((j, value));
                }
            }
        }
        let k = [
            bearing.stiffness[1],
            bearing.rotational_stiffness[0],
            bearing.rotational_stiffness[2],
        ];
        for (row, k) in deflection.into_iter().zip(k) {
            if k > 0.0 && !row.is_empty() {
                rows.push(row);
                stiffness.push(k);
            }
        }
    }
    let mass = &structure.mass;
    StiffLinearPart::new(N_DOF, rows, &stiffness, |rhs, x| mass.solve(rhs, x))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn unchecked_columns_give_the_bits_of_the_indexed_ones() {
        // Two springs over four coordinates with masses 1..4 kg.
        let rows = vec![vec![(0, 1.0), (1, -1.0)], vec![(1, 0.5), (3, -2.0)]];
        let part = StiffLinearPart::new(4, rows, &[3e6, 7e5], |rhs, x| {
            for (i, (x, r)) in x.iter_mut().zip(rhs).enumerate() {
                *x = r / (i + 1) as f64;
            }
        });
        let z = [1.3e-4, -2.9e-5];
        for scale in [1.0, -1.0] {
            let start: Vec<f64> = (0..4).map(|i| (i as f64 * 0.7).sin()).collect();
            let (mut response, mut projection) = (start.clone(), start.clone());
            part.add_response(&z, scale, &mut response);
            part.add_projection(&z, scale, &mut projection);
            for (columns, out) in [(&part.response, response), (&part.projection, projection)] {
                let mut expected = start.clone();
                for (column, &xc) in columns.iter().zip(&z) {
                    let s = scale * xc;
                    for &(i, b) in column {
                        expected[i] += b * s;
                    }
                }
                assert_eq!(
                    out.iter().map(|v| v.to_bits()).collect::<Vec<_>>(),
                    expected.iter().map(|v| v.to_bits()).collect::<Vec<_>>()
                );
            }
        }
        // An output that stops short of the columns is refused, not written past.
        let short = std::panic::catch_unwind(|| part.add_response(&z, 1.0, &mut [0.0; 3]));
        assert!(short.is_err());
    }
}

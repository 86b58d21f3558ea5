//! The constant mass matrix `M = Σ Tᵀ M_b T` and its block Cholesky factorisation.
//!
//! With small-motion kinematics `M` does not depend on the state, so it is factorised once. Bodies
//! defined relative to a parent couple only within their family (wheelset + hollow shaft + arms,
//! carbody + traction rods), so `M` is block diagonal after grouping coordinates that share a
//! non-zero entry; each block is factorised on its own and `M q̈ = Q` costs a few hundred flops.

use crate::error::{LocoError, Result};
use crate::vehicle::model::kinematics::MotionMap;
use crate::vehicle::model::layout::N_DOF;

/// One diagonal block of `M`: its coordinates and the lower Cholesky factor (row-major n×n).
#[derive(Debug, Clone)]
struct Block {
    dofs: Vec<usize>,
    factor: Vec<f64>,
    /// The factor's transpose (row-major), so that the back substitution reads rows too.
    upper: Vec<f64>,
}

/// The mass matrix (kg, kg·m, kg·m²), dense for inspection and factorised by blocks for solving.
#[derive(Debug, Clone)]
pub struct MassMatrix {
    dense: Vec<f64>,
    blocks: Vec<Block>,
    /// The blocks as the solve takes them: most coordinates are coupled to no other (70 of the
    /// 90) or to one other (12 pairs), and one loop over all blocks spent more on walking them
    /// than on their divisions.
    solver: BlockSolver,
}

/// The blocks of one, two and more coordinates, each kind in its own list.
#[derive(Debug, Clone)]
struct BlockSolver {
    /// The 1×1 blocks in runs of consecutive coordinates: (first coordinate, count), their
    /// factors one run after the other in `single_factors`. A run's divisions are independent
    /// and contiguous, so they go two per instruction: one at a time, the divider set the pace
    /// (nearly half the solve's samples).
    single_runs: Vec<(usize, usize)>,
    single_factors: Vec<f64>,
    /// The 2×2 blocks: coordinates and factor `[l00, l10, l11]`.
    pairs: Vec<([usize; 2], [f64; 3])>,
    /// The larger blocks.
    larger: Vec<Block>,
}

impl BlockSolver {
    fn new(blocks: &[Block]) -> Self {
        // `solve`'s unchecked accesses rest on this.
        assert!(blocks.iter().flat_map(|b| &b.dofs).all(|&d| d < N_DOF));
        let mut solver = Self {
            single_runs: Vec::new(),
            single_factors: Vec::new(),
            pairs: Vec::new(),
            larger: Vec::new(),
        };
        // Each block writes only its own coordinates: the order they are solved in is free.
        let mut single = Vec::new();
        for block in blocks {
            let l = &block.factor;
            match block.dofs[..] {
                [d] => single.push((d, l[0])),
                [d0, d1] => solver.pairs.push(([d0, d1], [l[0], l[2], l[3]])),
                _ => solver.larger.push(block.clone()),
            }
        }
        single.sort_unstable_by_key(|&(d, _)| d);
        for (d, l) in single {
            match solver.single_runs.last_mut() {
                Some((first, count)) if *first + *count == d => *count += 1,
                _ => solver.single_runs.push((d, 1)),
            }
            solver.single_factors.push(l);
        }
        solver
    }
}

impl MassMatrix {
    /// Assembles `Σ Tᵀ diag(m, m, m, Ixx, Iyy, Izz) T` from body maps and mass properties
    /// (`mass` in kg, `inertia` in kg·m² about the centre of gravity, vehicle axes).
    pub fn assemble(bodies: &[(&MotionMap, f64, [f64; 3])]) -> Result<Self> {
        let mut dense = vec![0.0; N_DOF * N_DOF];
        for (map, mass, inertia) in bodies {
            let diag = [*mass, *mass, *mass, inertia[0], inertia[1], inertia[2]];
            for (k, row) in map.rows().iter().enumerate() {
                for &(i, ci) in row {
                    for &(j, cj) in row {
                        dense[i * N_DOF + j] += diag[k] * ci * cj;
                    }
                }
            }
        }
        let blocks = factor_blocks(&dense)?;
        let solver = BlockSolver::new(&blocks);
        Ok(Self {
            dense,
            blocks,
            solver,
        })
    }

    /// Entry (i, j).
    pub fn get(&self, i: usize, j: usize) -> f64 {
        self.dense[i * N_DOF + j]
    }

    /// Solves `M x = rhs` (x in the units of acceleration for a force `rhs`).
    pub fn solve(&self, rhs: &[f64], x: &mut [f64]) {
        // The blocks are independent: each writes its own coordinates.
        let solver = &self.solver;
        // The 1×1 and 2×2 blocks' coordinates are below N_DOF (`BlockSolver::new`): one
        // length check here instead of one per access (a fifth of the solve's instructions).
        assert!(
            rhs.len() >= N_DOF && x.len() >= N_DOF,
            "MassMatrix::solve: short vectors"
        );
        let mut factors = &solver.single_factors[..];
        for &(first, count) in &solver.single_runs {
            let (l, rest) = factors.split_at(count);
            factors = rest;
            let range = first..first + count;
            for ((x, b), l) in x[range.clone()].iter_mut().zip(&rhs[range]).zip(l) {
                // A coordinate coupled to no other: the substitutions below in one line.
                *x = b / l / l;
            }
        }
        let get = |d: usize| rhs[d];
        let mut set = |d: usize, v: f64| x[d] = v;
        for &([d0, d1], [l00, l10, l11]) in &solver.pairs {
            // The substitutions below for n = 2, the same operations in the same order.
            let w0 = get(d0) / l00;
            let w1 = (get(d1) - l10 * w0) / l11;
            let w1 = w1 / l11;
            set(d0, (w0 - l10 * w1) / l00);
            set(d1, w1);
        }
        let mut work = [0.0; N_DOF];
        for block in &solver.larger {
            let n = block.dofs.len();
            let (l, u) = (&block.factor, &block.upper);
            let work = &mut work[..n];
            // Forward substitution L y = b, then back substitution Lᵀ x = y, each sum taken in
            // the order of increasing k.
            for i in 0..n {
                let row = &l[i * n..i * n + i];
                let mut s = rhs[block.dofs[i]];
                for (lik, wk) in row.iter().zip(&work[..i]) {
                    s -= lik * wk;
                }
                work[i] = s / l[i * n + i];
            }
            for i in (0..n).rev() {
                let row = &u[i * n + i + 1..i * n + n];
                let mut s = work[i];
                for (uik, wk) in row.iter().zip(&work[i + 1..]) {
                    s -= uik * wk;
                }
                work[i] = s / l[i * n + i];
            }
            for (&d, w) in block.dofs.iter().zip(work.iter()) {
                x[d] = *w;
            }
        }
    }

    /// Sizes of the diagonal blocks (for documentation and tests).
    pub fn block_sizes(&self) -> Vec<usize> {
        self.blocks.iter().map(|b| b.dofs.len()).collect()
    }
}

/// Groups coordinates into connected components of the sparsity pattern and factorises each.
fn factor_blocks(dense: &[f64]) -> Result<Vec<Block>> {
    let mut group: Vec<usize> = (0..N_DOF).collect();
    fn root(group: &mut [usize], mut i: usize) -> usize {
        while group[i] != i {
            group[i] = group[group[i]];
            i = group[i];
        }
        i
    }
    for i in 0..N_DOF {
        for j in 0..i {
            if dense[i * N_DOF + j] != 0.0 {
                let (a, b) = (root(&mut group, i), root(&mut group, j));
                group[a.max(b)] = a.min(b);
            }
        }
    }
    let mut members: Vec<Vec<usize>> = vec![Vec::new(); N_DOF];
    for i in 0..N_DOF {
        let r = root(&mut group, i);
        members[r].push(i);
    }
    let mut blocks = Vec::new();
    for dofs in members.into_iter().filter(|m| !m.is_empty()) {
        let n = dofs.len();
        let mut l = vec![0.0; n * n];
        for i in 0..n {
            for j in 0..=i {
                let mut s = dense[dofs[i] * N_DOF + dofs[j]];
                for k in 0..j {
                    s -= l[i * n + k] * l[j * n + k];
                }
                if i == j {
                    if s <= 0.0 || !s.is_finite() {
                        return Err(LocoError::param(
                            format!("mass matrix (coordinate {})", dofs[i]),
                            "not positive definite: a body has a non-positive mass or inertia",
                        ));
                    }
                    l[i * n + i] = s.sqrt();
                } else {
                    l[i * n + j] = s / l[j * n + j];
                }
            }
        }
        let upper = (0..n * n).map(|ij| l[(ij % n) * n + ij / n]).collect();
        blocks.push(Block {
            dofs,
            factor: l,
            upper,
        });
    }
    Ok(blocks)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::vehicle::model::structure::VehicleStructure;
    use crate::vehicle::params::parameters::ParameterSet;

    /// The solve as one loop over every block, the general substitutions (before the blocks
    /// were split by size).
    fn solve_by_blocks(m: &MassMatrix, rhs: &[f64], x: &mut [f64]) {
        for block in &m.blocks {
            let n = block.dofs.len();
            let (l, u) = (&block.factor, &block.upper);
            let mut work = vec![0.0; n];
            for i in 0..n {
                let mut s = rhs[block.dofs[i]];
                for k in 0..i {
                    s -= l[i * n + k] * work[k];
                }
                work[i] = s / l[i * n + i];
            }
            for i in (0..n).rev() {
                let mut s = work[i];
                for k in i + 1..n {
                    s -= u[i * n + k] * work[k];
                }
                work[i] = s / l[i * n + i];
            }
            for (&d, w) in block.dofs.iter().zip(&work) {
                x[d] = *w;
            }
        }
    }

    #[test]
    fn the_split_solve_gives_the_bits_of_the_block_loop() {
        let mass = VehicleStructure::new(ParameterSet::default_vehicle())
            .unwrap()
            .mass;
        let sizes = mass.block_sizes();
        assert!(sizes.contains(&1) && sizes.contains(&2) && sizes.iter().any(|&n| n > 2));
        for seed in [0.0, 0.9] {
            let rhs: Vec<f64> = (0..N_DOF)
                .map(|i| match i % 9 {
                    0 => 0.0,
                    4 => -0.0,
                    _ => 1e4 * (seed + i as f64 * 0.77).sin(),
                })
                .collect();
            let (mut x, mut expected) = (vec![f64::NAN; N_DOF], vec![f64::NAN; N_DOF]);
            mass.solve(&rhs, &mut x);
            solve_by_blocks(&mass, &rhs, &mut expected);
            let bits = |v: &[f64]| v.iter().map(|x| x.to_bits()).collect::<Vec<_>>();
            assert_eq!(bits(&x), bits(&expected));
        }
    }
}

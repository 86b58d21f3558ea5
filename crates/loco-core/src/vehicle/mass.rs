//! The constant mass matrix `M = Σ Tᵀ M_b T` and its block Cholesky factorisation.
//!
//! With small-motion kinematics `M` does not depend on the state, so it is factorised once. Bodies
//! defined relative to a parent couple only within their family (wheelset + hollow shaft + arms,
//! carbody + traction rods), so `M` is block diagonal after grouping coordinates that share a
//! non-zero entry; each block is factorised on its own and `M q̈ = Q` costs a few hundred flops.

use super::kinematics::MotionMap;
use super::layout::N_DOF;
use crate::error::{LocoError, Result};

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
        Ok(Self { dense, blocks })
    }

    /// Entry (i, j).
    pub fn get(&self, i: usize, j: usize) -> f64 {
        self.dense[i * N_DOF + j]
    }

    /// Solves `M x = rhs` (x in the units of acceleration for a force `rhs`).
    pub fn solve(&self, rhs: &[f64], x: &mut [f64]) {
        let mut work = [0.0; N_DOF];
        for block in &self.blocks {
            let n = block.dofs.len();
            let (l, u) = (&block.factor, &block.upper);
            if n == 1 {
                // A coordinate coupled to no other: the substitutions below in one line.
                x[block.dofs[0]] = rhs[block.dofs[0]] / l[0] / l[0];
                continue;
            }
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

//! One contact problem for every algorithm: the bodies' linear system, the pair rows, the gaps.
//!
//! ```text
//! K_ff u_f = w r + B_Nᵀ λ + B_Tᵀ τ          (r: right-hand side of the load pattern, w: load factor)
//! gap_k(u) = g0_k + (B_N u)_k ≥ 0,  λ_k ≥ 0,  λ_k gap_k = 0
//! (B_N u)_k = n_k · (u_master − Σ_j N_j u_slave_j),   (B_T u)_k likewise with t_k
//! ```
//!
//! `λ_k` is the normal force on the master node (along `n_k`, compressive when positive); the
//! slave nodes carry `−N_j λ_k n_k`. Rows are split into their free and constrained parts, so a
//! prescribed displacement (the pulled edge) enters the gap as `w (B_N,c u_c)`.

use std::sync::{Arc, OnceLock};

use contact2d_fem::{CholeskySolver, ElementMatrices, LinearSystem, Model, assemble};

use crate::error::ContactError;
pub use crate::pair_rows::{PairRow, SparseRow, condensed_rows};
use crate::pair_rows::{SlaveKind, has_free_part, pair_rows, point_tangent_moves};
use crate::pairing::ContactPair;
use crate::stiffness_factor::StiffnessFactor;

/// The discrete contact problem shared by all algorithms.
#[derive(Debug, Clone)]
pub struct ContactProblem {
    /// The finite-element model (bodies, Dirichlet pattern).
    pub model: Model,
    /// Its assembled system, shared by the copies of the problem (a load step's copy of the
    /// problem changes its loads, never `K`: at 952k DOFs `K` alone is 0.24 GB).
    pub system: Arc<LinearSystem>,
    /// Factorisation of `K_ff` bordered by the pair rows ([`condensed_rows`]), computed once:
    /// solves with `K_ff` and the compliance `C = B K⁻¹ Bᵀ`. Beyond
    /// [`crate::linear::SPARSE_FROM_PAIRS`] pairs `K_ff`'s own, made at the first solve that
    /// needs it ([`ContactProblem::solver`]).
    factor: StiffnessFactor,
    /// The pairs.
    pub pairs: Vec<ContactPair>,
    /// Normal rows `B_N`.
    pub normal_rows: Vec<PairRow>,
    /// Tangential rows `B_T`.
    pub tangent_rows: Vec<PairRow>,
    /// Initial gaps `g0` (geometric by default, replaceable).
    pub gap: Vec<f64>,
    /// Friction coefficient per pair (0 = frictionless).
    pub friction: Vec<f64>,
    /// Whether a pair has a tangential unknown: false where its tangential row has no free DOF
    /// (e.g. at a symmetry end point, where the tangent lies along a Dirichlet direction and a
    /// tangential condition would duplicate it; spec §8), and for a segment-to-segment pair also
    /// where the master node's own tangential motion against its closest slave point is held by
    /// fixes (the node-to-segment row of the node has no free DOF): its integrated row then
    /// reaches free DOFs only through the neighbours' shape functions, nearly a copy of their
    /// rows, and a multiplier there carries a shear that symmetry forbids (±25 MPa flipping
    /// sign with the step count, issue 27 item 7).
    pub tangential: Vec<bool>,
    /// Whether a pair has a normal unknown: false where its normal row has no free DOF (a
    /// master node held along the normal by a fix, against a rigid or likewise held slave).
    /// Its gap is then fixed by the prescribed values whatever λ is, a contact force could only
    /// move load between the fix and the contact: the fix holds the node (λ = 0, the force is
    /// in the reaction) and the pair takes no part in the contact conditions.
    pub normal: Vec<bool>,
    /// Right-hand side of the load the algorithms scale by `w`, `r = f_f − K_fc u_c`: the
    /// model's own values, or the combination of [`ContactProblem::patterns`] set by
    /// [`ContactProblem::apply_load`].
    pub pattern_rhs: Vec<f64>,
    /// Constrained values of that load (the model's prescribed values, or the combination).
    pub pattern_prescribed: Vec<f64>,
    /// The named load patterns (at least one; by default `main`, the model's own values).
    patterns: Vec<LoadPattern>,
    /// The largest diagonal entry of `K_ff`: a stiffness scale for judging round-off forces.
    pub stiffness_scale: f64,
    /// Per pair: whether its slave side deforms or is a rigid obstacle.
    slave: Vec<SlaveKind>,
    /// Wall time of assembly (with pairing rows) and of ordering plus factorisation, when built.
    pub build_times: BuildTimes,
    /// Whether `factor` was factored bordered by the pair rows (false above
    /// [`crate::linear::SPARSE_FROM_PAIRS`] pairs: `K` alone, [`ContactProblem::is_bordered`]).
    bordered: bool,
    /// This problem's element matrices, kept by the first [`ContactProblem::rebuild_moved`] for
    /// the next (the moved meshes' unmoved cells reuse them).
    element_matrices: OnceLock<Arc<ElementMatrices>>,
}

/// Where a problem's set-up time went.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct BuildTimes {
    /// Assembly of the stiffness and loads, and the pair rows.
    pub assemble: std::time::Duration,
    /// Fill-reducing ordering and Cholesky factorisation.
    pub factor: std::time::Duration,
}

impl ContactProblem {
    /// Assembles and factors `model` and builds the rows of `pairs` (frictionless, geometric gaps).
    ///
    /// # Errors
    /// From assembly/factorisation, or a pair whose nodes have no DOFs.
    pub fn new(model: Model, pairs: Vec<ContactPair>) -> Result<ContactProblem, ContactError> {
        let slave = vec![SlaveKind::Deformable; pairs.len()];
        ContactProblem::build(model, pairs, slave)
    }

    /// Like [`ContactProblem::new`], with a rigid slave (a fixed obstacle whose nodes belong to
    /// no body) for the pairs where `rigid_slave[k]` is true: pairs of several interfaces, some
    /// against deformable bodies and some against obstacles.
    ///
    /// # Errors
    /// As [`ContactProblem::new`], a length mismatch, or a rigid slave node that belongs to a
    /// body.
    pub fn with_slave_kinds(
        model: Model,
        pairs: Vec<ContactPair>,
        rigid_slave: &[bool],
    ) -> Result<ContactProblem, ContactError> {
        if rigid_slave.len() != pairs.len() {
            return Err(ContactError::InvalidInput(format!(
                "{} slave kinds given for {} pairs",
                rigid_slave.len(),
                pairs.len()
            )));
        }
        let slave = rigid_slave.iter().map(|r| if *r { SlaveKind::Rigid } else { SlaveKind::Deformable }).collect();
        ContactProblem::build(model, pairs, slave)
    }

    /// Like [`ContactProblem::new`], with the slave contour a rigid, fixed obstacle: its nodes
    /// belong to no body and do not move (exact, not a large modulus).
    ///
    /// # Errors
    /// As [`ContactProblem::new`], or a slave node that belongs to a body.
    pub fn with_rigid_slave(model: Model, pairs: Vec<ContactPair>) -> Result<ContactProblem, ContactError> {
        let slave = vec![SlaveKind::Rigid; pairs.len()];
        ContactProblem::build(model, pairs, slave)
    }

    fn build(model: Model, pairs: Vec<ContactPair>, slave: Vec<SlaveKind>) -> Result<ContactProblem, ContactError> {
        let clock = web_time::Instant::now();
        let system = assemble(&model)?;
        let (normal_rows, tangent_rows) = pair_rows(&system, &pairs, &slave)?;
        let assembled = clock.elapsed();
        let (solver, bordered) = factor_stiffness(&system, &normal_rows, &tangent_rows, None)?;
        let friction = vec![0.0; pairs.len()];
        let (system, factor) = shared(system, solver);
        let mut problem =
            ContactProblem::assemble_parts(model, system, factor, pairs, normal_rows, tangent_rows, friction, slave);
        problem.bordered = bordered;
        problem.build_times = BuildTimes { assemble: assembled, factor: clock.elapsed() - assembled };
        Ok(problem)
    }

    /// The same problem on a moved mesh with the same topology: `model` must have the same DOF
    /// numbering and stiffness sparsity pattern as `self.model` (e.g. the nodes moved by mesh
    /// morphing); the symbolic factorisation (ordering, elimination tree, supernodes) is reused
    /// and only the numeric factorisation is redone. Gaps are the new pairs' geometric gaps; the
    /// friction coefficients are kept (when the number of pairs is unchanged; else μ = 0); the
    /// slave side stays deformable or rigid as in `self`. `K` and the new pair rows are
    /// refactored together (numerically only, while the bordered sparsity pattern is the same).
    /// The element matrices of the cells whose nodes did not move are `self`'s (kept from the
    /// first call: [`ElementMatrices`]); the system is bit for bit that of assembling anew.
    ///
    /// # Errors
    /// From assembly or factorisation; [`ContactError::InvalidInput`] if the DOF numbering or
    /// the sparsity pattern differs.
    pub fn rebuild_moved(&self, model: Model, pairs: Vec<ContactPair>) -> Result<ContactProblem, ContactError> {
        let matrices = match self.element_matrices.get() {
            Some(m) => Arc::clone(m),
            None => {
                let m = Arc::new(ElementMatrices::new(&self.model, &self.system)?);
                Arc::clone(self.element_matrices.get_or_init(|| m))
            }
        };
        let system = matrices.assemble_moved(&model)?;
        if system.dofs != self.system.dofs {
            return Err(ContactError::InvalidInput("rebuild_moved: the DOF numbering differs".into()));
        }
        let (old, new) = (self.system.stiffness.symbolic(), system.stiffness.symbolic());
        if old.col_ptr() != new.col_ptr() || old.row_idx() != new.row_idx() {
            return Err(ContactError::InvalidInput("rebuild_moved: the stiffness sparsity pattern differs".into()));
        }
        let slave = if pairs.len() == self.slave.len() {
            self.slave.clone()
        } else {
            vec![self.slave.first().copied().unwrap_or(SlaveKind::Deformable); pairs.len()]
        };
        let (normal_rows, tangent_rows) = pair_rows(&system, &pairs, &slave)?;
        let (solver, bordered) = factor_stiffness(&system, &normal_rows, &tangent_rows, self.factor.if_made())?;
        let friction = if pairs.len() == self.friction.len() { self.friction.clone() } else { vec![0.0; pairs.len()] };
        let (system, factor) = shared(system, solver);
        let mut problem =
            ContactProblem::assemble_parts(model, system, factor, pairs, normal_rows, tangent_rows, friction, slave);
        problem.bordered = bordered;
        Ok(problem)
    }

    /// The same bodies, load patterns, friction and slave kinds with new `pairs` (one per pair
    /// of `self`, in the same order): finite sliding's pairs on the current configuration
    /// ([`crate::finite_sliding`]). `K` is not assembled again; the pair rows are built and,
    /// up to [`crate::linear::SPARSE_FROM_PAIRS`] pairs, `K` is factored bordered by them afresh
    /// (their sparsity changes as pairs change segment); beyond, `K`'s own factor is reused.
    ///
    /// # Errors
    /// A number of pairs other than `self`'s, or the rows' factorisation failing.
    pub(crate) fn with_pairs(&self, pairs: Vec<ContactPair>) -> Result<ContactProblem, ContactError> {
        if pairs.len() != self.pairs.len() {
            return Err(ContactError::InvalidInput(format!(
                "{} pairs given for a problem of {} pairs",
                pairs.len(),
                self.pairs.len()
            )));
        }
        let (normal_rows, tangent_rows) = pair_rows(&self.system, &pairs, &self.slave)?;
        let (factor, bordered) = if normal_rows.len() >= crate::linear::SPARSE_FROM_PAIRS {
            (self.factor.clone(), false)
        } else {
            let (solver, bordered) = factor_stiffness(&self.system, &normal_rows, &tangent_rows, None)?;
            (factor_of(Arc::clone(&self.system), solver), bordered)
        };
        let (model, system, friction, slave) =
            (self.model.clone(), Arc::clone(&self.system), self.friction.clone(), self.slave.clone());
        let mut problem =
            ContactProblem::assemble_parts(model, system, factor, pairs, normal_rows, tangent_rows, friction, slave);
        problem.bordered = bordered;
        problem.patterns = self.patterns.clone();
        problem.pattern_rhs = self.pattern_rhs.clone();
        problem.pattern_prescribed = self.pattern_prescribed.clone();
        Ok(problem)
    }

    /// `K_ff`'s factor: bordered by the pair rows (up to [`crate::linear::SPARSE_FROM_PAIRS`]
    /// pairs, made as the problem was built), or `K_ff`'s own supernodal Cholesky factor, made
    /// at the first call and shared by the problem's copies (the sparse path's active set never
    /// asks for it: `crate::stiffness_factor`).
    ///
    /// # Errors
    /// [`ContactError::Fem`] if a deferred factorisation finds `K_ff` not positive definite.
    pub fn solver(&self) -> Result<&CholeskySolver, ContactError> {
        self.factor.get()
    }

    /// Whether [`ContactProblem::solver`]'s factor has been made: always up to
    /// [`crate::linear::SPARSE_FROM_PAIRS`] pairs; beyond, once something asked for it.
    pub fn is_factored(&self) -> bool {
        self.factor.if_made().is_some()
    }

    /// The handle of [`ContactProblem::solver`] (made or deferred).
    pub(crate) fn stiffness_factor(&self) -> &StiffnessFactor {
        &self.factor
    }

    /// Whether [`ContactProblem::solver`] was factored bordered by the pair rows (always up to
    /// [`crate::linear::SPARSE_FROM_PAIRS`] pairs), so that [`crate::Interface::new`] condenses
    /// from it; else it is `K`'s own Cholesky factor (the sparse path needs no more, and the
    /// bordered factor's dense block of the rows would cost `(2 × pairs)³ / 3` flops) and
    /// [`crate::Interface::new`] borders it when the condensed path is asked for.
    pub fn is_bordered(&self) -> bool {
        self.bordered
    }

    #[allow(clippy::too_many_arguments)]
    fn assemble_parts(
        model: Model,
        system: Arc<LinearSystem>,
        factor: StiffnessFactor,
        pairs: Vec<ContactPair>,
        normal_rows: Vec<PairRow>,
        tangent_rows: Vec<PairRow>,
        friction: Vec<f64>,
        slave: Vec<SlaveKind>,
    ) -> ContactProblem {
        let pattern_prescribed = system.dofs.prescribed_values().to_vec();
        let nodal = system.load.clone();
        let pattern_rhs = system.rhs(&pattern_prescribed);
        let k = system.stiffness.as_ref();
        let stiffness_scale = (0..k.ncols())
            .flat_map(|j| k.row_idx_of_col(j).zip(k.val_of_col(j)).filter(move |(i, _)| *i == j).map(|(_, v)| v.abs()))
            .fold(0.0f64, f64::max);
        let gap = pairs.iter().map(|p| p.gap).collect();
        // A tangential row whose free part is negligible (the tangent lies along constrained
        // directions up to the edge geometry's error) has no unknown.
        let tangential = tangent_rows
            .iter()
            .zip(pairs.iter().zip(&slave))
            .map(|(row, (pair, kind))| has_free_part(row) && point_tangent_moves(&system, pair, *kind))
            .collect();
        let normal = normal_rows.iter().map(has_free_part).collect();
        ContactProblem {
            model,
            system,
            factor,
            pairs,
            normal_rows,
            tangent_rows,
            gap,
            friction,
            tangential,
            normal,
            patterns: vec![LoadPattern {
                name: "main".into(),
                rhs: pattern_rhs.clone(),
                prescribed: pattern_prescribed.clone(),
                nodal,
            }],
            pattern_rhs,
            pattern_prescribed,
            stiffness_scale,
            slave,
            build_times: BuildTimes::default(),
            bordered: true,
            element_matrices: OnceLock::new(),
        }
    }

    /// Replaces the initial gaps (e.g. by the paper's u_ρc, in displacement units).
    ///
    /// # Errors
    /// Wrong length or non-finite values.
    pub fn set_gaps(&mut self, gap: Vec<f64>) -> Result<(), ContactError> {
        if gap.len() != self.pairs.len() || gap.iter().any(|g| !g.is_finite()) {
            return Err(ContactError::InvalidInput(format!(
                "{} gaps given for {} pairs (all must be finite)",
                gap.len(),
                self.pairs.len()
            )));
        }
        self.gap = gap;
        Ok(())
    }

    /// Sets the friction coefficient of every pair.
    ///
    /// # Errors
    /// A negative or non-finite coefficient.
    pub fn set_friction(&mut self, mu: f64) -> Result<(), ContactError> {
        if !(mu.is_finite() && mu >= 0.0) {
            return Err(ContactError::InvalidInput(format!("friction coefficient must be finite and ≥ 0, got {mu}")));
        }
        self.friction = vec![mu; self.pairs.len()];
        Ok(())
    }

    /// The named load patterns.
    pub fn patterns(&self) -> &[LoadPattern] {
        &self.patterns
    }

    /// Replaces the load patterns (every pattern's vectors sized for this problem's free and
    /// constrained DOFs) and applies the first one with factor 1.
    ///
    /// # Errors
    /// No pattern, a wrong length, a non-finite value, or a repeated name.
    pub fn set_patterns(&mut self, patterns: Vec<LoadPattern>) -> Result<(), ContactError> {
        let (nf, nc) = (self.system.dofs.num_free(), self.system.dofs.num_constrained());
        if patterns.is_empty() {
            return Err(ContactError::InvalidInput("a problem needs at least one load pattern".into()));
        }
        for (i, p) in patterns.iter().enumerate() {
            if p.rhs.len() != nf || p.prescribed.len() != nc {
                return Err(ContactError::InvalidInput(format!(
                    "load pattern \"{}\": {} + {} values for {nf} free and {nc} constrained DOFs",
                    p.name,
                    p.rhs.len(),
                    p.prescribed.len()
                )));
            }
            if p.rhs.iter().chain(&p.prescribed).any(|v| !v.is_finite()) {
                return Err(ContactError::InvalidInput(format!("load pattern \"{}\" is not finite", p.name)));
            }
            if patterns[..i].iter().any(|q| q.name == p.name) {
                return Err(ContactError::InvalidInput(format!("load pattern \"{}\" given twice", p.name)));
            }
        }
        self.patterns = patterns;
        let mut first = vec![0.0; self.patterns.len()];
        first[0] = 1.0;
        self.apply_load(&first, None)
    }

    /// Sets the load the algorithms scale by `w` to `Σ_p factors[p] · pattern_p`, plus
    /// `extra_rhs` (free DOFs; e.g. the springs' force of a floating body's proximal step):
    ///
    /// ```text
    /// r = Σ_p f_p r_p + r_extra,   u_c = Σ_p f_p u_c,p
    /// ```
    ///
    /// # Errors
    /// A factor count that differs from the number of patterns, non-finite factors, or an
    /// `extra_rhs` of the wrong length.
    pub fn apply_load(&mut self, factors: &[f64], extra_rhs: Option<&[f64]>) -> Result<(), ContactError> {
        if factors.len() != self.patterns.len() || factors.iter().any(|f| !f.is_finite()) {
            return Err(ContactError::InvalidInput(format!(
                "{} finite load factors needed (one per pattern), got {:?}",
                self.patterns.len(),
                factors
            )));
        }
        let mut rhs = vec![0.0; self.system.dofs.num_free()];
        let mut prescribed = vec![0.0; self.system.dofs.num_constrained()];
        for (p, f) in self.patterns.iter().zip(factors) {
            if *f == 0.0 {
                continue;
            }
            rhs.iter_mut().zip(&p.rhs).for_each(|(r, v)| *r += f * v);
            prescribed.iter_mut().zip(&p.prescribed).for_each(|(r, v)| *r += f * v);
        }
        if let Some(extra) = extra_rhs {
            if extra.len() != rhs.len() {
                return Err(ContactError::InvalidInput("extra right-hand side of the wrong length".into()));
            }
            rhs.iter_mut().zip(extra).for_each(|(r, v)| *r += v);
        }
        self.pattern_rhs = rhs;
        self.pattern_prescribed = prescribed;
        Ok(())
    }

    /// The prescribed values `Σ_p f_p u_c,p` of the load with pattern factors `factors`.
    pub fn prescribed_for(&self, factors: &[f64]) -> Vec<f64> {
        let mut out = vec![0.0; self.system.dofs.num_constrained()];
        for (p, f) in self.patterns.iter().zip(factors) {
            out.iter_mut().zip(&p.prescribed).for_each(|(o, v)| *o += f * v);
        }
        out
    }

    /// Whether any pair has friction.
    pub fn is_frictional(&self) -> bool {
        self.friction.iter().any(|mu| *mu > 0.0)
    }

    /// Number of pairs.
    pub fn num_pairs(&self) -> usize {
        self.pairs.len()
    }

    /// Whether every initial gap is zero (then a frictionless solution is linear in the load).
    pub fn is_gapless(&self) -> bool {
        self.gap.iter().all(|g| *g == 0.0)
    }
}

/// One named load pattern: its right-hand side over free DOFs and its prescribed values.
///
/// ```text
/// r_p = f_p − K_fc u_c,p      (f_p: the pattern's nodal loads, u_c,p: its prescribed values)
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct LoadPattern {
    /// Name (scene files call the default pattern `main`).
    pub name: String,
    /// `r_p` over free DOFs.
    pub rhs: Vec<f64>,
    /// `u_c,p` per constrained index.
    pub prescribed: Vec<f64>,
    /// `f_p`: the pattern's nodal loads in global DOF order (for reactions).
    pub nodal: Vec<f64>,
}

/// `K_ff` factored bordered by the pair rows up to [`crate::linear::SPARSE_FROM_PAIRS`] pairs
/// (the factor's last block is then the compliance `C = B K⁻¹ Bᵀ` of the bodies at the pairs,
/// crate::interface), refactoring `previous`'s symbolic analysis when it has the same pattern;
/// above, `K` alone: `previous` refactored when it has the same pattern, else no factor yet
/// (made at its first use, `crate::stiffness_factor`). Returns the factor and whether it is
/// bordered.
fn factor_stiffness(
    system: &LinearSystem,
    normal_rows: &[PairRow],
    tangent_rows: &[PairRow],
    previous: Option<&CholeskySolver>,
) -> Result<(Option<CholeskySolver>, bool), ContactError> {
    if normal_rows.len() >= crate::linear::SPARSE_FROM_PAIRS {
        // `K` alone, refactored numerically if a previous factor of its pattern exists, else
        // left to the first solve that needs it (the sparse path's active set needs none).
        let solver = match previous {
            Some(p) if p.same_pattern(&system.stiffness) => {
                let mut s = p.clone();
                s.refactor(&system.stiffness)?;
                Some(s)
            }
            _ => None,
        };
        return Ok((solver, false));
    }
    let rows = condensed_rows(normal_rows, tangent_rows).1;
    let solver = match previous {
        Some(p) => {
            let mut s = p.clone();
            s.refactor_with_constraints(&system.stiffness, &rows)?;
            s
        }
        None => CholeskySolver::factor_with_constraints(&system.stiffness, &rows)?,
    };
    Ok((Some(solver), true))
}

/// `solver` as the problem's factor of `system`, or `K_ff`'s own deferred to its first use.
fn factor_of(system: Arc<LinearSystem>, solver: Option<CholeskySolver>) -> StiffnessFactor {
    match solver {
        Some(s) => StiffnessFactor::made(system, s),
        None => StiffnessFactor::deferred(system),
    }
}

/// A new problem's `system`, shared, and its factor ([`factor_of`]).
fn shared(system: LinearSystem, solver: Option<CholeskySolver>) -> (Arc<LinearSystem>, StiffnessFactor) {
    let system = Arc::new(system);
    (Arc::clone(&system), factor_of(system, solver))
}

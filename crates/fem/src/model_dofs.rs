//! The DOF map of a model: which DOFs are free, which prescribed and to what, and which nodes
//! carry a local frame `(un, ut)` from a curve with a normal or tangential condition.
//!
//! ```text
//! prescribed = {(dof, value)} from every group condition and node value, sorted, equal values merged
//! framed node: u = un n + ut t  (one frame per node; two curves meet only at zero supports that
//!                                span the plane, where the node is held fully, u = 0)
//! ```

use crate::dof::{Component, Dof, DofMap, Frame};
use crate::error::FemError;
use crate::model::Model;

impl Model {
    /// Numbers the DOFs, resolving the Dirichlet conditions and the local frames.
    ///
    /// # Errors
    /// [`FemError::ConflictingDirichlet`] when one DOF gets two different values;
    /// [`FemError::LocalDirections`] for a node with a frame that is also held in `u1` / `u2`, or
    /// that two curves give different frames, unless every condition there is a zero support
    /// and their directions span the plane (a corner where two rollers meet): the node is then
    /// held fully, `u = 0`, without a frame.
    pub fn dof_map(&self) -> Result<DofMap, FemError> {
        let (frames, pinned) = self.node_frames()?;
        let mut prescribed: Vec<(Dof, f64)> = vec![];
        let held_fully = |node: usize| !pinned.is_empty() && pinned.binary_search(&node).is_ok();
        for d in &self.dirichlet {
            for n in self.mesh.group_nodes(&d.group)? {
                if !held_fully(n.0) {
                    prescribed.push((Dof::of(n.0, d.component), d.value));
                }
            }
        }
        prescribed.extend(self.node_dirichlet.iter().filter(|(d, _)| !held_fully(d.node())));
        prescribed.extend(pinned.iter().flat_map(|&n| [(Dof(2 * n), 0.0), (Dof(2 * n + 1), 0.0)]));
        prescribed.sort_by_key(|p| p.0);
        for w in prescribed.windows(2) {
            // Exactly equal values (a corner shared by two groups) are consistent.
            if w[0].0 == w[1].0 && w[0].1 != w[1].1 {
                let node = w[0].0.node();
                return Err(FemError::ConflictingDirichlet {
                    node_tag: self.mesh.node_tags.get(node).copied().unwrap_or(node as u64),
                    component: match (w[0].0.0 % 2 == 0, frames.binary_search_by_key(&node, |f| f.0).is_ok()) {
                        (true, false) => "u1",
                        (false, false) => "u2",
                        (true, true) => "un",
                        (false, true) => "ut",
                    },
                    first: w[0].1,
                    second: w[1].1,
                });
            }
        }
        prescribed.dedup_by_key(|p| p.0);
        let frames: Vec<(usize, Frame)> = frames.into_iter().map(|(n, f, _)| (n, f)).collect();
        Ok(DofMap::new(&self.active_nodes(), &prescribed).with_frames(&frames))
    }

    /// The frame of every node of a curve with a local condition, sorted by node, with its
    /// group, and the nodes held fully (see [`Model::dof_map`]).
    fn node_frames(&self) -> Result<(Vec<FramedNode<'_>>, Vec<usize>), FemError> {
        let mut entries: Vec<FramedNode<'_>> = vec![];
        for (group, f) in &self.local_frames {
            for ((node, n), t) in f.nodes.iter().zip(&f.normals).zip(&f.tangents) {
                entries.push((node.0, Frame { n: *n, t: *t }, group.as_str()));
            }
        }
        if entries.is_empty() {
            return Ok((vec![], vec![]));
        }
        entries.sort_by_key(|f| f.0);
        let mut nodes: Vec<usize> = entries.iter().map(|f| f.0).collect();
        nodes.dedup();
        // Every condition at a framed node: (direction, value, what gives it).
        let mut conditions: Vec<Vec<Condition>> = vec![vec![]; nodes.len()];
        let unit = |c: Component| if c.index() == 0 { [1.0, 0.0] } else { [0.0, 1.0] };
        for d in &self.dirichlet {
            for n in self.mesh.group_nodes(&d.group)? {
                let Ok(k) = nodes.binary_search(&n.0) else { continue };
                let direction = if d.component.is_local() {
                    let Some((_, f, _)) = entries.iter().find(|e| e.0 == n.0 && e.2 == d.group) else { continue };
                    if d.component.index() == 0 { f.n } else { f.t }
                } else {
                    unit(d.component)
                };
                let by = format!("{} by \"{}\"", d.component.name(), d.group);
                conditions[k].push((direction, d.value, by, d.component.is_local()));
            }
        }
        for (d, v) in &self.node_dirichlet {
            if let Ok(k) = nodes.binary_search(&d.node()) {
                let c = if d.0 % 2 == 0 { Component::X } else { Component::Y };
                conditions[k].push((unit(c), *v, format!("{} by a node's value", c.name()), false));
            }
        }
        let tag = |node: usize| self.mesh.node_tags.get(node).copied().unwrap_or(node as u64);
        let cross = |a: [f64; 2], b: [f64; 2]| a[0] * b[1] - a[1] * b[0];
        let (mut frames, mut pinned) = (vec![], vec![]);
        for (k, &node) in nodes.iter().enumerate() {
            let mine: Vec<&FramedNode<'_>> = entries.iter().filter(|e| e.0 == node).collect();
            let first = mine[0];
            let other_frame = mine.iter().find(|e| {
                let (a, b) = (e.1.n, first.1.n);
                !(cross(a, b).abs() < PARALLEL && a[0] * b[0] + a[1] * b[1] > 0.0)
            });
            let global = conditions[k].iter().find(|c| !c.3);
            if other_frame.is_none() && global.is_none() {
                frames.push((node, first.1, first.2));
                continue;
            }
            let c = &conditions[k];
            let zero = c.iter().all(|c| c.1 == 0.0);
            let spans = c.iter().any(|a| c.iter().any(|b| cross(a.0, b.0).abs() > PARALLEL));
            if zero && spans {
                pinned.push(node);
                continue;
            }
            let reason = match global {
                Some(g) => format!(
                    "the node is also held in {}: un / ut and u1 / u2 on one node are conditions in two frames \
                     (allowed only where all are zero supports that hold the node in both directions)",
                    g.2
                ),
                None => {
                    let e = other_frame.copied().unwrap_or(first);
                    format!(
                        "the node is also on \"{}\" with another normal ({:?} vs {:?}): one node, one frame (two \
                         curves may meet only where all their values are zero supports that hold the node in both \
                         directions)",
                        e.2, e.1.n, first.1.n
                    )
                }
            };
            return Err(FemError::LocalDirections { group: first.2.to_string(), node_tag: tag(node), reason });
        }
        Ok((frames, pinned))
    }
}

/// A node, its frame and the group that gives it.
type FramedNode<'a> = (usize, Frame, &'a str);

/// A condition at a framed node: its unit direction, value, what gives it, whether local.
type Condition = ([f64; 2], f64, String, bool);

/// Below this `|a × b|` two unit directions are one (1e-8 rad).
const PARALLEL: f64 = 1e-8;

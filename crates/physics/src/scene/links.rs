//! The scene's rods, strings and spring ends in the solver's form ([`crate::constraints`]),
//! and whether its rods and strings can hold their lengths at the start.

use glam::DVec2;

use super::{Endpoint, Scene, Section, say};
use crate::constraints::{Constraints, End, Link};

impl Scene {
    /// The runtime form of an end of a valid scene.
    pub(crate) fn end(&self, end: &Endpoint) -> End {
        match end {
            Endpoint::Particle(name) => End::Particle(self.particle_index(name).unwrap_or(0)),
            Endpoint::Point(point) => End::Point(point.to_dvec2()),
        }
    }

    /// The rods and strings of a valid scene in runtime form, in scene order.
    pub(crate) fn links(&self) -> Vec<Link> {
        self.ties
            .iter()
            .map(|t| Link {
                from: self.end(&t.from),
                to: self.end(&t.to),
                length: t.length,
                kind: t.kind,
                restitution: t.restitution,
            })
            .collect()
    }
}

/// Whether the rods and strings of a scene (otherwise valid) can all have their lengths
/// at its start: the positions are projected onto them, and a set that still misses is
/// reported on the link that misses most, with the reason.
pub(crate) fn unsatisfiable(scene: &Scene) -> Option<(Section, String)> {
    if scene.ties.is_empty() {
        return None;
    }
    let w: Vec<f64> = scene
        .particles
        .iter()
        .map(|p| if p.fixed { 0.0 } else { 1.0 / p.mass })
        .collect();
    let constraints = Constraints::new(scene.links(), &w);
    let mut x: Vec<DVec2> = scene
        .particles
        .iter()
        .map(|p| p.position.to_dvec2())
        .collect();
    let mut v = vec![DVec2::ZERO; x.len()];
    let worst = constraints.project(&mut x, &mut v, &w);
    if worst <= 1e-9 && x.iter().all(|p| p.is_finite()) {
        return None;
    }
    let miss = |k: usize| {
        let link = &constraints.links[k];
        let length = link.d(&x).length();
        let over = if link.is_string() {
            (length - link.length).max(0.0)
        } else {
            (length - link.length).abs()
        };
        if over.is_finite() {
            over / link.length
        } else {
            f64::INFINITY
        }
    };
    let k = (0..constraints.links.len()).max_by(|&i, &j| miss(i).total_cmp(&miss(j)))?;
    let tie = &scene.ties[k];
    Some((
        Section::Tie(k),
        say(
            "scene-unsatisfiable",
            &[
                ("length", &tie.length.to_string()),
                ("miss", &format!("{:.3e}", miss(k) * tie.length)),
            ],
        ),
    ))
}

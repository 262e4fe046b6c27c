//! The rules of `[[body]]`: a shape that is a body's (a box with a size, a convex polygon
//! counter-clockwise), a mass or a density, friction that makes sense, and no two bodies
//! inside each other at the start.

use glam::DVec2;

use super::Checker;
use crate::scene::error::Section;
use crate::scene::fields;
use crate::scene::{Body, Shape, say};

/// The most vertices a polygon may have: a body is a block, a board, a wedge or a
/// wheel's outline; more corners than this are a curve, which is a turning particle's.
pub const MOST_VERTICES: usize = 64;

/// How far two bodies may reach into each other at the start, as a fraction of the
/// smaller one's size: their outlines' rounding (a box at 30° has corners that are no
/// short decimals), never an overlap a person placed.
const START_OVERLAP: f64 = 1e-9;

impl Checker<'_> {
    pub(super) fn is_body(&self, name: &str) -> bool {
        self.scene.bodies.iter().any(|b| b.name == name)
    }

    pub(super) fn bodies(&mut self) {
        let mut whole = Vec::with_capacity(self.scene.bodies.len());
        for (i, body) in self.scene.bodies.iter().enumerate() {
            let before = self.problems.len();
            let s = Section::Body(i);
            self.rules(s, fields::BODY, body);
            if let Some(reason) = super::static_problem(body.static_friction, body.friction) {
                self.report(s, "static_friction", &reason);
            }
            self.shape(s, body);
            self.mass(s, body);
            whole.push(self.problems.len() == before);
        }
        self.overlaps(&whole);
    }

    fn shape(&mut self, s: Section, body: &Body) {
        match &body.shape {
            Shape::Box => {
                for (field, size) in [("width", body.width), ("height", body.height)] {
                    if size <= 0.0 && size.is_finite() {
                        self.report(s, field, &say("scene-body-box-size", &[("field", field)]));
                    }
                }
            }
            Shape::Polygon(vertices) => {
                for (field, size) in [("width", body.width), ("height", body.height)] {
                    if size != 0.0 {
                        self.report(s, field, &say("scene-body-not-box", &[("field", field)]));
                    }
                }
                if let Some(reason) = polygon_problem(vertices) {
                    self.report(s, "vertices", &reason);
                }
            }
        }
    }

    fn mass(&mut self, s: Section, body: &Body) {
        match (body.mass > 0.0, body.density > 0.0) {
            (true, true) => self.report(s, "density", &say("scene-body-mass-and-density", &[])),
            (false, false) if body.mass == 0.0 && body.density == 0.0 => {
                self.report(s, "mass", &say("scene-body-no-mass", &[]));
            }
            _ => {}
        }
    }

    /// Two bodies inside each other at the start are refused, naming both: pushed apart
    /// by an impulse out of nowhere, they would fly off with energy nobody gave them.
    fn overlaps(&mut self, whole: &[bool]) {
        let bodies = &self.scene.bodies;
        let outlines: Vec<Option<Vec<DVec2>>> = bodies
            .iter()
            .zip(whole)
            .map(|(body, &whole)| {
                // A jointed body meets nothing yet (docs/physics.md): a wheel may sit on
                // its axle inside the cart.
                let jointed = self
                    .scene
                    .joints
                    .iter()
                    .any(|j| j.body == body.name || j.other() == Some(body.name.as_str()));
                (whole && !jointed).then(|| body.world_outline())
            })
            .collect();
        let boxes: Vec<Option<(DVec2, DVec2)>> = outlines
            .iter()
            .map(|outline| {
                let outline = outline.as_ref()?;
                let min = outline.iter().copied().reduce(DVec2::min)?;
                let max = outline.iter().copied().reduce(DVec2::max)?;
                Some((min, max))
            })
            .collect();
        // Sorted by their boxes' left edges, each body is compared with those whose
        // boxes start before its own ends: n log n for a row or a pyramid, not n².
        let mut order: Vec<usize> = (0..bodies.len()).filter(|&i| boxes[i].is_some()).collect();
        order.sort_by(|&a, &b| boxes_left(&boxes, a).total_cmp(&boxes_left(&boxes, b)));
        for (k, &i) in order.iter().enumerate() {
            let Some((min_i, max_i)) = boxes[i] else {
                continue;
            };
            for &j in &order[k + 1..] {
                let Some((min_j, max_j)) = boxes[j] else {
                    continue;
                };
                if min_j.x > max_i.x {
                    break;
                }
                if min_j.y > max_i.y || max_j.y < min_i.y {
                    continue;
                }
                let (Some(a), Some(b)) = (&outlines[i], &outlines[j]) else {
                    continue;
                };
                let size = (max_i - min_i)
                    .min_element()
                    .min((max_j - min_j).min_element());
                if overlap_depth(a, b) > START_OVERLAP * size {
                    let (first, second) = (i.min(j), i.max(j));
                    self.report(
                        Section::Body(second),
                        "position",
                        &say(
                            "scene-body-overlap",
                            &[("other", bodies[first].name.as_str())],
                        ),
                    );
                }
            }
        }
    }
}

fn boxes_left(boxes: &[Option<(DVec2, DVec2)>], i: usize) -> f64 {
    boxes[i].map_or(f64::INFINITY, |(min, _)| min.x)
}

/// What is wrong with a polygon's vertices, if anything: too few or too many, not
/// finite, a repeated point, three in a line, clockwise, concave, or winding more than
/// once.
pub(crate) fn polygon_problem(vertices: &[DVec2]) -> Option<String> {
    let n = vertices.len();
    if !(3..=MOST_VERTICES).contains(&n) {
        return Some(say(
            "scene-body-vertex-count",
            &[
                ("count", &n.to_string()),
                ("most", &MOST_VERTICES.to_string()),
            ],
        ));
    }
    let number = |k: usize| (k % n + 1).to_string();
    if let Some(k) = vertices
        .iter()
        .position(|v| !v.is_finite() || v.abs().max_element() > super::LARGEST_MAGNITUDE)
    {
        return Some(say("scene-body-vertex-not-finite", &[("k", &number(k))]));
    }
    for k in 0..n {
        if vertices[k] == vertices[(k + 1) % n] {
            return Some(say(
                "scene-body-repeated-vertex",
                &[("a", &number(k)), ("b", &number(k + 1))],
            ));
        }
    }
    let (mut left, mut right, mut turning) = (0, 0, 0.0);
    for k in 0..n {
        let (a, b, c) = (vertices[k], vertices[(k + 1) % n], vertices[(k + 2) % n]);
        let (e, f) = (b - a, c - b);
        let cross = e.perp_dot(f);
        // Within rounding of zero, relative to the edges: three points in a line.
        if cross.abs() <= 1e-12 * e.length() * f.length() {
            return Some(say(
                "scene-body-collinear",
                &[
                    ("a", &number(k)),
                    ("b", &number(k + 1)),
                    ("c", &number(k + 2)),
                ],
            ));
        }
        if cross > 0.0 {
            left += 1;
        } else {
            right += 1;
        }
        turning += cross.atan2(e.dot(f));
    }
    if right == n {
        return Some(say("scene-body-clockwise", &[]));
    }
    if right > 0 {
        let k = (0..n).find(|&k| {
            let (a, b, c) = (vertices[k], vertices[(k + 1) % n], vertices[(k + 2) % n]);
            (b - a).perp_dot(c - b) < 0.0
        });
        let k = k.map_or_else(String::new, |k| number(k + 1));
        return Some(say("scene-body-concave", &[("k", &k)]));
    }
    // Every turn to the left, yet more than one full turn: a star drawn in one stroke.
    if left == n && turning > 3.0 * std::f64::consts::PI {
        return Some(say("scene-body-winds", &[]));
    }
    None
}

/// How deep two convex outlines (counter-clockwise) reach into each other, metres: the
/// least overlap of their projections over the edges' normals (separating axes); 0 or
/// less when they are apart or touch.
pub(crate) fn overlap_depth(a: &[DVec2], b: &[DVec2]) -> f64 {
    let mut least = f64::INFINITY;
    for (one, other) in [(a, b), (b, a)] {
        for k in 0..one.len() {
            let edge = one[(k + 1) % one.len()] - one[k];
            let Some(normal) = DVec2::new(edge.y, -edge.x).try_normalize() else {
                continue;
            };
            let reach = one[k].dot(normal);
            let deepest = other
                .iter()
                .map(|v| reach - v.dot(normal))
                .fold(f64::NEG_INFINITY, f64::max);
            least = least.min(deepest);
        }
    }
    least
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{Body, Scene};

    fn square(at: [f64; 2]) -> Body {
        Body::rectangle("a", 1.0, 1.0, 1.0).position(at)
    }

    #[test]
    fn outlines_apart_touching_and_inside() {
        let a = square([0.0, 0.0]).world_outline();
        let apart = square([1.5, 0.0]).world_outline();
        let touching = square([1.0, 0.3]).world_outline();
        let inside = square([0.9, 0.0]).world_outline();
        assert!(overlap_depth(&a, &apart) < 0.0);
        assert!(overlap_depth(&a, &touching).abs() < 1e-15);
        assert!((overlap_depth(&a, &inside) - 0.1).abs() < 1e-12);
        let turned = square([1.2, 0.0]).angle(45.0).world_outline();
        // The turned square's corner reaches 0.5·√2 left of its centre: into a by 0.0071.
        let depth = overlap_depth(&a, &turned);
        assert!((depth - (0.5 * 2f64.sqrt() - 0.7)).abs() < 1e-12, "{depth}");
    }

    #[test]
    fn polygons_that_are_no_body() {
        let p = |points: &[[f64; 2]]| -> Vec<DVec2> {
            points.iter().map(|&[x, y]| DVec2::new(x, y)).collect()
        };
        let triangle = p(&[[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]]);
        assert_eq!(polygon_problem(&triangle), None);
        for (points, says) in [
            (p(&[[0.0, 0.0], [1.0, 0.0]]), "3 to 64"),
            (p(&[[0.0, 0.0], [0.0, 1.0], [1.0, 0.0]]), "clockwise"),
            (p(&[[0.0, 0.0], [1.0, 0.0], [2.0, 0.0], [0.0, 1.0]]), "line"),
            (
                p(&[[0.0, 0.0], [1.0, 0.0], [1.0, 0.0], [0.0, 1.0]]),
                "same point",
            ),
            (
                p(&[[0.0, 0.0], [2.0, 0.0], [1.0, 0.5], [2.0, 2.0], [0.0, 2.0]]),
                "convex",
            ),
            (
                p(&[[0.0, 0.0], [f64::NAN, 0.0], [0.0, 1.0]]),
                "not a finite",
            ),
        ] {
            let problem = polygon_problem(&points).expect("refused");
            assert!(problem.contains(says), "{problem}");
        }
        // A five-pointed star in one stroke turns left at every corner, twice round.
        let star: Vec<DVec2> = (0..5)
            .map(|k| DVec2::from_angle(f64::from(k * 2) * std::f64::consts::TAU / 5.0))
            .collect();
        assert!(polygon_problem(&star).expect("refused").contains("crosses"));
        let many: Vec<DVec2> = (0..10_000)
            .map(|k| DVec2::from_angle(f64::from(k) * std::f64::consts::TAU / 10_000.0))
            .collect();
        assert!(polygon_problem(&many).expect("refused").contains("10000"));
    }

    #[test]
    fn bodies_inside_each_other_are_refused_by_name() {
        let mut b = square([0.5, 0.2]);
        b.name = "b".to_owned();
        let scene = Scene::new().with_body(square([0.0, 0.0])).with_body(b);
        let problems = scene.validate();
        assert_eq!(problems.len(), 1, "{problems:?}");
        assert!(problems[0].message.contains("body 'b'"));
        assert!(problems[0].message.contains("'a'"));
        let mut touching = square([1.0, 0.0]);
        touching.name = "c".to_owned();
        let scene = Scene::new()
            .with_body(square([0.0, 0.0]))
            .with_body(touching);
        assert_eq!(scene.validate(), vec![]);
    }
}

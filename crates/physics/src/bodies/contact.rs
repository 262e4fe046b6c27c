//! Where rigid bodies touch: a body against the static solids (the walls of the bounds,
//! the ramps) and two bodies against each other, each point of touch with its normal and
//! its gap; and the separations a search for the next contact follows.
//!
//! Two convex outlines touch along one line: its normal is the face of either outline
//! that separates them best (the separating axis), and the points of touch are the other
//! outline's corners on that face and the face's own ends on the other outline — a box on
//! a box touches at two points, a tilted box at its corner.

use glam::DVec2;

use crate::Integrator;
use crate::contacts::obstacles::{Obstacle, Shape as Solid};

/// A body's state: the centroid's position and velocity, the angle (degrees) and spin.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Pose {
    pub position: DVec2,
    pub velocity: DVec2,
    pub angle: f64,
    pub spin: f64,
}

/// What a body is, for its contacts.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Rigid<'a> {
    pub mass: f64,
    /// About the centroid, kg·m².
    pub inertia: f64,
    /// About the centroid, in the body's frame.
    pub outline: &'a [DVec2],
    /// The farthest vertex from the centroid, m.
    pub radius: f64,
    /// The uniform field, m/s².
    pub gravity: DVec2,
    /// Held where it is: it pushes, and nothing moves it.
    pub fixed: bool,
    /// Its own coefficients, which meet another body's (the smaller restitution, the
    /// geometric mean of the frictions).
    pub restitution: f64,
    pub friction: f64,
    pub static_friction: f64,
}

impl Rigid<'_> {
    /// ½ m v² + ½ I ω², joules (none for a fixed body).
    pub fn kinetic_energy(&self, pose: &Pose) -> f64 {
        if self.fixed {
            return 0.0;
        }
        0.5 * self.mass * pose.velocity.length_squared() + 0.5 * self.inertia * pose.spin.powi(2)
    }

    /// 1/m, none for a fixed body.
    pub fn inverse_mass(&self) -> f64 {
        if self.fixed { 0.0 } else { 1.0 / self.mass }
    }

    /// 1/I, none for a fixed body.
    pub fn inverse_inertia(&self) -> f64 {
        if self.fixed { 0.0 } else { 1.0 / self.inertia }
    }

    /// Its accelerations with nothing touching it.
    pub fn free(&self) -> Push {
        Push {
            linear: if self.fixed {
                DVec2::ZERO
            } else {
                self.gravity
            },
            angular: 0.0,
        }
    }
}

/// The accelerations through a span, constant over it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Push {
    pub linear: DVec2,
    pub angular: f64,
}

impl Pose {
    /// The pose `s` seconds on under `push`, as `method` takes a step of `s`: euler
    /// x + v s, semi-implicit euler x + (v + a s) s, the others x + v s + a s²/2 (their
    /// exact result for a constant acceleration); the angle likewise.
    pub fn after(self, push: Push, method: Integrator, s: f64) -> Self {
        let (a, alpha) = (push.linear, push.angular);
        let (mut x, mut v, mut w) = (self.position, self.velocity, self.spin);
        let turn;
        match method {
            Integrator::Euler => {
                x += v * s;
                v += a * s;
                turn = w * s;
                w += alpha * s;
            }
            Integrator::SemiImplicitEuler => {
                v += a * s;
                x += v * s;
                w += alpha * s;
                turn = w * s;
            }
            Integrator::Verlet | Integrator::Rk4 | Integrator::Pefrl | Integrator::Dopri5 => {
                x += v * s + a * (0.5 * s * s);
                v += a * s;
                // A body in flight turns at a steady spin: its angle by the same
                // arithmetic as without contacts.
                turn = if alpha == 0.0 {
                    w * s
                } else {
                    w * s + alpha * (0.5 * s * s)
                };
                w += alpha * s;
            }
        }
        Self {
            position: x,
            velocity: v,
            angle: self.angle + turn.to_degrees(),
            spin: w,
        }
    }

    /// The outline `local` placed at this pose, counter-clockwise.
    pub fn outline(&self, local: &[DVec2]) -> Vec<DVec2> {
        let turn = DVec2::from_angle(self.angle.to_radians());
        local
            .iter()
            .map(|&v| self.position + turn.rotate(v))
            .collect()
    }

    /// The velocity of the body's point at `r` from the centroid.
    pub fn velocity_at(&self, r: DVec2) -> DVec2 {
        self.velocity + self.spin * r.perp()
    }
}

/// What a body touches: a solid (by its index) or another body of the island.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Other {
    Solid(usize),
    Body(usize),
}

/// Which point of an outline touches: one of its vertices, or the edge nearest a ramp's
/// rounded end (0: its `from`, 1: its `to`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Feature {
    Vertex(usize),
    Cap(usize),
}

/// A touching feature, as the search for the next contact knows it: `feature` of body
/// `owner` against `against`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct Key {
    pub owner: usize,
    pub against: Other,
    pub feature: Feature,
}

/// One point where a body touches a solid or another body.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Touch {
    /// The body the normal points into.
    pub body: usize,
    pub other: Other,
    /// The point of touch, on the other's surface.
    pub point: DVec2,
    /// Unit, from the other into the body; for two bodies, a face of the other's.
    pub normal: DVec2,
    /// The separation, m (negative: overlapping).
    pub gap: f64,
    pub key: Key,
}

/// The island's outlines and centroids now, for finding what touches.
pub(crate) struct Placed {
    pub outlines: Vec<Vec<DVec2>>,
    pub centres: Vec<DVec2>,
    pub radii: Vec<f64>,
    pub fixed: Vec<bool>,
    /// Whether bodies meet each other (`[world] collisions`).
    pub collide: bool,
}

/// Every point where a body comes within `reach` of a solid or of another body.
pub(crate) fn touches(placed: &Placed, solids: &[Obstacle], reach: f64) -> Vec<Touch> {
    let mut found = Vec::new();
    for (body, outline) in placed.outlines.iter().enumerate() {
        if !placed.fixed[body] {
            against_solids(body, outline, solids, reach, &mut found);
        }
    }
    for (i, j) in near_pairs(placed, reach) {
        between(placed, i, j, reach, &mut found);
    }
    found
}

/// The pairs of bodies whose bounding circles come within `reach`, not both fixed.
pub(crate) fn near_pairs(placed: &Placed, reach: f64) -> Vec<(usize, usize)> {
    let n = placed.outlines.len();
    let mut pairs = Vec::new();
    if !placed.collide {
        return pairs;
    }
    for i in 0..n {
        for j in i + 1..n {
            let apart =
                placed.centres[i].distance(placed.centres[j]) - placed.radii[i] - placed.radii[j];
            if apart <= reach && !(placed.fixed[i] && placed.fixed[j]) {
                pairs.push((i, j));
            }
        }
    }
    pairs
}

fn against_solids(
    body: usize,
    outline: &[DVec2],
    solids: &[Obstacle],
    reach: f64,
    found: &mut Vec<Touch>,
) {
    for (k, solid) in solids.iter().enumerate() {
        let key = |feature| Key {
            owner: body,
            against: Other::Solid(k),
            feature,
        };
        for (i, &v) in outline.iter().enumerate() {
            let (gap, normal) = solid.shape.distance(v);
            if gap <= reach {
                found.push(Touch {
                    body,
                    other: Other::Solid(k),
                    point: v - normal * gap,
                    normal,
                    gap,
                    key: key(Feature::Vertex(i)),
                });
            }
        }
        if let Solid::Capsule { a, b, radius } = solid.shape {
            for (c, centre) in [a, b].into_iter().enumerate() {
                let Some((nearest, distance)) = nearest_on_an_edge(outline, centre) else {
                    continue;
                };
                let gap = distance - radius;
                if gap <= reach {
                    let normal = (nearest - centre) / distance;
                    found.push(Touch {
                        body,
                        other: Other::Solid(k),
                        point: centre + normal * radius,
                        normal,
                        gap,
                        key: key(Feature::Cap(c)),
                    });
                }
            }
        }
    }
}

/// The outward unit normal of the edge from `a` to `b` of a counter-clockwise outline.
fn outward(a: DVec2, b: DVec2) -> DVec2 {
    let e = (b - a).normalize();
    DVec2::new(e.y, -e.x)
}

/// The face of `reference` that separates `other` from it best: its index and the
/// separation, the least distance of `other`'s vertices in front of it.
fn best_face(reference: &[DVec2], other: &[DVec2]) -> (usize, f64) {
    let n = reference.len();
    let mut best = (0, f64::NEG_INFINITY);
    for f in 0..n {
        let (a, b) = (reference[f], reference[(f + 1) % n]);
        let normal = outward(a, b);
        let separation = other
            .iter()
            .map(|&v| normal.dot(v - a))
            .fold(f64::INFINITY, f64::min);
        if separation > best.1 {
            best = (f, separation);
        }
    }
    best
}

/// The points where bodies `i` and `j` touch, within `reach`: the other outline's
/// vertices on the separating face, and the face's ends on the other outline.
fn between(placed: &Placed, i: usize, j: usize, reach: f64, found: &mut Vec<Touch>) {
    let (oi, oj) = (&placed.outlines[i], &placed.outlines[j]);
    let (face_i, separation_i) = best_face(oi, oj);
    let (face_j, separation_j) = best_face(oj, oi);
    if separation_i.max(separation_j) > reach {
        return;
    }
    // The reference face is the better separating one; parallel faces tie, and either
    // gives the same line of touch.
    let (reference, incident, face) = if separation_i >= separation_j {
        (i, j, face_i)
    } else {
        (j, i, face_j)
    };
    let (ro, io) = (&placed.outlines[reference], &placed.outlines[incident]);
    let (a, b) = (ro[face], ro[(face + 1) % ro.len()]);
    let normal = outward(a, b);
    let along = (b - a).normalize();
    let length = a.distance(b);
    let first = found.len();
    for (k, &v) in io.iter().enumerate() {
        let gap = normal.dot(v - a);
        let s = along.dot(v - a);
        if gap <= reach && s >= -reach && s <= length + reach {
            found.push(Touch {
                body: incident,
                other: Other::Body(reference),
                point: v - normal * gap,
                normal,
                gap,
                key: Key {
                    owner: incident,
                    against: Other::Body(reference),
                    feature: Feature::Vertex(k),
                },
            });
        }
    }
    for (k, corner) in [(face, a), ((face + 1) % ro.len(), b)] {
        let gap = signed_distance(corner, io);
        let repeated = found[first..]
            .iter()
            .any(|t| t.point.distance(corner) <= reach.max(1e-9 * length));
        if gap <= reach && !repeated {
            found.push(Touch {
                body: incident,
                other: Other::Body(reference),
                point: corner,
                normal,
                gap,
                key: Key {
                    owner: reference,
                    against: Other::Body(incident),
                    feature: Feature::Vertex(k),
                },
            });
        }
    }
}

/// The distance from `p` to a convex counter-clockwise `outline`: to its nearest edge
/// outside, the depth below its nearest face (negative) inside.
pub(crate) fn signed_distance(p: DVec2, outline: &[DVec2]) -> f64 {
    let n = outline.len();
    let mut deepest = f64::NEG_INFINITY;
    let mut nearest = f64::INFINITY;
    for k in 0..n {
        let (a, b) = (outline[k], outline[(k + 1) % n]);
        deepest = deepest.max(outward(a, b).dot(p - a));
        let edge = b - a;
        let s = ((p - a).dot(edge) / edge.length_squared()).clamp(0.0, 1.0);
        nearest = nearest.min((a + edge * s).distance(p));
    }
    if deepest > 0.0 { nearest } else { deepest }
}

/// The gaps of every feature of the island, touching or not, by key: each vertex's
/// distance from the solids and from the bodies near it (`pairs`), and each ramp end's
/// from the outlines' edges. The first contact is where the least of those not already
/// touching reaches zero.
pub(crate) fn gaps(
    placed: &Placed,
    solids: &[Obstacle],
    pairs: &[(usize, usize)],
    mut each: impl FnMut(Key, f64),
) {
    for (body, outline) in placed.outlines.iter().enumerate() {
        if placed.fixed[body] {
            continue;
        }
        let mut found = Vec::new();
        against_solids(body, outline, solids, f64::INFINITY, &mut found);
        for t in found {
            each(t.key, t.gap);
        }
    }
    for &(i, j) in pairs {
        for (owner, against) in [(i, j), (j, i)] {
            for (k, &v) in placed.outlines[owner].iter().enumerate() {
                let key = Key {
                    owner,
                    against: Other::Body(against),
                    feature: Feature::Vertex(k),
                };
                each(key, signed_distance(v, &placed.outlines[against]));
            }
        }
    }
}

/// The point of the outline's edges nearest `p` and its distance, when `p` lies outside
/// the outline and that point is inside an edge (a vertex nearest is the vertex's own
/// touch).
fn nearest_on_an_edge(outline: &[DVec2], p: DVec2) -> Option<(DVec2, f64)> {
    let n = outline.len();
    let mut best: Option<(DVec2, f64, bool)> = None;
    let mut inside = true;
    for k in 0..n {
        let (a, b) = (outline[k], outline[(k + 1) % n]);
        let edge = b - a;
        if edge.perp_dot(p - a) < 0.0 {
            inside = false;
        }
        let s = ((p - a).dot(edge) / edge.length_squared()).clamp(0.0, 1.0);
        let q = a + edge * s;
        let d = q.distance(p);
        if best.is_none_or(|(_, least, _)| d < least) {
            best = Some((q, d, s > 0.0 && s < 1.0));
        }
    }
    let (q, d, interior) = best?;
    (!inside && interior && d > 0.0).then_some((q, d))
}

/// A force on a body, where it acts.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Applied {
    /// From the centroid to where it acts, m.
    pub arm: DVec2,
    /// Newtons.
    pub force: DVec2,
    /// Friction (along the surface), or the normal force.
    pub friction: bool,
}

#[cfg(test)]
mod tests {
    use super::*;

    fn square(centre: DVec2, half: f64) -> Vec<DVec2> {
        [(-1.0, -1.0), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)]
            .iter()
            .map(|&(x, y)| centre + DVec2::new(x, y) * half)
            .collect()
    }

    fn placed_touches(outlines: &[Vec<DVec2>], centres: &[DVec2]) -> Vec<Touch> {
        let radii: Vec<f64> = outlines
            .iter()
            .zip(centres)
            .map(|(o, &c)| o.iter().fold(0.0, |r: f64, v| r.max(v.distance(c))))
            .collect();
        let placed = Placed {
            outlines: outlines.to_vec(),
            centres: centres.to_vec(),
            radii,
            fixed: vec![false, false],
            collide: true,
        };
        touches(&placed, &[], 1e-9)
    }

    /// A box resting on a wider one touches at its two lower corners, the normal up
    /// into it; one resting on a box of its own width touches at two points, not four.
    #[test]
    fn a_box_on_a_box_touches_at_two_corners() {
        for upper in [0.5, 1.0] {
            let centres = [DVec2::ZERO, DVec2::new(0.0, 1.0 + upper)];
            let outlines = [square(centres[0], 1.0), square(centres[1], upper)];
            let found = placed_touches(&outlines, &centres);
            assert_eq!(found.len(), 2, "{found:?}");
            for t in &found {
                assert_eq!((t.body, t.other), (1, Other::Body(0)));
                assert!((t.normal - DVec2::Y).length() < 1e-15);
                assert!(t.gap.abs() < 1e-15 && (t.point.y - 1.0).abs() < 1e-15);
            }
        }
    }

    /// A point's distance from a square: outside to its nearest edge or corner, inside
    /// the depth below the nearest face.
    #[test]
    fn signed_distance_of_a_point() {
        let s = square(DVec2::ZERO, 1.0);
        assert!((signed_distance(DVec2::new(3.0, 0.0), &s) - 2.0).abs() < 1e-15);
        assert!((signed_distance(DVec2::new(4.0, 5.0), &s) - 5.0).abs() < 1e-15);
        assert!((signed_distance(DVec2::new(0.5, 0.0), &s) + 0.5).abs() < 1e-15);
    }
}

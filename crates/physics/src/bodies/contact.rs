//! A rigid body against the static solids (the walls of the bounds, the ramps): where it
//! touches them, impacts located in time along its motion and resolved together by their
//! closed-form impulses, and resting contact held by its forces with Coulomb friction,
//! sticking or sliding, the instant a slide stops located.
//!
//! Through a span without events a body's accelerations are constant — the field's, and
//! the forces of the surfaces it rests on, which on a plane are constant while it sticks
//! or slides — so its motion is the closed form the scene's method gives (the exact
//! quadratic for all but the two Euler methods). A span ends at the first new contact
//! (found by conservative advancement: a body whose points move at most B m/s cannot
//! close a gap d in less than d/B) or where a slide stops; the step goes on from there.

use glam::DVec2;

use super::Taken;
use super::solve::{self, MOST_CONTACTS};
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
}

impl Rigid<'_> {
    /// ½ m v² + ½ I ω², joules.
    pub fn kinetic_energy(&self, pose: &Pose) -> f64 {
        0.5 * self.mass * pose.velocity.length_squared() + 0.5 * self.inertia * pose.spin.powi(2)
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
    fn velocity_at(&self, r: DVec2) -> DVec2 {
        self.velocity + self.spin * r.perp()
    }
}

/// Which point of a body touches: a vertex, or the edge nearest a ramp's rounded end
/// (0: its `from`, 1: its `to`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Feature {
    Vertex(usize),
    Cap(usize),
}

/// One point where a body touches a solid.
#[derive(Clone, Copy, Debug)]
struct Touch {
    solid: usize,
    feature: Feature,
    /// The contact point on the solid's surface.
    point: DVec2,
    /// Unit, from the solid into the body.
    normal: DVec2,
    /// The separation, m (negative: overlapping).
    gap: f64,
}

/// Every point of `outline` within `reach` of a solid.
fn touches(outline: &[DVec2], solids: &[Obstacle], reach: f64) -> Vec<Touch> {
    let mut found = Vec::new();
    for (k, solid) in solids.iter().enumerate() {
        for (i, &v) in outline.iter().enumerate() {
            let (gap, normal) = solid.shape.distance(v);
            if gap <= reach {
                found.push(Touch {
                    solid: k,
                    feature: Feature::Vertex(i),
                    point: v - normal * gap,
                    normal,
                    gap,
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
                        solid: k,
                        feature: Feature::Cap(c),
                        point: centre + normal * radius,
                        normal,
                        gap,
                    });
                }
            }
        }
    }
    found
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

/// How near counts as touching, as a fraction of the body's size: rounding leaves a body
/// resting on a plane a few ulps off it.
const TOUCHING: f64 = 1e-9;

/// A new contact is located to this fraction of the body's size: with speeds of metres
/// per second, to well under 1e-9 s.
const LOCATED: f64 = 1e-13;

/// The most events (impacts, slides stopping) in one step of a body; the rest of the step
/// is then taken without looking for more (a body chattering in a corner).
const MOST_EVENTS: usize = 64;

/// The most advances of the conservative search in one span.
const MOST_ADVANCES: usize = 10_000;

/// The body's acceleration now under the surfaces it rests on (no impact applied), and
/// their forces.
pub(crate) fn now(
    rigid: &Rigid<'_>,
    pose: Pose,
    solids: &[Obstacle],
    h: f64,
) -> (DVec2, Vec<Applied>) {
    let outline = pose.outline(rigid.outline);
    let mut touching = touches(&outline, solids, TOUCHING * rigid.radius);
    touching.sort_by(|a, b| a.gap.total_cmp(&b.gap));
    touching.truncate(MOST_CONTACTS);
    if touching.is_empty() {
        return (rigid.gravity, Vec::new());
    }
    let (push, _, applied) = hold(rigid, &pose, &touching, solids, rigid.gravity.length() * h);
    (push.linear, applied)
}

/// Moves a body `h` seconds on with `method`, against `solids`; returns its
/// accelerations over the last part of the step, and what its impacts (the kinetic energy
/// they took) and its sliding friction (μ N times the distance slid) took, joules.
pub(crate) fn advance(
    rigid: &Rigid<'_>,
    pose: &mut Pose,
    solids: &[Obstacle],
    method: Integrator,
    h: f64,
) -> (Push, Taken) {
    let band = TOUCHING * rigid.radius;
    // Slower than what the field adds in a step, an impact would bounce less than a step
    // high: it comes to rest instead, and no run of ever smaller bounces stalls the step.
    let resting_speed = rigid.gravity.length() * h;
    let mut left = h;
    let mut push = Push {
        linear: rigid.gravity,
        angular: 0.0,
    };
    let mut events = 0;
    let (mut struck, mut rubbed) = (0.0, 0.0);
    while left > 0.0 {
        let outline = pose.outline(rigid.outline);
        let mut touching = touches(&outline, solids, band);
        touching.sort_by(|a, b| a.gap.total_cmp(&b.gap));
        touching.truncate(MOST_CONTACTS);
        let mut slides = Vec::new();
        if touching.is_empty() {
            push = Push {
                linear: rigid.gravity,
                angular: 0.0,
            };
        } else {
            let before = rigid.kinetic_energy(pose);
            strike(rigid, pose, &touching, solids, resting_speed);
            struck += before - rigid.kinetic_energy(pose);
            (push, slides, _) = hold(rigid, pose, &touching, solids, resting_speed);
        }
        events += 1;
        if events > MOST_EVENTS {
            *pose = pose.after(push, method, left);
            break;
        }
        let mut span = left;
        let excluded: Vec<(usize, Feature)> =
            touching.iter().map(|t| (t.solid, t.feature)).collect();
        if let Some(at) = first_contact(rigid, *pose, push, method, span, solids, &excluded) {
            span = span.min(at);
        }
        for slide in &slides {
            if slide.speed * slide.acceleration < 0.0 {
                span = span.min(-slide.speed / slide.acceleration);
            }
        }
        rubbed += slides.iter().map(|slide| slide.work(span)).sum::<f64>();
        *pose = pose.after(push, method, span);
        left = if span >= left { 0.0 } else { left - span };
    }
    lift_out(rigid, pose, solids);
    (
        push,
        Taken {
            impacts: struck,
            friction: rubbed,
        },
    )
}

/// Lifts a body out of a solid it has sunk into by more than the contact band (a body
/// turning about a corner, whose constant forces over a step let the corner stray).
fn lift_out(rigid: &Rigid<'_>, pose: &mut Pose, solids: &[Obstacle]) {
    let outline = pose.outline(rigid.outline);
    let deepest = touches(&outline, solids, 0.0)
        .into_iter()
        .min_by(|a, b| a.gap.total_cmp(&b.gap));
    if let Some(touch) = deepest.filter(|t| t.gap < -TOUCHING * rigid.radius) {
        pose.position -= touch.normal * touch.gap;
    }
}

/// The first instant in (0, `span`] at which a point of the body, other than `excluded`,
/// comes within [`LOCATED`] of a solid. Conservative advancement (no point moves faster
/// than the bound, so no gap closes sooner than gap/bound), but by at least a
/// [`SEARCH_PIECES`]th of the span: where that lands inside a solid, the first contact
/// lies in the piece just taken and is found there by regula falsi (Illinois) on the
/// least gap.
fn first_contact(
    rigid: &Rigid<'_>,
    pose: Pose,
    push: Push,
    method: Integrator,
    span: f64,
    solids: &[Obstacle],
    excluded: &[(usize, Feature)],
) -> Option<f64> {
    let tolerance = LOCATED * rigid.radius;
    // The fastest any point moves over [s, span]: the centroid's speed and the spin's,
    // each largest at an end of the span (both change linearly).
    let fastest = |s: f64| {
        let v = (pose.velocity + push.linear * s)
            .length()
            .max((pose.velocity + push.linear * span).length());
        let w = (pose.spin + push.angular * s)
            .abs()
            .max((pose.spin + push.angular * span).abs());
        v + w * rigid.radius
    };
    let gap_at = |s: f64| {
        let outline = pose.after(push, method, s).outline(rigid.outline);
        touches(&outline, solids, f64::INFINITY)
            .into_iter()
            .filter(|t| !excluded.contains(&(t.solid, t.feature)))
            .map(|t| t.gap)
            .fold(f64::INFINITY, f64::min)
    };
    let (mut s, mut gap) = (0.0, gap_at(0.0));
    for _ in 0..MOST_ADVANCES {
        if gap <= tolerance {
            return Some(s);
        }
        let speed = fastest(s);
        if !(speed > 0.0 && gap.is_finite()) {
            return None;
        }
        let next = (s + (gap / speed).max(span / SEARCH_PIECES)).min(span);
        let gap_next = gap_at(next);
        if gap_next < -tolerance {
            return Some(falsi((s, gap), (next, gap_next), tolerance, gap_at));
        }
        if next >= span && gap_next > tolerance {
            return None;
        }
        (s, gap) = (next, gap_next);
    }
    Some(s)
}

/// The root of `gap` between `a` (gap above `tolerance`) and `b` (below −`tolerance`),
/// by the Illinois method, to within `tolerance` of the gap: the instant returned is
/// never past the root by more than that.
fn falsi(
    (mut a, mut ga): (f64, f64),
    (mut b, mut gb): (f64, f64),
    tolerance: f64,
    gap: impl Fn(f64) -> f64,
) -> f64 {
    let mut side = 0;
    for _ in 0..crate::tuning::EVENT_ITERATIONS {
        let c = (a * gb - b * ga) / (gb - ga);
        if !(c > a && c < b) {
            break;
        }
        let gc = gap(c);
        if gc.abs() <= tolerance {
            return c;
        }
        if gc > 0.0 {
            (a, ga) = (c, gc);
            if side == 1 {
                gb *= 0.5;
            }
            side = 1;
        } else {
            (b, gb) = (c, gc);
            if side == -1 {
                ga *= 0.5;
            }
            side = -1;
        }
    }
    a
}

/// The least fraction of a span the search for a contact advances by at once.
const SEARCH_PIECES: f64 = 16.0;

/// The point velocity change per unit push at `at` along `along`: the body's answer at
/// `r` along `to`.
fn answer(rigid: &Rigid<'_>, at: DVec2, along: DVec2, r: DVec2, to: DVec2) -> f64 {
    let turn = at.perp_dot(along) / rigid.inertia;
    to.dot(along / rigid.mass + turn * r.perp())
}

/// The impacts of the touching points that approach their solids, together: the normal
/// impulses by the complementarity problem (each approaching point leaves at e times its
/// approach, slow ones at none), then Coulomb friction at each point that took one.
fn strike(
    rigid: &Rigid<'_>,
    pose: &mut Pose,
    touching: &[Touch],
    solids: &[Obstacle],
    resting_speed: f64,
) {
    let arms: Vec<DVec2> = touching.iter().map(|t| t.point - pose.position).collect();
    let approach: Vec<f64> = touching
        .iter()
        .zip(&arms)
        .map(|(t, &r)| t.normal.dot(pose.velocity_at(r)))
        .collect();
    if approach.iter().all(|&u| u >= 0.0) {
        return;
    }
    let n = touching.len();
    let m: Vec<Vec<f64>> = (0..n)
        .map(|k| {
            (0..n)
                .map(|j| {
                    answer(
                        rigid,
                        arms[j],
                        touching[j].normal,
                        arms[k],
                        touching[k].normal,
                    )
                })
                .collect()
        })
        .collect();
    let q: Vec<f64> = (0..n)
        .map(|k| {
            let u = approach[k];
            let e = solids[touching[k].solid].restitution;
            if u < -resting_speed {
                u + e * u
            } else {
                u.min(0.0)
            }
        })
        .collect();
    let Some(impulses) = solve::solve(&m, &q, n) else {
        return;
    };
    for (k, &j) in impulses.iter().enumerate() {
        apply(rigid, pose, arms[k], touching[k].normal * j);
    }
    if touching.iter().all(|t| solids[t.solid].friction == 0.0) {
        return;
    }
    // Friction at the impacts: each point's normal and tangential impulses solved
    // together (a tangential blow at a corner turns the body, which changes the corner's
    // normal speed), sticking within μ jₙ or sliding on its edge, point by point until
    // they agree.
    let targets: Vec<f64> = q.iter().zip(&approach).map(|(q, u)| u - q).collect();
    let mut given: Vec<(f64, f64)> = impulses.iter().map(|&j| (j, 0.0)).collect();
    for _ in 0..FRICTION_PASSES {
        for k in 0..n {
            let (normal, r) = (touching[k].normal, arms[k]);
            let tangent = normal.perp();
            let mu = solids[touching[k].solid].friction;
            let u = pose.velocity_at(r);
            let (un, ut) = (normal.dot(u), tangent.dot(u));
            let (jn, jt) = given[k];
            let k_nn = answer(rigid, r, normal, r, normal);
            let k_nt = answer(rigid, r, tangent, r, normal);
            let k_tn = answer(rigid, r, normal, r, tangent);
            let k_tt = answer(rigid, r, tangent, r, tangent);
            // Sticking: the normal speed at its target and no slip.
            let (bn, bt) = (targets[k] - un, -ut);
            let det = k_nn * k_tt - k_nt * k_tn;
            let (mut n_new, mut t_new) = if det.abs() > 0.0 {
                (
                    jn + (bn * k_tt - k_nt * bt) / det,
                    jt + (k_nn * bt - k_tn * bn) / det,
                )
            } else {
                (jn, jt)
            };
            if t_new.abs() > mu * n_new.max(0.0) {
                // Sliding: the tangential impulse on the cone's edge.
                let side = t_new.signum() * mu;
                let scale = k_nn + k_nt * side;
                n_new = if scale > 0.0 {
                    (bn + k_nn * jn + k_nt * jt) / scale
                } else {
                    jn
                };
                t_new = side * n_new.max(0.0);
            }
            if n_new < 0.0 {
                (n_new, t_new) = (0.0, 0.0);
            }
            apply(
                rigid,
                pose,
                r,
                normal * (n_new - jn) + tangent * (t_new - jt),
            );
            given[k] = (n_new, t_new);
        }
    }
}

/// The passes over the points of an impact that settle their friction together.
const FRICTION_PASSES: usize = 32;

/// Applies the impulse `j` at `r` from the centroid.
fn apply(rigid: &Rigid<'_>, pose: &mut Pose, r: DVec2, j: DVec2) {
    pose.velocity += j / rigid.mass;
    pose.spin += r.perp_dot(j) / rigid.inertia;
}

/// A patch of a body sliding on a solid: its slip speed along `tangent` and how that
/// changes, for locating the instant it stops.
#[derive(Clone, Copy, Debug)]
struct Slide {
    speed: f64,
    acceleration: f64,
    /// The friction force, μ N, newtons.
    force: f64,
}

impl Slide {
    /// The work its friction does over `s` seconds, joules: μ N times the distance slid,
    /// u s + a s²/2 (a span ends where a slide stops, so the slip keeps its sign).
    fn work(&self, s: f64) -> f64 {
        self.force * (self.speed * s + 0.5 * self.acceleration * s * s).abs()
    }
}

/// The points of one solid a body rests on, with one normal: friction acts on the patch
/// as a whole (on a plane its torque about the centroid is the same wherever along the
/// patch it acts, so its share between the points is not needed).
struct Patch {
    solid: usize,
    normal: DVec2,
    points: Vec<usize>,
    /// `None` while it sticks, else the friction's direction along the tangent (+1/−1).
    sliding: Option<f64>,
}

/// The forces of the surfaces the body rests on: normal forces that keep every touching
/// point from sinking (and pull none), friction that holds a patch still within μ N or
/// slides against its motion with μ N. Returns the body's accelerations under them and the
/// patches that slide.
fn hold(
    rigid: &Rigid<'_>,
    pose: &Pose,
    touching: &[Touch],
    solids: &[Obstacle],
    resting_speed: f64,
) -> (Push, Vec<Slide>, Vec<Applied>) {
    let free = Push {
        linear: rigid.gravity,
        angular: 0.0,
    };
    let arms: Vec<DVec2> = touching.iter().map(|t| t.point - pose.position).collect();
    let speed_scale = pose.velocity.length() + pose.spin.abs() * rigid.radius;
    let still = 1e-9 * (speed_scale + resting_speed) + f64::MIN_POSITIVE;
    // Only points that neither leave nor strike rest: a bouncing body's points leave.
    let resting: Vec<usize> = (0..touching.len())
        .filter(|&k| touching[k].normal.dot(pose.velocity_at(arms[k])).abs() <= still)
        .collect();
    if resting.is_empty() {
        return (free, Vec::new(), Vec::new());
    }
    let mut patches: Vec<Patch> = Vec::new();
    for &k in &resting {
        let t = &touching[k];
        if let Some(patch) = patches
            .iter_mut()
            .find(|p| p.solid == t.solid && p.normal.dot(t.normal) > 1.0 - 1e-9)
        {
            patch.points.push(k);
        } else {
            let slip = t.normal.perp().dot(pose.velocity_at(arms[k]));
            patches.push(Patch {
                solid: t.solid,
                normal: t.normal,
                points: vec![k],
                sliding: (slip.abs() > still).then(|| -slip.signum()),
            });
        }
    }
    for _ in 0..=patches.len() {
        let Some(Held {
            push,
            totals: forces,
            applied,
        }) = forces(rigid, pose, (touching, solids), &arms, &resting, &patches)
        else {
            return (free, Vec::new(), Vec::new());
        };
        // A sticking patch that needs more friction than μ N slides, the friction then
        // pushing the way it was needed.
        let slipping = patches.iter().enumerate().find_map(|(p, patch)| {
            let (grip, normal) = forces[p];
            let mu = solids[patch.solid].static_friction;
            (patch.sliding.is_none() && grip.abs() > mu * normal * (1.0 + 1e-12))
                .then_some((p, grip))
        });
        if let Some((p, grip)) = slipping {
            patches[p].sliding = Some(grip.signum());
            continue;
        }
        let slides = patches
            .iter()
            .zip(&forces)
            .filter(|(p, _)| p.sliding.is_some())
            .map(|(p, &(_, normal))| {
                let (k, tangent) = (p.points[0], p.normal.perp());
                let r = arms[k];
                let a = push.linear + push.angular * r.perp() - pose.spin.powi(2) * r;
                Slide {
                    speed: tangent.dot(pose.velocity_at(r)),
                    acceleration: tangent.dot(a),
                    force: solids[p.solid].friction * normal,
                }
            })
            .collect();
        return (push, slides, applied);
    }
    (free, Vec::new(), Vec::new())
}

/// The forces for the patches as they are (sticking or sliding): the body's
/// accelerations, and each patch's friction and total normal force.
fn forces(
    rigid: &Rigid<'_>,
    pose: &Pose,
    (touching, solids): (&[Touch], &[Obstacle]),
    arms: &[DVec2],
    resting: &[usize],
    patches: &[Patch],
) -> Option<Held> {
    let n = resting.len();
    let sticking: Vec<usize> = (0..patches.len())
        .filter(|&p| patches[p].sliding.is_none())
        .collect();
    let patch_of = |k: usize| patches.iter().position(|p| p.points.contains(&k));
    // Each unknown as a unit force at an arm.
    let mut columns: Vec<(DVec2, DVec2)> = Vec::new();
    for &k in resting {
        let normal = touching[k].normal;
        let mut force = normal;
        if let Some(direction) = patch_of(k).and_then(|p| patches[p].sliding) {
            force += normal.perp() * (direction * solids[touching[k].solid].friction);
        }
        columns.push((force, arms[k]));
    }
    for &p in &sticking {
        let k = patches[p].points[0];
        columns.push((patches[p].normal.perp(), arms[k]));
    }
    // Each condition: a point's acceleration along a direction.
    let mut rows: Vec<(DVec2, DVec2)> = resting
        .iter()
        .map(|&k| (touching[k].normal, arms[k]))
        .collect();
    rows.extend(
        sticking
            .iter()
            .map(|&p| (patches[p].normal.perp(), arms[patches[p].points[0]])),
    );
    let accelerate = |force: DVec2, arm: DVec2| Push {
        linear: force / rigid.mass,
        angular: arm.perp_dot(force) / rigid.inertia,
    };
    let along = |push: Push, (to, r): (DVec2, DVec2)| to.dot(push.linear + push.angular * r.perp());
    let m: Vec<Vec<f64>> = rows
        .iter()
        .map(|&row| {
            columns
                .iter()
                .map(|&(f, r)| along(accelerate(f, r), row))
                .collect()
        })
        .collect();
    let q: Vec<f64> = rows
        .iter()
        .map(|&(to, r)| to.dot(rigid.gravity - pose.spin.powi(2) * r))
        .collect();
    let x = solve::solve(&m, &q, n)?;
    let mut push = Push {
        linear: rigid.gravity,
        angular: 0.0,
    };
    for (&(f, r), &amount) in columns.iter().zip(&x) {
        let a = accelerate(f * amount, r);
        push.linear += a.linear;
        push.angular += a.angular;
    }
    let mut applied = Vec::new();
    for (column, &k) in resting.iter().enumerate() {
        let (normal, amount) = (touching[k].normal, x[column]);
        applied.push(Applied {
            arm: arms[k],
            force: normal * amount,
            friction: false,
        });
        if let Some(direction) = patch_of(k).and_then(|p| patches[p].sliding) {
            let mu = solids[touching[k].solid].friction;
            applied.push(Applied {
                arm: arms[k],
                force: normal.perp() * (direction * mu * amount),
                friction: true,
            });
        }
    }
    for (s, &p) in sticking.iter().enumerate() {
        applied.push(Applied {
            arm: arms[patches[p].points[0]],
            force: patches[p].normal.perp() * x[n + s],
            friction: true,
        });
    }
    let totals = patches
        .iter()
        .enumerate()
        .map(|(p, patch)| {
            let normal: f64 = patch
                .points
                .iter()
                .map(|k| x[resting.iter().position(|r| r == k).unwrap_or(0)])
                .sum();
            let grip = sticking
                .iter()
                .position(|&s| s == p)
                .map_or(0.0, |s| x[n + s]);
            (grip, normal)
        })
        .collect();
    Some(Held {
        push,
        totals,
        applied,
    })
}

/// What the surfaces' forces come to: the body's accelerations, each patch's friction and
/// total normal force, and each force where it acts.
struct Held {
    push: Push,
    totals: Vec<(f64, f64)>,
    applied: Vec<Applied>,
}

/// A force of a surface on a body, where it acts.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Applied {
    /// From the centroid to where it acts, m.
    pub arm: DVec2,
    /// Newtons.
    pub force: DVec2,
    /// Friction (along the surface), or the normal force.
    pub friction: bool,
}

//! An island of bodies that may touch through a step — one body alone, or bodies near
//! each other — moved together: impacts located in time along their motion and resolved
//! together by their closed-form impulses, and resting contact held by its forces with
//! Coulomb friction, sticking or sliding, the instant a slide stops located.
//!
//! Through a span without events each body's accelerations are constant — the field's,
//! and the forces of what it rests on, which are constant while it sticks or slides on a
//! face — so its motion is the closed form the scene's method gives (the exact quadratic
//! for all but the two Euler methods). A span ends at the first new contact (found by
//! conservative advancement: points whose relative speed is at most B m/s cannot close a
//! gap d in less than d/B) or where a slide stops; the step goes on from there.

use glam::DVec2;

use super::Taken;
use super::contact::{self, Applied, Key, Other, Placed, Pose, Push, Rigid, Touch};
use super::solve;
use crate::Integrator;
use crate::contacts::obstacles::Obstacle;

/// How near counts as touching, as a fraction of the bodies' size: rounding leaves a
/// body resting on a plane a few ulps off it.
pub(super) const TOUCHING: f64 = 1e-9;

/// A new contact is located to this fraction of the bodies' size: with speeds of metres
/// per second, to well under 1e-9 s.
const LOCATED: f64 = 1e-13;

/// The most events (impacts, slides stopping) in one step of a body of the island; the
/// rest of the step is then taken without looking for more (a body chattering in a
/// corner).
const MOST_EVENTS: usize = 64;

/// The most advances of the conservative search in one span.
const MOST_ADVANCES: usize = 10_000;

/// The least fraction of a span the search for a contact advances by at once.
const SEARCH_PIECES: f64 = 16.0;

/// The passes over the points of an impact that settle their friction together.
const FRICTION_PASSES: usize = 32;

/// Bodies that may touch one another in a step, and the solids they may touch.
pub(crate) struct Island<'a> {
    pub members: Vec<Rigid<'a>>,
    pub solids: &'a [Obstacle],
    /// Whether bodies meet each other (`[world] collisions`).
    pub collide: bool,
}

/// One end of a touch: a body of the island, the sign the touch's push has on it, and
/// where on it the touch acts.
#[derive(Clone, Copy)]
struct End {
    body: usize,
    sign: f64,
    arm: DVec2,
}

/// A touch with its ends placed.
struct Site {
    touch: Touch,
    ends: [Option<End>; 2],
    restitution: f64,
    friction: f64,
    static_friction: f64,
}

impl Site {
    /// The velocity of the body's point relative to the other's.
    fn relative_velocity(&self, poses: &[Pose]) -> DVec2 {
        self.ends
            .iter()
            .flatten()
            .map(|e| poses[e.body].velocity_at(e.arm) * e.sign)
            .sum()
    }

    /// How the direction `to` turns with the other body's face, rad/s.
    fn turning(&self, poses: &[Pose]) -> f64 {
        match self.touch.other {
            Other::Body(b) => poses[b].spin,
            Other::Solid(_) => 0.0,
        }
    }
}

impl Island<'_> {
    fn size(&self) -> f64 {
        self.members.iter().map(|m| m.radius).fold(0.0, f64::max)
    }

    fn gravity(&self) -> f64 {
        self.members.first().map_or(0.0, |m| m.gravity.length())
    }

    /// The points that touch now, within `reach`, deepest first.
    fn touching(&self, poses: &[Pose], reach: f64) -> Vec<Site> {
        let placed = self.placed(poses);
        let mut found = contact::touches(&placed, self.solids, reach);
        found.sort_by(|a, b| a.gap.total_cmp(&b.gap));
        found.into_iter().map(|t| self.site(t, poses)).collect()
    }

    /// The island's outlines and centroids at `poses`.
    fn placed(&self, poses: &[Pose]) -> Placed {
        Placed {
            outlines: self
                .members
                .iter()
                .zip(poses)
                .map(|(m, p)| p.outline(m.outline))
                .collect(),
            centres: poses.iter().map(|p| p.position).collect(),
            radii: self.members.iter().map(|m| m.radius).collect(),
            fixed: self.members.iter().map(|m| m.fixed).collect(),
            collide: self.collide,
        }
    }

    fn site(&self, touch: Touch, poses: &[Pose]) -> Site {
        let me = &self.members[touch.body];
        let end = |body: usize, sign: f64| {
            (!self.members[body].fixed).then(|| End {
                body,
                sign,
                arm: touch.point - poses[body].position,
            })
        };
        let (ends, coefficients) = match touch.other {
            Other::Solid(k) => {
                let s = &self.solids[k];
                (
                    [end(touch.body, 1.0), None],
                    (s.restitution, s.friction, s.static_friction),
                )
            }
            Other::Body(b) => {
                let you = &self.members[b];
                (
                    [end(touch.body, 1.0), end(b, -1.0)],
                    (
                        me.restitution.min(you.restitution),
                        (me.friction * you.friction).sqrt(),
                        (me.static_friction * you.static_friction).sqrt(),
                    ),
                )
            }
        };
        Site {
            touch,
            ends,
            restitution: coefficients.0,
            friction: coefficients.1,
            static_friction: coefficients.2,
        }
    }

    /// The change of site `k`'s relative velocity along `to` per unit impulse at site
    /// `j` along `along` (and of its relative acceleration per unit force).
    fn response(&self, (k, to): (&Site, DVec2), (j, along): (&Site, DVec2)) -> f64 {
        let mut total = 0.0;
        for push in j.ends.iter().flatten() {
            let m = &self.members[push.body];
            let dv = along * (push.sign * m.inverse_mass());
            let dw = push.sign * push.arm.perp_dot(along) * m.inverse_inertia();
            for seen in k.ends.iter().flatten().filter(|e| e.body == push.body) {
                total += seen.sign * to.dot(dv + dw * seen.arm.perp());
            }
        }
        total
    }

    /// Applies the impulse `j` at site `site` (its reaction on the other body).
    fn apply(&self, poses: &mut [Pose], site: &Site, j: DVec2) {
        for end in site.ends.iter().flatten() {
            let m = &self.members[end.body];
            let pose = &mut poses[end.body];
            pose.velocity += j * (end.sign * m.inverse_mass());
            pose.spin += end.sign * end.arm.perp_dot(j) * m.inverse_inertia();
        }
    }

    fn kinetic_energy(&self, poses: &[Pose]) -> f64 {
        self.members
            .iter()
            .zip(poses)
            .map(|(m, p)| m.kinetic_energy(p))
            .sum()
    }

    fn free(&self) -> Vec<Push> {
        self.members.iter().map(Rigid::free).collect()
    }

    /// The bodies' accelerations now under what they rest on (no impact applied), and
    /// the forces of their contacts on each, by body.
    ///
    /// Read between steps, a body turning about a corner is found a little off its
    /// surface: held through one step by constant accelerations, the corner leaves it at
    /// some 1e-8 m/s, falls back through the next and is stopped by its impact at a
    /// resting speed. Through the steps the surface holds it, so the reading does too:
    /// a point within the distance a step's fall covers (g h²/2), meeting or leaving at
    /// no more than the resting speed (g h), is read as resting on it, the approach
    /// taken as the step's impact would take it.
    pub fn now(&self, poses: &[Pose], h: f64) -> (Vec<Push>, Vec<(usize, Applied)>) {
        let resting_speed = self.gravity() * h;
        let band = TOUCHING * self.size();
        let touching: Vec<Site> = self
            .touching(poses, band + 0.5 * resting_speed * h)
            .into_iter()
            .filter(|s| {
                s.touch.gap <= band
                    || s.touch.normal.dot(s.relative_velocity(poses)).abs() <= resting_speed
            })
            .collect();
        if touching.is_empty() {
            return (self.free(), Vec::new());
        }
        let mut settled = poses.to_vec();
        self.strike(&mut settled, &touching, resting_speed);
        let held = self.hold(&settled, &touching, (resting_speed, resting_speed));
        (held.pushes, held.applied)
    }

    /// Moves the island `h` seconds on with `method`; returns each body's accelerations
    /// over the last part of the step (as [`Self::now`] reads them where that part was
    /// free after a touch), and what its impacts (the kinetic energy they
    /// took) and its sliding friction (μ N times the distance slid) took, joules.
    pub fn advance(&self, poses: &mut [Pose], method: Integrator, h: f64) -> (Vec<Push>, Taken) {
        let band = TOUCHING * self.size();
        // Slower than what the field adds in a step, an impact would bounce less than a
        // step high: it comes to rest instead, and no run of ever smaller bounces stalls
        // the step.
        let resting_speed = self.gravity() * h;
        let mut left = h;
        let mut pushes = self.free();
        let mut events = 0;
        let (mut struck, mut rubbed) = (0.0, 0.0);
        let most = MOST_EVENTS * self.members.len();
        let mut touched = false;
        while left > 0.0 {
            let touching = self.touching(poses, band);
            touched |= !touching.is_empty();
            let mut slides = Vec::new();
            if touching.is_empty() {
                pushes = self.free();
            } else {
                let before = self.kinetic_energy(poses);
                self.strike(poses, &touching, resting_speed);
                struck += before - self.kinetic_energy(poses);
                let held = self.hold(poses, &touching, (resting_speed, 0.0));
                (pushes, slides) = (held.pushes, held.slides);
            }
            events += 1;
            if events > most {
                self.move_all(poses, &pushes, method, left);
                break;
            }
            let mut span = left;
            let excluded: Vec<Key> = touching.iter().map(|s| s.touch.key).collect();
            if let Some(at) = self.first_contact(poses, &pushes, method, span, &excluded) {
                span = span.min(at);
            }
            for slide in &slides {
                if slide.speed * slide.acceleration < 0.0 {
                    span = span.min(-slide.speed / slide.acceleration);
                }
            }
            rubbed += slides.iter().map(|slide| slide.work(span)).sum::<f64>();
            self.move_all(poses, &pushes, method, span);
            left = if span >= left { 0.0 } else { left - span };
        }
        self.lift_out(poses);
        if touched && pushes == self.free() {
            // Free through the step's last part after a touch, perhaps only a turning
            // corner's hop off its surface: read as the surface holds it now.
            pushes = self.now(poses, h).0;
        }
        (
            pushes,
            Taken {
                impacts: struck,
                friction: rubbed,
                motors: 0.0,
            },
        )
    }

    fn move_all(&self, poses: &mut [Pose], pushes: &[Push], method: Integrator, s: f64) {
        for ((pose, &push), m) in poses.iter_mut().zip(pushes).zip(&self.members) {
            if !m.fixed {
                *pose = pose.after(push, method, s);
            }
        }
    }

    /// Lifts bodies out of what they have sunk into deepest by more than the contact band
    /// (a body turning about a corner, whose constant forces over a step let the corner
    /// stray): out of a solid wholly, out of another body in inverse proportion to their
    /// masses. One overlap a step: lifting out of two at once, each by its own depth, can
    /// lift a body twice over and set it chattering.
    fn lift_out(&self, poses: &mut [Pose]) {
        let band = TOUCHING * self.size();
        let touching = self.touching(poses, 0.0);
        let Some(site) = touching.first().filter(|s| s.touch.gap < -band) else {
            return;
        };
        let t = &site.touch;
        let weights: Vec<(usize, f64)> = site
            .ends
            .iter()
            .flatten()
            .map(|e| (e.body, e.sign * self.members[e.body].inverse_mass()))
            .collect();
        let total: f64 = weights.iter().map(|(_, w)| w.abs()).sum();
        for (body, w) in weights {
            poses[body].position -= t.normal * (t.gap * w / total);
        }
    }

    /// The first instant in (0, `span`] at which a feature of the island, other than
    /// `excluded`, comes within [`LOCATED`] of what it may touch. Conservative advancement
    /// (no two points close faster than the bound, so no gap closes sooner than
    /// gap/bound), but by at least a [`SEARCH_PIECES`]th of the span: where that lands
    /// inside, the first contact lies in the piece just taken and is found there by
    /// regula falsi (Illinois) on the least gap.
    fn first_contact(
        &self,
        poses: &[Pose],
        pushes: &[Push],
        method: Integrator,
        span: f64,
        excluded: &[Key],
    ) -> Option<f64> {
        let tolerance = LOCATED * self.size();
        // The fastest any body's point moves over [s, span]: the centroid's speed and the
        // spin's, each largest at an end of the span (both change linearly).
        let fastest_of = |k: usize, s: f64| {
            let (pose, push, m) = (&poses[k], &pushes[k], &self.members[k]);
            if m.fixed {
                return 0.0;
            }
            let v = (pose.velocity + push.linear * s)
                .length()
                .max((pose.velocity + push.linear * span).length());
            let w = (pose.spin + push.angular * s)
                .abs()
                .max((pose.spin + push.angular * span).abs());
            v + w * m.radius
        };
        // Two bodies close at most at the sum of their speeds.
        let fastest = |s: f64| {
            let mut speeds: Vec<f64> = (0..poses.len()).map(|k| fastest_of(k, s)).collect();
            speeds.sort_by(|a, b| b.total_cmp(a));
            speeds.first().copied().unwrap_or(0.0) + speeds.get(1).copied().unwrap_or(0.0)
        };
        let pairs = self.pairs_within(poses, |k| fastest_of(k, 0.0) * span, tolerance);
        let gap_at = |s: f64| {
            let moved: Vec<Pose> = poses
                .iter()
                .zip(pushes)
                .zip(&self.members)
                .map(|((p, &push), m)| {
                    if m.fixed {
                        *p
                    } else {
                        p.after(push, method, s)
                    }
                })
                .collect();
            let placed = self.placed(&moved);
            let mut least = f64::INFINITY;
            contact::gaps(&placed, self.solids, &pairs, |key, gap| {
                if !excluded.contains(&key) {
                    least = least.min(gap);
                }
            });
            least
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

    /// The pairs of bodies that may come within `reach` of each other while each moves
    /// at most `travel(k)` metres.
    fn pairs_within(
        &self,
        poses: &[Pose],
        travel: impl Fn(usize) -> f64,
        reach: f64,
    ) -> Vec<(usize, usize)> {
        let n = poses.len();
        let mut pairs = Vec::new();
        if !self.collide {
            return pairs;
        }
        for i in 0..n {
            for j in i + 1..n {
                let (a, b) = (&self.members[i], &self.members[j]);
                let apart = poses[i].position.distance(poses[j].position) - a.radius - b.radius;
                if !(a.fixed && b.fixed) && apart <= travel(i) + travel(j) + reach {
                    pairs.push((i, j));
                }
            }
        }
        pairs
    }

    /// The impacts of the touching points that approach, together: the normal impulses
    /// by the complementarity problem (each approaching point leaves at e times its
    /// approach, slow ones at none), then Coulomb friction at each point that took one.
    fn strike(&self, poses: &mut [Pose], touching: &[Site], resting_speed: f64) {
        let approach: Vec<f64> = touching
            .iter()
            .map(|s| s.touch.normal.dot(s.relative_velocity(poses)))
            .collect();
        if approach.iter().all(|&u| u >= 0.0) {
            return;
        }
        let n = touching.len();
        let m: Vec<Vec<f64>> = touching
            .iter()
            .map(|k| {
                touching
                    .iter()
                    .map(|j| self.response((k, k.touch.normal), (j, j.touch.normal)))
                    .collect()
            })
            .collect();
        let q: Vec<f64> = touching
            .iter()
            .zip(&approach)
            .map(|(site, &u)| {
                if u < -resting_speed {
                    u + site.restitution * u
                } else {
                    u.min(0.0)
                }
            })
            .collect();
        let Some(impulses) = solve::solve(&m, &q, n) else {
            return;
        };
        for (site, &j) in touching.iter().zip(&impulses) {
            self.apply(poses, site, site.touch.normal * j);
        }
        if touching.iter().all(|s| s.friction == 0.0) {
            return;
        }
        // Friction at the impacts: each point's normal and tangential impulses solved
        // together (a tangential blow at a corner turns the body, which changes the
        // corner's normal speed), sticking within μ jₙ or sliding on its edge, point by
        // point until they agree.
        let targets: Vec<f64> = q.iter().zip(&approach).map(|(q, u)| u - q).collect();
        let mut given: Vec<(f64, f64)> = impulses.iter().map(|&j| (j, 0.0)).collect();
        for _ in 0..FRICTION_PASSES {
            for (k, site) in touching.iter().enumerate() {
                let normal = site.touch.normal;
                let tangent = normal.perp();
                let u = site.relative_velocity(poses);
                let (un, ut) = (normal.dot(u), tangent.dot(u));
                let (jn, jt) = given[k];
                let k_nn = self.response((site, normal), (site, normal));
                let k_nt = self.response((site, normal), (site, tangent));
                let k_tn = self.response((site, tangent), (site, normal));
                let k_tt = self.response((site, tangent), (site, tangent));
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
                if t_new.abs() > site.friction * n_new.max(0.0) {
                    // Sliding: the tangential impulse on the cone's edge.
                    let side = t_new.signum() * site.friction;
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
                self.apply(poses, site, normal * (n_new - jn) + tangent * (t_new - jt));
                given[k] = (n_new, t_new);
            }
        }
    }

    /// The forces of what the bodies rest on: normal forces that keep every touching
    /// point from sinking (and pull none), friction that holds a patch still within μ N
    /// or slides against its motion with μ N. Returns the bodies' accelerations under
    /// them, the patches that slide and each force where it acts.
    ///
    /// A point leaving at no more than `leaving` (m/s) still rests: a reading between
    /// steps allows what a step's constant accelerations leave (see [`Self::now`]); the
    /// step itself allows none, so that a body lifting off is let go.
    fn hold(
        &self,
        poses: &[Pose],
        touching: &[Site],
        (resting_speed, leaving): (f64, f64),
    ) -> Held {
        let free = Held {
            pushes: self.free(),
            slides: Vec::new(),
            applied: Vec::new(),
        };
        let speed_scale = poses
            .iter()
            .zip(&self.members)
            .map(|(p, m)| p.velocity.length() + p.spin.abs() * m.radius)
            .fold(0.0, f64::max);
        let still = 1e-9 * (speed_scale + resting_speed) + f64::MIN_POSITIVE;
        // Only points that neither leave nor strike rest: a bouncing body's points leave.
        let resting: Vec<&Site> = touching
            .iter()
            .filter(|s| {
                let u = s.touch.normal.dot(s.relative_velocity(poses));
                u.abs() <= still || (u > 0.0 && u <= 1e-4 * leaving)
            })
            .collect();
        if resting.is_empty() {
            return free;
        }
        let mut patches: Vec<Patch> = Vec::new();
        for (k, site) in resting.iter().enumerate() {
            let t = &site.touch;
            if let Some(patch) = patches.iter_mut().find(|p| {
                let first = &resting[p.points[0]].touch;
                (first.body, first.other) == (t.body, t.other)
                    && first.normal.dot(t.normal) > 1.0 - 1e-9
            }) {
                patch.points.push(k);
            } else {
                let slip = t.normal.perp().dot(site.relative_velocity(poses));
                patches.push(Patch {
                    points: vec![k],
                    sliding: (slip.abs() > still).then(|| -slip.signum()),
                });
            }
        }
        for _ in 0..=patches.len() {
            let Some(held) = self.forces(poses, &resting, &patches) else {
                return free;
            };
            // A sticking patch that needs more friction than μ N slides, the friction
            // then pushing the way it was needed.
            let slipping = patches.iter().enumerate().find_map(|(p, patch)| {
                let (grip, normal) = held.totals[p];
                let mu = resting[patch.points[0]].static_friction;
                (patch.sliding.is_none() && grip.abs() > mu * normal * (1.0 + 1e-12))
                    .then_some((p, grip))
            });
            if let Some((p, grip)) = slipping {
                patches[p].sliding = Some(grip.signum());
                continue;
            }
            let slides = patches
                .iter()
                .zip(&held.totals)
                .filter(|(p, _)| p.sliding.is_some())
                .map(|(p, &(_, normal))| {
                    let site = resting[p.points[0]];
                    let tangent = site.touch.normal.perp();
                    Slide {
                        speed: tangent.dot(site.relative_velocity(poses)),
                        acceleration: tangent.dot(relative_acceleration(site, poses, &held.pushes)),
                        force: site.friction * normal,
                    }
                })
                .collect();
            return Held {
                pushes: held.pushes,
                slides,
                applied: held.applied,
            };
        }
        free
    }

    /// The forces for the patches as they are (sticking or sliding): the bodies'
    /// accelerations, each patch's friction and total normal force, each force where it
    /// acts.
    fn forces(&self, poses: &[Pose], resting: &[&Site], patches: &[Patch]) -> Option<Forces> {
        let n = resting.len();
        let sticking: Vec<usize> = (0..patches.len())
            .filter(|&p| patches[p].sliding.is_none())
            .collect();
        let sliding_of = |k: usize| {
            patches
                .iter()
                .find(|p| p.points.contains(&k))
                .and_then(|p| p.sliding)
        };
        // Each unknown: a unit force along a direction at a site.
        let mut columns: Vec<(&Site, DVec2)> = Vec::new();
        for (k, site) in resting.iter().enumerate() {
            let normal = site.touch.normal;
            let mut force = normal;
            if let Some(direction) = sliding_of(k) {
                force += normal.perp() * (direction * site.friction);
            }
            columns.push((site, force));
        }
        for &p in &sticking {
            let site = resting[patches[p].points[0]];
            columns.push((site, site.touch.normal.perp()));
        }
        // Each condition: a site's relative acceleration along a direction.
        let mut rows: Vec<(&Site, DVec2)> = resting.iter().map(|&s| (s, s.touch.normal)).collect();
        rows.extend(sticking.iter().map(|&p| {
            let site = resting[patches[p].points[0]];
            (site, site.touch.normal.perp())
        }));
        let m: Vec<Vec<f64>> = rows
            .iter()
            .map(|&row| {
                columns
                    .iter()
                    .map(|&column| self.response(row, column))
                    .collect()
            })
            .collect();
        let free = self.free();
        let q: Vec<f64> = rows
            .iter()
            .map(|&(site, to)| {
                // A direction on the other body's face turns with it: the term
                // 2 ω (to⊥ · v) of the second derivative of the gap.
                let turning =
                    2.0 * site.turning(poses) * to.perp().dot(site.relative_velocity(poses));
                to.dot(relative_acceleration(site, poses, &free)) + turning
            })
            .collect();
        let x = solve::solve(&m, &q, n)?;
        let mut pushes = free;
        for (&(site, force), &amount) in columns.iter().zip(&x) {
            for end in site.ends.iter().flatten() {
                let member = &self.members[end.body];
                let f = force * (amount * end.sign);
                pushes[end.body].linear += f * member.inverse_mass();
                pushes[end.body].angular += end.arm.perp_dot(f) * member.inverse_inertia();
            }
        }
        let applied = applied(resting, patches, &sticking, &x);
        let totals = patches
            .iter()
            .enumerate()
            .map(|(p, patch)| {
                let normal: f64 = patch.points.iter().map(|&k| x[k]).sum();
                let grip = sticking
                    .iter()
                    .position(|&s| s == p)
                    .map_or(0.0, |s| x[n + s]);
                (grip, normal)
            })
            .collect();
        Some(Forces {
            pushes,
            totals,
            applied,
        })
    }
}

/// Each contact force where it acts, on each body it acts on (its reaction on the
/// other), from the solved amounts `x`: the resting points' normal forces (and their
/// sliding friction), then the sticking patches' friction.
fn applied(
    resting: &[&Site],
    patches: &[Patch],
    sticking: &[usize],
    x: &[f64],
) -> Vec<(usize, Applied)> {
    let n = resting.len();
    let mut applied = Vec::new();
    let mut act = |site: &Site, force: DVec2, friction: bool| {
        for end in site.ends.iter().flatten() {
            applied.push((
                end.body,
                Applied {
                    arm: end.arm,
                    force: force * end.sign,
                    friction,
                },
            ));
        }
    };
    for (k, site) in resting.iter().enumerate() {
        let (normal, amount) = (site.touch.normal, x[k]);
        act(site, normal * amount, false);
        let sliding = patches
            .iter()
            .find(|p| p.points.contains(&k))
            .and_then(|p| p.sliding);
        if let Some(direction) = sliding {
            act(
                site,
                normal.perp() * (direction * site.friction * amount),
                true,
            );
        }
    }
    for (s, &p) in sticking.iter().enumerate() {
        let site = resting[patches[p].points[0]];
        act(site, site.touch.normal.perp() * x[n + s], true);
    }
    applied
}

/// The acceleration of a site's point on its body relative to the other's under
/// `pushes`, the spins' centripetal terms included.
fn relative_acceleration(site: &Site, poses: &[Pose], pushes: &[Push]) -> DVec2 {
    site.ends
        .iter()
        .flatten()
        .map(|e| {
            let (push, spin) = (pushes[e.body], poses[e.body].spin);
            (push.linear + push.angular * e.arm.perp() - spin * spin * e.arm) * e.sign
        })
        .sum()
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

/// A patch sliding: its slip speed along its tangent and how that changes, for locating
/// the instant it stops.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Slide {
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

/// The points of a body resting on one solid or one other body, with one normal:
/// friction acts on the patch as a whole (along a face its torque about either centroid
/// is the same wherever along the patch it acts, so its share between the points is not
/// needed).
struct Patch {
    /// Indices into the resting sites.
    points: Vec<usize>,
    /// `None` while it sticks, else the friction's direction along the tangent (+1/−1).
    sliding: Option<f64>,
}

/// What the contact forces come to: the bodies' accelerations, each patch's friction and
/// total normal force, and each force where it acts.
struct Forces {
    pushes: Vec<Push>,
    totals: Vec<(f64, f64)>,
    applied: Vec<(usize, Applied)>,
}

/// The forces found: the bodies' accelerations, the patches that slide, each force where
/// it acts.
struct Held {
    pushes: Vec<Push>,
    slides: Vec<Slide>,
    applied: Vec<(usize, Applied)>,
}

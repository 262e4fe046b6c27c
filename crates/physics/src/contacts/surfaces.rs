//! The contacts at the start of a step: what touches (pairs of particles, particles on
//! ramps and walls), the impacts happening right now (a struck row of balls passes its
//! blow along here), and the normal force and friction of particles resting on surfaces,
//! which join the smooth forces for the step.

// Particle indices are u32 in the contact lists, as in the module above.
#![expect(
    clippy::cast_possible_truncation,
    reason = "u32 particle indices, see contacts/mod.rs"
)]

use glam::DVec2;

use super::broad_phase::Aabb;
use super::resting::settled_speed;
use super::strips::strip_count;
use super::{
    Applied, Contacts, Impact, TOUCHING, fat_margin, half_thickness, larger, particles_of,
    separation, velocity_changes,
};
use crate::forces::normal::Grip;
use crate::forces::{ForceModel, SurfaceContact};
use crate::profile::{Profiler, Stage};
use crate::state::State;
use crate::tuning::ROLLING;
use crate::turning::{Mode, Turning};

/// What touches at the start of the step: the resting solver's rows, and what the
/// impact search leaves alone.
#[derive(Clone, Debug, Default)]
pub(super) struct StartContacts {
    /// Pairs (i < j) touching, ascending.
    pub pairs: Vec<(u32, u32)>,
    /// (particle, obstacle) touching, ascending.
    pub surfaces: Vec<(u32, u32)>,
    /// Scratch: each touching contact and its normal.
    pub normals: Normals,
    /// Per surface contact, in `surfaces`' order: the friction its smooth normal force
    /// could still give, m/s² (μ times how hard the other forces press, less what rolling
    /// or holding still takes of it; none for one slipping, or not pressed). The resting
    /// solver's friction may take it besides μ times its own pushes.
    pub spare_friction: Vec<f64>,
}

impl StartContacts {
    /// Whether particles `p` and `q` touch (a search in the ascending list: asked only
    /// after a strike inside the step, for the struck particle's neighbours, so a lookup
    /// table built every step cost more than it saved).
    pub fn touch(&self, p: usize, q: usize) -> bool {
        let pair = (p.min(q) as u32, p.max(q) as u32);
        self.pairs.binary_search(&pair).is_ok()
    }
}

impl Contacts {
    /// Finds what touches at the start of a step of `h`, applies the impacts happening now
    /// (a struck row of balls passes the blow along here), and puts particles resting on
    /// surfaces under their normal force. Returns whether velocities or the forces
    /// changed.
    pub fn begin_step(
        &mut self,
        state: &mut State,
        forces: &mut ForceModel,
        h: f64,
        profiler: &mut Profiler,
    ) -> bool {
        let had_surface_contacts = !forces.surface_contacts.is_empty();
        self.report.clear();
        forces.surface_contacts.clear();
        self.find_touching(state, forces, h, profiler);
        let resting_speed = self.resting_speed(h);
        let mut changed = self.impacts_now(state, forces, resting_speed);
        // Friction needs to know how hard the other forces press and pull.
        let frictional = self
            .touching
            .surfaces
            .iter()
            .any(|&(_, k)| self.obstacles[k as usize].friction > 0.0);
        let mut free = Vec::new();
        if frictional {
            free.resize(state.len(), DVec2::ZERO);
            forces.accelerations(state.time, &state.position, &state.velocity, &mut free);
        }
        if let Some(turning) = &mut self.turning {
            turning.mode.fill(Mode::Free);
        }
        let spare = &mut self.touching.spare_friction;
        spare.clear();
        spare.resize(self.touching.surfaces.len(), 0.0);
        for (&(p, k), spare) in self.touching.surfaces.iter().zip(spare) {
            let (p, obstacle) = (p as usize, &self.obstacles[k as usize]);
            // Measured again, not taken from the touching test: sitting on an earlier
            // surface (a wall beside a ramp) may have moved the ball.
            let (distance, normal) = obstacle.shape.distance(state.position[p]);
            let approach = -state.velocity[p].dot(normal);
            if approach < -resting_speed {
                continue; // leaving the surface
            }
            if approach > 0.0 {
                state.velocity[p] += normal * approach;
                changed = true;
            }
            if distance < self.radius[p] {
                // Sit exactly on the surface.
                state.position[p] += normal * (self.radius[p] - distance);
            }
            let tangential = state.velocity[p] - normal * state.velocity[p].dot(normal);
            // A turning particle rolls or slips on the first surface with friction it
            // rests on; on any other, friction acts on it as on a point.
            let turning = self.turning.as_mut().filter(|turning| {
                obstacle.friction > 0.0 && turning.inertia[p] > 0.0 && turning.mode[p] == Mode::Free
            });
            let grip = turning.and_then(|turning| {
                let surface = Surface {
                    normal,
                    friction: obstacle.friction,
                    settled: settled_speed(resting_speed),
                };
                let velocity = &mut state.velocity[p];
                roll_or_slip(turning, p, surface, free[p], velocity, self.radius[p])
            });
            // How hard the other forces press it in and pull it along (none are asked
            // for where no surface has friction).
            let (pressing, pull) = free.get(p).map_or((0.0, DVec2::ZERO), |&a| {
                (-a.dot(normal), a - normal * a.dot(normal))
            });
            let limit = obstacle.friction * pressing.max(0.0);
            let sliding = if let Some(grip) = grip {
                if let Grip::Rolls { share } = grip {
                    *spare = larger(limit - (pull.length() * share), 0.0);
                }
                None
            } else if obstacle.friction > 0.0 {
                if tangential.length() <= limit * h && pull.length() <= limit {
                    // Friction stops it within this step and can hold it: static.
                    state.velocity[p] -= tangential;
                    changed |= tangential != DVec2::ZERO;
                    *spare = limit - pull.length();
                    None
                } else {
                    // Sliding, or about to start sliding the way it is pulled.
                    tangential.try_normalize().or_else(|| pull.try_normalize())
                }
            } else {
                None
            };
            forces.surface_contacts.push(SurfaceContact {
                particle: p,
                normal,
                friction: obstacle.friction,
                sliding,
                turning: grip,
            });
        }
        changed |= decide_tied_friction(state, forces, h);
        profiler.lap(Stage::StartContacts);
        changed || had_surface_contacts || !forces.surface_contacts.is_empty()
    }

    /// Fills the touching lists from the current positions.
    fn find_touching(
        &mut self,
        state: &State,
        forces: &ForceModel,
        h: f64,
        profiler: &mut Profiler,
    ) {
        let n = state.len();
        profiler.lap(Stage::StartContacts);
        self.boxes.clear();
        self.boxes.extend(
            (0..n).map(|i| Aabb::around(&[state.position[i]], self.radius[i] * (1.0 + TOUCHING))),
        );
        let radius = &self.radius;
        let (position, velocity) = (&state.position, &state.velocity);
        self.touching.pairs.clear();
        // Without collisions no pair of particles touches: the broad phase is not asked.
        let candidates: &[(u32, u32)] = if self.collisions {
            self.proxies.update(
                &self.boxes,
                |i| fat_margin(radius[i], velocity[i], h),
                |i, j| forces.is_fixed(i) && forces.is_fixed(j),
                &self.workers,
            )
        } else {
            &[]
        };
        let normals = &mut self.touching.normals.pairs;
        normals.clear();
        // Each candidate is tested on its own: pieces of the list go to different threads
        // and the pairs found join in the list's order.
        self.workers
            .collect_into(candidates.len(), normals, |range, normals| {
                // A plain loop: as an iterator's filter the test was a call through a
                // reference to the closure in WebAssembly, seen in V8's profile of the pit
                // (`benches/wasm`).
                for &(i, j) in &candidates[range] {
                    let (a, b) = (i as usize, j as usize);
                    let reach = radius[a] + radius[b];
                    let offset = position[b] - position[a];
                    // The squared distance first (no square root for the many
                    // candidates that are clearly apart), with room to spare for its
                    // rounding: the test after it decides.
                    let within = reach * (1.0 + 2.0 * TOUCHING);
                    if offset.length_squared() <= within * within {
                        let (distance, normal) = separation(offset);
                        if distance - reach <= TOUCHING * reach {
                            normals.push((i, j, normal));
                        }
                    }
                }
            });
        self.touching
            .pairs
            .extend(normals.iter().map(|&(i, j, _)| (i, j)));
        profiler.lap(Stage::BroadPhase);
        self.touching.surfaces.clear();
        for p in (0..n).filter(|&p| !forces.is_fixed(p)) {
            let near = self.obstacles_near(&self.boxes[p]);
            for (k, obstacle) in self.obstacles[..near].iter().enumerate() {
                if obstacle
                    .shape
                    .clear_of_box(self.boxes[p].min, self.boxes[p].max)
                {
                    continue;
                }
                let reach = self.radius[p] + half_thickness(&obstacle.shape);
                if obstacle.shape.distance(position[p]).0 - self.radius[p] <= TOUCHING * reach {
                    self.touching.surfaces.push((p as u32, k as u32));
                }
            }
        }
    }

    /// Applies every impact between touching things that approach faster than
    /// `resting_speed`, pass after pass until none does. A contact still approaching after
    /// many passes (a ball squeezed between two others) is made inelastic, which ends it.
    fn impacts_now(&mut self, state: &mut State, forces: &ForceModel, resting_speed: f64) -> bool {
        // Only velocities change here, so each contact's normal is found once (a pair's
        // when it was found touching). Each pass sweeps the pairs, then the surfaces,
        // each in a tight loop of its own (one list of both kinds is slower to sweep in
        // the browser).
        let mut normals = std::mem::take(&mut self.touching.normals);
        normals.surfaces.clear();
        if let Some(turning) = &mut self.turning {
            turning.mode.fill(Mode::Free);
        }
        for &(p, k) in &self.touching.surfaces {
            let normal = self
                .measure(Impact::Obstacle(p as usize, k as usize), state)
                .1;
            normals.surfaces.push((p, k, normal));
        }
        let max_passes = 2 * state.len() + 8;
        let mut changed = false;
        let strips = strip_count(state.len());
        // Turning particles' spins are swept with their velocities: in one strip. Without
        // touching pairs every order gives the same bits (each surface moves only its
        // own particle), and the strips are not needed.
        if strips > 1 && self.turning.is_none() && !normals.pairs.is_empty() {
            let mut cut = std::mem::take(&mut self.strips);
            cut.cut(
                strips,
                (&state.position, &state.velocity),
                &normals.pairs,
                &normals.surfaces,
            );
            for pass in 0..=max_passes {
                let any = self.sweep_strips(&mut cut, forces, resting_speed, pass == max_passes);
                changed |= any;
                if !any {
                    break;
                }
            }
            cut.velocities_into(&mut state.velocity);
            self.strips = cut;
            self.touching.normals = normals;
            return changed;
        }
        // Only a log of impacts and turning particles' books read the impacts at the
        // step's start; without them a strike is its velocity changes alone.
        let keep = self.logs_start || self.turning.is_some();
        for pass in 0..=max_passes {
            let inelastic = pass == max_passes;
            let mut any = false;
            let mut strike = |this: &mut Self, impact, normal, approach, state: &mut State| {
                if keep {
                    let applied = this.at_start(impact, approach, resting_speed, inelastic);
                    this.strike(applied, normal, state, forces);
                } else {
                    let (first, second) = particles_of(impact);
                    let kick =
                        this.kick_now(impact, (normal, approach), resting_speed, inelastic, forces);
                    state.velocity[first] += kick.0;
                    if let Some(j) = second {
                        state.velocity[j] += kick.1;
                    }
                }
                any = true;
            };
            for &(i, j, normal) in &normals.pairs {
                let (i, j) = (i as usize, j as usize);
                let approach = (state.velocity[i] - state.velocity[j]).dot(normal);
                if approach > resting_speed {
                    strike(self, Impact::Pair(i, j), normal, approach, state);
                }
            }
            for &(p, k, normal) in &normals.surfaces {
                let p = p as usize;
                let approach = -state.velocity[p].dot(normal);
                if approach > resting_speed {
                    strike(
                        self,
                        Impact::Obstacle(p, k as usize),
                        normal,
                        approach,
                        state,
                    );
                }
            }
            changed |= any;
            if !any {
                break;
            }
        }
        self.touching.normals = normals;
        changed
    }
}

impl Contacts {
    /// The restitution of an impact at the step's start approaching at `approach`: none
    /// in the last pass (`inelastic`).
    pub(super) fn restitution_now(
        &self,
        impact: Impact,
        approach: f64,
        resting_speed: f64,
        inelastic: bool,
    ) -> f64 {
        if inelastic {
            0.0
        } else {
            self.restitution_at(impact, approach, resting_speed)
        }
    }

    /// The velocity changes of an impact at the step's start approaching at `approach`
    /// along `normal`, between particles that do not turn: [`Self::impulse`]'s, to the
    /// bit, without the record.
    pub(super) fn kick_now(
        &self,
        impact: Impact,
        (normal, approach): (DVec2, f64),
        resting_speed: f64,
        inelastic: bool,
        forces: &ForceModel,
    ) -> (DVec2, DVec2) {
        let restitution = self.restitution_now(impact, approach, resting_speed, inelastic);
        let change = approach * (1.0 + restitution);
        let (first, second) = velocity_changes(impact, normal, change, forces);
        // Friction's part, none, added as `impulse` adds it: a zero's sign included.
        (first + DVec2::ZERO, second + DVec2::ZERO)
    }

    /// An impact at the step's start approaching at `approach`, its impulse not yet
    /// worked out: with its restitution, or none in the last pass (`inelastic`).
    pub(super) fn at_start(
        &self,
        impact: Impact,
        approach: f64,
        resting_speed: f64,
        inelastic: bool,
    ) -> Applied {
        Applied {
            time: 0.0,
            impact,
            approach,
            restitution: self.restitution_now(impact, approach, resting_speed, inelastic),
            grip: crate::turning::Grip::default(),
            kick: (DVec2::ZERO, DVec2::ZERO),
            tied: None,
        }
    }
}

/// The surface a turning particle rests on, as [`roll_or_slip`] needs it: its unit
/// `normal` (towards the particle), its coefficient of `friction`, and the resting
/// solver's [`settled_speed`] for the step.
#[derive(Clone, Copy, Debug)]
struct Surface {
    normal: DVec2,
    friction: f64,
    settled: f64,
}

/// How turning particle `p`, resting on `surface`, with the other forces accelerating it
/// by `free` and moving at `velocity` (its radius `radius`), turns through the step: it
/// rolls when its contact point does not slip and rolling needs at most μN, and slips
/// otherwise, with μN against the slip (or, not slipping, against the pull that makes
/// it). `None` when the surface does not press on it.
///
/// Not slipping: to [`ROLLING`] of its speeds (the slip left where a rolling start was
/// located; the spin is set to roll exactly), or, slower, below the resting solver's
/// [`Surface::settled`] speed, which is what the sweeps leave on a disc held in a pile or
/// a corner (some 1e-9 m/s): friction takes that slip at once, the impulse it would
/// give over the 1e-10 s it would take, so the disc rolls on (or rests) instead of
/// slipping through the step under full kinetic friction that the solver then takes
/// back. Its position differs from slipping's by slip² / 2a, some 1e-13 m at most.
fn roll_or_slip(
    turning: &mut Turning,
    p: usize,
    surface: Surface,
    free: DVec2,
    velocity: &mut DVec2,
    radius: f64,
) -> Option<Grip> {
    let normal = surface.normal;
    let pressing = -free.dot(normal);
    if pressing.is_nan() || pressing <= 0.0 {
        return None;
    }
    let (tangent, k) = (normal.perp(), turning.inertia[p]);
    let limit = surface.friction * pressing;
    let (pull, along, rim) = (
        free.dot(tangent),
        velocity.dot(tangent),
        turning.spin[p] * radius,
    );
    // The contact point's velocity along the tangent: v·t + (ω × −r n)·t = v·t − ω r.
    let slip = along - rim;
    let share = k / (1.0 + k);
    let rolls = slip.abs() <= ROLLING * (along.abs() + rim.abs());
    let settled = !rolls && slip.abs() <= surface.settled;
    if (rolls || settled) && (pull * share).abs() <= limit {
        if settled {
            // The friction impulse (per unit mass) −s k/(1 + k) that stops the slip s:
            // the speed along the tangent changes by it, the rim's by −1/k of it, and
            // the spin set below to roll is the one it leaves.
            *velocity -= tangent * (slip * share);
        }
        let along = velocity.dot(tangent);
        turning.spin[p] = along / radius;
        turning.mode[p] = Mode::Rolls {
            tangent,
            speed: along,
        };
        return Some(Grip::Rolls { share });
    }
    let against = -limit
        * if rolls || settled {
            pull.signum()
        } else {
            slip.signum()
        };
    turning.mode[p] = Mode::Slips {
        tangent,
        friction: against,
        // The friction m f t at the contact point −r n turns it by −m f r: I α = −m f r.
        angular: -against / (k * radius),
    };
    Some(Grip::Slips { friction: against })
}

/// The touching contacts' normals at the step's start, as [`Contacts::impacts_now`]
/// sweeps them: (i, j, normal from i towards j) and (particle, obstacle, normal from the
/// surface).
#[derive(Clone, Debug, Default)]
pub(super) struct Normals {
    pairs: Vec<(u32, u32, DVec2)>,
    surfaces: Vec<(u32, u32, DVec2)>,
}

/// Friction on particles that rods or strings hold against a surface, decided again on
/// what the links and the surfaces leave of the pull together: the links alone leave a
/// pull along the surface that the surface's normal force, answering with them, takes
/// (a pendulum pressed against a wall would slide in its friction's books while it
/// rests). Returns whether a velocity changed.
fn decide_tied_friction(state: &mut State, forces: &mut ForceModel, h: f64) -> bool {
    let frictional = |c: &SurfaceContact| c.friction > 0.0 && c.turning.is_none();
    if forces.constraints.is_empty() || !forces.surface_contacts.iter().any(frictional) {
        return false;
    }
    let kept = forces.surface_contacts.clone();
    for contact in &mut forces.surface_contacts {
        contact.friction = 0.0;
    }
    let mut held = vec![DVec2::ZERO; state.len()];
    let pressed =
        forces.accelerations_off_surfaces(state.time, &state.position, &state.velocity, &mut held);
    forces.surface_contacts = kept;
    let mut changed = false;
    for (k, contact) in forces.surface_contacts.iter_mut().enumerate() {
        let Some(pressing) = pressed.get(k).copied().flatten() else {
            continue; // no link holds it: decided as any particle's
        };
        if !frictional(contact) {
            continue;
        }
        let (p, normal) = (contact.particle, contact.normal);
        let tangential = state.velocity[p] - normal * state.velocity[p].dot(normal);
        let pull = held[p] - normal * held[p].dot(normal);
        let limit = contact.friction * pressing.max(0.0);
        contact.sliding = if tangential.length() <= limit * h && pull.length() <= limit {
            state.velocity[p] -= tangential;
            changed |= tangential != DVec2::ZERO;
            None
        } else {
            tangential.try_normalize().or_else(|| pull.try_normalize())
        };
    }
    changed
}

//! The impacts happening at a step's start, for many particles swept strip by strip so
//! that threads can share the sweep.
//!
//! The particles are cut into strips of equal width across the longer side of the box
//! around them, as many as the particle count sets ([`strip_count`]: never the thread
//! count). Each pass of the sweep ([`Contacts::impacts_now`]) takes each strip's own
//! contacts (its pairs, then its particles' surfaces, each in ascending order) and then
//! the pairs across strips, in ascending order. No two strips share a particle, so
//! sweeping the strips on different threads gives the bits of sweeping them one after
//! another: a pass is a Gauss–Seidel sweep in an order fixed by the positions alone. The
//! bits change once, at [`STRIPS_FROM`] particles, where that order replaces the
//! ascending one, and never with the number of threads.
//!
//! The strips' share of the contacts is what threads can split; the pairs across strips
//! are swept on one thread. Strips a few balls wide leave some 5–10 % of a pile's pairs
//! across them (`bench --scene pit`).

// Particle indices are u32 in the contact lists, as in the module above.
#![expect(
    clippy::cast_possible_truncation,
    reason = "u32 particle indices, see contacts/mod.rs"
)]

use glam::DVec2;

use super::{Applied, Contacts, Impact};
use crate::forces::ForceModel;
use crate::tuning::{PARTICLES_PER_STRIP, STRIPS, STRIPS_FROM};

/// How many strips `n` particles are cut into: one below [`STRIPS_FROM`].
pub(super) fn strip_count(n: usize) -> usize {
    if n < STRIPS_FROM {
        1
    } else {
        (n / PARTICLES_PER_STRIP).clamp(2, STRIPS)
    }
}

/// The strips of a sweep and the pairs across them. The particles are laid out strip
/// after strip (ascending within each), so that each strip's velocities are one slice.
#[derive(Clone, Debug, Default)]
pub(super) struct Strips {
    /// Each place's particle.
    particles: Vec<u32>,
    /// The velocities by place, swept.
    velocity: Vec<DVec2>,
    /// Each strip's first place, and the end.
    starts: Vec<usize>,
    each: Vec<Strip>,
    /// The touching pairs whose particles lie in different strips, by place, ascending.
    across: Vec<(u32, u32, DVec2)>,
    /// Scratch: each particle's strip, then its place.
    place: Vec<u32>,
}

/// One strip's contacts through a sweep.
#[derive(Clone, Debug, Default)]
struct Strip {
    /// Touching pairs inside the strip, by place counted from the strip's first,
    /// ascending, with the normal from the first towards the second.
    pairs: Vec<(u32, u32, DVec2)>,
    /// The strip's particles' touching surfaces: (place counted from the strip's first,
    /// obstacle, normal from the surface).
    surfaces: Vec<(u32, u32, DVec2)>,
    /// The impacts applied in the pass being swept, in order, when they are kept.
    applied: Vec<Applied>,
    /// Whether the pass struck anything.
    struck: bool,
}

/// What every strike of a pass needs to know.
#[derive(Clone, Copy)]
struct Pass<'a> {
    contacts: &'a Contacts,
    forces: &'a ForceModel,
    resting_speed: f64,
    /// The last pass, where whatever still approaches is stopped.
    inelastic: bool,
    /// Whether the impacts are kept ([`Contacts::logs_start`]).
    keep: bool,
}

impl Pass<'_> {
    /// The velocity changes of the impact `impact` approaching at `approach` along
    /// `normal` (the paper's 8–10 or 17–22, without friction: no particle in a strip
    /// sweep turns), and the impact as applied pushed to `applied` when impacts are kept.
    fn strike(
        self,
        impact: Impact,
        normal: DVec2,
        approach: f64,
        applied: &mut Vec<Applied>,
    ) -> (DVec2, DVec2) {
        let kick = self.contacts.kick_now(
            impact,
            (normal, approach),
            self.resting_speed,
            self.inelastic,
            self.forces,
        );
        if self.keep {
            let at_start =
                self.contacts
                    .at_start(impact, approach, self.resting_speed, self.inelastic);
            applied.push(Applied { kick, ..at_start });
        }
        kick
    }

    /// Sweeps a strip's contacts once: its particles are `particles`, moving at
    /// `velocity`; its strikes are left in its `applied`.
    fn sweep(self, (velocity, particles, strip): &mut (&mut [DVec2], &[u32], &mut Strip)) {
        let Strip {
            pairs,
            surfaces,
            applied,
            struck,
        } = strip;
        *struck = false;
        for &(a, b, normal) in pairs.iter() {
            let (a, b) = (a as usize, b as usize);
            let approach = (velocity[a] - velocity[b]).dot(normal);
            if approach > self.resting_speed {
                let impact = Impact::Pair(particles[a] as usize, particles[b] as usize);
                let kick = self.strike(impact, normal, approach, applied);
                velocity[a] += kick.0;
                velocity[b] += kick.1;
                *struck = true;
            }
        }
        for &(a, k, normal) in surfaces.iter() {
            let a = a as usize;
            let approach = -velocity[a].dot(normal);
            if approach > self.resting_speed {
                let impact = Impact::Obstacle(particles[a] as usize, k as usize);
                let kick = self.strike(impact, normal, approach, applied);
                velocity[a] += kick.0;
                *struck = true;
            }
        }
    }
}

impl Strips {
    /// Cuts `velocity.len()` particles at `position` into `count` strips and shares the
    /// touching `pairs` (i < j, ascending) and `surfaces` (particle, obstacle, ascending)
    /// out among them.
    pub fn cut(
        &mut self,
        count: usize,
        (position, velocity): (&[DVec2], &[DVec2]),
        pairs: &[(u32, u32, DVec2)],
        surfaces: &[(u32, u32, DVec2)],
    ) {
        let (low, high) = position.iter().fold(
            (DVec2::splat(f64::INFINITY), DVec2::splat(f64::NEG_INFINITY)),
            |(low, high), x| (low.min(*x), high.max(*x)),
        );
        let extent = high - low;
        let (along, from, width) = if extent.x >= extent.y {
            (DVec2::X, low.x, extent.x)
        } else {
            (DVec2::Y, low.y, extent.y)
        };
        // Equal widths; the last strip takes the far edge. Without a width, one strip.
        let scale = if width > 0.0 {
            count as f64 / width
        } else {
            0.0
        };
        // A counting sort by strip, ascending within each.
        self.starts.clear();
        self.starts.resize(count + 1, 0);
        self.place.clear();
        for x in position {
            #[expect(
                clippy::cast_sign_loss,
                reason = "at least zero: measured from the lowest position"
            )]
            let s = (((x.dot(along) - from) * scale) as usize).min(count - 1);
            self.place.push(s as u32);
            self.starts[s + 1] += 1;
        }
        for s in 0..count {
            self.starts[s + 1] += self.starts[s];
        }
        let mut next = self.starts.clone();
        self.particles.resize(position.len(), 0);
        self.velocity.resize(position.len(), DVec2::ZERO);
        for (p, place) in self.place.iter_mut().enumerate() {
            let s = *place as usize;
            *place = next[s] as u32;
            self.particles[next[s]] = p as u32;
            self.velocity[next[s]] = velocity[p];
            next[s] += 1;
        }
        self.each.resize_with(count, Strip::default);
        for strip in &mut self.each {
            strip.pairs.clear();
            strip.surfaces.clear();
            strip.applied.clear();
        }
        // The strip a place lies in: the places are in strip order.
        let strip_of = |place: u32| {
            self.starts
                .partition_point(|&start| start <= place as usize)
                - 1
        };
        self.across.clear();
        for &(i, j, normal) in pairs {
            let (a, b) = (self.place[i as usize], self.place[j as usize]);
            let s = strip_of(a);
            let end = self.starts[s + 1] as u32;
            if b >= self.starts[s] as u32 && b < end {
                let start = self.starts[s] as u32;
                self.each[s].pairs.push((a - start, b - start, normal));
            } else {
                self.across.push((a, b, normal));
            }
        }
        for &(p, k, normal) in surfaces {
            let a = self.place[p as usize];
            let s = strip_of(a);
            let start = self.starts[s] as u32;
            self.each[s].surfaces.push((a - start, k, normal));
        }
    }

    /// The velocities swept, written back to `velocity` by particle.
    pub fn velocities_into(&self, velocity: &mut [DVec2]) {
        for (&p, v) in self.particles.iter().zip(&self.velocity) {
            velocity[p as usize] = *v;
        }
    }
}

impl Contacts {
    /// One pass of the sweep over `strips` ([`Contacts::impacts_now`]): the strips on the
    /// workers' threads, then the pairs across them; the impacts applied are appended to
    /// the step's in that order. Returns whether anything was struck.
    pub(super) fn sweep_strips(
        &mut self,
        strips: &mut Strips,
        forces: &ForceModel,
        resting_speed: f64,
        inelastic: bool,
    ) -> bool {
        let mut applied = std::mem::take(&mut self.report.applied);
        let pass = Pass {
            contacts: self,
            forces,
            resting_speed,
            inelastic,
            keep: self.logs_start,
        };
        let Strips {
            particles,
            velocity,
            starts,
            each,
            across,
            ..
        } = strips;
        let mut pieces = Vec::with_capacity(each.len());
        let mut rest = velocity.as_mut_slice();
        for (k, strip) in each.iter_mut().enumerate() {
            let (mine, after) = std::mem::take(&mut rest).split_at_mut(starts[k + 1] - starts[k]);
            pieces.push((mine, &particles[starts[k]..starts[k + 1]], strip));
            rest = after;
        }
        self.workers
            .each_mut(&mut pieces, |piece| pass.sweep(piece));
        let mut any = false;
        for (_, _, strip) in pieces {
            any |= strip.struck;
            applied.append(&mut strip.applied);
        }
        for &(a, b, normal) in across.iter() {
            let (a, b) = (a as usize, b as usize);
            let approach = (velocity[a] - velocity[b]).dot(normal);
            if approach > resting_speed {
                let impact = Impact::Pair(particles[a] as usize, particles[b] as usize);
                let kick = pass.strike(impact, normal, approach, &mut applied);
                velocity[a] += kick.0;
                velocity[b] += kick.1;
                any = true;
            }
        }
        self.report.applied = applied;
        any
    }
}

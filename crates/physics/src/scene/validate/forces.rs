//! The rules of `[[force]]`: expressions that read and name only what a force may, on
//! particles that exist, finite where they start; a potential of the position alone
//! whose −∇U is the force, so that the ledger closes.

use glam::DVec2;

use super::Checker;
use crate::scene::error::Section;
use crate::scene::force::{At, Law};
use crate::scene::{Force, Particle, say};

/// How far −∇U (by central differences) may differ from the force at a particle's start,
/// relative to their size: the differences' own error is some 1e-8 of it, a wrong sign
/// or factor is of order one.
const GRADIENT_AGREES: f64 = 1e-5;

impl Checker<'_> {
    pub(super) fn forces(&mut self) {
        let scene = self.scene;
        for (i, force) in scene.forces.iter().enumerate() {
            let s = Section::Force(i);
            let mut read = |key: &'static str, text: &str, potential: bool| match Law::parse(
                text, potential,
            ) {
                Ok(law) => Some(law),
                Err(reason) => {
                    self.report(s, key, &reason);
                    None
                }
            };
            let fx = read("fx", &force.fx, false);
            let fy = read("fy", &force.fy, false);
            let potential = force
                .potential
                .as_deref()
                .and_then(|u| read("potential", u, true));
            let on: Vec<&Particle> = self
                .acted_on(s, force)
                .into_iter()
                .map(|k| &scene.particles[k])
                .collect();
            let (Some(fx), Some(fy)) = (fx, fy) else {
                continue;
            };
            let t = scene.simulation.start_time;
            for particle in &on {
                let at = at_start(particle, t);
                let f = DVec2::new(fx.at(&at), fy.at(&at));
                if !f.is_finite() {
                    let words = say(
                        "scene-force-not-finite",
                        &[
                            ("particle", &particle.name),
                            ("x", &format!("{}", f.x)),
                            ("y", &format!("{}", f.y)),
                        ],
                    );
                    self.report(s, if f.x.is_finite() { "fy" } else { "fx" }, &words);
                    break;
                }
            }
            let Some(potential) = potential else {
                continue;
            };
            if fx.varies_with_motion() || fy.varies_with_motion() {
                self.report(s, "potential", &say("scene-force-potential-of-motion", &[]));
                continue;
            }
            for particle in &on {
                let at = at_start(particle, t);
                let f = DVec2::new(fx.at(&at), fy.at(&at));
                let slope = minus_gradient(&potential, at);
                let scale = f.length() + slope.length();
                // A gradient that is not finite (NaN) disagrees too.
                let agrees = (f - slope).length() <= GRADIENT_AGREES * scale;
                if f.is_finite() && !agrees {
                    let words = say(
                        "scene-force-potential-mismatch",
                        &[
                            ("particle", &particle.name),
                            ("ux", &six_places(slope.x)),
                            ("uy", &six_places(slope.y)),
                            ("fx", &six_places(f.x)),
                            ("fy", &six_places(f.y)),
                        ],
                    );
                    self.report(s, "potential", &words);
                    break;
                }
            }
        }
    }

    /// The indices of the particles `force` acts on; a name that is no particle is
    /// reported.
    fn acted_on(&mut self, s: Section, force: &Force) -> Vec<usize> {
        if force.on.is_empty() {
            return (0..self.scene.particles.len()).collect();
        }
        let mut on = Vec::new();
        for name in &force.on {
            if let Some(&k) = self.names.get(name.as_str()) {
                on.push(k);
            } else if self.scene.bodies.iter().any(|b| b.name == *name) {
                self.report(s, "on", &say("scene-force-on-body", &[("name", name)]));
            } else {
                self.report(s, "on", &say("scene-force-on-nothing", &[("name", name)]));
            }
        }
        on
    }
}

/// `particle` where it starts, at time `t`.
fn at_start(particle: &Particle, t: f64) -> At {
    At {
        t,
        position: particle.position.to_dvec2(),
        velocity: particle.initial_velocity(),
        mass: particle.mass,
        charge: particle.charge,
    }
}

/// −∇U at `at`, by central differences over a thousandth of a millimetre per metre.
fn minus_gradient(potential: &Law, at: At) -> DVec2 {
    let h = 1e-6 * at.position.length().max(1.0);
    let u = |d: DVec2| {
        potential.at(&At {
            position: at.position + d,
            ..at
        })
    };
    let dx = (u(DVec2::new(h, 0.0)) - u(DVec2::new(-h, 0.0))) / (2.0 * h);
    let dy = (u(DVec2::new(0.0, h)) - u(DVec2::new(0.0, -h))) / (2.0 * h);
    -DVec2::new(dx, dy)
}

/// `x` to six decimal places, a value that rounds to zero written without a sign (not
/// "-0.000000").
fn six_places(x: f64) -> String {
    let text = format!("{x:.6}");
    if text
        .trim_start_matches('-')
        .bytes()
        .all(|b| b == b'0' || b == b'.')
    {
        "0.000000".to_owned()
    } else {
        text
    }
}

//! What a simulation reads out beyond its particles: a quantity's value, the rigid bodies
//! and their joints.

use glam::DVec2;

use super::Simulation;
use crate::bodies::{Applied, JointReadout};
use crate::diagnostics::{self, Diagnostics, ParticleReadout};
use crate::method::Integrator;
use crate::quantity::{
    JointOf, Link, LinkOf, Names, Of, Quantity, Reading, Total, angle_from_down,
};

impl Simulation {
    /// Particle names, in scene order.
    pub fn names(&self) -> &[String] {
        &self.names
    }

    /// Positions, metres.
    pub fn positions(&self) -> &[DVec2] {
        &self.state.position
    }

    /// Velocities, metres per second.
    pub fn velocities(&self) -> &[DVec2] {
        &self.state.velocity
    }

    /// The rods' and strings' names, in scene order (as [`Self::tensions`] lists them).
    pub fn tie_names(&self) -> &[String] {
        &self.tie_names
    }

    /// The springs' names, in scene order.
    pub fn spring_names(&self) -> &[String] {
        &self.spring_names
    }

    /// A rod's, string's or spring's `from` and `to` ends.
    pub fn link_anchors(&self, link: crate::quantity::Link) -> [crate::quantity::Anchor; 2] {
        let (from, to) = match link {
            crate::quantity::Link::Tie(k) => {
                let tie = &self.forces.constraints.links[k];
                (tie.from, tie.to)
            }
            crate::quantity::Link::Spring(k) => {
                let spring = &self.forces.springs[k];
                (spring.from, spring.to)
            }
        };
        [from, to].map(|end| match end {
            crate::constraints::End::Particle(i) => crate::quantity::Anchor::Particle(i),
            crate::constraints::End::Point(p) => crate::quantity::Anchor::Point(p),
        })
    }

    /// Where a rod's, string's or spring's `from` and `to` ends are now, metres.
    pub fn link_ends(&self, link: crate::quantity::Link) -> (DVec2, DVec2) {
        let [from, to] = self.link_anchors(link);
        (
            from.position(&self.state.position),
            to.position(&self.state.position),
        )
    }

    /// Radii, metres.
    pub fn radii(&self) -> &[f64] {
        &self.radius
    }

    /// Whether particle `i` is fixed.
    pub fn is_fixed(&self, i: usize) -> bool {
        self.forces.is_fixed(i)
    }

    /// The integration method.
    pub fn integrator(&self) -> Integrator {
        self.integrator
    }

    /// The time step (for `dopri5` the largest step), seconds.
    pub fn time_step(&self) -> f64 {
        self.time_step
    }

    /// Integration steps taken so far (accepted steps for `dopri5`).
    pub fn steps_taken(&self) -> u64 {
        self.steps
    }

    /// The acceleration of every particle from the smooth forces at this instant, m/s².
    pub fn accelerations(&self) -> Vec<DVec2> {
        // Verlet and dopri5 keep the acceleration at the end of a step for the next one.
        // Dopri5's is at the end state; Verlet's at the end positions and a predicted
        // velocity, the same when no force depends on velocity (no damping, no friction,
        // no rods or strings, whose tension holds a centripetal term). A tree evaluation
        // of 10,000 bodies is saved at every sample the app records.
        let velocity_free = !self.forces.dissipates() && self.forces.constraints.is_empty();
        let kept_is_exact = match self.integrator {
            Integrator::Dopri5 => true,
            Integrator::Verlet => velocity_free,
            _ => false,
        };
        if kept_is_exact && let Some(kept) = &self.work.start_acceleration {
            return kept.clone();
        }
        let mut a = vec![DVec2::ZERO; self.len()];
        self.forces.accelerations(
            self.state.time,
            &self.state.position,
            &self.state.velocity,
            &mut a,
        );
        a
    }

    /// Whether a force of the scene's own has a potential energy ([`crate::Energy::own`]).
    pub fn has_own_potential(&self) -> bool {
        self.forces
            .own
            .iter()
            .any(crate::forces::own::OwnForce::has_potential)
    }

    /// Energies by kind and total momentum at this instant.
    pub fn diagnostics(&self) -> Diagnostics {
        let mut diagnostics = diagnostics::measure(&self.forces, &self.state);
        if let Some(turning) = &self.contacts.turning {
            let (m, w, r) = (&self.forces.mass, &self.forces.inverse_mass, &self.radius);
            diagnostics.energy.kinetic += turning.kinetic_energy(m, w, r);
            diagnostics.angular_momentum += turning.angular_momentum(m, w, r);
        }
        if !self.bodies.is_empty() {
            self.bodies.add_to(&mut diagnostics);
        }
        diagnostics
    }

    /// Everything about particle `i` at this instant; `accelerations` from
    /// [`Self::accelerations`].
    pub fn particle(&self, i: usize, accelerations: &[DVec2]) -> ParticleReadout {
        let mut readout = diagnostics::particle(&self.forces, &self.state, accelerations, i);
        if let Some(turning) = &self.contacts.turning {
            let spin = turning.spin[i];
            readout.spin = spin;
            readout.angle = turning.angle[i];
            // A fixed particle, of infinite inertia, has no energy or momentum to count.
            if !self.forces.is_fixed(i) {
                let moment = turning.moment(i, &self.forces.mass, &self.radius);
                readout.rotational_energy = 0.5 * moment * spin * spin;
                readout.kinetic_energy += readout.rotational_energy;
                readout.angular_momentum += moment * spin;
            }
        }
        readout
    }

    /// Whether any particle turns (has a moment of inertia).
    pub fn turns(&self) -> bool {
        self.contacts.turning.is_some()
    }

    /// Whether particle `i` turns.
    pub fn particle_turns(&self, i: usize) -> bool {
        self.contacts
            .turning
            .as_ref()
            .is_some_and(|turning| turning.inertia[i] > 0.0)
    }

    /// Spins, radians per second counter-clockwise (all 0 when nothing turns).
    pub fn spins(&self) -> Vec<f64> {
        self.contacts
            .turning
            .as_ref()
            .map_or_else(|| vec![0.0; self.len()], |turning| turning.spin.clone())
    }

    /// Orientations, degrees counter-clockwise, unwrapped (all 0 when nothing turns).
    pub fn angles(&self) -> Vec<f64> {
        self.contacts
            .turning
            .as_ref()
            .map_or_else(|| vec![0.0; self.len()], |turning| turning.angle.clone())
    }

    /// Total kinetic energy, translational and rotational, joules.
    pub(super) fn kinetic_energy(&self) -> f64 {
        self.forces.kinetic_energy(&self.state.velocity) + self.rotational_energy()
    }

    /// The turning particles' kinetic energy of their spins, joules.
    pub(super) fn rotational_energy(&self) -> f64 {
        self.contacts.turning.as_ref().map_or(0.0, |turning| {
            let (m, w, r) = (&self.forces.mass, &self.forces.inverse_mass, &self.radius);
            turning.kinetic_energy(m, w, r)
        })
    }
}

impl Quantity {
    /// The quantity in `simulation`, its object found by name, to read at any state with
    /// [`Simulation::read`].
    ///
    /// # Errors
    /// The object it names is not there (with the names there are), or a tension is asked
    /// of a spring.
    pub fn reading(&self, simulation: &Simulation) -> Result<Reading, String> {
        self.find(&Names {
            particles: simulation.names(),
            ties: simulation.tie_names(),
            springs: simulation.spring_names(),
            bodies: simulation.body_names(),
            joints: simulation.joint_names(),
            pulleys: &(0..simulation.joint_names().len())
                .filter(|&j| simulation.joint_is_pulley(j))
                .map(|j| simulation.joint_names()[j].clone())
                .collect::<Vec<_>>(),
        })
    }
}

impl Simulation {
    /// The value of `reading` in this state, in SI units (degrees for an angle).
    /// Accelerations are the smooth forces' ([`Self::accelerations`]).
    pub fn read(&self, reading: Reading) -> f64 {
        match reading {
            Reading::Time => self.time(),
            Reading::Particle(i, of) => {
                let (x, v) = (self.positions()[i], self.velocities()[i]);
                match of {
                    Of::X => x.x,
                    Of::Y => x.y,
                    Of::Vx => v.x,
                    Of::Vy => v.y,
                    Of::Speed => v.length(),
                    Of::Ax | Of::Ay => {
                        let a = self.particle(i, &self.accelerations()).acceleration;
                        if of == Of::Ax { a.x } else { a.y }
                    }
                    Of::KineticEnergy | Of::Angle | Of::Spin | Of::AngularMomentum => {
                        let p = self.particle(i, &[]);
                        match of {
                            Of::Angle => p.angle,
                            Of::Spin => p.spin,
                            Of::AngularMomentum => p.angular_momentum,
                            _ => p.kinetic_energy,
                        }
                    }
                }
            }
            Reading::Body(i, of) => {
                let b = self.body(i);
                match of {
                    Of::X => b.position.x,
                    Of::Y => b.position.y,
                    Of::Vx => b.velocity.x,
                    Of::Vy => b.velocity.y,
                    Of::Speed => b.speed,
                    Of::Ax => b.acceleration.x,
                    Of::Ay => b.acceleration.y,
                    Of::KineticEnergy => b.kinetic_energy,
                    Of::Angle => b.angle,
                    Of::Spin => b.spin,
                    Of::AngularMomentum => b.angular_momentum,
                }
            }
            Reading::Total(total) => {
                let d = self.diagnostics();
                match total {
                    Total::KineticEnergy => d.energy.kinetic,
                    Total::PotentialEnergy => d.energy.potential(),
                    Total::TotalEnergy => d.energy.total(),
                    Total::MomentumX => d.momentum.x,
                    Total::MomentumY => d.momentum.y,
                    Total::AngularMomentum => d.angular_momentum,
                }
            }
            Reading::Side {
                particle,
                point,
                normal,
            } => (self.positions()[particle] - point).dot(normal),
            Reading::Joint(j, of) => {
                let joint = self.joint(j);
                match of {
                    JointOf::Angle => joint.angle,
                    JointOf::ForceX => joint.force.x,
                    JointOf::ForceY => joint.force.y,
                    JointOf::Torque => joint.torque,
                    JointOf::TensionA => joint.tensions[0],
                    JointOf::TensionB => joint.tensions[1],
                }
            }
            Reading::Link(link, of) => {
                let (from, to) = self.link_ends(link);
                let d = to - from;
                match (of, link) {
                    (LinkOf::Angle, _) => angle_from_down(d),
                    (LinkOf::Length, _) => d.length(),
                    (LinkOf::Tension, Link::Tie(k)) => self.tensions()[k],
                    // Refused by `reading`: a spring's pull is not a tension here.
                    (LinkOf::Tension, Link::Spring(_)) => f64::NAN,
                }
            }
        }
    }
}

impl Simulation {
    /// The rigid bodies' names, in scene order.
    pub fn body_names(&self) -> &[String] {
        self.bodies.names()
    }

    /// Everything about body `i` now: its centroid's position, velocity and acceleration,
    /// its angle (degrees, unwrapped) and spin, its energy and momenta.
    pub fn body(&self, i: usize) -> ParticleReadout {
        self.bodies.readout(i)
    }

    /// The pins' and hinges' names, in scene order (the pins, then the hinges).
    pub fn joint_names(&self) -> &[String] {
        self.bodies.joint_names()
    }

    /// The kinetic energy the joints took at the start from velocities typed in the
    /// scene that moved them apart (a hinge's two points, a pulley's string stretching),
    /// J; `None` where the velocities were consistent with them. The run starts from the
    /// nearest consistent velocities (the plastic impulse), which `check` says.
    pub fn joints_start_loss(&self) -> Option<f64> {
        self.bodies.start_loss()
    }

    /// Whether joint `j` is a pin (not a hinge): its rows carry its force.
    pub fn joint_is_pin(&self, j: usize) -> bool {
        self.bodies.is_pin(j)
    }

    /// Whether joint `j` is a pulley: its rows carry its tensions.
    pub fn joint_is_pulley(&self, j: usize) -> bool {
        self.bodies.is_pulley(j)
    }

    /// Whether a joint has a motor: the ledger then books its work
    /// ([`crate::MOTOR_WORK_COLUMN`]).
    pub fn has_motors(&self) -> bool {
        self.bodies.has_motors()
    }

    /// Joint `j` now: its angle, its force on the body it holds (a hinge's b), its
    /// motor's torque, and its point.
    pub fn joint(&self, j: usize) -> JointReadout {
        self.bodies.joint(j)
    }

    /// Body `i`'s outline in the world now, counter-clockwise, metres.
    pub fn body_outline(&self, i: usize) -> Vec<DVec2> {
        self.bodies.world_outline(i)
    }

    /// The forces on body `i` now, each where it acts (`arm` from its centroid): its
    /// weight, then each surface's normal force and friction — its free-body diagram.
    pub fn body_forces(&self, i: usize) -> Vec<Applied> {
        self.bodies.forces(i)
    }
}

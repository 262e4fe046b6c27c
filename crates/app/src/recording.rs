//! The run's recording: every plottable quantity of every particle and of the system,
//! sampled at the simulation's own instants from Play on, so a graph can be switched to
//! another axis, a series added late or the whole run exported without losing anything.
//!
//! Samples are taken every `stride` steps, at t₀ + k·stride·dt exactly (the instants the
//! simulation computes, never a frame's irregular time), the first at Play. Memory is
//! bounded: when the samples fill [`BUDGET`] numbers, every other one is dropped and the
//! stride doubles, so a run of any length keeps its whole span at a resolution that
//! halves as it grows. At a 1 ms step the first samples are 5 ms apart; a two-particle
//! scene keeps that resolution for about three hours of simulated time.

use physics::{
    Anchor, DVec2, Diagnostics, ImpactRecord, JointOf, Link, LinkOf, Of, Quantity, Simulation,
    Total,
};

/// Numbers kept at most: 32 MiB of f64.
pub const BUDGET: usize = 1 << 22;
/// The first samples are this far apart (or one step, if steps are longer), seconds.
const FIRST_INTERVAL: f64 = 0.005;
/// Numbers per particle per sample: x, y, vx, vy, ax, ay, kinetic energy.
const PER_PARTICLE: usize = 7;
/// System numbers per sample, after the particles'.
const TOTALS: [Total; 6] = Total::ALL;
/// Numbers per particle per sample after the totals, when any particle turns: angle,
/// spin, angular momentum.
const PER_TURNING: usize = 3;
/// Numbers per rigid body per sample, after the particles' turning: every particle
/// quantity but the speed, in [`Of::ALL`]'s order.
const PER_BODY: usize = Of::ALL.len();
/// Numbers per joint per sample, after the bodies': angle, force x and y, torque, and a
/// pulley's two tensions.
const PER_JOINT: usize = 6;

/// Where a quantity is in a sample: a number stored, the speed from the velocity's two
/// components, or a rod's, string's or spring's angle or length from its ends.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Column {
    Plain(usize),
    Speed(usize),
    Link([End; 2], LinkOf),
}

/// One end of a link in a sample: a particle's position columns (x, then y), or a fixed
/// point.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum End {
    Sampled(usize),
    Fixed(DVec2),
}

#[derive(Clone, Debug)]
pub struct Recording {
    /// The particles' names at Play, in simulation order.
    names: Vec<String>,
    /// Each name's particle index: a graph, a readout or the announcer asks every frame,
    /// for every spring's ends in a cloth of thousands.
    index: std::collections::HashMap<String, usize>,
    /// The rods and strings at Play, whose tensions follow the particles' numbers.
    ties: Vec<String>,
    /// Every rod, string and spring at Play, by name, with its ends.
    links: Vec<(String, [Anchor; 2])>,
    /// Numbers per sample: t, then each particle's, each tie's tension, the totals, and
    /// each particle's turning when any turns.
    width: usize,
    /// Whether the samples hold the particles' turning.
    turning: bool,
    /// The rigid bodies' names at Play, whose numbers follow the particles' turning.
    bodies: Vec<String>,
    /// The pins' and hinges' names at Play, whose numbers follow the bodies'.
    joints: Vec<String>,
    /// Samples, one after another.
    data: Vec<f64>,
    /// Steps between samples.
    stride: u64,
    /// The simulation's step count at the first sample.
    first_step: u64,
    /// Numbers kept at most.
    budget: usize,
    /// The impacts of the run, in time order, up to [`IMPACTS`].
    impacts: Vec<ImpactRecord>,
}

/// Impacts kept at most; a pile of balls makes thousands a second, and past this many a
/// graph could not mark them legibly anyway.
pub const IMPACTS: usize = 100_000;

impl Recording {
    /// A recording of `simulation` with its first sample taken now.
    pub fn start(simulation: &Simulation) -> Self {
        let dt = simulation.time_step();
        #[expect(
            clippy::cast_possible_truncation,
            clippy::cast_sign_loss,
            reason = "a small positive count of steps"
        )]
        let stride = (FIRST_INTERVAL / dt).floor().max(1.0) as u64;
        let mut recording = Self {
            names: simulation.names().to_vec(),
            index: (0..)
                .zip(simulation.names())
                .map(|(i, name)| (name.clone(), i))
                .collect(),
            ties: simulation.tie_names().to_vec(),
            links: links(simulation),
            width: 1
                + PER_PARTICLE * simulation.len()
                + simulation.tie_names().len()
                + TOTALS.len()
                + if simulation.turns() {
                    PER_TURNING * simulation.len()
                } else {
                    0
                }
                + PER_BODY * simulation.body_names().len()
                + PER_JOINT * simulation.joint_names().len(),
            turning: simulation.turns(),
            bodies: simulation.body_names().to_vec(),
            joints: simulation.joint_names().to_vec(),
            data: Vec::new(),
            stride,
            first_step: simulation.steps_taken(),
            budget: BUDGET,
            impacts: Vec::new(),
        };
        recording.sample(simulation);
        recording
    }

    /// Keeps the impacts of the last step (up to [`IMPACTS`] in all).
    pub fn note_impacts(&mut self, impacts: Vec<ImpactRecord>) {
        let room = IMPACTS.saturating_sub(self.impacts.len());
        self.impacts.extend(impacts.into_iter().take(room));
    }

    /// The impacts recorded, in time order.
    pub fn impacts(&self) -> &[ImpactRecord] {
        &self.impacts
    }

    /// The particles' names at Play, in simulation order.
    pub fn names(&self) -> &[String] {
        &self.names
    }

    /// The run's particle index of `name`.
    pub fn index_of(&self, name: &str) -> Option<usize> {
        self.index.get(name).copied()
    }

    /// The columns of particle `i`'s position (x, y).
    pub fn position_columns(i: usize) -> (Column, Column) {
        let first = 1 + PER_PARTICLE * i;
        (Column::Plain(first), Column::Plain(first + 1))
    }

    /// Takes a sample if this step is one of the recorded instants; returns the system's
    /// diagnostics when it did (the readouts show them without computing them again).
    pub fn after_step(&mut self, simulation: &Simulation) -> Option<Diagnostics> {
        let steps = simulation.steps_taken() - self.first_step;
        steps
            .is_multiple_of(self.stride)
            .then(|| self.sample(simulation))
    }

    fn sample(&mut self, simulation: &Simulation) -> Diagnostics {
        if self.data.len() + self.width > self.budget.max(2 * self.width) {
            self.thin();
        }
        let accelerations = simulation.accelerations();
        self.data.push(simulation.time());
        let mut turning = Vec::new();
        for i in 0..simulation.len() {
            let p = simulation.particle(i, &accelerations);
            if self.turning {
                turning.extend([p.angle, p.spin, p.angular_momentum]);
            }
            self.data.extend([
                p.position.x,
                p.position.y,
                p.velocity.x,
                p.velocity.y,
                p.acceleration.x,
                p.acceleration.y,
                p.kinetic_energy,
            ]);
        }
        self.data.extend(simulation.tensions());
        let d = simulation.diagnostics();
        self.data.extend(TOTALS.map(|total| match total {
            Total::KineticEnergy => d.energy.kinetic,
            Total::PotentialEnergy => d.energy.potential(),
            Total::TotalEnergy => d.energy.total(),
            Total::MomentumX => d.momentum.x,
            Total::MomentumY => d.momentum.y,
            Total::AngularMomentum => d.angular_momentum,
        }));
        self.data.extend(turning);
        for b in 0..self.bodies.len() {
            let body = simulation.body(b);
            self.data.extend(Of::ALL.map(|of| match of {
                Of::X => body.position.x,
                Of::Y => body.position.y,
                Of::Vx => body.velocity.x,
                Of::Vy => body.velocity.y,
                Of::Speed => body.speed,
                Of::Ax => body.acceleration.x,
                Of::Ay => body.acceleration.y,
                Of::KineticEnergy => body.kinetic_energy,
                Of::Angle => body.angle,
                Of::Spin => body.spin,
                Of::AngularMomentum => body.angular_momentum,
            }));
        }
        for j in 0..self.joints.len() {
            let joint = simulation.joint(j);
            self.data.extend([
                joint.angle,
                joint.force.x,
                joint.force.y,
                joint.torque,
                joint.tensions[0],
                joint.tensions[1],
            ]);
        }
        d
    }

    /// Keeps samples 0, 2, 4, …: the instants of twice the stride.
    fn thin(&mut self) {
        let width = self.width;
        let kept: Vec<f64> = self
            .data
            .chunks_exact(width)
            .step_by(2)
            .flatten()
            .copied()
            .collect();
        self.data = kept;
        self.stride *= 2;
    }

    /// The number of samples.
    /// Forgets the samples and impacts after `time`, seconds: the run branches there.
    pub fn truncate_after(&mut self, time: f64) {
        let keep = (0..self.len())
            .take_while(|&k| self.row(k)[0] <= time)
            .count();
        self.data.truncate(keep * self.width);
        self.impacts.retain(|impact| impact.time <= time);
    }

    pub fn len(&self) -> usize {
        self.data.len() / self.width
    }

    pub fn is_empty(&self) -> bool {
        self.data.is_empty()
    }

    /// Steps between samples.
    pub fn stride(&self) -> u64 {
        self.stride
    }

    fn row(&self, k: usize) -> &[f64] {
        &self.data[k * self.width..(k + 1) * self.width]
    }

    /// Where `quantity` is in every sample; `None` for a particle not in the run. Found
    /// once, then read for every sample with [`Self::at`].
    pub fn column(&self, quantity: &Quantity) -> Option<Column> {
        if let Some(column) = self.body_column(quantity) {
            return Some(column);
        }
        Some(match quantity {
            Quantity::Time => Column::Plain(0),
            Quantity::Particle(name, of) => {
                let i = self.index_of(name)?;
                let first = 1 + PER_PARTICLE * i;
                let turning = self.turning_start() + PER_TURNING * i;
                match of {
                    Of::X => Column::Plain(first),
                    Of::Y => Column::Plain(first + 1),
                    Of::Vx => Column::Plain(first + 2),
                    Of::Vy => Column::Plain(first + 3),
                    Of::Speed => Column::Speed(first + 2),
                    Of::Ax => Column::Plain(first + 4),
                    Of::Ay => Column::Plain(first + 5),
                    Of::KineticEnergy => Column::Plain(first + 6),
                    Of::Angle if self.turning => Column::Plain(turning),
                    Of::Spin if self.turning => Column::Plain(turning + 1),
                    Of::AngularMomentum if self.turning => Column::Plain(turning + 2),
                    Of::Angle | Of::Spin | Of::AngularMomentum => return None,
                }
            }
            // A particle's `NAME.angle` reads as a link's: its turning's first column.
            Quantity::Link(name, LinkOf::Angle)
                if self.index.contains_key(name) && self.turning =>
            {
                let i = self.index_of(name)?;
                Column::Plain(self.turning_start() + PER_TURNING * i)
            }
            Quantity::Link(name, LinkOf::Tension) => {
                let k = self.ties.iter().position(|n| n == name)?;
                Column::Plain(1 + PER_PARTICLE * self.names.len() + k)
            }
            Quantity::Link(name, of) => {
                let (_, anchors) = self.links.iter().find(|(n, _)| n == name)?;
                Column::Link(
                    anchors.map(|anchor| match anchor {
                        Anchor::Particle(i) => End::Sampled(1 + PER_PARTICLE * i),
                        Anchor::Point(p) => End::Fixed(p),
                    }),
                    *of,
                )
            }
            Quantity::Total(total) => {
                let j = TOTALS.iter().position(|t| t == total)?;
                Column::Plain(self.turning_start() - TOTALS.len() + j)
            }
            Quantity::Joint(..) => return None,
        })
    }

    /// Where a rigid body's or a joint's quantity is in every sample; `None` for any
    /// other.
    fn body_column(&self, quantity: &Quantity) -> Option<Column> {
        let bodies = self.turning_start()
            + if self.turning {
                PER_TURNING * self.names.len()
            } else {
                0
            };
        let joints = bodies + PER_BODY * self.bodies.len();
        let body = |name: &str| self.bodies.iter().position(|n| n == name);
        let joint = |name: &str| self.joints.iter().position(|n| n == name);
        let of_body = |b: usize, of: Of| {
            let k = Of::ALL.iter().position(|&o| o == of).unwrap_or(0);
            Column::Plain(bodies + PER_BODY * b + k)
        };
        let of_joint = |j: usize, of: JointOf| {
            let k = [
                JointOf::Angle,
                JointOf::ForceX,
                JointOf::ForceY,
                JointOf::Torque,
                JointOf::TensionA,
                JointOf::TensionB,
            ]
            .iter()
            .position(|&o| o == of)
            .unwrap_or(0);
            Column::Plain(joints + PER_JOINT * j + k)
        };
        match quantity {
            Quantity::Particle(name, of) if !self.index.contains_key(name) => {
                body(name).map(|b| of_body(b, *of))
            }
            Quantity::Link(name, LinkOf::Angle)
                if !self.index.contains_key(name) && !self.links.iter().any(|(n, _)| n == name) =>
            {
                joint(name)
                    .map(|j| of_joint(j, JointOf::Angle))
                    .or_else(|| body(name).map(|b| of_body(b, Of::Angle)))
            }
            Quantity::Joint(name, of) => joint(name).map(|j| of_joint(j, *of)),
            _ => None,
        }
    }

    /// Where the particles' turning begins in a sample: after the totals, at the end of
    /// the row when nothing turns.
    fn turning_start(&self) -> usize {
        1 + PER_PARTICLE * self.names.len() + self.ties.len() + TOTALS.len()
    }

    /// The value in `column` at sample `k`.
    pub fn at(&self, k: usize, column: Column) -> f64 {
        let row = self.row(k);
        match column {
            Column::Plain(c) => row[c],
            Column::Speed(c) => row[c].hypot(row[c + 1]),
            Column::Link(ends, of) => {
                let [from, to] = ends.map(|end| match end {
                    End::Sampled(c) => DVec2::new(row[c], row[c + 1]),
                    End::Fixed(p) => p,
                });
                match of {
                    LinkOf::Angle => physics::angle_from_down(to - from),
                    LinkOf::Length => from.distance(to),
                    // Stored as a plain column (`Self::column`).
                    LinkOf::Tension => f64::NAN,
                }
            }
        }
    }

    /// The value of `quantity` at sample `k`; `None` for a particle not in the run.
    pub fn value(&self, k: usize, quantity: &Quantity) -> Option<f64> {
        self.column(quantity).map(|c| self.at(k, c))
    }

    /// The positions and velocities at the last sample: the last good state of a run
    /// that failed after it.
    pub fn last_state(&self) -> Option<(Vec<DVec2>, Vec<DVec2>)> {
        let k = self.len().checked_sub(1)?;
        let row = self.row(k);
        let n = self.names.len();
        Some((
            (0..n)
                .map(|i| DVec2::new(particle(row, i)[0], particle(row, i)[1]))
                .collect(),
            (0..n)
                .map(|i| DVec2::new(particle(row, i)[2], particle(row, i)[3]))
                .collect(),
        ))
    }

    /// Every particle's positions over the last `seconds` of the recording: the recent
    /// paths that Fit frames.
    pub fn recent_positions(&self, seconds: f64) -> Vec<DVec2> {
        let Some(end) = self.last_time() else {
            return Vec::new();
        };
        let first = (0..self.len())
            .rev()
            .take_while(|&k| self.row(k)[0] >= end - seconds)
            .last()
            .unwrap_or(0);
        (first..self.len())
            .flat_map(|k| {
                let row = self.row(k);
                (0..self.names.len())
                    .map(move |i| DVec2::new(particle(row, i)[0], particle(row, i)[1]))
            })
            .filter(|p| p.is_finite())
            .collect()
    }

    /// The time of the last sample.
    pub fn last_time(&self) -> Option<f64> {
        self.len().checked_sub(1).map(|k| self.row(k)[0])
    }

    /// The system quantities at the last sample.
    pub fn last_total(&self, total: Total) -> Option<f64> {
        self.len()
            .checked_sub(1)
            .and_then(|k| self.value(k, &Quantity::Total(total)))
    }
}

/// Every rod, string and spring of `simulation`, by name, with its ends.
fn links(simulation: &Simulation) -> Vec<(String, [Anchor; 2])> {
    let ties = (0..simulation.tie_names().len()).map(Link::Tie);
    let springs = (0..simulation.spring_names().len()).map(Link::Spring);
    ties.chain(springs)
        .map(|link| {
            let name = match link {
                Link::Tie(k) => &simulation.tie_names()[k],
                Link::Spring(k) => &simulation.spring_names()[k],
            };
            (name.clone(), simulation.link_anchors(link))
        })
        .collect()
}

/// Particle `i`'s numbers in a sample's row.
fn particle(row: &[f64], i: usize) -> &[f64] {
    let first = 1 + PER_PARTICLE * i;
    &row[first..first + PER_PARTICLE]
}

#[cfg(test)]
mod tests {
    use super::*;
    use physics::{Particle, Scene, World};

    /// A ball thrown up in a uniform field: every sample is at a multiple of the stride's
    /// instants and holds the closed-form motion, however often the recording is thinned.
    #[test]
    fn samples_are_at_the_steps_instants_and_thinning_keeps_the_span() {
        let scene = Scene::new()
            .with_world(World::default())
            .with_particle(Particle::new("ball", 2.0).velocity([1.0, 20.0]));
        let mut simulation = Simulation::new(&scene).unwrap();
        let mut recording = Recording::start(&simulation);
        assert_eq!(recording.stride(), 5, "5 ms at 1 ms steps");
        let budget_samples = 100;
        recording.budget = budget_samples * recording.width;
        let steps = 2 * 5 * budget_samples as u64 + 7;
        for _ in 0..steps {
            simulation.step().unwrap();
            recording.after_step(&simulation);
        }
        assert!(recording.stride() >= 10, "thinned at least once");
        assert!(recording.len() <= budget_samples, "within the budget");
        let dt = 0.001 * recording.stride() as f64;
        for k in [0, 1, recording.len() / 2, recording.len() - 1] {
            let t = recording.value(k, &Quantity::Time).unwrap();
            assert!((t - k as f64 * dt).abs() < 1e-9, "sample {k} at {t}");
            let y = recording
                .value(k, &Quantity::Particle("ball".into(), Of::Y))
                .unwrap();
            // rk4 is exact for constant acceleration up to rounding.
            let expected = 20.0 * t - 0.5 * 9.81 * t * t;
            assert!(
                (y - expected).abs() < 1e-6,
                "y({t}) = {y}, expected {expected}"
            );
            let kinetic = recording
                .value(k, &Quantity::Total(Total::KineticEnergy))
                .unwrap();
            let vy = 20.0 - 9.81 * t;
            assert!(
                (kinetic - (1.0 + vy * vy)).abs() < 1e-6,
                "kinetic energy at {t}"
            );
        }
        assert_eq!(
            recording.value(0, &Quantity::Particle("nobody".into(), Of::X)),
            None
        );
    }

    /// A scene with a ball, a body on a pin and a hinged one records the bodies' and the
    /// joints' quantities (a body's angle also as `NAME.angle`), each the simulation's
    /// own value, and leaves the ball's where they were.
    #[test]
    fn bodies_and_joints_are_recorded() {
        let text = r#"
version = 1
[[particle]]
name = "ball"
mass = 1.0
position = [0.0, 3.0]
velocity = [1.0, 2.0]
[[body]]
name = "ruler"
shape = "box"
width = 1.0
height = 0.05
mass = 0.5
position = [0.5, 0.0]
[[body]]
name = "tag"
shape = "box"
width = 0.1
height = 0.1
mass = 0.1
position = [1.0, -0.2]
[[pin]]
name = "nail"
body = "ruler"
at = [0.0, 0.0]
motor = { torque = 0.3 }
[[hinge]]
name = "hook"
a = "ruler"
b = "tag"
at = [1.0, 0.0]
"#;
        let scene = Scene::from_toml(text).expect("valid");
        let mut simulation = Simulation::new(&scene).unwrap();
        let mut recording = Recording::start(&simulation);
        for _ in 0..200 {
            simulation.step().unwrap();
            recording.after_step(&simulation);
        }
        let k = recording.len() - 1;
        let read = |text: &str| {
            let quantity = Quantity::parse(text).expect(text);
            recording.value(k, &quantity).expect(text)
        };
        for (text, expected) in [
            ("ball.vy", simulation.velocities()[0].y),
            ("ruler.angle", simulation.body(0).angle),
            ("ruler.spin", simulation.body(0).spin),
            ("tag.y", simulation.body(1).position.y),
            ("tag.speed", simulation.body(1).speed),
            ("nail.angle", simulation.joint(0).angle),
            ("nail.force_y", simulation.joint(0).force.y),
            ("nail.torque", 0.3),
            ("hook.angle", simulation.joint(1).angle),
            ("hook.force_x", simulation.joint(1).force.x),
        ] {
            assert_eq!(read(text).to_bits(), expected.to_bits(), "{text}");
        }
        assert!(read("nail.angle") < -1.0, "the ruler swings down");
    }

    /// A scene with a turning particle records its angle, spin and angular momentum
    /// (the angle also as `NAME.angle`, as a file writes it) and the system's angular
    /// momentum, each the simulation's own value; the totals stay where they are.
    #[test]
    fn a_turning_particles_quantities_are_recorded() {
        let scene = physics::example("spin-bounce")
            .expect("the example")
            .scene()
            .expect("a scene");
        let mut simulation = Simulation::new(&scene).expect("valid");
        simulation.step_to(0.3).expect("runs");
        let recording = Recording::start(&simulation);
        let d = simulation.diagnostics();
        let p = simulation.particle(0, &[]);
        for (text, expected) in [
            ("Ball.spin", p.spin),
            ("Ball.angle", p.angle),
            ("Ball.angular_momentum", p.angular_momentum),
            ("Ball.x", simulation.positions()[0].x),
            ("angular_momentum", d.angular_momentum),
            ("kinetic_energy", d.energy.kinetic),
        ] {
            let quantity = Quantity::parse(text).expect("a quantity");
            let value = recording.value(0, &quantity).expect("recorded");
            assert_eq!(value.to_bits(), expected.to_bits(), "{text}");
        }
    }
}

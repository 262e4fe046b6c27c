//! The simulation library of `NewtonLab`.
//!
//! A [`Scene`] is the editable description of a physical set-up: what the user typed, in
//! the form they typed it (polar or Cartesian vectors, names, colours). [`Simulation::new`]
//! turns a scene into runtime state in SI units and advances it in time with the
//! integrator the scene chose; [`Diagnostics`] reads energies, momentum and per-particle
//! quantities at any instant.
//!
//! The library knows nothing about screens, files or clocks: time is passed in, text is
//! passed in and out as strings. It builds for `wasm32-unknown-unknown`. Natively (the
//! default `parallel` feature) a simulation may search its contacts on several threads,
//! with results bit-identical to one thread ([`Simulation::set_threads`]).
//!
//! # Build a scene in code, run it, read the diagnostics
//!
//! A ball thrown at 10 m/s, 30° up, under g = 9.81 m/s²: after t seconds it is at
//! v₀t + g t²/2, which the default integrator (`rk4`) follows exactly.
//!
//! ```
//! use physics::{DVec2, Particle, Scene, Simulation, Vector};
//!
//! let scene = Scene::new().with_particle(
//!     Particle::new("ball", 0.5).velocity(Vector::polar(10.0, 30.0)),
//! );
//! let mut simulation = Simulation::new(&scene)?;
//! simulation.step_to(1.0)?;
//!
//! let v0 = DVec2::from_angle(30f64.to_radians()) * 10.0;
//! let expected = v0 + DVec2::new(0.0, -9.81) * 0.5;
//! assert!(simulation.positions()[0].distance(expected) < 1e-9);
//!
//! // Energy is kinetic plus potential; with no damping or impacts it stays put.
//! let energy = simulation.diagnostics().energy;
//! assert!((energy.total() - 0.5 * 0.5 * 100.0).abs() < 1e-9);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```
//!
//! # Load a scene file and print its problems
//!
//! Every problem is found at once, with its line and column, in words a student reads:
//!
//! ```
//! use physics::Scene;
//!
//! let text = "version = 1\n\n[[particle]]\nname = \"B\"\nmass = -2.0\nposition = [0.0, 0.0]\n";
//! let error = Scene::from_toml(text).unwrap_err();
//! let report = error.report("bad.toml");
//! assert!(report.contains("bad.toml:5:8: particle 'B': mass must be greater than 0, got -2"));
//! println!("{report}");
//! ```
//!
//! # Pick an integrator
//!
//! Integrators are named as in scene files; explicit Euler, the 2007 paper's method, gains
//! energy on an undamped spring where `verlet` does not:
//!
//! ```
//! use physics::{Integrator, Particle, Scene, Simulation, Spring, World};
//!
//! let spring = |integrator: &str| -> Result<f64, Box<dyn std::error::Error>> {
//!     let scene = Scene::new()
//!         .with_world(World::weightless())
//!         .with_integrator(integrator.parse::<Integrator>()?, 0.01)
//!         .with_particle(Particle::new("bob", 1.0).position([1.5, 0.0]))
//!         .with_spring(Spring::new("s", "bob", [0.0, 0.0], 1.0, 1.0));
//!     let mut simulation = Simulation::new(&scene)?;
//!     let start = simulation.diagnostics().energy.total();
//!     simulation.step_to(20.0)?;
//!     Ok(simulation.diagnostics().energy.total() / start)
//! };
//! assert!(spring("euler")? > 1.1); // (1 + (ωh)²)^2000 ≈ e^0.2
//! assert!((spring("verlet")? - 1.0).abs() < 1e-3);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

mod bodies;
mod constraints;
mod contacts;
mod csv;
mod cycle;
pub use bodies::{Applied, JointReadout, pulley_path};
pub use csv::csv_field;
pub use cycle::{Cycle, NoCycle, cycle};
mod diagnostics;
mod events;
mod examples;
mod field;
mod forces;
pub mod generated;
mod impact;
mod integrators;
mod method;
mod parallel;
mod profile;
mod quantity;
mod scene;
pub mod series;
mod simulation;
mod state;
#[cfg(test)]
mod testing;
mod trajectory;
mod tuning;
mod turning;
pub mod units;

pub use diagnostics::{Diagnostics, Energy, ParticleReadout};
pub use events::{Located, Watch};
pub use examples::{EXAMPLES, Example, example};
pub use field::{FieldReadout, field_at};
pub use glam::DVec2;
pub use impact::{ImpactRecord, ImpactTarget};
pub use method::{Integrator, UnknownIntegrator};
pub use parallel::every_core;
pub use profile::{Clock, Profile, Stage};
pub use quantity::{
    Anchor, Direction, Event, JointOf, Link, LinkOf, Of, Quantity, Reading, Total, Turn,
    angle_from_down,
};
pub use scene::error::{LoadError, Problem};
pub use scene::fields;
pub use scene::format::{SceneFormat, closest as closest_key};
pub use scene::series::{MAX_STEPS, MAX_WORK};
pub use scene::{
    Body, Bounds, Color, Endpoint, FieldRef, Follow, Force, Graph, Instruments, Joint, JointKind,
    Lesson, Moments, Motor, ObjectId, ObjectKind, PairForces, Particle, Protractor, Question, Ramp,
    Rule, Scene, Section, SectionKind, Series, Settings, Shape, Slider, Spring, Stopwatch, Tie,
    TieKind, Trigger, Vector, Verdict, View, World, check_value, lesson, moments,
};
pub use simulation::{Ledger, Simulation, SimulationError};
pub use trajectory::{
    IMPACT_COLUMNS, LEDGER_COLUMNS, MAX_NUMBERS, MOTOR_WORK_COLUMN, Plan, Row, Trajectory,
};

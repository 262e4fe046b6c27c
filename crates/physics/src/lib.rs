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

mod contacts;
mod csv;
mod diagnostics;
mod examples;
mod forces;
pub mod generated;
mod integrators;
mod parallel;
mod profile;
mod scene;
mod simulation;
mod state;

pub use diagnostics::{Diagnostics, Energy, ParticleReadout};
pub use examples::{EXAMPLES, Example, example};
pub use glam::DVec2;
pub use integrators::{Integrator, UnknownIntegrator};
pub use profile::{Clock, Profile, Stage};
pub use scene::format::{LoadError, Problem, SceneFormat};
pub use scene::{
    Bounds, Color, Endpoint, FieldRef, Particle, Ramp, Rule, Scene, Section, Settings, Spring,
    Vector, World, check_value,
};
pub use simulation::{ImpactRecord, ImpactTarget, Simulation, SimulationError};

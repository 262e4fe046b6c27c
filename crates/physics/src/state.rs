//! The runtime state the integrators touch: positions and velocities as
//! structure-of-arrays, indexed by particle in scene order.
//!
//! Names, colours and radii live elsewhere ([`crate::Simulation`] keeps them): the hot
//! loops read only these arrays and the force model's per-particle constants, so they
//! stream through memory without loading bookkeeping they never use.

use crate::tuning::RUNAWAY;
use glam::DVec2;

/// Positions and velocities at one instant.
#[derive(Clone, Debug, Default, PartialEq)]
pub(crate) struct State {
    /// Seconds since the start.
    pub time: f64,
    /// Metres, one per particle.
    pub position: Vec<DVec2>,
    /// Metres per second, one per particle.
    pub velocity: Vec<DVec2>,
}

impl State {
    pub fn len(&self) -> usize {
        self.position.len()
    }

    /// The first particle whose position or velocity is not finite, or has run away
    /// beyond [`RUNAWAY`] (a scene's numbers are at most 1e100; a state 1e50 times
    /// larger is an integration that has blown up, on its way to infinity).
    pub fn first_non_finite(&self) -> Option<usize> {
        let bounded = |v: DVec2| v.abs().max_element() <= RUNAWAY;
        self.position
            .iter()
            .zip(&self.velocity)
            .position(|(&x, &v)| !bounded(x) || !bounded(v))
    }
}

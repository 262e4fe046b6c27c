//! The events the app watches through a run for the stopwatch, located exactly by the
//! physics (`physics::Watch`: inside the step, to 1e-12 s) rather than between frames: a
//! typed event (`rod.angle crosses 0 down`), and a light gate — any particle's centre
//! crossing the tape's segment.

use physics::{DVec2, Direction, Event, Located, Reading, Simulation, Watch};

/// What a watched instant was.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Cue {
    /// The typed event.
    Event,
    /// A particle crossing the light gate.
    Gate,
}

/// What to watch: the typed event and the gate's segment, each if asked for.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Wanted {
    pub event: Option<String>,
    pub gate: Option<(DVec2, DVec2)>,
}

impl Wanted {
    pub fn is_empty(&self) -> bool {
        self.event.is_none() && self.gate.is_none()
    }
}

/// Events watched through a run, and the instants found since the stopwatch last looked.
#[derive(Clone, Debug)]
pub struct Watching {
    /// What it was built for.
    pub wanted: Wanted,
    watch: Watch,
    /// What each watched event stands for; a gate's crossing counts only on its segment.
    cues: Vec<Cue>,
    /// The instants found, in time order, not yet taken.
    found: Vec<(Cue, f64)>,
}

impl Watching {
    /// The watch of `wanted` in `simulation` from its present state on.
    ///
    /// # Errors
    /// The typed event is not an event of this scene (the reason, in words).
    pub fn new(wanted: Wanted, simulation: &Simulation) -> Result<Self, String> {
        let mut readings = Vec::new();
        let mut cues = Vec::new();
        if let Some(text) = &wanted.event {
            let event = Event::parse(text)?;
            readings.push((
                event.quantity.reading(simulation)?,
                event.value,
                event.direction,
            ));
            cues.push(Cue::Event);
        }
        if let Some((a, b)) = wanted.gate
            && a != b
        {
            let normal = (b - a).perp().normalize();
            for particle in 0..simulation.len() {
                let side = Reading::Side {
                    particle,
                    point: a,
                    normal,
                };
                readings.push((side, 0.0, Direction::Either));
                cues.push(Cue::Gate);
            }
        }
        Ok(Self {
            watch: Watch::of_readings(readings, simulation),
            cues,
            found: Vec::new(),
            wanted,
        })
    }

    /// Steps `simulation` once (as `Simulation::step`, the same bits), keeping the
    /// instants of what happened inside the step.
    ///
    /// # Errors
    /// The step's failure.
    pub fn step(&mut self, simulation: &mut Simulation) -> Result<(), physics::SimulationError> {
        let until = simulation.time() + simulation.time_step();
        let located = simulation.step_to_watching(until, &mut self.watch)?;
        for Located { event, at } in located {
            let cue = self.cues[event];
            if cue == Cue::Gate && !self.on_the_gate(&at, event) {
                continue;
            }
            self.found.push((cue, at.time()));
        }
        Ok(())
    }

    /// Whether the crossing of watched event `event` (a gate's, for one particle) at the
    /// state `at` is on the gate's segment, not beside it.
    fn on_the_gate(&self, at: &Simulation, event: usize) -> bool {
        let Some((a, b)) = self.wanted.gate else {
            return false;
        };
        let first_gate = self.cues.iter().position(|&c| c == Cue::Gate).unwrap_or(0);
        let x = at.positions()[event - first_gate];
        let along = b - a;
        (0.0..=1.0).contains(&((x - a).dot(along) / along.length_squared()))
    }

    /// The instants found since the last call, in time order.
    pub fn take(&mut self) -> Vec<(Cue, f64)> {
        std::mem::take(&mut self.found)
    }
}

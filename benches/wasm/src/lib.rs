//! The ball pit of `newtonlab bench --scene pit`, built for wasm32 with no JavaScript
//! glue: `run.mjs` instantiates the module, times `run_pit` with `performance.now()`,
//! and prints steps per second beside the native figure of the same scene.

use std::cell::RefCell;

use physics::{Simulation, generated};

thread_local! {
    static PIT: RefCell<Option<Simulation>> = const { RefCell::new(None) };
}

/// Builds the pit of `n` balls; returns 0 on success.
#[unsafe(no_mangle)]
pub extern "C" fn build_pit(n: u32) -> u32 {
    let scene = generated::ball_pit(n as usize);
    match Simulation::new(&scene) {
        Ok(simulation) => {
            PIT.with(|p| *p.borrow_mut() = Some(simulation));
            0
        }
        Err(_) => 1,
    }
}

/// Takes `steps` steps; returns the simulated time reached (NaN on failure).
#[unsafe(no_mangle)]
pub extern "C" fn run_pit(steps: u32) -> f64 {
    PIT.with(|p| {
        let mut p = p.borrow_mut();
        let Some(simulation) = p.as_mut() else {
            return f64::NAN;
        };
        for _ in 0..steps {
            if simulation.step().is_err() {
                return f64::NAN;
            }
        }
        simulation.time()
    })
}

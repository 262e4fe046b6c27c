//! `newtonlab.Simulation`: a scene's simulation stepped from Python, for a student who
//! writes their own loop.

use numpy::{PyArray2, PyArrayMethods};
use physics::{DVec2, Vector};
use pyo3::prelude::*;
use pyo3::types::PyDict;

use crate::scene::{checked, scene_of};
use crate::{SimulationError, scene_error};

/// An (n, 2) array of points, a row per particle.
type Points<'py> = Bound<'py, PyArray2<f64>>;

/// The most time steps one `advance` may take: as `newtonlab run`'s bound, beyond which
/// a typed time is likelier a mistake than intent (and would look like a hang).
const MAX_STEPS: f64 = 1e9;

/// A scene's simulation, stepped from Python: `step()` one time step, `advance(to=t)`
/// to an instant, `state` the positions and velocities as (n, 2) arrays, `energies()`.
///
/// Setting `positions`, `velocities` or `state` continues from the state given, at the
/// present time, as a saved state would (checked as a scene file is: particles that
/// overlap or a value that is not finite raise `SceneError`); the energy ledger starts
/// again there.
#[pyclass(module = "newtonlab")]
pub struct Simulation {
    scene: physics::Scene,
    inner: physics::Simulation,
    ledger: bool,
}

fn failed(error: &physics::SimulationError) -> PyErr {
    SimulationError::new_err(error.to_string())
}

/// `points` as an (n, 2) array.
fn array<'py>(py: Python<'py>, points: &[DVec2]) -> PyResult<Bound<'py, PyArray2<f64>>> {
    let rows: Vec<Vec<f64>> = points.iter().map(|p| vec![p.x, p.y]).collect();
    if rows.is_empty() {
        return PyArray2::zeros(py, [0, 2], false).reshape([0, 2]);
    }
    Ok(PyArray2::from_vec2(py, &rows)?)
}

impl Simulation {
    /// `value` as n points, n the number of particles.
    fn points(&self, value: &Bound<'_, PyAny>, what: &str) -> PyResult<Vec<DVec2>> {
        let n = self.inner.len();
        let rows: Vec<[f64; 2]> = value.extract().map_err(|_| {
            scene_error(format!(
                "{what} must be an (n, 2) array of numbers, n = {n} particles"
            ))
        })?;
        if rows.len() != n {
            return Err(scene_error(format!(
                "{what} must have one row per particle ({n}), got {}",
                rows.len()
            )));
        }
        Ok(rows.iter().map(|&[x, y]| DVec2::new(x, y)).collect())
    }

    /// Continues from `positions` and `velocities` at the present time.
    fn place(&mut self, positions: &[DVec2], velocities: &[DVec2]) -> PyResult<()> {
        let mut scene = self.inner.saved_state(&self.scene);
        for ((particle, x), v) in scene.particles.iter_mut().zip(positions).zip(velocities) {
            particle.position = Vector::cartesian(x.x, x.y);
            if !particle.fixed {
                particle.velocity = Vector::cartesian(v.x, v.y);
            }
        }
        let scene = checked(scene)?;
        let mut inner = physics::Simulation::new(&scene).map_err(|e| scene_error(e.to_string()))?;
        if self.ledger {
            inner.keep_ledger();
        }
        self.inner = inner;
        Ok(())
    }
}

#[pymethods]
impl Simulation {
    /// The simulation of `scene` (a `Scene`, a file's path or `"example:NAME"`) at its
    /// start time; `ledger=True` keeps the energy ledger for `energies()`.
    #[new]
    #[pyo3(signature = (scene, ledger = false))]
    fn new(scene: &Bound<'_, PyAny>, ledger: bool) -> PyResult<Self> {
        let scene = scene_of(scene)?;
        let mut inner = physics::Simulation::new(&scene).map_err(|e| scene_error(e.to_string()))?;
        if ledger {
            inner.keep_ledger();
        }
        Ok(Self {
            scene,
            inner,
            ledger,
        })
    }

    /// Advances by one time step (`scene.simulation.time_step`).
    fn step(&mut self) -> PyResult<()> {
        self.inner.step().map_err(|e| failed(&e))
    }

    /// Advances to exactly `to` seconds (nothing happens for an instant not ahead).
    #[pyo3(signature = (*, to))]
    fn advance(&mut self, py: Python<'_>, to: f64) -> PyResult<()> {
        if !to.is_finite() {
            return Err(scene_error(format!(
                "to must be a finite number of seconds, got {to}"
            )));
        }
        let steps = (to - self.inner.time()) / self.inner.time_step();
        if steps > MAX_STEPS {
            return Err(scene_error(format!(
                "advancing to {to} s takes {steps:.1e} steps of {:e} s, more than {MAX_STEPS:e}; \
                 advance in parts or choose a larger time step",
                self.inner.time_step()
            )));
        }
        let inner = &mut self.inner;
        py.detach(|| inner.step_to(to)).map_err(|e| failed(&e))
    }

    /// Simulated time, seconds.
    #[getter]
    fn time(&self) -> f64 {
        self.inner.time()
    }

    /// The particles' names, in the order of the arrays' rows.
    #[getter]
    fn names(&self) -> Vec<String> {
        self.inner.names().to_vec()
    }

    /// Positions, metres: an (n, 2) array, a row per particle.
    #[getter]
    fn positions<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArray2<f64>>> {
        array(py, self.inner.positions())
    }

    #[setter]
    fn set_positions(&mut self, value: &Bound<'_, PyAny>) -> PyResult<()> {
        let positions = self.points(value, "positions")?;
        let velocities = self.inner.velocities().to_vec();
        self.place(&positions, &velocities)
    }

    /// Velocities, m/s: an (n, 2) array.
    #[getter]
    fn velocities<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArray2<f64>>> {
        array(py, self.inner.velocities())
    }

    #[setter]
    fn set_velocities(&mut self, value: &Bound<'_, PyAny>) -> PyResult<()> {
        let velocities = self.points(value, "velocities")?;
        let positions = self.inner.positions().to_vec();
        self.place(&positions, &velocities)
    }

    /// `(positions, velocities)`, each an (n, 2) array.
    #[getter]
    fn state<'py>(&self, py: Python<'py>) -> PyResult<(Points<'py>, Points<'py>)> {
        Ok((self.positions(py)?, self.velocities(py)?))
    }

    #[setter]
    fn set_state(&mut self, value: (Bound<'_, PyAny>, Bound<'_, PyAny>)) -> PyResult<()> {
        let positions = self.points(&value.0, "positions")?;
        let velocities = self.points(&value.1, "velocities")?;
        self.place(&positions, &velocities)
    }

    /// The energies now, joules: `kinetic`, `potential`, `total`; with the ledger kept,
    /// also what damping, friction, impacts and drag took since the start (or since the
    /// state was last set), as `newtonlab run --ledger` names them.
    fn energies<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let energy = self.inner.diagnostics().energy;
        let dict = PyDict::new(py);
        dict.set_item("kinetic", energy.kinetic)?;
        dict.set_item("potential", energy.potential())?;
        dict.set_item("total", energy.total())?;
        if let Some(ledger) = self.inner.ledger() {
            dict.set_item("dissipated_damping", ledger.damping)?;
            dict.set_item("dissipated_friction", ledger.friction)?;
            dict.set_item("dissipated_impacts", ledger.impacts)?;
            dict.set_item("dissipated_drag", ledger.drag)?;
        }
        Ok(dict)
    }

    /// Momentum, kg·m/s, as `(px, py)`.
    fn momentum(&self) -> (f64, f64) {
        let p = self.inner.diagnostics().momentum;
        (p.x, p.y)
    }

    fn __repr__(&self) -> String {
        format!(
            "<newtonlab.Simulation of {} particles at t = {} s>",
            self.inner.len(),
            self.inner.time()
        )
    }
}

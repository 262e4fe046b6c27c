//! `newtonlab` in Python: the native module `newtonlab._native`, which the package's
//! `__init__.py` re-exports. Every number comes from the same code as the command line:
//! `run` from [`physics::Trajectory`] (what `newtonlab run` writes), `sweep` from
//! [`physics::series`] (what `newtonlab sweep` writes), `validate` from
//! [`newtonlab_validation`]. Bad input raises `newtonlab.SceneError` (a `ValueError`)
//! with the scene's own words; a simulation that fails raises
//! `newtonlab.SimulationError`. Long work releases the interpreter's lock.

mod build;
mod run;
mod scene;
mod simulation;
mod table;

use pyo3::create_exception;
use pyo3::exceptions::{PyRuntimeError, PyValueError};
use pyo3::prelude::*;

create_exception!(
    newtonlab,
    SceneError,
    PyValueError,
    "A scene, a value or an argument NewtonLab cannot take; the message says which and why."
);
create_exception!(
    newtonlab,
    SimulationError,
    PyRuntimeError,
    "A run that failed: a value became infinite or not a number (the message names the particle and the time)."
);

/// A `SceneError` with `message`.
pub(crate) fn scene_error(message: impl Into<String>) -> PyErr {
    SceneError::new_err(message.into())
}

#[pymodule]
fn _native(m: &Bound<'_, PyModule>) -> PyResult<()> {
    let py = m.py();
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    m.add("SceneError", py.get_type::<SceneError>())?;
    m.add("SimulationError", py.get_type::<SimulationError>())?;
    m.add_class::<scene::Scene>()?;
    m.add_class::<scene::SceneObject>()?;
    m.add_class::<table::Table>()?;
    m.add_class::<table::Trajectory>()?;
    m.add_class::<simulation::Simulation>()?;
    m.add_function(wrap_pyfunction!(scene::load, m)?)?;
    m.add_function(wrap_pyfunction!(scene::examples, m)?)?;
    m.add_function(wrap_pyfunction!(run::run, m)?)?;
    m.add_function(wrap_pyfunction!(run::sweep, m)?)?;
    m.add_function(wrap_pyfunction!(run::sweep_values, m)?)?;
    m.add_function(wrap_pyfunction!(run::validate, m)?)?;
    Ok(())
}

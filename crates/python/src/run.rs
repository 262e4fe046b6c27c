//! `newtonlab.run`, `newtonlab.sweep` and `newtonlab.validate`: the command line's `run`,
//! `sweep` and `validate`, through the same code, their numbers in numpy arrays. Each
//! releases the interpreter's lock while it computes.

use physics::series::{Measure, Sweep, Vary};
use physics::{IMPACT_COLUMNS, Plan, Trajectory};
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyString};

use crate::scene::scene_of;
use crate::table::{Column, Table};
use crate::{SimulationError, scene_error};

/// A run's table, as it came out of the physics.
struct Rows {
    names: Vec<String>,
    values: Vec<Vec<f64>>,
    events: Option<Vec<String>>,
    impacts: Vec<physics::ImpactRecord>,
    impact_names: Vec<(String, String)>,
    note: Option<String>,
    failure: Option<String>,
}

/// Runs `trajectory` to its end, keeping every row and impact.
fn collect(mut trajectory: Trajectory, events: bool) -> Rows {
    let names = trajectory.columns();
    let mut values = vec![Vec::new(); names.len()];
    let mut event_names = events.then(Vec::new);
    let mut impacts = Vec::new();
    let mut impact_names = Vec::new();
    let mut failure = None;
    loop {
        let stepped = trajectory.advance(&mut |row| {
            for (column, &value) in values.iter_mut().zip(row.values) {
                column.push(value);
            }
            if let Some(event_names) = &mut event_names {
                event_names.push(row.event.unwrap_or_default().to_owned());
            }
        });
        for impact in trajectory.take_impacts() {
            let (particle, other) = trajectory.impact_names(&impact);
            impact_names.push((particle.to_owned(), other.to_owned()));
            impacts.push(impact);
        }
        match stepped {
            None => break,
            Some(Ok(())) => {}
            Some(Err(error)) => {
                failure = Some(error.to_string());
                break;
            }
        }
    }
    Rows {
        names,
        values,
        events: event_names,
        impacts,
        impact_names,
        note: trajectory.note().map(str::to_owned),
        failure,
    }
}

/// Runs `scene` from its start time to `until` seconds and returns its rows: a
/// `Trajectory` whose columns are `newtonlab run`'s, the same numbers bit for bit.
///
/// `every`: the sampling interval in seconds (rows at t = 0, every, 2·every, … and at
/// `until`); 0.01 when left out, or no samples when there are `events`. `events`: a
/// string or a list of them, `QUANTITY crosses VALUE [up|down]` (`"Bob.vx crosses 0
/// down"`), each a row at its instant, located inside its step; the `event` column names
/// it. `ledger`: the energy ledger's columns at the end of each row. `impacts`: keep
/// every impact for `traj.impacts` (a resting pile counts thousands a step, and keeping
/// them costs time: off unless asked). `no_limit`: run however long it takes (without it,
/// more than 10⁸ time steps, 10⁹ particle-steps or 10⁸ numbers are refused, as the
/// command line refuses them without `--no-limit`). `threads`: how many the step may use
/// (every core when left out; the same bits for any number).
///
/// Raises `SceneError` for a bad scene or argument, `SimulationError` when the run fails.
#[pyfunction]
#[pyo3(signature = (scene, until, every = None, events = None, ledger = false, impacts = false, no_limit = false, threads = None))]
#[expect(
    clippy::too_many_arguments,
    reason = "Python's keyword arguments, each with its default"
)]
pub fn run(
    py: Python<'_>,
    scene: &Bound<'_, PyAny>,
    until: f64,
    every: Option<f64>,
    events: Option<&Bound<'_, PyAny>>,
    ledger: bool,
    impacts: bool,
    no_limit: bool,
    threads: Option<usize>,
) -> PyResult<Py<crate::table::Trajectory>> {
    let scene = scene_of(scene)?;
    let events = strings(events, "events")?;
    let plan = Plan {
        until,
        every,
        events: events.clone(),
        columns: Vec::new(),
        ledger,
        impacts,
        no_limit,
        threads: threads
            .filter(|&t| t > 0)
            .unwrap_or_else(physics::every_core),
    };
    let trajectory = Trajectory::new(&scene, &plan).map_err(scene_error)?;
    let rows = py.detach(|| collect(trajectory, !events.is_empty()));
    if let Some(failure) = rows.failure {
        return Err(SimulationError::new_err(failure));
    }
    let mut names = rows.names;
    let mut columns: Vec<Column> = rows.values.into_iter().map(Column::Numbers).collect();
    if let Some(events) = rows.events {
        names.push("event".to_owned());
        columns.push(Column::Words(events));
    }
    let impacts = if impacts {
        Some(Py::new(py, impact_table(&rows.impacts, rows.impact_names))?)
    } else {
        None
    };
    let initializer = PyClassInitializer::from(Table::new(names, columns))
        .add_subclass(crate::table::Trajectory::new(impacts, rows.note));
    Py::new(py, initializer)
}

/// The impacts as a table of `newtonlab run --impacts`'s columns.
fn impact_table(impacts: &[physics::ImpactRecord], names: Vec<(String, String)>) -> Table {
    let numbers = |read: fn(&physics::ImpactRecord) -> f64| {
        Column::Numbers(impacts.iter().map(read).collect())
    };
    let (particles, others): (Vec<String>, Vec<String>) = names.into_iter().unzip();
    Table::new(
        IMPACT_COLUMNS.map(str::to_owned).to_vec(),
        vec![
            numbers(|i| i.time),
            Column::Words(particles),
            Column::Words(others),
            numbers(|i| i.impulse),
            numbers(|i| i.normal_speed_before),
            numbers(|i| i.normal_speed_after),
            numbers(|i| i.kinetic_energy_lost),
        ],
    )
}

/// `value` as a list of strings: None, one string, or an iterable of strings.
fn strings(value: Option<&Bound<'_, PyAny>>, what: &str) -> PyResult<Vec<String>> {
    let Some(value) = value.filter(|v| !v.is_none()) else {
        return Ok(Vec::new());
    };
    if let Ok(text) = value.cast::<PyString>() {
        return Ok(vec![text.to_cow()?.into_owned()]);
    }
    value
        .extract::<Vec<String>>()
        .map_err(|_| scene_error(format!("{what} must be a string or a list of strings")))
}

/// Runs `scene` once for every combination of the values in `vary` and measures each run:
/// `newtonlab sweep`, in parallel (each run on one thread, `threads` of them, every core
/// when left out), the same numbers bit for bit.
///
/// `vary`: `{FIELD: values}`, a field as `sweep --vary` names it (`"Ball.velocity.angle"`,
/// `"Bob.mass"`, `"world.gravity.y"`) and its values (a list or a numpy array), or
/// `"FROM:TO:STEP"`; two fields make a grid, the first outermost. `measure`: a string
/// or a list of them, `QUANTITY at EVENT [#N]`, `t at EVENT`, `max QUANTITY`, `min
/// QUANTITY`, `period QUANTITY` or `QUANTITY at T`.
///
/// Returns a `Table`: the varied values, then a column per measure named as typed (NaN
/// where a run had no such number; `problems` says why). Raises `SimulationError` when
/// every run failed.
#[pyfunction]
#[pyo3(signature = (scene, vary, until, measure, threads = None))]
pub fn sweep(
    py: Python<'_>,
    scene: &Bound<'_, PyAny>,
    vary: &Bound<'_, PyDict>,
    until: f64,
    measure: &Bound<'_, PyAny>,
    threads: Option<usize>,
) -> PyResult<Py<Table>> {
    let scene = scene_of(scene)?;
    if !until.is_finite() || until < scene.simulation.start_time {
        return Err(scene_error(format!(
            "until must be a number no earlier than the scene's start ({} s), got {until}",
            scene.simulation.start_time
        )));
    }
    let (fields, varies) = varies(vary, &scene)?;
    let measures_typed = strings(Some(measure), "measure")?;
    if measures_typed.is_empty() {
        return Err(scene_error("measure must name at least one measure"));
    }
    let measures = measures_typed
        .iter()
        .map(|text| Measure::parse(text))
        .collect::<Result<Vec<_>, _>>()
        .map_err(scene_error)?;
    let sweep = Sweep {
        varies,
        until,
        measures,
        trace: false,
    };
    sweep.check(&scene).map_err(scene_error)?;
    let threads = threads
        .filter(|&t| t > 0)
        .unwrap_or_else(physics::every_core);
    let rows = py.detach(|| sweep.run(&scene, threads, &|| {}));
    let mut problems = Vec::new();
    let mut columns: Vec<Vec<f64>> = vec![Vec::new(); fields.len() + measures_typed.len()];
    for row in &rows {
        let run = row.label(&fields);
        for (column, &value) in columns.iter_mut().zip(&row.values) {
            column.push(value);
        }
        match &row.measured {
            Ok(numbers) => {
                for (k, m) in numbers.iter().enumerate() {
                    columns[fields.len() + k].push(*m.as_ref().unwrap_or(&f64::NAN));
                    if let Err(why) = m {
                        problems.push(format!("{run}: {}: {why}", measures_typed[k].trim()));
                    }
                }
            }
            Err(why) => {
                for column in &mut columns[fields.len()..] {
                    column.push(f64::NAN);
                }
                problems.push(format!("{run}: the run failed: {why}"));
            }
        }
    }
    if !rows.is_empty() && rows.iter().all(|row| row.measured.is_err()) {
        return Err(SimulationError::new_err(format!(
            "every run failed:\n{}",
            problems.join("\n")
        )));
    }
    warn(py, &problems)?;
    let names = fields
        .into_iter()
        .chain(measures_typed.iter().map(|m| m.trim().to_owned()))
        .collect();
    Py::new(
        py,
        Table::new(names, columns.into_iter().map(Column::Numbers).collect()),
    )
}

/// The values each field of `vary` takes in a sweep of `scene`, as `sweep` reads them
/// (`"FROM:TO:STEP"` expanded): `[(field, values)]`, the first outermost. What a sweep
/// split among workers hands each its part of.
#[pyfunction]
pub fn sweep_values(
    scene: &Bound<'_, PyAny>,
    vary: &Bound<'_, PyDict>,
) -> PyResult<Vec<(String, Vec<f64>)>> {
    let scene = scene_of(scene)?;
    let (fields, varies) = varies(vary, &scene)?;
    Ok(fields
        .into_iter()
        .zip(varies)
        .map(|(field, vary)| (field, vary.values))
        .collect())
}

/// `vary`'s fields as typed, and what each varies over.
fn varies(vary: &Bound<'_, PyDict>, scene: &physics::Scene) -> PyResult<(Vec<String>, Vec<Vary>)> {
    let mut fields = Vec::new();
    let mut varies = Vec::new();
    for (field, values) in vary.iter() {
        let field: String = field
            .extract()
            .map_err(|_| scene_error("vary's keys must be fields' names, as strings"))?;
        let vary = if let Ok(range) = values.cast::<PyString>() {
            Vary::parse(&format!("{field}={}", range.to_cow()?), scene).map_err(scene_error)?
        } else {
            let values: Vec<f64> = values.extract().map_err(|_| {
                scene_error(format!(
                    "vary['{field}'] must be numbers (a list or an array) or \"FROM:TO:STEP\""
                ))
            })?;
            if values.is_empty() || values.iter().any(|v| !v.is_finite()) {
                return Err(scene_error(format!(
                    "vary['{field}'] must hold at least one value, each a finite number"
                )));
            }
            Vary {
                setting: physics::series::Setting::parse(&field, scene).map_err(scene_error)?,
                values,
            }
        };
        fields.push(field.trim().to_owned());
        varies.push(vary);
    }
    if varies.is_empty() {
        return Err(scene_error("vary must name at least one field"));
    }
    Ok((fields, varies))
}

/// Each problem as a Python warning (what `newtonlab sweep` writes on stderr).
fn warn(py: Python<'_>, problems: &[String]) -> PyResult<()> {
    if problems.is_empty() {
        return Ok(());
    }
    let warnings = py.import("warnings")?;
    for problem in problems {
        warnings.call_method1("warn", (problem.as_str(),))?;
    }
    Ok(())
}

/// Runs `newtonlab validate`'s checks (every group, or those named in `groups`: "paper",
/// "rods", "strings", "integrators", "tree", "softening", "ledger", "friction",
/// "saved-state", "events", "drag", "series") and returns one record per check: a dict
/// with `group`, `what`, `error`, `limit` and `passed`.
#[pyfunction]
#[pyo3(signature = (groups = None, tolerance = 1e-6, threads = None))]
pub fn validate(
    py: Python<'_>,
    groups: Option<&Bound<'_, PyAny>>,
    tolerance: f64,
    threads: Option<usize>,
) -> PyResult<Vec<Py<PyDict>>> {
    use newtonlab_validation::Group;
    if !(tolerance.is_finite() && tolerance > 0.0) {
        return Err(scene_error(format!(
            "tolerance must be a number greater than 0, got {tolerance}"
        )));
    }
    let names = strings(groups, "groups")?;
    let groups: Vec<Group> = if names.is_empty() {
        Group::ALL.to_vec()
    } else {
        names
            .iter()
            .map(|name| name.parse::<Group>())
            .collect::<Result<_, _>>()
            .map_err(scene_error)?
    };
    let threads = threads
        .filter(|&t| t > 0)
        .unwrap_or_else(physics::every_core);
    let outcome = py.detach(|| newtonlab_validation::validate(&groups, tolerance, threads));
    let (report, _) = outcome.map_err(|failure| match failure {
        newtonlab_validation::Failure::Simulation(why) => SimulationError::new_err(why),
        newtonlab_validation::Failure::Input(why) => scene_error(why),
    })?;
    report
        .checks
        .iter()
        .map(|check| {
            let record = PyDict::new(py);
            let limit = report.limit(check);
            record.set_item("group", check.group)?;
            record.set_item("what", &check.what)?;
            record.set_item("error", check.error)?;
            record.set_item("limit", limit)?;
            // NaN fails: it is a quantity that could not be measured.
            record.set_item("passed", check.error <= limit)?;
            Ok(record.unbind())
        })
        .collect()
}

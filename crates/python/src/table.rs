//! `newtonlab.Table` and `newtonlab.Trajectory`: named columns, numbers as numpy float64
//! arrays and words as lists of strings, in the order the command line writes them.

use numpy::PyArray1;
use pyo3::exceptions::{PyImportError, PyKeyError};
use pyo3::prelude::*;
use pyo3::types::PyDict;

/// A column's values.
#[derive(Clone, Debug)]
pub(crate) enum Column {
    Numbers(Vec<f64>),
    Words(Vec<String>),
}

/// Named columns of equal length: `table["t"]` is a numpy array; `table.columns` their
/// names in order; `table.to_pandas()` a `DataFrame` (with pandas installed).
#[pyclass(module = "newtonlab", subclass, frozen)]
pub struct Table {
    names: Vec<String>,
    columns: Vec<Column>,
}

impl Table {
    pub(crate) fn new(names: Vec<String>, columns: Vec<Column>) -> Self {
        Self { names, columns }
    }

    fn rows(&self) -> usize {
        self.columns.first().map_or(0, |c| match c {
            Column::Numbers(v) => v.len(),
            Column::Words(v) => v.len(),
        })
    }

    fn column(&self, py: Python<'_>, k: usize) -> PyResult<Py<PyAny>> {
        Ok(match &self.columns[k] {
            Column::Numbers(values) => PyArray1::from_slice(py, values).into_any().unbind(),
            Column::Words(values) => values.clone().into_pyobject(py)?.into_any().unbind(),
        })
    }
}

#[pymethods]
impl Table {
    /// The columns' names, in order.
    #[getter]
    fn columns(&self) -> Vec<String> {
        self.names.clone()
    }

    /// The column called `name`: a numpy float64 array, or a list of strings.
    fn __getitem__(&self, py: Python<'_>, name: &str) -> PyResult<Py<PyAny>> {
        match self.names.iter().position(|n| n == name) {
            Some(k) => self.column(py, k),
            None => Err(PyKeyError::new_err(format!(
                "no column '{name}'; the columns are: {}",
                self.names.join(", ")
            ))),
        }
    }

    fn __contains__(&self, name: &str) -> bool {
        self.names.iter().any(|n| n == name)
    }

    /// The number of rows.
    fn __len__(&self) -> usize {
        self.rows()
    }

    /// The columns' names, in order (as a dict's keys).
    fn keys(&self) -> Vec<String> {
        self.names.clone()
    }

    /// `{name: column}`, in order.
    fn to_dict<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let dict = PyDict::new(py);
        for (k, name) in self.names.iter().enumerate() {
            dict.set_item(name, self.column(py, k)?)?;
        }
        Ok(dict)
    }

    /// A pandas `DataFrame` of the columns, in order, indexed by time (`t`) where the
    /// table has it, as a time series is. Needs pandas (`pip install pandas`).
    fn to_pandas(&self, py: Python<'_>) -> PyResult<Py<PyAny>> {
        let pandas = py.import("pandas").map_err(|_| {
            PyImportError::new_err(
                "Table.to_pandas needs pandas, which is not installed: pip install pandas",
            )
        })?;
        let kwargs = PyDict::new(py);
        kwargs.set_item("columns", self.names.clone())?;
        let frame = pandas
            .getattr("DataFrame")?
            .call((self.to_dict(py)?,), Some(&kwargs))?;
        if self.names.iter().any(|n| n == "t") {
            return Ok(frame.call_method1("set_index", ("t",))?.unbind());
        }
        Ok(frame.unbind())
    }

    fn __repr__(slf: &Bound<'_, Self>) -> PyResult<String> {
        let table = slf.get();
        Ok(format!(
            "<newtonlab.{} of {} rows: {}>",
            slf.get_type().name()?,
            table.rows(),
            table.names.join(", ")
        ))
    }
}

/// A run's rows, by `newtonlab run`'s column names (`traj["Ball.x"]`, `traj["t"]`), the
/// same numbers bit for bit; with events, a column `event` naming each row's event (empty
/// for a sample). `impacts` is a `Table` of every impact (with `impacts=True`); `note` says when the interval
/// is not a whole number of time steps.
#[pyclass(module = "newtonlab", extends = Table, frozen)]
pub struct Trajectory {
    impacts: Option<Py<Table>>,
    note: Option<String>,
}

impl Trajectory {
    pub(crate) fn new(impacts: Option<Py<Table>>, note: Option<String>) -> Self {
        Self { impacts, note }
    }
}

#[pymethods]
impl Trajectory {
    /// Every impact, one row each: t, particle, other (a particle's or a ramp's name, or
    /// `wall`), impulse (N·s), the normal speeds before and after (m/s), the kinetic
    /// energy lost (J). Kept when the run was asked for them (`run(..., impacts=True)`).
    #[getter]
    fn impacts(&self, py: Python<'_>) -> PyResult<Py<Table>> {
        self.impacts
            .as_ref()
            .map(|t| t.clone_ref(py))
            .ok_or_else(|| {
                crate::scene_error(
                    "this run did not keep its impacts: run(..., impacts=True) keeps them",
                )
            })
    }

    /// When the interval is not a whole number of fixed time steps, why some steps were
    /// shortened; otherwise None.
    #[getter]
    fn note(&self) -> Option<String> {
        self.note.clone()
    }
}

//! `newtonlab.Table` and `newtonlab.Trajectory`: named columns, numbers as numpy float64
//! arrays and words as lists of strings, in the order the command line writes them.

use numpy::PyArray1;
use pyo3::exceptions::{PyImportError, PyKeyError};
use pyo3::prelude::*;
use pyo3::types::PyDict;

/// A table's names and columns, as it pickles.
type Columns = (Vec<String>, Vec<Py<PyAny>>);

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

    /// A table of `names` and `columns` (each numbers or a list of words): what a
    /// pickled table is made again from.
    #[staticmethod]
    fn _from_columns(names: Vec<String>, columns: Vec<Bound<'_, PyAny>>) -> PyResult<Table> {
        let columns = columns
            .iter()
            .map(|c| {
                c.extract::<Vec<f64>>()
                    .map(Column::Numbers)
                    .or_else(|_| c.extract::<Vec<String>>().map(Column::Words))
            })
            .collect::<PyResult<Vec<_>>>()?;
        if names.len() != columns.len() {
            return Err(crate::scene_error("a table needs one name per column"));
        }
        Ok(Table { names, columns })
    }

    /// Pickles as its columns (a `Table` goes to another process, a Dask worker's
    /// result, whole); a `Trajectory`'s impacts and note would be lost, so it refuses.
    fn __reduce__<'py>(slf: &Bound<'py, Self>) -> PyResult<(Bound<'py, PyAny>, Columns)> {
        let py = slf.py();
        if !slf.get_type().is(py.get_type::<Table>()) {
            return Err(pyo3::exceptions::PyTypeError::new_err(
                "a Trajectory does not pickle (its impacts and note would be lost): pickle traj.to_dict()",
            ));
        }
        let table = slf.get();
        let columns = (0..table.names.len())
            .map(|k| table.column(py, k))
            .collect::<PyResult<Vec<_>>>()?;
        Ok((
            slf.get_type().getattr("_from_columns")?,
            (table.names.clone(), columns),
        ))
    }

    /// The rows of `tables`, one after another: tables of the same columns (the parts of
    /// one sweep run apart, as `sweep(..., client=...)` joins them).
    #[staticmethod]
    fn concat(tables: Vec<PyRef<'_, Table>>) -> PyResult<Table> {
        let Some(first) = tables.first() else {
            return Err(crate::scene_error("Table.concat needs at least one table"));
        };
        let names = first.names.clone();
        let mut columns = first.columns.clone();
        for table in &tables[1..] {
            if table.names != names {
                return Err(crate::scene_error(format!(
                    "Table.concat: the tables' columns differ ({} against {})",
                    table.names.join(", "),
                    names.join(", ")
                )));
            }
            for (mine, theirs) in columns.iter_mut().zip(&table.columns) {
                match (mine, theirs) {
                    (Column::Numbers(a), Column::Numbers(b)) => a.extend_from_slice(b),
                    (Column::Words(a), Column::Words(b)) => a.extend_from_slice(b),
                    _ => {
                        return Err(crate::scene_error(
                            "Table.concat: a column holds numbers in one table, words in another",
                        ));
                    }
                }
            }
        }
        Ok(Table { names, columns })
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

//! The Python extension `fricosc._fricosc`: conversions between numpy arrays
//! and `fricosc-core`, nothing else. The public API (broadcasting, shapes as
//! classes, docstrings) is the Python package in `python/fricosc/`.
//!
//! Errors: every error of the core becomes a `ValueError` carrying the
//! command line's message (an internal error, a bug, a `RuntimeError`); errors
//! on an array element carry the element's flat index as a second argument, which
//! the Python side turns into an index of the broadcast shape.

use fricosc::error::{check_nonneg, Error};
use fricosc::history::{history as core_history, History};
use fricosc::profile::Table;
use fricosc::shape::{check_tol, evaluate_with, Shape};
use numpy::{IntoPyArray, PyArray1, PyArray3, PyReadonlyArray1};
use pyo3::exceptions::{PyRuntimeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::PyDict;
use rayon::prelude::*;
use std::sync::Arc;

/// Largest shape file read (`profile:FILE@U0`), as on the command line.
const MAX_FILE_BYTES: u64 = 64 << 20;

/// Arrays at least this long are evaluated on every core (rayon); shorter ones
/// on the calling thread, where starting the pool would cost more than it saves.
const PARALLEL_THRESHOLD: usize = 256;

fn to_py(e: Error) -> PyErr {
    match e {
        Error::Internal { .. } => PyRuntimeError::new_err(e.to_string()),
        _ => PyValueError::new_err(e.to_string()),
    }
}

/// A `ValueError(message, index)` for array element `index` (flat).
fn at_index(e: Error, index: usize) -> PyErr {
    match e {
        Error::Internal { .. } => PyRuntimeError::new_err((e.to_string(), index)),
        _ => PyValueError::new_err((e.to_string(), index)),
    }
}

/// The text of a tabulated shape's file, refused beyond [`MAX_FILE_BYTES`]
/// before reading (a UTF-8 byte-order mark is dropped).
fn read_file(path: &str) -> fricosc::Result<String> {
    let meta = std::fs::metadata(path).map_err(|e| Error::read(path, e))?;
    if meta.len() > MAX_FILE_BYTES {
        let (count, limit) = (meta.len() as u128, MAX_FILE_BYTES as u128);
        return Err(Error::TooLarge { what: format!("bytes of {path}"), count, limit });
    }
    let text = std::fs::read_to_string(path).map_err(|e| Error::read(path, e))?;
    Ok(text.strip_prefix('\u{feff}').map(str::to_string).unwrap_or(text))
}

/// A parsed shape (the core's `Shape`).
#[pyclass(name = "CoreShape", frozen, module = "fricosc._fricosc")]
struct CoreShape {
    inner: Shape,
}

#[pymethods]
impl CoreShape {
    /// Parse a shape as the command line names it (`flat`, `power:2.5`,
    /// `profile:FILE@U0`, ...).
    #[staticmethod]
    fn parse(spec: &str) -> PyResult<CoreShape> {
        Shape::parse_with(spec, &read_file).map(|inner| CoreShape { inner }).map_err(to_py)
    }

    /// A tabulated contact from columns: `profile` (true: `r, f(r)`) or `x, g(x)`,
    /// at mean indentation `u0` (the columns' length unit); `name` names it.
    #[staticmethod]
    fn from_table(
        x: PyReadonlyArray1<'_, f64>,
        v: PyReadonlyArray1<'_, f64>,
        u0: f64,
        profile: bool,
        name: &str,
    ) -> PyResult<CoreShape> {
        let (x, v) = (x.as_array().to_vec(), v.as_array().to_vec());
        let t = Table::from_columns(x, v, profile, name).and_then(|t| t.at(u0)).map_err(to_py)?;
        Ok(CoreShape { inner: Shape::Tabulated(Arc::new(t), name.to_string()) })
    }

    /// The canonical name.
    #[getter]
    fn name(&self) -> String {
        self.inner.name()
    }
}

/// `(vbar, amp)` of element `i`: checked, `vbar` from `vhat` if asked.
fn velocity(v: f64, a: f64, vhat: bool) -> fricosc::Result<(f64, f64)> {
    check_nonneg("amp", a)?;
    if vhat {
        Ok((fricosc::model::vbar_from_vhat(v, a)?, a))
    } else {
        Ok((check_nonneg("vbar", v)?, a))
    }
}

/// `(mu_ratio, reduction)` at every pair `(v[i], a[i])` (equal lengths): every
/// element is checked before any is computed; the first bad one is reported.
#[pyfunction]
#[pyo3(signature = (shape, v, a, vhat, tol))]
#[allow(clippy::type_complexity)]
fn evaluate<'py>(
    py: Python<'py>,
    shape: &CoreShape,
    v: PyReadonlyArray1<'py, f64>,
    a: PyReadonlyArray1<'py, f64>,
    vhat: bool,
    tol: f64,
) -> PyResult<(Bound<'py, PyArray1<f64>>, Bound<'py, PyArray1<f64>>)> {
    let (v, a) = (v.as_array(), a.as_array());
    if v.len() != a.len() {
        return Err(PyValueError::new_err(format!("vbar and amp differ in length ({} and {})", v.len(), a.len())));
    }
    check_tol(tol).map_err(to_py)?;
    let mut pairs = Vec::with_capacity(v.len());
    for (i, (&vi, &ai)) in v.iter().zip(a.iter()).enumerate() {
        pairs.push(velocity(vi, ai, vhat).map_err(|e| at_index(e, i))?);
    }
    let shape = &shape.inner;
    let results: Vec<fricosc::Result<(f64, f64)>> = py.detach(|| {
        let one = |&(v, a): &(f64, f64)| evaluate_with(shape, v, a, tol).map(|e| (e.ratio.mu_ratio, e.ratio.reduction));
        if pairs.len() >= PARALLEL_THRESHOLD {
            pairs.par_iter().map(one).collect()
        } else {
            pairs.iter().map(one).collect()
        }
    });
    let (mut mu, mut red) = (Vec::with_capacity(results.len()), Vec::with_capacity(results.len()));
    for (i, r) in results.into_iter().enumerate() {
        let (m, d) = r.map_err(|e| at_index(e, i))?;
        mu.push(m);
        red.push(d);
    }
    Ok((mu.into_pyarray(py), red.into_pyarray(py)))
}

/// One point as the command line's JSON (`fricosc point`), a string.
#[pyfunction]
fn point(shape: &CoreShape, v: f64, a: f64, vhat: bool, tol: f64) -> PyResult<String> {
    let (v, a) = velocity(v, a, vhat).map_err(to_py)?;
    let p = fricosc::shape::point(&shape.inner, v, a, tol).map_err(to_py)?;
    let mut obj = serde_json::Map::new();
    obj.insert("shape".into(), shape.inner.name().into());
    match serde_json::to_value(p) {
        Ok(serde_json::Value::Object(m)) => obj.extend(m),
        other => return Err(PyRuntimeError::new_err(format!("serialising the point: {other:?}"))),
    }
    Ok(serde_json::Value::Object(obj).to_string())
}

/// A force history (`fricosc history`) as a dict of numpy arrays.
#[pyfunction]
#[pyo3(signature = (shape, v, a, vhat, periods, samples, springs, spring_at))]
#[allow(clippy::too_many_arguments)]
fn history<'py>(
    py: Python<'py>,
    shape: &CoreShape,
    v: f64,
    a: f64,
    vhat: bool,
    periods: usize,
    samples: usize,
    springs: usize,
    spring_at: Vec<f64>,
) -> PyResult<Bound<'py, PyDict>> {
    let (v, a) = velocity(v, a, vhat).map_err(to_py)?;
    let shape = &shape.inner;
    let h: History = py.detach(|| core_history(shape, v, a, periods, samples, springs, &spring_at)).map_err(to_py)?;
    let d = PyDict::new(py);
    d.set_item("shape", &h.shape)?;
    d.set_item("vbar", h.vbar)?;
    d.set_item("amp", h.amp)?;
    d.set_item("units", &h.units)?;
    let col = |f: fn(&fricosc::history::Sample) -> f64| h.samples.iter().map(f).collect::<Vec<f64>>();
    d.set_item("tau", col(|s| s.tau).into_pyarray(py))?;
    d.set_item("normal", col(|s| s.normal).into_pyarray(py))?;
    d.set_item("tangential", col(|s| s.tangential).into_pyarray(py))?;
    let events: Vec<Option<String>> = h
        .samples
        .iter()
        .map(|s| s.event.and_then(|e| serde_json::to_value(e).ok()).and_then(|v| v.as_str().map(str::to_string)))
        .collect();
    d.set_item("event", events)?;
    if !h.spring_positions.is_empty() {
        d.set_item("spring_positions", h.spring_positions.clone().into_pyarray(py))?;
        let flat: Vec<f64> = h.samples.iter().flat_map(|s| s.springs.iter().flatten().copied()).collect();
        let arr = numpy::ndarray::Array3::from_shape_vec((h.samples.len(), h.spring_positions.len(), 2), flat)
            .map_err(|e| PyRuntimeError::new_err(format!("history springs: {e}")))?;
        let arr: Bound<'py, PyArray3<f64>> = arr.into_pyarray(py);
        d.set_item("springs", arr)?;
    }
    Ok(d)
}

/// A table's comparison with the exact values (`fricosc validate`'s JSON), a
/// string: columns as `fricosc::validation::rows_from_columns` reads them.
#[pyfunction]
#[pyo3(signature = (shape, velocity, amp, friction, vhat, mu, mu0, at_rest, tolerance))]
#[allow(clippy::too_many_arguments)]
fn validate(
    py: Python<'_>,
    shape: &CoreShape,
    velocity: PyReadonlyArray1<'_, f64>,
    amp: PyReadonlyArray1<'_, f64>,
    friction: PyReadonlyArray1<'_, f64>,
    vhat: bool,
    mu: bool,
    mu0: Option<f64>,
    at_rest: &str,
    tolerance: f64,
) -> PyResult<String> {
    use fricosc::validation::{compare, rows_from_columns, AtRest};
    let at_rest = match at_rest {
        "sliding" => AtRest::Sliding,
        "relaxed" => AtRest::Relaxed,
        other => return Err(PyValueError::new_err(format!("at_rest: '{other}' is neither 'sliding' nor 'relaxed'"))),
    };
    let (v, a, m) = (velocity.as_array().to_vec(), amp.as_array().to_vec(), friction.as_array().to_vec());
    let rows = rows_from_columns(&v, &a, &m, vhat, mu, mu0).map_err(to_py)?;
    let shape = &shape.inner;
    let result = py.detach(|| compare(shape, &rows, at_rest, tolerance)).map_err(to_py)?;
    serde_json::to_string(&result).map_err(|e| PyRuntimeError::new_err(format!("serialising: {e}")))
}

/// A flat punch's force history against the exact one (`fricosc validate
/// --history`'s JSON), a string.
#[pyfunction]
#[pyo3(signature = (shape, time, is_tau, tangential, normal, v, a, vhat, omega, tolerance))]
#[allow(clippy::too_many_arguments)]
fn validate_history(
    py: Python<'_>,
    shape: &CoreShape,
    time: PyReadonlyArray1<'_, f64>,
    is_tau: bool,
    tangential: PyReadonlyArray1<'_, f64>,
    normal: Option<PyReadonlyArray1<'_, f64>>,
    v: f64,
    a: f64,
    vhat: bool,
    omega: Option<f64>,
    tolerance: f64,
) -> PyResult<String> {
    use fricosc::validation::{compare_history, phases};
    let (v, a) = velocity(v, a, vhat).map_err(to_py)?;
    let t = time.as_array().to_vec();
    let f = tangential.as_array().to_vec();
    let n: Option<Vec<f64>> = normal.map(|x| x.as_array().to_vec());
    let taus = phases(&t, is_tau, omega, n.as_deref()).map_err(to_py)?;
    let shape = &shape.inner;
    let result = py.detach(|| compare_history(shape, v, a, &taus, &f, n.as_deref(), tolerance)).map_err(to_py)?;
    serde_json::to_string(&result).map_err(|e| PyRuntimeError::new_err(format!("serialising: {e}")))
}

/// A physical scene (`fricosc scene`): its JSON text in (or, without `text`, the
/// file `source`, read with the command line's cap), its results' JSON out (a
/// list, one per amplitude);
/// `source` is its path (a profile file is found relative to it) or a name.
#[pyfunction]
#[pyo3(signature = (text, source))]
fn scene(py: Python<'_>, text: Option<&str>, source: &str) -> PyResult<String> {
    let owned;
    let text = match text {
        Some(t) => t,
        None => {
            owned = read_file(source).map_err(to_py)?;
            &owned
        }
    };
    // A scene is a JSON object: serde would also take its fields as an array.
    if !text.trim_start().starts_with('{') {
        return Err(PyValueError::new_err(format!("{source}: a scene is a JSON object ({{...}})")));
    }
    let s: fricosc::scene::Scene = serde_json::from_str(text)
        .map_err(|e| to_py(Error::Parse { context: source.into(), reason: e.to_string() }))?;
    let result = py.detach(|| fricosc::scene::solve_with(&s, source, &read_file, &|_| {})).map_err(to_py)?;
    serde_json::to_string(&result).map_err(|e| PyRuntimeError::new_err(format!("serialising: {e}")))
}

/// The default relative quadrature tolerance of curved shapes.
#[pyfunction]
fn default_tol() -> f64 {
    fricosc::mdr::DEFAULT_TOL
}

#[pymodule]
fn _fricosc(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<CoreShape>()?;
    m.add_function(wrap_pyfunction!(evaluate, m)?)?;
    m.add_function(wrap_pyfunction!(point, m)?)?;
    m.add_function(wrap_pyfunction!(history, m)?)?;
    m.add_function(wrap_pyfunction!(validate, m)?)?;
    m.add_function(wrap_pyfunction!(scene, m)?)?;
    m.add_function(wrap_pyfunction!(validate_history, m)?)?;
    m.add_function(wrap_pyfunction!(default_tol, m)?)?;
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    Ok(())
}

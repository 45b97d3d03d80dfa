//! The Python extension `fricosc._fricosc`: conversions between numpy arrays
//! and Python objects and the `fricosc` library, nothing else. The public API
//! (broadcasting, shapes as classes, docstrings) is the Python package in
//! `python/fricosc/`.
//!
//! Errors: bad input raises `fricosc.InputError` (a `ValueError`) carrying the
//! command line's message; an internal error (a bug) `fricosc.InternalError`
//! (a `RuntimeError`). Errors on an array element carry the element's flat
//! index as a second argument, which the Python side turns into an index of
//! the broadcast shape.

use fricosc::contact::Table as ProfileTable;
use fricosc::history::{history as core_history, HistoryOptions, Sample};
use fricosc::stepper::Stepping;
use fricosc::validation::{
    compare, compare_history, compare_oscillation, convergence, to_static_units, AtRest, Check, Column, HistoryData,
    Table, TimeAxis,
};
use fricosc::{Conditions, Error, Report, Shape, DEFAULT_TOL};
use numpy::{IntoPyArray, PyArray3, PyReadonlyArray1};
use pyo3::create_exception;
use pyo3::exceptions::{PyRuntimeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::PyDict;
use std::sync::Arc;

mod vectorised;
use vectorised::{evaluate, evaluate_oscillation, evaluate_plane, evaluate_system};

create_exception!(fricosc, InputError, PyValueError, "Bad input: a value, a shape or a table fricosc refuses.");
create_exception!(fricosc, InternalError, PyRuntimeError, "A bug of fricosc (please report it).");

fn to_py(e: Error) -> PyErr {
    if e.is_internal() {
        InternalError::new_err(e.to_string())
    } else {
        InputError::new_err(e.to_string())
    }
}

/// An error for array element `index` (flat): `(message, index)`.
fn at_index(e: Error, index: usize) -> PyErr {
    if e.is_internal() {
        InternalError::new_err((e.to_string(), index))
    } else {
        InputError::new_err((e.to_string(), index))
    }
}

/// Run `work` on a thread of its own with the GIL released, looking for
/// Ctrl-C every [`POLL`]: on one, every solve on a system is asked to stop
/// (`fricosc::interrupt`; it returns at its next period) and
/// `KeyboardInterrupt` is raised once it has. A signal that came as the work
/// ended is raised too, before any Python (numpy) code runs.
fn interruptible<T: Send>(py: Python<'_>, work: impl FnOnce() -> fricosc::Result<T> + Send) -> PyResult<T> {
    std::thread::scope(|scope| {
        let (tx, rx) = std::sync::mpsc::channel();
        // A panic is caught on the thread (and raised as an internal error), not carried out of the scope.
        scope.spawn(move || tx.send(std::panic::catch_unwind(std::panic::AssertUnwindSafe(work))));
        let rx = std::sync::Mutex::new(rx);
        // The answer, none yet (`Ok(None)`), or the solve's thread ended without one (a panic).
        let recv = |wait: Option<std::time::Duration>| {
            use std::sync::mpsc::RecvTimeoutError::{Disconnected, Timeout};
            let rx = rx.lock().map_err(|_| InternalError::new_err("a solve's channel was poisoned"))?;
            let got = match wait {
                Some(d) => rx.recv_timeout(d),
                None => rx.recv().map_err(|_| Disconnected),
            };
            match got {
                Ok(r) => Ok(Some(r)),
                Err(Timeout) => Ok(None),
                Err(Disconnected) => Err(InternalError::new_err("a solve ended without an answer (a panic)")),
            }
        };
        loop {
            let answer = py.detach(|| recv(Some(POLL)))?;
            if let Err(e) = py.check_signals() {
                fricosc::interrupt::request();
                let _ = py.detach(|| recv(None));
                fricosc::interrupt::clear();
                return Err(e);
            }
            if let Some(r) = answer {
                return r.map_err(|_| InternalError::new_err("a solve panicked (please report it)"))?.map_err(to_py);
            }
        }
    })
}

/// How often a long solve looks for Ctrl-C ([`interruptible`]).
const POLL: std::time::Duration = std::time::Duration::from_millis(50);

fn serialise_err(e: impl std::fmt::Display) -> PyErr {
    InternalError::new_err(format!("converting the result: {e}"))
}

/// The text of a file a shape or scene names, with the command line's cap,
/// counted as it is read ([`fricosc::io::read_capped`]).
fn read_file(path: &str) -> std::io::Result<String> {
    fricosc::io::read_capped(path, fricosc::io::MAX_FILE_BYTES)
}

/// A parsed shape.
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
        let t = ProfileTable::from_columns(x, v, profile, name).and_then(|t| t.at(u0)).map_err(to_py)?;
        Ok(CoreShape { inner: Shape::from_contact(Arc::new(t.named(name))) })
    }

    /// The canonical name.
    #[getter]
    fn name(&self) -> String {
        self.inner.name().to_string()
    }
}

/// The conditions of one element of the seed's problem: checked, `vbar`
/// from `vhat` if asked (and defined).
fn conditions(v: f64, a: f64, vhat: bool, tol: f64) -> fricosc::Result<Conditions> {
    let c = if vhat { Conditions::vhat(v, a)? } else { Conditions::vbar(v, a)? };
    c.as_vbar()?;
    c.with_tol(tol)
}

/// The conditions of a history: `(v, a)` as `vbar` or `vhat`, with a
/// tangential oscillation `(T, phase)` if given (then `v` is `vhat`).
fn history_conditions(v: f64, a: f64, vhat: bool, tangential: Option<(f64, f64)>) -> fricosc::Result<Conditions> {
    match tangential {
        Some((t, p)) => oscillation(v, a, t, p, DEFAULT_TOL),
        None => conditions(v, a, vhat, DEFAULT_TOL),
    }
}

/// The conditions of one element under a tangential oscillation.
fn oscillation(v: f64, a: f64, t: f64, p: f64, tol: f64) -> fricosc::Result<Conditions> {
    Conditions::vhat(v, a)?.with_tangential(t, p)?.with_tol(tol)
}

/// One point under oscillation in the sliding direction, as `fricosc point
/// --tangential-amp` reports it: a dict.
#[pyfunction]
#[pyo3(signature = (shape, vhat, amp, t, phase, tol))]
fn point_oscillation<'py>(
    py: Python<'py>,
    shape: &CoreShape,
    vhat: f64,
    amp: f64,
    t: f64,
    phase: f64,
    tol: f64,
) -> PyResult<Bound<'py, PyAny>> {
    #[derive(serde::Serialize)]
    struct Named<'a> {
        shape: &'a str,
        #[serde(flatten)]
        point: Report,
    }
    let c = oscillation(vhat, amp, t, phase, tol).map_err(to_py)?;
    let p = shape.inner.report(&c).map_err(to_py)?;
    pythonize::pythonize(py, &Named { shape: shape.inner.name(), point: p }).map_err(serialise_err)
}

/// One point under an oscillation across the sliding direction, as `fricosc
/// point --transverse-amp` reports it: a dict.
#[pyfunction]
#[pyo3(signature = (shape, v, amp, vhat, tangential, w, psi))]
#[allow(clippy::too_many_arguments)]
fn point_plane<'py>(
    py: Python<'py>,
    shape: &CoreShape,
    v: f64,
    amp: f64,
    vhat: bool,
    tangential: Option<(f64, f64)>,
    w: f64,
    psi: f64,
) -> PyResult<Bound<'py, PyAny>> {
    #[derive(serde::Serialize)]
    struct Named<'a> {
        shape: &'a str,
        vhat: f64,
        amp: f64,
        tangential_amp: f64,
        phase: f64,
        transverse_amp: f64,
        transverse_phase: f64,
        #[serde(flatten)]
        point: Report,
    }
    let transverse = fricosc::plane::Transverse::new(w, psi).map_err(to_py)?;
    let c = match tangential {
        Some((t, p)) => oscillation(v, amp, t, p, DEFAULT_TOL),
        None if vhat => Conditions::vhat(v, amp),
        None => Conditions::vbar(v, amp),
    }
    .map_err(to_py)?
    .with_transverse(transverse);
    let point = interruptible(py, || shape.inner.report(&c))?;
    let (t, phase) = c.tangential().unwrap_or((0.0, 0.0));
    let named = Named {
        shape: shape.inner.name(),
        vhat: c.as_vhat(),
        amp,
        tangential_amp: t,
        phase,
        transverse_amp: transverse.amp(),
        transverse_phase: transverse.phase(),
        point,
    };
    pythonize::pythonize(py, &named).map_err(serialise_err)
}

/// A body on a system with mass and stiffness, as `fricosc point
/// --system-stiffness` reports it: a dict.
#[pyfunction]
#[pyo3(signature = (shape, vhat, amp, t, phase, stiffness, frequency_ratio, damping, springs=None))]
#[allow(clippy::too_many_arguments)]
fn point_system<'py>(
    py: Python<'py>,
    shape: &CoreShape,
    vhat: f64,
    amp: f64,
    t: f64,
    phase: f64,
    stiffness: f64,
    frequency_ratio: f64,
    damping: f64,
    springs: Option<usize>,
) -> PyResult<Bound<'py, PyAny>> {
    let c = oscillation(vhat, amp, t, phase, DEFAULT_TOL).map_err(to_py)?;
    let mut sys = fricosc::system::System::new(stiffness, frequency_ratio, damping).map_err(to_py)?;
    if let Some(n) = springs {
        sys = sys.with_springs(n).map_err(to_py)?;
    }
    let c = c.with_system(sys);
    let Report::System(r) = interruptible(py, || shape.inner.report(&c))? else {
        return Err(to_py(fricosc::Error::Internal { what: "a point on a system is reported as one".into() }));
    };
    /// The report with its regime and reduction, as `fricosc point` prints them.
    #[derive(serde::Serialize)]
    struct Named {
        regime: String,
        reduction: f64,
        #[serde(flatten)]
        report: fricosc::system::SystemReport,
    }
    let named = Named { regime: r.regime(), reduction: r.ratio().reduction, report: r };
    pythonize::pythonize(py, &named).map_err(serialise_err)
}

/// One point as `fricosc point` reports it: a dict.
#[pyfunction]
fn point<'py>(py: Python<'py>, shape: &CoreShape, v: f64, a: f64, vhat: bool, tol: f64) -> PyResult<Bound<'py, PyAny>> {
    #[derive(serde::Serialize)]
    struct Named<'a> {
        shape: &'a str,
        #[serde(flatten)]
        point: Report,
    }
    let p = shape.inner.report(&conditions(v, a, vhat, tol).map_err(to_py)?).map_err(to_py)?;
    pythonize::pythonize(py, &Named { shape: shape.inner.name(), point: p }).map_err(serialise_err)
}

/// A force history (`fricosc history`) as a dict of numpy arrays.
#[pyfunction]
#[pyo3(signature = (shape, v, a, vhat, tangential, periods, samples, springs, spring_at, system=None, transverse=None))]
#[allow(clippy::too_many_arguments)]
fn history<'py>(
    py: Python<'py>,
    shape: &CoreShape,
    v: f64,
    a: f64,
    vhat: bool,
    tangential: Option<(f64, f64)>,
    periods: usize,
    samples: usize,
    springs: usize,
    spring_at: Vec<f64>,
    system: Option<(f64, f64, f64)>,
    transverse: Option<(f64, f64)>,
) -> PyResult<Bound<'py, PyDict>> {
    let c = match transverse {
        // The plane asks for vhat only: amp = 0 is the transverse oscillation alone.
        Some((w, psi)) => {
            let w = fricosc::plane::Transverse::new(w, psi).map_err(to_py)?;
            let c = if vhat { Conditions::vhat(v, a) } else { Conditions::vbar(v, a) }.map_err(to_py)?;
            match tangential {
                Some((t, p)) => c.with_tangential(t, p).map_err(to_py)?,
                None => c,
            }
            .with_transverse(w)
        }
        None => history_conditions(v, a, vhat, tangential).map_err(to_py)?,
    };
    let shape = &shape.inner;
    let opts = HistoryOptions::default()
        .with_periods(periods)
        .with_samples(samples)
        .with_springs(springs)
        .with_spring_at(spring_at);
    let c = match system {
        Some((k, om, z)) => {
            c.with_system(fricosc::system::System::new(k, om, z).and_then(|s| s.with_springs(springs)).map_err(to_py)?)
        }
        None => c,
    };
    let h = interruptible(py, || core_history(shape, &c, &opts))?;
    let d = PyDict::new(py);
    d.set_item("shape", &h.shape)?;
    for (key, value) in [
        ("vbar", h.point.vbar),
        ("vhat", h.point.vhat),
        ("amp", Some(h.point.amp)),
        ("tangential_amp", h.point.in_plane.tangential_amp),
        ("phase", h.point.in_plane.phase),
        ("transverse_amp", h.point.in_plane.transverse_amp),
        ("transverse_phase", h.point.in_plane.transverse_phase),
    ] {
        if let Some(x) = value {
            d.set_item(key, x)?;
        }
    }
    d.set_item("units", &h.units)?;
    let col = |f: fn(&Sample) -> f64| h.samples.iter().map(f).collect::<Vec<f64>>();
    d.set_item("tau", col(|s| s.tau).into_pyarray(py))?;
    d.set_item("normal", col(|s| s.normal).into_pyarray(py))?;
    d.set_item("tangential", col(|s| s.tangential).into_pyarray(py))?;
    if h.samples.first().is_some_and(|s| s.transverse.is_some()) {
        d.set_item("transverse", col_of(&h.samples, |s| s.transverse.unwrap_or(f64::NAN)).into_pyarray(py))?;
    }
    let events: Vec<Option<Bound<'py, PyAny>>> = h
        .samples
        .iter()
        .map(|s| s.event.map(|e| pythonize::pythonize(py, &e)).transpose())
        .collect::<Result<_, _>>()
        .map_err(serialise_err)?;
    d.set_item("event", events)?;
    // On a system, the body: its lag behind the drive, velocity, and the system's force.
    if h.samples.first().is_some_and(|s| s.body.is_some()) {
        let body = |f: fn(&fricosc::history::Body) -> f64| col_of(&h.samples, |s| s.body.map_or(f64::NAN, |b| f(&b)));
        d.set_item("body_lag", body(|b| b.body_lag).into_pyarray(py))?;
        d.set_item("body_velocity", body(|b| b.body_velocity).into_pyarray(py))?;
        d.set_item("system_force", body(|b| b.system_force).into_pyarray(py))?;
    }
    if !h.spring_positions.is_empty() {
        d.set_item("spring_positions", h.spring_positions.clone().into_pyarray(py))?;
        let flat: Vec<f64> = h.samples.iter().flat_map(|s| s.springs.iter().flatten().copied()).collect();
        let arr = numpy::ndarray::Array3::from_shape_vec((h.samples.len(), h.spring_positions.len(), 2), flat)
            .map_err(serialise_err)?;
        let arr: Bound<'py, PyArray3<f64>> = arr.into_pyarray(py);
        d.set_item("springs", arr)?;
    }
    Ok(d)
}

/// One value of every sample.
fn col_of(samples: &[Sample], f: impl Fn(&Sample) -> f64) -> Vec<f64> {
    samples.iter().map(f).collect()
}

/// A table as Python passes it: every column's name, and the numeric columns read.
type NamedColumns<'py> = (Vec<String>, Vec<(String, PyReadonlyArray1<'py, f64>)>);

/// A table as the command line reads one ([`Table::from_columns`]): every
/// column's name, and the values of those among [`Table::COLUMNS`] (numbers).
fn table_of(names: Vec<String>, columns: Vec<(String, PyReadonlyArray1<'_, f64>)>) -> PyResult<Table> {
    let mut read = vec![];
    for (name, values) in columns {
        let known = Table::COLUMNS.iter().find(|&&c| c == name && c != "shape");
        let name =
            known.ok_or_else(|| InputError::new_err(format!("table: the column '{name}' is not one fricosc reads")))?;
        read.push((*name, Column::Numbers(values.as_array().to_vec())));
    }
    Table::from_columns(&names, read, "columns", "table").map_err(to_py)
}

/// A table's comparison with the exact values (`fricosc validate`'s report) as a
/// dict: the table read as the command line reads it, compared as it compares
/// it (under oscillation in the sliding direction where it has `tangential_amp`;
/// on a system `(kappa, Omega, zeta)` with its attractors).
#[pyfunction]
#[pyo3(signature = (shape, names, columns, mu0, at_rest, tolerance, peer, peer_springs, system=None, max_error=None))]
#[allow(clippy::too_many_arguments)]
fn validate<'py>(
    py: Python<'py>,
    shape: &CoreShape,
    names: Vec<String>,
    columns: Vec<(String, PyReadonlyArray1<'py, f64>)>,
    mu0: Option<f64>,
    at_rest: &str,
    tolerance: f64,
    peer: Option<usize>,
    peer_springs: Option<usize>,
    system: Option<(f64, f64, f64)>,
    max_error: Option<f64>,
) -> PyResult<Bound<'py, PyAny>> {
    let system = system.map(|(k, om, z)| fricosc::system::System::new(k, om, z)).transpose().map_err(to_py)?;
    let check = Check::default()
        .with_at_rest(at_rest_of(at_rest)?)
        .with_tolerance(tolerance)
        .with_peer(peer.map(|m| Stepping { steps_per_period: m, springs: peer_springs.unwrap_or(m) }))
        .with_system(system)
        .with_max_error(max_error);
    let table = table_of(names, columns)?;
    let shape = &shape.inner;
    let result = if table.is_oscillation() {
        let rows = table.oscillation_rows(mu0, "table").map_err(to_py)?;
        let v = interruptible(py, || compare_oscillation(shape, &rows, &check))?;
        pythonize::pythonize(py, &v)
    } else {
        let rows = table.rows(mu0, "table").map_err(to_py)?;
        let mut v = interruptible(py, || compare(shape, &rows, &check))?;
        v.key_by(&table);
        pythonize::pythonize(py, &v)
    }
    .map_err(serialise_err)?;
    if !table.ignored_columns().is_empty() {
        result.set_item("ignored_columns", table.ignored_columns().to_vec())?;
    }
    Ok(result)
}

/// `fricosc fit`'s report as a dict: the model fitted to the rows `(v0, du,
/// omega, mu, sigma)` with the `fixed` parameters `(mu0, kx/kz, u0)` held,
/// on the rig's `system` `(kappa, Omega, zeta)` if any (its `kappa` fitted
/// from there where `fit_system_stiffness`), each fitted parameter within
/// its `bounds` `[lo, hi]` where given (in the order of `fricosc::fit::NAMES`).
#[pyfunction]
#[pyo3(signature = (shape, v0, du, omega, mu, sigma, fixed, system=None, load=None, fit_system_stiffness=false, bounds=None))]
#[allow(clippy::too_many_arguments)]
fn fit<'py>(
    py: Python<'py>,
    shape: &CoreShape,
    v0: PyReadonlyArray1<'py, f64>,
    du: PyReadonlyArray1<'py, f64>,
    omega: PyReadonlyArray1<'py, f64>,
    mu: PyReadonlyArray1<'py, f64>,
    sigma: Option<PyReadonlyArray1<'py, f64>>,
    fixed: (Option<f64>, Option<f64>, Option<f64>),
    system: Option<(f64, f64, f64)>,
    load: Option<PyReadonlyArray1<'py, f64>>,
    fit_system_stiffness: bool,
    bounds: Option<[Option<[f64; 2]>; 4]>,
) -> PyResult<Bound<'py, PyAny>> {
    let system = system.map(|(k, om, z)| fricosc::system::System::new(k, om, z)).transpose().map_err(to_py)?;
    let (v0, du, omega, mu) = (v0.as_slice()?, du.as_slice()?, omega.as_slice()?, mu.as_slice()?);
    let sigma = sigma.as_ref().map(|s| s.as_slice()).transpose()?;
    let load = load.as_ref().map(|s| s.as_slice()).transpose()?;
    let n = v0.len();
    let optional = [sigma.map_or(n, |s| s.len()), load.map_or(n, |s| s.len())];
    if [du.len(), omega.len(), mu.len()].iter().chain(&optional).any(|&k| k != n) {
        return Err(InputError::new_err("fit: the columns differ in length"));
    }
    let rows: Vec<fricosc::fit::Measurement> = (0..n)
        .map(|i| fricosc::fit::Measurement {
            v0: v0[i],
            du: du[i],
            omega: omega[i],
            mu: mu[i],
            sigma: sigma.map(|s| s[i]),
            system,
            load: load.map(|l| l[i]),
        })
        .collect();
    let bounds = bounds.unwrap_or_default();
    let fixed =
        fricosc::fit::Fixed { mu0: fixed.0, stiffness_ratio: fixed.1, u0: fixed.2, fit_system_stiffness, bounds };
    let shape = &shape.inner;
    let r = interruptible(py, || fricosc::fit::fit(shape, &rows, &fixed))?;
    pythonize::pythonize(py, &r).map_err(serialise_err)
}

fn at_rest_of(at_rest: &str) -> PyResult<AtRest> {
    match at_rest {
        "sliding" => Ok(AtRest::Sliding),
        "relaxed" => Ok(AtRest::Relaxed),
        other => Err(InputError::new_err(format!("at_rest: '{other}' is neither 'sliding' nor 'relaxed'"))),
    }
}

/// A convergence study (`fricosc validate --series`'s report) as a dict: one
/// table of columns per resolution, each read as [`validate`] reads one.
#[pyfunction]
#[pyo3(signature = (shape, resolutions, tables, mu0, at_rest, tolerance, target, system=None))]
#[allow(clippy::too_many_arguments)]
fn validate_series<'py>(
    py: Python<'py>,
    shape: &CoreShape,
    resolutions: Vec<f64>,
    tables: Vec<NamedColumns<'py>>,
    mu0: Option<f64>,
    at_rest: &str,
    tolerance: f64,
    target: Option<f64>,
    system: Option<(f64, f64, f64)>,
) -> PyResult<Bound<'py, PyAny>> {
    let system = system.map(|(k, om, z)| fricosc::system::System::new(k, om, z)).transpose().map_err(to_py)?;
    let check = Check::default().with_at_rest(at_rest_of(at_rest)?).with_tolerance(tolerance).with_system(system);
    let mut rows = vec![];
    for (names, columns) in tables {
        rows.push(table_of(names, columns)?.rows(mu0, "table").map_err(to_py)?);
    }
    let shape = &shape.inner;
    let result = interruptible(py, || convergence(shape, &resolutions, &rows, &check, target))?;
    pythonize::pythonize(py, &result).map_err(serialise_err)
}

/// A force history against the exact one (`fricosc validate --history`'s
/// report) as a dict.
#[pyfunction]
#[pyo3(signature = (shape, time, is_tau, tangential, normal, v, a, vhat, oscillation, omega, tolerance, static_force, mu0, system, body, transverse=None, across=None))]
#[allow(clippy::too_many_arguments)]
fn validate_history<'py>(
    py: Python<'py>,
    shape: &CoreShape,
    time: PyReadonlyArray1<'py, f64>,
    is_tau: bool,
    tangential: PyReadonlyArray1<'py, f64>,
    normal: Option<PyReadonlyArray1<'py, f64>>,
    v: f64,
    a: f64,
    vhat: bool,
    oscillation: Option<(f64, f64)>,
    omega: Option<f64>,
    tolerance: f64,
    static_force: f64,
    mu0: f64,
    system: Option<(f64, f64, f64)>,
    body: Option<(PyReadonlyArray1<'py, f64>, PyReadonlyArray1<'py, f64>)>,
    transverse: Option<(f64, f64)>,
    across: Option<PyReadonlyArray1<'py, f64>>,
) -> PyResult<Bound<'py, PyAny>> {
    let mut c = history_conditions(v, a, vhat, oscillation).map_err(to_py)?;
    if let Some((w, psi)) = transverse {
        c = c.with_transverse(fricosc::plane::Transverse::new(w, psi).map_err(to_py)?);
    }
    let mut y: Option<Vec<f64>> = across.map(|x| x.as_array().to_vec());
    if let Some(y) = y.as_deref_mut() {
        to_static_units(y, None, static_force, mu0).map_err(to_py)?;
    }
    if let Some((k, om, z)) = system {
        c = c.with_system(fricosc::system::System::new(k, om, z).map_err(to_py)?);
    }
    let body = body.map(|(l, v)| (l.as_array().to_vec(), v.as_array().to_vec()));
    let t = time.as_array().to_vec();
    let mut f = tangential.as_array().to_vec();
    let mut n: Option<Vec<f64>> = normal.map(|x| x.as_array().to_vec());
    to_static_units(&mut f, n.as_deref_mut(), static_force, mu0).map_err(to_py)?;
    let time = if is_tau { TimeAxis::Phase(&t) } else { TimeAxis::Time { t: &t, omega } };
    let body = body.as_ref().map(|(l, v)| (&l[..], &v[..]));
    let data = HistoryData { time, tangential: &f, normal: n.as_deref(), transverse: y.as_deref(), body };
    let shape = &shape.inner;
    let result = interruptible(py, || compare_history(shape, &c, &data, tolerance))?;
    pythonize::pythonize(py, &result).map_err(serialise_err)
}

/// A physical scene (`fricosc scene`): its JSON text in (or, without `text`, the
/// file `source`, read with the command line's cap), its results out as a list
/// of dicts, one per amplitude; `source` is its path (a profile file is found
/// relative to it) or a name.
#[pyfunction]
#[pyo3(signature = (text, source))]
fn scene<'py>(py: Python<'py>, text: Option<&str>, source: &str) -> PyResult<Bound<'py, PyAny>> {
    let owned;
    let text = match text {
        Some(t) => t,
        None => {
            owned = read_file(source).map_err(|e| to_py(Error::File { path: source.into(), source: Box::new(e) }))?;
            &owned
        }
    };
    // A scene is a JSON object: serde would also take its fields as an array.
    if !text.trim_start().starts_with('{') {
        return Err(InputError::new_err(format!("{source}: a scene is a JSON object ({{...}})")));
    }
    let s: fricosc::scene::Scene = serde_json::from_str(text)
        .map_err(|e| to_py(Error::Parse { context: source.into(), reason: e.to_string() }))?;
    let result = py.detach(|| fricosc::scene::solve_with(&s, source, &read_file, &|_| {})).map_err(to_py)?;
    pythonize::pythonize(py, &result).map_err(serialise_err)
}

/// The default relative quadrature tolerance of curved shapes.
#[pyfunction]
fn default_tol() -> f64 {
    fricosc::DEFAULT_TOL
}

#[pymodule]
fn _fricosc(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<CoreShape>()?;
    m.add("InputError", m.py().get_type::<InputError>())?;
    m.add("InternalError", m.py().get_type::<InternalError>())?;
    m.add_function(wrap_pyfunction!(evaluate, m)?)?;
    m.add_function(wrap_pyfunction!(point, m)?)?;
    m.add_function(wrap_pyfunction!(evaluate_oscillation, m)?)?;
    m.add_function(wrap_pyfunction!(evaluate_system, m)?)?;
    m.add_function(wrap_pyfunction!(evaluate_plane, m)?)?;
    m.add_function(wrap_pyfunction!(point_oscillation, m)?)?;
    m.add_function(wrap_pyfunction!(point_plane, m)?)?;
    m.add_function(wrap_pyfunction!(point_system, m)?)?;
    m.add_function(wrap_pyfunction!(history, m)?)?;
    m.add_function(wrap_pyfunction!(validate, m)?)?;
    m.add_function(wrap_pyfunction!(scene, m)?)?;
    m.add_function(wrap_pyfunction!(validate_history, m)?)?;
    m.add_function(wrap_pyfunction!(validate_series, m)?)?;
    m.add_function(wrap_pyfunction!(default_tol, m)?)?;
    m.add_function(wrap_pyfunction!(fit, m)?)?;
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    Ok(())
}

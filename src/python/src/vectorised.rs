//! The vectorised evaluations behind `fricosc.mu_ratio` and
//! `fricosc.reduction`: every element of the broadcast arrays checked
//! first (the first bad one reported by its flat index), then computed in
//! chunks sized by time, with the GIL released, in parallel where a chunk is
//! worth it, and Ctrl-C answered between chunks and (on a system) within a
//! period of the solve.

use crate::{at_index, conditions, interruptible, oscillation, to_py, CoreShape, InputError, InternalError};
use fricosc::system::System;
use fricosc::Conditions;
use numpy::{PyArrayDyn, PyArrayMethods, PyReadonlyArrayDyn, PyUntypedArrayMethods};
use pyo3::prelude::*;

/// Elements in the first chunk: it measures the cost of an element (a
/// stiff flat point costs 0.2 us, a curved one 5 us, a curved one on a
/// system 20 ms: five orders of magnitude), and the chunks after it are
/// sized from that to take about [`CHUNK_SECONDS`].
const FIRST_CHUNK: usize = 16;

/// Elements checked between two checks for Ctrl-C while the inputs are
/// checked (a broadcast of 4e9 elements takes about a minute to check).
const CHECK_CHUNK: usize = 1 << 20;

/// The time one chunk should take on all cores.
const CHUNK_SECONDS: f64 = 0.04;
/// Largest chunk (the buffer it needs: 24 bytes an element).
const MAX_CHUNK: usize = 1 << 20;

/// A chunk is evaluated on every core (rayon) when its work is at least
/// this (seconds, at the last chunk's cost an element); shorter ones on one
/// thread, where starting the pool would cost more than it saves.
const PARALLEL_SECONDS: f64 = 1e-3;

/// Check element `i` of the checking pass for Ctrl-C every [`CHECK_CHUNK`] elements.
fn check_signals_at(py: Python<'_>, i: usize) -> PyResult<()> {
    if i % CHECK_CHUNK == CHECK_CHUNK - 1 {
        py.check_signals()?;
    }
    Ok(())
}

/// A new float64 array of shape `dims`, zeroed, by numpy itself: an array too
/// large for memory raises `MemoryError` (rust-numpy's own constructor panics).
fn zeros<'py>(py: Python<'py>, dims: &[usize]) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
    let np = PyModule::import(py, "numpy")?;
    let a = np.getattr("zeros")?.call1((pyo3::types::PyTuple::new(py, dims)?,))?;
    a.cast_into::<PyArrayDyn<f64>>().map_err(|e| InternalError::new_err(format!("numpy.zeros: {e}")))
}

/// `mu_ratio` (or, with `reduction`, the reduction) at every element of the
/// broadcast arrays `v`, `a` (same shape; views are read in place), into a new
/// array of that shape. Every element is checked before any is computed (the
/// first bad one is reported); memory is the output array plus a chunk.
#[pyfunction]
#[pyo3(signature = (shape, v, a, vhat, tol, reduction))]
pub(crate) fn evaluate<'py>(
    py: Python<'py>,
    shape: &CoreShape,
    v: PyReadonlyArrayDyn<'py, f64>,
    a: PyReadonlyArrayDyn<'py, f64>,
    vhat: bool,
    tol: f64,
    reduction: bool,
) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
    let (v, a) = (v.as_array(), a.as_array());
    if v.shape() != a.shape() {
        return Err(InputError::new_err(format!("vbar and amp differ in shape ({:?} and {:?})", v.shape(), a.shape())));
    }
    Conditions::vbar(0.0, 0.0).and_then(|c| c.with_tol(tol)).map_err(to_py)?;
    // The output first: an array too large for memory is refused before the
    // inputs are checked.
    let out = zeros(py, v.shape())?;
    for (i, (&vi, &ai)) in v.iter().zip(a.iter()).enumerate() {
        conditions(vi, ai, vhat, tol).map_err(|e| at_index(e, i))?;
        check_signals_at(py, i)?;
    }
    let shape = &shape.inner;
    let mut inputs = v.iter().zip(a.iter()).map(|(&x, &y)| [x, y]);
    chunked(py, out, &mut inputs, false, &|&[x, y]: &[f64; 2]| {
        let r = shape.evaluate(&conditions(x, y, vhat, tol)?)?.ratio;
        Ok(if reduction { r.reduction } else { r.mu_ratio })
    })
}

/// `mu_ratio` (or the reduction) under oscillation in the sliding direction
/// ([`fricosc::combined`]) at every element of the broadcast arrays `vhat`,
/// `amp`, `t` (tangential amplitude), `phase`; checked first, as [`evaluate`].
#[pyfunction]
#[pyo3(signature = (shape, vhat, amp, t, phase, tol, reduction))]
#[allow(clippy::too_many_arguments)]
pub(crate) fn evaluate_oscillation<'py>(
    py: Python<'py>,
    shape: &CoreShape,
    vhat: PyReadonlyArrayDyn<'py, f64>,
    amp: PyReadonlyArrayDyn<'py, f64>,
    t: PyReadonlyArrayDyn<'py, f64>,
    phase: PyReadonlyArrayDyn<'py, f64>,
    tol: f64,
    reduction: bool,
) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
    let arrays = [vhat.as_array(), amp.as_array(), t.as_array(), phase.as_array()];
    if arrays.iter().any(|x| x.shape() != arrays[0].shape()) {
        return Err(InputError::new_err("vhat, amp, tangential_amp and phase differ in shape".to_string()));
    }
    Conditions::vbar(0.0, 0.0).and_then(|c| c.with_tol(tol)).map_err(to_py)?;
    let out = zeros(py, arrays[0].shape())?;
    let each = || {
        arrays[0]
            .iter()
            .zip(arrays[1].iter())
            .zip(arrays[2].iter())
            .zip(arrays[3].iter())
            .map(|(((&v, &a), &t), &p)| [v, a, t, p])
    };
    for (i, [v, a, t, p]) in each().enumerate() {
        oscillation(v, a, t, p, tol).map_err(|e| at_index(e, i))?;
        check_signals_at(py, i)?;
    }
    let shape = &shape.inner;
    chunked(py, out, &mut each(), false, &|&[v, a, t, p]: &[f64; 4]| {
        let r = shape.ratio(&oscillation(v, a, t, p, tol)?)?;
        Ok(if reduction { r.reduction } else { r.mu_ratio })
    })
}

/// How an element on a system is posed: the velocity as `vhat` (else
/// `vbar`), with a tangential drive (then `vhat`), a curved body's springs.
#[derive(Clone, Copy)]
struct Posed {
    vhat: bool,
    tangential: bool,
    springs: Option<usize>,
    tol: f64,
}

/// One element on a system, as `fricosc batch` poses a row with
/// `system_stiffness` (its values bit for bit): `x` is `[v, amp, T, phase,
/// kappa, Omega, zeta]`.
fn on_system(x: &[f64; 7], how: Posed) -> fricosc::Result<Conditions> {
    let [v, a, t, p, kappa, omega, zeta] = *x;
    let c = if how.tangential { oscillation(v, a, t, p, how.tol)? } else { conditions(v, a, how.vhat, how.tol)? };
    let sys = System::new(kappa, omega, zeta)?;
    Ok(c.with_system(how.springs.map_or(Ok(sys), |n| sys.with_springs(n))?))
}

/// `mu_ratio` (or the reduction) on a system with mass and stiffness at
/// every element of the broadcast arrays (`x` as [`on_system`] reads them);
/// checked first, as [`evaluate`]. With `nan`, an element the solver
/// refuses as it solves (a body that cannot settle, too light to resolve)
/// is NaN; otherwise the refusal is raised with the element's index. An
/// internal error is raised either way.
#[pyfunction]
#[pyo3(signature = (shape, x, vhat, tangential, springs, tol, reduction, nan))]
#[allow(clippy::too_many_arguments)]
pub(crate) fn evaluate_system<'py>(
    py: Python<'py>,
    shape: &CoreShape,
    x: Vec<PyReadonlyArrayDyn<'py, f64>>,
    vhat: bool,
    tangential: bool,
    springs: Option<usize>,
    tol: f64,
    reduction: bool,
    nan: bool,
) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
    let arrays = views(&x, 7, "evaluate_system", tol)?;
    let how = Posed { vhat, tangential, springs, tol };
    let out = zeros(py, arrays[0].shape())?;
    let mut each = rows::<7>(&arrays);
    for (i, row) in rows::<7>(&arrays).enumerate() {
        on_system(&row, how).map_err(|e| at_index(e, i))?;
        check_signals_at(py, i)?;
    }
    let shape = &shape.inner;
    chunked(py, out, &mut each, nan, &|row: &[f64; 7]| {
        let r = shape.ratio(&on_system(row, how)?)?;
        Ok(if reduction { r.reduction } else { r.mu_ratio })
    })
}

/// The `n` arrays of `x` as views, checked to be of one shape (for
/// `what`), and the tolerance `tol` checked.
fn views<'a>(
    x: &'a [PyReadonlyArrayDyn<'_, f64>],
    n: usize,
    what: &str,
    tol: f64,
) -> PyResult<Vec<numpy::ndarray::ArrayViewD<'a, f64>>> {
    let arrays: Vec<_> = x.iter().map(|a| a.as_array()).collect();
    if arrays.len() != n || arrays.iter().any(|a| a.shape() != arrays[0].shape()) {
        return Err(InternalError::new_err(format!("{what} takes {n} arrays of one shape")));
    }
    Conditions::vbar(0.0, 0.0).and_then(|c| c.with_tol(tol)).map_err(to_py)?;
    Ok(arrays)
}

/// The elements of `N` arrays of one shape, a row of `N` at a time (C order).
fn rows<'a, 'b: 'a, const N: usize>(
    arrays: &'a [numpy::ndarray::ArrayViewD<'b, f64>],
) -> impl Iterator<Item = [f64; N]> + 'a {
    let mut iters: Vec<_> = arrays.iter().map(|a| a.iter()).collect();
    std::iter::from_fn(move || {
        let mut row = [0.0; N];
        for (r, it) in row.iter_mut().zip(iters.iter_mut()) {
            *r = *it.next()?;
        }
        Some(row)
    })
}

/// One element in the plane, as `fricosc point` poses it with
/// `--transverse-amp`: `x` is `[v, amp, T, phase, W, psi]`, the velocity as
/// `vhat` (else `vbar`), with a tangential drive where `tangential`.
fn in_plane(x: &[f64; 6], vhat: bool, tangential: bool, tol: f64) -> fricosc::Result<Conditions> {
    let [v, a, t, p, w, psi] = *x;
    let c = if vhat { Conditions::vhat(v, a)? } else { Conditions::vbar(v, a)? };
    let c = if tangential { c.with_tangential(t, p)? } else { c };
    Ok(c.with_tol(tol)?.with_transverse(fricosc::plane::Transverse::new(w, psi)?))
}

/// `mu_ratio` (or the reduction) under an oscillation across the sliding
/// direction ([`fricosc::plane`]) at every element of the broadcast arrays
/// (`x` as [`in_plane`] reads them); checked first, as [`evaluate`], what
/// the plane refuses before any work included.
#[pyfunction]
#[pyo3(signature = (shape, x, vhat, tangential, tol, reduction))]
pub(crate) fn evaluate_plane<'py>(
    py: Python<'py>,
    shape: &CoreShape,
    x: Vec<PyReadonlyArrayDyn<'py, f64>>,
    vhat: bool,
    tangential: bool,
    tol: f64,
    reduction: bool,
) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
    let arrays = views(&x, 6, "evaluate_plane", tol)?;
    let out = zeros(py, arrays[0].shape())?;
    let shape = &shape.inner;
    for (i, row) in rows::<6>(&arrays).enumerate() {
        in_plane(&row, vhat, tangential, tol)
            .and_then(|c| fricosc::plane::check(shape, &c))
            .map_err(|e| at_index(e, i))?;
        check_signals_at(py, i)?;
    }
    let mut each = rows::<6>(&arrays);
    chunked(py, out, &mut each, false, &|row: &[f64; 6]| {
        let r = shape.evaluate(&in_plane(row, vhat, tangential, tol)?)?.ratio;
        Ok(if reduction { r.reduction } else { r.mu_ratio })
    })
}

/// Evaluate `one` at every element of `inputs` (read a chunk at a time) into
/// `out` (of their shape, C order): chunks timed to about
/// [`CHUNK_SECONDS`], in parallel from [`PARALLEL_SECONDS`] of work, each
/// run with the GIL released by [`interruptible`] (Ctrl-C within its poll,
/// a system's solve stopped at its next period). With `nan`, an element's
/// refusal (not an internal error) is NaN.
fn chunked<'py, const N: usize>(
    py: Python<'py>,
    out: Bound<'py, PyArrayDyn<f64>>,
    inputs: &mut dyn Iterator<Item = [f64; N]>,
    nan: bool,
    one: &(dyn Fn(&[f64; N]) -> fricosc::Result<f64> + Sync),
) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
    let total: usize = out.shape().iter().product();
    let threads = rayon::current_num_threads().max(1) as f64;
    let (mut done, mut chunk, mut per_element) = (0, FIRST_CHUNK, 0.0);
    while done < total {
        let n = chunk.min(total - done);
        let t0 = std::time::Instant::now();
        let items: Vec<[f64; N]> = (&mut *inputs).take(n).collect();
        let parallel = n > 1 && per_element * n as f64 >= PARALLEL_SECONDS;
        let results = interruptible(py, || {
            use rayon::prelude::*;
            Ok(if parallel { items.par_iter().map(one).collect() } else { items.iter().map(one).collect::<Vec<_>>() })
        })?;
        {
            let mut rw = out.readwrite();
            let slice = rw.as_slice_mut().map_err(|e| InternalError::new_err(format!("the output array: {e}")))?;
            for (k, r) in results.into_iter().enumerate() {
                slice[done + k] = match r {
                    Err(e) if nan && !e.is_internal() => f64::NAN,
                    r => r.map_err(|e| at_index(e, done + k))?,
                };
            }
        }
        done += n;
        let took = t0.elapsed().as_secs_f64();
        per_element = took / n as f64 * if parallel { threads } else { 1.0 };
        // At least eight elements a thread: slow elements of unequal cost
        // (a system's points) keep every core busy, and a system's solve
        // answers Ctrl-C within a period whatever its chunk.
        let target = (CHUNK_SECONDS * threads / per_element.max(1e-9)).max(8.0 * threads);
        chunk = (target as usize).clamp(1, MAX_CHUNK);
    }
    Ok(out)
}

//! Tabulated contacts: an axisymmetric profile `f(r)` (`profile:FILE@U0`) or an
//! MDR equivalent profile `g(x)` (`gx:FILE@U0`), with `U0` the mean indentation
//! in the file's length unit.
//!
//! # Interpolation
//! The table is interpolated by monotone piecewise-cubic Hermite interpolation
//! (three-point slopes with Hyman's limiter): `C^1`, shape-preserving, exact for
//! quadratics, cubic on each interval. For `profile:`, `g` is computed at the table's radii by the MDR
//! transform `g(x) = x int_0^x f'(r)/sqrt(x^2 - r^2) dr = x int_0^(pi/2) f'(x sin t) dt`
//! of the interpolated `f` (in closed form per interval, summed over the
//! intervals hierarchically in `O(n log n)`: `transform::mdr_transform_knots`), and
//! interpolated again. The error interpolation adds is estimated by
//! integrating a second time on the table with every other point removed:
//! PCHIP converges like `h^3`, so the differences overestimate the error of the
//! full table. Each of the sums `mu` is the quotient of differs separately, and
//! the differences are propagated through the quotient in absolute value
//! (the difference of the two `mu` can vanish by accident:
//! `ratio::sums_difference`); it is reported as `interpolation_error`.
//!
//! # Quadrature
//! With `z = x/x_c` (`g(x_c) = U0`) and `G = g/U0`, the springs are integrated
//! over `z` between breakpoints: the table's knots and the band edges
//! `s = (1 - G(z))/amp = 1, +-sqrt(1 - vbar^2), -1`. On each interval the
//! substitution `z = p + (q - p)(1 - cos t)/2` absorbs the square-root
//! behaviour at `s = +-1`, and Gauss-Legendre at 16 and 32 points gives the
//! value and its error estimate. `mu` is the quotient of the mean tangential
//! force and the mean normal force where it is the small one, else `1 - ` that
//! of the deficit (`ratio::from_sums`).

use crate::error::{Error, Result};
use crate::integrate;
mod transform;

use crate::ratio::Ratio;
use transform::{mdr_transform_knots, normal_force, Pchip};

/// Most rows of a tabulated profile: the MDR transform is `O(n log n)`
/// (`transform::mdr_transform_knots`); 1,000,000 rows take about 30 s on two cores.
pub const MAX_TABLE_ROWS: usize = 1_000_000;

/// Parse the text of a two-column table (`r,f` or `x,g`): comma, semicolon or
/// blank separated, at most one header line (before the first row), `#`
/// comments; `path` names it in messages. Checks: at most [`MAX_TABLE_ROWS`]
/// (it stops reading past them), at least 3 rows, finite values, the first
/// column strictly increasing from 0, the second nondecreasing (it is shifted so
/// that its first value is 0). The core reads no files: the caller does (the
/// command line with a size cap).
pub(crate) fn parse_table(text: &str, path: &str) -> Result<(Vec<f64>, Vec<f64>)> {
    let bad = |reason: String| Error::Parse { context: path.into(), reason };
    let (mut xs, mut ys, mut lines) = (vec![], vec![], vec![]);
    let mut header_seen = false;
    for (ln, line) in text.lines().enumerate() {
        let line = line.split('#').next().unwrap_or("").trim();
        if line.is_empty() {
            continue;
        }
        let f: Vec<&str> =
            line.split(|c: char| c == ',' || c == ';' || c.is_whitespace()).filter(|s| !s.is_empty()).collect();
        let nums: Vec<Option<f64>> = f.iter().map(|s| s.parse::<f64>().ok()).collect();
        if xs.is_empty() && !header_seen && nums.iter().any(|v| v.is_none()) {
            header_seen = true;
            continue; // the one header line
        }
        if f.len() != 2 || nums.iter().any(|v| v.is_none()) {
            return Err(bad(format!("line {}: expected two numbers", ln + 1)));
        }
        xs.push(nums[0].unwrap_or(f64::NAN));
        ys.push(nums[1].unwrap_or(f64::NAN));
        lines.push(ln + 1);
        if xs.len() > MAX_TABLE_ROWS {
            break; // check_columns names the limit
        }
    }
    check_columns(xs, ys, path, &|i| format!("line {}", lines[i]))
}

/// The checks every table passes, from a file or from arrays: at most
/// [`MAX_TABLE_ROWS`] and at least 3 rows, finite values, the first column
/// strictly increasing from 0, the second nondecreasing (returned shifted so that
/// it starts at 0); `label(i)` names row `i` in messages.
pub(crate) fn check_columns(
    xs: Vec<f64>,
    ys: Vec<f64>,
    source: &str,
    label: &dyn Fn(usize) -> String,
) -> Result<(Vec<f64>, Vec<f64>)> {
    let bad = |reason: String| Error::Parse { context: source.into(), reason };
    if xs.len() != ys.len() {
        return Err(bad(format!("the columns differ in length ({} and {})", xs.len(), ys.len())));
    }
    if xs.len() > MAX_TABLE_ROWS {
        return Err(Error::TooLarge {
            what: format!("rows of {source}"),
            count: xs.len() as u128,
            limit: MAX_TABLE_ROWS as u128,
        });
    }
    for i in 0..xs.len() {
        if !xs[i].is_finite() || !ys[i].is_finite() {
            return Err(bad(format!("{}: values must be finite", label(i))));
        }
        if i > 0 && xs[i] <= xs[i - 1] {
            return Err(bad(format!("{}: the first column must increase strictly", label(i))));
        }
        if i > 0 && ys[i] < ys[i - 1] {
            return Err(bad(format!("{}: the profile must not decrease (monotone profiles only)", label(i))));
        }
    }
    if xs.len() < 3 {
        return Err(bad(format!("needs at least 3 rows, found {}", xs.len())));
    }
    if xs[0] != 0.0 {
        return Err(bad("the first column must start at 0 (the axis)".into()));
    }
    let y0 = ys[0];
    Ok((xs, ys.iter().map(|y| y - y0).collect()))
}

/// A table read once, with its MDR transform done: `g` at the table's radii, in
/// units scaled by the table's extent (`x / x_max`, `g / g_max`) so that tables
/// at any scale of f64 interpolate the same way. The transform does not depend
/// on the mean indentation: a scene's load control reuses it ([`Table::at`]).
#[derive(Debug, Clone, PartialEq)]
pub struct Table {
    path: String,
    /// `g/g_max` on `x/x_max` (full table).
    g: Pchip,
    /// The same from every other row (for the interpolation error), if >= 5 rows.
    coarse: Option<Pchip>,
    /// The table's extent: `x_max` and `g_max` in its length unit.
    scale: (f64, f64),
}

impl Table {
    /// Parse and transform a table's text (`parse_table`; `path` names it in
    /// messages): `profile` (true: `f(r)`, MDR-transformed) or `g(x)`.
    ///
    /// # Errors
    /// [`Error::Parse`] naming the line for malformed text, too few rows or values
    /// out of order; [`Error::TooLarge`] beyond [`MAX_TABLE_ROWS`].
    pub fn parse(text: &str, path: &str, profile: bool) -> Result<Table> {
        let (x, v) = parse_table(text, path)?;
        Self::from_checked(x, v, profile, path)
    }

    /// From arrays (no file): `r, f` of an axisymmetric profile (`profile`) or
    /// `x, g` of an equivalent profile, checked as a file's columns are; `name`
    /// appears in messages.
    ///
    /// ```
    /// use fricosc::contact::Table;
    /// // A paraboloid f = r^2/2 (R = 1) at mean indentation 1e-4: Hertz.
    /// let r: Vec<f64> = (0..=200).map(|i| i as f64 * 0.005).collect();
    /// let f: Vec<f64> = r.iter().map(|r| r * r / 2.0).collect();
    /// let t = Table::from_columns(r, f, true, "paraboloid").unwrap().at(1e-4).unwrap();
    /// assert!((t.contact_radius - 1e-2).abs() < 1e-12); // g = x^2/R: x_c = sqrt(R u0)
    /// ```
    ///
    /// # Errors
    /// As [`Table::parse`], naming the row.
    pub fn from_columns(x: Vec<f64>, v: Vec<f64>, profile: bool, name: &str) -> Result<Table> {
        let (x, v) = check_columns(x, v, name, &|i| format!("row {i}"))?;
        Self::from_checked(x, v, profile, name)
    }

    fn from_checked(x: Vec<f64>, v: Vec<f64>, profile: bool, path: &str) -> Result<Table> {
        let bad = |reason: String| Error::Parse { context: path.into(), reason };
        let (xmax, vmax) = (x[x.len() - 1], v[v.len() - 1]);
        if vmax <= 0.0 {
            return Err(bad("the profile is flat (its last value equals its first)".into()));
        }
        let xs: Vec<f64> = x.iter().map(|&xi| xi / xmax).collect();
        let vs: Vec<f64> = v.iter().map(|&vi| vi / vmax).collect();
        // Slopes of the scaled table must be ordinary numbers (a near-vertical
        // step such as 0 -> 1 over 1e-300 cannot be interpolated in f64): both
        // columns scaled lie in [0, 1], so rows 1e-12 apart keep them below 1e12.
        for i in 1..xs.len() {
            if xs[i] - xs[i - 1] < 1e-12 {
                return Err(bad(format!(
                    "rows {} and {} are too close ({:?} apart in x, relative {:.1e} of the table's extent) to interpolate",
                    i - 1,
                    i,
                    x[i] - x[i - 1],
                    xs[i] - xs[i - 1]
                )));
            }
        }
        let build = |xs: Vec<f64>, vs: Vec<f64>| -> Result<Pchip> {
            if !profile {
                return Ok(Pchip::new(xs, vs));
            }
            let f = Pchip::new(xs.clone(), vs);
            let gv = mdr_transform_knots(&f);
            // A profile with a steep step has a transform that falls again
            // (g ~ x / sqrt(x^2 - r0^2) after a step at r0): not a simple contact.
            if let Some(i) = (1..gv.len()).find(|&i| gv[i] < gv[i - 1]) {
                let (imax, gmax) =
                    gv.iter().enumerate().fold((0, f64::MIN), |b, (k, &g)| if g > b.1 { (k, g) } else { b });
                return Err(bad(format!(
                    "the MDR transform g(x) of this profile decreases after x = {:?} (largest g = {:?} at x = {:?}): \
                     fricosc handles profiles whose equivalent profile increases",
                    xs[i - 1] * xmax,
                    gmax * vmax,
                    xs[imax] * xmax
                )));
            }
            Ok(Pchip::new(xs, gv))
        };
        let coarse = if xs.len() >= 5 {
            build(xs.iter().step_by(2).copied().collect(), vs.iter().step_by(2).copied().collect()).ok()
        } else {
            None
        };
        let g = build(xs, vs)?;
        let gmax = *g.values().last().unwrap_or(&0.0);
        Ok(Table { path: path.into(), g, coarse, scale: (xmax, gmax * vmax) })
    }

    /// The largest `g` of the (transformed) table, in its length unit.
    #[must_use]
    pub fn max_g(&self) -> f64 {
        self.scale.1
    }

    /// The contact at mean indentation `u0` (the table's length unit).
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] for `u0` not finite and `> 0`; [`Error::Parse`]
    /// when the table does not reach `u0` or does not resolve the contact.
    pub fn at(&self, u0: f64) -> Result<Tabulated> {
        if !(u0.is_finite() && u0 > 0.0) {
            return Err(Error::param("U0", u0, "the mean indentation must be finite and > 0"));
        }
        let (xmax, gmax) = self.scale;
        // In the table's scaled units g/g_max of the transformed values.
        let g_top = *self.g.values().last().unwrap_or(&1.0);
        let u = u0 / gmax * g_top;
        if !(u.is_normal() && u <= g_top) {
            return Err(Error::Parse {
                context: self.path.clone(),
                reason: format!(
                    "the table reaches only g = {gmax:?} < U0 = {u0:?}: the contact is wider than the table"
                ),
            });
        }
        let normalise = |g: &Pchip| -> (Pchip, f64) {
            let xc = g.inverse(u);
            let z: Vec<f64> = g.knots().iter().map(|&xi| xi / xc).collect();
            let gz: Vec<f64> = g.values().iter().map(|&gi| gi / u).collect();
            (Pchip::new(z, gz), xc)
        };
        let (g, xc) = normalise(&self.g);
        // The contact at the mean indentation must span more than the table's
        // first interval: inside it the shape is only the interpolating cubic.
        let first = self.g.knots()[1];
        if xc <= first {
            return Err(Error::Parse {
                context: self.path.clone(),
                reason: format!(
                    "the contact radius at U0 = {u0:?} is {:?}, inside the table's first interval [0, {:?}]: the table \
                     does not resolve the contact (add rows near the axis)",
                    xc * xmax,
                    first * xmax
                ),
            });
        }
        let coarse = self.coarse.as_ref().filter(|c| *c.values().last().unwrap_or(&0.0) >= u).map(|c| normalise(c).0);
        Ok(Tabulated { g, coarse, contact_radius: xc * xmax, name: format!("{}@{u0:?}", self.path) })
    }
}

/// The contact of a `profile:FILE@U0` (`profile`) or `gx:FILE@U0` shape; `rest`
/// is `FILE@U0`, `spec` the whole name (which the contact keeps).
pub(crate) fn parse_shape(
    rest: &str,
    spec: &str,
    profile: bool,
    read: crate::shape::Reader,
) -> Result<std::sync::Arc<dyn crate::contact::Contact>> {
    let bad = |reason: &str| Error::InvalidShape { spec: spec.into(), reason: reason.into() };
    let (path, u0) =
        rest.rsplit_once('@').ok_or_else(|| bad("needs the mean indentation: profile:FILE@U0 or gx:FILE@U0"))?;
    let u0: f64 = u0.trim().parse().map_err(|_| bad("the mean indentation after '@' is not a number"))?;
    let text = read(path).map_err(|e| Error::File { path: path.into(), source: Box::new(e) })?;
    let t = Table::parse(&text, path, profile)?.at(u0)?.named(spec);
    Ok(std::sync::Arc::new(t))
}

/// A tabulated contact, normalised: `G(z) = g(x_c z)/U0` with `G(1) = 1`.
#[derive(Debug, Clone, PartialEq)]
pub struct Tabulated {
    /// `G` on the normalised knots.
    g: Pchip,
    /// The same from every other knot (for the interpolation error).
    coarse: Option<Pchip>,
    /// Contact radius at the mean indentation, in the table's length unit.
    pub contact_radius: f64,
    /// The name outputs give the shape.
    name: String,
}

impl Tabulated {
    /// This contact named `name` (as outputs print it).
    #[must_use]
    pub fn named(self, name: &str) -> Tabulated {
        Tabulated { name: name.into(), ..self }
    }

    /// The name outputs give the shape.
    #[must_use]
    pub fn name(&self) -> &str {
        &self.name
    }
}

/// `mu_macro/mu0` of a tabulated contact and its error estimates.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct TabulatedResult {
    /// Ratio and reduction.
    pub ratio: Ratio,
    /// Quadrature error estimate of `mu_ratio`.
    pub error_estimate: f64,
    /// Interpolation error estimate of `mu_ratio` (0 if the table is too short to tell).
    pub interpolation_error: f64,
}

/// Evaluate a tabulated contact at `(vbar, amp)`; both must be finite and `>= 0`
/// (an error otherwise). The interpolation error is the difference the coarse
/// table makes to the sums, propagated through the quotient
/// (`ratio::sums_difference`).
pub(crate) fn evaluate(t: &Tabulated, vbar: f64, amp: f64, tol: f64) -> Result<TabulatedResult> {
    crate::error::check_nonneg("vbar", vbar)?;
    crate::error::check_nonneg("amp", amp)?;
    if amp == 0.0 || vbar >= 1.0 {
        let ratio = Ratio { mu_ratio: 1.0, reduction: 0.0 };
        return Ok(TabulatedResult { ratio, error_estimate: 0.0, interpolation_error: 0.0 });
    }
    let at = crate::contact::VelocityScale::of(vbar, amp);
    if at.vbar != vbar {
        let r = evaluate(t, at.vbar, amp, tol)?;
        let (ratio, error_estimate) = at.back(r.ratio, r.error_estimate);
        let interpolation_error = at.back(r.ratio, r.interpolation_error).1;
        return Ok(TabulatedResult { ratio, error_estimate, interpolation_error });
    }
    let fine = integrate(&t.g, vbar, amp, tol)?;
    let interpolation_error = match &t.coarse {
        Some(c) => integrate(c, vbar, amp, tol)
            .map_or(0.0, |coarse| fine.scale * crate::ratio::sums_difference(fine.sums, coarse.sums)),
        None => 0.0,
    };
    Ok(TabulatedResult { ratio: fine.ratio, error_estimate: fine.estimate, interpolation_error })
}

/// Mean normal force of the whole contact at amplitude `amp`, units
/// `E* x_c U0` (both sides of the MDR foundation), by the same quadrature.
pub(crate) fn mean_normal(t: &Tabulated, amp: f64) -> Result<f64> {
    crate::error::check_nonneg("amp", amp)?;
    // Both sides, in units of E* x_c U0: the sums are in kz u0 up to amp = 1,
    // in kz du beyond (integrate::mdr::unit).
    let sums = integrate(&t.g, 0.5, amp, crate::DEFAULT_TOL)?.sums;
    Ok(2.0 * sums[0] * if amp > 1.0 { amp } else { 1.0 })
}

/// `G(z)` of a tabulated contact (the cubic interpolant; the end cubics
/// extrapolate beyond the table).
/// The knots of `G` (in `z`).
pub(crate) fn knots(t: &Tabulated) -> Vec<f64> {
    t.g.knots().to_vec()
}

pub(crate) fn equivalent_profile(t: &Tabulated, z: f64) -> f64 {
    t.g.eval(z).0
}

/// The largest amplitude the table reaches ([`reach`] accepts it): its
/// deepest level less 1, or just below where that difference rounds up.
pub(crate) fn max_amp(t: &Tabulated) -> f64 {
    let gmax = *t.g.values().last().unwrap_or(&0.0);
    let mut amp = gmax - 1.0;
    while 1.0 + amp > gmax {
        amp = amp.next_down();
    }
    amp
}

/// `z` with `G(z) = level`.
pub(crate) fn level(t: &Tabulated, level: f64) -> f64 {
    t.g.inverse(level)
}

/// `z` with `G(z) = 1 + amp`: an error if the table ends before.
pub(crate) fn reach(t: &Tabulated, amp: f64) -> Result<f64> {
    crate::error::check_nonneg("amp", amp)?;
    let gmax = *t.g.values().last().unwrap_or(&0.0);
    if gmax < 1.0 + amp {
        return Err(Error::param(
            "amp",
            amp,
            &format!("the tabulated profile ends at g = {gmax:?} U0, before the contact edge at (1 + amp) U0"),
        ));
    }
    Ok(t.g.inverse(1.0 + amp))
}

/// Static normal force at indentation `depth U0`, units `E* x_c U0` (both sides).
pub(crate) fn static_force(t: &Tabulated, depth: f64) -> f64 {
    if depth > 0.0 {
        normal_force(&t.g, depth)
    } else {
        0.0
    }
}

/// One quadrature of a table: the ratio, its error estimate, the sums `[nn,
/// dd, tt]` of [`crate::ratio::from_sums`] (at [`crate::contact::AMP_LINEAR`]
/// for an `amp` below it; in the units of [`integrate::mdr::unit`]) and the
/// factor `scale` by which that ratio's reduction was scaled (1 otherwise).
struct Quadrature {
    ratio: Ratio,
    estimate: f64,
    sums: [f64; 3],
    scale: f64,
}

/// A table's profile along `z` itself.
impl integrate::mdr::Profile for Pchip {
    fn at(&self, z: f64) -> (f64, f64) {
        (self.eval(z).0, 1.0)
    }
    fn level(&self, level: f64) -> f64 {
        self.inverse(level)
    }
    /// The knots: the interpolant is a cubic between them.
    fn breakpoints(&self) -> Vec<f64> {
        self.knots().to_vec()
    }
}

/// The quadrature of the springs of `g` at `(vbar, amp)` ([`integrate::mdr`]);
/// at `amp = 0` only the sums' normal force is meaningful (one side's static
/// force).
fn integrate(g: &Pchip, vbar: f64, amp: f64, tol: f64) -> Result<Quadrature> {
    if amp > 0.0 && amp < crate::contact::AMP_LINEAR {
        let at = integrate(g, vbar, crate::contact::AMP_LINEAR, tol)?;
        let k = amp / crate::contact::AMP_LINEAR;
        return Ok(Quadrature { ratio: at.ratio.scaled(k), estimate: at.estimate * k, scale: k, ..at });
    }
    if amp == 0.0 {
        // No oscillation: one side's static force, int (1 - G(z))_+ dz.
        let nn = 0.5 * normal_force(g, 1.0);
        let ratio = Ratio { mu_ratio: 1.0, reduction: 0.0 };
        return Ok(Quadrature { ratio, estimate: 0.0, sums: [nn, 0.0, nn], scale: 1.0 });
    }
    let gmax = *g.values().last().unwrap_or(&0.0);
    if gmax < 1.0 + amp {
        return Err(Error::param(
            "amp",
            amp,
            &format!("the tabulated profile ends at g = {:?} U0, before the contact edge at (1 + amp) U0", gmax),
        ));
    }
    let r = integrate::mdr::springs(g, vbar, amp, tol, "tabulated contact")?;
    Ok(Quadrature { ratio: r.ratio, estimate: r.estimate, sums: r.sums, scale: 1.0 })
}

#[cfg(test)]
mod tests;

//! Another code's table as its columns name it: the velocity as `vbar` or
//! `vhat` (eq. 15, `vbar = vhat / amp`), `amp`, the friction as `mu_ratio` or
//! `mu` (then `mu_ratio = mu / mu0`), optionally `shape` (one for the whole
//! table) and, under oscillation in the sliding direction, `tangential_amp`
//! and `phase` (0 where missing); across it, `transverse_amp`,
//! `transverse_phase` (0 where missing) and, if the table gives the mean
//! force across, `transverse_ratio`. The command line's reader and Python's
//! DataFrames both end here, so a table means the same in both.

use crate::error::{Error, Result};

/// A table to validate, read from named columns ([`Table::from_columns`]).
#[derive(Debug, Clone, PartialEq)]
pub struct Table {
    shape: Option<String>,
    vhat: bool,
    mu: bool,
    velocity: Vec<f64>,
    amp: Vec<f64>,
    friction: Vec<f64>,
    tangential: Option<Vec<(f64, f64)>>,
    transverse: Option<Vec<(f64, f64)>>,
    transverse_ratio: Option<Vec<f64>>,
    ignored_columns: Vec<String>,
    format: String,
}

/// The values of one column of a table.
#[derive(Debug, Clone, PartialEq)]
pub enum Column {
    /// A numeric column, one value per row.
    Numbers(Vec<f64>),
    /// The distinct values of a text column (the `shape`).
    Labels(Vec<String>),
}

impl Table {
    /// The columns a table may have; `shape` is text, the others numbers.
    pub const COLUMNS: [&'static str; 11] = [
        "vbar",
        "vhat",
        "amp",
        "mu_ratio",
        "mu",
        "shape",
        "tangential_amp",
        "phase",
        "transverse_amp",
        "transverse_phase",
        "transverse_ratio",
    ];

    /// A table from the columns its source has: `names` every column's name
    /// (those not in [`Table::COLUMNS`] are reported as not read), `columns`
    /// the values of those in it, `format` how the source was read (`CSV (','
    /// delimited)`, `pandas 'columns' JSON`, ...); `source` names it in errors.
    ///
    /// # Errors
    /// [`Error::Parse`] where a column is missing or given twice over
    /// (`vbar` and `vhat`), names more than one shape, `phase` comes without
    /// `tangential_amp` (`transverse_phase` or `transverse_ratio` without
    /// `transverse_amp`), or either amplitude with `vbar`; columns of
    /// different lengths.
    pub fn from_columns(names: &[String], columns: Vec<(&str, Column)>, format: &str, source: &str) -> Result<Table> {
        let err = |reason: String| Error::Parse { context: source.into(), reason };
        let mut numbers: Vec<Option<Vec<f64>>> = vec![None; Table::COLUMNS.len()];
        let mut shapes = vec![];
        for (name, column) in columns {
            let k = Table::COLUMNS.iter().position(|c| *c == name);
            match (k, column) {
                (Some(5), Column::Labels(l)) => shapes = l,
                (Some(k), Column::Numbers(v)) if k != 5 => numbers[k] = Some(v),
                _ => return Err(err(format!("the column '{name}' is not read as given"))),
            }
        }
        let listed = || if names.is_empty() { "no names".to_string() } else { names.join(", ") };
        let one_of = |a: usize, b: usize, what: &str| match (numbers[a].is_some(), numbers[b].is_some()) {
            (true, false) => Ok(false),
            (false, true) => Ok(true),
            (true, true) => Err(err(format!(
                "both '{}' and '{}' given: one {what} column only",
                Table::COLUMNS[a],
                Table::COLUMNS[b]
            ))),
            (false, false) => Err(err(format!(
                "no column '{}' (or '{}'): a table needs vbar (or vhat), amp and mu_ratio (or mu); this one ({format}) \
                 has {}",
                Table::COLUMNS[a],
                Table::COLUMNS[b],
                listed()
            ))),
        };
        let vhat = one_of(0, 1, "velocity")?;
        let mu = one_of(3, 4, "friction")?;
        let amp =
            numbers[2].take().ok_or_else(|| err(format!("no column 'amp'; this table ({format}) has {}", listed())))?;
        let velocity = numbers[usize::from(vhat)].take().unwrap_or_default();
        let friction = numbers[3 + usize::from(mu)].take().unwrap_or_default();
        if shapes.len() > 1 {
            let named: Vec<String> = shapes.iter().map(|s| format!("'{s}'")).collect();
            return Err(err(format!(
                "the table names more than one shape ({}): validate one shape at a time",
                named.join(", ")
            )));
        }
        let tangential =
            pairs_of(numbers[6].take(), numbers[7].take(), vhat, ["tangential_amp", "phase"]).map_err(&err)?;
        let transverse = pairs_of(numbers[8].take(), numbers[9].take(), vhat, ["transverse_amp", "transverse_phase"])
            .map_err(&err)?;
        let transverse_ratio = numbers[10].take();
        if transverse_ratio.is_some() && transverse.is_none() {
            return Err(err("a column 'transverse_ratio' without 'transverse_amp'".into()));
        }
        let rows = amp.len();
        let long = |c: Option<usize>| c.is_some_and(|n| n != rows);
        if velocity.len() != rows
            || friction.len() != rows
            || long(tangential.as_ref().map(Vec::len))
            || long(transverse.as_ref().map(Vec::len))
            || long(transverse_ratio.as_ref().map(Vec::len))
        {
            return Err(err("the columns differ in length".into()));
        }
        let read = [if vhat { "vhat" } else { "vbar" }, "amp", if mu { "mu" } else { "mu_ratio" }, "shape"];
        let read_also = &Table::COLUMNS[6..];
        let ignored_columns =
            names.iter().filter(|h| !read.contains(&h.as_str()) && !read_also.contains(&h.as_str())).cloned().collect();
        Ok(Table {
            shape: shapes.pop(),
            vhat,
            mu,
            velocity,
            amp,
            friction,
            tangential,
            transverse,
            transverse_ratio,
            ignored_columns,
            format: format.into(),
        })
    }

    /// The shape the table names, if any.
    #[must_use]
    pub fn shape(&self) -> Option<&str> {
        self.shape.as_deref()
    }

    /// How the source was read.
    #[must_use]
    pub fn format(&self) -> &str {
        &self.format
    }

    /// The columns not read.
    #[must_use]
    pub fn ignored_columns(&self) -> &[String] {
        &self.ignored_columns
    }

    /// Whether the table is under oscillation in the sliding direction or
    /// across it (it has `tangential_amp` or `transverse_amp`).
    #[must_use]
    pub fn is_oscillation(&self) -> bool {
        self.tangential.is_some() || self.transverse.is_some()
    }

    /// Row `i`'s velocity as the table gives it: `("vhat", value)` or
    /// `("vbar", value)` (`None` past the last row).
    pub(crate) fn velocity_of(&self, i: usize) -> Option<(&'static str, f64)> {
        Some((if self.vhat { "vhat" } else { "vbar" }, *self.velocity.get(i)?))
    }

    /// `(vbar, amp, mu_ratio)` of every row (a bad row is named by its index),
    /// the input of [`super::compare`]; `source` names the table in errors.
    ///
    /// # Errors
    /// [`Error::Parse`] for a table under oscillation in the sliding direction,
    /// `mu` without `mu0` (or `mu0` with `mu_ratio`), a bad row.
    pub fn rows(&self, mu0: Option<f64>, source: &str) -> Result<Vec<(f64, f64, f64)>> {
        if self.is_oscillation() {
            return Err(Error::Parse {
                context: source.into(),
                reason: "a table under oscillation in or across the sliding direction (column 'tangential_amp' or \
                         'transverse_amp'): only a single table's validate compares it"
                    .into(),
            });
        }
        rows_from_columns(&self.velocity, &self.amp, &self.friction, self.vhat, self.mu, mu0)
            .map_err(|e| Error::Parse { context: source.into(), reason: e.to_string() })
    }

    /// Every row of a table under oscillation in or across the sliding
    /// direction, the input of [`super::compare_oscillation`].
    ///
    /// # Errors
    /// [`Error::Parse`] without `tangential_amp` or `transverse_amp`, or for
    /// `mu` without `mu0` (or `mu0` with `mu_ratio`).
    pub fn oscillation_rows(&self, mu0: Option<f64>, source: &str) -> Result<Vec<super::OscillationInput>> {
        let bad = |reason: &str| Error::Parse { context: source.into(), reason: reason.into() };
        if !self.is_oscillation() {
            return Err(bad("no column 'tangential_amp' or 'transverse_amp'"));
        }
        let scale = match (self.mu, mu0) {
            (true, Some(m)) if m.is_finite() && m > 0.0 => m,
            (true, Some(m)) => return Err(Error::param("mu0", m, "must be finite and > 0")),
            (true, None) => return Err(bad("the column 'mu' needs --mu0 (mu_ratio = mu / mu0)")),
            (false, Some(_)) => return Err(bad("--mu0 applies to a column 'mu'; this table has 'mu_ratio'")),
            (false, None) => 1.0,
        };
        let pair = |p: &Option<Vec<(f64, f64)>>, i: usize| p.as_ref().map_or((0.0, 0.0), |p| p[i]);
        let rows = (0..self.amp.len()).map(|i| {
            let ((t, p), (w, q)) = (pair(&self.tangential, i), pair(&self.transverse, i));
            // The force across is a ratio to mu0 like the one along.
            let across = self.transverse_ratio.as_ref().map(|r| r[i] / scale);
            super::OscillationInput::new(self.velocity[i], self.amp[i], self.friction[i] / scale)
                .with_tangential(t, p)
                .with_transverse(w, q, across)
        });
        Ok(rows.collect())
    }
}

/// `(amplitude, phase)` of every row, where the table has the amplitude
/// column (a missing phase is 0); it needs the velocities as `vhat`.
/// `names`: the two columns' names.
fn pairs_of(
    amp: Option<Vec<f64>>,
    phase: Option<Vec<f64>>,
    vhat: bool,
    names: [&str; 2],
) -> std::result::Result<Option<Vec<(f64, f64)>>, String> {
    let [a, p] = names;
    match (amp, phase) {
        (None, Some(_)) => Err(format!("a column '{p}' without '{a}'")),
        (None, None) => Ok(None),
        (Some(_), _) if !vhat => Err(format!(
            "a table with '{a}' needs its velocities as 'vhat' (vbar = vhat/amp is undefined without normal \
             oscillation)"
        )),
        (Some(t), Some(q)) if q.len() != t.len() => Err("the columns differ in length".into()),
        (Some(t), q) => Ok(Some(t.iter().enumerate().map(|(i, &t)| (t, q.as_ref().map_or(0.0, |q| q[i]))).collect())),
    }
}

/// `(vbar, amp, mu_ratio)` rows from a table's columns: `velocity` is `vbar`,
/// or `vhat` (eq. 15) if `vhat` (then `vbar = vhat / amp`); `friction` is
/// `mu_ratio`, or `mu` if `mu` (then `mu_ratio = mu / mu0`, and `mu0` is
/// required; refused otherwise, where the values are already ratios).
///
/// # Errors
/// [`Error::Parse`] naming the row for a bad value, columns of different lengths,
/// or `mu` without `mu0`.
fn rows_from_columns(
    velocity: &[f64],
    amp: &[f64],
    friction: &[f64],
    vhat: bool,
    mu: bool,
    mu0: Option<f64>,
) -> Result<Vec<(f64, f64, f64)>> {
    let bad = |reason: &str| Error::Parse { context: "mu0".into(), reason: reason.into() };
    if velocity.len() != amp.len() || amp.len() != friction.len() {
        return Err(Error::Parse { context: "columns".into(), reason: "they differ in length".into() });
    }
    let mu0 = match (mu, mu0) {
        (true, Some(m)) if m.is_finite() && m > 0.0 => m,
        (true, Some(m)) => return Err(Error::param("mu0", m, "must be finite and > 0")),
        (true, None) => return Err(bad("the table gives 'mu': mu0 is needed (mu_ratio = mu / mu0)")),
        (false, Some(_)) => return Err(bad("given, but the table gives 'mu_ratio' (already divided by mu0)")),
        (false, None) => 1.0,
    };
    (0..amp.len())
        .map(|i| {
            let at = |e: Error| Error::Parse { context: format!("row {i}"), reason: e.to_string() };
            let a = crate::error::check_nonneg("amp", amp[i]).map_err(at)?;
            let v = if vhat {
                crate::Conditions::vhat(velocity[i], a).and_then(|c| c.as_vbar()).map_err(at)?
            } else {
                crate::error::check_nonneg("vbar", velocity[i]).map_err(at)?
            };
            Ok((v, a, friction[i] / mu0))
        })
        .collect()
}

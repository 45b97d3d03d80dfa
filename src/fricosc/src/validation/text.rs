//! The comparisons' reports for a person: short, in lines of at most 100
//! characters, every finding with its rows and what to check.

use super::{
    AtRest, Convergence, Finding, FindingKind, HistoryValidation, Needed, OscillationValidation, RowStatus, Summary,
    Table, Validation,
};
use crate::contact::regime::ContactRegime;
use std::fmt::Write as _;

impl FindingKind {
    /// The name reports print (as JSON writes it).
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            FindingKind::AboveOne => "above_one",
            FindingKind::Negative => "negative",
            FindingKind::NotOneAboveCritical => "not_one_above_critical",
            FindingKind::NotMonotone => "not_monotone",
            FindingKind::NotSteady => "not_steady",
            FindingKind::AtRestConvention => "at_rest_convention",
            FindingKind::StaticLimit => "static_limit",
            FindingKind::WorseThanPeer => "worse_than_peer",
            FindingKind::NotConverging => "not_converging",
            FindingKind::ResolutionIndependent => "resolution_independent",
            FindingKind::RichardsonUntrustworthy => "richardson_untrustworthy",
            FindingKind::NormalScale => "normal_scale",
            FindingKind::NormalShape => "normal_shape",
            FindingKind::NotPeriodic => "not_periodic",
            FindingKind::AboveBound => "above_bound",
            FindingKind::MissingEvent => "missing_event",
            FindingKind::BelowMinusOne => "below_minus_one",
            FindingKind::NegativeNormal => "negative_normal",
            FindingKind::ForceOutOfContact => "force_out_of_contact",
            FindingKind::ContactLoss => "contact_loss",
            FindingKind::LargeErrors => "large_errors",
            FindingKind::Convention => "convention",
            FindingKind::Diverged => "diverged",
            FindingKind::MaxError => "max_error",
        }
    }
}

impl RowStatus {
    /// The name reports print (as JSON writes it).
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            RowStatus::Exact => "exact",
            RowStatus::Converging => "converging",
            RowStatus::NotConverging => "not_converging",
            RowStatus::ResolutionIndependent => "resolution_independent",
        }
    }
}

impl ContactRegime {
    /// The regime's label in a report: its name, and for a curved contact the
    /// share of the load on springs that lose contact, from `share[0]` to
    /// `share[1]` ("mixed: 38 % jumping", or a range).
    #[must_use]
    pub fn label(self, share: [f64; 2]) -> String {
        let pct = |x: f64| format!("{:.0}", 100.0 * x);
        match self {
            ContactRegime::Mixed if pct(share[0]) == pct(share[1]) => format!("mixed: {} % jumping", pct(share[0])),
            ContactRegime::Mixed => format!("mixed: {}-{} % jumping", pct(share[0]), pct(share[1])),
            ContactRegime::Jumping => "jumping: 100 %".into(),
            r => r.name().into(),
        }
    }
}

impl Validation {
    /// Each row keyed as `table` keys it: its `vhat` where the table gives
    /// the velocity so (`Row::vhat`; `vbar` stays the one compared).
    pub fn key_by(&mut self, table: &super::Table) {
        for r in &mut self.rows {
            r.vhat = table.velocity_of(r.row).filter(|(name, _)| *name == "vhat").map(|(_, v)| v);
        }
    }

    /// The report for a person: `table` is the table compared, `shape_source`
    /// says where its shape came from ("named by the table", ...).
    #[must_use]
    pub fn summary(&self, table: &Table, shape_source: &str) -> String {
        let v = self;
        let e = |x: f64| format!("{x:.2e}");
        let w = &v.worst;
        let at_rest = match v.at_rest {
            AtRest::Sliding => "the sliding limit vbar -> 0+ (mu_static; --at-rest relaxed for a relaxed start)",
            AtRest::Relaxed => "a relaxed start (0; --at-rest sliding for the limit vbar -> 0+)",
        };
        let mut s = String::new();
        s += &wrap(
            "",
            &format!(
                "fricosc validate: {} of shape {} ({shape_source}), read as {}.",
                count(v.n, "row"),
                v.shape,
                table.format()
            ),
            100,
        );
        if let Some(sys) = &v.system {
            let estimate = v.rows.iter().filter_map(|r| r.exact_error_estimate).fold(0.0f64, f64::max);
            let means = v.rows.iter().filter(|r| r.vbar > 0.0 && r.period.is_none()).count();
            let means = if means > 0 {
                format!("; {} without period (long-time means)", count(means, "row"))
            } else {
                String::new()
            };
            s += &wrap(
                "",
                &format!(
                    "On a system {}: the exact values are its attractors, their largest error estimate {}{means}.",
                    system_params(sys),
                    e(estimate)
                ),
                100,
            );
        }
        if v.rows.iter().any(|r| r.vbar == 0.0) {
            s += &wrap("", &format!("Rows at vbar = 0 are compared with {at_rest}."), 100);
        }
        let largest = if v.max_abs_error.is_nan() {
            "No row has a finite value: every row diverged.".to_string()
        } else {
            // Keyed as the file keys it: by `vhat` where the table gives it.
            let (velocity, value) = table.velocity_of(w.row).unwrap_or(("vbar", w.vbar));
            format!(
                "Largest |error| {} at row {} ({velocity} {value}, amp {}: {} against the exact {}); rms {}.",
                e(v.max_abs_error),
                w.row,
                w.amp,
                w.mu_ratio,
                w.exact,
                e(v.rms_error)
            )
        };
        s += &wrap("", &largest, 100);
        if let Some(p) = &v.peer {
            s += &wrap(
                "",
                &format!(
                    "fricosc's stepping peer (the seed's scheme) at {} steps per period{}: largest |error| {}, rms {} \
                     (each row's in the JSON and CSV as peer_error).",
                    p.steps_per_period,
                    if p.springs > 1 { format!(" and {} springs", p.springs) } else { String::new() },
                    e(p.max_abs_error),
                    e(p.rms_error)
                ),
                100,
            );
        }
        if !table.ignored_columns().is_empty() {
            s += &wrap("", &format!("Columns not read: {}.", table.ignored_columns().join(", ")), 100);
        }
        if !v.by_amp.is_empty() {
            s += &summary_table("regime", v.by_regime.iter().map(|g| (g.regime.label(g.jumping_share), &g.summary)));
            s += &summary_table("amp", v.by_amp.iter().map(|g| (g.amp.to_string(), &g.summary)));
        }
        s += &findings_text(&format!("Findings (value checks to {:?})", v.tolerance), &v.findings, "none", "row");
        s
    }
}

/// The summary of an oscillation table's comparison.
impl OscillationValidation {
    /// The report for a person; `source` names the table.
    #[must_use]
    pub fn summary(&self, source: &str) -> String {
        let v = self;
        let s = &v.summary;
        let setting = match &v.system {
            Some(sys) => format!("on a system {}", system_params(sys)),
            None if v.rows.iter().any(|r| r.transverse.is_some()) => "under oscillation in the plane".into(),
            None => "under oscillation in the sliding direction".into(),
        };
        let mut out = format!(
            "{source}: {} rows of {} {setting}\n\
             largest error {:.3e} (row {}), rms {:.3e}, largest relative {:.3e}\n",
            s.n, v.shape, s.max_abs_error, s.worst_row, s.rms_error, s.max_rel_error
        );
        if let Some(t) = &v.transverse {
            let _ = writeln!(
                out,
                "the force across: largest error {:.3e} (row {}), rms {:.3e}",
                t.max_abs_error, t.worst_row, t.rms_error
            );
        }
        if let Some(e) = v.rows.iter().map(|r| r.exact_error_estimate).reduce(f64::max) {
            let _ = writeln!(out, "the exact values' largest error estimate {e:.3e}");
        }
        if let Some(p) = &v.peer {
            let _ = writeln!(
                out,
                "stepping peer ({} steps a period, {} springs): largest error {:.3e}, rms {:.3e}",
                p.steps_per_period, p.springs, p.max_abs_error, p.rms_error
            );
        }
        out.push_str("by regime:\n");
        for r in &v.by_regime {
            let _ = writeln!(
                out,
                "  {:>5} rows  largest {:.3e}  rms {:.3e}  {}",
                r.summary.n, r.summary.max_abs_error, r.summary.rms_error, r.regime
            );
        }
        if v.findings.is_empty() {
            out.push_str("findings: none\n");
        }
        for f in &v.findings {
            let _ = writeln!(out, "finding: {} ({} rows, first {:?}): {}", f.kind.name(), f.count, f.rows, f.hint);
        }
        out
    }
}

impl HistoryValidation {
    /// The report for a person; `format` says how the history was read.
    #[must_use]
    pub fn summary(&self, format: &str) -> String {
        let v = self;
        let e = |x: f64| format!("{x:.2e}");
        let mut s = wrap(
            "",
            &format!(
                "fricosc validate --history: {} at {}; {}, {} in the last (read as {format}).",
                v.shape,
                v.point,
                count(v.periods, "whole period"),
                count(v.samples, "sample")
            ),
            100,
        );
        s += &wrap("", &origin_text(v), 100);
        s += &wrap(
            "",
            &format!(
                "Tangential force over the last period: largest |error| {}, rms {} (units: {}).",
                e(v.max_abs_error),
                e(v.rms_error),
                v.units
            ),
            100,
        );
        if let Some(nc) = &v.normal {
            s += &wrap(
                "",
                &format!(
                    "Normal force: largest |error| {}, rms {}; its mean over the period is {:.6} times the exact mean.",
                    e(nc.max_abs_error),
                    e(nc.rms_error),
                    nc.mean_ratio
                ),
                100,
            );
        }
        if let Some(t) = &v.transverse {
            let line = format!(
                "Force across the sliding direction: largest |error| {}, rms {}.",
                e(t.max_abs_error),
                e(t.rms_error)
            );
            s += &wrap("", &line, 100);
        }
        if let Some(b) = &v.body {
            let line = format!(
                "The body (pre-slip lengths): its lag X_d - x errs by {} at most (range {}), its velocity by {} (range {}).",
                e(b.lag_max_abs_error),
                e(b.lag_range),
                e(b.velocity_max_abs_error),
                e(b.velocity_range)
            );
            s += &wrap("", &line, 100);
        }
        s += &wrap(
            "",
            &match (v.period_drift, v.periodic) {
                (Some(d), Some(true)) => {
                    format!("Periodic: the last period differs from the one before by {} at most.", e(d))
                }
                (Some(d), _) => {
                    format!("Not yet periodic: the last period differs from the one before by up to {}.", e(d))
                }
                _ => "One period only: periodicity cannot be judged (give two or more).".into(),
            },
            100,
        );
        if !v.exact_events.is_empty() || !v.events.is_empty() {
            s += &format!("\n{:<18}{:>12}{:>12}{:>14}\n", "event", "tau", "exact tau", "timing error");
            for f in &v.events {
                let o = |x: Option<f64>| x.map_or("-".into(), |y| format!("{y:.6}"));
                s += &format!(
                    "{:<18}{:>12.6}{:>12}{:>14}\n",
                    f.kind.name(),
                    f.tau,
                    o(f.exact_tau),
                    f.timing_error.map_or("-".into(), e)
                );
            }
        } else {
            s += &wrap("", "Events: not compared (a curved contact's total force has none).", 100);
        }
        s += &findings_text("Findings", &v.findings, "none", "sample");
        s
    }
}

/// The time origin in words.
fn origin_text(v: &HistoryValidation) -> String {
    use super::OriginSource;
    let o = &v.time_origin;
    let omega = o
        .omega
        .map_or(String::new(), |w| format!(" Angular frequency found from the normal force: {w} rad per unit of t."));
    match o.source {
        OriginSource::Assumed => format!(
            "Time origin: assumed to be the seed's (no normal column to check it): tau = omega t with the \
             indentation u_z = u0 - du cos(omega t).{omega}"
        ),
        OriginSource::NormalForce if o.offset == 0.0 => {
            format!("Time origin: the seed's (from the normal force: u_z = u0 - du cos(omega t)).{omega}")
        }
        OriginSource::NormalForce => {
            let follows = o.convention.map_or(String::new(), |c| format!(" (the file follows u_z = {c})"));
            format!(
                "Time origin of your file: {:+.6} rad ({:+.2} samples) against the seed's u_z = u0 - du \
                 cos(omega t){follows}, found from the normal force; compared after aligning.{omega}",
                o.offset, o.offset_samples
            )
        }
    }
}

/// `(K/kx .., omega/omega_c .., zeta ..)`: the system of a comparison.
fn system_params(sys: &crate::system::System) -> String {
    format!("(K/kx {}, omega/omega_c {}, zeta {})", sys.stiffness(), sys.frequency_ratio(), sys.damping())
}

impl Convergence {
    /// The smallest and largest jumping share of the rows in `regime`.
    #[must_use]
    pub fn jumping_share(&self, regime: ContactRegime) -> [f64; 2] {
        let share = self.rows.iter().filter(|r| r.regime == regime).map(|r| r.jumping_share);
        [share.clone().fold(f64::INFINITY, f64::min), share.fold(f64::NEG_INFINITY, f64::max)]
    }

    /// The report for a person: orders per regime, every row, findings and cautions.
    #[must_use]
    pub fn summary(&self) -> String {
        let c = self;
        let e = |x: f64| format!("{x:.2e}");
        let opt = |x: Option<f64>, f: &dyn Fn(f64) -> String| x.map(f).unwrap_or_else(|| "-".into());
        let res: Vec<String> = c.resolutions.iter().map(|r| r.to_string()).collect();
        let mut s = wrap(
            "",
            &format!(
                "fricosc validate --series: {} of {} at resolutions {}.",
                count(c.rows.len(), "row"),
                c.shape,
                res.join(", ")
            ),
            100,
        );
        if let Some(sys) = &c.system {
            s += &wrap("", &format!("On a system {}: the exact values are its attractors.", system_params(sys)), 100);
        }
        s += &wrap(
            "",
            "Observed order: the least-squares slope of log |error| against log resolution (errors at rounding left \
             out). Status: converging (order >= 0.5), not_converging, resolution_independent (the same error at \
             every resolution), exact (at rounding).",
            100,
        );
        s += &format!("\n{:<26}{:>6}{:>14}{:>8}{:>8}\n", "regime", "rows", "median order", "min", "max");
        for g in &c.by_regime {
            s += &format!(
                "{:<26}{:>6}{:>14.2}{:>8.2}{:>8.2}\n",
                g.regime.label(c.jumping_share(g.regime)),
                g.n,
                g.median_order,
                g.min_order,
                g.max_order
            );
        }
        let with_needed = c.target.is_some();
        s += &format!(
            "\n{:>8}{:>6}  {:<22}{:>7}{:>11}{:>13}{:>13}  {:<22}{}\n",
            "vbar",
            "amp",
            "regime",
            "order",
            "constant",
            "last error",
            "richardson",
            "status",
            if with_needed { format!("{:>12}", "needed") } else { String::new() }
        );
        for r in &c.rows {
            s += &format!(
                "{:>8}{:>6}  {:<22}{:>7}{:>11}{:>13}{:>13}  {:<22}{}\n",
                r.vbar,
                r.amp,
                r.regime.label([r.jumping_share; 2]),
                opt(r.order, &|p| format!("{p:.2}")),
                opt(r.constant, &e),
                e(*r.errors.last().unwrap_or(&0.0)),
                opt(r.richardson_error, &e),
                r.status.name(),
                if with_needed {
                    format!("{:>12}", needed_text(r.needed_resolution, &|m| format!("{m:.3e}")))
                } else {
                    String::new()
                }
            );
        }
        s += &findings_text("Findings", &c.findings, "none", "row");
        if !c.cautions.is_empty() {
            s += &findings_text("Cautions (not findings)", &c.cautions, "none", "row");
        }
        s
    }
}

/// A needed resolution in words: `f` of it, `unreachable`, or nothing.
pub(crate) fn needed_text(n: Option<Needed>, f: &dyn Fn(f64) -> String) -> String {
    match n {
        None => String::new(),
        Some(Needed::Resolution(m)) => f(m),
        Some(Needed::Unreachable) => "unreachable".into(),
    }
}

/// Words wrapped to lines of at most `width` characters, the first prefixed by
/// `first` and the rest indented as deep.
pub(crate) fn wrap(first: &str, text: &str, width: usize) -> String {
    let indent = " ".repeat(first.chars().count());
    let mut out = String::new();
    let mut line = first.to_string();
    for word in text.split_whitespace() {
        if line.chars().count() + 1 + word.chars().count() > width && !line.trim().is_empty() && line != first {
            out.push_str(line.trim_end());
            out.push('\n');
            line = indent.clone();
        } else if !line.ends_with(' ') && !line.is_empty() {
            line.push(' ');
        }
        line.push_str(word);
    }
    out.push_str(line.trim_end());
    out.push('\n');
    out
}

/// `n noun`, with the plural where `n != 1`.
pub(crate) fn count(n: usize, noun: &str) -> String {
    if n == 1 {
        format!("1 {noun}")
    } else {
        format!("{n} {noun}s")
    }
}

/// Findings as a list for a person, after a blank line: none, or each with its rows and hint.
pub(crate) fn findings_text(title: &str, findings: &[Finding], none: &str, row_noun: &str) -> String {
    if findings.is_empty() {
        return format!("\n{title}: {none}.\n");
    }
    let mut s = format!("\n{title}:\n");
    for f in findings {
        let rows = f.rows.iter().map(|r| r.to_string()).collect::<Vec<_>>().join(", ");
        let more = if f.count > f.rows.len() { ", ..." } else { "" };
        let which =
            if f.rows.is_empty() { String::new() } else { format!("{} ({rows}{more}): ", count(f.count, row_noun)) };
        s += &wrap("- ", &format!("{}: {which}{}", f.kind.name(), f.hint), 100);
    }
    s
}

/// A table of error summaries, one line per group, after a blank line.
fn summary_table<'a>(title: &str, groups: impl Iterator<Item = (String, &'a Summary)>) -> String {
    let e = |x: f64| format!("{x:.2e}");
    let mut s = format!(
        "\n{:<22}{:>8}{:>14}{:>12}{:>16}{:>11}\n",
        title, "rows", "max |error|", "rms error", "max rel error", "worst row"
    );
    for (name, m) in groups {
        s += &format!(
            "{:<22}{:>8}{:>14}{:>12}{:>16}{:>11}\n",
            name,
            m.n,
            e(m.max_abs_error),
            e(m.rms_error),
            e(m.max_rel_error),
            m.worst_row
        );
    }
    s
}

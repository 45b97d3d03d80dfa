//! The findings of a table against the exact values ([`super::compare`]):
//! each names a pattern of errors and what usually causes it.

use super::{convention, exact_value, finding, AtRest, Check, Finding, FindingKind, Row};
use crate::error::Result;
use crate::shape::Shape;

/// A vbar below which errors are compared with those at the same amplitude
/// above it (and below 1) for [`FindingKind::NotSteady`].
const LOW_VBAR: f64 = 0.3;
/// How much larger the errors at low vbar must be than elsewhere to be a finding.
const NOT_STEADY_FACTOR: f64 = 10.0;

pub(super) fn findings(
    shape: &Shape,
    rows: &[Row],
    amps: &[f64],
    check: &Check,
    critical: Option<&[f64]>,
) -> Result<Vec<Finding>> {
    let (at_rest, tol) = (check.at_rest, check.tolerance);
    let pick = |f: &dyn Fn(&Row) -> bool| rows.iter().filter(|r| f(r)).map(|r| r.row).collect::<Vec<_>>();
    let mut out = vec![];
    out.extend(finding(
        FindingKind::AboveOne,
        pick(&|r| r.mu_ratio > 1.0 + tol),
        "values above 1: check the normalisation by the mean normal force (mu0 times the period-averaged \
         normal force, not the static one or its value at one instant)",
    ));
    // On a system the body may slip backwards, but where the exact value is
    // not negative a negative one is the table's.
    out.extend(finding(
        FindingKind::Negative,
        pick(&|r| r.mu_ratio < -tol && r.exact >= -tol),
        "negative values: check the sign of the tangential force and that every average spans whole periods",
    ));
    out.extend(finding(
        FindingKind::ContactLoss,
        contact_loss(rows, tol),
        "rows with du/u0 > 1, where the contact opens every period, are below the exact values by more than 0.01 \
         and ten times the largest error at du/u0 <= 1: check contact loss (the normal force is (u0 - du cos tau)_+, never \
         negative; a spring out of contact carries no force and enters contact again relaxed)",
    ));
    out.extend(not_one_above_critical(rows, amps, tol, critical));
    out.extend(finding(
        FindingKind::NotMonotone,
        decreasing(rows, amps, tol),
        "mu/mu0 decreases with velocity at these rows where the exact curve does not: check convergence there \
         (time step, number of periods, springs)",
    ));
    out.extend(finding(
        FindingKind::NotSteady,
        not_steady(rows, amps, tol),
        "errors grow towards vbar -> 0, ten times those at the same amplitude's higher velocities: the \
         steady state takes longer to reach at low velocity (the tangential force builds up at a rate \
         proportional to vbar); run more periods and average the last one",
    ));
    at_rest_findings(shape, rows, amps, at_rest, tol, &mut out)?;
    out.extend(finding(
        FindingKind::WorseThanPeer,
        worse_than_peer(rows, amps, tol),
        "errors ten times (or more) those of fricosc's stepping peer (the seed's scheme) at the same resolution: \
         not the discretisation but a bug (see the peer_error column)",
    ));
    let worst = rows.iter().fold(0.0f64, |m, r| m.max(r.error.abs()));
    if let Some(sys) = &check.system {
        let table: Vec<(usize, f64, f64, f64)> = rows.iter().map(|r| (r.row, r.vbar, r.amp, r.mu_ratio)).collect();
        let errors: Vec<f64> = rows.iter().map(|r| r.error).collect();
        out.extend(super::system::mistake(shape, &table, sys, &errors));
        if out.is_empty() {
            out.extend(super::system::unexplained(rows.iter().map(|r| (r.row, r.error)), worst));
        }
    }
    if out.is_empty() {
        out.extend(convention::large_errors(convention::large(rows.iter().map(|r| (r.row, r.error))), worst));
    }
    Ok(out)
}

/// [`FindingKind::NotOneAboveCritical`]: rows at or above the critical
/// velocity (`vbar = 1`; on a system its own, `critical` per amplitude of
/// `amps`, where the exact value is 1 too) whose value is not 1. Without a
/// system, values below 1 there are what a body on a system spring gives:
/// the hint says so.
fn not_one_above_critical(rows: &[Row], amps: &[f64], tol: f64, critical: Option<&[f64]>) -> Option<Finding> {
    let at = |a: f64| amps.partition_point(|&x| x < a);
    let above = |r: &Row| match critical {
        Some(c) => r.vbar >= c[at(r.amp)] && (r.exact - 1.0).abs() <= tol,
        None => r.vbar >= 1.0,
    };
    let bad: Vec<&Row> = rows.iter().filter(|r| above(r) && (r.mu_ratio - 1.0).abs() > tol).collect();
    let mut hint = String::from(match critical {
        Some(_) => {
            "from the system's critical velocity on (each amplitude's, where every spring slips forward \
             for ever) mu/mu0 = 1 exactly: check the velocity's normalisation (eq. 3) and the system's \
             parameters"
        }
        None => {
            "at vbar >= 1 no spring sticks and mu/mu0 = 1 exactly: check the velocity's normalisation (eq. 3: \
             vbar = (kx/kz) v0 / (mu0 omega du)) and the Coulomb bound"
        }
    });
    if critical.is_none() && bad.iter().any(|r| r.mu_ratio < 1.0) {
        hint += ". Values below 1 there are what a body with mass on a system spring gives (the body oscillates \
             and sticks again): if your code models one, compare with --system-stiffness, --frequency-ratio and \
             --damping";
    }
    finding(FindingKind::NotOneAboveCritical, bad.iter().map(|r| r.row).collect(), &hint)
}

/// [`FindingKind::ContactLoss`]: rows at `amp > 1` and `vbar < 1` below the
/// exact value by more than [`CONTACT_LOSS_ERROR`] and ten times the largest
/// error at `amp <= 1` (none unless the table has rows on both sides). A spring
/// kept in contact past `du cos tau = u0` carries a negative bound, which pulls
/// `mu` down (by 0.12 at `vbar = 0.1, amp = 1.2`, 0.34 at `amp = 1.5`, the same
/// at 100 and 1000 steps a period); the seed's scheme errs upwards there, by
/// at most 5.5e-3 at 100 steps.
fn contact_loss(rows: &[Row], tol: f64) -> Vec<usize> {
    let closed: Vec<f64> = rows.iter().filter(|r| r.amp <= 1.0).map(|r| r.error.abs()).collect();
    if closed.is_empty() {
        return vec![];
    }
    let bar = (10.0 * closed.iter().fold(0.0f64, |m, &e| m.max(e))).max(tol).max(CONTACT_LOSS_ERROR);
    rows.iter().filter(|r| r.amp > 1.0 && r.vbar < 1.0 && r.error < -bar).map(|r| r.row).collect()
}

/// The smallest shortfall [`contact_loss`] names: beyond the seed's scheme's
/// own errors at 100 steps a period (at most 5.5e-3, and upwards; see there).
const CONTACT_LOSS_ERROR: f64 = 1e-2;

/// Rows where `mu` decreases in `vbar` at one amplitude (rows sorted by vbar;
/// vbar = 0 rows follow the chosen convention, so a relaxed 0 is not a decrease).
fn decreasing(rows: &[Row], amps: &[f64], tol: f64) -> Vec<usize> {
    let mut decreasing = vec![];
    for &a in amps {
        let mut line: Vec<&Row> = rows.iter().filter(|r| r.amp == a).collect();
        line.sort_by(|x, y| x.vbar.total_cmp(&y.vbar));
        for w in line.windows(2) {
            // Where the exact curve falls too (on a system), only a faster fall.
            let exact_fall = (w[0].exact - w[1].exact).max(0.0);
            if w[1].vbar > w[0].vbar && w[1].mu_ratio < w[0].mu_ratio - exact_fall - tol {
                decreasing.push(w[1].row);
            }
        }
    }
    decreasing.sort_unstable();
    decreasing
}

/// Rows whose errors are far larger at low velocity than at the same
/// amplitude's higher velocities (below the critical one): the transient.
/// Compared within one amplitude, so that a scheme's larger error in the
/// jumping regimes is not mistaken for it. Only where some spring never loses
/// contact (`amp < 1`): a spring that loses contact enters it relaxed every
/// period, so its steady state is reached in the first; and with a peer, only
/// rows ten times worse than the peer at the same resolution (a peer as far
/// off has the same discretisation, not a transient).
fn not_steady(rows: &[Row], amps: &[f64], tol: f64) -> Vec<usize> {
    let mut slow = vec![];
    for &a in amps.iter().filter(|&&a| a < 1.0) {
        let rest: Vec<f64> =
            rows.iter().filter(|r| r.amp == a && r.vbar >= LOW_VBAR && r.vbar < 1.0).map(|r| r.error.abs()).collect();
        if rest.is_empty() {
            continue;
        }
        let bar = (NOT_STEADY_FACTOR * rest.iter().sum::<f64>() / rest.len() as f64).max(tol);
        slow.extend(
            rows.iter()
                .filter(|r| r.amp == a && r.vbar > 0.0 && r.vbar < LOW_VBAR && r.error.abs() > bar)
                .filter(|r| r.peer_error.is_none_or(|p| r.error.abs() > 10.0 * p.abs()))
                .map(|r| r.row),
        );
    }
    slow.sort_unstable();
    slow
}

/// The findings about `vbar = 0` rows: those that match the other convention
/// rather than the chosen one, and those off by as much as the sliding rows.
fn at_rest_findings(
    shape: &Shape,
    rows: &[Row],
    amps: &[f64],
    at_rest: AtRest,
    tol: f64,
    out: &mut Vec<Finding>,
) -> Result<()> {
    let other = match at_rest {
        AtRest::Sliding => AtRest::Relaxed,
        AtRest::Relaxed => AtRest::Sliding,
    };
    let mut mismatched = vec![];
    for r in rows.iter().filter(|r| r.vbar == 0.0) {
        let alt = exact_value(shape, 0.0, r.amp, other)?;
        if r.error.abs() > tol && (r.mu_ratio - alt).abs() <= tol.max(1e-12) {
            mismatched.push(r.row);
        }
    }
    let hint = match other {
        AtRest::Relaxed => {
            "at vbar = 0 these values equal 0, what a stepper started from relaxed springs gives at exactly zero \
             velocity (not the limit vbar -> 0+ of a sliding contact): compare with --at-rest relaxed"
        }
        AtRest::Sliding => {
            "at vbar = 0 these values equal the limit vbar -> 0+ of a sliding contact (mu_static), not the relaxed \
             start: compare with --at-rest sliding"
        }
    };
    out.extend(finding(FindingKind::AtRestConvention, mismatched.clone(), hint));
    out.extend(finding(
        FindingKind::StaticLimit,
        static_limit(rows, amps, at_rest, tol, &mismatched),
        "at vbar = 0 nothing sticks or slips (mu/mu0 is the closed form N_min/N_mean: 1 - amp for the flat \
         punch up to amp = 1), so a stepper gets these rows far more accurately than the rows at sliding \
         velocities, yet they are as far off: the error is in what every row shares: the averaging (over whole \
         periods?), the normalisation by the mean normal force, or the start",
    ));
    Ok(())
}

/// A `vbar = 0` row's error is a finding when it exceeds this share of the
/// median error of the same amplitude's rows at `0 < vbar < 1`: a stepper's
/// error there is the spring grid's alone (none for the flat punch), which
/// enters every other row too, on top of the stick-slip's.
const STATIC_SHARE: f64 = 0.25;

/// [`FindingKind::StaticLimit`]: `vbar = 0` rows (compared with the sliding
/// limit, and not already explained by the other convention) off by more than
/// [`STATIC_SHARE`] of the median error at the same amplitude's sliding
/// velocities below 1 (or by more than the tolerance, where there are none).
fn static_limit(rows: &[Row], amps: &[f64], at_rest: AtRest, tol: f64, explained: &[usize]) -> Vec<usize> {
    if at_rest != AtRest::Sliding {
        return vec![];
    }
    let mut out = vec![];
    for &a in amps {
        let mut moving: Vec<f64> =
            rows.iter().filter(|r| r.amp == a && r.vbar > 0.0 && r.vbar < 1.0).map(|r| r.error.abs()).collect();
        moving.sort_by(f64::total_cmp);
        let bar = match moving.len() {
            0 => tol,
            n => (STATIC_SHARE * moving[n / 2]).max(tol),
        };
        out.extend(
            rows.iter()
                .filter(|r| r.amp == a && r.vbar == 0.0 && r.error.abs() > bar && !explained.contains(&r.row))
                .map(|r| r.row),
        );
    }
    out.sort_unstable();
    out
}

/// How many times the peer's error a row's error may be before it is a
/// [`FindingKind::WorseThanPeer`] finding.
const PEER_FACTOR: f64 = 10.0;

/// [`FindingKind::WorseThanPeer`]: rows whose error exceeds [`PEER_FACTOR`]
/// times the peer's there or (where the peer happens to be near a zero of its
/// error) the median of the peer's errors at the same amplitude.
fn worse_than_peer(rows: &[Row], amps: &[f64], tol: f64) -> Vec<usize> {
    let mut out = vec![];
    for &a in amps {
        let mut peer: Vec<f64> =
            rows.iter().filter(|r| r.amp == a).filter_map(|r| r.peer_error.map(f64::abs)).collect();
        if peer.is_empty() {
            continue;
        }
        peer.sort_by(f64::total_cmp);
        let median = peer[peer.len() / 2];
        out.extend(
            rows.iter()
                .filter(|r| r.amp == a)
                .filter(|r| r.peer_error.is_some_and(|p| r.error.abs() > (PEER_FACTOR * p.abs().max(median)).max(tol)))
                .map(|r| r.row),
        );
    }
    out.sort_unstable();
    out
}

//! A table of `(vbar, amp, mu_ratio)` on a system with mass and stiffness
//! ([`super::Check::system`]): the exact values are the attractors, the
//! regimes and the critical velocity the system's, the peer the stepper with
//! the body; and where the errors are large, the usual mistakes in the
//! system's equation, each tried against the exact solver.

use super::{finding, AtRest, Check, Finding, FindingKind};
use crate::contact::regime::ContactRegime;
use crate::error::{Error, Result};
use crate::shape::Shape;
use crate::stepper::Stepping;
use crate::system::System;
use crate::Conditions;

/// One row's exact answer: `mu`, and on a system the attractor's period and
/// its error estimate.
pub(super) struct Exact {
    pub(super) mu: f64,
    pub(super) period: Option<usize>,
    pub(super) estimate: Option<f64>,
}

/// The exact answer at `(vbar, amp)` under `check` (its `vbar = 0`
/// convention, its system).
pub(super) fn exact(shape: &Shape, vbar: f64, amp: f64, check: &Check) -> Result<Exact> {
    let Some(sys) = check.system else {
        return Ok(Exact { mu: super::exact_value(shape, vbar, amp, check.at_rest)?, period: None, estimate: None });
    };
    if vbar == 0.0 && check.at_rest == AtRest::Relaxed {
        return Ok(Exact { mu: 0.0, period: None, estimate: Some(0.0) });
    }
    let r = attractor(shape, &Conditions::vbar(vbar, amp)?.with_system(sys))?;
    Ok(Exact { mu: r.mu_ratio, period: r.period, estimate: Some(r.error_estimate) })
}

/// The attractor at the conditions `c` (on a system).
fn attractor(shape: &Shape, c: &Conditions) -> Result<crate::system::SystemReport> {
    match shape.report(c)? {
        crate::Report::System(r) => Ok(r),
        _ => Err(Error::Internal { what: "a point on a system is reported as the system's".into() }),
    }
}

/// The stepping peer with the body ([`crate::stepper::system`], at least
/// [`crate::system::MIN_SPRINGS`] springs, [`super::SYSTEM_PEER_PERIODS`] periods).
pub(super) fn peer(shape: &Shape, c: &Conditions, sys: System, st: Stepping) -> Result<f64> {
    let sys = sys.with_springs(st.springs.max(crate::system::MIN_SPRINGS))?;
    crate::stepper::system(shape, &c.with_system(sys), st.steps_per_period, super::SYSTEM_PEER_PERIODS)
}

/// On a system, the least `vbar` from which `mu = 1` at each amplitude
/// ([`crate::system::critical_vbar`]; infinite where there is none).
pub(super) fn critical(shape: &Shape, amps: &[f64], system: Option<&System>) -> Result<Option<Vec<f64>>> {
    let Some(sys) = system else { return Ok(None) };
    let at = |&a: &f64| Ok(crate::system::critical_vbar(shape, a, sys)?.unwrap_or(f64::INFINITY));
    Ok(Some(amps.iter().map(at).collect::<Result<Vec<f64>>>()?))
}

/// The regime of a row: without a system the stiff one
/// ([`Shape::regime`]); on a system `sliding` from its critical velocity
/// `critical`, else what the imposed normal oscillation does to the contact
/// (which does not depend on the body): permanent contact, mixed, or every
/// spring losing contact (`jumping`).
pub(super) fn regime(shape: &Shape, vbar: f64, amp: f64, critical: Option<f64>) -> Result<ContactRegime> {
    let stiff = shape.regime(vbar, amp)?;
    let Some(critical) = critical else { return Ok(stiff) };
    Ok(if vbar == 0.0 {
        ContactRegime::AtRest
    } else if vbar >= critical || amp == 0.0 {
        ContactRegime::Sliding
    } else if !shape.is_flat() {
        shape.regime(0.5, amp)?
    } else if amp <= 1.0 {
        ContactRegime::PermanentContact
    } else {
        ContactRegime::Jumping
    })
}

/// Errors from which the usual mistakes of a system's equation are tried:
/// well above a stepper's discretisation error at ordinary resolutions (the
/// planted mistakes of `tests/README.md` err by 4e-2 to 8e-2).
pub(crate) const SUSPECT_ERROR: f64 = 1e-2;

/// A mistake in the system's equation: the system it amounts to, or `None`
/// for one that is not a system.
pub(super) type Mistake = (fn(&System) -> Result<Option<System>>, &'static str);

/// The usual mistakes in `Omega^2 x'' = kappa (X_d - x) - 2 zeta sqrt(kappa)
/// Omega (x' - X_d') - f`, each as the system a code with it solves: the
/// damping left out; `Omega` for `Omega^2` in the mass term (the dashpot's
/// coefficient kept: `Omega' = sqrt(Omega)`, `zeta' = zeta sqrt(Omega)`) and
/// `Omega^2` squared again (`Omega' = Omega^2`, `zeta' = zeta / Omega`);
/// `Omega^2` in the dashpot (`zeta' = zeta Omega`); `kappa` inverted; the
/// system left out (the stiff answer).
pub(super) const MISTAKES: [Mistake; 6] = [
    (|s| Ok(Some(System::new(s.stiffness(), s.frequency_ratio(), 0.0)?)), "the damping left out (zeta = 0)"),
    (
        |s| {
            let om = s.frequency_ratio();
            Ok(Some(System::new(s.stiffness(), om.sqrt(), s.damping() * om.sqrt())?))
        },
        "Omega where Omega^2 belongs in the mass term (Omega x'')",
    ),
    (
        |s| {
            let om = s.frequency_ratio();
            // A massless body has no mass term to get wrong (Omega = 0 is not tried).
            if om == 0.0 {
                return Err(Error::param("frequency-ratio", om, "no mass term"));
            }
            Ok(Some(System::new(s.stiffness(), om * om, s.damping() / om)?))
        },
        "Omega^4 in the mass term (Omega^2 squared twice)",
    ),
    (
        |s| Ok(Some(System::new(s.stiffness(), s.frequency_ratio(), s.damping() * s.frequency_ratio())?)),
        "Omega^2 where Omega belongs in the dashpot (2 zeta sqrt(kappa) Omega^2 x')",
    ),
    (
        |s| Ok(Some(System::new(1.0 / s.stiffness(), s.frequency_ratio(), s.damping())?)),
        "kappa inverted (kx/K for K/kx)",
    ),
    (|_| Ok(None), "no system at all (the stiff answer: the code has no body on a spring)"),
];

/// Periods of the transient tried for a run too short ([`mistake`]).
const SHORT_RUNS: usize = 400;

/// Errors from which a run too short is looked for: above a stepper's
/// discretisation error at ordinary resolutions (5e-4 at 500 steps a period
/// on the example stepper's table).
const SHORT_RUN_ERROR: f64 = 1e-3;

/// How a candidate's errors compare with those as read: it explains the
/// table where its median (or largest) error is at most this share of the
/// one as read, and the other no larger.
pub(super) const EXPLAINS: f64 = 0.25;

/// The median and the largest of `|errors|`.
fn spread(errors: &[f64]) -> (f64, f64) {
    let mut e: Vec<f64> = errors.iter().map(|x| x.abs()).collect();
    e.sort_by(f64::total_cmp);
    (e[e.len() / 2], e[e.len() - 1])
}

/// On a system, where the errors are large: the mistake whose exact values
/// the table meets far better than the right ones ([`EXPLAINS`]), the one
/// with the smallest median error. Tried
/// from a largest error of [`SUSPECT_ERROR`]: the mistakes of [`MISTAKES`]
/// and the normalisation by the static normal force; from
/// [`SHORT_RUN_ERROR`] (the flat punch): a run of `k <= 400` periods from the
/// stated start, its last period averaged. `rows` are the finite rows
/// `(row, vbar, amp, mu_ratio)`, `errors` theirs.
pub(super) fn mistake(shape: &Shape, rows: &[(usize, f64, f64, f64)], sys: &System, errors: &[f64]) -> Option<Finding> {
    if rows.is_empty() {
        return None;
    }
    let (median, worst) = spread(errors);
    let fits = |errs: &[f64]| {
        let (m, top) = spread(errs);
        let better = (m <= EXPLAINS * median && top <= worst) || (top <= EXPLAINS * worst && m <= median);
        better.then_some((m, top))
    };
    let errors_of = |value: &(dyn Fn(f64, f64) -> Result<f64> + Sync)| -> Option<Vec<f64>> {
        let errs = crate::numerics::par::map(rows, |&(_, v, a, mu)| value(v, a).map(|x| mu - x));
        errs.into_iter().collect::<Result<Vec<f64>>>().ok()
    };
    let mut found: Vec<(f64, f64, String)> = vec![];
    if worst > SUSPECT_ERROR {
        for (read, name) in MISTAKES {
            let Ok(as_read) = read(sys) else { continue };
            let value = |v: f64, a: f64| {
                let c = Conditions::vbar(v, a)?;
                Ok(match as_read {
                    Some(s) => shape.ratio(&c.with_system(s))?.mu_ratio,
                    None => shape.ratio(&c)?.mu_ratio,
                })
            };
            found.extend(errors_of(&value).as_deref().and_then(fits).map(|(m, top)| (m, top, name.to_string())));
        }
        // `<f>` over the static normal force `F0` instead of `<N>`: `mu <N>/F0`.
        let static_norm = |v: f64, a: f64| {
            let mu = shape.ratio(&Conditions::vbar(v, a)?.with_system(*sys))?.mu_ratio;
            Ok(mu * shape.contact().mean_normal(a)? / shape.contact().static_force(1.0))
        };
        let name = "the mean force over the static normal force, not the period-averaged one";
        found.extend(errors_of(&static_norm).as_deref().and_then(fits).map(|(m, top)| (m, top, name.into())));
    }
    if worst > SHORT_RUN_ERROR && shape.is_flat() {
        found.extend(short_run(rows, sys, &fits));
    }
    let (m, top, name) = found.into_iter().min_by(|x, y| x.0.total_cmp(&y.0))?;
    let hint = format!(
        "your values match the exact ones with {name}: errors {m:.1e} (median) and {top:.1e} (largest) there, \
         {median:.1e} and {worst:.1e} as read (tried: the damping left out, Omega for Omega^2 and Omega^4, \
         Omega^2 in the dashpot, kappa inverted, no system, the static normal force, runs of 1 to 400 periods)"
    );
    finding(FindingKind::Convention, rows.iter().map(|r| r.0).collect(), &hint)
}

/// On a system, errors above [`SUSPECT_ERROR`] that no mistake explains
/// ([`mistake`]) and no other finding names: [`FindingKind::LargeErrors`]
/// (on a system the bar is lower than without one: its usual mistakes err
/// by a few hundredths).
pub(super) fn unexplained(errors: impl Iterator<Item = (usize, f64)>, worst: f64) -> Option<Finding> {
    let rows: Vec<usize> = errors.filter(|e| e.1.abs() > SUSPECT_ERROR).map(|e| e.0).collect();
    let hint = format!(
        "errors up to {worst:.3}, far above a stepper's discretisation error, and none of the usual mistakes in the \
         system's equation explains them (the damping left out, Omega for Omega^2 or Omega^4, Omega^2 in the \
         dashpot, kappa inverted, no system, the static normal force, a run of up to 400 periods): check the \
         system's parameters as given (--frequency-ratio and --damping are 0 unless given), the start and the \
         normalisation"
    );
    finding(FindingKind::LargeErrors, rows, &hint)
}

/// Whether a candidate's errors explain the table: its median and largest
/// error where they do.
type Fits<'a> = &'a dyn Fn(&[f64]) -> Option<(f64, f64)>;

/// The run of `k` periods (from the stated start, the `k`-th averaged) whose
/// values the table meets best, if that fits; `None` where a row's transient
/// cannot be computed.
fn short_run(rows: &[(usize, f64, f64, f64)], sys: &System, fits: Fits) -> Option<(f64, f64, String)> {
    let runs = crate::numerics::par::map(rows, |&(_, v, a, _)| {
        crate::system::transient(&Conditions::vbar(v, a)?, sys, SHORT_RUNS)
    });
    let runs: Vec<Vec<f64>> = runs.into_iter().collect::<Result<_>>().ok()?;
    if runs.iter().any(|r| r.len() != SHORT_RUNS) {
        return None;
    }
    (0..SHORT_RUNS)
        .filter_map(|k| {
            let errs: Vec<f64> = rows.iter().zip(&runs).map(|(r, run)| r.3 - run[k]).collect();
            fits(&errs).map(|(m, top)| (m, top, format!("a run of {} periods (the last averaged)", k + 1)))
        })
        .min_by(|x, y| x.0.total_cmp(&y.0))
}

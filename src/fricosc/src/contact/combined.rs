//! Friction under oscillation in the sliding direction, alone or with the
//! normal oscillation and a phase between them (README: oscillation in the sliding direction),
//! for every contact: the flat punch is one spring ([`crate::stop`]); a curved
//! contact is its MDR foundation, each spring with its own bound
//! `(1 - G(z) - amp cos tau)_+` and the same body motion.
//!
//! # Bands
//! A spring's steady state changes its sequence of phases (stick, forward
//! and backward slips, contact) only at isolated `z`: where it starts or stops
//! to lose contact (`G = 1 - amp`, closed form), where `G` itself is not smooth
//! ([`crate::contact::Contact::breakpoints`]), and where an event appears or disappears
//! (a tangency of the force and its bound, found by bisection on the
//! sequence of phases between `z` samples). Between those edges the means
//! are smooth in `z` and vanish or turn like a square root at the edges, so each
//! band is integrated by the shared order ladder ([`crate::integrate`]) in
//! `theta`, `z = a + (b - a)(1 - cos theta)/2`, the order doubled from 8
//! until two orders agree to the tolerance relative to the contact's normal
//! force (or to the springs' rounding); the error estimate is the sum of the
//! last differences (an event that appears between two samples of the band
//! search leaves a kink that the coefficients' decay would not see) and rounding.
//!
//! # Units
//! `mu_macro/mu0 = int <f> dz / int <B> dz` over the foundation (`<f>`, `<B>`
//! per unit length in `mu0 E* u0`), the normal force from the same quadrature
//! as the friction force (it equals [`crate::contact::Contact::mean_normal`] to the
//! tolerance, tested); the reduction `int <B - f> dz / int <B> dz` on its own.

use crate::conditions::Conditions;
use crate::error::{check_nonneg, Error, Result};
use crate::integrate::{bands, cosine_pass, Ladder, Sums};
use crate::ratio::Ratio;
use crate::shape::Shape;
use crate::stop::{solve, Bound, Drive, StopKind, StopSpring};

/// The oscillation and the sliding of [`Conditions`] with a tangential
/// oscillation: `vhat` (eq. 15), the normal amplitude `amp = du/u0`, the
/// tangential amplitude `T = dx/l` (pre-slip lengths `l = mu0 u0 kz/kx`) and
/// its phase against the normal oscillation (the body's position is
/// `vhat tau + T sin(tau + phase)`, the indentation `u0 - du cos tau`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Oscillation {
    pub(crate) vhat: f64,
    pub(crate) amp: f64,
    pub(crate) tangential_amp: f64,
    pub(crate) phase: f64,
}

impl Oscillation {
    /// The oscillation of `c` (`T = 0` without a tangential one).
    pub(crate) fn of(c: &Conditions) -> Oscillation {
        let (t, phase) = c.tangential().unwrap_or((0.0, 0.0));
        Oscillation { vhat: c.as_vhat(), amp: c.amp(), tangential_amp: t, phase }
    }

    pub(crate) fn drive(&self) -> Drive {
        Drive { vhat: self.vhat, t: self.tangential_amp, phase: self.phase }
    }
}

/// One band of a curved contact's springs.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct CombinedBand {
    /// Extent in `z = x/x_c`.
    pub from: f64,
    /// End.
    pub to: f64,
    /// What its springs do: the contact and the phases of one period, e.g.
    /// `permanent: stick, forward`.
    pub regime: String,
    /// Its share of `<f>` (of the total; negative where it pushes).
    pub share: f64,
    /// Springs evaluated (Gauss nodes of every order tried).
    pub nodes: usize,
}

/// The answer for one point.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct Combined {
    /// `mu_macro/mu0` (in `[-1, 1]`) and the reduction `1 - mu/mu0` (in `[0, 2]`),
    /// each from its own integral.
    #[cfg_attr(feature = "serde", serde(flatten))]
    pub ratio: Ratio,
    /// Bound on `|error|` of both.
    pub error_estimate: f64,
    /// The flat punch's spring: its phases over one period.
    #[cfg_attr(feature = "serde", serde(skip_serializing_if = "Option::is_none"))]
    pub spring: Option<SpringReport>,
    /// A curved contact's bands.
    #[cfg_attr(feature = "serde", serde(skip_serializing_if = "Vec::is_empty"))]
    pub bands: Vec<CombinedBand>,
}

/// A point under an oscillation in the sliding direction
/// ([`crate::Report::Tangential`]): its inputs and the answer with the flat
/// punch's spring or a curved contact's bands.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
#[non_exhaustive]
pub struct Tangential {
    /// `vhat` (eq. 15).
    pub vhat: f64,
    /// `du/u0`.
    pub amp: f64,
    /// `T = dx/l`.
    pub tangential_amp: f64,
    /// The phase, radians in `[0, 2 pi)`.
    pub phase: f64,
    /// The answer, the spring's phases or the bands.
    #[cfg_attr(feature = "serde", serde(flatten))]
    pub result: Combined,
}

/// One spring's steady state for a report.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct SpringReport {
    /// Its contact and phases, as a band's regime: e.g. `jumping: stick, backward, stick, forward`.
    pub regime: String,
    /// `permanent`, `jumping` or `never`.
    pub contact: crate::stop::Touch,
    /// The phases, in order from the start of the window.
    pub phases: Vec<crate::stop::StopPhase>,
    /// The events of one period: where a phase ends (phase in `[0, 2 pi)`).
    pub events: Vec<StopEvent>,
}

/// A change of phase.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct StopEvent {
    /// What starts: `stick`, `forward` (slip), `backward` (slip), `contact`, `loss_of_contact`.
    pub kind: &'static str,
    /// Where, in `[0, 2 pi)`.
    pub tau: f64,
    /// The normal force (the bound) there, units `kz u0`.
    pub normal: f64,
    /// The tangential force there, units `mu0 kz u0`.
    pub tangential: f64,
}

fn kind_name(k: StopKind) -> &'static str {
    match k {
        StopKind::Stick => "stick",
        StopKind::Forward => "forward",
        StopKind::Backward => "backward",
    }
}

/// What a spring does, as a band's name: its contact and phases.
fn signature(s: &StopSpring) -> (crate::stop::Touch, Vec<StopKind>) {
    let mut kinds: Vec<StopKind> = s.phases.iter().filter(|p| p.end > p.start).map(|p| p.kind).collect();
    kinds.dedup();
    (s.contact, kinds)
}

fn signature_name(sig: &(crate::stop::Touch, Vec<StopKind>)) -> String {
    let contact = match sig.0 {
        crate::stop::Touch::Never => "never",
        crate::stop::Touch::Permanent => "permanent",
        crate::stop::Touch::Jumping => "jumping",
    };
    let phases: Vec<&str> = sig.1.iter().map(|&k| kind_name(k)).collect();
    format!("{contact}: {}", phases.join(", "))
}

/// The flat punch's spring for a report: phases and events.
pub(crate) fn report(s: &StopSpring, b: Bound) -> SpringReport {
    use std::f64::consts::TAU;
    let mut events = vec![];
    if s.contact == crate::stop::Touch::Jumping {
        events.push(StopEvent { kind: "contact", tau: s.window.0.rem_euclid(TAU), normal: 0.0, tangential: 0.0 });
    }
    let wrap = match (s.contact, s.phases.first(), s.phases.last()) {
        // Always in contact: the period's first phase starts where its last ends.
        (crate::stop::Touch::Permanent, Some(first), Some(last)) if first.kind != last.kind => Some((last, first)),
        _ => None,
    };
    for (p, q) in s.phases.iter().zip(s.phases.iter().skip(1)).chain(wrap) {
        if p.kind == q.kind {
            continue;
        }
        let bound = b.c - b.amp * p.end.cos();
        let f = match q.kind {
            StopKind::Stick => q.force,
            StopKind::Forward => bound,
            StopKind::Backward => -bound,
        };
        events.push(StopEvent {
            kind: kind_name(q.kind),
            tau: p.end.rem_euclid(TAU),
            normal: bound.max(0.0),
            tangential: f,
        });
    }
    if s.contact == crate::stop::Touch::Jumping {
        events.push(StopEvent {
            kind: "loss_of_contact",
            tau: s.window.1.rem_euclid(TAU),
            normal: 0.0,
            tangential: 0.0,
        });
    }
    // At one instant (a spring touching only at tau = 0) the loss comes first.
    events.sort_by(|x, y| {
        x.tau.total_cmp(&y.tau).then((y.kind == "loss_of_contact").cmp(&(x.kind == "loss_of_contact")))
    });
    SpringReport { regime: signature_name(&signature(s)), contact: s.contact, phases: s.phases.clone(), events }
}

/// Rounding of one spring's means, in eps of the largest term (the phases'
/// integrals are closed forms of a few terms each): on the 16 40-digit
/// references of `data/combined-reference.json` the error is at most 0.57 of
/// these eps, so 8 bounds it with a margin of 14.
const SPRING_ROUNDING: f64 = 8.0;

/// The scale of a spring's phase integrals (for its rounding): the bound's
/// and the drive's swings over the period.
fn spring_scale(b: Bound, d: Drive) -> f64 {
    (b.c.abs() + b.amp + d.t + d.vhat * std::f64::consts::TAU).max(f64::MIN_POSITIVE)
}

/// `mu_macro/mu0` of `shape` under the conditions `c`, to their relative
/// quadrature tolerance (curved shapes). `T = 0` is the seed's problem: its
/// solver's answer (`vbar = vhat/amp`; no oscillation at all: 1).
///
/// # Errors
/// The solver's errors; [`Error::Internal`] for a result out of range.
pub(crate) fn evaluate(shape: &Shape, c: &Conditions) -> Result<Combined> {
    let (o, tol) = (Oscillation::of(c), c.tol());
    if o.tangential_amp == 0.0 {
        if o.amp == 0.0 {
            return Ok(Combined {
                ratio: Ratio { mu_ratio: 1.0, reduction: 0.0 },
                error_estimate: 0.0,
                spring: None,
                bands: vec![],
            });
        }
        let e = shape.contact().evaluate(c.as_vbar()?, o.amp, tol)?;
        return Ok(Combined { ratio: e.ratio, error_estimate: e.error_estimate, spring: None, bands: vec![] });
    }
    let d = o.drive();
    if shape.contact().single_spring() {
        let b = Bound { c: 1.0, amp: o.amp };
        let s = solve(b, d);
        let nb = s.mean_bound;
        let est = SPRING_ROUNDING * f64::EPSILON * spring_scale(b, d) / nb;
        let ratio = Ratio::signed(s.mean_force / nb, s.mean_deficit / nb, est, "flat punch, combined oscillation")?;
        return Ok(Combined { ratio, error_estimate: est, spring: Some(report(&s, b)), bands: vec![] });
    }
    if d.always_forward(o.amp) {
        // Every spring slips forward whenever it touches: f = B (skip the bands).
        return Ok(Combined {
            ratio: Ratio { mu_ratio: 1.0, reduction: 0.0 },
            error_estimate: 0.0,
            spring: None,
            bands: vec![],
        });
    }
    curved(shape.contact(), &o, tol)
}

/// First Gauss-Legendre order of a band (the next doubles it; their
/// difference is the first estimate).
const FIRST_ORDER: usize = 8;

/// Largest Gauss-Legendre order of a band (the stop operator's means turn
/// at the bands' edges like square roots, and within a band where an event
/// just appears; they need more than the power laws' 256).
const MAX_ORDER: usize = 1024;

fn curved(c: &dyn crate::contact::Contact, o: &Oscillation, tol: f64) -> Result<Combined> {
    check_nonneg("tol", tol)?;
    let d = o.drive();
    let zmax = c.reach(o.amp)?;
    // The quadrature sums a spring's means (up to its scale) over `[0, z_max]`:
    // both must stay finite, with room for the ladder's orders.
    if !(zmax * spring_scale(Bound { c: 1.0, amp: o.amp }, d) * MAX_ORDER as f64).is_finite() {
        return Err(Error::param(
            "amp",
            o.amp,
            &format!("the force integral over {}'s springs overflows double precision", c.name()),
        ));
    }
    let spring = |z: f64| {
        let b = Bound { c: 1.0 - c.equivalent_profile(z), amp: o.amp };
        (solve(b, d), b)
    };
    let search = bands::Search { scan: bands::SCAN, resolution: 0.0 };
    let edges = bands::edges(c, (o.amp, zmax), search, &|z| Ok(signature(&spring(z).0)))?;
    // The scale of the convergence test; the answer's normal force is the
    // quadrature's own integral of the springs' mean bounds, so that `mu` and
    // the reduction share one normalisation (they add up to 1 to rounding).
    let scale_normal = c.mean_normal(o.amp)?;
    // Each band on the order ladder, to the tolerance relative to the
    // contact's normal force, or to the rounding of the springs' means (the
    // estimate adds that rounding on its own).
    let ladder = Ladder { tol, max_order: MAX_ORDER, noise: SPRING_ROUNDING * f64::EPSILON, difference: true };
    let node = |z: f64| {
        let (s, bd) = spring(z);
        ([s.mean_force, s.mean_deficit, s.mean_bound], spring_scale(bd, d))
    };
    let mut bands = vec![];
    let (mut total, mut est) = (Sums::<3>::default(), 0.0);
    for w in edges.windows(2) {
        let (a, b) = (w[0], w[1]);
        if b <= a {
            continue;
        }
        let r = ladder.run(FIRST_ORDER, |m| cosine_pass(a, b, m, [true; 3], &node), [scale_normal; 3]);
        // |d mu| <= (|dF| + |dN|)/N for |mu| <= 1 (likewise the reduction's |dD|).
        est += r.error[0].max(r.error[1]) + r.error[2];
        let mid = spring(0.5 * (a + b)).0;
        let regime = signature_name(&signature(&mid));
        bands.push(CombinedBand { from: a, to: b, regime, share: r.value[0], nodes: r.nodes });
        total += r;
    }
    let (sum_f, sum_d, sum_b, scale) = (total.value[0], total.value[1], total.value[2], total.magnitude);
    // Both sides of the foundation (they cancel in the quotients).
    let normal = sum_b;
    if normal.is_nan() || normal <= 0.0 {
        return Err(Error::Internal { what: format!("mean normal force {normal:?} ({})", c.name()) });
    }
    let (mu, red) = (sum_f / normal, sum_d / normal);
    let rounding = SPRING_ROUNDING * f64::EPSILON * scale / normal;
    let error_estimate = est / normal + rounding;
    for band in &mut bands {
        band.share = if sum_f != 0.0 { band.share / sum_f } else { 0.0 };
    }
    let ratio = Ratio::signed(mu, red, error_estimate, &c.name())?;
    Ok(Combined { ratio, error_estimate, spring: None, bands })
}

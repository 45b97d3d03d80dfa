//! The qualitative claims of Part II of the series (Mao, V.L. Popov,
//! Starcevic, M. Popov, Friction 5 (2017) 194-206, "In-plane system
//! dynamics"), as `../shared/MODEL-system.md` states them, checked against the
//! exact solver on a system with mass and stiffness ([`crate::system`]), the
//! flat punch at `vbar = 0.3` (or 1.5), `du/u0 = 0.5`.

use super::claims::{named, Claim, Verdict};
use crate::system::{solve, System};
use crate::{Conditions, Shape};

/// `mu/mu0` of the flat punch on `(kappa, Omega, zeta)`, NaN where it fails.
fn mu(vbar: f64, kappa: f64, omega: f64, zeta: f64) -> f64 {
    let run = || solve(&Shape::flat(), &Conditions::vbar(vbar, 0.5)?, &System::new(kappa, omega, zeta)?);
    run().map_or(f64::NAN, |r| r.mu_ratio)
}

/// The stiff answer at `vbar`, `du/u0 = 0.5`.
fn stiff(vbar: f64) -> f64 {
    Conditions::vbar(vbar, 0.5).and_then(|c| Shape::flat().ratio(&c)).map_or(f64::NAN, |r| r.mu_ratio)
}

/// A very stiff system gives back the seed's answer: the difference falls like `1/kappa`.
pub(super) fn stiff_system() -> Claim {
    let s = stiff(0.3);
    let (d2, d4) = ((mu(0.3, 1e2, 0.5, 0.3) - s).abs(), (mu(0.3, 1e4, 0.5, 0.3) - s).abs());
    let ratio = d2 / d4;
    Claim {
        claim: "Part II: a very stiff system".into(),
        seed_says: "a very stiff measuring system gives back the results without the system's dynamics".into(),
        exact_gives: format!(
            "|mu - mu_stiff| = {d2:.3e} at K/kx = 100 and {d4:.3e} at 1e4 (ratio {ratio:.1}: like kx/K)"
        ),
        criterion: "holds if the difference at K/kx = 1e4 is below 1e-4 and falls by 50 to 200 times from K/kx = 100"
            .into(),
        measured: named(&[("difference_kappa_100", d2), ("difference_kappa_1e4", d4), ("ratio", ratio)]),
        deviation: Some(d4),
        deviation_is: "|mu/mu0 on the system - the stiff mu/mu0| at K/kx = 1e4".into(),
        location: "flat punch, vbar 0.3, du/u0 0.5, Omega 0.5, zeta 0.3".into(),
        verdict: if d4 < 1e-4 && (50.0..=200.0).contains(&ratio) { Verdict::Holds } else { Verdict::Wrong },
    }
}

/// A soft system with a heavy body (the excitation far above the contact's
/// resonance) gives back the seed's answer: the difference falls like
/// `Omega^-2`, whatever the stiffness.
pub(super) fn heavy_soft_system() -> Claim {
    let s = stiff(0.3);
    let d = |kappa: f64, omega: f64| (mu(0.3, kappa, omega, 0.1) - s).abs();
    let (d10, d20, d20_stiffer) = (d(0.05, 10.0), d(0.05, 20.0), d(1.0, 20.0));
    let ratio = d10 / d20;
    Claim {
        claim: "Part II: a very soft system".into(),
        seed_says: "a very soft measuring system gives back the results without the system's dynamics".into(),
        exact_gives: format!(
            "with K/kx = 0.05 and the excitation far above the contact's resonance: |mu - mu_stiff| = {d10:.3e} at \
             Omega = 10, {d20:.3e} at 20 (ratio {ratio:.2}: like Omega^-2; {d20_stiffer:.3e} at K/kx = 1): the body \
             too heavy to follow the oscillation slides at the drive's speed"
        ),
        criterion: "holds if the difference at Omega = 20 is below 1e-3 and falls by 3 to 5 times from Omega = 10"
            .into(),
        measured: named(&[("difference_omega_10", d10), ("difference_omega_20", d20), ("ratio", ratio)]),
        deviation: Some(d20),
        deviation_is: "|mu/mu0 on the system - the stiff mu/mu0| at K/kx = 0.05, Omega = 20".into(),
        location: "flat punch, vbar 0.3, du/u0 0.5, zeta 0.1".into(),
        verdict: if d20 < 1e-3 && (3.0..=5.0).contains(&ratio) { Verdict::Holds } else { Verdict::Wrong },
    }
}

/// Near resonance the critical velocity can vanish: friction stays reduced
/// beyond `vbar = 1`, where a stiff system has none.
pub(super) fn resonance_removes_critical_velocity() -> Claim {
    let (below, at, above) = (mu(1.5, 1.0, 0.5, 0.05), mu(1.5, 1.0, 1.0, 0.05), mu(1.5, 1.0, 1.41, 0.05));
    Claim {
        claim: "Part II: resonance and the critical velocity".into(),
        seed_says: "in a resonant case the critical velocity (above which oscillation no longer reduces friction) \
                    can vanish"
            .into(),
        exact_gives: format!(
            "at vbar = 1.5 (a stiff system: mu/mu0 = 1) on K/kx = 1, zeta 0.05: mu/mu0 = {at:.4} at Omega = 1 (below \
             the stick resonance sqrt(2)), {below:.4} at 0.5, {above:.4} at 1.41"
        ),
        criterion: "holds if mu/mu0 < 0.9 at vbar 1.5 for some frequency ratio through the resonance".into(),
        measured: named(&[("mu_omega_0.5", below), ("mu_omega_1", at), ("mu_omega_1.41", above)]),
        deviation: Some(1.0 - at),
        deviation_is: "the reduction 1 - mu/mu0 left at vbar = 1.5, Omega = 1".into(),
        location: "flat punch, vbar 1.5, du/u0 0.5, K/kx 1, zeta 0.05".into(),
        verdict: if at < 0.9 { Verdict::Holds } else { Verdict::Wrong },
    }
}

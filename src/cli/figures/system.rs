//! The flat punch on a tribometer with mass and stiffness
//! ([`fricosc::system`]): friction against the velocity through resonance.

use super::{figure, grid, Curve, Figure, XAxis};
use crate::error::Result;

/// `kappa`, `zeta` and `du/u0` of the resonance figure.
pub const RESONANCE: (f64, f64, f64) = (1.0, 0.05, 0.5);
/// Its frequency ratios `Omega`: massless, below, at and above the stick's
/// natural frequency `sqrt(1 + kappa)` (1.414).
pub const OMEGAS: [f64; 5] = [0.0, 0.5, 1.0, 1.41, 2.0];

/// `mu/mu0` against `vbar` for the frequency ratios [`OMEGAS`] (the stated
/// start's attractor at every point; all of period 1 here).
pub(super) fn resonance() -> Result<Figure> {
    let (kappa, zeta, amp) = RESONANCE;
    let xs = grid(0.025, 2.0, 80);
    let mut curves = vec![];
    for om in OMEGAS {
        let sys = fricosc::system::System::new(kappa, om, zeta)?;
        let points = xs
            .iter()
            .map(|&v| {
                Ok([v, fricosc::Shape::flat().ratio(&fricosc::Conditions::vbar(v, amp)?.with_system(sys))?.mu_ratio])
            })
            .collect::<Result<Vec<_>>>()?;
        curves.push(Curve::new(format!("exact, Ω = {om}"), "exact", Some(om), points));
    }
    let mut f = figure(
        "system-resonance",
        &format!(
            "Flat punch on a system with mass and stiffness (K/k_x = {kappa}, damping ratio {zeta}, Δu/u0 = {amp}): \
             friction against the velocity for excitation frequencies through the stick resonance ω_c √2"
        ),
        XAxis::Vbar,
        [0.0, 2.0, 0.0, 1.05],
        curves,
    );
    f.family = "frequency_ratio".into();
    f.notes = vec![format!("K/k_{{x}} = {kappa}"), format!("ζ = {zeta}")];
    Ok(f)
}

/// `vbar`, `du/u0` and `zeta` of the frequency figure.
pub const FREQUENCY: (f64, f64, f64) = (0.3, 0.5, 0.05);
/// Its stiffness ratios `kappa = K/kx` (stick resonances at `Omega = sqrt(1 + kappa)`:
/// 1.12, 1.41, 2.24, 4.12).
pub const KAPPAS: [f64; 4] = [0.25, 1.0, 4.0, 16.0];

/// `mu/mu0` against the frequency ratio `Omega` for the stiffness ratios
/// [`KAPPAS`]: the reduction vanishes (`mu = 1`) around each stick resonance,
/// with weaker features at its sub-harmonics. The response's regime (the
/// attractor's period) is in the notes.
pub(super) fn frequency() -> Result<Figure> {
    let (vbar, amp, zeta) = FREQUENCY;
    let omegas = grid(0.0, 3.0, 121);
    let c = fricosc::Conditions::vbar(vbar, amp)?;
    let mut curves = vec![];
    let mut other = vec![];
    for kappa in KAPPAS {
        let mut points = vec![];
        for &om in &omegas {
            let sys = fricosc::system::System::new(kappa, om, zeta)?;
            let r = crate::cmd::system_report(&fricosc::Shape::flat(), &c.with_system(sys))?;
            if r.period != Some(1) {
                other.push(format!("K/k_{{x}} {kappa}, Ω {om}: period {:?}", r.period));
            }
            points.push([om, r.mu_ratio]);
        }
        let label = format!("exact, K/kx = {kappa}");
        curves.push(Curve { label, kind: "exact".into(), equation: None, amp: Some(kappa), points });
    }
    let mut f = figure(
        "system-frequency",
        &format!(
            "Flat punch on a system with mass and stiffness (v̄ = {vbar}, Δu/u0 = {amp}, damping ratio {zeta}): \
             friction against the excitation frequency for several system stiffnesses; the reduction vanishes \
             around each stick resonance Ω = √(1 + K/k_x)"
        ),
        XAxis::FrequencyRatio,
        [0.0, 3.0, 0.0, 1.05],
        curves,
    );
    f.family = "system_stiffness".into();
    f.notes = vec![format!("v̄ = {vbar}"), format!("ζ = {zeta}")];
    f.notes.push(if other.is_empty() { "period 1 throughout".into() } else { other.join("; ") });
    Ok(f)
}

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
                Ok([
                    v,
                    fricosc::system::solve(&fricosc::Shape::flat(), &fricosc::Conditions::vbar(v, amp)?, &sys)?
                        .mu_ratio,
                ])
            })
            .collect::<Result<Vec<_>>>()?;
        curves.push(Curve {
            label: format!("exact, Ω = {om}"),
            kind: "exact".into(),
            equation: None,
            amp: Some(om),
            points,
        });
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

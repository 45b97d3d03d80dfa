//! The figures of oscillation across the sliding direction
//! (`Conditions::with_transverse`), and the three directions compared.

use super::{approx, figure, grid, Curve, Figure, XAxis};
use crate::error::Result;
use fricosc::plane::Transverse;
use fricosc::Shape;

/// The transverse amplitudes `W = dy/l` of the pure-transverse figure.
pub const TRANSVERSE_AMPS: [f64; 5] = [0.5, 0.9, 2.0, 5.0, 20.0];
/// The sideways-force figure's sliding velocity `vhat` and normal amplitude.
pub const SIDEWAYS: (f64, f64) = (0.3, 0.5);
/// Its transverse amplitudes.
pub const SIDEWAYS_WS: [f64; 2] = [1.0, 2.0];

/// The comparison of the three directions at one physical amplitude `d`:
/// `(d/u0, kx/kz, mu0)`, so that `d/l = (d/u0) (kx/kz)/mu0` in pre-slip lengths.
pub const DIRECTIONS: (f64, f64, f64) = (0.5, 0.8, 0.3);

/// `(mu_ratio, transverse_ratio)` of the flat punch.
fn plane(vhat: f64, amp: f64, w: f64, psi: f64) -> Result<(f64, f64)> {
    let c = fricosc::Conditions::vhat(vhat, amp)?.with_transverse(Transverse::new(w, psi)?);
    let e = Shape::flat().evaluate(&c)?;
    Ok((e.ratio.mu_ratio, e.transverse_ratio.unwrap_or(0.0)))
}

/// Pure transverse oscillation against `vhat/W` with the rigid limit
/// `1/AGM(1, sqrt(1 + (W/vhat)^2))`; the sideways force and the friction
/// against the transverse phase under normal oscillation too.
pub(super) fn plane_figures() -> Result<Vec<Figure>> {
    let xs = grid(0.02, 2.0, 100);
    let mut c = vec![];
    for &w in &TRANSVERSE_AMPS {
        let points = xs.iter().map(|&x| Ok([x, plane(x * w, 0.0, w, 0.0)?.0])).collect::<Result<Vec<_>>>()?;
        c.push(Curve::new(format!("exact, W = {w}"), "exact", Some(w), points));
    }
    c.push(approx("rigid limit, 1/AGM(1, √(1 + (W/v̂)²))", None, &xs, |x| fricosc::stepper::rigid_limit(1.0 / x)));
    let mut across = figure(
        "transverse-flat",
        "Oscillation across the sliding direction, flat punch: exact for Δy/l = 0.5 to 20 and the rigid limit; \
         below one pre-slip length static friction survives as √(1 - W²), above it friction falls with the velocity",
        XAxis::TransverseRatio,
        [0.0, 2.0, 0.0, 1.05],
        c,
    );
    across.family = "transverse_amp".into();
    let (vhat, amp) = SIDEWAYS;
    let phases = grid(0.0, std::f64::consts::TAU, 91);
    let mut c = vec![];
    for &w in &SIDEWAYS_WS {
        let values = phases.iter().map(|&p| plane(vhat, amp, w, p)).collect::<Result<Vec<_>>>()?;
        let along = phases.iter().zip(&values).map(|(&p, v)| [p, v.0]).collect();
        let side = phases.iter().zip(&values).map(|(&p, v)| [p, v.1]).collect();
        c.push(Curve::new(format!("along, W = {w}"), "exact", Some(w), along));
        // Exact too: drawn dashed, its legend entry the quantity.
        c.push(Curve {
            label: format!("sideways, W = {w}"),
            kind: "exact".into(),
            equation: Some("across, <f_y>/<B>".into()),
            amp: Some(w),
            points: side,
        });
    }
    let mut sideways = figure(
        "transverse-phase",
        &format!(
            "Normal and transverse oscillation, flat punch at v\u{302} = {vhat}, Δu/u0 = {amp}: friction along the \
             sliding direction (solid) and the mean force across it (dashed) against the transverse phase ψ"
        ),
        XAxis::TransversePhase,
        [0.0, std::f64::consts::TAU, -1.05, 1.05],
        c,
    );
    sideways.family = "transverse_amp".into();
    Ok(vec![across, sideways, directions(&Shape::flat(), 100)?, directions(&Shape::parabolic(), 40)?])
}

/// Friction against `vhat` under an oscillation of one physical amplitude
/// ([`DIRECTIONS`]) normal to the plane, along the sliding direction and
/// across it, on `shape` (`n` velocities).
fn directions(shape: &Shape, n: usize) -> Result<Figure> {
    use rayon::prelude::*;
    let (d, stiffness, mu0) = DIRECTIONS;
    let a = d * stiffness / mu0;
    let xs = grid(0.02, 3.0, n);
    let curve = |label: String, at: &(dyn Fn(f64) -> fricosc::Result<fricosc::Conditions> + Sync)| -> Result<Curve> {
        let points = xs
            .par_iter()
            .map(|&x| Ok([x, shape.evaluate(&at(x)?)?.ratio.mu_ratio]))
            .collect::<fricosc::Result<Vec<_>>>()?;
        // Each its own colour and legend entry (no family of amplitudes).
        Ok(Curve { label, kind: "exact".into(), equation: None, amp: None, points })
    };
    let curves = vec![
        curve(format!("normal, Δu/u0 = {d}"), &|x| fricosc::Conditions::vhat(x, d))?,
        curve(format!("along, Δx/l = {a:.3}"), &|x| fricosc::Conditions::vhat(x, 0.0)?.with_tangential(a, 0.0))?,
        curve(format!("across, Δy/l = {a:.3}"), &|x| {
            Ok(fricosc::Conditions::vhat(x, 0.0)?.with_transverse(Transverse::new(a, 0.0)?))
        })?,
    ];
    Ok(figure(
        &format!("directions-{}", shape.name()),
        &format!(
            "One amplitude Δ = {d} u0 in each direction ({shape}, k_x/k_z = {stiffness}, μ0 = {mu0}, so Δ/l = {a:.3}): \
             friction against the sliding velocity under normal, in-direction and transverse oscillation",
            shape = shape.name()
        ),
        XAxis::Vhat,
        [0.0, 3.0, 0.0, 1.05],
        curves,
    ))
}

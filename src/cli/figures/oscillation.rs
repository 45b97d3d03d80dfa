//! The figures beyond the seed: oscillation in the sliding direction
//! (`Conditions::with_tangential`), alone and with the normal oscillation.

use super::{approx, figure, grid, Curve, Figure, XAxis};
use crate::error::Result;
use fricosc::Shape;

/// The tangential amplitudes of the pure-tangential figures.
pub const TANGENTIAL_AMPS: [f64; 6] = [0.5, 1.0, 2.0, 5.0, 20.0, 100.0];
/// The combined-oscillation figures' sliding velocity `vhat` and normal amplitude.
pub const COMBINED: (f64, f64) = (0.3, 1.5);
/// The tangential amplitudes of the phase figure.
pub const COMBINED_TS: [f64; 4] = [0.5, 1.0, 2.0, 3.0];
/// The tangential amplitude of the regime map.
pub const MAP_T: f64 = 2.0;

/// `mu_macro/mu0` under oscillation, in the sliding direction and `across` it (the solver's value).
pub(super) fn combined_mu(
    shape: &Shape,
    vhat: f64,
    amp: f64,
    t: f64,
    phase: f64,
    across: Option<fricosc::plane::Transverse>,
) -> Result<f64> {
    let c = fricosc::Conditions::vhat(vhat, amp)?.with_tangential(t, phase)?;
    Ok(shape.ratio(&across.map_or(c, |w| c.with_transverse(w)))?.mu_ratio)
}

/// The figures beyond the seed (README: oscillation in the sliding direction): pure
/// tangential oscillation against `vhat/T` with the rigid-body law (flat punch
/// and paraboloid), combined oscillation against the phase, and the flat
/// punch's regime map over phase and normal amplitude.
pub(super) fn oscillation_figures() -> Result<Vec<Figure>> {
    let mut figs = vec![];
    let xs = grid(0.0, 1.2, 121);
    for (shape, name, what) in
        [(Shape::flat(), "tangential-flat", "flat punch"), (Shape::parabolic(), "tangential-parabolic", "paraboloid")]
    {
        let mut c = vec![];
        for &t in &TANGENTIAL_AMPS {
            let points = xs
                .iter()
                .map(|&x| Ok([x, combined_mu(&shape, x * t, 0.0, t, 0.0, None)?]))
                .collect::<Result<Vec<_>>>()?;
            c.push(Curve::new(format!("exact, T = {t}"), "exact", Some(t), points));
        }
        c.push(approx("rigid body, (2/π) arcsin", None, &xs, |x| 2.0 / std::f64::consts::PI * x.min(1.0).asin()));
        let mut f = figure(
            name,
            &format!(
                "Oscillation in the sliding direction, {what}: exact for Δx/l = 0.5 to 100, and the rigid-body law \
                 (2/π) arcsin(v0/(ω Δx)) they tend to"
            ),
            XAxis::SlidingRatio,
            [0.0, 1.2, 0.0, 1.05],
            c,
        );
        f.family = "tangential_amp".into();
        figs.push(f);
    }
    // Against the phase: the friction turns negative (the ratchet).
    let (vhat, amp) = COMBINED;
    let phases = grid(0.0, std::f64::consts::TAU, 181);
    let mut c = vec![];
    for &t in &COMBINED_TS {
        let points = phases
            .iter()
            .map(|&p| Ok([p, combined_mu(&Shape::flat(), vhat, amp, t, p, None)?]))
            .collect::<Result<Vec<_>>>()?;
        c.push(Curve::new(format!("exact, T = {t}"), "exact", Some(t), points));
    }
    let mut f = figure(
        "combined-phase",
        &format!(
            "Normal and tangential oscillation, flat punch: friction against the phase at v\u{302} = {vhat}, \
             Δu/u0 = {amp}; below 0 the oscillations push the punch forward"
        ),
        XAxis::Phase,
        [0.0, std::f64::consts::TAU, -1.05, 1.05],
        c,
    );
    f.family = "tangential_amp".into();
    figs.push(f);
    figs.push(regime_map()?);
    Ok(figs)
}

/// The flat punch's regimes over phase and normal amplitude at `vhat` of
/// [`COMBINED`] and `T` = [`MAP_T`]: one marker per grid point, coloured by
/// whether the contact is kept and which way the spring slips, and the line
/// where `mu_macro` changes sign.
fn regime_map() -> Result<Figure> {
    use fricosc::spring::{StopKind, Touch};
    let (vhat, t) = (COMBINED.0, MAP_T);
    let classes = [
        "contact kept, slips forward",
        "contact kept, slips both ways",
        "jumping, slips forward",
        "jumping, slips both ways",
    ];
    let mut points: Vec<Vec<[f64; 2]>> = vec![vec![]; classes.len()];
    let phases = grid(0.0, std::f64::consts::TAU, 61);
    let amps = grid(0.0, 3.0, 41);
    let mu = |amp: f64, p: f64| -> Result<(f64, usize)> {
        let c = fricosc::Conditions::vhat(vhat, amp)?.with_tangential(t, p)?;
        let fricosc::Report::Tangential(r) = Shape::flat().report(&c)? else {
            return Err(crate::error::Error::Internal { what: "a tangential report without its spring".into() });
        };
        let class = r.result.spring.map_or(0, |s| {
            let both = s.phases.iter().any(|q| q.kind == StopKind::Backward && q.end > q.start);
            usize::from(both) + if s.contact == Touch::Jumping { 2 } else { 0 }
        });
        Ok((r.result.ratio.mu_ratio, class))
    };
    for &p in &phases {
        for &a in &amps {
            let (_, k) = mu(a, p)?;
            points[k].push([p, a]);
        }
    }
    // mu = 0: sign changes along the amplitude and along the phase, refined by bisection.
    let mut zero = vec![];
    let sign_changes = |xs: &[f64], f: &dyn Fn(f64) -> Result<f64>| -> Result<Vec<f64>> {
        let mut out = vec![];
        // Each grid value once (a window's end is the next one's start).
        let negative = xs.iter().map(|&x| Ok(f(x)? < 0.0)).collect::<Result<Vec<bool>>>()?;
        for (w, n) in xs.windows(2).zip(negative.windows(2)) {
            let (mut lo, mut hi, neg) = (w[0], w[1], n[0]);
            if n[1] == neg {
                continue;
            }
            for _ in 0..40 {
                let m = 0.5 * (lo + hi);
                if (f(m)? < 0.0) == neg {
                    lo = m;
                } else {
                    hi = m;
                }
            }
            out.push(0.5 * (lo + hi));
        }
        Ok(out)
    };
    for &p in &grid(0.0, std::f64::consts::TAU, 361) {
        zero.extend(sign_changes(&grid(0.0, 3.0, 61), &|a| Ok(mu(a, p)?.0))?.into_iter().map(|a| [p, a]));
    }
    for &a in &grid(0.0, 3.0, 241) {
        zero.extend(
            sign_changes(&grid(0.0, std::f64::consts::TAU, 121), &|p| Ok(mu(a, p)?.0))?.into_iter().map(|p| [p, a]),
        );
    }
    let mut curves: Vec<Curve> = classes
        .iter()
        .zip(points)
        .filter(|(_, pts)| !pts.is_empty())
        .map(|(name, pts)| Curve::new((*name).into(), "regime", None, pts))
        .collect();
    curves.push(Curve::new("μ_{macro} = 0 (< 0 on the side of φ = 1)".into(), "sign change", None, zero));
    let mut f = figure(
        "combined-regimes",
        &format!(
            "Normal and tangential oscillation, flat punch: regimes over phase and normal amplitude at \
             v\u{302} = {vhat}, Δx/l = {t}, and where the friction changes sign"
        ),
        XAxis::Phase,
        [0.0, std::f64::consts::TAU, 0.0, 3.0],
        curves,
    );
    f.y_label = "oscillation amplitude Δu_{z}/u_{z0}".into();
    Ok(f)
}

/// `fricosc plot --phase LIST`: `mu/mu0` against the phase of the tangential
/// oscillation at one `vhat` and `T = t`, one curve per amplitude; `vhat`, `T`
/// and the range of phases in the title.
///
/// # Errors
/// Bad inputs (named), fewer than two phases, the size limits of a plot.
pub fn against_phase(shape: &Shape, amps: &[f64], vhat: f64, t: f64, phases: &[f64]) -> Result<Figure> {
    super::check_family(amps, phases.len(), "phases")?;
    let (xs, lo, hi) = super::span(phases, "phase", "phases")?;
    let mut curves = vec![];
    for (i, &a) in amps.iter().enumerate() {
        if amps[..i].contains(&a) {
            continue;
        }
        let points =
            xs.iter().map(|&p| Ok([p, combined_mu(shape, vhat, a, t, p, None)?])).collect::<Result<Vec<_>>>()?;
        curves.push(Curve::new(format!("exact, du/u0 = {a}"), "exact", Some(a), points));
    }
    let negative = curves.iter().flat_map(|c| &c.points).any(|p| p[1] < 0.0);
    let title =
        format!("{}: mu/mu0 against the phase at vhat = {vhat}, tangential oscillation dx/l = {t}", shape.name());
    let mut f = figure("plot", &title, XAxis::Phase, [lo, hi, if negative { -1.05 } else { 0.0 }, 1.05], curves);
    f.notes = vec![format!("v\u{302} = {vhat}"), format!("Δx/l = {t}")];
    Ok(f)
}

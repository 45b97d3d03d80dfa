//! `fricosc figures`: the seed's Figs. 3, 4, 5 (with its inset), 7 and 8, exact,
//! with the seed's approximations on each (dashed), as JSON, CSV and SVG.
//! Every exact point is the solver's value ([`fricosc::Shape::evaluate`]).

use crate::chart::{self, Axis, Chart, Dash, Key, Rule, Series, Style};
use crate::cmd::emit;
use crate::error::{Error, Result};
use clap::Args;
use fricosc::seed::Approximation::{
    Eq11, Eq12, Eq16, Eq17, Eq21Slope, Eq21SlopePrinted, Eq22Corrected, Eq22Printed, Eq27,
};
use fricosc::Shape;
use serde::Serialize;
mod oscillation;
mod system;
pub use oscillation::{against_phase, COMBINED, COMBINED_TS, MAP_T, TANGENTIAL_AMPS};
use oscillation::{combined_mu, oscillation_figures};
mod plane;
pub use plane::{DIRECTIONS, SIDEWAYS, SIDEWAYS_WS, TRANSVERSE_AMPS};
pub use system::{FREQUENCY, KAPPAS, OMEGAS, RESONANCE};

/// One curve of a figure.
#[derive(Debug, Clone, Serialize)]
pub struct Curve {
    /// Legend label (plain text).
    pub label: String,
    /// `exact` (the solver's values) or `approximation` (one of the seed's formulas).
    pub kind: String,
    /// The seed's equation an approximation evaluates (`eq. 11`, ...).
    pub equation: Option<String>,
    /// The family's parameter, where the curve has one: `du/u0`, or `dx/l` where
    /// the figure's `family` is `tangential_amp`.
    pub amp: Option<f64>,
    /// `(x, y)` points.
    pub points: Vec<[f64; 2]>,
}

impl Curve {
    /// A curve of `kind` without an equation.
    pub fn new(label: String, kind: &str, amp: Option<f64>, points: Vec<[f64; 2]>) -> Curve {
        Curve { label, kind: kind.into(), equation: None, amp, points }
    }
}

/// What a figure's horizontal axis is.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum XAxis {
    /// `vbar` (eq. 3).
    Vbar,
    /// `vhat = vbar amp` (eq. 15).
    Vhat,
    /// The amplitude `du/u0`.
    Amp,
    /// `vhat/T = v0/(omega dx)`: sliding over the tangential oscillation's velocity amplitude.
    SlidingRatio,
    /// The phase of the tangential oscillation against the normal one (radians).
    Phase,
    /// The frequency ratio `Omega = omega / sqrt(kx/m)` (a system with mass).
    FrequencyRatio,
    /// `vhat/W = v0/(omega dy)`: sliding over the transverse oscillation's velocity amplitude.
    TransverseRatio,
    /// The phase `psi` of the transverse oscillation against the normal one (radians).
    TransversePhase,
}

/// One figure.
#[derive(Debug, Clone, Serialize)]
pub struct Figure {
    /// File stem (`fig3`, `fig5-inset`, ...).
    pub name: String,
    /// Caption (the SVG's title; README sets it below the picture).
    pub title: String,
    /// The horizontal axis' quantity.
    pub x: XAxis,
    /// Axis label (markup of [`crate::chart`]: `_{}` subscripts).
    pub x_label: String,
    /// Axis label.
    pub y_label: String,
    /// Axis ranges `[x0, x1, y0, y1]`.
    pub range: [f64; 4],
    /// Draw the critical amplitude `du/u0 = 1` bold (where the seed does).
    pub bold_critical: bool,
    /// What the curves' `amp` is: `amp` (`du/u0`) or `tangential_amp` (`dx/l`).
    pub family: String,
    /// Curves.
    pub curves: Vec<Curve>,
    /// What the curves hold fixed, drawn below the key (e.g. `Δx/l = 1.5`).
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub notes: Vec<String>,
}

/// Axis label of `vbar`.
pub const VBAR_LABEL: &str = "normalized velocity v\u{304} (eq. 3)";
/// Axis label of `vhat`.
pub const VHAT_LABEL: &str = "normalized velocity v\u{302} (eq. 15)";
/// Axis label of `mu_macro/mu0`.
pub const MU_LABEL: &str = "friction coefficient μ_{macro}/μ_{0}";
/// Legend heading of an amplitude family.
pub const AMP_LABEL: &str = "Δu_{z}/u_{z0}";
/// Legend heading of a tangential-amplitude family (pre-slip lengths `l`).
pub const T_LABEL: &str = "Δx/l";
/// Legend heading of a family of frequency ratios `Omega = omega / sqrt(kx/m)`.
pub const OMEGA_LABEL: &str = "ω/ω_{c}";
/// The legend heading of a family over the system stiffness ratio.
pub const KAPPA_LABEL: &str = "K/k_{x}";

fn figure(name: &str, title: &str, x: XAxis, range: [f64; 4], curves: Vec<Curve>) -> Figure {
    let x_label = match x {
        XAxis::Vbar => VBAR_LABEL,
        XAxis::Vhat => VHAT_LABEL,
        XAxis::Amp => "oscillation amplitude Δu_{z}/u_{z0}",
        XAxis::SlidingRatio => "sliding over oscillation velocity v_{0}/(ω Δx)",
        XAxis::Phase => "phase φ of the tangential oscillation (rad)",
        XAxis::FrequencyRatio => "frequency ratio Ω = ω/√(k_{x}/m)",
        XAxis::TransverseRatio => "sliding over transverse oscillation velocity v_{0}/(ω Δy)",
        XAxis::TransversePhase => "phase ψ of the transverse oscillation (rad)",
    };
    Figure {
        name: name.into(),
        title: title.into(),
        x,
        x_label: x_label.into(),
        y_label: MU_LABEL.into(),
        range,
        bold_critical: false,
        family: "amp".into(),
        curves,
        notes: vec![],
    }
}

/// A figure against `vhat` over both regimes, the critical amplitude bold between them (Figs. 4, 8).
fn against_vhat(name: &str, title: &str, curves: Vec<Curve>) -> Figure {
    let mut f = figure(name, title, XAxis::Vhat, [0.0, 2.0, 0.0, 1.05], curves);
    f.bold_critical = true;
    f
}

fn grid(x0: f64, x1: f64, n: usize) -> Vec<f64> {
    (0..n).map(|k| x0 + (x1 - x0) * k as f64 / (n - 1) as f64).collect()
}

/// The exact curve of `shape` at `amp` over `xs` (`vbar`, or `vhat` where
/// `vhat` is set; at `amp = 0` the value does not depend on the velocity).
fn exact(shape: &Shape, amp: f64, xs: &[f64], vhat: bool) -> Result<Curve> {
    let vbar_of = |x: f64| if vhat && amp > 0.0 { x / amp } else { x };
    let points = xs
        .iter()
        .map(|&x| fricosc::Conditions::vbar(vbar_of(x), amp).and_then(|c| shape.ratio(&c)).map(|r| [x, r.mu_ratio]))
        .collect::<fricosc::Result<Vec<_>>>()?;
    Ok(Curve::new(format!("exact, du/u0 = {amp}"), "exact", Some(amp), points))
}

fn approx(eq: &str, amp: Option<f64>, xs: &[f64], f: impl Fn(f64) -> f64) -> Curve {
    let label = match amp {
        Some(a) => format!("{eq}, du/u0 = {a}"),
        None => eq.to_string(),
    };
    Curve {
        label,
        kind: "approximation".into(),
        equation: Some(eq.into()),
        amp,
        points: xs.iter().map(|&x| [x, f(x)]).collect(),
    }
}

/// Build all figures.
///
/// Which approximation is drawn where follows the seed: eq. 11 on Fig. 3 (no
/// contact loss), eq. 12 on its inset (`du/u0 = 1`), eq. 16 (eq. 11 in `vhat`)
/// for the amplitudes up to 1 and eq. 17 (eq. 11 at the critical amplitude,
/// the seed's rough rule for jumping) beyond it on Fig. 4, eq. 17 on Fig. 5,
/// eqs. 21 and 22 (as printed and corrected) on Fig. 5's inset, eq. 27 (the
/// universal form, for both regimes) on Figs. 7 and 8; eq. 28 differs from
/// eq. 27 by at most 1.55 % of mu0 (see `claims`), too little to tell apart at
/// print size, so it is left out. The line at `du/u0 = 0` (sliding without
/// oscillation, mu = mu0) is drawn where the seed draws it (Figs. 3, 4, 7, 8),
/// and the critical amplitude `du/u0 = 1` bold where it separates the two
/// regimes (Figs. 4 and 8).
pub fn build() -> Result<Vec<Figure>> {
    let mut figs = flat_figures()?;
    figs.extend(jumping_figures()?);
    figs.extend(oscillation_figures()?);
    figs.extend(plane::plane_figures()?);
    figs.push(system::resonance()?);
    figs.push(system::frequency()?);
    Ok(figs)
}

/// The seed's amplitudes without jumping (Figs. 3, 4, 7, 8).
const SMALL: [f64; 6] = [0.0, 0.2, 0.4, 0.6, 0.8, 1.0];
/// The seed's jumping amplitudes of Figs. 4 and 8.
const JUMPING: [f64; 5] = [1.2, 1.4, 1.6, 1.8, 2.0];

/// Figs. 3 (with its inset) and 4: the flat punch.
fn flat_figures() -> Result<Vec<Figure>> {
    let flat = Shape::flat();
    let vb = grid(0.0, 1.2, 241);
    let (small, jumping) = (SMALL, JUMPING);
    let mut figs = vec![];

    // Fig. 3: flat punch, no jumping, and eq. 11.
    let mut c = vec![];
    for &a in &small {
        c.push(exact(&flat, a, &vb, false)?);
        if a > 0.0 {
            c.push(approx("eq. 11", Some(a), &vb, |v| Eq11 { amp: a }.value(v)));
        }
    }
    figs.push(figure(
        "fig3",
        "Fig. 3: flat punch without jumping, exact and eq. 11",
        XAxis::Vbar,
        [0.0, 1.2, 0.0, 1.05],
        c,
    ));

    // Fig. 3 inset: amp = 1 at low velocity, eq. 12.
    let vs = grid(0.0, 0.1, 201);
    figs.push(figure(
        "fig3-inset",
        "Fig. 3 inset: flat punch at du/u0 = 1, low velocity, exact and eq. 12",
        XAxis::Vbar,
        [0.0, 0.1, 0.0, 0.3],
        vec![exact(&flat, 1.0, &vs, false)?, approx("eq. 12", Some(1.0), &vs, |v| Eq12 { amp: 1.0 }.value(v))],
    ));

    // Fig. 4: flat punch against vhat = vbar amp; eq. 16 up to amp 1, eq. 17 beyond.
    let vh = grid(0.0, 2.0, 201);
    let mut c = vec![];
    for &a in small.iter().chain(&jumping) {
        c.push(exact(&flat, a, &vh, true)?);
        if a > 1.0 {
            c.push(approx("eq. 17", Some(a), &vh, |x| Eq17.value(x / a)));
        } else if a > 0.0 {
            c.push(approx("eq. 16", Some(a), &vh, |x| Eq16 { amp: a }.value(x)));
        }
    }
    figs.push(against_vhat(
        "fig4",
        "Fig. 4: flat punch against v\u{302}, exact, eq. 16 (no jumping) and eq. 17 (jumping)",
        c,
    ));

    Ok(figs)
}

/// Fig. 5 (with its inset), Figs. 7 and 8: the flat punch jumping, the paraboloid.
fn jumping_figures() -> Result<Vec<Figure>> {
    let (flat, parabolic) = (Shape::flat(), Shape::parabolic());
    let vb = grid(0.0, 1.2, 241);
    let vh = grid(0.0, 2.0, 201);
    let (small, jumping) = (SMALL, JUMPING);
    let mut figs = vec![];
    // Fig. 5: jumping, and eq. 17.
    let mut c = vec![];
    for k in 0..=10 {
        let a = (10 + k) as f64 / 10.0;
        c.push(exact(&flat, a, &vb, false)?);
    }
    c.push(approx("eq. 17", None, &vb, |v| Eq17.value(v)));
    figs.push(figure(
        "fig5",
        "Fig. 5: flat punch, jumping, du/u0 = 1 to 2, exact and eq. 17",
        XAxis::Vbar,
        [0.0, 1.2, 0.0, 1.05],
        c,
    ));

    // Fig. 5 inset: the low-velocity slope against the amplitude.
    let aa = grid(1.0, 5.0, 161);
    let slope_exact: Vec<[f64; 2]> = aa.iter().map(|&a| [a, fricosc::seed::exact_slope(a)]).collect();
    let mut f = figure(
        "fig5-inset",
        "Fig. 5 inset: low-velocity slope against the amplitude, exact, eqs. 21 and 22 as printed and corrected",
        XAxis::Amp,
        [1.0, 5.0, 0.0, 3.5],
        vec![
            Curve::new("exact (the solver at v\u{304} = 10^{−10})".into(), "exact", None, slope_exact),
            approx("eq. 21 corrected", None, &aa, |a| Eq21Slope.value(a)),
            approx("eq. 21 as printed (π too small)", None, &aa, |a| Eq21SlopePrinted.value(a)),
            approx("eq. 22 corrected, π²/4", None, &aa, |a| Eq22Corrected.value(a)),
            approx("eq. 22 as printed, π/4", None, &aa, |a| Eq22Printed.value(a)),
        ],
    );
    f.y_label = "low-velocity slope μ_{macro}/(μ_{0} v\u{304})".into();
    figs.push(f);

    // Figs. 7 and 8: paraboloid, with eq. 27.
    let mut c = vec![];
    for &a in &small {
        let ms = parabolic.mu_static(a, fricosc::DEFAULT_TOL)?;
        c.push(exact(&parabolic, a, &vb, false)?);
        if a > 0.0 {
            c.push(approx("eq. 27", Some(a), &vb, |v| Eq27 { mu_static: ms }.value(v)));
        }
    }
    figs.push(figure("fig7", "Fig. 7: parabolic indenter, exact and eq. 27", XAxis::Vbar, [0.0, 1.2, 0.0, 1.05], c));
    let mut c = vec![];
    for &a in small.iter().chain(&jumping) {
        let ms = parabolic.mu_static(a, fricosc::DEFAULT_TOL)?;
        c.push(exact(&parabolic, a, &vh, true)?);
        if a > 0.0 {
            c.push(approx("eq. 27", Some(a), &vh, |x| Eq27 { mu_static: ms }.value(x / a)));
        }
    }
    figs.push(against_vhat("fig8", "Fig. 8: parabolic indenter against v\u{302}, exact and eq. 27", c));
    Ok(figs)
}

/// At most this many amplitudes in one [`user`] figure (so that neighbouring
/// colours stay apart: CIE76 difference 8 or more, checked by the tests).
pub const MAX_CURVES: usize = 12;
/// At most this many velocities per curve of a [`user`] figure.
pub const MAX_POINTS: usize = 100_000;

/// A figure of the user's own curves (`fricosc plot`): the exact `mu/mu0` of
/// `shape` at each amplitude over the velocities `xs` (`vbar`, or `vhat` where
/// `vhat` is set), in the style of the seed's figures.
pub fn user(shape: &Shape, amps: &[f64], xs: &[f64], vhat: bool) -> Result<Figure> {
    user_with(shape, amps, xs, vhat, (None, None), None)
}

/// [`user`], under an oscillation in the sliding direction `(T, phase)` where
/// given (velocities `vhat` then; the axis reaches down to -1 where `mu` does).
pub fn user_with(
    shape: &Shape,
    amps: &[f64],
    xs: &[f64],
    vhat: bool,
    (tangential, transverse): (Option<(f64, f64)>, Option<fricosc::plane::Transverse>),
    system: Option<&fricosc::system::System>,
) -> Result<Figure> {
    if tangential.is_some() && !vhat {
        return Err(Error::parse(
            "--tangential-amp",
            "give the velocities as --vhat (vbar = vhat/amp is undefined without normal oscillation)",
        ));
    }
    check_family(amps, xs.len(), "velocities")?;
    let what = if vhat { "vhat" } else { "vbar" };
    for &x in xs {
        // The conditions' own check and message of a velocity (and below, of an amplitude).
        if vhat {
            fricosc::Conditions::vhat(x, 0.0)?;
        } else {
            fricosc::Conditions::vbar(x, 0.0)?;
        }
    }
    // vbar = vhat / amp must be a number at every amplitude (the message names both).
    if let (true, Some(&top)) = (vhat, xs.iter().max_by(|a, b| a.total_cmp(b))) {
        for &a in amps.iter().filter(|&&a| a > 0.0) {
            fricosc::Conditions::vhat(top, a)?.as_vbar()?;
        }
    }
    let (xs, lo, hi) = span(xs, what, "velocities")?;
    let mut seen = vec![];
    let curves = amps
        .iter()
        .filter(|a| {
            let new = !seen.contains(*a);
            seen.push(**a);
            new
        })
        .map(|&a| match (tangential, transverse, system) {
            (_, _, Some(sys)) => on_system(shape, a, &xs, vhat, tangential, sys),
            (None, None, None) => exact(shape, a, &xs, vhat),
            (t, w, None) => {
                let (t, p) = t.unwrap_or((0.0, 0.0));
                let mu = |x: f64| combined_mu(shape, x, a, t, p, w);
                let points = xs.iter().map(|&x| Ok([x, mu(x)?])).collect::<Result<Vec<_>>>()?;
                Ok(Curve::new(format!("exact, du/u0 = {a}"), "exact", Some(a), points))
            }
        })
        .collect::<Result<Vec<_>>>()?;
    let (x, title) = if vhat { (XAxis::Vhat, "vhat") } else { (XAxis::Vbar, "vbar") };
    let negative = curves.iter().flat_map(|c| &c.points).any(|p| p[1] < 0.0);
    let mut title = format!("{}: mu/mu0 against {title}", shape.name());
    if let Some((t, p)) = tangential {
        title += &format!(", tangential oscillation dx/l = {t}, phase {p}");
    }
    if let Some(w) = transverse {
        title += &format!(", across dy/l = {}, phase {}", w.amp(), w.phase());
    }
    let mut f = figure("plot", &title, x, [lo, hi, if negative { -1.05 } else { 0.0 }, 1.05], curves);
    f.bold_critical = amps.len() > 1 && amps.contains(&1.0);
    if let Some((t, p)) = tangential {
        f.notes = vec![format!("Δx/l = {t}"), format!("φ = {p}")];
    }
    if let Some(sys) = system {
        f.title +=
            &format!(", on a system K/kx = {}, Ω = {}, ζ = {}", sys.stiffness(), sys.frequency_ratio(), sys.damping());
        let notes = [("K/k_{x}", sys.stiffness()), ("Ω", sys.frequency_ratio()), ("ζ", sys.damping())];
        f.notes.extend(notes.iter().map(|(n, v)| format!("{n} = {v}")));
    }
    Ok(f)
}

/// One amplitude's curve on a system ([`fricosc::Conditions::with_system`], the points on every core).
fn on_system(
    shape: &Shape,
    amp: f64,
    xs: &[f64],
    vhat: bool,
    tangential: Option<(f64, f64)>,
    sys: &fricosc::system::System,
) -> Result<Curve> {
    use rayon::prelude::*;
    let (t, p) = tangential.unwrap_or((0.0, 0.0));
    let bar = crate::progress::Bar::new(Some(xs.len() as u64), &format!("du/u0 = {amp}"));
    let points = xs
        .par_iter()
        .map(|&x| {
            bar.inc(1);
            let c = if vhat {
                fricosc::Conditions::vhat(x, amp)?.with_tangential(t, p)?
            } else {
                fricosc::Conditions::vbar(x, amp)?
            };
            Ok([x, shape.ratio(&c.with_system(*sys))?.mu_ratio])
        })
        .collect::<Result<Vec<_>>>()?;
    Ok(Curve::new(format!("exact, du/u0 = {amp}"), "exact", Some(amp), points))
}

/// The values of a plot's axis (option `--{option}`), sorted without repeats,
/// and their range: at least two different `what`.
fn span(xs: &[f64], option: &str, what: &str) -> Result<(Vec<f64>, f64, f64)> {
    let mut xs = xs.to_vec();
    xs.sort_by(f64::total_cmp);
    xs.dedup();
    match (xs.first(), xs.last()) {
        (Some(&lo), Some(&hi)) if hi > lo => Ok((xs, lo, hi)),
        _ => {
            Err(Error::Parse { context: format!("--{option}"), reason: format!("needs two different {what} or more") })
        }
    }
}

/// The limits of a `plot` (at most [`MAX_CURVES`] amplitudes, each `>= 0`, and
/// [`MAX_POINTS`] points of `what` a curve), checked before any work.
fn check_family(amps: &[f64], points: usize, what: &str) -> Result<()> {
    if amps.len() > MAX_CURVES {
        return Err(Error::TooLarge {
            what: "amplitudes in one plot".into(),
            count: amps.len() as u128,
            limit: MAX_CURVES as u128,
        });
    }
    if points > MAX_POINTS {
        return Err(Error::TooLarge {
            what: format!("{what} in one plot"),
            count: points as u128,
            limit: MAX_POINTS as u128,
        });
    }
    for &a in amps {
        fricosc::Conditions::vbar(0.0, a)?;
    }
    Ok(())
}

/// Most points of a `plot --overlay` file.
pub const MAX_OVERLAY: usize = 100_000;

/// Add another code's points `(vbar, amp, mu_ratio)` (or `(x, amp,
/// mu_ratio)` on the figure's own axis where `x_as_is`) to a `plot` figure,
/// one marker curve per amplitude (`kind` `yours`): drawn in the colour of the
/// plot's curve of that amplitude, grey where the plot has none.
///
/// # Errors
/// [`Error::TooLarge`] beyond [`MAX_OVERLAY`] points.
pub fn overlay(f: &mut Figure, rows: &[(f64, f64, f64)], x_as_is: bool, name: &str) -> Result<()> {
    if rows.len() > MAX_OVERLAY {
        return Err(Error::TooLarge {
            what: "points of --overlay".into(),
            count: rows.len() as u128,
            limit: MAX_OVERLAY as u128,
        });
    }
    let mut amps: Vec<f64> = rows.iter().map(|r| r.1).collect();
    amps.sort_by(f64::total_cmp);
    amps.dedup();
    let vhat = f.x == XAxis::Vhat;
    for a in amps {
        let x = |v: f64, amp: f64| if vhat && !x_as_is { v * amp } else { v };
        let points = rows.iter().filter(|r| r.1 == a).map(|&(v, amp, mu)| [x(v, amp), mu]).collect();
        f.curves.push(Curve::new(format!("{name}, du/u0 = {a}"), "yours", Some(a), points));
    }
    Ok(())
}

/// The house style for a family of curves over amplitudes, with approximations.
///
/// Every distinct amplitude gets one colour (black for `du/u0 = 0`, viridis in
/// order for the others); exact curves are solid (2 pt at the critical
/// amplitude where `bold_critical`), approximations dashed, a second
/// approximation dotted, a third dash-dotted. Curves without an amplitude get
/// the Okabe-Ito colours and their own legend entries.
pub fn chart(f: &Figure) -> Chart {
    // The family is the amplitudes of the solver's curves; overlaid points of
    // other amplitudes are grey.
    let mut amps: Vec<f64> = f.curves.iter().filter(|c| c.kind != "yours").filter_map(|c| c.amp).collect();
    amps.sort_by(f64::total_cmp);
    amps.dedup();
    let nonzero: Vec<f64> = amps.iter().copied().filter(|a| *a != 0.0).collect();
    let other = chart::Rgb(0x99, 0x99, 0x99);
    let color = |a: f64| match nonzero.iter().position(|x| *x == a) {
        Some(i) => chart::family_color(i, nonzero.len()),
        None if a == 0.0 && amps.contains(&0.0) => chart::BLACK,
        None => other,
    };
    let bold = |a: f64| if f.bold_critical && a == 1.0 { 2.0 } else { 1.0 };
    // The approximations' equations in order of appearance: dash patterns.
    let mut eqs: Vec<&str> = vec![];
    for e in f.curves.iter().filter_map(|c| c.equation.as_deref()) {
        if !eqs.contains(&e) {
            eqs.push(e);
        }
    }
    let dash = |c: &Curve| match c.equation.as_deref().and_then(|e| eqs.iter().position(|x| *x == e)) {
        None => Dash::Solid,
        Some(0) => Dash::Dashed,
        Some(1) => Dash::Dotted,
        Some(_) => Dash::DashDot,
    };
    let mut loners = 0;
    let mut series = vec![];
    for c in &f.curves {
        let (style, legend) = match c.amp {
            Some(a) if c.kind == "yours" => {
                (Style { color: color(a), dash: None, width: 1.0, marker: Some(chart::Marker::Circle) }, false)
            }
            Some(a) => (Style::dashed(color(a), dash(c)).width(if c.kind == "exact" { bold(a) } else { 1.0 }), false),
            None => {
                let color = chart::OKABE_ITO[loners % chart::OKABE_ITO.len()];
                // A map's tiles in the light colours (Okabe-Ito after black).
                let tile = chart::OKABE_ITO[(loners + 1) % chart::OKABE_ITO.len()];
                let s = match c.kind.as_str() {
                    // A map: markers only.
                    "regime" => Style { color: tile, dash: None, width: 1.0, marker: Some(chart::Marker::Square) },
                    "sign change" => {
                        Style { color: chart::BLACK, dash: None, width: 1.0, marker: Some(chart::Marker::Dot) }
                    }
                    _ => Style::dashed(color, dash(c)),
                };
                loners += usize::from(c.kind != "sign change");
                (s, true)
            }
        };
        series.push(Series {
            label: c.label.clone(),
            points: c.points.iter().map(|p| (p[0], p[1])).collect(),
            style,
            legend,
        });
    }
    let mut key = vec![];
    if !amps.is_empty() {
        key.push(Key::Heading(family_heading(f).into()));
        for &a in &amps {
            key.push(Key::Entry(Style::line(color(a)).width(bold(a)), crate::output::num(a)));
        }
        let grey = chart::Rgb(0x55, 0x55, 0x55);
        let family_eqs: Vec<&str> = eqs
            .iter()
            .copied()
            .filter(|e| f.curves.iter().any(|c| c.amp.is_some() && c.equation.as_deref() == Some(*e)))
            .collect();
        let yours = f.curves.iter().any(|c| c.kind == "yours");
        if !family_eqs.is_empty() || yours {
            key.push(Key::Heading(String::new()));
            key.push(Key::Entry(Style::line(grey), "exact".into()));
        }
        if yours {
            let dots = Style { color: grey, dash: None, width: 1.0, marker: Some(chart::Marker::Circle) };
            key.push(Key::Entry(dots, "yours".into()));
        }
        if !family_eqs.is_empty() {
            for e in family_eqs {
                let d = dash(f.curves.iter().find(|c| c.equation.as_deref() == Some(e)).expect("listed above"));
                key.push(Key::Entry(Style::dashed(grey, d), e.to_string()));
            }
        }
    }
    key.extend(f.notes.iter().enumerate().flat_map(|(i, n)| {
        // A blank line above the notes.
        (i == 0).then(|| Key::Heading(String::new())).into_iter().chain([Key::Heading(n.clone())])
    }));
    Chart {
        title: f.title.clone(),
        x: Axis::linear(&f.x_label, (f.range[0], f.range[1])),
        y: Axis::linear(&f.y_label, (f.range[2], f.range[3])),
        series,
        key,
        rules: rules(f),
    }
}

/// The legend's heading of a figure's family.
fn family_heading(f: &Figure) -> &'static str {
    match f.family.as_str() {
        "amp" => AMP_LABEL,
        "frequency_ratio" => OMEGA_LABEL,
        "system_stiffness" => KAPPA_LABEL,
        "transverse_amp" => "Δy/l",
        _ => T_LABEL,
    }
}

/// On a `mu/mu0` axis: a line at 1 (no reduction), and at 0 where the axis
/// reaches below it (where the friction changes sign).
fn rules(f: &Figure) -> Vec<Rule> {
    let ratio_axis = f.y_label == MU_LABEL;
    [(ratio_axis, 1.0), (ratio_axis && f.range[2] < 0.0, 0.0)]
        .into_iter()
        .filter(|r| r.0)
        .map(|(_, at)| Rule { horizontal: true, at })
        .collect()
}

impl crate::export::Report for Figure {
    /// Long format: `curve,kind,equation,amp,x,y` (`tangential_amp` for the
    /// figures whose family is the tangential amplitude).
    fn columns(&self) -> Vec<String> {
        ["curve", "kind", "equation", self.family.as_str(), "x", "y"].map(String::from).to_vec()
    }

    fn rows(&self) -> Vec<Vec<String>> {
        let n = crate::output::num;
        self.curves
            .iter()
            .flat_map(|c| {
                c.points.iter().map(move |p| {
                    vec![
                        c.label.clone(),
                        c.kind.to_string(),
                        c.equation.clone().unwrap_or_default(),
                        c.amp.map_or(String::new(), n),
                        n(p[0]),
                        n(p[1]),
                    ]
                })
            })
            .collect()
    }

    fn svg(&self) -> Option<Result<String>> {
        Some(Ok(chart(self).svg()))
    }
}

/// Write every figure as `name.json`, `name.csv`, `name.svg` and `name.png` into `dir`.
pub fn write_all(out: &crate::outdir::OutDir) -> Result<Vec<String>> {
    let mut names = vec![];
    for f in build()? {
        use crate::export::{export, Format};
        for (ext, format) in [("json", Format::Json), ("csv", Format::Csv), ("svg", Format::Svg)] {
            out.write(&format!("{}.{ext}", f.name), export(&f, format)?.as_bytes())?;
        }
        let png =
            chart::png(&chart(&f).svg()).map_err(|e| Error::Internal { what: format!("rendering the PNG: {e}") })?;
        out.write(&format!("{}.png", f.name), &png)?;
        names.push(f.name);
    }
    Ok(names)
}

#[derive(Args)]
pub struct FiguresArgs {
    /// Output directory (created if missing).
    #[arg(long)]
    pub out: String,
}

/// Write every figure into `--out`.
pub fn run(a: FiguresArgs) -> Result<()> {
    let out = a.out.as_str();
    let dir = crate::outdir::OutDir::open("--out", out)?;
    let names = crate::figures::write_all(&dir)?;
    emit(&format!("wrote {} figures to {out}: {}\n", names.len(), names.join(", ")))
}

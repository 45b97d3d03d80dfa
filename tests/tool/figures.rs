//! The figures: exact curves are the solver's values (no second implementation),
//! each approximation is drawn only where the seed uses it, and every drawing
//! parses, tells its curves apart, names its axes' symbols and renders to a PNG
//! of the stated size.
use fricosc::Shape;
use fricosc_cli::chart::{self, Rgb};
use fricosc_cli::figures::{build, chart, Figure, XAxis};

/// The figures, built once for every test here (the paraboloid's across the
/// sliding direction take seconds).
fn figures() -> &'static [Figure] {
    static FIGURES: std::sync::OnceLock<Vec<Figure>> = std::sync::OnceLock::new();
    FIGURES.get_or_init(|| build().unwrap())
}

#[test]
fn exact_curves_equal_the_solver_and_every_figure_is_there() {
    let figs = figures();
    let names: Vec<&str> = figs.iter().map(|f| f.name.as_str()).collect();
    assert_eq!(
        names,
        [
            "fig3",
            "fig3-inset",
            "fig4",
            "fig5",
            "fig5-inset",
            "fig7",
            "fig8",
            "tangential-flat",
            "tangential-parabolic",
            "combined-phase",
            "combined-regimes",
            "transverse-flat",
            "transverse-phase",
            "directions-flat",
            "directions-parabolic",
            "system-resonance",
            "system-frequency"
        ]
    );
    for f in figs.iter().filter(|f| f.name.starts_with("fig")) {
        let shape =
            if f.name.starts_with("fig7") || f.name.starts_with("fig8") { Shape::parabolic() } else { Shape::flat() };
        for c in f.curves.iter().filter(|c| c.kind == "exact") {
            let Some(amp) = c.amp else { continue };
            for p in c.points.iter().step_by(7) {
                let vbar = if f.x == XAxis::Vhat && amp > 0.0 { p[0] / amp } else { p[0] };
                assert_eq!(
                    p[1],
                    crate::common::eval(&shape, vbar, amp).unwrap().ratio.mu_ratio,
                    "{} {}",
                    f.name,
                    c.label
                );
            }
        }
    }
    // The inset's exact slope is the claims' one, and the corrected eq. 21 follows it.
    let inset = figs.iter().find(|f| f.name == "fig5-inset").unwrap();
    for (e, c) in inset.curves[0].points.iter().zip(&inset.curves[1].points).skip(1) {
        assert!((e[1] / c[1] - 1.0).abs() < 1e-6, "amp {}: {} vs {}", e[0], e[1], c[1]);
    }
}

/// The figures beyond the seed: their exact points are the solver's
/// (`Shape::report` under a tangential oscillation), the regime map's tiles are the spring's
/// regimes, and its sign-change line lies where `mu` is 0.
#[test]
fn oscillation_figures_are_the_solvers_values() {
    use fricosc_cli::figures::{COMBINED, MAP_T};
    let mu = |shape: &Shape, vhat: f64, amp: f64, t: f64, p: f64| {
        crate::common::at::combined(shape, vhat, amp, t, p).unwrap()
    };
    let figs = figures();
    for f in figs {
        let shape = if f.name.ends_with("parabolic") { Shape::parabolic() } else { Shape::flat() };
        let beyond = ["fig", "system-", "transverse-", "directions-"].iter().all(|p| !f.name.starts_with(p));
        for c in f.curves.iter().filter(|c| c.kind == "exact" && beyond) {
            let t = c.amp.unwrap();
            assert_eq!(f.family, "tangential_amp", "{}", f.name);
            for p in c.points.iter().step_by(5) {
                let want = match f.x {
                    XAxis::SlidingRatio => mu(&shape, p[0] * t, 0.0, t, 0.0),
                    XAxis::Phase => mu(&shape, COMBINED.0, COMBINED.1, t, p[0]),
                    x => panic!("{}: axis {x:?}", f.name),
                };
                assert_eq!(p[1], want.ratio.mu_ratio, "{} {}", f.name, c.label);
            }
        }
    }
    // The rigid-body law is what the largest T approaches.
    let flat = figs.iter().find(|f| f.name == "tangential-flat").unwrap();
    let (big, law) = (&flat.curves[5], flat.curves.last().unwrap());
    for (e, l) in big.points.iter().zip(&law.points).filter(|(e, _)| e[0] < 0.9) {
        assert!((e[1] - l[1]).abs() < 0.02, "x {}: {} against {}", e[0], e[1], l[1]);
    }
    let map = figs.iter().find(|f| f.name == "combined-regimes").unwrap();
    for c in &map.curves {
        for p in c.points.iter().step_by(37) {
            let r = mu(&Shape::flat(), COMBINED.0, p[1], MAP_T, p[0]);
            if c.kind == "sign change" {
                assert!(r.ratio.mu_ratio.abs() < 1e-9, "mu {} at {p:?}", r.ratio.mu_ratio);
                continue;
            }
            let s = r.spring.unwrap();
            let jumping = s.contact == fricosc::spring::Touch::Jumping;
            let both = s.phases.iter().any(|q| q.kind == fricosc::spring::StopKind::Backward && q.end > q.start);
            assert_eq!(c.label.starts_with("jumping"), jumping, "{} at {p:?}", c.label);
            assert_eq!(c.label.ends_with("both ways"), both, "{} at {p:?}", c.label);
        }
    }
}

/// The resonance figure's points are `fricosc::system`'s attractors: at
/// `Omega = 0` the stiff answer at `vbar kappa/(1 + kappa)`.
#[test]
fn the_resonance_figure_is_the_systems_values() {
    use fricosc_cli::figures::RESONANCE;
    let (kappa, zeta, amp) = RESONANCE;
    let figs = figures();
    let f = figs.iter().find(|f| f.name == "system-resonance").unwrap();
    assert_eq!(f.family, "frequency_ratio");
    for c in &f.curves {
        let sys = fricosc::system::System::new(kappa, c.amp.unwrap(), zeta).unwrap();
        for p in c.points.iter().step_by(9) {
            let r =
                crate::common::on_system(&fricosc::Shape::flat(), &fricosc::Conditions::vbar(p[0], amp).unwrap(), &sys)
                    .unwrap();
            assert_eq!(p[1], r.mu_ratio, "{} at {}", c.label, p[0]);
            if c.amp == Some(0.0) {
                let stiff = crate::common::eval(&Shape::flat(), p[0] * kappa / (1.0 + kappa), amp).unwrap();
                assert!((p[1] - stiff.ratio.mu_ratio).abs() < 1e-15, "{}", p[0]);
            }
        }
    }
}

/// The frequency figure's points are the attractors (the stated start); at
/// `Omega = 0` the massless identity; the reduction vanishes (`mu > 0.98`)
/// within 10 % of the stick resonance `sqrt(1 + kappa)` for `kappa <= 4`, and
/// nowhere below 0.85 of it (where the friction is reduced: below 0.76 there).
#[test]
fn the_frequency_figure_is_the_systems_values() {
    use fricosc_cli::figures::FREQUENCY;
    let (vbar, amp, zeta) = FREQUENCY;
    let figs = figures();
    let f = figs.iter().find(|f| f.name == "system-frequency").unwrap();
    assert_eq!(f.family, "system_stiffness");
    let c = fricosc::Conditions::vbar(vbar, amp).unwrap();
    for curve in &f.curves {
        let kappa = curve.amp.unwrap();
        for p in curve.points.iter().step_by(10) {
            let sys = fricosc::system::System::new(kappa, p[0], zeta).unwrap();
            assert_eq!(p[1], crate::common::on_system(&Shape::flat(), &c, &sys).unwrap().mu_ratio, "{}", curve.label);
        }
        let massless = crate::common::eval(&Shape::flat(), vbar * kappa / (1.0 + kappa), amp).unwrap();
        assert_eq!(curve.points[0][1], massless.ratio.mu_ratio);
        let resonance = (1.0 + kappa).sqrt();
        let near = curve.points.iter().filter(|p| (p[0] / resonance - 1.0).abs() <= 0.1).map(|p| p[1]);
        let below = curve.points.iter().filter(|p| p[0] < 0.85 * resonance).map(|p| p[1]);
        if kappa <= 4.0 {
            assert!(near.fold(0.0, f64::max) > 0.98, "{}", curve.label);
            assert!(below.fold(0.0, f64::max) < 0.9, "{}", curve.label);
        }
    }
}

/// The seed's approximations where it uses them: eq. 16 (eq. 11 in vhat) only
/// without jumping, eq. 17 for jumping; no approximation at du/u0 = 0 (mu = mu0
/// is exact there); the seed's amplitudes and the line at du/u0 = 0 where it has them.
#[test]
fn approximations_are_drawn_where_the_seed_uses_them() {
    let figs = figures();
    for f in figs {
        for c in f.curves.iter().filter(|c| c.kind == "approximation") {
            let eq = c.equation.as_deref().unwrap();
            match (eq, c.amp) {
                ("eq. 16", Some(a)) => assert!(a > 0.0 && a <= 1.0, "{}: eq. 16 at {a}", f.name),
                ("eq. 17", Some(a)) => assert!(a > 1.0, "{}: eq. 17 at {a}", f.name),
                (_, Some(a)) => assert!(a > 0.0, "{}: {eq} at 0", f.name),
                _ => {}
            }
            // On a mu axis an approximation stays within [0, 1]: none is drawn
            // where it goes negative (eq. 16 at jumping amplitudes reaches -1).
            if f.y_label == fricosc_cli::figures::MU_LABEL {
                assert!(c.points.iter().all(|p| (0.0..=1.0).contains(&p[1])), "{}: {}", f.name, c.label);
            }
        }
        let amps = |kind: &str| {
            let mut a: Vec<f64> = f.curves.iter().filter(|c| c.kind == kind).filter_map(|c| c.amp).collect();
            a.dedup();
            a
        };
        let expected: &[f64] = match f.name.as_str() {
            "fig3" | "fig7" => &[0.0, 0.2, 0.4, 0.6, 0.8, 1.0],
            "fig4" | "fig8" => &[0.0, 0.2, 0.4, 0.6, 0.8, 1.0, 1.2, 1.4, 1.6, 1.8, 2.0],
            "fig5" => &[1.0, 1.1, 1.2, 1.3, 1.4, 1.5, 1.6, 1.7, 1.8, 1.9, 2.0],
            "fig3-inset" => &[1.0],
            "tangential-flat" | "tangential-parabolic" => &fricosc_cli::figures::TANGENTIAL_AMPS,
            "combined-phase" => &fricosc_cli::figures::COMBINED_TS,
            "transverse-flat" => &fricosc_cli::figures::TRANSVERSE_AMPS,
            "transverse-phase" => &fricosc_cli::figures::SIDEWAYS_WS,
            "system-resonance" => &fricosc_cli::figures::OMEGAS,
            "system-frequency" => &fricosc_cli::figures::KAPPAS,
            _ => &[],
        };
        assert_eq!(amps("exact"), expected, "{}", f.name);
    }
}

/// The plane's figures: every point is the library's (`Conditions::with_transverse`),
/// the sideways curves its `transverse_ratio`; the rigid limit is Gauss's AGM.
#[test]
fn plane_figures_are_the_solvers_values() {
    use fricosc::plane::Transverse;
    let at = |vhat: f64, amp: f64, w: f64, psi: f64| {
        let c = fricosc::Conditions::vhat(vhat, amp).unwrap().with_transverse(Transverse::new(w, psi).unwrap());
        Shape::flat().evaluate(&c).unwrap()
    };
    let (vhat, amp) = fricosc_cli::figures::SIDEWAYS;
    let figs = figures();
    for f in figs.iter().filter(|f| f.name.starts_with("transverse-")) {
        assert_eq!(f.family, "transverse_amp");
        for c in &f.curves {
            for p in c.points.iter().step_by(9) {
                let got = match (f.x, c.amp) {
                    (XAxis::TransverseRatio, Some(w)) => at(p[0] * w, 0.0, w, 0.0).ratio.mu_ratio,
                    (XAxis::TransverseRatio, None) => fricosc::stepper::rigid_limit(1.0 / p[0]),
                    (XAxis::TransversePhase, Some(w)) if c.label.starts_with("sideways") => {
                        at(vhat, amp, w, p[0]).transverse_ratio.unwrap()
                    }
                    (XAxis::TransversePhase, Some(w)) => at(vhat, amp, w, p[0]).ratio.mu_ratio,
                    (x, _) => panic!("{}: axis {x:?}", f.name),
                };
                assert_eq!(p[1], got, "{} {}", f.name, c.label);
            }
        }
    }
}

/// `(colour, width, dash)` of every series in an SVG, read from the document.
fn series_styles(svg: &str) -> Vec<(String, Rgb, String, String)> {
    let attr = |s: &str, name: &str| {
        s.split(&format!(" {name}=\"")).nth(1).map(|t| t.split('"').next().unwrap_or("").to_string())
    };
    svg.split("<g data-series=\"")
        .skip(1)
        .map(|g| {
            let label = g.split('"').next().unwrap().to_string();
            let path = g.split("</g>").next().unwrap();
            let hex = attr(path, "stroke").or_else(|| attr(path, "fill")).expect("a colour");
            let c = u32::from_str_radix(hex.trim_start_matches('#'), 16).unwrap();
            let rgb = Rgb((c >> 16) as u8, (c >> 8) as u8, c as u8);
            (
                label,
                rgb,
                attr(path, "stroke-width").unwrap_or_default(),
                attr(path, "stroke-dasharray").unwrap_or_default(),
            )
        })
        .collect()
}

#[test]
fn every_drawing_parses_tells_curves_apart_and_renders() {
    for f in figures() {
        let svg = fricosc_cli::export::export(f, fricosc_cli::export::Format::Svg).unwrap();
        let (w, h) = chart::parse_size(&svg).unwrap_or_else(|e| panic!("{}: {e}", f.name));
        assert_eq!(w, chart::WIDTH, "{}: 8.5 cm wide", f.name);
        // Axis symbols in Unicode, never the ASCII stand-ins.
        let symbol = match f.x {
            XAxis::Vbar => "v\u{304}",
            XAxis::Vhat => "v\u{302}",
            XAxis::Amp => "Δu",
            XAxis::SlidingRatio => "ω Δx",
            XAxis::FrequencyRatio => "Ω",
            XAxis::Phase => "φ",
            XAxis::TransverseRatio => "ω Δy",
            XAxis::TransversePhase => "ψ",
        };
        let text: String = svg.split("<text").skip(1).map(|t| t.split("</text>").next().unwrap()).collect();
        assert!(text.contains(symbol) && text.contains("μ"), "{}: axis symbols", f.name);
        for ascii in ["mu_macro", "mu0", "vbar", "vhat", "du/u0"] {
            assert!(!text.contains(ascii), "{}: '{ascii}' printed", f.name);
        }
        // No two series alike: the library's own check, and the same read back from the SVG.
        let c = chart(f);
        chart::distinct(&c, 8.0).unwrap_or_else(|e| panic!("{}: {e}", f.name));
        let styles = series_styles(&svg);
        assert_eq!(styles.len(), f.curves.len(), "{}", f.name);
        for (i, a) in styles.iter().enumerate() {
            for b in &styles[i + 1..] {
                let same_line = a.2 == b.2 && a.3 == b.3;
                assert!(!(same_line && a.1.delta_e(b.1) < 8.0), "{}: '{}' and '{}' look alike", f.name, a.0, b.0);
            }
        }
        // Coordinates carry fractions of a point (no whole-pixel steps).
        // (A map has markers, no curves: their positions.)
        let sixth = svg.split(" L").nth(5).or_else(|| svg.split(" x=\"").nth(5));
        assert!(svg.contains(".") && sixth.is_some_and(|s| s.contains('.')), "{}", f.name);
        // The PNG: 300 dpi of the drawing's size in pt.
        let png = chart::png(&svg).unwrap();
        assert_eq!(&png[1..4], b"PNG");
        let be = |k: usize| u32::from_be_bytes([png[k], png[k + 1], png[k + 2], png[k + 3]]);
        let px = |pt: f64| (pt / 72.0 * chart::DPI).round() as u32;
        assert_eq!((be(16), be(20)), (px(w), px(h)), "{}", f.name);
    }
}

/// The checker itself: two series in one style are caught.
#[test]
fn distinct_catches_a_repeated_style() {
    let mut c = chart(&figures()[0]);
    assert!(chart::distinct(&c, 8.0).is_ok());
    c.series[2].style = c.series[0].style;
    assert!(chart::distinct(&c, 8.0).is_err());
    // Near colours count as the same.
    let s = c.series[0].style;
    c.series[2].style = chart::Style { color: Rgb(s.color.0.saturating_add(3), s.color.1, s.color.2), ..s };
    assert!(chart::distinct(&c, 8.0).is_err());
}

/// `plot`'s limit of 12 amplitudes keeps neighbouring colours apart.
#[test]
fn the_largest_user_plot_tells_its_curves_apart() {
    let amps: Vec<f64> = (1..=fricosc_cli::figures::MAX_CURVES).map(|k| k as f64 * 0.25).collect();
    let xs: Vec<f64> = (0..=12).map(|k| k as f64 * 0.1).collect();
    let f = fricosc_cli::figures::user(&Shape::flat(), &amps, &xs, false).unwrap();
    assert_eq!(f.curves.len(), 12);
    chart::distinct(&chart(&f), 8.0).unwrap();
    // With a 13th amplitude the limit is enforced.
    let mut more = amps.clone();
    more.push(9.0);
    assert!(fricosc_cli::figures::user(&Shape::flat(), &more, &xs, false).is_err());
}

/// The three directions at one physical amplitude: every point is the
/// library's answer to the one oscillation it names (normal `du/u0`, along
/// `T`, across `W`, with `d/l = (d/u0)(kx/kz)/mu0`), on the flat punch and
/// the paraboloid.
#[test]
fn the_directions_figures_are_the_solvers_values() {
    use fricosc::plane::Transverse;
    use fricosc::Conditions;
    let (d, stiffness, mu0) = fricosc_cli::figures::DIRECTIONS;
    let a = d * stiffness / mu0;
    for f in figures().iter().filter(|f| f.name.starts_with("directions-")) {
        let shape = Shape::parse(f.name.trim_start_matches("directions-")).unwrap();
        assert_eq!(f.curves.len(), 3, "{}", f.name);
        for c in &f.curves {
            for p in c.points.iter().step_by(7) {
                let at = match c.label.split(',').next() {
                    Some("normal") => Conditions::vhat(p[0], d).unwrap(),
                    Some("along") => Conditions::vhat(p[0], 0.0).unwrap().with_tangential(a, 0.0).unwrap(),
                    Some("across") => {
                        Conditions::vhat(p[0], 0.0).unwrap().with_transverse(Transverse::new(a, 0.0).unwrap())
                    }
                    other => panic!("{}: {other:?}", f.name),
                };
                assert_eq!(p[1], shape.evaluate(&at).unwrap().ratio.mu_ratio, "{} {} at {}", f.name, c.label, p[0]);
            }
        }
    }
}

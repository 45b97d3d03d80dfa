//! The figures' exact curves are the solver's values (no second implementation).
use fricosc::figures::build;
use fricosc::shape::{evaluate, Shape};

#[test]
fn exact_curves_equal_the_solver_and_every_figure_is_there() {
    let figs = build().unwrap();
    let names: Vec<&str> = figs.iter().map(|f| f.name.as_str()).collect();
    assert_eq!(names, ["fig3", "fig3-inset", "fig4", "fig5", "fig5-inset", "fig7", "fig8"]);
    for f in &figs {
        let shape =
            if f.name.starts_with("fig7") || f.name.starts_with("fig8") { Shape::Power(2.0) } else { Shape::Flat };
        let vhat = f.x_label.starts_with("vhat");
        for c in f.curves.iter().filter(|c| c.kind == "exact") {
            let Some(amp) = c.amp else { continue };
            for p in c.points.iter().step_by(7) {
                let vbar = if vhat { p[0] / amp } else { p[0] };
                assert_eq!(p[1], evaluate(&shape, vbar, amp).unwrap().ratio.mu_ratio, "{} {}", f.name, c.label);
            }
        }
        let svg = fricosc::export::export(f, fricosc::export::Format::Svg).unwrap();
        assert!(svg.starts_with("<svg"));
    }
    // The inset's exact slope is the claims' one, and the corrected eq. 21 follows it.
    let inset = figs.iter().find(|f| f.name == "fig5-inset").unwrap();
    for (e, c) in inset.curves[0].points.iter().zip(&inset.curves[1].points).skip(1) {
        assert!((e[1] / c[1] - 1.0).abs() < 1e-6, "amp {}: {} vs {}", e[0], e[1], c[1]);
    }
}

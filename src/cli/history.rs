//! `fricosc history`: the force histories of [`fricosc::history`] as a
//! report (CSV, JSON, the seed's Fig. 2 as SVG).

use crate::error::Result;
use fricosc::history::{History, Sample};

impl crate::export::Report for History {
    fn columns(&self) -> Vec<String> {
        ["tau", "normal", "tangential", "event"].map(String::from).to_vec()
    }

    fn comment(&self) -> Option<String> {
        Some(format!(
            "fricosc history of {} at vbar {}, du/u0 {}: tau = omega t with the indentation u0 - du cos(tau); {}",
            self.shape, self.vbar, self.amp, self.units
        ))
    }

    fn rows(&self) -> Vec<Vec<String>> {
        let n = crate::output::num;
        self.samples
            .iter()
            .map(|x| {
                let ev = x.event.map(|e| {
                    serde_json::to_value(e).ok().and_then(|v| v.as_str().map(String::from)).unwrap_or_default()
                });
                vec![n(x.tau), n(x.normal), n(x.tangential), ev.unwrap_or_default()]
            })
            .collect()
    }

    /// Both forces over the phase (the seed's Fig. 2).
    fn svg(&self) -> Option<Result<String>> {
        use crate::plot::{Axis, Chart, Series, Style, OKABE_ITO};
        let pts = |f: fn(&Sample) -> f64| self.samples.iter().map(|x| (x.tau, f(x))).collect::<Vec<_>>();
        let ymax = self.samples.iter().map(|x| x.normal).fold(0.0, f64::max) * 1.05 + 1e-12;
        let series = vec![
            Series {
                label: "μ_{0} × normal force".into(),
                points: pts(|x| x.normal),
                style: Style::line(OKABE_ITO[4]),
                legend: true,
            },
            Series {
                label: "tangential force".into(),
                points: pts(|x| x.tangential),
                style: Style::line(OKABE_ITO[5]).width(1.5),
                legend: true,
            },
        ];
        let tmax = self.samples.last().map_or(1.0, |x| x.tau);
        let unit = "force / (μ_{0} F_{0})";
        Some(Ok(Chart {
            title: format!("{}: forces at vbar = {}, du/u0 = {} ({})", self.shape, self.vbar, self.amp, self.units),
            x: Axis::linear("phase ωt (rad)", (0.0, tmax)),
            y: Axis::linear(unit, (0.0, ymax)),
            series,
            key: vec![],
            rules: vec![],
        }
        .svg()))
    }
}

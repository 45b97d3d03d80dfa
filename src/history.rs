//! `fricosc history`: the force histories of [`fricosc_core::history`] as a
//! report (CSV, JSON, the seed's Fig. 2 as SVG).

use crate::error::{Error, Result};
pub use fricosc_core::history::*;

impl crate::export::Report for History {
    fn columns(&self) -> Vec<String> {
        ["tau", "normal", "tangential", "event"].map(String::from).to_vec()
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
        let pts = |f: fn(&Sample) -> f64| self.samples.iter().map(|x| (x.tau, f(x))).collect::<Vec<_>>();
        let ymax = self.samples.iter().map(|x| x.normal).fold(0.0, f64::max) * 1.05 + 1e-12;
        let series = [
            crate::plot::Series { label: "mu0 x normal force".into(), points: pts(|x| x.normal), dashed: false },
            crate::plot::Series { label: "tangential force".into(), points: pts(|x| x.tangential), dashed: false },
        ];
        let title = format!("{} vbar = {}, du/u0 = {} ({})", self.shape, self.vbar, self.amp, self.units);
        let tmax = self.samples.last().map_or(1.0, |x| x.tau);
        Some(
            crate::plot::lines(&title, "omega t", "force", (0.0, tmax), (0.0, ymax), &series)
                .map_err(|e| Error::Internal { what: format!("drawing the plot: {e}") }),
        )
    }
}

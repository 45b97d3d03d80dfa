//! A series of histories at increasing resolution: the largest error over the
//! last period and each event's timing error, with their observed orders.

use super::HistoryValidation;
use crate::model::spring::EventKind;
use crate::validation::{findings_text, observed_order, Finding};

/// The convergence of a series of histories ([`HistorySeries::new`]).
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
#[non_exhaustive]
pub struct HistorySeries {
    /// The resolutions, increasing.
    pub resolutions: Vec<f64>,
    /// The largest error over the last period at each resolution.
    pub max_abs_errors: Vec<f64>,
    /// Their observed order: the least-squares slope of `log |error|` against `log resolution`.
    pub order: Option<f64>,
    /// Their error constant.
    pub constant: Option<f64>,
    /// Per event kind of the coarsest history's exact events: its timing errors and their order.
    pub events: Vec<EventSeries>,
    /// The findings of the finest history.
    pub findings: Vec<Finding>,
}

/// One event kind's timing errors over a [`HistorySeries`].
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
#[non_exhaustive]
pub struct EventSeries {
    /// The event.
    pub kind: EventKind,
    /// Its timing error at each resolution (none where the history lacks it).
    pub timing_errors: Vec<Option<f64>>,
    /// Their observed order.
    pub order: Option<f64>,
}

impl HistorySeries {
    /// The series of `runs`, each a resolution and its history's comparison
    /// (in any order).
    #[must_use]
    pub fn new(mut runs: Vec<(f64, HistoryValidation)>) -> HistorySeries {
        runs.sort_by(|x, y| x.0.total_cmp(&y.0));
        let resolutions: Vec<f64> = runs.iter().map(|r| r.0).collect();
        let max_abs_errors: Vec<f64> = runs.iter().map(|r| r.1.max_abs_error).collect();
        let (order, constant) = observed_order(&resolutions, &max_abs_errors);
        let mut kinds: Vec<EventKind> =
            runs.first().map_or(vec![], |r| r.1.exact_events.iter().map(|e| e.kind).collect());
        kinds.dedup();
        let events = kinds
            .iter()
            .map(|&kind| {
                let timing_errors: Vec<Option<f64>> = runs
                    .iter()
                    .map(|r| r.1.events.iter().find(|e| e.kind == kind).and_then(|e| e.timing_error))
                    .collect();
                let (res, errs): (Vec<f64>, Vec<f64>) =
                    resolutions.iter().zip(&timing_errors).filter_map(|(r, e)| e.map(|e| (*r, e))).unzip();
                EventSeries { kind, timing_errors, order: observed_order(&res, &errs).0 }
            })
            .collect();
        let findings = runs.last().map(|r| r.1.findings.clone()).unwrap_or_default();
        HistorySeries { resolutions, max_abs_errors, order, constant, events, findings }
    }

    /// The report for a person.
    #[must_use]
    pub fn summary(&self) -> String {
        let o = |p: Option<f64>| p.map_or("-".into(), |p| format!("{p:.2}"));
        let mut t = format!(
            "fricosc validate --series --history: {} histories; the largest error over the last period has order {}.\n",
            self.resolutions.len(),
            o(self.order)
        );
        for (r, e) in self.resolutions.iter().zip(&self.max_abs_errors) {
            t += &format!("  resolution {r:>10}: largest |error| {e:.2e}\n");
        }
        for ev in &self.events {
            t += &format!("  event {:<16} timing order {}\n", ev.kind.name(), o(ev.order));
        }
        t + &findings_text("Findings of the finest history", &self.findings, "none", "sample")
    }
}

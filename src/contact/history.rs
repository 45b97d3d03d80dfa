//! Force histories: the normal and tangential force over time (the seed's
//! Fig. 2), exact, sampled from the closed-form phases with every event time
//! included as a sample (`fricosc history`, the Python package's `history()`).
//!
//! Flat punch: forces in units of `kz u0` (normal) and `mu0 kz u0` (tangential).
//! Every other contact: totals in units of `E* x_c u0` (and `mu0 E* x_c u0`);
//! the normal total is exact ([`crate::contact::Contact::static_force`] at each
//! phase's depth, both sides of the foundation), the tangential total sums the exact forces of `springs` springs at the midpoints
//! of a uniform grid (second order in the spacing away from the phase switches).

use crate::error::{check_nonneg, Error, Result};
use crate::shape::Shape;
use crate::spring::{EventKind, Spring};
use std::f64::consts::TAU;

/// One sample of the forces.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct Sample {
    /// Phase `omega t` (from 0 to `2 pi periods`).
    pub tau: f64,
    /// Normal force.
    pub normal: f64,
    /// Tangential force.
    pub tangential: f64,
    /// The event at this phase, if it is one (flat punch only).
    #[cfg_attr(feature = "serde", serde(skip_serializing_if = "Option::is_none"))]
    pub event: Option<EventKind>,
    /// For MDR shapes, the chosen springs' `[normal, tangential]` forces per unit
    /// length of the foundation, units `E* u0` (and `mu0 E* u0`), in the order of
    /// [`History::spring_positions`].
    #[cfg_attr(feature = "serde", serde(skip_serializing_if = "Vec::is_empty"))]
    pub springs: Vec<[f64; 2]>,
}

/// A force history.
#[derive(Debug, Clone)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct History {
    /// Shape name.
    pub shape: String,
    /// Dimensionless velocity.
    pub vbar: f64,
    /// Amplitude.
    pub amp: f64,
    /// Units of the forces.
    pub units: String,
    /// Positions `x/x_c` of the chosen springs (MDR shapes).
    #[cfg_attr(feature = "serde", serde(skip_serializing_if = "Vec::is_empty"))]
    pub spring_positions: Vec<f64>,
    /// The samples, in phase order.
    pub samples: Vec<Sample>,
}

/// Tangential force of one spring at phase `tau`, units `mu0 kz du`, from its phases.
pub fn spring_force(sp: &Spring, tau: f64) -> f64 {
    let b = (sp.s - tau.cos()).max(0.0);
    if b == 0.0 {
        return 0.0;
    }
    if let Some(st) = sp.stick {
        let t0 = st.start;
        let x = (tau - t0).rem_euclid(TAU);
        if x < st.length {
            return (st.start_force + sp.vbar * x).min(b);
        }
    }
    b
}

/// Most springs summed for an MDR history.
pub const MAX_SPRINGS: usize = 1_000_000;

/// Most spring-force evaluations one history may take (rows x springs: about a
/// minute on two cores).
pub const MAX_SPRING_WORK: u128 = 4_000_000_000;

/// Most rows one history may hold (and most chosen-spring values): the same
/// 10^7 as every other output of the command line (`grid::MAX_ROWS` there).
pub const MAX_SAMPLES: usize = 10_000_000;

/// The history of `periods` periods with `samples` uniform samples (plus events).
/// `chosen`: positions `x/x_c >= 0` of springs of an MDR shape to report one by one.
pub fn history(
    shape: &Shape,
    vbar: f64,
    amp: f64,
    periods: usize,
    samples: usize,
    springs: usize,
    chosen: &[f64],
) -> Result<History> {
    check_nonneg("vbar", vbar)?;
    check_nonneg("amp", amp)?;
    for &x in chosen {
        check_nonneg("spring position", x)?;
    }
    if !chosen.is_empty() && shape.with_contact(|c| c.single_spring()) {
        return Err(Error::InvalidShape { spec: shape.name(), reason: "chosen springs need an MDR shape".into() });
    }
    if periods == 0 || samples == 0 || springs == 0 {
        return Err(Error::param("periods/samples/springs", 0.0, "must be >= 1"));
    }
    if springs > MAX_SPRINGS {
        return Err(Error::TooLarge {
            what: "history springs".into(),
            count: springs as u128,
            limit: MAX_SPRINGS as u128,
        });
    }
    // Rows: the uniform samples, their end point, and up to 4 events a period
    // (flat punch); every limit is checked before anything is allocated.
    let events = if shape.with_contact(|c| c.single_spring()) { 4 * periods as u128 } else { 0 };
    let rows = samples as u128 + 1 + events;
    if rows > MAX_SAMPLES as u128 {
        return Err(Error::TooLarge {
            what: "history rows (samples + 1 + events)".into(),
            count: rows,
            limit: MAX_SAMPLES as u128,
        });
    }
    let values = rows * chosen.len() as u128;
    if values > MAX_SAMPLES as u128 {
        return Err(Error::TooLarge {
            what: "history chosen-spring values (rows x --spring-at positions)".into(),
            count: values,
            limit: MAX_SAMPLES as u128,
        });
    }
    let work = rows * if shape.with_contact(|c| c.single_spring()) { 1 } else { springs as u128 };
    if work > MAX_SPRING_WORK {
        return Err(Error::TooLarge {
            what: "history spring evaluations (rows x springs)".into(),
            count: work,
            limit: MAX_SPRING_WORK,
        });
    }
    let total = TAU * periods as f64;
    let mut taus: Vec<(f64, Option<EventKind>)> =
        (0..=samples).map(|j| (total * j as f64 / samples as f64, None)).collect();
    let (units, out) = match shape.with_contact(|c| c.single_spring()) {
        true => {
            let sp = crate::flat::spring(vbar, amp, true);
            for p in 0..periods {
                for e in sp.events() {
                    taus.push((e.tau + TAU * p as f64, Some(e.kind)));
                }
            }
            taus.sort_by(|a, b| a.0.total_cmp(&b.0));
            let scale = if amp > 0.0 { amp } else { 1.0 };
            let samples = taus
                .iter()
                .map(|&(tau, event)| {
                    let (normal, tangential) = if amp > 0.0 {
                        ((sp.s - tau.cos()).max(0.0) * scale, spring_force(&sp, tau) * scale)
                    } else {
                        (1.0, 1.0)
                    };
                    Sample { tau, normal, tangential, event, springs: vec![] }
                })
                .collect();
            ("normal: kz u0; tangential: mu0 kz u0".to_string(), samples)
        }
        // Every other contact through its MDR foundation (crate::contact::grid):
        // the normal force exactly, the tangential one as the grid's sum.
        false => shape.with_contact(|c| -> Result<(String, Vec<Sample>)> {
            let (dz, sp): (f64, Vec<Spring>) = if amp > 0.0 {
                let (dz, s_of) = crate::contact::grid(c, amp, springs)?;
                (dz, (0..springs).map(|i| Spring::with_events(s_of(i), vbar)).collect())
            } else {
                (0.0, vec![])
            };
            taus.sort_by(|a, b| a.0.total_cmp(&b.0));
            let picked: Vec<(f64, Option<Spring>)> = chosen
                .iter()
                .map(|&x| {
                    let g = c.equivalent_profile(x);
                    (g, (amp > 0.0).then(|| Spring::with_events((1.0 - g) / amp, vbar)))
                })
                .collect();
            let samples = taus
                .iter()
                .map(|&(tau, _)| {
                    // Both sides of the foundation.
                    let normal = c.static_force(1.0 - amp * tau.cos());
                    let tangential = if amp > 0.0 {
                        2.0 * amp * dz * sp.iter().map(|s| spring_force(s, tau)).sum::<f64>()
                    } else {
                        normal
                    };
                    let springs = picked
                        .iter()
                        .map(|(g, sp)| {
                            let nrm = (1.0 - g - amp * tau.cos()).max(0.0);
                            [nrm, sp.as_ref().map_or(nrm, |s| amp * spring_force(s, tau))]
                        })
                        .collect();
                    Sample { tau, normal, tangential, event: None, springs }
                })
                .collect();
            Ok(("normal: E* x_c u0; tangential: mu0 E* x_c u0 (x_c: contact radius at u0)".to_string(), samples))
        })?,
    };
    Ok(History { shape: shape.name(), vbar, amp, units, spring_positions: chosen.to_vec(), samples: out })
}

/// The flat punch's history by the seed's time-stepping scheme (the peer),
/// every step of `periods` periods at `steps_per_period` steps, in the units of
/// [`history`]: the same columns as the exact history, so that a stepper's
/// output can be checked against it (`validate --history`). The spring starts
/// sliding (on its bound), as the peer does.
pub fn stepped_history(vbar: f64, amp: f64, periods: usize, steps_per_period: usize) -> Result<History> {
    check_nonneg("vbar", vbar)?;
    check_nonneg("amp", amp)?;
    if periods == 0 || steps_per_period == 0 {
        return Err(Error::param("periods/steps-per-period", 0.0, "must be >= 1"));
    }
    let rows = periods as u128 * steps_per_period as u128 + 1;
    if rows > MAX_SAMPLES as u128 {
        return Err(Error::TooLarge {
            what: "history rows (periods x steps + 1)".into(),
            count: rows,
            limit: MAX_SAMPLES as u128,
        });
    }
    if amp == 0.0 {
        return Err(Error::param("amp", amp, "a stepped history needs an oscillation (amp > 0)"));
    }
    let s = crate::flat::spring_s(amp);
    let h = TAU / steps_per_period as f64;
    let mut f = (s - 1.0).max(0.0);
    let mut samples = Vec::with_capacity(rows as usize);
    for k in 0..rows as usize {
        let tau = h * k as f64;
        let b = (s - tau.cos()).max(0.0);
        if k > 0 {
            f = crate::stepper::update(f, b, vbar * h);
        }
        samples.push(Sample { tau, normal: b * amp, tangential: f * amp, event: None, springs: vec![] });
    }
    Ok(History {
        shape: "flat".into(),
        vbar,
        amp,
        units: "normal: kz u0; tangential: mu0 kz u0 (time stepping)".into(),
        spring_positions: vec![],
        samples,
    })
}

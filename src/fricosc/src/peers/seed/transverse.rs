//! The qualitative statements about oscillation across the sliding direction
//! that `../shared/MODEL-transverse.md` makes for its anchors (Popov & Li
//! 2018; Wetter & Popov 2020; Teidelt, Starcevic & Popov 2012; Gutowski &
//! Leus), checked against the exact solver in the plane ([`crate::plane`]).

use super::claims::{named, Claim, Verdict};
use crate::plane::Transverse;
use crate::{Conditions, Shape};

/// `(mu_ratio, transverse_ratio)` of `shape` (NaN where it fails).
fn plane(shape: &Shape, vhat: f64, amp: f64, w: f64, psi: f64) -> (f64, f64) {
    let run = || shape.evaluate(&Conditions::vhat(vhat, amp)?.with_transverse(Transverse::new(w, psi)?));
    run().map_or((f64::NAN, f64::NAN), |e| (e.ratio.mu_ratio, e.transverse_ratio.unwrap_or(f64::NAN)))
}

/// `mu_ratio` of `shape` under `c`, NaN where it fails.
fn mu(shape: &Shape, c: crate::Result<Conditions>) -> f64 {
    c.and_then(|c| shape.evaluate(&c)).map_or(f64::NAN, |e| e.ratio.mu_ratio)
}

/// Oscillation in each of the three directions reduces friction: one
/// physical amplitude `d = 0.5 u0` (`d/l = 1.333` with `kx/kz = 0.8`, `mu0 =
/// 0.3`) at `vhat = 0.3`, flat punch and paraboloid.
pub(super) fn three_directions() -> Claim {
    let (d, a, v) = (0.5, 0.5 * 0.8 / 0.3, 0.3);
    let mut measured = vec![];
    for (name, shape) in [("flat", Shape::flat()), ("parabolic", Shape::parabolic())] {
        let normal = mu(&shape, Conditions::vhat(v, d));
        let along = mu(&shape, Conditions::vhat(v, 0.0).and_then(|c| c.with_tangential(a, 0.0)));
        let across = plane(&shape, v, 0.0, a, 0.0).0;
        measured.extend([(format!("{name}_normal"), normal), (format!("{name}_along"), along)]);
        measured.push((format!("{name}_across"), across));
    }
    let largest =
        measured.iter().map(|m| m.1).fold(f64::NEG_INFINITY, |x, y| if y.is_nan() { f64::NAN } else { x.max(y) });
    let text: Vec<String> = measured.iter().map(|(n, x)| format!("{n} {x:.4}")).collect();
    Claim {
        claim: "Transverse: three directions".into(),
        seed_says: "friction is reduced by oscillation in any of the three directions: normal to the plane, in the \
                    sliding direction, and in the plane across it"
            .into(),
        exact_gives: format!("mu/mu0 at vhat 0.3, one amplitude 0.5 u0 in each direction: {}", text.join(", ")),
        criterion: "holds if every one of the six is below 0.95".into(),
        measured,
        deviation: Some(largest),
        deviation_is: "the largest mu/mu0 of the six".into(),
        location: "flat punch and paraboloid, vhat 0.3, du/u0 0.5 or dx/l = dy/l = 1.333".into(),
        verdict: if largest < 0.95 { Verdict::Holds } else { Verdict::Wrong },
    }
}

/// Across the sliding direction there is no critical velocity: friction
/// stays below `mu0` at every velocity and approaches the rigid limit
/// `1/AGM(1, sqrt(1 + (W/vhat)^2))`, which is below 1 for every `vhat`.
pub(super) fn no_critical_velocity() -> Claim {
    let w = 2.0;
    let at = |ratio: f64| plane(&Shape::flat(), ratio * w, 0.0, w, 0.0).0;
    let (m1, m3, m10) = (at(1.0), at(3.0), at(10.0));
    let rigid = crate::stepper::rigid_limit(0.1);
    Claim {
        claim: "Transverse: no critical velocity".into(),
        seed_says: "the anchors' rigid-body picture (every spring slipping along the velocity): friction reduced at \
                    any sliding velocity, to 1/AGM(1, sqrt(1 + (W/vhat)^2)) for amp = 0, T = 0"
            .into(),
        exact_gives: format!(
            "flat punch, dy/l = 2, no normal oscillation: mu/mu0 = {m1:.5} at v0/(omega dy) = 1, {m3:.5} at 3, \
             {m10:.6} at 10 (the rigid limit there {rigid:.6})"
        ),
        criterion: "holds if mu/mu0 < 1 - 1e-3 at v0/(omega dy) = 10 and mu/mu0 rises with the velocity".into(),
        measured: named(&[("mu_1", m1), ("mu_3", m3), ("mu_10", m10), ("rigid_10", rigid)]),
        deviation: Some(1.0 - m10),
        deviation_is: "the reduction 1 - mu/mu0 left at v0/(omega dy) = 10".into(),
        location: "flat punch, W 2, amp 0".into(),
        verdict: if m10 < 1.0 - 1e-3 && m1 < m3 && m3 < m10 { Verdict::Holds } else { Verdict::Wrong },
    }
}

/// Normal and transverse oscillation together push the body sideways: on a
/// grid of velocities, amplitudes and phases, how often the mean force
/// across the sliding direction exceeds the friction along it.
pub(super) fn sideways_force() -> Claim {
    let (mut larger, mut total, mut best) = (0usize, 0usize, (f64::NEG_INFINITY, [0.0; 4], 0.0, 0.0));
    for vhat in [0.05, 0.3] {
        for amp in [0.5, 1.5] {
            for w in [1.0, 5.0] {
                for k in 0..16 {
                    let psi = std::f64::consts::TAU * f64::from(k) / 16.0;
                    let (m, t) = plane(&Shape::flat(), vhat, amp, w, psi);
                    // A failure counts against the claim.
                    let excess = if t.is_nan() || m.is_nan() { f64::NEG_INFINITY } else { t.abs() - m };
                    larger += usize::from(excess > 0.0);
                    total += 1;
                    // `psi + pi` is the mirror image (`X_y` reversed), its
                    // excess the same to rounding: the first of a tie is kept.
                    if excess > best.0 + 1e-12 {
                        best = (excess, [vhat, amp, w, psi], t, m);
                    }
                }
            }
        }
    }
    let share = larger as f64 / total as f64;
    let (excess, [v, a, w, psi], t, m) = best;
    Claim {
        claim: "Transverse: a sideways force".into(),
        seed_says: "with normal and transverse oscillation together the mean force across the sliding direction (a \
                    sideways ratchet) is often larger than the friction along it"
            .into(),
        exact_gives: format!(
            "flat punch, vhat 0.05 and 0.3, du/u0 0.5 and 1.5, dy/l 1 and 5, 16 phases psi: |<f_y>|/<B> > mu/mu0 at \
             {larger} of {total}; the most at vhat {v}, du/u0 {a}, dy/l {w}, psi {psi:.3}: {:.4} against {m:.4}",
            t.abs()
        ),
        criterion: "holds if |<f_y>|/<B> exceeds mu/mu0 at a quarter of the grid or more".into(),
        measured: named(&[("share_larger", share), ("largest_excess", excess)]),
        deviation: Some(share),
        deviation_is: "the share of the grid where the sideways force exceeds the friction".into(),
        location: "flat punch, the grid above".into(),
        verdict: if share >= 0.25 { Verdict::Holds } else { Verdict::Wrong },
    }
}

//! `fricosc claims`: every quantitative statement of the seed, checked against
//! the exact solver, with a verdict. `tests/claims.rs` asserts each verdict.

use crate::flat;
use crate::mdr::{mu_static_ratio, power_law, DEFAULT_TOL};
use crate::seed;
use crate::spring::Spring;
use serde::Serialize;
use std::f64::consts::{PI, TAU};

/// The verdict on one claim.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Verdict {
    /// The statement is right.
    Holds,
    /// A printed formula or number is wrong; the correction is given.
    Misprint,
    /// An approximation, with the measured error.
    Approximation,
}

/// One checked statement.
#[derive(Debug, Clone, Serialize)]
pub struct Claim {
    /// Equation or place in the seed.
    pub claim: String,
    /// What the seed says.
    pub seed_says: String,
    /// What the exact solver gives.
    pub exact_gives: String,
    /// Largest deviation found (absolute, in the claim's own quantity), if any.
    pub deviation: Option<f64>,
    /// Where the largest deviation is.
    pub location: String,
    /// The verdict.
    pub verdict: Verdict,
}

fn mu_flat(v: f64, a: f64) -> f64 {
    flat::ratio(v, a).map_or(f64::NAN, |r| r.mu_ratio)
}

fn mu_mdr(n: f64, v: f64, a: f64) -> f64 {
    power_law(n, v, a, DEFAULT_TOL, false).map_or(f64::NAN, |r| r.ratio.mu_ratio)
}

/// Small-velocity slope `mu/vbar` of the flat punch at `vbar = 1e-9`.
pub fn exact_slope(amp: f64) -> f64 {
    mu_flat(1e-9, amp) / 1e-9
}

/// A single spring in physical units (seed eq. 1): stiffnesses, friction,
/// sliding velocity, angular frequency, mean indentation and amplitude.
#[derive(Clone, Copy)]
struct Physical {
    kx: f64,
    kz: f64,
    mu0: f64,
    v0: f64,
    omega: f64,
    u0: f64,
    du: f64,
}

/// The seed's scheme in physical units, `m` steps per period; returns `mu/mu0`.
fn dimensional_stepper(p: &Physical, m: usize) -> f64 {
    let Physical { kx, kz, mu0, v0, omega, u0, du } = *p;
    let dt = TAU / omega / m as f64;
    let bound = |t: f64| (mu0 * kz * (u0 - du * (omega * t).cos())).max(0.0);
    let mut f = bound(0.0);
    let (mut sf, mut sn) = (0.0, 0.0);
    for k in 1..=2 * m {
        let t = dt * k as f64;
        let b = bound(t);
        f = if b > 0.0 { (f + kx * v0 * dt).min(b) } else { 0.0 };
        if k > m {
            sf += f;
            sn += b / mu0;
        }
    }
    sf / (mu0 * sn)
}

/// Largest `f(v, p)` over `v` in `{0, 1/k, ..., 1}` and `p` in `ps`, and where.
fn worst_over(ps: &[f64], k: usize, f: impl Fn(f64, f64) -> f64) -> (f64, (f64, f64)) {
    let mut best = (0.0f64, (0.0, 0.0));
    for &p in ps {
        for j in 0..=k {
            let v = j as f64 / k as f64;
            let d = f(v, p);
            if d > best.0 {
                best = (d, (v, p));
            }
        }
    }
    best
}

/// Check every claim.
pub fn check() -> Vec<Claim> {
    let mut out = vec![];

    // Eq. 8's sign.
    let v = 0.3f64;
    let sp = Spring::with_events(2.0, v);
    let t1 = v.asin();
    let t2 = t1 + sp.stick.map_or(f64::NAN, |s| s.length);
    let printed = |t: f64| t.cos() - ((1.0 - v * v).sqrt() + v * (t - t1));
    let worst_printed = (1..=1000).map(|k| printed(t1 + k as f64 * TAU / 1000.0)).fold(f64::NEG_INFINITY, f64::max);
    out.push(Claim {
        claim: "eq. 8 (stick -> slip)".into(),
        seed_says: "cos tau2 = vbar (tau2 - arcsin vbar) + sqrt(1 - vbar^2)".into(),
        exact_gives: format!(
            "cos tau2 = sqrt(1 - vbar^2) - vbar (tau2 - arcsin vbar); at vbar = 0.3, tau2 = {t2:.12}; the printed \
             form has no root after tau1 (its residual stays <= {worst_printed:.3e})"
        ),
        deviation: Some(printed(t2).abs()),
        location: "vbar = 0.3, amp = 0.5 (residual of the printed form at the true tau2)".into(),
        verdict: Verdict::Misprint,
    });

    // Eq. 11's error, relative to amp.
    let amps: Vec<f64> = (1..=10).map(|i| i as f64 / 10.0).collect();
    let (worst, at) = worst_over(&amps, 1000, |v, a| (seed::eq11(v, a) - mu_flat(v, a)).abs() / a);
    out.push(Claim {
        claim: "eq. 11 (empirical fit, amp <= 1)".into(),
        seed_says: "approximates the numerical results 'very accurately'".into(),
        exact_gives: format!("largest error {worst:.4} amp, exact at vbar = 0 and 1"),
        deviation: Some(worst),
        location: format!("vbar = {}, amp = {} (error / amp; the same at every amp to 1e-3)", at.0, at.1),
        verdict: Verdict::Approximation,
    });

    // Eq. 12's asymptotic exactness at amp = 1 (Fig. 3 inset).
    let err12 = |v: f64| (seed::eq12(v, 1.0) - mu_flat(v, 1.0)).abs();
    let (e3, e4, e5) = (err12(1e-3), err12(1e-4), err12(1e-5));
    let order = (e4 / e5).log10();
    out.push(Claim {
        claim: "eq. 12 (low-velocity asymptote)".into(),
        seed_says: "asymptotically exact as vbar -> 0".into(),
        exact_gives: format!(
            "error {e3:.2e}, {e4:.2e}, {e5:.2e} at vbar = 1e-3, 1e-4, 1e-5 (amp = 1): O(vbar^{order:.2}), \
             vanishing faster than every term of eq. 12"
        ),
        deviation: Some(e3),
        location: "amp = 1, vbar = 1e-3".into(),
        verdict: if order > 2.0 { Verdict::Holds } else { Verdict::Approximation },
    });

    // Eq. 21's factor pi.
    let ratio: f64 =
        [1.2, 1.5, 2.0, 5.0].iter().map(|&a| exact_slope(a) / seed::eq21_slope_printed(a)).sum::<f64>() / 4.0;
    let dev21 =
        [1.2, 1.5, 2.0, 5.0].iter().map(|&a| (exact_slope(a) / seed::eq21_slope(a) - 1.0).abs()).fold(0.0, f64::max);
    out.push(Claim {
        claim: "eq. 21 (low-velocity slope, amp > 1)".into(),
        seed_says: "mu/mu0 = vbar (1 - th/pi)^2 / (s (1 - th/pi + (1/pi)(du/u0) sqrt(1 - s^2)))".into(),
        exact_gives: format!(
            "the exact slope is {ratio:.9} = pi times the printed one; corrected: (pi - th)^2 / (s (pi - th) + sin th), \
             matching the solver to {dev21:.1e}"
        ),
        deviation: Some((ratio - 1.0).abs()),
        location: "amp = 1.2, 1.5, 2, 5 (vbar = 1e-9)".into(),
        verdict: Verdict::Misprint,
    });

    // Eq. 22 and the Fig. 5 caption.
    let big = exact_slope(1e8);
    out.push(Claim {
        claim: "eq. 22 and Fig. 5 caption (large-amplitude slope)".into(),
        seed_says: format!("limit pi/4 = {:.4}", seed::EQ22_PRINTED),
        exact_gives: format!("slope {big:.6} at amp = 1e8; the limit is pi^2/4 = {:.6}", seed::EQ22_CORRECTED),
        deviation: Some((big - seed::EQ22_PRINTED).abs()),
        location: "amp = 1e8".into(),
        verdict: Verdict::Misprint,
    });

    // "The slope drops by about 20 %".
    let s1 = exact_slope(1.0);
    let (mut smin, mut amin) = (f64::INFINITY, 1.0);
    for k in 1..=400 {
        let a = 1.0 + k as f64 / 100.0;
        let sl = exact_slope(a);
        if sl < smin {
            smin = sl;
            amin = a;
        }
    }
    let drop_limit = 1.0 - big / s1;
    let drop_max = 1.0 - smin / s1;
    out.push(Claim {
        claim: "Fig. 5 inset / section 2 ('slope drops by about 20 %')".into(),
        seed_says: "once the sample jumps the slope drops by about 20 % and then stays nearly constant".into(),
        exact_gives: format!(
            "slope {s1:.6} (= pi) at amp = 1, a minimum {smin:.4} at amp = {amin:.2} (a drop of {:.1} %), then rising to \
             pi^2/4 = {big:.6} as amp -> infinity (a drop of {:.2} %, 1 - pi/4)",
            100.0 * drop_max,
            100.0 * drop_limit
        ),
        deviation: Some(drop_max - 0.2),
        location: format!("amp = {amin:.2} (largest drop minus 20 %)"),
        verdict: Verdict::Approximation,
    });

    // Eq. 28 against eq. 27.
    let statics: Vec<f64> = (0..=100).map(|i| i as f64 / 100.0).collect();
    let (w28, at28) = worst_over(&statics, 1000, |v, ms| (seed::eq28(v, ms) - seed::eq27(v, ms)).abs());
    out.push(Claim {
        claim: "eq. 28 vs eq. 27".into(),
        seed_says: "differs from (27) by 1 % or less".into(),
        exact_gives: format!("largest difference {w28:.5} (of mu0)"),
        deviation: Some(w28),
        location: format!("vbar = {}, mu_static/mu0 = {}", at28.0, at28.1),
        verdict: if w28 <= 0.01 { Verdict::Holds } else { Verdict::Approximation },
    });

    // The critical velocity vbar = 1 for every shape (eq. 26).
    type Mu = Box<dyn Fn(f64, f64) -> f64>;
    let shapes: [(&str, Mu); 3] = [
        ("flat", Box::new(mu_flat)),
        ("parabolic", Box::new(|v, a| mu_mdr(2.0, v, a))),
        ("cone", Box::new(|v, a| mu_mdr(1.0, v, a))),
    ];
    let mut critical_ok = true;
    let mut worst_below = 1.0f64;
    for (_, f) in &shapes {
        for a in [0.3, 1.0, 2.0] {
            critical_ok &= f(1.0, a) == 1.0 && f(1.1, a) == 1.0 && f(1.0 - 1e-6, a) < 1.0;
            worst_below = worst_below.min(1.0 - f(1.0 - 1e-3, a));
        }
    }
    out.push(Claim {
        claim: "eq. 26 (critical velocity)".into(),
        seed_says: "vbar = 1 for all shapes, with and without jumping".into(),
        exact_gives: format!(
            "mu = mu0 exactly for vbar >= 1 and mu < mu0 just below (reduction >= {worst_below:.1e} at 1 - vbar = 1e-3) for flat, parabolic, cone at amp 0.3, 1, 2"
        ),
        deviation: None,
        location: "flat, parabolic, cone".into(),
        verdict: if critical_ok { Verdict::Holds } else { Verdict::Approximation },
    });

    // Eq. 27's shape independence.
    let mut parts = vec![];
    let mut w27 = 0.0f64;
    for (name, f) in &shapes {
        let mu_static = |a: f64| match *name {
            "flat" => flat::mu_static_ratio(a),
            "parabolic" => mu_static_ratio(2.0, a, DEFAULT_TOL),
            _ => mu_static_ratio(1.0, a, DEFAULT_TOL),
        };
        let (w, at) =
            worst_over(&[0.2, 0.4, 0.6, 0.8, 1.0, 1.5, 2.0], 200, |v, a| (seed::eq27(v, mu_static(a)) - f(v, a)).abs());
        w27 = w27.max(w);
        parts.push(format!("{name} {w:.3} (vbar {}, amp {})", at.0, at.1));
    }
    out.push(Claim {
        claim: "eq. 27 (shape independence)".into(),
        seed_says: "approximately valid for all shapes, jumping or not; shape enters only through mu_static".into(),
        exact_gives: format!("largest error: {}", parts.join("; ")),
        deviation: Some(w27),
        location: "amp in 0.2..2, vbar in [0, 1]".into(),
        verdict: Verdict::Approximation,
    });

    // mu depends only on (vbar, amp): two dimensional systems with the same pair.
    let (kx, kz, mu0, omega, u0, du) = (3.0e7, 4.0e7, 0.3, 2.0 * PI * 100.0, 2e-6, 1e-6);
    let v0 = 0.4 * kz * mu0 * omega * du / kx;
    let vbar = kx * v0 / (kz * mu0 * omega * du);
    let a_ = dimensional_stepper(&Physical { kx, kz, mu0, v0, omega, u0, du }, 20000);
    // A second system: stiffnesses x 1e3, kz/kx changed, frequency x 7, lengths x 1e-3, same (vbar, amp).
    let (kx2, kz2, mu02, omega2, u02, du2) = (5.0e10, 2.0e10, 0.6, omega * 7.0, u0 * 1e-3, du * 1e-3);
    let v02 = vbar * kz2 * mu02 * omega2 * du2 / kx2;
    let b_ =
        dimensional_stepper(&Physical { kx: kx2, kz: kz2, mu0: mu02, v0: v02, omega: omega2, u0: u02, du: du2 }, 20000);
    let exact = mu_flat(vbar, du / u0);
    // The same with two physical scenes (sphere, exact solver), lengths x 1e3,
    // moduli x 1e-4, frequency x 1e-2, velocities scaled with omega du.
    let scene = |e: f64, r: f64, u: f64, d: f64, f: f64, v: f64| {
        let json = format!(
            r#"{{"materials": {{"e1_pa": {e:?}, "nu1": 0.3, "e2_pa": {e:?}, "nu2": 0.3}}, "mu0": 0.4,
                "indenter": {{"sphere": {{"radius_m": {r:?}}}}}, "loading": {{"mean_indentation_m": {u:?}}},
                "oscillation": {{"amplitude_m": {d:?}, "frequency_hz": {f:?}}}, "velocity": {{"values_m_per_s": [{v:?}]}}}}"#
        );
        crate::scene::parse(&json, "claim")
            .and_then(|s| crate::scene::solve(&s, "claim"))
            .map_or(f64::NAN, |r| r.rows[0].mu_ratio)
    };
    let (sa, sb) = (scene(2e11, 5e-3, 1e-6, 1.3e-6, 1e3, 3e-4), scene(2e7, 5.0, 1e-3, 1.3e-3, 10.0, 3e-3));
    out.push(Claim {
        claim: "section 2 ('a function of only two dimensionless parameters')".into(),
        seed_says: "mu/mu0 depends only on vbar (eq. 3) and du/u0".into(),
        exact_gives: format!(
            "two dimensional systems (stiffnesses, mu0, frequency and lengths changed by up to 1e3) with vbar = {vbar:.6}, \
             amp = 0.5 give {a_:.12} and {b_:.12} by the seed's scheme (M = 20000); exact {exact:.12}. Two \
             sphere scenes (lengths x 1e3, moduli x 1e-4, frequency x 1e-2) give {sa:.15} and {sb:.15}"
        ),
        deviation: Some((a_ - b_).abs().max((sa - sb).abs())),
        location: "flat punch (time stepping in physical units) and sphere scenes".into(),
        verdict: if (a_ - b_).abs() < 1e-10 && (a_ - exact).abs() < 1e-6 && (sa - sb).abs() < 1e-14 {
            Verdict::Holds
        } else {
            Verdict::Approximation
        },
    });
    out
}

/// The claims as a Markdown table.
pub fn to_markdown(claims: &[Claim]) -> String {
    let mut s = String::from(
        "| claim | the seed says | the exact solver gives | deviation | verdict |\n|---|---|---|---|---|\n",
    );
    for c in claims {
        let dev = c.deviation.map_or("-".to_string(), |d| format!("{d:.3e} ({})", c.location));
        s += &format!(
            "| {} | {} | {} | {} | {} |\n",
            c.claim,
            c.seed_says.replace('|', "/"),
            c.exact_gives.replace('|', "/"),
            dev.replace('|', "/"),
            match c.verdict {
                Verdict::Holds => "holds",
                Verdict::Misprint => "misprint",
                Verdict::Approximation => "approximation",
            }
        );
    }
    s
}

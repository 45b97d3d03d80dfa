//! Numerical stress: many points, random and on every edge, checked for what
//! must always hold: no panic, finite results, `0 <= mu_ratio <= 1`,
//! `reduction >= 0` and `= 1 - mu_ratio` to rounding, and `mu_ratio`
//! nondecreasing in `vbar` along lines of constant amplitude. Under
//! oscillation in the sliding direction (`run_oscillation`): `-1 <= mu_ratio
//! <= 1`, `0 <= reduction <= 2`, their sum 1 within the error estimates (a
//! quarter of the points on or near the degenerate drive, where every spring
//! rides on a bound), the same value a period of the phase later, and
//! continuity in every parameter (a relative step of 1e-12 moves the value by
//! at most 1e-5). Then continuity across every regime boundary of the power laws.
//!
//! 10^5 points by default; a long run sets `FRICOSC_STRESS_POINTS` (and
//! `FRICOSC_STRESS_SEED`), e.g. `FRICOSC_STRESS_POINTS=1000000 cargo test
//! --release -p fricosc --test library stress`.

use fricosc::{Shape, DEFAULT_TOL};

/// The edge velocities: zero, denormal-small, `1 -+ 2^-52`, huge.
const EDGE_VBAR: [f64; 9] = [0.0, 5e-324, 1e-300, 1e-16, 1.0 - f64::EPSILON, 1.0, 1.0 + f64::EPSILON, 1e300, f64::MAX];
/// The edge amplitudes: zero, tiny, `1 -+ 1e-15`, huge.
const EDGE_AMP: [f64; 9] = [0.0, 5e-324, 2.2e-308, 1e-300, 1.0 - 1e-15, 1.0 + 1e-15, 1e300, 1e308, f64::MAX];
/// Points per line of constant amplitude (the monotonicity check).
const LINE: usize = 16;
/// Slack for monotonicity: the solvers' absolute accuracy.
const MONOTONE_SLACK: f64 = 1e-13;

/// What a run checked, and every failure described.
struct Report {
    points: usize,
    oscillation_points: usize,
    failures: Vec<String>,
}

/// `f` over `jobs` on every core (`std::thread::scope`), the outputs in order.
fn on_threads<T: Sync>(jobs: &[T], f: impl Fn(&T) -> Vec<String> + Sync) -> Vec<String> {
    let threads = std::thread::available_parallelism().map_or(2, usize::from);
    let chunk = jobs.len().div_ceil(threads).max(1);
    std::thread::scope(|s| {
        let handles: Vec<_> =
            jobs.chunks(chunk).map(|c| s.spawn(|| c.iter().flat_map(&f).collect::<Vec<String>>())).collect();
        handles.into_iter().flat_map(|h| h.join().unwrap_or_else(|_| vec!["a thread panicked".into()])).collect()
    })
}

fn env(name: &str, default: u64) -> u64 {
    std::env::var(name).ok().and_then(|v| v.parse().ok()).unwrap_or(default)
}

#[test]
fn random_and_edge_points_pass_every_check() {
    let points = env("FRICOSC_STRESS_POINTS", 100_000) as usize;
    let r = check(points, env("FRICOSC_STRESS_SEED", 7), &default_shapes());
    assert!(r.points >= points);
    // Oscillation in the sliding direction too: a hundredth as many.
    assert!(r.oscillation_points >= points / 100, "{}", r.oscillation_points);
    assert!(
        r.failures.is_empty(),
        "{} failures, the first: {:#?}",
        r.failures.len(),
        &r.failures[..r.failures.len().min(20)]
    );
}

/// splitmix64: a small, well-mixed generator for reproducible points.
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }
    fn unit(&mut self) -> f64 {
        (self.next() >> 11) as f64 / (1u64 << 53) as f64
    }
    fn pick<T: Copy>(&mut self, xs: &[T]) -> T {
        xs[(self.next() % xs.len() as u64) as usize]
    }
}

/// One line: an amplitude and sorted velocities, a mix of edges and random values.
fn line(rng: &mut Rng) -> (f64, Vec<f64>) {
    let amp = match rng.next() % 6 {
        0 => rng.pick(&EDGE_AMP),
        1 => 10f64.powf(-6.0 + 12.0 * rng.unit()),
        2 => 3.0 * rng.unit(),
        3 => 1.0 + (rng.unit() - 0.5) * 10f64.powf(-15.0 * rng.unit()),
        // s = 1/amp exactly at +-sqrt(1 - vbar^2) for some vbar of the line.
        _ => 1.0 / (1.0 - (0.99 * rng.unit()).powi(2)).sqrt(),
    };
    let mut v: Vec<f64> = (0..LINE)
        .map(|k| match (k + (rng.next() % 4) as usize) % 4 {
            0 => rng.pick(&EDGE_VBAR),
            1 => 1.2 * rng.unit(),
            2 => 1.0 - 10f64.powf(-15.0 * rng.unit()),
            _ => 10f64.powf(-16.0 * rng.unit()),
        })
        .collect();
    if amp > 1.0 && amp.is_finite() {
        // The slip-first / stick-first switch of the flat punch: 1/amp = sqrt(1 - vbar^2).
        v[0] = (1.0 - 1.0 / (amp * amp)).sqrt();
    }
    v.sort_by(f64::total_cmp);
    (amp, v)
}

/// Run about `points` points (rounded up to whole lines) over the shapes, in parallel.
fn check(points: usize, seed: u64, shapes: &[Shape]) -> Report {
    let lines_per_shape = points.div_ceil(LINE * shapes.len().max(1));
    let jobs: Vec<(usize, u64)> =
        (0..shapes.len()).flat_map(|s| (0..lines_per_shape as u64).map(move |l| (s, l))).collect();
    let failures = on_threads(&jobs, |&(si, l)| {
        let shape = &shapes[si];
        let mut rng = Rng(seed ^ (l.wrapping_mul(0x2545_F491_4F6C_DD1D)) ^ ((si as u64) << 56));
        let (amp, vs) = line(&mut rng);
        let mut out = vec![];
        let mut prev: Option<(f64, f64)> = None;
        for &v in &vs {
            let res = std::panic::catch_unwind(|| fricosc::Conditions::vbar(v, amp).and_then(|c| shape.evaluate(&c)));
            let here = format!("{} vbar={v:e} amp={amp:e}", shape.name());
            match res {
                Err(_) => out.push(format!("{here}: panicked")),
                Ok(Err(e)) => out.push(format!("{here}: error {e}")),
                Ok(Ok(e)) => {
                    let (m, r) = (e.ratio.mu_ratio, e.ratio.reduction);
                    if !m.is_finite() || !r.is_finite() {
                        out.push(format!("{here}: non-finite {m} {r}"));
                    } else if !(0.0..=1.0).contains(&m) || r < 0.0 {
                        out.push(format!("{here}: out of range mu {m} reduction {r}"));
                    } else if (m + r - 1.0).abs() > 2.0 * f64::EPSILON {
                        out.push(format!("{here}: reduction {r} != 1 - mu {m}"));
                    } else {
                        if let Some((pv, pm)) = prev {
                            if m < pm - MONOTONE_SLACK {
                                out.push(format!("{here}: mu {m} < {pm} at smaller vbar {pv:e}"));
                            }
                        }
                        prev = Some((v, m));
                    }
                }
            }
        }
        out
    });
    // A hundredth as many points under oscillation in the sliding direction:
    // each is evaluated six times (continuity and periodicity), and a curved
    // one costs about ten of the seed's.
    let (oscillation_points, more) = run_oscillation(points.div_ceil(100), seed, shapes);
    let failures: Vec<String> = failures.into_iter().chain(more).collect();
    Report { points: jobs.len() * LINE, oscillation_points, failures }
}

/// Edge values of the tangential amplitude `T`: tiny, `1 -+` rounding (where
/// backward slip starts for the flat punch), the largest accepted.
const EDGE_T: [f64; 6] = [5e-324, 1e-300, 1.0 - f64::EPSILON, 1.0, 1.0 + f64::EPSILON, 1e6];

/// About `points` random and edge points under oscillation in the sliding
/// direction over `shapes`: how many were run, and the failures described.
fn run_oscillation(points: usize, seed: u64, shapes: &[Shape]) -> (usize, Vec<String>) {
    let per_shape = points.div_ceil(shapes.len().max(1));
    let jobs: Vec<(usize, u64)> = (0..shapes.len()).flat_map(|s| (0..per_shape as u64).map(move |k| (s, k))).collect();
    let failures = on_threads(&jobs, |&(si, k)| {
        let shape = &shapes[si];
        let mut rng = Rng(!seed ^ k.wrapping_mul(0x9E37_79B9_7F4A_7C15) ^ ((si as u64) << 48));
        let (vhat, amp, t, phase) = if rng.next().is_multiple_of(4) { degenerate(&mut rng) } else { drive(&mut rng) };
        let here = format!("{} vhat={vhat:e} amp={amp:e} T={t:e} phase={phase:e}", shape.name());
        let eval = |v: f64, a: f64, tt: f64, p: f64| {
            std::panic::catch_unwind(|| {
                fricosc::Conditions::vhat(v, a).and_then(|c| c.with_tangential(tt, p)).and_then(|c| shape.evaluate(&c))
            })
        };
        let mut out = vec![];
        let base = match eval(vhat, amp, t, phase) {
            Err(_) => return vec![format!("{here}: panicked")],
            Ok(Err(e)) => return vec![format!("{here}: error {e}")],
            Ok(Ok(e)) => e,
        };
        let (m, r, est) = (base.ratio.mu_ratio, base.ratio.reduction, base.error_estimate);
        if !m.is_finite() || !r.is_finite() || !(-1.0..=1.0).contains(&m) || !(0.0..=2.0).contains(&r) {
            out.push(format!("{here}: out of range mu {m} reduction {r}"));
        } else if (m + r - 1.0).abs() > 2.0 * est + 4.0 * f64::EPSILON {
            out.push(format!("{here}: mu {m} + reduction {r} != 1 (estimate {est:e})"));
        }
        // The same a period later, and continuous in every parameter.
        let step = 1e-12;
        for (what, v, a, tt, p, bound) in [
            ("phase + 2 pi", vhat, amp, t, phase + std::f64::consts::TAU, 1e-9),
            ("vhat", vhat * (1.0 + step), amp, t, phase, 1e-5),
            ("amp", vhat, amp * (1.0 + step), t, phase, 1e-5),
            ("T", vhat, amp, t * (1.0 + step), phase, 1e-5),
            ("phase", vhat, amp, t, phase + step, 1e-5),
        ] {
            if let Ok(Ok(e)) = eval(v, a, tt, p) {
                let d = (e.ratio.mu_ratio - m).abs();
                if d > bound + 2.0 * (est + e.error_estimate) {
                    out.push(format!("{here}: {what} moved mu by {d:e} ({m} -> {})", e.ratio.mu_ratio));
                }
            }
        }
        out
    });
    (jobs.len(), failures)
}

/// A random drive: edges and random values of each parameter.
fn drive(rng: &mut Rng) -> (f64, f64, f64, f64) {
    let amp = match rng.next() % 4 {
        0 => rng.pick(&[0.0, 5e-324, 1.0 - 1e-15, 1.0, 1.0 + 1e-15, 1e6]),
        1 => 1.0 + (rng.unit() - 0.5) * 10f64.powf(-12.0 * rng.unit()),
        _ => 3.0 * rng.unit(),
    };
    let t = match rng.next() % 4 {
        0 => rng.pick(&EDGE_T),
        1 => 10f64.powf(-6.0 + 9.0 * rng.unit()),
        _ => 4.0 * rng.unit(),
    };
    let vhat = match rng.next() % 4 {
        0 => rng.pick(&[0.0, 5e-324, 1e-12, t, 1e6]),
        1 => (t * (1.0 + (rng.unit() - 0.5) * 10f64.powf(-12.0 * rng.unit()))).min(1e6),
        _ => 2.0 * rng.unit(),
    };
    let phase = match rng.next() % 3 {
        0 => rng.pick(&[0.0, -1e-300, std::f64::consts::FRAC_PI_2, std::f64::consts::PI, -0.0]),
        _ => std::f64::consts::TAU * rng.unit(),
    };
    (vhat, amp, t, phase)
}

/// A drive on or near the degenerate family (`vhat ~ 0`, `T ~ amp`, phase `~
/// pi/2` or `3 pi/2`, where every spring rides on a bound): each parameter
/// exact, a few ulps off, or up to 1e-12 off.
fn degenerate(rng: &mut Rng) -> (f64, f64, f64, f64) {
    let ulps = |rng: &mut Rng, x: f64| {
        let k = (rng.next() % 7) as i64 - 3;
        f64::from_bits((x.to_bits() as i64 + k) as u64)
    };
    let amp = match rng.next() % 3 {
        0 => rng.pick(&[0.3, 1.0, 2.0]),
        _ => 3.0 * rng.unit(),
    };
    let near = |rng: &mut Rng, x: f64| match rng.next() % 3 {
        0 => x,
        1 => ulps(rng, x),
        _ => x * (1.0 + (rng.unit() - 0.5) * 2e-12),
    };
    let t = near(rng, amp);
    let family = rng.pick(&[std::f64::consts::FRAC_PI_2, 1.5 * std::f64::consts::PI]);
    let phase = near(rng, family);
    let small = 1e-12 * rng.unit();
    let vhat = rng.pick(&[0.0, 5e-324, 1e-15, small]);
    (vhat, amp, t, phase)
}

/// The shapes of the stress run: flat, parabolic, cone and two other power laws.
fn default_shapes() -> Vec<Shape> {
    // Constant names that parse.
    ["flat", "parabolic", "cone", "power:0.5", "power:3.7", "flat-tip:0.5"]
        .iter()
        .filter_map(|s| Shape::parse(s).ok())
        .collect()
}

fn mu(n: f64, v: f64, a: f64) -> f64 {
    let c = fricosc::Conditions::vbar(v, a).and_then(|c| c.with_tol(DEFAULT_TOL)).unwrap();
    fricosc::Shape::power(n).unwrap().ratio(&c).unwrap().mu_ratio
}

/// Jumps of mu across a boundary at distance d on both sides: Lipschitz part
/// (|dmu/dx| < 10 here) plus the solver's accuracy.
fn assert_continuous(what: &str, f: impl Fn(f64) -> f64, x0: f64) {
    for d in [1e-6, 1e-9, 1e-12] {
        let jump = (f(x0 + d) - f(x0 - d)).abs();
        assert!(jump <= 20.0 * d + 2e-13, "{what} at {x0} +- {d:e}: jump {jump:e}");
    }
}

#[test]
fn mdr_is_continuous_across_every_regime_boundary() {
    for n in [1.0, 2.0, 3.7] {
        for v in [1e-3, 0.3, 0.8, 0.999] {
            // amp = 1: the permanent-contact band vanishes.
            assert_continuous(&format!("n={n} v={v} amp"), |a| mu(n, v, a), 1.0);
        }
        for a in [0.3, 1.0, 2.5] {
            // vbar = 1: the stick band vanishes.
            assert_continuous(&format!("n={n} a={a} vbar"), |v| mu(n, v, a), 1.0);
        }
        for a in [1.2f64, 3.0] {
            // amp sqrt(1 - vbar^2) = 1: the stick-first band reaches the centre.
            let v0 = (1.0 - 1.0 / (a * a)).sqrt();
            assert_continuous(&format!("n={n} a={a} centre switch"), |v| mu(n, v, a), v0);
        }
    }
}

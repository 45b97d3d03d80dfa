//! `fricosc stress`: many points, random and on every edge, checked for what
//! must always hold: no panic, finite results, `0 <= mu_ratio <= 1`,
//! `reduction >= 0` and `= 1 - mu_ratio` to rounding, and `mu_ratio`
//! nondecreasing in `vbar` along lines of constant amplitude.

use crate::shape::Shape;
use rayon::prelude::*;
use serde::Serialize;
use std::time::Instant;

/// The edge velocities of issue 8: zero, denormal-small, `1 -+ 2^-52`, huge.
pub const EDGE_VBAR: [f64; 9] =
    [0.0, 5e-324, 1e-300, 1e-16, 1.0 - f64::EPSILON, 1.0, 1.0 + f64::EPSILON, 1e300, f64::MAX];
/// The edge amplitudes: zero, tiny, `1 -+ 1e-15`, huge.
pub const EDGE_AMP: [f64; 9] = [0.0, 5e-324, 2.2e-308, 1e-300, 1.0 - 1e-15, 1.0 + 1e-15, 1e300, 1e308, f64::MAX];
/// Points per line of constant amplitude (the monotonicity check).
const LINE: usize = 16;
/// Slack for monotonicity: the solvers' absolute accuracy.
const MONOTONE_SLACK: f64 = 1e-13;

/// Summary of a stress run.
#[derive(Debug, Clone, Serialize)]
pub struct StressReport {
    /// Points evaluated.
    pub points: usize,
    /// Lines of constant amplitude checked for monotonicity.
    pub lines: usize,
    /// Shapes covered.
    pub shapes: Vec<String>,
    /// Number of failed checks.
    pub failure_count: usize,
    /// The first failures (up to 20), described.
    pub failures: Vec<String>,
    /// Wall time, seconds.
    pub time_s: f64,
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
pub fn run(points: usize, seed: u64, shapes: &[Shape]) -> StressReport {
    let t0 = Instant::now();
    let lines_per_shape = points.div_ceil(LINE * shapes.len().max(1));
    let jobs: Vec<(usize, u64)> =
        (0..shapes.len()).flat_map(|s| (0..lines_per_shape as u64).map(move |l| (s, l))).collect();
    let failures: Vec<String> = jobs
        .par_iter()
        .flat_map_iter(|&(si, l)| {
            let shape = &shapes[si];
            let mut rng = Rng(seed ^ (l.wrapping_mul(0x2545_F491_4F6C_DD1D)) ^ ((si as u64) << 56));
            let (amp, vs) = line(&mut rng);
            let mut out = vec![];
            let mut prev: Option<(f64, f64)> = None;
            for &v in &vs {
                let res = std::panic::catch_unwind(|| shape.evaluate(v, amp));
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
        })
        .collect();
    StressReport {
        points: jobs.len() * LINE,
        lines: jobs.len(),
        shapes: shapes.iter().map(|s| s.name().to_string()).collect(),
        failure_count: failures.len(),
        failures: failures.into_iter().take(20).collect(),
        time_s: t0.elapsed().as_secs_f64(),
    }
}

/// The shapes of the stress run: flat, parabolic, cone and two other power laws.
pub fn default_shapes() -> Vec<Shape> {
    // Constant names that parse.
    ["flat", "parabolic", "cone", "power:0.5", "power:3.7", "flat-tip:0.5"]
        .iter()
        .filter_map(|s| Shape::parse(s).ok())
        .collect()
}

//! A sampled periodic signal: its period from the normal force, its first
//! harmonic, periodic mean, time origin and drift between periods.

use super::*;

/// How close (in sample spacings) a time origin must be to a multiple of
/// `pi/2` to be taken as that convention exactly.
pub(super) const SNAP_SAMPLES: f64 = 0.01;

/// The period of a history (in units of `t`) from its normal force: the mean
/// spacing of its crossings of the mid-level `(min + max)/2` in the same
/// direction (interpolated linearly), upward and downward ones pooled.
pub(super) fn period_from_normal(t: &[f64], n: &[f64]) -> Result<f64> {
    let bad = |reason: &str| Error::Parse { context: "history".into(), reason: reason.into() };
    let (lo, hi) = n.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &x| (a.min(x), b.max(x)));
    if hi.partial_cmp(&lo) != Some(std::cmp::Ordering::Greater) {
        return Err(bad("the normal force is constant: the period cannot be found from it (give omega)"));
    }
    let mid = lo + 0.5 * (hi - lo);
    let (mut up, mut down) = (vec![], vec![]);
    for i in 1..n.len() {
        let (a, b) = (n[i - 1] - mid, n[i] - mid);
        if (a < 0.0) != (b < 0.0) {
            let at = t[i - 1] + (t[i] - t[i - 1]) * a / (a - b);
            if a < 0.0 { &mut up } else { &mut down }.push(at);
        }
    }
    let (mut span, mut count) = (0.0, 0usize);
    for c in [&up, &down] {
        if c.len() >= 2 {
            span += c[c.len() - 1] - c[0];
            count += c.len() - 1;
        }
    }
    if count == 0 || span.is_nan() || span <= 0.0 {
        return Err(bad(
            "the normal force crosses its mid-level fewer than twice in the same direction: the history is \
             shorter than about one period (give omega, or more periods)",
        ));
    }
    Ok(span / count as f64)
}

/// `(int y cos tau, int y sin tau)` over one period by the periodic trapezoid
/// rule on samples `(tau_i, y_i)` spanning less than a period (the last
/// interval wraps round from the last sample to the first plus `2 pi`).
pub(super) fn first_harmonic(taus: &[f64], y: &[f64]) -> (f64, f64) {
    let (mut c, mut s) = (0.0, 0.0);
    let n = taus.len();
    for i in 0..n {
        let j = (i + 1) % n;
        let width = if j == 0 { taus[0] + TAU - taus[n - 1] } else { taus[j] - taus[i] };
        let (si, ci) = taus[i].sin_cos();
        let (sj, cj) = taus[j].sin_cos();
        c += 0.5 * width * (y[i] * ci + y[j] * cj);
        s += 0.5 * width * (y[i] * si + y[j] * sj);
    }
    (c, s)
}

/// The periodic trapezoid mean of `y` over one period (as [`first_harmonic`]).
pub(super) fn periodic_mean(taus: &[f64], y: &[f64]) -> f64 {
    let n = taus.len();
    let mut sum = 0.0;
    for i in 0..n {
        let j = (i + 1) % n;
        let width = if j == 0 { taus[0] + TAU - taus[n - 1] } else { taus[j] - taus[i] };
        sum += 0.5 * width * (y[i] + y[j]);
    }
    sum / TAU
}

/// The offset `d` with `N_file(tau) = N(tau + d)`: every exact normal force is a
/// decreasing function of `cos tau`, so its first harmonic is `A cos tau` with
/// `A < 0` and no sine part; shifted by `d` it becomes
/// `A cos d cos tau - A sin d sin tau`, whence `d = atan2(b, -a)` from the file's
/// cosine and sine coefficients `a`, `b`. Snapped to a multiple of `pi/2`
/// within `snap` (the conventions of [`TimeOrigin::convention`]; 0: never).
/// `None` if the normal force has no first harmonic (it does not oscillate).
pub(super) fn origin_offset(taus: &[f64], normal: &[f64], snap: f64) -> Option<(f64, Option<&'static str>)> {
    let (a, b) = first_harmonic(taus, normal);
    let peak = normal.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    let size = a.hypot(b);
    if size.is_nan() || size <= 1e-9 * peak {
        return None;
    }
    let d = b.atan2(-a);
    let conventions = [
        (0.0, "u0 - du cos(omega t)"),
        (FRAC_PI_2, "u0 + du sin(omega t)"),
        (PI, "u0 + du cos(omega t)"),
        (-FRAC_PI_2, "u0 - du sin(omega t)"),
        (-PI, "u0 + du cos(omega t)"),
    ];
    for (at, name) in conventions {
        if (d - at).abs() <= snap {
            return Some((if at == -PI { PI } else { at }, Some(name)));
        }
    }
    Some((d, None))
}

/// Largest `|F(tau) - F(tau - 2 pi)|` over samples in `[from, to]`, the earlier
/// value interpolated linearly between the user's samples.
pub(super) fn drift(taus: &[f64], f: &[f64], from: f64, to: f64) -> Option<f64> {
    let at = |t: f64| -> Option<f64> {
        let j = taus.partition_point(|&x| x < t);
        if j == 0 || j >= taus.len() {
            return (j < taus.len() && taus[j] == t).then(|| f[j]);
        }
        let (t0, t1) = (taus[j - 1], taus[j]);
        if t1 == t0 {
            return Some(f[j]);
        }
        Some(f[j - 1] + (f[j] - f[j - 1]) * (t - t0) / (t1 - t0))
    };
    let mut worst: Option<f64> = None;
    for (i, &t) in taus.iter().enumerate() {
        if t > from && t <= to {
            if let Some(prev) = at(t - TAU) {
                worst = Some(worst.unwrap_or(0.0).max((f[i] - prev).abs()));
            }
        }
    }
    worst
}

/// How the last periods of a history drift (the largest change of a force
/// at the same phase, linear interpolation; in the plane of either force):
/// the last from the one before, the one before from its own, whether the
/// last is within `bar`, and the periods still needed for that.
pub(super) struct Drifts {
    pub(super) last: Option<f64>,
    pub(super) previous: Option<f64>,
    pub(super) periodic: Option<bool>,
    pub(super) needed: Option<f64>,
}

impl Drifts {
    pub(super) fn of(
        taus: &[f64],
        data: &super::HistoryData,
        (start, end): (f64, f64),
        periods: usize,
        bar: f64,
    ) -> Drifts {
        let worst = |from: f64, to: f64| {
            let of = |f: &[f64]| drift(taus, f, from, to);
            match data.transverse {
                Some(y) => of(data.tangential).zip(of(y)).map(|(a, b)| a.max(b)),
                None => of(data.tangential),
            }
        };
        let last = (periods >= 2).then(|| worst(start, end)).flatten();
        let previous = (periods >= 3).then(|| worst(start - TAU, start)).flatten();
        let needed = match (last, previous) {
            (Some(d), _) if d <= bar => Some(0.0),
            (Some(d), Some(p)) if d < p && d > 0.0 => Some(((bar / d).ln() / (d / p).ln()).ceil()),
            _ => None,
        };
        Drifts { last, previous, periodic: last.map(|d| d <= bar), needed }
    }
}

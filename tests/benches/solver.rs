//! Criterion benchmarks of the hot paths. `cargo bench --bench solver`
use criterion::{criterion_group, criterion_main, Criterion};
use std::hint::black_box;

fn flat(c: &mut Criterion) {
    // A sweep over regimes: permanent contact, jumping stick-first and slip-first.
    let points: Vec<(f64, f64)> =
        (0..100).map(|i| ((i % 10) as f64 / 10.0 + 0.05, [0.5, 1.5, 3.0, 0.9][i % 4])).collect();
    c.bench_function("flat point (mean over 100 regimes mix)", |b| {
        b.iter(|| {
            let mut acc = 0.0;
            for &(v, a) in &points {
                acc += fricosc::flat::ratio(black_box(v), black_box(a)).unwrap().mu_ratio;
            }
            acc
        })
    });
}

fn parabolic(c: &mut Criterion) {
    c.bench_function("parabolic point (vbar 0.3, amp 0.4)", |b| {
        b.iter(|| fricosc::mdr::power_law(2.0, black_box(0.3), black_box(0.4), &fricosc::Options::default()))
    });
}

fn parabolic_table(c: &mut Criterion) {
    // The seed's Fig. 7 grid, refined: 11 amplitudes x 1001 velocities, one thread.
    let mut g = c.benchmark_group("table");
    g.sample_size(10);
    g.bench_function("parabolic 11 x 1001 (one thread)", |b| {
        b.iter(|| {
            let mut acc = 0.0;
            for i in 0..11 {
                for j in 0..1001 {
                    let (a, v) = (i as f64 / 10.0, j as f64 / 1000.0);
                    acc += fricosc::mdr::power_law(2.0, v, a, &fricosc::Options::default()).unwrap().ratio.mu_ratio;
                }
            }
            acc
        })
    });
    g.finish();
}

criterion_group! {
    name = benches;
    config = Criterion::default().measurement_time(std::time::Duration::from_secs(3));
    targets = flat, parabolic, parabolic_table
}
criterion_main!(benches);

fn main() {
    // MDR stepper vs exact: springs at midpoints of a z grid.
    for (n, v, a) in [(2.0, 0.3, 0.4), (2.0, 0.6, 1.0), (2.0, 0.3, 1.6), (1.0, 0.5, 2.0), (2.0, 0.95, 0.5)] {
        let exact = fricosc::mdr::power_law(n, v, a, 0.0, false).ratio.mu_ratio;
        for (nz, m) in [(1000usize, 1000usize), (4000, 4000)] {
            let zmax = (1.0f64 + a).powf(1.0 / n);
            let dz = zmax / nz as f64;
            let s: Vec<f64> = (0..nz).map(|i| (1.0 - ((i as f64 + 0.5) * dz).powf(n)) / a).collect();
            let w = vec![dz; nz];
            let t = std::time::Instant::now();
            let r = fricosc::stepper::run(&s, &w, v, m, 2);
            println!("n={n} v={v} a={a} nz={nz} m={m}: err {:.2e} ({:?})", r.mu_ratio() - exact, t.elapsed());
        }
    }
}

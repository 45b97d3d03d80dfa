fn main() {
    for (v, a) in [
        (0.3, 0.4),
        (0.6, 1.0),
        (0.3, 1.6),
        (0.05, 0.5),
        (0.95, 0.999),
        (0.5, 1.001),
    ] {
        let t = std::time::Instant::now();
        let mut acc = 0.0;
        let mut nodes = 0;
        for i in 0..2000 {
            let r = fricosc::mdr::power_law(2.0, v + i as f64 * 1e-7, a, 0.0, false);
            acc += r.ratio.mu_ratio;
            nodes = r.nodes;
        }
        println!("v={v} a={a}: {:?} per point, nodes {nodes} ({acc})", t.elapsed() / 2000);
    }
}

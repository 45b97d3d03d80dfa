fn main() {
    let mut acc = 0.0;
    for (v, a) in [(0.3, 0.4), (0.6, 1.0), (0.3, 1.6), (0.05, 0.5)] {
        for i in 0..200 {
            acc += fricosc::mdr::power_law(2.0, v + i as f64 * 1e-4, a, 0.0, false)
                .ratio
                .mu_ratio;
        }
    }
    println!("{acc}");
}

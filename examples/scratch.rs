fn main() {
    for (v, a, m) in [(0.2,0.5,0.7145191049466343399125),(0.5,0.5,0.8992738983331656556021),(0.9,0.5,0.9963445948327358966227),(0.2,1.0,0.429038209893268679825),(0.2,1.5,0.3786084673826043104487),(0.05,2.0,0.1085962363920461505086),(0.999,0.6,0.9999995701956780449534)] {
        let p = fricosc::flat::point(v, a).unwrap();
        println!("{v} {a} err {:e} evals {} {:?}", p.ratio.mu_ratio - m, p.root_evaluations, p.regime);
        let r = fricosc::spring::Spring::new(1.0/a, v);
        println!("   means evals {}", r.root_evaluations);
    }
}

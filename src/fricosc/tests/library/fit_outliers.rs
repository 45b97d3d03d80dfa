//! The outlier threshold grows with the number of rows, so that rows whose
//! errors are normal are named outlying with probability at most 1 %.

use crate::fit::{normals, synthetic};
use fricosc::fit::{fit, outlier_threshold, Fixed, Measurement};
use fricosc::Shape;

/// The size a standard normal exceeds with probability `0.01/n`, from
/// mpmath (`sqrt(2) erfinv(1 - 0.01/n)`, 30 digits), at least 3.5.
#[test]
fn the_threshold_is_the_normal_quantile_of_a_one_percent_false_alarm() {
    for (rows, want) in [
        (0, 3.5),
        (1, 3.5),
        (21, 3.5),
        (22, 3.50620472661722222345669145225),
        (27, 3.56034323196460256741964674995),
        (1000, 4.41717341346902210674093250548),
        (1_000_000, 5.73072886823628965007597877103),
    ] {
        let got = outlier_threshold(rows);
        assert!((got - want).abs() <= 1e-12 * want, "{rows} rows: {got} vs {want}");
    }
}

/// Among 999 rows (the synthetic flat rows 37 times, normal noise of
/// sigma), one row 4 sigma off is not named (a fixed 3.5 would name it, and
/// about one normal row in 2,000 with it), one 5.5 sigma off is.
#[test]
fn among_many_rows_the_threshold_is_the_rows_one() {
    let mut normal = normals(777);
    // The generator's first draws from a small seed are not yet random.
    for _ in 0..20 {
        normal();
    }
    let exact = synthetic();
    let mut rows: Vec<Measurement> = (0..37)
        .flat_map(|_| exact.clone())
        .map(|m| Measurement { mu: m.mu + 0.002 * normal(), sigma: Some(0.002), ..m })
        .collect();
    rows[5].mu = exact[5].mu + 4.0 * 0.002;
    rows[6].mu = exact[6].mu + 5.5 * 0.002;
    let r = fit(&Shape::flat(), &rows, &Fixed::default()).unwrap();
    assert_eq!(r.outlier_threshold, outlier_threshold(999));
    assert!(r.normalised_residuals[5] > 3.5 && r.normalised_residuals[5] < 4.4, "{}", r.normalised_residuals[5]);
    assert_eq!(r.outliers, vec![6], "{:?}", &r.normalised_residuals[..8]);
}

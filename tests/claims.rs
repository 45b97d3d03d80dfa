//! Each verdict of `fricosc claims` is asserted: a solver change that flips one fails here.
use fricosc::claims::{check, Verdict};

#[test]
fn every_claim_keeps_its_verdict() {
    let claims = check();
    let get = |prefix: &str| claims.iter().find(|c| c.claim.starts_with(prefix)).unwrap_or_else(|| panic!("{prefix}"));
    let expect = [
        ("eq. 8", Verdict::Misprint),
        ("eq. 11", Verdict::Approximation),
        ("eq. 12", Verdict::Holds),
        ("eq. 21", Verdict::Misprint),
        ("eq. 22", Verdict::Misprint),
        ("Fig. 5 inset", Verdict::Approximation),
        ("eq. 28", Verdict::Approximation),
        ("eq. 26", Verdict::Holds),
        ("eq. 27", Verdict::Approximation),
        ("section 2", Verdict::Holds),
    ];
    assert_eq!(claims.len(), expect.len());
    for (prefix, verdict) in expect {
        assert_eq!(get(prefix).verdict, verdict, "{prefix}: {:?}", get(prefix));
    }
    // The numbers behind the verdicts (MODEL.md: eq. 11 is off by up to 0.0144 amp near vbar 0.1).
    let e11 = get("eq. 11").deviation.unwrap();
    assert!((0.0140..0.0148).contains(&e11), "{e11}");
    assert!(get("eq. 11").location.starts_with("vbar = 0.1"));
    let e28 = get("eq. 28").deviation.unwrap();
    assert!((0.0150..0.0160).contains(&e28), "eq. 28 differs from eq. 27 by {e28}, not 1 %");
    assert!(get("eq. 21").exact_gives.contains("3.14159"));
    // The limit drop is 1 - pi/4 = 21.46 %; the slope first dips lower (about 27 % near amp = 2).
    assert!(get("Fig. 5 inset").exact_gives.contains("21.46 %"));
    let extra = get("Fig. 5 inset").deviation.unwrap();
    assert!((0.05..0.09).contains(&extra), "{extra}");
}

#[test]
fn markdown_has_a_row_per_claim() {
    let md = fricosc::claims::to_markdown(&check());
    assert_eq!(md.lines().count(), 2 + check().len());
}

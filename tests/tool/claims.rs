//! `fricosc claims`: the report's forms (Markdown wrapped to its width, CSV)
//! hold every claim of [`fricosc::seed::claims`] and every field; the claims'
//! measurements are tested in the library's tests.
use fricosc::seed::claims;

#[test]
fn the_markdown_table_has_a_row_per_claim() {
    let cs = claims();
    use fricosc_cli::export::{export, Format};
    let md = export(&cs, Format::Markdown).unwrap();
    assert_eq!(md.lines().count(), 2 + cs.len());
}

/// The Markdown report fits a 100-column terminal and says everything the
/// claims hold: each verdict with its criterion, each deviation with its definition.
#[test]
fn markdown_is_wrapped_and_complete() {
    let cs = claims();
    let md = fricosc_cli::claims::markdown(&cs);
    for line in md.lines() {
        assert!(line.chars().count() <= fricosc_cli::claims::WIDTH, "too long: {line}");
    }
    let flat: String = md.split_whitespace().collect::<Vec<_>>().join(" ");
    for (i, c) in cs.iter().enumerate() {
        let verdict = c.verdict.name();
        assert!(md.contains(&format!("| {} | {} | {verdict} |", i + 1, c.claim)), "{}", c.claim);
        for part in [&c.seed_says, &c.exact_gives, &c.deviation_is, &c.criterion] {
            let part = part.split_whitespace().collect::<Vec<_>>().join(" ");
            assert!(flat.contains(&part), "{}: '{part}' missing", c.claim);
        }
    }
}

/// The CSV form holds every field, and the deviations read back bit for bit.
#[test]
fn csv_round_trips() {
    let cs = claims();
    let text = fricosc_cli::export::export(&cs, fricosc_cli::export::Format::Csv).unwrap();
    let mut reader = csv::Reader::from_reader(text.as_bytes());
    let header: Vec<String> = reader.headers().unwrap().iter().map(String::from).collect();
    assert_eq!(
        header,
        ["claim", "seed_says", "exact_gives", "deviation", "deviation_is", "location", "criterion", "verdict"]
    );
    let rows: Vec<csv::StringRecord> = reader.records().map(Result::unwrap).collect();
    assert_eq!(rows.len(), cs.len());
    for (r, c) in rows.iter().zip(&cs) {
        assert_eq!(&r[0], c.claim);
        assert_eq!(&r[1], c.seed_says);
        assert_eq!(&r[2], c.exact_gives);
        assert_eq!(r[3].parse::<f64>().ok(), c.deviation, "{}", c.claim);
        assert_eq!(&r[4], c.deviation_is);
        assert_eq!(&r[5], c.location);
        assert_eq!(&r[6], c.criterion);
        assert_eq!(&r[7], c.verdict.name());
    }
}

#[test]
fn wrap_breaks_at_words_within_the_width() {
    use fricosc_cli::claims::wrap;
    assert_eq!(wrap("- a:", "one two three", "  ", 9), "- a: one\n  two\n  three\n");
    // A word longer than the width stands alone on its line.
    assert_eq!(wrap("-", "x abcdefghijkl y", " ", 5), "- x\n abcdefghijkl\n y\n");
}

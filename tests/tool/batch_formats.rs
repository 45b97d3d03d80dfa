//! `batch` in its three formats: a JSON array, JSON Lines and CSV (the last two
//! streamed in two passes, or one for an input of one chunk). The same rows give bit-identical results in every
//! format; other fields and columns are kept; a bad row anywhere leaves stdout
//! empty; stdin's spool file is removed.
use crate::common::run as cli;

use std::process::Output;

fn fricosc(args: &[&str], stdin: &str) -> (Output, u32) {
    cli::run_with_id(args, Some(stdin))
}

fn ok(args: &[&str], stdin: &str) -> String {
    let (out, id) = fricosc(args, stdin);
    assert!(out.status.success(), "{args:?}: {}", String::from_utf8_lossy(&out.stderr));
    // Nothing left in the temporary directory by this run.
    let prefix = format!("fricosc-batch-{id}-");
    let left = std::fs::read_dir(std::env::temp_dir())
        .unwrap()
        .filter_map(|e| e.ok())
        .any(|e| e.file_name().to_string_lossy().starts_with(&prefix));
    assert!(!left, "spool file left behind");
    String::from_utf8(out.stdout).unwrap()
}

fn refused(args: &[&str], stdin: &str, needle: &str) {
    let (out, _) = fricosc(args, stdin);
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{args:?}: {err}");
    assert!(out.stdout.is_empty(), "{args:?}: partial output");
    assert!(err.contains(needle) && err.lines().count() == 1, "{args:?}: {err}");
}

/// A few hundred rows over every regime and three shapes.
fn rows() -> Vec<(&'static str, f64, f64)> {
    let mut v = vec![];
    for (k, shape) in ["flat", "parabolic", "cone"].iter().enumerate() {
        for i in 0..60 {
            v.push((*shape, (i % 13) as f64 * 0.1 + 0.013 * k as f64, (i % 7) as f64 * 0.5));
        }
    }
    v
}

#[test]
fn three_formats_give_bit_identical_results() {
    let r = rows();
    let json = format!(
        "[{}]",
        r.iter()
            .map(|(s, v, a)| format!(r#"{{"shape":"{s}","vbar":{v:?},"amp":{a:?}}}"#))
            .collect::<Vec<_>>()
            .join(",")
    );
    let lines: String =
        r.iter().map(|(s, v, a)| format!("{{\"shape\":\"{s}\",\"vbar\":{v:?},\"amp\":{a:?}}}\n")).collect();
    let csv: String =
        "shape,vbar,amp\n".to_string() + &r.iter().map(|(s, v, a)| format!("{s},{v:?},{a:?}\n")).collect::<String>();
    let from_json: Vec<serde_json::Value> = serde_json::from_str(&ok(&["batch"], &json)).unwrap();
    let from_lines: Vec<serde_json::Value> =
        ok(&["batch", "--format", "jsonl"], &lines).lines().map(|l| serde_json::from_str(l).unwrap()).collect();
    let out = ok(&["batch", "--format", "csv"], &csv);
    let mut reader = csv::Reader::from_reader(out.as_bytes());
    assert_eq!(reader.headers().unwrap(), vec!["shape", "vbar", "amp", "mu_ratio", "reduction"]);
    let from_csv: Vec<csv::StringRecord> = reader.records().map(Result::unwrap).collect();
    assert_eq!((from_json.len(), from_lines.len(), from_csv.len()), (r.len(), r.len(), r.len()));
    for ((j, l), c) in from_json.iter().zip(&from_lines).zip(&from_csv) {
        assert_eq!(j, l);
        for (k, name) in [(3, "mu_ratio"), (4, "reduction")] {
            let x: f64 = c[k].parse().unwrap();
            assert_eq!(x.to_bits(), j[name].as_f64().unwrap().to_bits(), "{j}");
        }
    }
    // Files: the format from the extension, the same answer.
    // Removed when dropped, also when the test fails.
    let scratch = tempfile::Builder::new().prefix("fricosc-formats-").tempdir().unwrap();
    let dir = scratch.path().to_path_buf();
    let (fl, fc) = (dir.join("rows.jsonl"), dir.join("rows.csv"));
    std::fs::write(&fl, &lines).unwrap();
    std::fs::write(&fc, &csv).unwrap();
    assert_eq!(ok(&["batch", fl.to_str().unwrap()], ""), ok(&["batch", "--format", "jsonl"], &lines));
    assert_eq!(ok(&["batch", fc.to_str().unwrap()], ""), out);
}

#[test]
fn json_lines_keep_bytes_skip_blank_lines_and_replace_results() {
    let input = "{\"id\": 1, \"shape\": \"flat\",  \"vbar\": 0.5, \"amp\": 2.0, \"x\": [1,  2]}  \n\n\r\n{\"shape\":\"flat\",\"vbar\":2,\"amp\":1,\"mu_ratio\":7}\r\n";
    let out = ok(&["batch", "--format", "jsonl"], input);
    let lines: Vec<&str> = out.lines().collect();
    assert_eq!(lines.len(), 2);
    assert!(lines[0]
        .starts_with("{\"id\": 1, \"shape\": \"flat\",  \"vbar\": 0.5, \"amp\": 2.0, \"x\": [1,  2],\"mu_ratio\":"));
    let second: serde_json::Value = serde_json::from_str(lines[1]).unwrap();
    assert_eq!((second["mu_ratio"].as_f64(), second["reduction"].as_f64()), (Some(1.0), Some(0.0)));
}

/// A row that already holds `mu_ratio` and `reduction` keeps every other
/// field byte for byte, in a JSON array and in JSON Lines: a 30-digit integer,
/// 23 significant digits, `-0`, `1e400`, a lone surrogate and deep nesting (the
/// fields were re-serialised: `1.2345678901234568e+29`, `0.1`, `-0.0`, and a
/// failure after output had started).
#[test]
fn fields_beside_replaced_results_pass_through_as_written() {
    let fields = r#""x":123456789012345678901234567890,"y":0.10000000000000000000001,"z":-0,"w":1e400,"s":"\ud800","d":[[[[[[[[{"k":[1]}]]]]]]]]"#;
    let row = format!(r#"{{"mu_ratio":7,{fields},"shape":"flat","vbar":0.5,"amp":2.0,"reduction":9}}"#);
    for (format, input) in [("jsonl", format!("{row}\n")), ("json", format!("[{row},{row}]"))] {
        let out = ok(&["batch", "--format", format], &input);
        let got = out.matches(fields).count();
        assert_eq!(got, if format == "json" { 2 } else { 1 }, "{format}: {out}");
        assert!(!out.contains(":7,") && !out.contains(":9}"), "{format}: results not replaced: {out}");
    }
}

/// A CSV error names the line as an editor counts it: with `\r\n`, lone `\r`,
/// blank lines and quoted line breaks (they were off by one, not counted, and
/// always line 1). Column names that differ only in spaces are ambiguous, and
/// an empty input has no header.
#[test]
fn csv_errors_name_the_line_and_the_header() {
    for (input, line) in [
        ("shape,vbar,amp\r\nflat,0.3,0.5\r\nflat,x,0.5\r\n", 3),
        ("shape,vbar,amp\n\nflat,0.3,0.5\n\nflat,x,0.5\n", 5),
        ("shape,vbar,amp\r\n\r\n\r\nflat,0.3,0.5\r\n\r\nflat,x,0.5\r\n", 6),
        ("shape,vbar,amp\rflat,0.3,0.5\r\rflat,x,0.5\r", 4),
        ("shape,note,vbar,amp\r\nflat,\"a\r\nb\nc\",0.3,0.5\r\n\r\nflat,\"x\",x,0.5\n", 6),
        ("shape,vbar,amp\nflat,x,0.5", 2),
    ] {
        refused(&["batch", "--format", "csv"], input, &format!("line {line}: 'vbar' is not a finite number"));
    }
    refused(&["batch", "--format", "csv"], "shape,vbar,amp\nflat,0.3,0.5\nflat,0.3\n", "line 3: 2 fields");
    refused(
        &["batch", "--format", "csv"],
        "shape,vbar, vbar,amp\nflat,0.3,0.4,0.5\n",
        "repeats the column 'vbar' and ' vbar'",
    );
    refused(&["batch", "--format", "csv"], "", "the input is empty: no header");
    refused(&["batch", "--format", "csv"], "\n\n", "the input is empty: no header");
}

/// A streamed CSV of exactly one chunk (65,536 rows) with more distinct
/// shapes than the cache holds (5,000 power laws for 4,096 places) gives
/// every row (it panicked with an index out of bounds).
#[test]
fn a_full_chunk_of_more_shapes_than_the_cache_holds() {
    let mut input = String::from("shape,vbar,amp\n");
    for i in 0..65_536 {
        input.push_str(&format!("power:{},0.3,0.5\n", 1.0 + (i % 5000) as f64 / 10_000.0));
    }
    let out = ok(&["batch", "--format", "csv"], &input);
    assert_eq!(out.lines().count(), 65_537);
    assert!(out.lines().nth(5001).unwrap().starts_with("power:1,0.3,0.5,"), "{:?}", out.lines().nth(5001));
}

#[test]
fn csv_keeps_columns_and_fills_given_result_columns() {
    let input = "id,shape,note,vbar,amp\n1,flat,\"a, b\",0.3,0.5\n2,cone,\"say \"\"hi\"\"\",0.2,2\n";
    let out = ok(&["batch", "--format", "csv"], input);
    let mut r = csv::Reader::from_reader(out.as_bytes());
    assert_eq!(r.headers().unwrap(), vec!["id", "shape", "note", "vbar", "amp", "mu_ratio", "reduction"]);
    let rows: Vec<csv::StringRecord> = r.records().map(Result::unwrap).collect();
    assert_eq!((&rows[0][2], &rows[1][2]), ("a, b", "say \"hi\""));
    // Result columns already there (in any order) are filled, not repeated.
    let given = "reduction,shape,vbar,amp,mu_ratio\n9,flat,0.3,0.5,9\n";
    let out = ok(&["batch", "--format", "csv"], given);
    let mut r = csv::Reader::from_reader(out.as_bytes());
    assert_eq!(r.headers().unwrap(), vec!["reduction", "shape", "vbar", "amp", "mu_ratio"]);
    let row = r.records().next().unwrap().unwrap();
    let (red, mu): (f64, f64) = (row[0].parse().unwrap(), row[4].parse().unwrap());
    let j: serde_json::Value =
        serde_json::from_str(&ok(&["batch", "--format", "jsonl"], "{\"shape\":\"flat\",\"vbar\":0.3,\"amp\":0.5}\n"))
            .unwrap();
    assert_eq!((mu, red), (j["mu_ratio"].as_f64().unwrap(), j["reduction"].as_f64().unwrap()));
}

#[test]
fn a_bad_row_anywhere_leaves_stdout_empty() {
    let mut lines: String =
        (0..100_000).map(|i| format!("{{\"shape\":\"flat\",\"vbar\":0.{i},\"amp\":1}}\n")).collect();
    lines.push_str("{\"shape\":\"flat\",\"vbar\":0.1}\n");
    refused(&["batch", "--format", "jsonl"], &lines, "line 100001: missing field 'amp'");
    refused(
        &["batch", "--format", "jsonl"],
        "{\"shape\":\"flat\",\"vbar\":0.1,\"amp\":1,}\n",
        "line 1: malformed JSON",
    );
    refused(&["batch", "--format", "jsonl"], "[1]\n", "line 1: malformed JSON: expected an object");
    refused(&["batch", "--format", "jsonl"], "{\"shape\":\"nope\",\"vbar\":0.1,\"amp\":1}\n", "line 1:");
    refused(
        &["batch", "--format", "jsonl"],
        "{\"shape\":\"flat\",\"vbar\":0.1,\"vbar\":1,\"amp\":1}\n",
        "duplicate key 'vbar'",
    );
    let long = format!("{{\"shape\":\"flat\",\"vbar\":0.1,\"amp\":1,\"x\":\"{}\"}}\n", "a".repeat(1 << 20));
    refused(&["batch", "--format", "jsonl"], &long, "bytes of line 1");
    let mut csv = "shape,vbar,amp\n".to_string() + &"flat,0.5,1\n".repeat(100_000);
    csv.push_str("flat,NaN,1\n");
    refused(&["batch", "--format", "csv"], &csv, "line 100002: 'vbar' is not a finite number");
    refused(&["batch", "--format", "csv"], "shape,vbar\nflat,0.1\n", "no column 'amp'");
    refused(&["batch", "--format", "csv"], "shape,vbar,amp,vbar\nflat,0.1,1,2\n", "repeats the column 'vbar'");
    refused(&["batch", "--format", "csv"], "shape,vbar,amp\nflat,0.1\n", "line 2: 2 fields where the header has 3");
    refused(&["batch", "--format", "csv"], "shape,vbar,amp,mu_ratio\nflat,0.1,1,2\n", "only one of");
    // A tabulated profile that does not reach the amplitude: refused in the first pass.
    let table = concat!(env!("CARGO_MANIFEST_DIR"), "/data/profiles/sphere.csv");
    let rows = format!("shape,vbar,amp\nflat,0.1,1\n\"profile:{table}@1e-6\",0.3,1e9\n");
    refused(&["batch", "--format", "csv"], &rows, "line 3:");
    refused(&["batch", "--format", "xml"], "", "not one of json, jsonl, csv");
}

/// A JSON array is checked a chunk (65,536 rows) at a time in parallel: the
/// first bad row is named even when later chunks hold others, and when the
/// same chunk holds many (spread over the threads' shares of it).
#[test]
fn the_first_bad_row_across_chunks() {
    let rows: Vec<String> = (0..150_000)
        .map(|i| match i {
            70_000..=130_000 if i % 5_000 == 0 => r#"{"shape":"flat","vbar":-1,"amp":1}"#.to_string(),
            140_000 => r#"{"shape":"nope","vbar":0.1,"amp":1}"#.to_string(),
            _ => format!(r#"{{"shape":"flat","vbar":0.{i},"amp":1}}"#),
        })
        .collect();
    refused(&["batch"], &format!("[{}]", rows.join(",")), "row 70000: invalid vbar");
    // And a top-level fault after all rows comes last.
    let good: Vec<String> = (0..70_000).map(|i| format!(r#"{{"shape":"flat","vbar":0.{i},"amp":1}}"#)).collect();
    refused(&["batch"], &format!("[{}] x", good.join(",")), "trailing characters");
}

/// A JSON Lines or CSV batch of at most one chunk (65,536 rows) is read once
/// and kept from its check; a longer one is read again a chunk at a time. Both
/// give every row's results as a JSON array does (another reader), with every
/// other column or field kept byte for byte, on each side of the chunk's size.
#[test]
fn streamed_batches_on_each_side_of_a_chunk() {
    for n in [65_536usize, 65_537] {
        let row = |i: usize| (0.1 + (i % 997) as f64 * 1e-3, (i % 31) as f64 * 0.1);
        let json = |i: usize| {
            let (v, a) = row(i);
            format!("{{\"id\": {i}, \"shape\":\"flat\",\"vbar\":{v:?},\"amp\":{a:?}}}")
        };
        let array = ok(&["batch"], &format!("[{}]", (0..n).map(json).collect::<Vec<_>>().join(",")));
        let want: Vec<serde_json::Value> = serde_json::from_str(&array).unwrap();
        assert_eq!(want.len(), n);
        let num = |x: &serde_json::Value| serde_json::to_string(x).unwrap();
        // JSON Lines, a blank line between rows.
        let lines = ok(&["batch", "--format", "jsonl"], &(0..n).map(|i| json(i) + "\n\n").collect::<String>());
        let mut count = 0;
        for ((i, l), j) in lines.lines().enumerate().zip(&want) {
            let kept = json(i);
            let tail = format!(",\"mu_ratio\":{},\"reduction\":{}}}", num(&j["mu_ratio"]), num(&j["reduction"]));
            assert_eq!(l, format!("{}{tail}", &kept[..kept.len() - 1]), "line {i} of {n}");
            count += 1;
        }
        assert_eq!(count, n);
        // CSV, a quoted column first.
        let note = |i: usize| format!("\"n{i}, \"\"q\"\"\"");
        let csv: String = "note,shape,vbar,amp\n".to_string()
            + &(0..n)
                .map(|i| {
                    let (v, a) = row(i);
                    format!("{},flat,{v:?},{a:?}\n", note(i))
                })
                .collect::<String>();
        let out = ok(&["batch", "--format", "csv"], &csv);
        let mut got = out.lines();
        assert_eq!(got.next(), Some("note,shape,vbar,amp,mu_ratio,reduction"));
        let mut count = 0;
        for ((i, c), j) in got.enumerate().zip(&want) {
            let (v, a) = row(i);
            let want = format!("{},flat,{v:?},{a:?},{},{}", note(i), num(&j["mu_ratio"]), num(&j["reduction"]));
            assert_eq!(c, want, "row {i} of {n}");
            count += 1;
        }
        assert_eq!(count, n);
    }
}

/// Rows in the plane (`transverse_amp`, `transverse_phase`): each gets
/// `transverse_ratio` beside `mu_ratio`, the point's values bit for bit, in
/// every format; a CSV row without the drive gets 0 (no force across the
/// sliding direction); a given `transverse_ratio` is replaced where it
/// stands. What the plane does not solve (a curved shape, a body on a
/// system, the stepping peer) and a phase without its amplitude are refused
/// before any output.
#[test]
fn rows_in_the_plane_get_the_transverse_ratio() {
    let point =
        ok(&["point", "--vhat", "0.6", "--amp", "0.5", "--transverse-amp", "1.2", "--transverse-phase", "0.7"], "");
    let p: serde_json::Value = serde_json::from_str(&point).unwrap();
    let (mu, t) = (p["mu_ratio"].as_f64().unwrap(), p["transverse_ratio"].as_f64().unwrap());
    let reduction = p["reduction"].as_f64().unwrap();
    assert!(t.abs() > 0.1, "{p}");
    let row = r#"{"shape":"flat","vhat":0.6,"amp":0.5,"transverse_amp":1.2,"transverse_phase":0.7}"#;
    let given =
        r#"{"transverse_ratio":9,"shape":"flat","vhat":0.6,"amp":0.5,"transverse_amp":1.2,"transverse_phase":0.7}"#;
    let out = ok(&["batch", "--format", "jsonl"], &format!("{row}\n{given}\n"));
    let lines: Vec<serde_json::Value> = out.lines().map(|l| serde_json::from_str(l).unwrap()).collect();
    for v in &lines {
        assert_eq!((v["mu_ratio"].as_f64(), v["transverse_ratio"].as_f64()), (Some(mu), Some(t)), "{v}");
    }
    assert!(out.lines().nth(1).unwrap().starts_with(&format!("{{\"transverse_ratio\":{t:?},")), "{out}");
    let csv = "shape,vhat,amp,transverse_amp,transverse_phase\nflat,0.6,0.5,1.2,0.7\nflat,0.3,0.5,,\n";
    let out = ok(&["batch", "--format", "csv"], csv);
    let want = format!(
        "shape,vhat,amp,transverse_amp,transverse_phase,mu_ratio,reduction,transverse_ratio\n\
         flat,0.6,0.5,1.2,0.7,{mu:?},{reduction:?},{t:?}\n"
    );
    assert!(out.starts_with(&want) && out.lines().nth(2).unwrap().ends_with(",0.0"), "{out}");
    for (row, needle) in [
        (r#"{"shape":"parabolic","vhat":0.6,"amp":0.5,"transverse_amp":2e6}"#, "transverse-amp"),
        (
            r#"{"shape":"flat","vhat":0.6,"amp":0.5,"transverse_amp":1.2,"system_stiffness":1}"#,
            "not solved in the plane",
        ),
        (
            r#"{"shape":"flat","vhat":0.6,"amp":0.5,"transverse_phase":1.2}"#,
            "'transverse_phase' needs 'transverse_amp'",
        ),
        (r#"{"shape":"flat","vhat":0.6,"amp":0.5,"transverse_amp":-1}"#, "transverse-amp"),
    ] {
        refused(&["batch", "--format", "jsonl"], &format!("{row}\n"), needle);
    }
    refused(&["batch", "--format", "jsonl", "--method", "stepping"], &format!("{row}\n"), "solved exactly only");
}

//! Hostile input and hostile output: closed pipes, a full disk, endless inputs.
//! Each case here panicked or ran out of memory before it was fixed.
use std::process::{Command, Stdio};

fn bin() -> Command {
    Command::new(env!("CARGO_BIN_EXE_fricosc"))
}

const COMMANDS: &[&[&str]] = &[
    &["claims"],
    &["claims", "--format", "json"],
    &["scene", "--schema"],
    &["stress", "--points", "16"],
    &["table", "--amp", "0.5", "--vbar", "0:1:20001"],
    &["point", "--vbar", "0.3", "--amp", "0.5"],
    &["--help"],
    &["--version"],
];

/// `/dev/full` accepts the open and fails every write with ENOSPC.
#[test]
fn a_full_disk_is_a_one_line_error_with_exit_2_never_a_panic() {
    for args in COMMANDS {
        let full = std::fs::OpenOptions::new().write(true).open("/dev/full").unwrap();
        let out = bin().args(*args).stdout(full).stderr(Stdio::piped()).output().unwrap();
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{args:?}: {err}");
        assert!(err.starts_with("error: cannot write stdout"), "{args:?}: {err}");
        assert_eq!(err.lines().count(), 1, "{args:?}: {err}");
    }
}

/// A reader that closes the pipe after a few bytes (`| head -c 10`): quiet exit 0.
#[test]
fn a_closed_pipe_ends_the_program_quietly() {
    for args in COMMANDS {
        let mut child = bin().args(*args).stdout(Stdio::piped()).stderr(Stdio::piped()).spawn().unwrap();
        let mut stdout = child.stdout.take().unwrap();
        let mut first = [0u8; 10];
        use std::io::Read;
        let _ = stdout.read(&mut first);
        drop(stdout);
        let out = child.wait_with_output().unwrap();
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(!err.contains("panicked"), "{args:?}: {err}");
        assert_eq!(out.status.code(), Some(0), "{args:?}: {err}");
        assert!(err.is_empty(), "{args:?}: {err}");
    }
}

/// Endless inputs are refused at their documented cap, before memory runs out.
#[test]
fn endless_inputs_stop_at_the_documented_cap() {
    for args in [
        vec!["batch", "/dev/zero"],
        vec!["validate", "/dev/zero"],
        vec!["scene", "/dev/zero"],
        vec!["point", "--shape", "gx:/dev/zero@1", "--vbar", "0.3", "--amp", "0.5"],
    ] {
        let out = bin().args(&args).stdin(Stdio::null()).output().unwrap();
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{args:?}: {err}");
        assert!(err.contains("is more than the limit of"), "{args:?}: {err}");
        assert!(out.stdout.is_empty());
    }
}

/// A UTF-8 byte-order mark (written by spreadsheets) is not part of a header.
#[test]
fn a_byte_order_mark_is_tolerated() {
    let dir = std::env::temp_dir().join(format!("fricosc-bom-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("t.csv");
    std::fs::write(&path, "\u{feff}vbar,amp,mu_ratio\n0.5,0.5,0.8992738983331657\n").unwrap();
    let out = bin().args(["validate", path.to_str().unwrap()]).output().unwrap();
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
}

/// Misleading or silent cases of the hostile-input issue: each is now a clear error or normalised.
#[test]
fn negative_zero_empty_out_and_history_springs() {
    let out = bin().args(["table", "--vbar", "-0.0", "--amp", "0.5", "--format", "csv"]).output().unwrap();
    let text = String::from_utf8(out.stdout).unwrap();
    assert!(!text.contains("-0.0"), "{text}");
    for args in [["bench", "--out", ""], ["figures", "--out", ""]] {
        let out = bin().args(args).output().unwrap();
        assert_eq!(out.status.code(), Some(2));
        assert!(String::from_utf8_lossy(&out.stderr).contains("output directory is empty"));
    }
    let out = bin()
        .args(["history", "--shape", "parabolic", "--vbar", "0.3", "--amp", "0.5", "--springs", "2000000"])
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("history springs: 2000000 is more than the limit of 1000000"), "{err}");
    assert!(out.stdout.is_empty());
}

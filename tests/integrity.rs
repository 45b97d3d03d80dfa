//! Nothing lost, nothing half-written: every input and output path as a hostile
//! user drives it (pipes and FIFOs read twice, files that change, output folders
//! with other files or links in them, signals, full disks, closed pipes,
//! answers that would not be numbers, and memory).
//!
//! A test crate of its own: the peak memory of a child (`wait4`) starts from
//! the parent's own peak where the child is spawned (Linux carries the high
//! water mark across `exec`), so the parent must stay small.
use std::io::{Read, Write};
use std::os::unix::process::ExitStatusExt;
use std::path::Path;
use std::process::{Command, Output, Stdio};
use std::time::{Duration, Instant};

fn bin() -> Command {
    Command::new(env!("CARGO_BIN_EXE_fricosc"))
}

/// A scratch folder of the test's own, removed when the guard is dropped (also
/// when the test fails).
fn scratch(name: &str) -> tempfile::TempDir {
    tempfile::Builder::new().prefix(&format!("fricosc-integrity-{name}-")).tempdir().unwrap()
}

/// Run `cmd` with `stdin` bytes; its output and peak resident memory (KiB), by
/// `wait4`'s resource usage of the child itself (std's `wait` gives no usage,
/// so the child is reaped here).
#[allow(clippy::zombie_processes)]
fn run_measured(cmd: &mut Command, stdin: &[u8]) -> (Output, i64) {
    let mut child = cmd.stdin(Stdio::piped()).stdout(Stdio::piped()).stderr(Stdio::piped()).spawn().unwrap();
    let mut input = child.stdin.take().unwrap();
    let bytes = stdin.to_vec();
    let writer = std::thread::spawn(move || {
        let _ = input.write_all(&bytes);
    });
    let (mut out, mut err) = (child.stdout.take().unwrap(), child.stderr.take().unwrap());
    let reader = std::thread::spawn(move || {
        let mut v = vec![];
        out.read_to_end(&mut v).unwrap();
        v
    });
    let mut e = vec![];
    err.read_to_end(&mut e).unwrap();
    let stdout = reader.join().unwrap();
    writer.join().unwrap();
    let mut status = 0;
    let mut usage: libc::rusage = unsafe { std::mem::zeroed() };
    let pid = child.id() as libc::pid_t;
    let r = unsafe { libc::wait4(pid, &mut status, 0, &mut usage) };
    assert_eq!(r, pid, "wait4");
    let output = Output { status: std::process::ExitStatus::from_raw(status), stdout, stderr: e };
    (output, usage.ru_maxrss)
}

fn jsonl_rows(n: usize) -> String {
    (0..n).map(|i| format!("{{\"shape\":\"flat\",\"vbar\":{:?},\"amp\":0.5}}\n", (i % 97) as f64 / 100.0)).collect()
}

/// `/dev/stdin` and a named FIFO are read once (spooled), in both streamed
/// formats: every row comes out; before, a pipe gave empty output with exit 0
/// and a FIFO hung on its second opening.
#[test]
fn pipes_and_fifos_are_read_once() {
    let rows = jsonl_rows(500);
    let (out, _) = run_measured(bin().args(["batch", "/dev/stdin", "--format", "jsonl"]), rows.as_bytes());
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    assert_eq!(String::from_utf8(out.stdout).unwrap().lines().count(), 500);
    let csv = "shape,vbar,amp\nflat,0.3,0.5\nflat,0.4,0.5\n";
    let (out, _) = run_measured(bin().args(["batch", "/dev/stdin", "--format", "csv"]), csv.as_bytes());
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    assert_eq!(String::from_utf8(out.stdout).unwrap().lines().count(), 3);
    // A named FIFO, written by another thread.
    let tmp = scratch("fifo");
    let dir = tmp.path();
    let fifo = dir.join("rows.jsonl");
    let c = std::ffi::CString::new(fifo.to_str().unwrap()).unwrap();
    assert_eq!(unsafe { libc::mkfifo(c.as_ptr(), 0o600) }, 0);
    let path = fifo.clone();
    let writer = std::thread::spawn(move || std::fs::write(&path, jsonl_rows(300)).unwrap());
    let mut child = bin().args(["batch", fifo.to_str().unwrap()]).stdout(Stdio::piped()).spawn().unwrap();
    let t0 = Instant::now();
    while child.try_wait().unwrap().is_none() {
        assert!(t0.elapsed() < Duration::from_secs(20), "batch hangs on a FIFO");
        std::thread::sleep(Duration::from_millis(20));
    }
    writer.join().unwrap();
    let mut text = String::new();
    child.stdout.take().unwrap().read_to_string(&mut text).unwrap();
    assert_eq!(text.lines().count(), 300);
}

/// Standard input's spool has no name from the moment it exists: a run killed
/// while reading leaves nothing in the temporary directory. Endless input
/// without line breaks stops at the line cap (1 MiB) while it is spooled, not
/// after 16 GiB.
#[test]
fn the_spool_is_never_left_behind_and_the_line_cap_applies_while_spooling() {
    let tmp = std::env::temp_dir();
    let spools = |pid: u32| {
        std::fs::read_dir(&tmp)
            .unwrap()
            .filter_map(|e| e.ok())
            .filter(|e| e.file_name().to_string_lossy().starts_with(&format!("fricosc-spool-{pid}-")))
            .count()
    };
    let mut child = bin()
        .args(["batch", "-", "--format", "jsonl"])
        .stdin(Stdio::piped())
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .spawn()
        .unwrap();
    let mut input = child.stdin.take().unwrap();
    input.write_all(jsonl_rows(1000).as_bytes()).unwrap();
    std::thread::sleep(Duration::from_millis(300));
    assert_eq!(spools(child.id()), 0, "a spool file with a name while running");
    unsafe { libc::kill(child.id() as libc::pid_t, libc::SIGTERM) };
    let status = child.wait().unwrap();
    assert!(!status.success());
    assert_eq!(spools(child.id()), 0, "a spool file left after SIGTERM");
    // /dev/zero on stdin: refused at line 1 quickly, in little memory.
    let t0 = Instant::now();
    let mut child = bin()
        .args(["batch", "-", "--format", "jsonl"])
        .stdin(std::fs::File::open("/dev/zero").unwrap())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let out = loop {
        if child.try_wait().unwrap().is_some() {
            break child.wait_with_output().unwrap();
        }
        assert!(t0.elapsed() < Duration::from_secs(20), "endless stdin is spooled without a cap");
        std::thread::sleep(Duration::from_millis(20));
    };
    assert_eq!(out.status.code(), Some(2));
    assert!(out.stdout.is_empty());
    assert!(String::from_utf8_lossy(&out.stderr).contains("line 1"), "{}", String::from_utf8_lossy(&out.stderr));
}

/// A streamed batch of 10^5 distinct `power:N` shapes: the shape cache is
/// bounded, so memory does not grow with the number of distinct shapes (before:
/// 163 MB for 10^6 rows, here below 60 MB for 10^5 including the process).
#[test]
fn distinct_shapes_do_not_grow_memory() {
    let rows: String = (0..100_000)
        .map(|i| format!("{{\"shape\":\"power:{:?}\",\"vbar\":1.5,\"amp\":0.5}}\n", 1.0 + i as f64 * 1e-5))
        .collect();
    let (out, kib) = run_measured(bin().args(["batch", "-", "--format", "jsonl"]), rows.as_bytes());
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    assert_eq!(out.stdout.iter().filter(|&&b| b == b'\n').count(), 100_000);
    eprintln!("100,000 distinct shapes: peak {kib} KiB");
    assert!(kib < 60_000, "peak {kib} KiB");
}

/// `suite --out` and `figures --out` refuse a user's folder, never write
/// through a link, and leave no temporary files.
#[test]
fn output_folders_are_ours_and_links_are_not_followed() {
    let tmp = scratch("out");
    let dir = tmp.path();
    let proj = dir.join("proj");
    std::fs::create_dir(&proj).unwrap();
    std::fs::write(proj.join("README.md"), "mine\n").unwrap();
    for cmd in ["suite", "figures"] {
        let out = bin().args([cmd, "--out", proj.to_str().unwrap()]).output().unwrap();
        assert_eq!(out.status.code(), Some(2), "{cmd}");
        assert!(String::from_utf8_lossy(&out.stderr).contains("not empty and was not written by fricosc"));
        assert!(out.stdout.is_empty());
    }
    assert_eq!(std::fs::read_to_string(proj.join("README.md")).unwrap(), "mine\n");
    // A folder of ours with a link where a file goes: the link is replaced, its target untouched.
    let victim = dir.join("victim.txt");
    std::fs::write(&victim, "precious\n").unwrap();
    let ours = dir.join("suite");
    std::fs::create_dir(&ours).unwrap();
    std::fs::write(ours.join(".fricosc-output"), "").unwrap();
    std::os::unix::fs::symlink(&victim, ours.join("README.md")).unwrap();
    let out = bin().args(["suite", "--out", ours.to_str().unwrap()]).output().unwrap();
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    assert_eq!(std::fs::read_to_string(&victim).unwrap(), "precious\n");
    assert!(!std::fs::symlink_metadata(ours.join("README.md")).unwrap().file_type().is_symlink());
    // A linked subfolder is refused.
    let other = dir.join("elsewhere");
    std::fs::create_dir(&other).unwrap();
    std::fs::remove_dir_all(ours.join("tables")).unwrap();
    std::os::unix::fs::symlink(&other, ours.join("tables")).unwrap();
    let out = bin().args(["suite", "--out", ours.to_str().unwrap()]).output().unwrap();
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("is a symlink"), "{}", String::from_utf8_lossy(&out.stderr));
    assert_eq!(std::fs::read_dir(&other).unwrap().count(), 0);
    // No temporary file stays behind.
    let leftovers = |p: &Path| {
        std::fs::read_dir(p)
            .unwrap()
            .filter(|e| e.as_ref().unwrap().file_name().to_string_lossy().ends_with(".tmp"))
            .count()
    };
    assert_eq!(leftovers(&ours), 0);
    // suite --check: a missing folder and an empty name are bad input (2);
    // a file linked to /dev/zero is a difference, read no further than the expected size.
    for arg in ["", dir.join("missing").to_str().unwrap()] {
        assert_eq!(bin().args(["suite", "--check", arg]).output().unwrap().status.code(), Some(2), "{arg:?}");
    }
    std::fs::remove_dir_all(&other).unwrap();
    std::fs::remove_file(ours.join("tables")).unwrap();
    assert!(bin().args(["suite", "--out", ours.to_str().unwrap()]).output().unwrap().status.success());
    std::fs::remove_file(ours.join("README.md")).unwrap();
    std::os::unix::fs::symlink("/dev/zero", ours.join("README.md")).unwrap();
    let t0 = Instant::now();
    let out = bin().args(["suite", "--check", ours.to_str().unwrap()]).output().unwrap();
    assert_eq!(out.status.code(), Some(1));
    assert!(String::from_utf8_lossy(&out.stdout).contains("README.md is not a regular file"));
    assert!(t0.elapsed() < Duration::from_secs(30));
}

/// Histories never print `null` (NaN or inf) as an answer: curved shapes at
/// amplitudes whose forces overflow are refused naming the amplitude; the flat
/// punch at a subnormal amplitude has its normal force 1, not 8.9e-16.
#[test]
fn histories_are_numbers_or_errors() {
    for (shape, amp) in [
        ("parabolic", "5e-324"),
        ("cone", "1e-310"),
        ("power:3.7", "5e-324"),
        ("power:0.05", "1e-310"),
        ("flat-tip:0.5", "5e-324"),
        ("cone", "1e160"),
        ("parabolic", "1e290"),
        ("power:0.05", "1e160"),
        ("flat-tip:0.5", "1e290"),
    ] {
        let out = bin()
            .args(["history", "--shape", shape, "--vbar", "0.3", "--amp", amp, "--samples", "4", "--format", "csv"])
            .output()
            .unwrap();
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{shape} {amp}: {err}");
        assert!(err.contains("invalid amp"), "{shape} {amp}: {err}");
        assert!(out.stdout.is_empty());
    }
    for amp in ["5e-324", "1e-310", "1e300"] {
        let out = bin()
            .args(["history", "--vbar", "0.3", "--amp", amp, "--samples", "8", "--format", "csv"])
            .output()
            .unwrap();
        let text = String::from_utf8(out.stdout).unwrap();
        assert!(out.status.success() && !text.contains("null"), "{amp}: {text}");
        let a: f64 = amp.parse().unwrap();
        for line in text.lines().skip_while(|l| l.starts_with('#')).skip(1) {
            let f: Vec<f64> = line.split(',').take(3).map(|x| x.parse().unwrap()).collect();
            let exact = (1.0 - a * f[0].cos()).max(0.0);
            assert!((f[1] - exact).abs() <= 1e-15 * exact.max(1.0), "{amp}: normal {} vs {exact}", f[1]);
            assert!(f[2] >= 0.0 && f[2] <= f[1] * (1.0 + 1e-15), "{amp}: {line}");
        }
    }
}

/// `validate` reports finite errors for absurd values (an rms of 1e200 errors
/// no longer overflows to null), and a history with no sample in its last
/// period is an error, not a pass with 0 samples.
#[test]
fn validate_never_reports_null_or_checks_nothing() {
    let tmp = scratch("validate");
    let dir = tmp.path();
    let table = dir.join("big.csv");
    std::fs::write(&table, "vbar,amp,mu_ratio\n0.3,0.5,1e200\n0.4,0.5,1e308\n").unwrap();
    let out = bin().args(["validate", table.to_str().unwrap(), "--format", "json"]).output().unwrap();
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let rms = v["rms_error"].as_f64().expect("rms_error is a number");
    assert!((rms / (1e308 / 2f64.sqrt()) - 1.0).abs() < 1e-12, "{rms}");
    // tau multiplied by 1e300: the last period holds no sample.
    let h = dir.join("h.csv");
    let mut text = String::from("tau,tangential\n");
    for k in 0..=400 {
        text += &format!("{:?},0.5\n", 1e300 * k as f64 * std::f64::consts::TAU / 200.0);
    }
    std::fs::write(&h, text).unwrap();
    let out =
        bin().args(["validate", "--history", h.to_str().unwrap(), "--vbar", "0.3", "--amp", "0.5"]).output().unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert!(err.contains("samples in the last period"), "{err}");
    assert!(out.stdout.is_empty());
}

/// Streams: a closed pipe under CSV output ends with 0; a message that cannot
/// be written (stderr on a full disk) neither panics nor costs the answer.
#[test]
fn closed_pipes_and_full_stderr() {
    let tmp = scratch("streams");
    let dir = tmp.path();
    let csv = dir.join("many.csv");
    let mut text = String::from("shape,vbar,amp\n");
    for i in 0..200_000 {
        text += &format!("flat,{:?},0.5\n", (i % 97) as f64 / 100.0);
    }
    std::fs::write(&csv, text).unwrap();
    let mut child =
        bin().args(["batch", csv.to_str().unwrap()]).stdout(Stdio::piped()).stderr(Stdio::piped()).spawn().unwrap();
    let mut one = [0u8; 1];
    child.stdout.take().unwrap().read_exact(&mut one).unwrap(); // then the pipe closes
    let out = child.wait_with_output().unwrap();
    assert_eq!(out.status.code(), Some(0), "{}", String::from_utf8_lossy(&out.stderr));
    let full = || std::fs::OpenOptions::new().write(true).open("/dev/full").unwrap();
    let out = bin().args(["point", "--vbar", "-1", "--amp", "0.5"]).stderr(full()).output().unwrap();
    assert_eq!(out.status.code(), Some(2));
    // A scene whose warning cannot be printed still prints its answer.
    let scene = dir.join("warn.json");
    std::fs::write(
        &scene,
        r#"{"materials": {"e1_pa": 2e11, "nu1": 0.3, "e2_pa": 2e11, "nu2": 0.3}, "mu0": 0.4,
            "indenter": {"sphere": {"radius_m": 1e-6}}, "loading": {"mean_indentation_m": 2e-7},
            "oscillation": {"amplitude_m": 5e-8, "frequency_hz": 1e3}, "velocity": {"values_m_per_s": [1e-3]}}"#,
    )
    .unwrap();
    let out = bin().args(["scene", scene.to_str().unwrap()]).stderr(full()).output().unwrap();
    assert_eq!(out.status.code(), Some(0));
    assert!(String::from_utf8_lossy(&out.stdout).contains("mu_ratio"));
}

/// A scene of 10^6 rows holds 16 bytes a row (before: 815 MB), and a history
/// drawing is refused beyond the plot's limit before any work.
#[test]
fn large_scenes_and_drawings_stay_bounded() {
    let tmp = scratch("scene");
    let dir = tmp.path();
    let scene = dir.join("big.json");
    std::fs::write(
        &scene,
        r#"{"materials": {"e1_pa": 2e11, "nu1": 0.3, "e2_pa": 2e11, "nu2": 0.3}, "mu0": 0.4,
            "indenter": {"flat_punch": {"radius_m": 1e-3}}, "loading": {"mean_indentation_m": 1e-6},
            "oscillation": {"amplitude_m": 5e-7, "frequency_hz": 1e3},
            "velocity": {"sweep": {"start_m_per_s": 0.1, "stop_m_per_s": 1.0, "count": 1000000}}}"#,
    )
    .unwrap();
    let (out, kib) = run_measured(bin().args(["scene", scene.to_str().unwrap(), "--format", "csv"]), b"");
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    assert_eq!(out.stdout.iter().filter(|&&b| b == b'\n').count(), 1_000_001);
    eprintln!("scene of 10^6 rows: peak {kib} KiB");
    assert!(kib < 150_000, "peak {kib} KiB");
    let out = bin()
        .args(["history", "--vbar", "0.3", "--amp", "0.5", "--samples", "10000000", "--format", "svg"])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    assert!(out.stdout.is_empty());
}

/// Smaller ones: a byte-order mark before JSON Lines; control characters of an
/// input escaped in messages; messages that name the right thing.
#[test]
fn boms_escapes_and_messages() {
    let (out, _) = run_measured(
        bin().args(["batch", "-", "--format", "jsonl"]),
        b"\xEF\xBB\xBF{\"shape\":\"flat\",\"vbar\":0.3,\"amp\":0.5}\n",
    );
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let out = bin().args(["point", "--shape", "flat\u{1b}[31mRED", "--vbar", "0.3", "--amp", "0.5"]).output().unwrap();
    assert!(!out.stderr.contains(&0x1b), "a raw escape reached the terminal");
    assert!(String::from_utf8_lossy(&out.stderr).contains("\\u{1b}"));
    let cases: [(&[&str], &str); 3] = [
        (&["history", "--vbar", "0.3", "--amp", "0.5", "--samples", "0"], "invalid samples"),
        (&["plot", "--vhat", "0:1e308:3", "--amp", "1e-10"], "vhat / amp"),
        (&["validate", "--series", "run@1e400.csv", "run@250.csv"], "run@1e400.csv"),
    ];
    for (args, needle) in cases {
        let out = bin().args(args).output().unwrap();
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{args:?}: {err}");
        assert!(err.contains(needle), "{args:?}: {err}");
    }
}

/// A long table on a system (three seconds) with stderr on a terminal (a
/// pseudo-terminal): indicatif's bar, with the rows done; with `--quiet`, or
/// with stderr not a terminal, nothing; the output the same bytes each time.
#[test]
fn a_progress_bar_only_on_a_terminal() {
    use std::os::fd::{FromRawFd, OwnedFd};
    let args = ["table", "--shape", "parabolic", "--amp", "0.5", "--vbar", "0.05:1:120", "--system-stiffness", "1"];
    let args = [&args[..], &["--frequency-ratio", "0.5", "--damping", "0.05", "--format", "csv"]].concat();
    let on_terminal = |quiet: bool| {
        let (mut master, mut slave) = (0, 0);
        // SAFETY: openpty writes two descriptors it opened; each is owned once below.
        let ok =
            unsafe { libc::openpty(&mut master, &mut slave, std::ptr::null_mut(), std::ptr::null(), std::ptr::null()) };
        assert_eq!(ok, 0, "openpty");
        // SAFETY: the descriptors are open and owned by nothing else.
        let (master, slave) = unsafe { (OwnedFd::from_raw_fd(master), OwnedFd::from_raw_fd(slave)) };
        let mut cmd = bin();
        cmd.args(&args).stdout(Stdio::piped()).stderr(Stdio::from(slave));
        if quiet {
            cmd.arg("--quiet");
        }
        let child = cmd.spawn().unwrap();
        drop(cmd);
        let reader = std::thread::spawn(move || {
            let mut terminal = std::fs::File::from(master);
            let mut seen = vec![];
            // EIO once the child, the last holder of the terminal's other end, has gone.
            let _ = terminal.read_to_end(&mut seen);
            String::from_utf8_lossy(&seen).into_owned()
        });
        let out = child.wait_with_output().unwrap();
        assert!(out.status.success());
        (out.stdout, reader.join().unwrap())
    };
    let (stdout, bar) = on_terminal(false);
    assert!(bar.contains("table: ") && bar.contains("/120 rows"), "{bar:?}");
    let (quiet_stdout, nothing) = on_terminal(true);
    assert_eq!((quiet_stdout, nothing.as_str()), (stdout.clone(), ""));
    let piped = bin().args(&args).output().unwrap();
    assert_eq!((piped.stdout, piped.stderr), (stdout, vec![]));
}

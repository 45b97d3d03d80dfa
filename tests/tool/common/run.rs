//! Running the `fricosc` binary from the command-line tests (included with
//! `#[path]` by those tests only: the library's own tests have no binary).
#![allow(dead_code)]

use std::io::Write;
use std::process::{Command, Output, Stdio};

/// Run `fricosc args`, feeding `stdin` (from a thread, so that a large input
/// cannot deadlock against a full stdout pipe); its output and process id.
pub fn run_with_id(args: &[&str], stdin: Option<&str>) -> (Output, u32) {
    let mut child = Command::new(env!("CARGO_BIN_EXE_fricosc"))
        .args(args)
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let id = child.id();
    let input = stdin.unwrap_or("").to_string();
    let mut pipe = child.stdin.take().unwrap();
    let writer = std::thread::spawn(move || {
        // A command that exits before reading all of it closes the pipe: fine.
        let _ = pipe.write_all(input.as_bytes());
    });
    let out = child.wait_with_output().unwrap();
    writer.join().unwrap();
    (out, id)
}

/// Run `fricosc args` with `stdin`; its output.
pub fn run(args: &[&str], stdin: Option<&str>) -> Output {
    run_with_id(args, stdin).0
}

//! `fricosc`: the command line, a thin layer over the library. Each
//! subcommand is one module of `src/cli/` with its options and its run; this
//! file parses them and decides every exit code:
//!
//! - 0: success (also when the reader closes the pipe, as ripgrep does);
//! - 1: a negative answer (`validate` with a finding or an error above
//!   `--max-error`, a stale suite);
//! - 2: bad input or a failed read/write (one line on stderr, nothing on stdout);
//! - 3: an internal error (a bug to report, never printed as a number).
//!
//! Writing to stderr never panics: a message that cannot be written (a full
//! disk, a closed stderr) is dropped, and the exit code still tells.

use clap::Parser;
use fricosc_cli::cmd::{emit, say, Command, Outcome};
use std::io::Write;
use std::process::ExitCode;

#[derive(Parser)]
#[command(
    name = "fricosc",
    version,
    about = "Exact friction under normal oscillation (Popov, Popov, Popov 2017)",
    arg_required_else_help = true
)]
struct Cli {
    #[command(subcommand)]
    command: Command,
    /// No progress bar on stderr (drawn only on a terminal, for work over a second)
    #[arg(long, global = true)]
    quiet: bool,
}

/// clap's own outcome: help and version on stdout (through the checked path),
/// usage errors as one line on stderr with exit code 2.
fn clap_exit(e: clap::Error) -> ExitCode {
    // No command at all: the full help, on stderr (a usage error, exit 2).
    if e.kind() == clap::error::ErrorKind::DisplayHelpOnMissingArgumentOrSubcommand {
        let mut err = std::io::stderr().lock();
        let _ = write!(err, "{}", e.render());
        return ExitCode::from(2);
    }
    if !e.use_stderr() {
        return match emit(&e.render().to_string()) {
            Ok(()) => ExitCode::SUCCESS,
            Err(err) if err.is_broken_pipe() => ExitCode::SUCCESS,
            Err(err) => {
                say(&format!("error: {err}"));
                ExitCode::from(2)
            }
        };
    }
    // One line: clap's message up to its usage block, joined.
    let msg = e.to_string();
    let text: Vec<&str> = msg
        .lines()
        .map(str::trim)
        .take_while(|l| !l.starts_with("Usage:") && !l.starts_with("For more information"))
        .filter(|l| !l.is_empty())
        .collect();
    say(&text.join(" "));
    ExitCode::from(2)
}

fn main() -> ExitCode {
    let cli = match Cli::try_parse() {
        Ok(c) => c,
        Err(e) => return clap_exit(e),
    };
    fricosc_cli::progress::set_quiet(cli.quiet);
    match cli.command.run() {
        Ok(Outcome::Done) => ExitCode::SUCCESS,
        Ok(Outcome::Negative) => ExitCode::from(1),
        // The reader went away (`| head`): end quietly.
        Err(e) if e.is_broken_pipe() => ExitCode::SUCCESS,
        Err(e) => {
            say(&format!("error: {e}"));
            ExitCode::from(e.exit_code())
        }
    }
}

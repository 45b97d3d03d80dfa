//! A progress bar on stderr for long work (indicatif): rows done, rate and
//! time left, drawn only where stderr is a terminal, only once the work has
//! run a second, never with `--quiet`, and never into the output.

use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};
use std::io::IsTerminal;
use std::sync::atomic::{AtomicBool, Ordering};

/// Set by `--quiet`: no bar at all.
static QUIET: AtomicBool = AtomicBool::new(false);

/// Work shorter than this shows no bar.
const DELAY: std::time::Duration = std::time::Duration::from_secs(1);

/// No progress bars from now on (`--quiet`).
pub fn set_quiet(quiet: bool) {
    QUIET.store(quiet, Ordering::Relaxed);
}

/// A bar of `total` items (`None`: a count without a length), hidden until
/// a second has passed; inert where stderr is not a terminal.
pub struct Bar {
    bar: Option<ProgressBar>,
    shown: AtomicBool,
}

impl Bar {
    pub fn new(total: Option<u64>, what: &str) -> Bar {
        let live = !QUIET.load(Ordering::Relaxed) && std::io::stderr().is_terminal();
        let bar = live.then(|| {
            let template = match total {
                Some(_) => "{msg}: {wide_bar} {human_pos}/{human_len} rows, {per_sec}, {eta} left",
                None => "{msg}: {human_pos} rows, {per_sec}",
            };
            let style = ProgressStyle::with_template(template).unwrap_or_else(|_| ProgressStyle::default_bar());
            let b = ProgressBar::with_draw_target(total, ProgressDrawTarget::hidden()).with_style(style);
            b.set_message(what.to_string());
            b
        });
        Bar { bar, shown: AtomicBool::new(false) }
    }

    /// `k` more items done (from any thread).
    pub fn inc(&self, k: u64) {
        if let Some(b) = &self.bar {
            b.inc(k);
            if b.elapsed() >= DELAY && !self.shown.swap(true, Ordering::Relaxed) {
                b.set_draw_target(ProgressDrawTarget::stderr());
            }
        }
    }
}

impl Drop for Bar {
    /// The bar cleared from the terminal, whether the work ended or failed.
    fn drop(&mut self) {
        if let Some(b) = &self.bar {
            b.finish_and_clear();
        }
    }
}

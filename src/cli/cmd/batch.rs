//! `fricosc batch`: rows in (a JSON array, JSON Lines or CSV), the same rows
//! with results out, in the same format.

use super::{io_err, read_input};
use crate::cli::batch::{self, Format};
use crate::cli::error::{Error, Result};
use crate::stepper::Stepping;
use std::io::{self, BufRead, Write};

#[derive(clap::Args)]
pub struct BatchArgs {
    /// Input file; stdin when absent or '-'.
    pub file: Option<String>,
    /// Input and output format: json (an array), jsonl (one object per line, streamed) or csv
    /// (streamed); default: by the file's extension (.jsonl, .ndjson, .csv), else json.
    #[arg(long)]
    pub format: Option<String>,
    #[command(flatten)]
    pub method: super::MethodArgs,
}

pub fn run(a: BatchArgs) -> Result<()> {
    let stepping: Option<Stepping> = a.method.stepping()?;
    let (file, format) = (a.file, a.format);
    let path = file.clone().unwrap_or_else(|| "-".into());
    match Format::choose(format.as_deref(), &path)? {
        Format::Json => {
            let (text, source) = read_input(file)?;
            let rows = batch::run(&text, &source, stepping)?;
            let mut out = io::BufWriter::with_capacity(1 << 16, io::stdout().lock());
            rows.write(&mut out).and_then(|()| out.flush()).map_err(io_err)
        }
        streamed => {
            // Streaming reads its input twice: stdin is first copied to a
            // temporary file (removed when done), in constant memory.
            let spool = if path == "-" { Some(Spool::from_stdin()?) } else { None };
            let (read_path, source) = match &spool {
                Some(s) => (s.path.display().to_string(), "stdin".to_string()),
                None => (path.clone(), path.clone()),
            };
            let open = || -> Result<Box<dyn BufRead>> {
                let f = std::fs::File::open(&read_path)
                    .map_err(|e| Error::Parse { context: source.clone(), reason: format!("cannot read: {e}") })?;
                if f.metadata().is_ok_and(|m| m.is_dir()) {
                    return Err(Error::Parse { context: source.clone(), reason: "cannot read: a directory".into() });
                }
                Ok(Box::new(io::BufReader::with_capacity(1 << 16, f)))
            };
            let mut out = io::BufWriter::with_capacity(1 << 16, io::stdout().lock());
            batch::stream(streamed, &open, &source, stepping, &mut out).map(|_| ())
        }
    }
}

/// Standard input copied to a temporary file (readable by its owner only),
/// removed on drop.
struct Spool {
    path: std::path::PathBuf,
}

/// Most bytes of standard input a streamed batch spools (16 GiB).
pub const MAX_SPOOL_BYTES: u64 = 16 << 30;

impl Spool {
    fn from_stdin() -> Result<Spool> {
        let nanos = std::time::SystemTime::now().duration_since(std::time::UNIX_EPOCH).map_or(0, |d| d.as_nanos());
        let path = std::env::temp_dir().join(format!("fricosc-batch-{}-{nanos}", std::process::id()));
        let spool = Spool { path };
        let werr = |e: io::Error| Error::write(&spool.path.display().to_string(), e);
        let mut options = std::fs::OpenOptions::new();
        options.write(true).create_new(true);
        #[cfg(unix)]
        std::os::unix::fs::OpenOptionsExt::mode(&mut options, 0o600);
        let mut f = options.open(&spool.path).map_err(werr)?;
        let copied =
            io::copy(&mut io::Read::take(io::stdin().lock(), MAX_SPOOL_BYTES + 1), &mut f).map_err(|e| {
                match e.kind() {
                    io::ErrorKind::WriteZero | io::ErrorKind::StorageFull => werr(e),
                    _ => Error::Parse { context: "stdin".into(), reason: format!("cannot read: {e}") },
                }
            })?;
        if copied > MAX_SPOOL_BYTES {
            return Err(Error::TooLarge {
                what: "bytes of stdin (JSON Lines and CSV are spooled to a temporary file; give a file instead)".into(),
                count: copied as u128,
                limit: MAX_SPOOL_BYTES as u128,
            });
        }
        f.sync_data().ok();
        Ok(spool)
    }
}

impl Drop for Spool {
    fn drop(&mut self) {
        let _ = std::fs::remove_file(&self.path);
    }
}

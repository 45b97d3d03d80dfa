//! `fricosc batch`: rows in (a JSON array, JSON Lines or CSV), the same rows
//! with results out, in the same format.

use super::{io_err, read_input};
use crate::batch::{self, Format};
use crate::error::Result;
use fricosc::stepper::Stepping;
use std::io::{self, Write};

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
            // Streaming reads its input twice (check, then compute and write),
            // the second time exactly the bytes the first one checked; an input
            // of one chunk (65,536 rows) once.
            let input = crate::twopass::TwoPass::open(&path)?;
            let mut out = io::BufWriter::with_capacity(1 << 16, io::stdout().lock());
            batch::stream(streamed, &input, stepping, &mut out).map(|_| ())
        }
    }
}

//! `fricosc batch`: a JSON array of rows in, the same rows with results out.

use super::{io_err, read_input};
use fricosc::batch;
use fricosc::error::Result;
use fricosc::shape::Stepping;
use std::io::{self, Write};

pub(crate) fn run(file: Option<String>, stepping: Option<Stepping>) -> Result<()> {
    let (text, source) = read_input(file)?;
    let rows = batch::run(&text, &source, stepping)?;
    let mut out = io::BufWriter::with_capacity(1 << 16, io::stdout().lock());
    rows.write(&mut out).and_then(|()| out.flush()).map_err(io_err)
}

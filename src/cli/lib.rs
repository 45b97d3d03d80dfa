//! The `fricosc` command-line tool: its subcommands ([`cmd`]), reports, formats
//! and I/O, over the library. Behind the `cli` feature; not part of the
//! library's API (the binary, the fuzz targets and the tests use it).

pub mod batch;
pub mod bench;
pub mod claims;
pub mod cmd;
pub mod error;
pub mod export;
pub mod figures;
pub mod grid;
pub mod history;
pub mod input;
pub mod json;
pub mod outdir;
pub mod output;
pub mod plot;
pub mod scene;
pub mod stress;
pub mod suite;
pub mod tables;
pub mod twopass;
pub mod validate;

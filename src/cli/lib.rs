//! The `fricosc` command-line tool over the library: one module per
//! subcommand (its options and its run; [`cmd`] dispatches them and holds what
//! they share), the readers and writers of tables, and the charts. Not a
//! library for others: the binary, the fuzz targets and the tool's tests use it.

pub mod batch;
pub mod bench;
pub mod chart;
pub mod claims;
pub mod cmd;
pub mod error;
pub mod export;
pub mod figures;
pub mod fit;
pub mod grid;
pub mod history;
pub mod input;
pub mod json;
pub mod outdir;
pub mod output;
pub mod plot;
pub mod point;
pub mod progress;
pub mod scene;
pub mod suite;
pub mod table;
pub mod table_plane;
pub mod tables;
pub mod twopass;
pub mod validate;

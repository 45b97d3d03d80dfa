//! The command-line tool's tests: one test crate (one build and link), a
//! module per subject. Most run the `fricosc` binary as a user does; what
//! each checks against what is listed in `tests/README.md`.

mod common;

mod batch_formats;
mod batch_rows;
mod claims;
mod cli;
mod combined_cli;
mod combined_history;
mod figures;
mod fit_cli;
mod fuzz_mirror;
mod hostile;
mod plane_cli;
mod scene;
mod scene_plane;
mod suite;
mod system_cli;
mod tidy;
mod users;
mod validate;

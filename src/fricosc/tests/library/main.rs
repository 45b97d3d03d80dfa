//! The library's tests: one test crate (one build and link), a module per
//! subject. Each compares the solver with something it did not compute (see
//! `tests/README.md` at the top of the repository).

mod common;

mod claims;
mod combined;
mod combined_curved;
mod contact;
mod degenerate;
mod edges;
mod fit;
#[allow(clippy::excessive_precision)]
mod fit_outliers;
#[allow(clippy::excessive_precision)]
mod flat;
mod flat_events;
mod flat_tip;
mod history;
mod mdr;
mod mdr_independent;
mod plane;
mod plane_curved;
mod plane_history;
mod plane_validate;
mod profile;
mod properties;
mod reference;
#[allow(clippy::excessive_precision)]
mod report_fields;
mod scene_plane;
mod stepper;
mod stress;
mod system;
mod system_curved;
mod table;
mod transverse_peer;

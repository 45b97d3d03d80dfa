//! `fricosc stress`: random and edge points through every check.

use super::{emit, to_json, Outcome};
use crate::error::{Error, Result};
use clap::Args;

#[derive(Args)]
pub struct StressArgs {
    /// Points (rounded up to whole lines of 16).
    #[arg(long, default_value_t = 1_000_000)]
    pub points: usize,
    /// Seed of the point generator.
    #[arg(long, default_value_t = 1)]
    pub seed: u64,
}

/// Most points one stress run may take.
pub const MAX_POINTS: usize = 100_000_000;

/// Run and print the report; [`Outcome::Negative`] when any check failed.
pub fn run(a: StressArgs) -> Result<Outcome> {
    let (points, seed) = (a.points, a.seed);
    if points > MAX_POINTS {
        return Err(Error::TooLarge { what: "stress points".into(), count: points as u128, limit: MAX_POINTS as u128 });
    }
    let r = crate::stress::run(points, seed, &crate::stress::default_shapes());
    emit(&format!("{}\n", to_json(&r)?))?;
    Ok(if r.failure_count == 0 { Outcome::Done } else { Outcome::Negative })
}

//! `fricosc scene`: the core's physical scenes ([`fricosc_core::scene`]) read
//! from JSON, with the capped file reader, their schema, and their report.

use crate::error::{Error, Result};
pub use fricosc_core::scene::*;

/// Parse a scene from JSON text; `source` names the file in errors. A scene is a
/// JSON object: serde would also accept its fields as a positional array.
pub fn parse(text: &str, source: &str) -> Result<Scene> {
    if !text.trim_start().starts_with('{') {
        return Err(Error::Parse { context: source.into(), reason: "a scene is a JSON object ({...})".into() });
    }
    serde_json::from_str(text).map_err(|e| Error::Parse { context: source.into(), reason: e.to_string() })
}

/// Solve a scene; `source` is its path (tables are found relative to it and read
/// with the command line's cap).
pub fn solve(s: &Scene, source: &str) -> Result<SceneResult> {
    solve_with_progress(s, source, &|_| {})
}

/// [`solve`], calling `progress(k)` after each chunk of `k` velocities.
pub fn solve_with_progress(s: &Scene, source: &str, progress: &(dyn Fn(u64) + Sync)) -> Result<SceneResult> {
    solve_with(s, source, &|path| crate::input::read_capped(path, crate::input::MAX_SMALL_BYTES), progress)
}

/// The JSON Schema of the scene file (schemars).
pub fn schema() -> String {
    serde_json::to_string_pretty(&schemars::schema_for!(Scene)).unwrap_or_default()
}

impl crate::export::Report for SceneResult {
    /// One row per velocity.
    fn columns(&self) -> Vec<String> {
        [
            "velocity_m_per_s",
            "vbar",
            "vhat",
            "mu_macro",
            "mu_ratio",
            "mean_friction_force_n",
            "mean_normal_force_n",
            "regime",
        ]
        .map(String::from)
        .to_vec()
    }

    fn rows(&self) -> Vec<Vec<String>> {
        let n = crate::output::num;
        self.rows
            .iter()
            .map(|x| {
                vec![
                    n(x.velocity_m_per_s),
                    n(x.vbar),
                    n(x.vhat),
                    n(x.mu_macro),
                    n(x.mu_ratio),
                    n(x.mean_friction_force_n),
                    n(x.mean_normal_force_n),
                    x.regime.to_string(),
                ]
            })
            .collect()
    }
}

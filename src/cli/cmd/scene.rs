//! `fricosc scene`: physical scenes in SI units.

use super::emit;
use crate::error::{Error, Result};
use crate::output::Format;
use rayon::prelude::*;
use std::io::{self, IsTerminal, Write};

#[derive(clap::Args)]
pub struct SceneArgs {
    /// Scene files (run in parallel).
    pub files: Vec<String>,
    /// Print the JSON Schema of the scene file instead.
    #[arg(long)]
    pub schema: bool,
    /// Output format.
    #[arg(long, value_enum, default_value = "json")]
    pub format: Format,
    /// Also draw mu_macro against the velocity, one curve per amplitude (the seed's Fig. 9
    /// layout), to this file: SVG or PNG by its extension.
    #[arg(long)]
    pub plot: Option<String>,
}

pub fn run(a: SceneArgs) -> Result<()> {
    let SceneArgs { files, schema, format, plot } = a;
    if schema {
        return emit(&format!("{}\n", crate::scene::schema()));
    }
    if let Some(path) = &plot {
        super::drawing_kind("--plot", path)?;
    }
    if files.is_empty() {
        return Err(Error::Parse { context: "scene".into(), reason: "give a scene file (or --schema)".into() });
    }
    // Read and solve everything before the first byte is written.
    let scenes: Vec<Result<fricosc::scene::Scene>> = files
        .iter()
        .map(|f| {
            let text = crate::input::read_capped(f, crate::input::MAX_SMALL_BYTES)?;
            crate::scene::parse(&text, f)
        })
        .collect();
    let scenes = scenes.into_iter().collect::<Result<Vec<_>>>()?;
    // A progress bar on stderr only when it is a terminal and the work is long.
    let total: usize = scenes.iter().map(fricosc::scene::velocity_count).sum();
    let bar = (std::io::stderr().is_terminal() && total >= 2000).then(|| Progress::new(total as u64));
    let tick = |k: u64| {
        if let Some(b) = &bar {
            b.inc(k);
        }
    };
    let results: Vec<Result<Vec<fricosc::scene::SceneResult>>> =
        scenes.par_iter().zip(&files).map(|(s, f)| crate::scene::solve_with_progress(s, f, &tick)).collect();
    if let Some(b) = &bar {
        b.finish();
    }
    // Each answer (one per amplitude) with its scene's label: its name, or its file.
    let mut labelled: Vec<(String, fricosc::scene::SceneResult)> = vec![];
    for (r, f) in results.into_iter().zip(&files) {
        labelled.extend(r?.into_iter().map(|x| (x.name.clone().unwrap_or_else(|| f.clone()), x)));
    }
    for (f, r) in &labelled {
        for w in &r.warnings {
            super::say(&format!("warning: {f}: {w}"));
        }
    }
    if let Some(path) = &plot {
        let svg = crate::scene::family_chart(&labelled).svg();
        super::write_drawing("--plot", path, &svg)?;
    }
    let results: Vec<&fricosc::scene::SceneResult> = labelled.iter().map(|(_, r)| r).collect();
    // One shape of output whatever the number of files: a JSON list, and CSV in
    // long form (one header; each row with its scene and the scene's results).
    // Everything is computed; now it is written as it is formatted (a row's
    // text is never held whole).
    let mut out = io::BufWriter::with_capacity(1 << 16, io::stdout().lock());
    match format {
        Format::Csv => scenes_csv(&mut out, &labelled).map_err(super::io_err)?,
        Format::Json => {
            serde_json::to_writer_pretty(&mut out, &results).map_err(|e| super::io_err(e.into()))?;
            out.write_all(b"\n").map_err(super::io_err)?;
        }
    }
    out.flush().map_err(super::io_err)
}

/// Every scene's rows in one CSV table: the scene (its name, or its file), the
/// scene-level results repeated on each row (one amplitude of a family each),
/// then the row's own columns.
fn scenes_csv(out: &mut dyn Write, results: &[(String, fricosc::scene::SceneResult)]) -> io::Result<()> {
    use crate::export::Report;
    let n = crate::output::num;
    let mut w = csv::WriterBuilder::new().terminator(csv::Terminator::Any(b'\n')).from_writer(out);
    let fail = crate::output::io_of;
    let scene_cols = ["scene", "u0_m", "du_m", "amp", "contact_radius_m", "critical_velocity_m_per_s", "mu_static"];
    let mut header: Vec<String> = scene_cols.map(String::from).to_vec();
    if let Some((_, r)) = results.first() {
        header.extend(r.columns());
    }
    w.write_record(&header).map_err(fail)?;
    for (label, r) in results {
        let scene = [
            label.clone(),
            n(r.mean_indentation_m),
            n(r.amplitude_m),
            n(r.amplitude_ratio),
            n(r.contact_radius_m),
            n(r.critical_velocity_m_per_s),
            n(r.mu_static),
        ];
        for x in r.rows.iter() {
            w.write_record(scene.iter().chain(&crate::scene::row_cells(&x))).map_err(fail)?;
        }
    }
    w.flush()
}

/// A percentage on a terminal's stderr, rewritten in place (whole percents
/// only); a failed write to stderr is ignored (the answer matters more).
struct Progress {
    total: u64,
    done: std::sync::atomic::AtomicU64,
}

impl Progress {
    fn new(total: u64) -> Self {
        Progress { total: total.max(1), done: std::sync::atomic::AtomicU64::new(0) }
    }

    fn inc(&self, k: u64) {
        use std::sync::atomic::Ordering::Relaxed;
        let before = self.done.fetch_add(k, Relaxed);
        let (p0, p1) = (100 * before / self.total, 100 * (before + k) / self.total);
        if p1 > p0 {
            let _ = write!(std::io::stderr(), "\rscene: {p1:>3} %");
        }
    }

    fn finish(&self) {
        let _ = write!(std::io::stderr(), "\r             \r");
    }
}

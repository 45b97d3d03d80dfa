//! `fricosc scene`: the core's physical scenes ([`fricosc::scene`]) read
//! from JSON, with the capped file reader, their schema, and their report.

use crate::cmd::emit;
use crate::error::{Error, Result};
use crate::output::Format;
use fricosc::scene::{solve_with, Scene, SceneResult};
use rayon::prelude::*;
use std::io::{self, Write};
/// Parse a scene from JSON text; `source` names the file in errors. A scene is a
/// JSON object: serde would also accept its fields as a positional array.
pub fn parse(text: &str, source: &str) -> Result<Scene> {
    if !text.trim_start().starts_with('{') {
        return Err(Error::Parse { context: source.into(), reason: "a scene is a JSON object ({...})".into() });
    }
    serde_json::from_str(text).map_err(|e| Error::Parse { context: source.into(), reason: e.to_string() })
}

/// Solve a scene, one answer per amplitude; `source` is its path (tables are
/// found relative to it and read with the command line's cap).
pub fn solve(s: &Scene, source: &str) -> Result<Vec<SceneResult>> {
    solve_with_progress(s, source, &|_| {})
}

/// [`solve`], calling `progress(k)` after each chunk of `k` velocities.
pub fn solve_with_progress(s: &Scene, source: &str, progress: &(dyn Fn(u64) + Sync)) -> Result<Vec<SceneResult>> {
    Ok(solve_with(s, source, &crate::input::small_file, progress)?)
}

/// The JSON Schema of the scene file (schemars).
pub fn schema() -> String {
    serde_json::to_string_pretty(&schemars::schema_for!(Scene)).unwrap_or_default()
}

/// An amplitude in a readable unit: nm, μm, mm or m, four significant digits.
pub fn length_label(m: f64) -> String {
    let (scale, unit) = match m.abs() {
        x if x < 1e-6 => (1e9, "nm"),
        x if x < 1e-3 => (1e6, "μm"),
        x if x < 1.0 => (1e3, "mm"),
        _ => (1.0, "m"),
    };
    let v: f64 = format!("{:.3e}", m * scale).parse().unwrap_or(m * scale);
    format!("{} {unit}", crate::output::num(v).trim_end_matches(".0"))
}

/// `mu_macro` against the sliding velocity, one curve per answer (the seed's
/// Fig. 9 layout: one scene's amplitudes as a family in viridis order, with the
/// line of sliding without oscillation, `mu = mu0`, in black). Each answer
/// comes with its scene's label; with several scenes the legend names both.
/// The velocity axis is logarithmic where the velocities are positive and span
/// two decades or more.
pub fn family_chart(results: &[(String, SceneResult)]) -> crate::chart::Chart {
    use crate::chart::{family_color, Axis, Chart, Key, Rule, Series, Style};
    let scenes: Vec<&str> = results.iter().fold(vec![], |mut v, (l, _)| {
        if !v.contains(&l.as_str()) {
            v.push(l.as_str());
        }
        v
    });
    let (mut vmin, mut vmax, mut mumax) = (f64::INFINITY, 0.0f64, 0.0f64);
    let mut positive_min = f64::INFINITY;
    for (_, r) in results {
        for x in r.rows.iter() {
            vmin = vmin.min(x.velocity_m_per_s);
            vmax = vmax.max(x.velocity_m_per_s);
            if x.velocity_m_per_s > 0.0 {
                positive_min = positive_min.min(x.velocity_m_per_s);
            }
        }
        mumax = mumax.max(r.mu_static.unwrap_or(0.0).max(r.rows.iter().map(|x| x.mu_macro).fold(0.0, f64::max)));
    }
    let mu0s: Vec<f64> = results.iter().map(|(_, r)| r.mu0).collect();
    let log = vmin > 0.0 && vmax >= 100.0 * vmin;
    let x = if log {
        Axis::log("sliding velocity v_{0} (m/s)", (positive_min / 1.2, vmax * 1.2))
    } else if vmax > vmin {
        Axis::linear("sliding velocity v_{0} (m/s)", (vmin, vmax))
    } else if vmin > 0.0 {
        // One velocity: a range around it.
        Axis::linear("sliding velocity v_{0} (m/s)", (0.5 * vmin, 1.5 * vmin))
    } else {
        Axis::linear("sliding velocity v_{0} (m/s)", (0.0, 1.0))
    };
    let top = mumax.max(mu0s.iter().copied().fold(0.0, f64::max)) * 1.08;
    let n = results.len();
    let series = results
        .iter()
        .enumerate()
        .map(|(i, (label, r))| {
            let du = length_label(r.amplitude_m);
            let text = if scenes.len() > 1 { format!("{label}: {du}") } else { du };
            Series {
                label: text,
                points: r.rows.iter().map(|x| (x.velocity_m_per_s, x.mu_macro)).collect(),
                // A lone velocity is a point: drawn as a marker.
                style: if r.rows.len() < 2 {
                    Style::line(family_color(i, n)).marker(crate::chart::Marker::Circle)
                } else {
                    Style::line(family_color(i, n))
                },
                legend: true,
            }
        })
        .collect();
    let mut key = vec![Key::Heading("Δu_{z}".into())];
    // Sliding without oscillation: mu = mu0 (one line per distinct mu0).
    let mut rules = vec![];
    for &m in &mu0s {
        if m > 0.0 && !rules.iter().any(|r: &Rule| r.at == m) {
            rules.push(Rule { horizontal: true, at: m });
        }
    }
    if !rules.is_empty() {
        key.push(Key::Entry(Style::line(crate::chart::Rgb(0x99, 0x99, 0x99)).width(0.5), "0 (μ_{0})".into()));
    }
    Chart {
        title: format!("mu_macro against velocity: {}", scenes.join(", ")),
        x,
        y: Axis::linear("friction coefficient μ_{macro}", (0.0, if top > 0.0 { top } else { 1.0 })),
        series,
        key,
        rules,
    }
}

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
        crate::cmd::drawing_kind("--plot", path)?;
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
    let total: usize = scenes.iter().map(Scene::rows).sum();
    let bar = crate::progress::Bar::new(Some(total as u64), "scene");
    let tick = |k: u64| bar.inc(k);
    let results: Vec<Result<Vec<fricosc::scene::SceneResult>>> =
        scenes.par_iter().zip(&files).map(|(s, f)| crate::scene::solve_with_progress(s, f, &tick)).collect();
    drop(bar);
    // Each answer (one per amplitude) with its scene's label: its name, or its file.
    let mut labelled: Vec<(String, fricosc::scene::SceneResult)> = vec![];
    for (r, f) in results.into_iter().zip(&files) {
        labelled.extend(r?.into_iter().map(|x| (x.name.clone().unwrap_or_else(|| f.clone()), x)));
    }
    for (f, r) in &labelled {
        for w in &r.warnings {
            crate::cmd::say(&format!("warning: {f}: {w}"));
        }
    }
    if let Some(path) = &plot {
        let svg = crate::scene::family_chart(&labelled).svg();
        crate::cmd::write_drawing("--plot", path, &svg)?;
    }
    let results: Vec<&fricosc::scene::SceneResult> = labelled.iter().map(|(_, r)| r).collect();
    // One shape of output whatever the number of files: a JSON list, and CSV in
    // long form (one header; each row with its scene and the scene's results).
    // Everything is computed; now it is written as it is formatted (a row's
    // text is never held whole).
    let mut out = io::BufWriter::with_capacity(1 << 16, io::stdout().lock());
    match format {
        Format::Csv => scenes_csv(&mut out, &labelled).map_err(crate::cmd::io_err)?,
        Format::Json => {
            serde_json::to_writer_pretty(&mut out, &results).map_err(|e| crate::cmd::io_err(e.into()))?;
            out.write_all(b"\n").map_err(crate::cmd::io_err)?;
        }
    }
    out.flush().map_err(crate::cmd::io_err)
}

/// Every scene's rows in one CSV table: the scene (its name, or its file), the
/// scene-level results repeated on each row (one amplitude of a family each),
/// then the row's own columns. The columns of the oscillations in the plane
/// are there when a scene has them (empty cells in the others), `mu_static`
/// is empty under them.
fn scenes_csv(out: &mut dyn Write, results: &[(String, SceneResult)]) -> io::Result<()> {
    let n = crate::output::num;
    let opt = |x: Option<f64>| x.map_or_else(String::new, n);
    let tangential = results.iter().any(|(_, r)| r.in_plane.tangential_amp.is_some());
    let transverse = results.iter().any(|(_, r)| r.in_plane.transverse_amp.is_some());
    let mut w = csv::WriterBuilder::new().terminator(csv::Terminator::Any(b'\n')).from_writer(out);
    let fail = crate::output::io_of;
    let mut header = vec!["scene", "u0_m", "du_m", "amp", "contact_radius_m", "critical_velocity_m_per_s", "mu_static"];
    header.extend(if tangential { &["tangential_amp", "phase"][..] } else { &[] });
    header.extend(if transverse { &["transverse_amp", "transverse_phase"][..] } else { &[] });
    header.extend(["velocity_m_per_s", "vbar", "vhat", "mu_macro", "mu_ratio", "mean_friction_force_n"]);
    header.push("mean_normal_force_n");
    header.extend(if transverse { &["transverse_ratio", "mean_transverse_force_n"][..] } else { &[] });
    header.push("regime");
    w.write_record(&header).map_err(fail)?;
    for (label, r) in results {
        let (du, radius, v_crit) = (r.amplitude_m, r.contact_radius_m, r.critical_velocity_m_per_s);
        let mut scene = vec![label.clone(), n(r.mean_indentation_m), n(du), n(r.amplitude_ratio), n(radius)];
        scene.extend([n(v_crit), opt(r.mu_static)]);
        if tangential {
            scene.extend([opt(r.in_plane.tangential_amp), opt(r.in_plane.phase)]);
        }
        if transverse {
            scene.extend([opt(r.in_plane.transverse_amp), opt(r.in_plane.transverse_phase)]);
        }
        for x in r.rows.iter() {
            let mut cells =
                [x.velocity_m_per_s, x.vbar, x.vhat, x.mu_macro, x.mu_ratio, x.mean_friction_force_n].map(n).to_vec();
            cells.push(n(x.mean_normal_force_n));
            if transverse {
                cells.extend([opt(x.transverse_ratio), opt(x.mean_transverse_force_n)]);
            }
            cells.push(x.regime.name().to_string());
            w.write_record(scene.iter().chain(&cells)).map_err(fail)?;
        }
    }
    w.flush()
}

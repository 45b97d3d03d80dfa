//! Figures: SVG written directly (real coordinates to 0.01 pt, Unicode text,
//! a legend outside the plot area) and PNG rendered from that SVG by `resvg`
//! with an embedded font (DejaVu Sans), so a PNG looks the same on every machine.
//!
//! Decisions (the house style of every drawing fricosc makes):
//! - Size: 8.5 cm wide (a journal's single column; 1 SVG unit = 1 pt), text at
//!   7-8 pt, lines 1 pt (bold 2 pt). The SVG scales to a full page; the PNG is
//!   rendered at 300 dpi (1004 px wide).
//! - No title inside the plot (journals set captions below the figure); the
//!   title goes into the SVG's `<title>` element.
//! - Colour: families of curves (one per amplitude) take evenly spaced colours
//!   of viridis (colour-blind safe, monotone in lightness, so it also reads in
//!   greyscale) in the order of the amplitude; the light yellow end is left out.
//!   Single curves take the Okabe-Ito palette. No two curves of one figure
//!   share colour, dash and width ([`distinct`]).
//! - Exact values are solid lines; approximations are dashed (a second one
//!   dotted) in the colour of their amplitude; reference lines (no oscillation,
//!   the critical amplitude) are black or bold.
//! - Text takes a small markup: `_{...}` a subscript, `^{...}` a superscript.

use std::fmt::Write as _;

mod color;
pub use color::{family_color, viridis, Rgb, BLACK, OKABE_ITO};

/// A line's dash pattern.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Dash {
    /// Solid.
    Solid,
    /// Long dashes.
    Dashed,
    /// Dots.
    Dotted,
    /// Dash and dot.
    DashDot,
}

impl Dash {
    fn array(self) -> Option<&'static str> {
        match self {
            Dash::Solid => None,
            Dash::Dashed => Some("4 2"),
            Dash::Dotted => Some("1 1.5"),
            Dash::DashDot => Some("4 1.5 1 1.5"),
        }
    }
}

/// A point marker.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Marker {
    /// A filled circle.
    Circle,
    /// A filled square.
    Square,
    /// A filled triangle.
    Triangle,
    /// A filled diamond.
    Diamond,
    /// A small dot (dense point sets that read as a line).
    Dot,
}

/// How a series is drawn.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Style {
    /// Colour.
    pub color: Rgb,
    /// Dash pattern (`None`: no line, markers only).
    pub dash: Option<Dash>,
    /// Line width (pt).
    pub width: f64,
    /// Marker at each point.
    pub marker: Option<Marker>,
}

impl Style {
    /// A solid line.
    pub fn line(color: Rgb) -> Style {
        Style { color, dash: Some(Dash::Solid), width: 1.0, marker: None }
    }

    /// A line with `dash`.
    pub fn dashed(color: Rgb, dash: Dash) -> Style {
        Style { color, dash: Some(dash), width: 1.0, marker: None }
    }

    /// The same, `width` pt wide.
    pub fn width(self, width: f64) -> Style {
        Style { width, ..self }
    }

    /// The same, with markers.
    pub fn marker(self, marker: Marker) -> Style {
        Style { marker: Some(marker), ..self }
    }
}

/// One curve.
#[derive(Debug, Clone)]
pub struct Series {
    /// Name (the SVG's `data-series`; legend text where `legend` is true).
    pub label: String,
    /// Points in drawing order (non-finite points break the line).
    pub points: Vec<(f64, f64)>,
    /// Style.
    pub style: Style,
    /// Whether the series has its own legend entry.
    pub legend: bool,
}

/// One axis.
#[derive(Debug, Clone)]
pub struct Axis {
    /// Label (with markup), including the unit.
    pub label: String,
    /// Range in data units.
    pub range: (f64, f64),
    /// Logarithmic (base 10).
    pub log: bool,
}

impl Axis {
    /// A linear axis.
    pub fn linear(label: &str, range: (f64, f64)) -> Axis {
        Axis { label: label.into(), range, log: false }
    }

    /// A log10 axis.
    pub fn log(label: &str, range: (f64, f64)) -> Axis {
        Axis { label: label.into(), range, log: true }
    }

    fn t(&self, v: f64) -> f64 {
        if self.log {
            v.log10()
        } else {
            v
        }
    }

    /// Where `v` falls, 0 at the start of the range, 1 at its end.
    fn frac(&self, v: f64) -> f64 {
        let (a, b) = (self.t(self.range.0), self.t(self.range.1));
        (self.t(v) - a) / (b - a)
    }
}

/// A legend entry that is not a series: a heading, or a style sample.
#[derive(Debug, Clone)]
pub enum Key {
    /// A heading line.
    Heading(String),
    /// A sample line in `Style` with its text.
    Entry(Style, String),
}

/// A reference line across the plot (e.g. `mu = mu0`).
#[derive(Debug, Clone)]
pub struct Rule {
    /// Horizontal (`y` = value) or vertical (`x` = value).
    pub horizontal: bool,
    /// Where.
    pub at: f64,
}

/// A chart: axes, series, legend.
#[derive(Debug, Clone)]
pub struct Chart {
    /// Title (the SVG's `<title>`; not drawn).
    pub title: String,
    /// Horizontal axis.
    pub x: Axis,
    /// Vertical axis.
    pub y: Axis,
    /// Curves, drawn in order.
    pub series: Vec<Series>,
    /// Legend, outside the plot on the right: headings and style samples,
    /// followed by the series with `legend` set. Empty: no legend.
    pub key: Vec<Key>,
    /// Thin grey reference lines.
    pub rules: Vec<Rule>,
}

/// Width of the drawing (pt): 8.5 cm.
pub const WIDTH: f64 = 241.0;
const HEIGHT: f64 = 172.0;
const FONT: f64 = 7.5;
const TICK_FONT: f64 = 6.5;
/// Mean advance of DejaVu Sans, in em (for layout).
const EM: f64 = 0.58;
/// The PNG's resolution (dots per inch).
pub const DPI: f64 = 300.0;

fn esc(s: &str) -> String {
    s.replace('&', "&amp;").replace('<', "&lt;").replace('>', "&gt;").replace('"', "&quot;")
}

/// Plain text of a marked-up label (markup removed).
pub fn plain(s: &str) -> String {
    s.replace("_{", "").replace("^{", "").replace('}', "")
}

/// Estimated width of a marked-up label at `size` pt.
fn text_width(s: &str, size: f64) -> f64 {
    let (mut w, mut small) = (0.0, 0usize);
    let mut chars = s.chars().peekable();
    while let Some(c) = chars.next() {
        match c {
            '_' | '^' if chars.peek() == Some(&'{') => {
                chars.next();
                small += 1;
            }
            '}' if small > 0 => small -= 1,
            // Combining marks take no advance.
            '\u{300}'..='\u{36f}' => {}
            _ => w += if small > 0 { 0.7 } else { 1.0 },
        }
    }
    w * EM * size
}

/// SVG text content for a marked-up label: sub- and superscripts as `tspan`s.
fn markup(s: &str, size: f64) -> String {
    let mut out = String::new();
    let mut depth: Vec<bool> = vec![];
    let mut chars = s.chars().peekable();
    let mut buf = String::new();
    while let Some(c) = chars.next() {
        match c {
            '_' | '^' if chars.peek() == Some(&'{') => {
                chars.next();
                out += &esc(&buf);
                buf.clear();
                let shift = if c == '_' { "sub" } else { "super" };
                let _ = write!(out, r#"<tspan baseline-shift="{shift}" font-size="{:.2}">"#, size * 0.7);
                depth.push(true);
            }
            '}' if !depth.is_empty() => {
                out += &esc(&buf);
                buf.clear();
                out += "</tspan>";
                depth.pop();
            }
            _ => buf.push(c),
        }
    }
    out += &esc(&buf);
    for _ in depth {
        out += "</tspan>";
    }
    out
}

/// Four to seven round tick values in `[lo, hi]` (1, 2 or 5 times a power of ten apart).
pub fn ticks(lo: f64, hi: f64) -> Vec<f64> {
    let span = hi - lo;
    if !(span > 0.0 && span.is_finite()) {
        return vec![lo];
    }
    let raw = span / 6.0;
    let p = 10f64.powf(raw.log10().floor());
    let step = [1.0, 2.0, 5.0, 10.0].iter().map(|m| m * p).find(|s| *s >= raw * 0.999).unwrap_or(10.0 * p);
    let (k0, k1) = ((lo / step - 1e-9).ceil() as i64, (hi / step + 1e-9).floor() as i64);
    (k0..=k1).map(|k| k as f64 * step).collect()
}

/// A tick value as text: the fewest decimals of the step, a true minus sign.
fn tick_label(v: f64, step: f64) -> String {
    let d = (-(step.log10().floor())).max(0.0) as usize;
    let s = format!("{:.*}", d, v);
    let s = if s.trim_start_matches('-').chars().all(|c| c == '0' || c == '.') { "0".to_string() } else { s };
    s.replace('-', "\u{2212}")
}

/// Tick positions (data units) and labels for an axis.
fn axis_ticks(a: &Axis) -> Vec<(f64, String)> {
    if a.log {
        let (lo, hi) = (a.range.0.log10(), a.range.1.log10());
        let (k0, k1) = ((lo - 1e-9).ceil() as i64, (hi + 1e-9).floor() as i64);
        let power = |k: i64| format!("10^{{{}}}", k.to_string().replace('-', "\u{2212}"));
        if k1 - k0 >= 2 {
            let every = ((k1 - k0) / 6 + 1).max(1);
            return (k0..=k1).filter(|k| (k - k0) % every == 0).map(|k| (10f64.powi(k as i32), power(k))).collect();
        }
        // Less than two decades: 1, 2 and 5 times the powers of ten in range.
        let (lo, hi) = a.range;
        let mut out = vec![];
        for k in (k0 - 1)..=(k1 + 1) {
            for m in [1.0, 2.0, 5.0] {
                let v = m * 10f64.powi(k as i32);
                if v >= lo * (1.0 - 1e-9) && v <= hi * (1.0 + 1e-9) {
                    let label = match (m == 1.0, (-3..5).contains(&k)) {
                        (_, true) => crate::output::num(v).trim_end_matches(".0").to_string(),
                        (true, false) => power(k),
                        (false, false) => format!("{m}·{}", power(k)),
                    };
                    out.push((v, label));
                }
            }
        }
        out
    } else {
        let t = ticks(a.range.0, a.range.1);
        let step = if t.len() > 1 { t[1] - t[0] } else { 1.0 };
        t.iter().map(|&v| (v, tick_label(v, step))).collect()
    }
}

fn path_data(points: &[(f64, f64)], to: impl Fn(f64, f64) -> Option<(f64, f64)>) -> String {
    let mut d = String::new();
    let mut pen_down = false;
    for &(x, y) in points {
        match to(x, y) {
            Some((px, py)) => {
                let _ = write!(d, "{}{px:.2},{py:.2}", if pen_down { " L" } else { " M" });
                pen_down = true;
            }
            None => pen_down = false,
        }
    }
    d.trim_start().to_string()
}

fn stroke(style: &Style) -> String {
    let mut s = format!(r#"fill="none" stroke="{}" stroke-width="{}""#, style.color.hex(), style.width);
    if let Some(a) = style.dash.and_then(Dash::array) {
        let _ = write!(s, r#" stroke-dasharray="{a}""#);
    }
    s + r#" stroke-linejoin="round" stroke-linecap="butt""#
}

fn marker(out: &mut String, m: Marker, x: f64, y: f64, color: Rgb) {
    let c = color.hex();
    let r = 1.8;
    let _ = match m {
        Marker::Circle => write!(out, r#"<circle cx="{x:.2}" cy="{y:.2}" r="{r}" fill="{c}"/>"#),
        Marker::Square => {
            write!(
                out,
                r#"<rect x="{:.2}" y="{:.2}" width="{:.2}" height="{:.2}" fill="{c}"/>"#,
                x - r,
                y - r,
                2.0 * r,
                2.0 * r
            )
        }
        Marker::Triangle => write!(
            out,
            r#"<path d="M{x:.2},{:.2} L{:.2},{:.2} L{:.2},{:.2} Z" fill="{c}"/>"#,
            y - 1.2 * r,
            x + 1.1 * r,
            y + 0.8 * r,
            x - 1.1 * r,
            y + 0.8 * r
        ),
        Marker::Diamond => write!(
            out,
            r#"<path d="M{x:.2},{:.2} L{:.2},{y:.2} L{x:.2},{:.2} L{:.2},{y:.2} Z" fill="{c}"/>"#,
            y - 1.3 * r,
            x + 1.3 * r,
            y + 1.3 * r,
            x - 1.3 * r
        ),
        Marker::Dot => write!(out, r#"<circle cx="{x:.2}" cy="{y:.2}" r="0.55" fill="{c}"/>"#),
    };
}

/// Whether no two series of `chart` share colour, dash, width and marker, where
/// two colours count as shared unless they differ by `min_delta_e` (CIE76) or more.
pub fn distinct(chart: &Chart, min_delta_e: f64) -> Result<(), String> {
    for (i, a) in chart.series.iter().enumerate() {
        for b in &chart.series[i + 1..] {
            let (s, t) = (a.style, b.style);
            if s.dash == t.dash && s.width == t.width && s.marker == t.marker && s.color.delta_e(t.color) < min_delta_e
            {
                return Err(format!("'{}' and '{}' look the same", a.label, b.label));
            }
        }
    }
    Ok(())
}

/// Where everything of a chart goes: the plot area and the legend.
struct Layout {
    left: f64,
    top: f64,
    /// Plot width and height.
    pw: f64,
    ph: f64,
    /// Height of the whole drawing.
    height: f64,
    /// Room below the plot for tick labels and the x label.
    axes_bottom: f64,
    /// The legend below the plot (else to its right).
    below: bool,
}

/// Legend line height and the width of a style sample.
const KEY_LINE: f64 = FONT * 1.3;
const KEY_SAMPLE: f64 = 14.0;

impl Chart {
    /// The legend: headings, style samples, then the series' own entries.
    fn legend(&self) -> Vec<Key> {
        let mut key = self.key.clone();
        key.extend(self.series.iter().filter(|s| s.legend).map(|s| Key::Entry(s.style, s.label.clone())));
        key
    }

    fn layout(&self, key: &[Key], yt: &[(f64, String)]) -> Layout {
        let key_w = key
            .iter()
            .map(|k| match k {
                Key::Heading(t) => text_width(t, FONT),
                Key::Entry(_, t) => KEY_SAMPLE + 3.0 + text_width(t, FONT),
            })
            .fold(0.0, f64::max);
        let ytw = yt.iter().map(|(_, l)| text_width(l, TICK_FONT)).fold(0.0, f64::max);
        let left = 3.0 + FONT + 6.0 + 1.1 * ytw + 3.0;
        let axes_bottom = 3.0 + TICK_FONT + 3.0 + FONT + 4.0;
        let top = 6.0;
        // A narrow legend goes to the right of the plot, a wide one below it.
        let below = key_w > 0.3 * WIDTH;
        let right = if key.is_empty() || below { 8.0 } else { key_w + 14.0 };
        let key_h = key.len() as f64 * KEY_LINE + 4.0;
        let bottom = if below { axes_bottom + key_h } else { axes_bottom };
        let height = if below { HEIGHT + key_h } else { HEIGHT.max(top + key_h + axes_bottom) };
        Layout { left, top, pw: WIDTH - left - right, ph: height - top - bottom, height, axes_bottom, below }
    }

    /// The chart as an SVG document.
    pub fn svg(&self) -> String {
        let key = self.legend();
        let (xt, yt) = (axis_ticks(&self.x), axis_ticks(&self.y));
        let l = self.layout(&key, &yt);
        let (left, top, pw, ph, height) = (l.left, l.top, l.pw, l.ph, l.height);
        let mut o = String::new();
        let _ = write!(
            o,
            r#"<svg xmlns="http://www.w3.org/2000/svg" width="{WIDTH}pt" height="{height}pt" viewBox="0 0 {WIDTH} {height}" font-family="DejaVu Sans, Verdana, sans-serif">"#
        );
        let _ = write!(o, "<title>{}</title>", esc(&plain(&self.title)));
        let _ = write!(o, r#"<rect width="{WIDTH}" height="{height}" fill="white"/>"#);
        let _ = write!(
            o,
            r#"<clipPath id="plot"><rect x="{left:.2}" y="{top:.2}" width="{pw:.2}" height="{ph:.2}"/></clipPath>"#
        );
        self.axes_svg(&mut o, &l, &xt, &yt);
        self.series_svg(&mut o, &l);
        let _ = write!(
            o,
            r#"<rect x="{left:.2}" y="{top:.2}" width="{pw:.2}" height="{ph:.2}" fill="none" stroke="black" stroke-width="0.6"/>"#
        );
        legend_svg(&mut o, &l, &key);
        o += "</svg>\n";
        o
    }

    fn px(&self, l: &Layout, x: f64) -> f64 {
        l.left + l.pw * self.x.frac(x)
    }

    fn py(&self, l: &Layout, y: f64) -> f64 {
        l.top + l.ph * (1.0 - self.y.frac(y))
    }

    /// Ticks, tick labels and axis labels.
    fn axes_svg(&self, o: &mut String, l: &Layout, xt: &[(f64, String)], yt: &[(f64, String)]) {
        let (left, top, pw, ph) = (l.left, l.top, l.pw, l.ph);
        let _ = write!(o, r#"<g stroke="black" stroke-width="0.5">"#);
        for (v, _) in xt {
            let _ = write!(o, r#"<path d="M{:.2},{:.2} v2.5"/>"#, self.px(l, *v), top + ph);
        }
        for (v, _) in yt {
            let _ = write!(o, r#"<path d="M{left:.2},{:.2} h-2.5"/>"#, self.py(l, *v));
        }
        *o += "</g>";
        let _ = write!(o, r#"<g font-size="{TICK_FONT}" fill="black">"#);
        for (v, t) in xt {
            let (x, y) = (self.px(l, *v), top + ph + 3.0 + TICK_FONT);
            let _ = write!(o, r#"<text x="{x:.2}" y="{y:.2}" text-anchor="middle">{}</text>"#, markup(t, TICK_FONT));
        }
        for (v, t) in yt {
            let (x, y) = (left - 3.5, self.py(l, *v) + TICK_FONT * 0.35);
            let _ = write!(o, r#"<text x="{x:.2}" y="{y:.2}" text-anchor="end">{}</text>"#, markup(t, TICK_FONT));
        }
        *o += "</g>";
        let _ = write!(
            o,
            r#"<text x="{:.2}" y="{:.2}" font-size="{FONT}" text-anchor="middle" class="x-label">{}</text>"#,
            left + pw / 2.0,
            top + ph + l.axes_bottom - 4.0,
            markup(&self.x.label, FONT)
        );
        // A label longer than the plot is tall is set smaller, never clipped.
        let size = FONT.min(FONT * ph / text_width(&self.y.label, FONT).max(1e-9));
        let (lx, ly) = (3.0 + FONT * 0.8, top + ph / 2.0);
        let _ = write!(
            o,
            r#"<text x="{lx:.2}" y="{ly:.2}" font-size="{size:.2}" text-anchor="middle" transform="rotate(-90 {lx:.2} {ly:.2})" class="y-label">{}</text>"#,
            markup(&self.y.label, size)
        );
    }

    /// Reference lines and series, clipped to the plot.
    fn series_svg(&self, o: &mut String, l: &Layout) {
        let (left, top, pw, ph) = (l.left, l.top, l.pw, l.ph);
        let _ = write!(o, r#"<g clip-path="url(#plot)">"#);
        for r in &self.rules {
            let d = if r.horizontal {
                format!("M{left:.2},{:.2} h{pw:.2}", self.py(l, r.at))
            } else {
                format!("M{:.2},{top:.2} v{ph:.2}", self.px(l, r.at))
            };
            let _ = write!(o, r##"<path d="{d}" stroke="#999999" stroke-width="0.5" fill="none"/>"##);
        }
        let inside = |x: f64, y: f64| {
            let ok = x.is_finite() && y.is_finite() && (!self.x.log || x > 0.0) && (!self.y.log || y > 0.0);
            ok.then(|| (self.px(l, x), self.py(l, y)))
        };
        for s in &self.series {
            let _ = write!(o, r#"<g data-series="{}">"#, esc(&plain(&s.label)));
            if s.style.dash.is_some() {
                let _ = write!(o, r#"<path d="{}" {}/>"#, path_data(&s.points, inside), stroke(&s.style));
            }
            if let Some(m) = s.style.marker {
                for &(x, y) in &s.points {
                    if let Some((x, y)) = inside(x, y) {
                        marker(o, m, x, y, s.style.color);
                    }
                }
            }
            *o += "</g>";
        }
        *o += "</g>";
    }
}

/// The legend, right of the plot or below it.
fn legend_svg(o: &mut String, l: &Layout, key: &[Key]) {
    if key.is_empty() {
        return;
    }
    let (x0, y0) = if l.below { (l.left, l.top + l.ph + l.axes_bottom) } else { (l.left + l.pw + 8.0, l.top) };
    let _ = write!(o, r#"<g font-size="{FONT}" class="legend">"#);
    for (i, k) in key.iter().enumerate() {
        let y = y0 + KEY_LINE * (i as f64 + 0.75);
        match k {
            Key::Heading(t) => {
                let _ = write!(o, r#"<text x="{x0:.2}" y="{:.2}">{}</text>"#, y + FONT * 0.35, markup(t, FONT));
            }
            Key::Entry(st, t) => {
                if st.dash.is_some() {
                    let _ = write!(o, r#"<path d="M{x0:.2},{y:.2} h{KEY_SAMPLE}" {}/>"#, stroke(st));
                }
                if let Some(m) = st.marker {
                    marker(o, m, x0 + KEY_SAMPLE / 2.0, y, st.color);
                }
                let (x, yt) = (x0 + KEY_SAMPLE + 3.0, y + FONT * 0.35);
                let _ = write!(o, r#"<text x="{x:.2}" y="{yt:.2}">{}</text>"#, markup(t, FONT));
            }
        }
    }
    *o += "</g>";
}

/// The font PNGs are drawn with, built in.
fn fonts() -> resvg::usvg::Options<'static> {
    let mut opt = resvg::usvg::Options { font_family: "DejaVu Sans".into(), ..Default::default() };
    let db = opt.fontdb_mut();
    db.load_font_data(dejavu::sans::regular().to_vec());
    db.load_font_data(dejavu::sans::oblique().to_vec());
    db.set_sans_serif_family("DejaVu Sans");
    opt
}

/// Render an SVG document as a PNG at [`DPI`] (the same pixels on every machine:
/// the only font is the built-in DejaVu Sans).
pub fn png(svg: &str) -> Result<Vec<u8>, String> {
    let tree = resvg::usvg::Tree::from_str(svg, &fonts()).map_err(|e| e.to_string())?;
    let scale = (DPI / 96.0) as f32;
    let size = tree.size();
    let (w, h) = ((size.width() * scale).round() as u32, (size.height() * scale).round() as u32);
    let mut pixmap = resvg::tiny_skia::Pixmap::new(w, h).ok_or("empty drawing")?;
    resvg::render(&tree, resvg::tiny_skia::Transform::from_scale(scale, scale), &mut pixmap.as_mut());
    pixmap.encode_png().map_err(|e| e.to_string())
}

/// Check that `svg` parses as SVG (with `resvg`'s parser) and return its size
/// in pt (to 0.01 pt: the parser works in `f32`).
pub fn parse_size(svg: &str) -> Result<(f64, f64), String> {
    let tree = resvg::usvg::Tree::from_str(svg, &fonts()).map_err(|e| e.to_string())?;
    let s = tree.size();
    let pt = |px: f32| (px as f64 * 75.0).round() / 100.0;
    Ok((pt(s.width()), pt(s.height())))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A log axis over less than two decades has 1-2-5 ticks (the series plot's
    /// 250 to 8000 had one label); over more, powers of ten.
    #[test]
    fn log_axes_have_ticks_over_short_ranges() {
        let labels = |lo: f64, hi: f64| -> Vec<String> {
            axis_ticks(&Axis::log("x", (lo, hi))).into_iter().map(|t| t.1).collect()
        };
        assert_eq!(labels(250.0 / 1.2, 8000.0 * 1.2), ["500", "1000", "2000", "5000"]);
        assert_eq!(labels(1e-9, 1e-2), ["10^{−9}", "10^{−7}", "10^{−5}", "10^{−3}"]);
        assert_eq!(labels(2e-7, 3e-6), ["2·10^{−7}", "5·10^{−7}", "10^{−6}", "2·10^{−6}"]);
    }

    /// A y label longer than the plot is tall is set smaller to fit, not clipped.
    #[test]
    fn long_y_labels_fit() {
        let label = "a very long label ".repeat(8);
        let chart = Chart {
            title: "t".into(),
            x: Axis::linear("x", (0.0, 1.0)),
            y: Axis::linear(&label, (0.0, 1.0)),
            series: vec![],
            key: vec![],
            rules: vec![],
        };
        let svg = chart.svg();
        let at = svg.find("class=\"y-label\"").unwrap();
        let size: f64 = svg[..at].rsplit("font-size=\"").next().unwrap().split('"').next().unwrap().parse().unwrap();
        let l = chart.layout(&[], &axis_ticks(&chart.y));
        assert!(size < FONT && text_width(&label, size) <= l.ph + 0.01, "{size}");
    }

    #[test]
    fn ticks_are_round() {
        assert_eq!(ticks(0.0, 1.2), vec![0.0, 0.2, 0.4, 0.6000000000000001, 0.8, 1.0, 1.2000000000000002]);
        assert_eq!(tick_label(0.6000000000000001, 0.2), "0.6");
        assert_eq!(tick_label(-0.5, 0.5), "\u{2212}0.5");
        assert_eq!(tick_label(-0.0, 0.5), "0");
        assert_eq!(ticks(0.0, 0.1).len(), 6);
    }

    #[test]
    fn markup_nests_and_escapes() {
        assert_eq!(markup("μ_{a<b}/x", 10.0), r#"μ<tspan baseline-shift="sub" font-size="7.00">a&lt;b</tspan>/x"#);
        assert_eq!(plain("Δu_{z}/u_{z0}"), "Δuz/uz0");
    }

    #[test]
    fn viridis_ends_and_distance() {
        assert_eq!(viridis(0.0), Rgb(0x44, 0x01, 0x54));
        assert_eq!(viridis(1.0), Rgb(0xfd, 0xe7, 0x25));
        // CIE76: black to white is 100.
        assert!((BLACK.delta_e(Rgb(255, 255, 255)) - 100.0).abs() < 0.01);
    }
}

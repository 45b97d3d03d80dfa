//! SVG line plots (plotters' SVG backend only: no font or system library).

use plotters::prelude::*;

/// One curve: label, points, dashed (an approximation) or solid (exact).
pub struct Series {
    /// Legend label.
    pub label: String,
    /// Points in order of `x`.
    pub points: Vec<(f64, f64)>,
    /// Dashed line (used for the seed's approximations).
    pub dashed: bool,
}

/// A linear-axes line plot with a legend, as an SVG document.
pub fn lines(
    title: &str,
    x_label: &str,
    y_label: &str,
    x: (f64, f64),
    y: (f64, f64),
    series: &[Series],
) -> Result<String, String> {
    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, (900, 600)).into_drawing_area();
        root.fill(&WHITE).map_err(|e| e.to_string())?;
        let mut chart = ChartBuilder::on(&root)
            .caption(title, ("sans-serif", 20))
            .margin(15)
            .x_label_area_size(45)
            .y_label_area_size(60)
            .build_cartesian_2d(x.0..x.1, y.0..y.1)
            .map_err(|e| e.to_string())?;
        chart.configure_mesh().x_desc(x_label).y_desc(y_label).draw().map_err(|e| e.to_string())?;
        for (i, s) in series.iter().enumerate() {
            let color = Palette99::pick(i).to_rgba();
            let style = color.stroke_width(2);
            if s.dashed {
                // Dashes: every other segment of a fine resampling.
                let segs: Vec<Vec<(f64, f64)>> = s.points.windows(2).step_by(2).map(|w| w.to_vec()).collect();
                let mut first = true;
                for seg in segs {
                    let a = chart.draw_series(LineSeries::new(seg, style)).map_err(|e| e.to_string())?;
                    if first {
                        a.label(s.label.clone())
                            .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 8, y)], style));
                        first = false;
                    }
                }
            } else {
                chart
                    .draw_series(LineSeries::new(s.points.clone(), style))
                    .map_err(|e| e.to_string())?
                    .label(s.label.clone())
                    .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], style));
            }
        }
        chart
            .configure_series_labels()
            .position(SeriesLabelPosition::LowerRight)
            .background_style(WHITE.mix(0.85))
            .border_style(BLACK)
            .draw()
            .map_err(|e| e.to_string())?;
        root.present().map_err(|e| e.to_string())?;
    }
    Ok(svg)
}

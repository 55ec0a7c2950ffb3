//! SVG plots of the experiments (plotters' SVG backend): the distribution of w(e) per model
//! (Observation 1), all models' distributions together (Observation 2, uniform against
//! non-uniform), and w/l against l on log-log axes with the fitted power laws, and w(e)
//! against the scale (Observation 3).

use super::Runs;
use exact_geodesics::experiments::{ResolutionFit, ScaleRow};
use plotters::coord::Shift;
use plotters::prelude::*;
use std::path::Path;

const SIZE: (u32, u32) = (720, 480);
const FONT: &str = "sans-serif";

/// Table 1's plots, of the runs in the first backend (every source pooled):
/// `DIR/table1_wedges_I_NAME.svg`, the histogram of w(e) on model I, and
/// `DIR/table1_distributions.svg`, the share of edges with each w(e) on every model.
pub fn table1(dir: &Path, runs: &[Runs]) -> Result<(), String> {
    let Some(first) = runs.first().map(|r| r.backend) else {
        return Ok(());
    };
    let mut shares = Vec::new();
    for (i, run) in runs.iter().filter(|r| r.backend == first).enumerate() {
        let pooled: Vec<usize> = run
            .measurements
            .iter()
            .flat_map(|m| m.per_edge.iter().copied())
            .collect();
        let share = share_per_count(&pooled);
        let title = format!(
            "w(e) on {} ({}, {} sources pooled)",
            file_name(&run.model),
            first.name(),
            run.measurements.len()
        );
        let path = dir.join(format!("table1_wedges_{i}_{}.svg", file_stem(&run.model)));
        draw(&path, |root| histogram(root, &title, &share))?;
        shares.push((file_name(&run.model), share));
    }
    let title = format!("share of edges with w(e) wedges ({})", first.name());
    draw(&dir.join("table1_distributions.svg"), |root| {
        distributions(root, &title, &shares)
    })
}

/// Observation 3 by scale: mean w(e) (over the sources) against the power of the scale, one
/// line per model and backend.
pub fn scale(path: &Path, rows: &[ScaleRow]) -> Result<(), String> {
    let mut lines: Vec<(String, Vec<(f64, f64)>)> = Vec::new();
    for row in rows {
        let name = format!("{} {}", file_name(&row.model), row.backend.name());
        let x = f64::from(row.scale_exponent);
        let line = match lines.iter_mut().find(|(n, _)| *n == name) {
            Some((_, line)) => line,
            None => {
                lines.push((name, Vec::new()));
                &mut lines.last_mut().expect("just pushed").1
            }
        };
        line.push((x, row.wedges_mean));
    }
    // Average the sources at each power.
    let lines: Vec<(String, Vec<(f64, f64)>)> = lines
        .into_iter()
        .map(|(name, points)| {
            let mut xs: Vec<f64> = points.iter().map(|p| p.0).collect();
            xs.sort_by(f64::total_cmp);
            xs.dedup();
            let mean = |x: f64| {
                let at: Vec<f64> = points.iter().filter(|p| p.0 == x).map(|p| p.1).collect();
                at.iter().sum::<f64>() / at.len() as f64
            };
            (name, xs.into_iter().map(|x| (x, mean(x))).collect())
        })
        .collect();
    let base = rows.first().map_or(10, |r| r.scale_base);
    draw(path, |root| {
        let (x, y) = bounds(lines.iter().flat_map(|(_, p)| p.iter().copied()));
        let y = pad(y);
        let mut chart = ChartBuilder::on(root)
            .caption("mean w(e) of a model scaled uniformly", (FONT, 20))
            .margin(12)
            .x_label_area_size(40)
            .y_label_area_size(60)
            .build_cartesian_2d(x.0..x.1, y.0..y.1)
            .map_err(text)?;
        chart
            .configure_mesh()
            .x_desc(format!("log{base} of the scale"))
            .y_desc("mean w(e)")
            .x_label_formatter(&|v| format!("{v:.0}"))
            .draw()
            .map_err(text)?;
        for (i, (name, points)) in lines.iter().enumerate() {
            let color = Palette99::pick(i).to_rgba();
            chart
                .draw_series(LineSeries::new(points.iter().copied(), color))
                .map_err(text)?
                .label(name.as_str())
                .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], color));
            chart
                .draw_series(points.iter().map(|&p| Circle::new(p, 3, color.filled())))
                .map_err(text)?;
        }
        legend(&mut chart, SeriesLabelPosition::UpperRight)
    })
}

/// Observation 3 by resolution: w/l against l on log-log axes, the levels of each series and
/// backend as points, with the fitted line and its exponent in the legend.
pub fn resolution(path: &Path, fits: &[ResolutionFit]) -> Result<(), String> {
    let points = |f: &ResolutionFit| -> Vec<(f64, f64)> {
        f.points
            .iter()
            .map(|p| (p.edge_length_mean, p.wedges_per_unit_length))
            .collect()
    };
    draw(path, |root| {
        let (x, y) = bounds(fits.iter().flat_map(points));
        let mut chart = ChartBuilder::on(root)
            .caption(
                "wedges per unit length against mean edge length",
                (FONT, 20),
            )
            .margin(12)
            .x_label_area_size(40)
            .y_label_area_size(60)
            .build_cartesian_2d(
                (x.0 / 1.2..x.1 * 1.2).log_scale(),
                (y.0 / 1.5..y.1 * 1.5).log_scale(),
            )
            .map_err(text)?;
        chart
            .configure_mesh()
            .x_desc("mean edge length l (unit cube)")
            .y_desc("mean w(e) / l")
            .x_label_formatter(&|v| tick(*v))
            .y_label_formatter(&|v| tick(*v))
            .draw()
            .map_err(text)?;
        for (i, f) in fits.iter().enumerate() {
            let color = Palette99::pick(i).to_rgba();
            let pts = points(f);
            chart
                .draw_series(pts.iter().map(|&p| Circle::new(p, 3, color.filled())))
                .map_err(text)?;
            let label = match f.fit {
                Some(fit) => format!(
                    "{} {}: exponent {:.2} [{:.2}, {:.2}]",
                    series_name(&f.series),
                    f.backend.name(),
                    fit.slope,
                    fit.slope_ci95[0],
                    fit.slope_ci95[1]
                ),
                None => format!("{} {}", series_name(&f.series), f.backend.name()),
            };
            let line: Vec<(f64, f64)> = match f.fit {
                Some(fit) => pts
                    .iter()
                    .map(|&(l, _)| (l, (fit.intercept + fit.slope * l.ln()).exp()))
                    .collect(),
                None => pts.clone(),
            };
            chart
                .draw_series(LineSeries::new(line, color))
                .map_err(text)?
                .label(label)
                .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], color));
        }
        legend(&mut chart, SeriesLabelPosition::LowerLeft)
    })
}

/// A histogram of shares: bar k is the share of edges with w(e) = k.
fn histogram(root: &Area, title: &str, share: &[f64]) -> Result<(), String> {
    let top = share.iter().copied().fold(0.0, f64::max) * 1.1;
    let mut chart = ChartBuilder::on(root)
        .caption(title, (FONT, 20))
        .margin(12)
        .x_label_area_size(40)
        .y_label_area_size(60)
        .build_cartesian_2d(
            -0.5..share.len() as f64 - 0.5,
            0.0..top.max(f64::MIN_POSITIVE),
        )
        .map_err(text)?;
    chart
        .configure_mesh()
        .disable_x_mesh()
        .x_desc("w(e): final wedges on the edge")
        .y_desc("share of edges")
        .draw()
        .map_err(text)?;
    chart
        .draw_series(share.iter().enumerate().map(|(k, &s)| {
            let k = k as f64;
            Rectangle::new([(k - 0.45, 0.0), (k + 0.45, s)], BLUE.mix(0.7).filled())
        }))
        .map_err(text)?;
    Ok(())
}

/// Every model's share of edges per w(e), as lines.
fn distributions(root: &Area, title: &str, shares: &[(String, Vec<f64>)]) -> Result<(), String> {
    let points = shares
        .iter()
        .flat_map(|(_, s)| s.iter().enumerate().map(|(k, &v)| (k as f64, v)));
    let (x, y) = bounds(points);
    let mut chart = ChartBuilder::on(root)
        .caption(title, (FONT, 20))
        .margin(12)
        .x_label_area_size(40)
        .y_label_area_size(60)
        .build_cartesian_2d(0.0..x.1.max(1.0), 0.0..(y.1 * 1.1).max(f64::MIN_POSITIVE))
        .map_err(text)?;
    chart
        .configure_mesh()
        .x_desc("w(e): final wedges on the edge")
        .y_desc("share of edges")
        .draw()
        .map_err(text)?;
    for (i, (name, share)) in shares.iter().enumerate() {
        let color = Palette99::pick(i).to_rgba();
        chart
            .draw_series(LineSeries::new(
                share.iter().enumerate().map(|(k, &v)| (k as f64, v)),
                color,
            ))
            .map_err(text)?
            .label(name.as_str())
            .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], color));
    }
    legend(&mut chart, SeriesLabelPosition::UpperRight)
}

type Area<'a> = DrawingArea<SVGBackend<'a>, Shift>;

/// Draws into an SVG file of [`SIZE`].
fn draw(path: &Path, paint: impl FnOnce(&Area) -> Result<(), String>) -> Result<(), String> {
    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, SIZE).into_drawing_area();
        root.fill(&WHITE).map_err(text)?;
        paint(&root)?;
        root.present().map_err(text)?;
    }
    std::fs::write(path, svg).map_err(|e| format!("{}: {e}", path.display()))
}

fn legend<'a, X, Y>(
    chart: &mut ChartContext<'a, SVGBackend<'a>, Cartesian2d<X, Y>>,
    position: SeriesLabelPosition,
) -> Result<(), String>
where
    X: Ranged,
    Y: Ranged,
{
    chart
        .configure_series_labels()
        .position(position)
        .background_style(WHITE.mix(0.8))
        .border_style(BLACK)
        .draw()
        .map_err(text)
}

/// The share of the values equal to each k = 0..=max.
fn share_per_count(values: &[usize]) -> Vec<f64> {
    let mut counts = vec![0usize; values.iter().max().map_or(1, |m| m + 1)];
    for &v in values {
        counts[v] += 1;
    }
    let n = values.len().max(1) as f64;
    counts.into_iter().map(|c| c as f64 / n).collect()
}

/// The smallest and largest x and y of `points` (`(0, 1)` each when there are none).
fn bounds(points: impl Iterator<Item = (f64, f64)>) -> ((f64, f64), (f64, f64)) {
    let mut x = (f64::INFINITY, f64::NEG_INFINITY);
    let mut y = x;
    for (a, b) in points {
        x = (x.0.min(a), x.1.max(a));
        y = (y.0.min(b), y.1.max(b));
    }
    let finite = |r: (f64, f64)| if r.0 <= r.1 { r } else { (0.0, 1.0) };
    (finite(x), finite(y))
}

/// A range widened by 5 % of its span (or of its value, when it is one point).
fn pad(r: (f64, f64)) -> (f64, f64) {
    let margin = 0.05 * (r.1 - r.0).max(r.1.abs()).max(1.0);
    (r.0 - margin, r.1 + margin)
}

/// A tick label with three significant digits and no trailing zeros.
fn tick(v: f64) -> String {
    if v == 0.0 || !v.is_finite() {
        return v.to_string();
    }
    let digits = (2 - v.abs().log10().floor() as i32).max(0) as usize;
    let text = format!("{v:.digits$}");
    if text.contains('.') {
        text.trim_end_matches('0').trim_end_matches('.').to_owned()
    } else {
        text
    }
}

/// A model's name without its directory.
fn file_name(model: &str) -> String {
    Path::new(model)
        .file_name()
        .map_or(model.to_owned(), |n| n.to_string_lossy().into_owned())
}

/// A series' name with any model path reduced to its file name.
fn series_name(series: &str) -> String {
    match series.split_once(':') {
        Some(("refined", model)) => format!("refined {}", file_name(model)),
        _ => series.to_owned(),
    }
}

/// A model's name as part of a file name: its file stem, other characters than letters,
/// digits, `-` and `_` replaced by `_`.
fn file_stem(model: &str) -> String {
    let stem = Path::new(model)
        .file_stem()
        .map_or(model.to_owned(), |n| n.to_string_lossy().into_owned());
    stem.chars()
        .map(|c| {
            if c.is_ascii_alphanumeric() || c == '-' || c == '_' {
                c
            } else {
                '_'
            }
        })
        .collect()
}

fn text(e: impl std::fmt::Display) -> String {
    format!("plot: {e}")
}

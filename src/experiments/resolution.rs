//! Observation 3 [LZT §6] tested by resolution: one surface meshed ever finer, each mesh
//! normalized into the unit cube. The paper states that the wedges per unit length
//! `mean w(e) / mean l(e)` are "inversely proportional to the average edge length", i.e.
//! `w/l ~ l^-1` (w(e) independent of the mesh); the fitted exponent of `w/l` against `l` on
//! log-log axes, with its confidence interval, says whether it is so. Since
//! `ln(w/l) = ln w - ln l`, the exponent of `w` alone is that exponent plus one.

use super::tables::csv_field;
use super::{LineFit, Measurement, ModelShape};
use crate::scalar::Backend;
use serde::Serialize;

/// One mesh of a resolution series, from one source vertex.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct ResolutionRow {
    /// The series (`icosphere`, `grid`, `refined:MODEL`, ...).
    pub series: String,
    /// The mesh (its file or `gen:` spec, with the refinement).
    pub model: String,
    /// Its place in the series (finer with each level).
    pub level: u32,
    /// The number type.
    pub backend: Backend,
    /// The source vertex (0-based index).
    pub source: u32,
    /// Number of faces.
    pub faces: usize,
    /// Number of edges.
    pub edges: usize,
    /// Mean edge length in the unit cube.
    pub edge_length_mean: f64,
    /// Mean of w(e) over all edges.
    pub wedges_mean: f64,
    /// `mean w(e) / mean l(e)`.
    pub wedges_per_unit_length: f64,
    /// Decisions the exact backend left uncertified (0 in the float backends).
    pub uncertified: u64,
}

impl ResolutionRow {
    /// The CSV header, in field order.
    pub const CSV_HEADER: &'static str = "series,model,level,backend,source,faces,edges,\
edge_length_mean,wedges_mean,wedges_per_unit_length,uncertified";

    /// The row of `model`, level `level` of `series`, measured in `backend`; `shape` is the
    /// model normalized into the unit cube.
    pub fn new(
        series: &str,
        model: &str,
        level: u32,
        backend: Backend,
        shape: &ModelShape,
        measured: &Measurement,
    ) -> Self {
        let counts = &measured.counts;
        ResolutionRow {
            series: series.to_owned(),
            model: model.to_owned(),
            level,
            backend,
            source: counts.source.0,
            faces: shape.faces,
            edges: shape.edges,
            edge_length_mean: shape.edge_length.mean,
            wedges_mean: counts.per_edge.mean,
            wedges_per_unit_length: counts.per_edge.mean / shape.edge_length.mean,
            uncertified: measured.uncertified,
        }
    }

    /// The row as one CSV record (no line end), fields as in [`Self::CSV_HEADER`].
    pub fn csv_record(&self) -> String {
        format!(
            "{},{},{},{},{},{},{},{},{},{},{}",
            csv_field(&self.series),
            csv_field(&self.model),
            self.level,
            self.backend.name(),
            self.source,
            self.faces,
            self.edges,
            self.edge_length_mean,
            self.wedges_mean,
            self.wedges_per_unit_length,
            self.uncertified,
        )
    }
}

/// One level of a series: its rows averaged over the sources.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct ResolutionPoint {
    /// The level.
    pub level: u32,
    /// Mean edge length l.
    pub edge_length_mean: f64,
    /// Mean of w(e), averaged over the sources: w.
    pub wedges_mean: f64,
    /// `w / l`.
    pub wedges_per_unit_length: f64,
}

/// The power law `w/l = c l^exponent` fitted to one series in one backend: the least-squares
/// line of `ln(w/l)` against `ln l` over its levels (each level's `w` averaged over its
/// sources, so that the points are independent meshes), its slope being the exponent.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct ResolutionFit {
    /// The series.
    pub series: String,
    /// The number type.
    pub backend: Backend,
    /// The levels, finest last.
    pub points: Vec<ResolutionPoint>,
    /// The line through `(ln l, ln(w/l))`; `None` with fewer than three levels.
    pub fit: Option<LineFit>,
}

impl ResolutionFit {
    /// The CSV header of [`Self::csv_record`]. `exponent` is the fitted slope, `ci95_low` and
    /// `ci95_high` its 95 % confidence interval, `intercept` is `ln c`.
    pub const CSV_HEADER: &'static str =
        "series,backend,levels,exponent,std_error,ci95_low,ci95_high,intercept";

    /// The fit as one CSV record (no line end); the fitted fields are empty without a fit.
    pub fn csv_record(&self) -> String {
        let fitted = self.fit.map_or_else(
            || ",,,,".to_owned(),
            |f| {
                format!(
                    "{},{},{},{},{}",
                    f.slope, f.slope_std_error, f.slope_ci95[0], f.slope_ci95[1], f.intercept
                )
            },
        );
        format!(
            "{},{},{},{fitted}",
            csv_field(&self.series),
            self.backend.name(),
            self.points.len()
        )
    }
}

/// Fits every (series, backend) of `rows`, in the order they first appear; within one, the
/// rows of a level are averaged over their sources and the levels are sorted.
///
/// # Example
/// ```
/// use exact_geodesics::experiments::{fit_resolution, ResolutionRow};
/// use exact_geodesics::scalar::Backend;
/// // w = 1 at every level (the paper's claim): w/l = 1/l, exponent -1.
/// let rows: Vec<ResolutionRow> = (0..4)
///     .map(|level| {
///         let l = 0.5f64.powi(level as i32);
///         ResolutionRow {
///             series: "s".into(), model: format!("m{level}"), level, backend: Backend::F64,
///             source: 0, faces: 0, edges: 0, edge_length_mean: l, wedges_mean: 1.0,
///             wedges_per_unit_length: 1.0 / l, uncertified: 0,
///         }
///     })
///     .collect();
/// let fits = fit_resolution(&rows);
/// let fit = fits[0].fit.expect("four levels");
/// assert!((fit.slope + 1.0).abs() < 1e-12);
/// ```
pub fn fit_resolution(rows: &[ResolutionRow]) -> Vec<ResolutionFit> {
    let mut groups: Vec<(&str, Backend)> = Vec::new();
    for row in rows {
        if !groups.contains(&(row.series.as_str(), row.backend)) {
            groups.push((&row.series, row.backend));
        }
    }
    groups
        .into_iter()
        .map(|(series, backend)| {
            let mine: Vec<&ResolutionRow> = rows
                .iter()
                .filter(|r| r.series == series && r.backend == backend)
                .collect();
            let mut levels: Vec<u32> = mine.iter().map(|r| r.level).collect();
            levels.sort_unstable();
            levels.dedup();
            let points: Vec<ResolutionPoint> = levels
                .into_iter()
                .map(|level| {
                    let at: Vec<&&ResolutionRow> =
                        mine.iter().filter(|r| r.level == level).collect();
                    let l = at[0].edge_length_mean;
                    let w = at.iter().map(|r| r.wedges_mean).sum::<f64>() / at.len() as f64;
                    ResolutionPoint {
                        level,
                        edge_length_mean: l,
                        wedges_mean: w,
                        wedges_per_unit_length: w / l,
                    }
                })
                .collect();
            let x: Vec<f64> = points.iter().map(|p| p.edge_length_mean.ln()).collect();
            let y: Vec<f64> = points
                .iter()
                .map(|p| p.wedges_per_unit_length.ln())
                .collect();
            ResolutionFit {
                series: series.to_owned(),
                backend,
                fit: LineFit::of(&x, &y),
                points,
            }
        })
        .collect()
}

//! The rows of Tables 1 and 2 [LZT §6]: one per (model, backend, source vertex), with their CSV
//! form. Lengths and angles are those of the model normalized into the unit cube.

use super::{min_angle_summary, Summary, WedgeCounts};
use crate::scalar::Backend;
use crate::TriMesh;
use serde::Serialize;

/// What Tables 1-2 need of a model apart from its wedges: its size, edge lengths and uniformity,
/// measured on the mesh normalized into the unit cube ([`super::normalize_to_unit_cube`]).
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct ModelShape {
    /// Number of faces.
    pub faces: usize,
    /// Number of edges.
    pub edges: usize,
    /// l(e) over all edges [LZT Table 2].
    pub edge_length: Summary,
    /// The per-face minimal angle in degrees; its `max` is the paper's uniformity measure.
    pub min_angle: Summary,
}

impl ModelShape {
    /// Measures `normalized`, a mesh already normalized into the unit cube.
    ///
    /// # Example
    /// ```
    /// use exact_geodesics::{experiments::ModelShape, mesh::shapes};
    /// let shape = ModelShape::of(&shapes::cube());
    /// assert_eq!((shape.faces, shape.edges), (12, 18));
    /// assert_eq!((shape.edge_length.min, shape.edge_length.max), (1.0, 2f64.sqrt()));
    /// ```
    pub fn of(normalized: &TriMesh) -> ModelShape {
        ModelShape {
            faces: normalized.face_count(),
            edges: normalized.edge_count(),
            edge_length: Summary::of(normalized.edge_lengths())
                .expect("a TriMesh has at least one face, so edges"),
            min_angle: min_angle_summary(normalized),
        }
    }
}

/// A row of Table 1 [LZT §6]: w(e) from one source, its mean, standard deviation (population)
/// and maximum, the propagation time, and the model's uniformity.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Table1Row {
    /// The model's name (its file or `gen:` spec).
    pub model: String,
    /// The number type.
    pub backend: Backend,
    /// The source vertex (0-based index).
    pub source: u32,
    /// Number of faces.
    pub faces: usize,
    /// Number of edges.
    pub edges: usize,
    /// Mean of w(e) over all edges.
    pub wedges_mean: f64,
    /// Population standard deviation of w(e).
    pub wedges_std: f64,
    /// Largest w(e).
    pub wedges_max: f64,
    /// Propagation time in seconds.
    pub seconds: f64,
    /// Population skewness of w(e).
    pub wedges_skewness: f64,
    /// Sum of w(e).
    pub wedges_total: usize,
    /// Edges with w(e) = 0 (counted as zeros in the statistics).
    pub edges_without_wedges: usize,
    /// The smallest fraction of the edges holding half of all wedges (Observation 1).
    pub edges_holding_half: f64,
    /// The paper's uniformity: the largest per-face minimal angle, in degrees.
    pub min_angle_max: f64,
    /// Mean per-face minimal angle, in degrees.
    pub min_angle_mean: f64,
    /// Smallest per-face minimal angle, in degrees.
    pub min_angle_min: f64,
}

/// A row of Table 2 [LZT §6]: l(e) of the normalized model and wedges per unit length
/// `mean w(e) / mean l(e)`, with the propagation time (the paper's Table 2 models are the large
/// ones, where times compare best).
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Table2Row {
    /// The model's name (its file or `gen:` spec).
    pub model: String,
    /// The number type.
    pub backend: Backend,
    /// The source vertex (0-based index).
    pub source: u32,
    /// Mean edge length.
    pub edge_length_mean: f64,
    /// Population standard deviation of the edge length.
    pub edge_length_std: f64,
    /// Longest edge.
    pub edge_length_max: f64,
    /// Shortest edge.
    pub edge_length_min: f64,
    /// `mean w(e) / mean l(e)`.
    pub wedges_per_unit_length: f64,
    /// Mean of w(e), as in Table 1.
    pub wedges_mean: f64,
    /// Number of edges.
    pub edges: usize,
    /// Propagation time in seconds, as in Table 1.
    pub seconds: f64,
}

impl Table1Row {
    /// The CSV header, in field order.
    pub const CSV_HEADER: &'static str = "model,backend,source,faces,edges,wedges_mean,wedges_std,\
wedges_max,seconds,wedges_skewness,wedges_total,edges_without_wedges,edges_holding_half,\
min_angle_max,min_angle_mean,min_angle_min";

    /// The row of `model` (a name) measured in `backend`.
    pub fn new(model: &str, backend: Backend, shape: &ModelShape, counts: &WedgeCounts) -> Self {
        Table1Row {
            model: model.to_owned(),
            backend,
            source: counts.source.0,
            faces: shape.faces,
            edges: shape.edges,
            wedges_mean: counts.per_edge.mean,
            wedges_std: counts.per_edge.std,
            wedges_max: counts.per_edge.max,
            seconds: counts.seconds,
            wedges_skewness: counts.per_edge.skewness,
            wedges_total: counts.total,
            edges_without_wedges: counts.edges_without_wedges,
            edges_holding_half: counts.edges_holding_half,
            min_angle_max: shape.min_angle.max,
            min_angle_mean: shape.min_angle.mean,
            min_angle_min: shape.min_angle.min,
        }
    }

    /// The row as one CSV record (no line end), fields as in [`Self::CSV_HEADER`]; numbers in
    /// Rust's shortest round-trip form.
    pub fn csv_record(&self) -> String {
        format!(
            "{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{}",
            csv_field(&self.model),
            self.backend.name(),
            self.source,
            self.faces,
            self.edges,
            self.wedges_mean,
            self.wedges_std,
            self.wedges_max,
            self.seconds,
            self.wedges_skewness,
            self.wedges_total,
            self.edges_without_wedges,
            self.edges_holding_half,
            self.min_angle_max,
            self.min_angle_mean,
            self.min_angle_min,
        )
    }
}

impl Table2Row {
    /// The CSV header, in field order.
    pub const CSV_HEADER: &'static str = "model,backend,source,edge_length_mean,edge_length_std,\
edge_length_max,edge_length_min,wedges_per_unit_length,wedges_mean,edges,seconds";

    /// The row of `model` (a name) measured in `backend`.
    pub fn new(model: &str, backend: Backend, shape: &ModelShape, counts: &WedgeCounts) -> Self {
        let l = &shape.edge_length;
        Table2Row {
            model: model.to_owned(),
            backend,
            source: counts.source.0,
            edge_length_mean: l.mean,
            edge_length_std: l.std,
            edge_length_max: l.max,
            edge_length_min: l.min,
            wedges_per_unit_length: counts.per_edge.mean / l.mean,
            wedges_mean: counts.per_edge.mean,
            edges: shape.edges,
            seconds: counts.seconds,
        }
    }

    /// The row as one CSV record (no line end), fields as in [`Self::CSV_HEADER`].
    pub fn csv_record(&self) -> String {
        format!(
            "{},{},{},{},{},{},{},{},{},{},{}",
            csv_field(&self.model),
            self.backend.name(),
            self.source,
            self.edge_length_mean,
            self.edge_length_std,
            self.edge_length_max,
            self.edge_length_min,
            self.wedges_per_unit_length,
            self.wedges_mean,
            self.edges,
            self.seconds,
        )
    }
}

/// A CSV field: quoted (with doubled quotes) when it holds a comma, quote or line break.
pub(super) fn csv_field(text: &str) -> String {
    if text.contains([',', '"', '\n', '\r']) {
        format!("\"{}\"", text.replace('"', "\"\""))
    } else {
        text.to_owned()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn model_names_with_commas_are_quoted() {
        assert_eq!(csv_field("a,b\"c"), "\"a,b\"\"c\"");
        assert_eq!(csv_field("gen:icosphere:2"), "gen:icosphere:2");
    }
}

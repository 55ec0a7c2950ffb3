//! Observation 3 [LZT §6] tested by scale: the same surface in other units. The paper reports
//! that with floating point "the average number of wedges per unit edge length is
//! scale-dependent"; if a backend's wedges, eq.-(2) cases or distances change when a model is
//! only scaled, that backend depends on the units, which a geometric property cannot.

use super::tables::csv_field;
use super::Measurement;
use crate::scalar::Backend;
use serde::Serialize;

/// One run on a model scaled by `scale_base^scale_exponent`, compared with the run from the
/// same source in the same backend on the unscaled model (the reference).
///
/// Distances are compared in the reference's units (each scaled distance divided by the
/// scale): `distance_sum` is the sum over reached vertices, and
/// `distance_max_difference` is `max_v |d(v) / scale - d_ref(v)| / max_v d_ref(v)`, infinite if
/// the two runs reach different vertices.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct ScaleRow {
    /// The model's name (its file or `gen:` spec).
    pub model: String,
    /// The number type.
    pub backend: Backend,
    /// The source vertex (0-based index).
    pub source: u32,
    /// The base of the scale (10 or 2).
    pub scale_base: u32,
    /// The power of the base.
    pub scale_exponent: i32,
    /// The factor every coordinate was multiplied by.
    pub scale: f64,
    /// Number of edges.
    pub edges: usize,
    /// Mean of w(e) over all edges.
    pub wedges_mean: f64,
    /// Largest w(e).
    pub wedges_max: f64,
    /// Sum of w(e).
    pub wedges_total: usize,
    /// Edges whose w(e) differs from the reference's.
    pub edges_changed: usize,
    /// Eq. (2) with no solution in the shared range.
    pub eq2_none: u64,
    /// Eq. (2) with one solution.
    pub eq2_one: u64,
    /// Eq. (2) with two solutions.
    pub eq2_two: u64,
    /// Eq. (2) with infinitely many solutions.
    pub eq2_infinite: u64,
    /// Sum of the distances of the reached vertices, divided by the scale.
    pub distance_sum: f64,
    /// Largest distance difference from the reference, relative to the largest distance.
    pub distance_max_difference: f64,
    /// Propagation time in seconds.
    pub seconds: f64,
    /// Decisions the exact backend left uncertified (0 in the float backends).
    pub uncertified: u64,
}

impl ScaleRow {
    /// The CSV header, in field order.
    pub const CSV_HEADER: &'static str = "model,backend,source,scale_base,scale_exponent,scale,\
edges,wedges_mean,wedges_max,wedges_total,edges_changed,eq2_none,eq2_one,eq2_two,eq2_infinite,\
distance_sum,distance_max_difference,seconds,uncertified";

    /// The row of `scaled`, a run on `model` scaled by `base^exponent`, against `reference`,
    /// the run from the same source in the same backend on the unscaled model.
    ///
    /// # Example
    /// ```
    /// use exact_geodesics::experiments::{measure, scale_uniformly, ScaleRow};
    /// use exact_geodesics::{mesh::shapes, scalar::Backend, VertexId};
    /// let cube = shapes::cube();
    /// let reference = measure::<f64>(&cube, VertexId(0), |_| {})?;
    /// let scaled = measure::<f64>(&scale_uniformly(&cube, 1024.0)?, VertexId(0), |_| {})?;
    /// let row = ScaleRow::new("gen:cube", Backend::F64, 2, 10, &reference, &scaled);
    /// assert_eq!((row.edges_changed, row.distance_max_difference), (0, 0.0));
    /// # Ok::<(), exact_geodesics::experiments::ExperimentError>(())
    /// ```
    pub fn new(
        model: &str,
        backend: Backend,
        base: u32,
        exponent: i32,
        reference: &Measurement,
        scaled: &Measurement,
    ) -> Self {
        let scale = scale_factor(base, exponent);
        let in_reference_units = scaled.distances.iter().map(|d| d / scale);
        let largest = reference
            .distances
            .iter()
            .copied()
            .filter(|d| d.is_finite())
            .fold(0.0, f64::max);
        let difference = in_reference_units
            .clone()
            .zip(&reference.distances)
            .map(|(d, r)| match (d.is_finite(), r.is_finite()) {
                (true, true) => (d - r).abs(),
                (false, false) => 0.0,
                _ => f64::INFINITY,
            })
            .fold(0.0, f64::max);
        let eq2 = &scaled.eq2;
        ScaleRow {
            model: model.to_owned(),
            backend,
            source: scaled.counts.source.0,
            scale_base: base,
            scale_exponent: exponent,
            scale,
            edges: scaled.per_edge.len(),
            wedges_mean: scaled.counts.per_edge.mean,
            wedges_max: scaled.counts.per_edge.max,
            wedges_total: scaled.counts.total,
            edges_changed: scaled
                .per_edge
                .iter()
                .zip(&reference.per_edge)
                .filter(|(a, b)| a != b)
                .count(),
            eq2_none: eq2.none,
            eq2_one: eq2.one,
            eq2_two: eq2.two,
            eq2_infinite: eq2.infinite,
            distance_sum: in_reference_units.filter(|d| d.is_finite()).sum(),
            distance_max_difference: if largest > 0.0 {
                difference / largest
            } else {
                difference
            },
            seconds: scaled.counts.seconds,
            uncertified: scaled.uncertified,
        }
    }

    /// The row as one CSV record (no line end), fields as in [`Self::CSV_HEADER`].
    pub fn csv_record(&self) -> String {
        format!(
            "{},{},{},{},{},{:e},{},{},{},{},{},{},{},{},{},{},{:e},{},{}",
            csv_field(&self.model),
            self.backend.name(),
            self.source,
            self.scale_base,
            self.scale_exponent,
            self.scale,
            self.edges,
            self.wedges_mean,
            self.wedges_max,
            self.wedges_total,
            self.edges_changed,
            self.eq2_none,
            self.eq2_one,
            self.eq2_two,
            self.eq2_infinite,
            self.distance_sum,
            self.distance_max_difference,
            self.seconds,
            self.uncertified,
        )
    }
}

/// The factor `base^exponent` as `f64::powi` computes it: exact for powers of two and for
/// `10^0 ..= 10^22`, within an ulp or two of `10^exponent` otherwise. The factor by which a
/// scale series multiplies the model, and by which [`ScaleRow::new`] divides its distances.
///
/// # Example
/// ```
/// use exact_geodesics::experiments::scale_factor;
/// assert_eq!(scale_factor(10, 6), 1e6);
/// assert_eq!(scale_factor(2, -3), 0.125);
/// ```
pub fn scale_factor(base: u32, exponent: i32) -> f64 {
    f64::from(base).powi(exponent)
}

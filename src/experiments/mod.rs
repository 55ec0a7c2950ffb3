//! The experiments of [LZT §6]: Tables 1 and 2 as values, one row per (model, backend, source).
//!
//! - Every model is first normalized into the unit cube ([`normalize_to_unit_cube`]), as the
//!   paper does, so that edge lengths compare across models.
//! - Table 1: the number of final wedges w(e) on each edge, from one source vertex, regarded as a
//!   random variable over all edges ([`count_wedges`], [`WedgeCounts`]): mean, standard deviation,
//!   maximum, and the propagation time; uniformity as the paper judges it, the largest per-face
//!   minimal angle, with the rest of that distribution ([`min_angle_summary`]).
//! - Table 2: the edge length l(e) of the normalized model ([`ModelShape`]) and the wedges per
//!   unit length `mean w(e) / mean l(e)`.
//! - Observation 3, that the wedges per unit length grow as the edges shorten, tested two
//!   ways: by scale ([`scale_uniformly`], [`ScaleRow`]: the same surface in other units, where a
//!   geometric property cannot change) and by resolution ([`ResolutionRow`], [`fit_resolution`]:
//!   one surface meshed ever finer, with the exponent of `w/l ~ l^k` fitted by least squares
//!   with its 95 % confidence interval, [`LineFit`]).
//! - The paper does not say where its sources were: [`random_sources`] draws seeded vertices.
//!
//! Statistics are population moments ([`Summary`]). Nothing here prints; the command
//! `exact-geodesics experiment` writes the rows as CSV and JSON.
//!
//! # Example
//! ```
//! use exact_geodesics::experiments::{
//!     count_wedges_in, normalize_to_unit_cube, random_sources, ModelShape, Table1Row,
//! };
//! use exact_geodesics::{mesh::shapes, scalar::Backend};
//! let unit = normalize_to_unit_cube(&shapes::icosphere(1))?;
//! let shape = ModelShape::of(&unit);
//! for source in random_sources(&unit, 2, 1) {
//!     let counts = count_wedges_in(Backend::F64, &unit, source, |_| {})?;
//!     let row = Table1Row::new("icosphere:1", Backend::F64, &shape, &counts);
//!     assert!(row.wedges_mean >= 1.0);
//! }
//! # Ok::<(), exact_geodesics::experiments::ExperimentError>(())
//! ```

mod error;
mod fit;
mod normalize;
mod resolution;
mod scale;
mod sources;
mod summary;
mod tables;
mod uniformity;
mod wedges;

pub use error::ExperimentError;
pub use fit::{student_t_critical, LineFit, CONFIDENCE};
pub use normalize::{normalize_to_unit_cube, scale_uniformly};
pub use resolution::{fit_resolution, ResolutionFit, ResolutionPoint, ResolutionRow};
pub use scale::{scale_factor, ScaleRow};
pub use sources::random_sources;
pub use summary::Summary;
pub use tables::{ModelShape, Table1Row, Table2Row};
pub use uniformity::{min_angle_summary, min_angles_degrees};
pub use wedges::{
    count_wedges, count_wedges_in, measure, measure_in, share_holding_half, Measurement,
    WedgeCounts,
};

//! # exact-geodesics
//!
//! Exact geodesics (shortest paths along the surface) on triangle meshes by the MMP algorithm in
//! the wedge ("window") form of Surazhsky et al., generic over the number type.
//!
//! References, cited by key throughout the docs:
//! - \[LZT\] Liu, Zhang, Tang, *Some properties of exact geodesics on triangular mesh surfaces*.
//! - \[SSK+05\] Surazhsky, Surazhsky, Kirsanov, Gortler, Hoppe, *Fast exact and approximate
//!   geodesics on meshes*, SIGGRAPH 2005.
//! - \[MMP87\] Mitchell, Mount, Papadimitriou, *The discrete geodesic problem*, SIAM J. Comput. 1987.
//!
//! The same field in two backends: floating point, and exact reals whose every decision is
//! certified and whose distances can be printed with guaranteed digits.
//! ```
//! use exact_geodesics::scalar::Real;
//! use exact_geodesics::{mesh::shapes, propagate, PropagateOptions, SurfacePoint, VertexId};
//!
//! let cube = shapes::cube();
//! let source = [SurfacePoint::Vertex(VertexId(0))];
//! let options = PropagateOptions::default();
//! let float = propagate::<f64>(&cube, &source, &options)?;
//! let exact = propagate::<Real>(&cube, &source, &options)?;
//! assert!(exact.is_certified());
//! let corner = VertexId(6); // opposite v0: sqrt(5) across two faces
//! assert!((float.vertex_distance(corner) - 5f64.sqrt()).abs() < 1e-12);
//! let digits = exact.vertex_distance_exact(corner).and_then(|d| d.to_decimal(20));
//! assert_eq!(digits.as_deref(), Some("2.2360679774997896964"));
//! # Ok::<(), exact_geodesics::PointError>(())
//! ```
#![forbid(unsafe_code)]
#![deny(missing_docs, rustdoc::broken_intra_doc_links)]

pub mod benchmark_model;
pub mod degeneracy;
pub mod experiments;
pub mod matrix;
pub mod mesh;
pub mod mmp;
pub mod paper;
pub mod render;
pub mod scalar;
pub mod subdivision;

pub use mesh::{EdgeId, FaceId, MeshError, Side, SourceId, TriMesh, ValidationReport, VertexId};
pub use mmp::{
    geodesic_distances, propagate, propagate_shared, propagate_vertices,
    propagate_vertices_with_progress, propagate_with_progress, ExactPath, GeodesicField,
    GeodesicPath, PointError, PropagateOptions, PseudoSource, Stats, SurfacePoint, TraceError,
    VertexField, Wedge,
};
pub use scalar::Scalar;

/// The vector crate of mesh positions ([`TriMesh::positions`] are [`glam::DVec3`]), so that
/// callers can name its types without depending on the same version themselves.
pub use glam;

/// The README's code, compiled and run as doctests.
#[cfg(doctest)]
#[doc = include_str!("../README.md")]
pub struct ReadmeDoctests;

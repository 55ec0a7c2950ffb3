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
#![forbid(unsafe_code)]
#![deny(missing_docs, rustdoc::broken_intra_doc_links)]

pub mod benchmark_model;
pub mod degeneracy;
pub mod experiments;
pub mod mesh;
pub mod mmp;
pub mod paper;
pub mod render;
pub mod scalar;

pub use mesh::{EdgeId, FaceId, MeshError, TriMesh, ValidationReport, VertexId};
pub use mmp::{
    propagate, propagate_with_progress, GeodesicField, GeodesicPath, PointError, PropagateOptions,
    PseudoSource, Side, Stats, SurfacePoint, TraceError, Wedge,
};
pub use scalar::Scalar;

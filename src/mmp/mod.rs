//! The MMP engine in the wedge form of Surazhsky et al. \[SSK+05\], as described in [LZT §2]:
//! wedges are propagated across faces in continuous-Dijkstra order; where wedges meet on an edge
//! they are intersected by solving eq. (2) (Section 4); the final wedges on the edges induce the
//! subdivision from which distances are read and paths traced back (Section 2).

mod bounds;
mod coverage;
mod crease;
mod edge_wedges;
mod fan;
mod field;
mod flat_region;
mod front;
mod intersect;
mod paths;
mod planar;
mod propagate;
mod provenance;
mod query;
mod radix_queue;
mod region_runs;
mod rounded_gap;
mod sectors;
mod shadow;
mod source;
mod stats;
mod stop;
mod strips;
mod trace_back;
mod trace_loop;
mod unfold;
mod vertex_field;
mod wedge;
mod wedge_lists;

pub use coverage::{CoverageIssue, CoverageReport};
pub use field::GeodesicField;
pub use intersect::intersect;
pub use propagate::{
    propagate, propagate_shared, propagate_with_progress, Progress, PropagateOptions,
};
pub use source::{PointError, SurfacePoint};
pub use stats::{Eq2Counts, Eq2Decision, Stats};
pub use trace_back::{ExactPath, GeodesicPath, TraceError};
pub use vertex_field::{
    geodesic_distances, propagate_vertices, propagate_vertices_with_progress, VertexField,
};
pub use wedge::{PseudoSource, Wedge};

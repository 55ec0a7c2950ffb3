//! A corpus of degenerate meshes and the invariants a geodesic distance must keep on them, in
//! every backend: no silently wrong answer on degenerate input.
//!
//! - [`generate`](degenerate_case): seeded meshes of eleven [`DegenerateKind`]s (coincident
//!   vertices and zero-length edges, zero-area faces, exactly flat grids and fans, slivers,
//!   symmetric pyramids, scales from `2^-600` to `2^600`, mixed magnitudes, bowties, edges
//!   shared by more than two faces, several components and loose vertices);
//! - [`check_invariants`]: `d(a, a) = 0`, the straight-line and edge-path bounds (exact in the
//!   exact backend), reachability, symmetry, traced paths [LZT §2] and agreement with a
//!   reference backend, each broken invariant a [`Violation`];
//! - [`run_corpus`]: many cases in one [`Backend`], panics caught and counted, summarized in a
//!   serializable [`CorpusSummary`].
//!
//! Straight lines and edge paths are computed without overflow or underflow (scaled by powers
//! of two), so the checks themselves hold at every scale the corpus uses.

mod bumpy;
mod draw;
mod figures;
mod generate;
mod invariants;
mod measure;
mod run;
mod soup;

pub use generate::{degenerate_case, degenerate_mesh, DegenerateCase, DegenerateKind, MeshSize};
pub use invariants::{
    at_least, at_most, check_invariants, relatively_close, InvariantReport, Tolerances, Violation,
    ViolationKind,
};
pub use run::{
    run_case, run_case_of_size, run_corpus, Backend, CaseReport, CaseViolation, CorpusProgress,
    CorpusSummary, MeshKindTally,
};

//! Why a scene or a benchmark model cannot be built.

use crate::mesh::MeshError;
use thiserror::Error;

/// Why a scene is rejected or its benchmark model cannot be built.
///
/// Obstacles and their corners are numbered from 0 in the order of the scene.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum BenchmarkError {
    /// A coordinate is NaN or infinite.
    #[error("{what} has a non-finite coordinate")]
    NonFinite {
        /// The rectangle, p, q, or an obstacle corner.
        what: String,
    },
    /// The rectangle has no interior.
    #[error("the rectangle is empty: min {min:?}, max {max:?}")]
    EmptyRectangle {
        /// Its lower left corner.
        min: [f64; 2],
        /// Its upper right corner.
        max: [f64; 2],
    },
    /// An obstacle has fewer than three corners.
    #[error("obstacle {obstacle} has {count} corner(s); a polygon needs at least 3")]
    TooFewCorners {
        /// The obstacle.
        obstacle: usize,
        /// Its number of corners.
        count: usize,
    },
    /// A corner is collinear with its two neighbours, or repeats one of them.
    #[error(
        "obstacle {obstacle}: corner {corner} is collinear with its neighbours (or repeats one)"
    )]
    DegenerateCorner {
        /// The obstacle.
        obstacle: usize,
        /// The corner.
        corner: usize,
    },
    /// Two edges of one obstacle meet away from a shared corner.
    #[error("obstacle {obstacle} is not a simple polygon: its edges {first} and {second} meet")]
    SelfIntersecting {
        /// The obstacle.
        obstacle: usize,
        /// One edge (from corner `first` to the next).
        first: usize,
        /// The other edge.
        second: usize,
    },
    /// Two obstacles share a point.
    #[error("obstacles {first} and {second} overlap or touch; obstacles must be disjoint")]
    ObstaclesOverlap {
        /// One obstacle.
        first: usize,
        /// The other.
        second: usize,
    },
    /// An obstacle corner is not strictly inside the rectangle.
    #[error("obstacle {obstacle} is not strictly inside the rectangle")]
    ObstacleOutsideRectangle {
        /// The obstacle.
        obstacle: usize,
    },
    /// p or q is not strictly inside the rectangle.
    #[error("{point} is not strictly inside the rectangle")]
    PointOutsideRectangle {
        /// "p" or "q".
        point: &'static str,
    },
    /// p or q is inside an obstacle or on its boundary.
    #[error("{point} is inside obstacle {obstacle} or on its boundary")]
    PointInObstacle {
        /// "p" or "q".
        point: &'static str,
        /// The obstacle.
        obstacle: usize,
    },
    /// p and q are the same point.
    #[error("p and q coincide")]
    PointsCoincide,
    /// An option is out of its range.
    #[error("invalid {name}: {reason}")]
    InvalidOption {
        /// The option.
        name: &'static str,
        /// What is wrong with it.
        reason: String,
    },
    /// A scene file is not the JSON of a scene.
    #[error("scene JSON: {0}")]
    Json(String),
    /// The constrained Delaunay triangulation refused the input.
    #[error("triangulation: {0}")]
    Triangulation(String),
    /// Refinement used up its budget of additional vertices.
    #[error(
        "refinement stopped after {budget} additional vertices; raise the budget or refine less"
    )]
    RefinementIncomplete {
        /// The budget.
        budget: usize,
    },
    /// The lifted surface is not a mesh (a bug: it is built to be one).
    #[error(transparent)]
    Mesh(#[from] MeshError),
}

//! The face subdivision's tolerance policy: it samples the face in `f64` (rays from each image,
//! bisection along them), so it decides closeness with slack, and every slack it uses is one
//! constant here, relative to the face's size, as [`FloatTolerance`](crate::scalar::FloatTolerance)
//! is for the engine.

/// The face subdivision's tolerances and sampling budget, one constant per use.
pub struct SubdivisionTolerance;

impl SubdivisionTolerance {
    /// Points closer than this fraction of the face's longest edge are one point (an image at
    /// a corner, two images of one pseudo-source, a pseudo-source outside the face); sigmas
    /// that close make a bisector a line.
    pub const POINT: f64 = 1e-9;
    /// Of two images whose distances to a point differ by less than this fraction of
    /// [`POINT`](Self::POINT), the one with the smaller sigma owns it.
    pub const DISTANCE_TIE: f64 = 1e-3;
    /// Angular slack (radians) when asking whether a wedge's rays meet a point.
    pub const ANGLE: f64 = 1e-12;
    /// Slack, as a fraction of the face's doubled area, when asking whether an image lies in
    /// the face.
    pub const IN_FACE: f64 = 1e-12;
    /// A ray's first sample lies this fraction of its run into the face (its entry point is
    /// on a region's boundary).
    pub const FIRST_SAMPLE: f64 = 1e-6;
    /// Angles this close (radians) to the ends of an image's reach are left out: the limiting
    /// rays run along edges.
    pub const REACH_MARGIN: f64 = 1e-9;
    /// A boundary ray that is a tie along its whole length is traced this fraction of the
    /// angular step inside the region.
    pub const RAY_NUDGE: f64 = 1e-4;
    /// A ray whose cross product with an edge is below this is parallel to it.
    pub const PARALLEL: f64 = 1e-300;
    /// Distance, as a fraction of the face's size, from a region's boundary at which the
    /// regions on both sides are probed to name the bisector between them.
    pub const PROBE: f64 = 1e-6;
    /// Consecutive polygon points closer than this fraction of the face's size are one.
    pub const DEDUP: f64 = 1e-12;
    /// Polygons of smaller area (as a fraction of the squared face size) are dropped.
    pub const AREA: f64 = 1e-14;
    /// Rays per region.
    pub const RAYS: usize = 720;
    /// Bisection steps per boundary point.
    pub const BISECTIONS: usize = 50;
    /// Samples per ray.
    pub const SAMPLES: usize = 96;
}

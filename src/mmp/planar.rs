//! Points in an edge's frame [SSK+05 §3]: x runs along the edge from the frame's first end (see
//! `unfold.rs`), y is the signed distance from the edge's line; the unfolding carries them from frame to frame.

/// A point in an edge's frame.
#[derive(Clone, Debug, PartialEq)]
pub struct Planar<S> {
    /// Position along the edge, from the frame's first end.
    pub x: S,
    /// Signed distance from the edge's line.
    pub y: S,
}

//! Points in an edge's frame [SSK+05 §3]: x runs along the edge from the frame's first end (see
//! `unfold.rs`), y is the signed distance from the edge's line; the unfolding carries them from
//! frame to frame. Among them the apex of a face on the edge, which the unfolding lays out.

/// A point in an edge's frame.
#[derive(Clone, Debug, PartialEq)]
pub struct Planar<S> {
    /// Position along the edge, from the frame's first end.
    pub x: S,
    /// Signed distance from the edge's line.
    pub y: S,
}

/// The apex of a face in the frame of one of its edges. Both offsets along the edge are
/// measured from their own end, and the height from the end nearer the apex: on a sliver
/// whose far edge is a millionth of the edge at hand, `length - x` would lose the far edge's
/// direction to cancellation, and rays unfolded across it would turn by as much, times their
/// length.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Apex<S> {
    /// Position along the edge, from the frame's first end.
    pub x: S,
    /// Position along the edge, from the frame's second end backwards (`length - x`).
    pub far_x: S,
    /// Distance from the edge's line, `h >= 0`.
    pub h: S,
}

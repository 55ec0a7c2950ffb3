//! Upper bounds of the vertices' distances shared between the propagations of one run that
//! go on at once in different sectors of a source's directions (`sectors.rs`): each publishes
//! every distance it gives a vertex, the length of a path there, and gives up wedges and
//! pseudo-sources that such a path beats throughout [SSK+05 §4.2].

use crate::mesh::VertexId;
use std::sync::atomic::{AtomicU64, AtomicUsize, Ordering};

/// The margin, relative to the distance and the mesh's extent, by which a published distance
/// is raised before it may beat anything: far above the rounding of a float backend's
/// distances (about 1e-16 of the coordinates per face crossed), so that the path it stands for
/// is shorter than what it beats, never within rounding of it.
const MARGIN: f64 = 1.0 / (1u64 << 36) as f64;

/// The shortest distance of each vertex published so far, as the bits of a non-negative
/// `f64` (which order as the numbers do); `+inf` where none is.
pub(crate) struct SharedBounds {
    bits: Vec<AtomicU64>,
    /// Vertices with a distance published.
    reached: AtomicUsize,
    /// The largest coordinate magnitude, in the units of the distances.
    extent: f64,
}

impl SharedBounds {
    /// No vertex of `vertex_count` reached, on a mesh whose largest coordinate magnitude is
    /// `extent`.
    pub(crate) fn new(vertex_count: usize, extent: f64) -> Self {
        SharedBounds {
            bits: (0..vertex_count)
                .map(|_| AtomicU64::new(f64::INFINITY.to_bits()))
                .collect(),
            reached: AtomicUsize::new(0),
            extent,
        }
    }

    /// Publishes `d` (the `f64` value of the length of a path to `v`).
    pub(crate) fn lower(&self, v: VertexId, d: f64) {
        if d >= 0.0 {
            let before = self.bits[v.index()].fetch_min(d.to_bits(), Ordering::Relaxed);
            if before == f64::INFINITY.to_bits() {
                self.reached.fetch_add(1, Ordering::Relaxed);
            }
        }
    }

    /// Vertices with a distance published, by either engine.
    pub(crate) fn reached(&self) -> usize {
        self.reached.load(Ordering::Relaxed)
    }

    /// A length no shorter than some path to `v` found so far, by a margin above rounding
    /// ([`MARGIN`]); `None` where none is known.
    pub(crate) fn beyond(&self, v: VertexId) -> Option<f64> {
        let d = f64::from_bits(self.bits[v.index()].load(Ordering::Relaxed));
        d.is_finite().then_some(d + (d + self.extent) * MARGIN)
    }
}

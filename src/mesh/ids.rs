//! Typed indices for mesh elements (and for the sources placed on them).
//!
//! Indices are `u32` newtypes (as spade's fixed handles are), so a vertex index can never be
//! passed where a face index is expected. All indices are 0-based and follow the order of the
//! input file.

use std::fmt;

macro_rules! id_type {
    ($(#[$doc:meta])* $name:ident, $prefix:literal) => {
        $(#[$doc])*
        #[derive(Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash, Debug, serde::Serialize)]
        pub struct $name(pub u32);

        impl $name {
            /// The index as a `usize`, for indexing slices.
            #[inline]
            pub fn index(self) -> usize {
                self.0 as usize
            }
        }

        impl fmt::Display for $name {
            fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
                write!(f, concat!($prefix, "{}"), self.0)
            }
        }
    };
}

id_type!(
    /// A vertex of a [`TriMesh`](crate::TriMesh), in file order.
    VertexId,
    "v"
);
id_type!(
    /// An undirected edge of a [`TriMesh`](crate::TriMesh).
    EdgeId,
    "e"
);
id_type!(
    /// A triangle of a [`TriMesh`](crate::TriMesh), in file order.
    FaceId,
    "f"
);
id_type!(
    /// A source of a propagation: its place in the list of sources given to it.
    SourceId,
    "s"
);

/// A side of an edge: the place of one of its faces. A wedge's tau (Definition 1 [LZT §2]) is
/// the side its pseudo-source lies on, the side of the face the wedge came through, so that it
/// goes on into the face (or, on an edge shared by more than two faces, the faces) on the
/// other sides.
///
/// Sides are numbered as [`TriMesh::wing`](crate::TriMesh::wing) numbers them: `FIRST` and
/// `SECOND` are the edge's [`faces`](crate::mesh::Edge::faces)`[0]` and `[1]`, and an edge shared
/// by more than two faces has a side per face. A wedge lying along its edge (pseudo-source on
/// the edge's line) is on the `FIRST` side by convention.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, serde::Serialize)]
pub struct Side(u32);

impl Side {
    /// The side of the edge's first face.
    pub const FIRST: Side = Side(0);
    /// The side of the edge's second face.
    pub const SECOND: Side = Side(1);

    /// The side's number: 0 for `FIRST`, 1 for `SECOND`, and so on.
    #[inline]
    pub fn index(self) -> usize {
        self.0 as usize
    }

    /// The side with the given number.
    #[inline]
    pub fn from_index(i: usize) -> Side {
        Side(i as u32)
    }
}

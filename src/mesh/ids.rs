//! Typed indices for mesh elements.
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

//! How a distance field holds its mesh: borrowed for one-off use, or shared so that the field
//! can be stored beside the mesh (in a struct, a cache, another thread) and queried for as long
//! as it lives.

use super::TriMesh;
use std::ops::Deref;
use std::sync::Arc;

/// A mesh, borrowed or shared ([`propagate_shared`](crate::propagate_shared) makes fields
/// that share theirs).
#[derive(Clone, Debug)]
pub enum MeshHandle<'m> {
    /// Borrowed for the lifetime `'m`.
    Borrowed(&'m TriMesh),
    /// Shared: a field holding it has no lifetime of its own.
    Shared(Arc<TriMesh>),
}

impl Deref for MeshHandle<'_> {
    type Target = TriMesh;

    #[inline]
    fn deref(&self) -> &TriMesh {
        match self {
            MeshHandle::Borrowed(mesh) => mesh,
            MeshHandle::Shared(mesh) => mesh,
        }
    }
}

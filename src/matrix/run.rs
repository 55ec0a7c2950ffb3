//! The sources of a matrix propagated in parallel (rayon), rows streamed to the caller's sink.

use super::{validate, MatrixError, MatrixOptions, MatrixRow, MatrixSummary};
use crate::mesh::{TriMesh, VertexId};
use crate::mmp::{propagate_vertices, PropagateOptions, SurfacePoint};
use crate::scalar::Scalar;
use rayon::prelude::*;
use std::sync::mpsc;

/// The distance matrix from `sources` to `targets` on the backend `S`: for each `i`, the
/// distances from `sources[i]` to every `targets[j]`, handed to `sink` as a [`MatrixRow`] as
/// soon as it is done (in completion order; `row.index` says which it is). Each row is one
/// propagation from its source, stopped once every target is final (or at
/// [`MatrixOptions::max_distance`]), so its distances are bit for bit those of a full
/// single-source run. At most [`MatrixOptions::threads`] propagations run at once, and as many
/// finished rows wait for the sink.
///
/// # Errors
/// [`MatrixError`] if there is no source or no target, a source or target is not one of the
/// mesh, the threads cannot start, or the sink fails (the sink's error; the propagations still
/// running finish, no new one starts).
pub fn distance_matrix<S: Scalar, E>(
    mesh: &TriMesh,
    sources: &[SurfacePoint],
    targets: &[VertexId],
    options: &MatrixOptions,
    mut sink: impl FnMut(MatrixRow) -> Result<(), E>,
) -> Result<MatrixSummary, MatrixError<E>> {
    validate(mesh, sources, targets)?;
    let threads = match options.threads {
        Some(0) => return Err(MatrixError::NoThreads),
        Some(n) => n,
        None => rayon::current_num_threads(),
    };
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .build()
        .map_err(|e| MatrixError::Threads(e.to_string()))?;
    // A vertex that no face uses is never reached: waiting for it would run every
    // propagation to its end.
    let stops = targets
        .iter()
        .filter(|&&v| !mesh.vertex_faces(v).is_empty())
        .map(|&v| SurfacePoint::Vertex(v));
    let mut propagate_options = PropagateOptions::default().with_stop_points(stops);
    propagate_options.max_distance = options.max_distance;
    propagate_options.precision_cap = options.precision_cap;
    let row = |index: usize| -> MatrixRow {
        let source = std::slice::from_ref(&sources[index]);
        let field = propagate_vertices::<S>(mesh, source, &propagate_options)
            .expect("the sources and targets were validated");
        MatrixRow {
            index,
            distances: targets.iter().map(|&v| field.vertex_distance(v)).collect(),
            uncertified: field.stats().backend.uncertified,
            wedges_propagated: field.stats().wedges_propagated,
        }
    };
    let mut summary = MatrixSummary::default();
    let mut refused = None;
    let (sender, receiver) = mpsc::sync_channel::<MatrixRow>(threads);
    pool.in_place_scope(|scope| {
        scope.spawn(|_| {
            // A failed send means the sink has given up: stop taking new sources.
            let _ = (0..sources.len())
                .into_par_iter()
                .with_max_len(1)
                .try_for_each_with(sender, |sender, index| sender.send(row(index)));
        });
        for row in receiver.iter() {
            summary.rows += 1;
            summary.uncertified_rows += usize::from(row.uncertified > 0);
            summary.wedges_propagated += row.wedges_propagated;
            if let Err(e) = sink(row) {
                refused = Some(e);
                break;
            }
        }
        // Dropping the receiver here (not at the scope's end) lets the workers see it.
        drop(receiver);
    });
    match refused {
        Some(e) => Err(MatrixError::Sink(e)),
        None => Ok(summary),
    }
}

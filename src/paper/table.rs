//! The final wedges of an edge as the paper prints them in Example 4 [LZT §3]: 7-tuples
//! `(b0, b1, d0, d1, tau, s, sigma)`, with the edge read from a chosen end.

use crate::mesh::{EdgeId, FaceId, VertexId};
use crate::mmp::{GeodesicField, PseudoSource, SurfacePoint, Wedge};
use crate::scalar::Scalar;
use serde::Serialize;
use std::fmt;

/// One wedge in the paper's 7-tuple form.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct WedgeRow {
    /// Start of the range, from the edge's chosen first end.
    pub b0: f64,
    /// End of the range.
    pub b1: f64,
    /// Distance from the pseudo-source to `b0`.
    pub d0: f64,
    /// Distance from the pseudo-source to `b1`.
    pub d1: f64,
    /// Relative to a face: `true` if the wedge comes from outside it, `false` from inside or
    /// along the edge [LZT Example 4]. Without a face: the face on the pseudo-source's side
    /// (`f7`), or `line` for a wedge along the edge.
    pub tau: String,
    /// The pseudo-source: `v7` for a vertex (or a source at a vertex), `source2` otherwise.
    pub s: String,
    /// Geodesic distance from the pseudo-source to the source.
    pub sigma: f64,
}

impl fmt::Display for WedgeRow {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "({:.3}, {:.3}, {:.3}, {:.3}, {}, {}, {:.3})",
            self.b0, self.b1, self.d0, self.d1, self.tau, self.s, self.sigma
        )
    }
}

/// The final wedges of one edge, read from vertex `from` to vertex `to`.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct EdgeRows {
    /// The end the parameters are measured from.
    pub from: u32,
    /// The other end.
    pub to: u32,
    /// The wedges, sorted from `from`.
    pub wedges: Vec<WedgeRow>,
}

impl fmt::Display for EdgeRows {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        writeln!(
            f,
            "There are {} wedges at edge (v{}, v{}):",
            self.wedges.len(),
            self.from,
            self.to
        )?;
        self.wedges.iter().try_for_each(|r| writeln!(f, "{r}"))
    }
}

/// The name the paper gives a wedge's pseudo-source: `v7`, or `source2` for a source that is
/// not a vertex.
pub fn pseudo_source_name<S: Scalar>(field: &GeodesicField<'_, S>, w: &Wedge<S>) -> String {
    match w.pseudo_source {
        PseudoSource::Vertex(v) => format!("v{}", v.0),
        PseudoSource::Source(k) => match field.sources()[k.index()] {
            SurfacePoint::Vertex(v) => format!("v{}", v.0),
            _ => format!("source{k}"),
        },
    }
}

/// The final wedges of edge `e` read from its end `from`, tau relative to `face` when given.
pub fn edge_rows<S: Scalar>(
    field: &GeodesicField<'_, S>,
    from: VertexId,
    e: EdgeId,
    face: Option<FaceId>,
) -> EdgeRows {
    let edge = field.mesh().edge(e);
    let length = field.edge_length(e).to_f64();
    let reversed = edge.vertices[0] != from;
    let mut wedges: Vec<WedgeRow> = field
        .wedges(e)
        .iter()
        .map(|w| {
            let on_line = w.source_y.to_f64() == 0.0;
            let source_face = field.mesh().wing(e, w.tau).map(|wing| wing.face);
            let tau = match face {
                Some(f) => (!on_line && source_face != Some(f)).to_string(),
                None if on_line => "line".to_string(),
                None => source_face.map_or("none".into(), |f| format!("f{}", f.0)),
            };
            let (b0, b1, d0, d1) = (
                w.b0.to_f64(),
                w.b1.to_f64(),
                w.d0().to_f64(),
                w.d1().to_f64(),
            );
            let (b0, b1, d0, d1) = if reversed {
                (length - b1, length - b0, d1, d0)
            } else {
                (b0, b1, d0, d1)
            };
            WedgeRow {
                b0,
                b1,
                d0,
                d1,
                tau,
                s: pseudo_source_name(field, w),
                sigma: w.sigma.to_f64(),
            }
        })
        .collect();
    if reversed {
        wedges.reverse();
    }
    EdgeRows {
        from: from.0,
        to: edge.other(from).map_or(from.0, |v| v.0),
        wedges,
    }
}

/// The final wedges on the three edges of a face, each edge read in the face's vertex order
/// (`(c0, c1)`, `(c1, c2)`, `(c2, c0)`), tau relative to the face [LZT Example 4].
pub fn face_rows<S: Scalar>(field: &GeodesicField<'_, S>, face: FaceId) -> Vec<EdgeRows> {
    let mesh = field.mesh();
    let corners = mesh.face(face);
    mesh.face_edges(face)
        .into_iter()
        .enumerate()
        .map(|(i, e)| edge_rows(field, corners[i], e, Some(face)))
        .collect()
}

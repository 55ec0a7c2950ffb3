//! The command line's point forms: `v:I`, `e:A,B,T`, `f:F,U,V,W` (0-based indices).

use exact_geodesics::{FaceId, SurfacePoint, TriMesh, VertexId};

/// Parses a point spec against a mesh; the error says what was expected.
pub fn parse_point(mesh: &TriMesh, spec: &str) -> Result<SurfacePoint, String> {
    let bad = |why: &str| format!("bad point '{spec}': {why} (expected v:I, e:A,B,T or f:F,U,V,W)");
    let (kind, rest) = spec.split_once(':').ok_or_else(|| bad("no ':'"))?;
    let fields: Vec<&str> = rest.split(',').map(str::trim).collect();
    let int = |s: &str| {
        s.parse::<u32>()
            .map_err(|_| bad(&format!("'{s}' is not an index")))
    };
    let real = |s: &str| {
        s.parse::<f64>()
            .ok()
            .filter(|x| x.is_finite())
            .ok_or_else(|| bad(&format!("'{s}' is not a finite number")))
    };
    let point = match (kind, fields.as_slice()) {
        ("v", [i]) => SurfacePoint::Vertex(VertexId(int(i)?)),
        ("e", [a, b, t]) => SurfacePoint::on_edge(mesh, int(a)?, int(b)?, real(t)?)
            .map_err(|e| bad(&e.to_string()))?,
        ("f", [f, u, v, w]) => SurfacePoint::Face {
            face: FaceId(int(f)?),
            bary: [real(u)?, real(v)?, real(w)?],
        },
        _ => return Err(bad("wrong kind or number of fields")),
    };
    point.validated(mesh).map_err(|e| bad(&e.to_string()))
}

/// Parses an edge given by its end vertices, `A,B`.
pub fn parse_vertex_pair(spec: &str) -> Result<(u32, u32), String> {
    let bad = || format!("bad edge '{spec}': expected A,B (two vertex indices)");
    let (a, b) = spec.split_once(',').ok_or_else(bad)?;
    Ok((
        a.trim().parse().map_err(|_| bad())?,
        b.trim().parse().map_err(|_| bad())?,
    ))
}

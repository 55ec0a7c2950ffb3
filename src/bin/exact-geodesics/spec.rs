//! The command line's point forms: `v:I`, `e:A,B,T`, `f:F,U,V,W` (0-based indices).

use exact_geodesics::{FaceId, SurfacePoint, TriMesh, VertexId};

/// How far from 1 (relative) the barycentric coordinates of `f:F,U,V,W` may sum. The library
/// takes barycentric coordinates as homogeneous and divides them by their sum; numbers typed on
/// the command line that do not sum to 1 are more likely a typo (a wrong digit, a coordinate
/// left out) than a choice, so the command line refuses them instead of moving the point.
const BARYCENTRIC_SUM_TOLERANCE: f64 = 1e-9;

/// Parses a point spec against a mesh (`mesh_name` is what errors call it); the error says
/// what was expected or why the point is not a point of the mesh.
pub fn parse_point(mesh: &TriMesh, mesh_name: &str, spec: &str) -> Result<SurfacePoint, String> {
    let bad = |why: &str| format!("bad point '{spec}': {why} (expected v:I, e:A,B,T or f:F,U,V,W)");
    let invalid = |why: &str| format!("bad point '{spec}' on {mesh_name}: {why}");
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
            .map_err(|e| invalid(&e.to_string()))?,
        ("f", [f, u, v, w]) => SurfacePoint::Face {
            face: FaceId(int(f)?),
            bary: [real(u)?, real(v)?, real(w)?],
        },
        _ => return Err(bad("wrong kind or number of fields")),
    };
    let valid = point.validated(mesh).map_err(|e| invalid(&e.to_string()))?;
    if let SurfacePoint::Face { bary, .. } = point {
        let sum: f64 = bary.iter().sum();
        if (sum - 1.0).abs() > BARYCENTRIC_SUM_TOLERANCE {
            return Err(invalid(&format!(
                "barycentric coordinates must sum to 1 (within {BARYCENTRIC_SUM_TOLERANCE:e}), these sum to {sum}"
            )));
        }
    }
    Ok(valid)
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

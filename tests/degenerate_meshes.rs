//! Hand-made degenerate meshes: the engine returns documented results, never panics or hangs.

mod common;

use exact_geodesics::glam::DVec3;
use exact_geodesics::mesh::shapes;
use exact_geodesics::{propagate, PropagateOptions, SurfacePoint, TraceError, TriMesh, VertexId};

fn from_vertex(mesh: &TriMesh, v: u32) -> Vec<f64> {
    common::distances::<f64>(mesh, v)
}

#[test]
fn zero_area_face_is_reported_and_crossed() {
    // A unit square with vertex 4 on its bottom side, and a collinear face (0, 1, 4) folded onto
    // that side: the mesh stays manifold, the face has area zero.
    let positions = vec![
        [0.0, 0.0, 0.0],
        [1.0, 0.0, 0.0],
        [1.0, 1.0, 0.0],
        [0.0, 1.0, 0.0],
        [0.5, 0.0, 0.0],
    ];
    let faces = vec![[0, 4, 3], [4, 1, 2], [4, 2, 3], [0, 1, 4]];
    let mesh = TriMesh::new(positions, faces).expect("usable mesh");
    assert_eq!(mesh.validation().zero_area_faces.len(), 1);
    for source in [0, 4, 2] {
        let d = from_vertex(&mesh, source);
        let s = mesh.position(VertexId(source));
        for (v, got) in d.iter().enumerate() {
            let p = mesh.position(VertexId(v as u32));
            let want = ((p[0] - s[0]).powi(2) + (p[1] - s[1]).powi(2)).sqrt();
            assert!(
                (got - want).abs() < 1e-12,
                "from v{source} to v{v}: {got} vs {want}"
            );
        }
    }
}

#[test]
fn disconnected_parts_and_loose_vertices_are_unreachable() {
    let mut positions = shapes::tetrahedron().positions().to_vec();
    let mut faces = shapes::tetrahedron().faces().to_vec();
    let shift = positions.len() as u32;
    positions.extend(
        shapes::tetrahedron()
            .positions()
            .iter()
            .map(|&p| p + 5.0 * DVec3::X),
    );
    faces.extend(
        shapes::tetrahedron()
            .faces()
            .iter()
            .map(|f| f.map(|i| i + shift)),
    );
    positions.push(DVec3::splat(9.0));
    let mesh = TriMesh::new(positions, faces).expect("usable mesh");
    assert_eq!(mesh.validation().components, 2);
    assert_eq!(mesh.validation().unreferenced_vertices, vec![VertexId(8)]);
    let field = propagate::<f64>(
        &mesh,
        &[SurfacePoint::Vertex(VertexId(0))],
        &PropagateOptions::default(),
    )
    .expect("valid source");
    for v in 4..9 {
        assert_eq!(field.vertex_distance(VertexId(v)), f64::INFINITY);
        assert_eq!(field.nearest_source(VertexId(v)), None);
    }
    assert_eq!(
        field.trace_back(&SurfacePoint::Vertex(VertexId(5))),
        Err(TraceError::Unreachable)
    );
}

#[test]
fn bowtie_vertex_joins_its_fans() {
    let mesh = shapes::bowtie();
    assert_eq!(mesh.validation().non_manifold_vertices, vec![VertexId(0)]);
    let d = from_vertex(&mesh, 1);
    assert!(
        (d[3] - 2.0).abs() < 1e-12,
        "through the bowtie vertex: {d:?}"
    );
}

#[test]
fn sources_on_boundaries_and_corners() {
    let mesh = shapes::grid(3, 3, 1.0, 1.0);
    for source in [
        SurfacePoint::Vertex(VertexId(0)),
        SurfacePoint::on_edge(&mesh, 0, 1, 0.5).expect("boundary edge"),
        SurfacePoint::on_edge(&mesh, 0, 1, 1.0).expect("edge end"),
        SurfacePoint::Face {
            face: exact_geodesics::FaceId(0),
            bary: [0.5, 0.5, 0.0],
        },
    ] {
        let field =
            propagate::<f64>(&mesh, &[source], &PropagateOptions::default()).expect("valid");
        let s = source.position(&mesh);
        for v in 0..mesh.vertex_count() {
            let p = mesh.position(VertexId(v as u32));
            let want = ((p[0] - s[0]).powi(2) + (p[1] - s[1]).powi(2)).sqrt();
            let got = field.vertex_distance(VertexId(v as u32));
            assert!(
                (got - want).abs() < 1e-12,
                "{source:?} to v{v}: {got} vs {want}"
            );
        }
    }
}

#[test]
fn coincident_sources_and_sliver_triangles() {
    // Two sources at the same place, and a mesh of needle triangles.
    let n = 40;
    let mut positions = vec![[0.0, 0.0, 0.0]];
    for i in 0..=n {
        positions.push([1.0, i as f64 * 1e-4, 0.0]);
    }
    let faces: Vec<[u32; 3]> = (1..=n as u32).map(|i| [0, i, i + 1]).collect();
    let mesh = TriMesh::new(positions, faces).expect("usable mesh");
    let v0 = SurfacePoint::Vertex(VertexId(0));
    let field = propagate::<f64>(&mesh, &[v0, v0], &PropagateOptions::default()).expect("valid");
    for v in 1..=n + 1 {
        let p = mesh.position(VertexId(v as u32));
        let want = (p[0] * p[0] + p[1] * p[1]).sqrt();
        assert!((field.vertex_distance(VertexId(v as u32)) - want).abs() < 1e-12);
    }
}

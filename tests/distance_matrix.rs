//! Distance matrices: every row equals a single-source run from its vertex, in every backend;
//! symmetrization; radius-limited rows; errors.

use exact_geodesics::glam::DVec3;
use exact_geodesics::matrix::{
    distance_matrix, DenseMatrix, MatrixError, MatrixOptions, MatrixRow, ShapeError, SparseMatrix,
};
use exact_geodesics::mesh::shapes::{self, SplitMix64};
use exact_geodesics::scalar::{Adaptive, Real};
use exact_geodesics::{
    geodesic_distances, EdgeId, FaceId, PointError, PropagateOptions, Scalar, SurfacePoint,
    TriMesh, VertexId,
};
use std::convert::Infallible;

/// An icosphere with every vertex moved radially by up to 15 %: no symmetry to hide errors.
fn bumpy_sphere(seed: u64) -> TriMesh {
    let sphere = shapes::icosphere(2);
    let mut rng = SplitMix64::new(seed);
    let positions = sphere
        .positions()
        .iter()
        .map(|&p| p * DVec3::from_array([0; 3].map(|_| 0.85 + 0.3 * rng.next_f64())))
        .collect::<Vec<_>>();
    assert!(positions.iter().all(|p| p.length() > 0.5));
    TriMesh::new(positions, sphere.faces().to_vec()).unwrap()
}

/// `count` distinct vertices drawn with `seed`.
fn random_vertices(mesh: &TriMesh, count: usize, seed: u64) -> Vec<VertexId> {
    let mut rng = SplitMix64::new(seed);
    let mut chosen = Vec::new();
    while chosen.len() < count {
        let v = VertexId((rng.next_u64() % mesh.vertex_count() as u64) as u32);
        if !chosen.contains(&v) {
            chosen.push(v);
        }
    }
    chosen
}

fn points(vertices: &[VertexId]) -> Vec<SurfacePoint> {
    vertices.iter().map(|&v| SurfacePoint::Vertex(v)).collect()
}

fn dense<S: Scalar>(mesh: &TriMesh, vertices: &[VertexId], options: &MatrixOptions) -> DenseMatrix {
    let n = vertices.len();
    let mut matrix = DenseMatrix::new(n, n);
    let sources = points(vertices);
    let summary =
        distance_matrix::<S, _>(mesh, &sources, vertices, options, |row| matrix.insert(&row))
            .expect("a valid selection");
    assert_eq!(summary.rows, vertices.len());
    matrix
}

/// Every row against a full single-source run from its vertex, bit for bit.
fn rows_equal_single_source_runs<S: Scalar>(mesh: &TriMesh, vertices: &[VertexId]) {
    let matrix = dense::<S>(mesh, vertices, &MatrixOptions::default().with_threads(2));
    for (i, &s) in vertices.iter().enumerate() {
        let single = geodesic_distances::<S>(
            mesh,
            &[SurfacePoint::Vertex(s)],
            &PropagateOptions::default(),
        )
        .unwrap();
        for (j, &t) in vertices.iter().enumerate() {
            assert_eq!(
                matrix.get(i, j).to_bits(),
                single[t.index()].to_bits(),
                "d(v{}, v{})",
                s.0,
                t.0
            );
        }
    }
}

#[test]
fn f64_matrix_of_30_random_vertices_equals_single_source_runs() {
    let mesh = bumpy_sphere(3);
    rows_equal_single_source_runs::<f64>(&mesh, &random_vertices(&mesh, 30, 7));
}

#[test]
fn adaptive_matrix_equals_single_source_runs() {
    let mesh = bumpy_sphere(4);
    rows_equal_single_source_runs::<Adaptive>(&mesh, &random_vertices(&mesh, 12, 8));
}

#[test]
fn exact_matrix_equals_single_source_runs() {
    let cube = shapes::cube();
    rows_equal_single_source_runs::<Real>(&cube, &[0, 6, 3, 5].map(VertexId));
}

#[test]
fn stopping_at_the_selection_saves_events() {
    let mesh = bumpy_sphere(5);
    // Vertex 0 and its neighbours: their distances are final long before the propagation
    // covers the sphere.
    let near: Vec<VertexId> = mesh
        .vertex_edges(VertexId(0))
        .iter()
        .copied()
        .flat_map(|e| mesh.edge(e).vertices)
        .fold(Vec::new(), |mut seen, v| {
            if !seen.contains(&v) {
                seen.push(v);
            }
            seen
        });
    let mut events = 0;
    let options = MatrixOptions::default();
    distance_matrix::<f64, Infallible>(&mesh, &points(&near), &near, &options, |row| {
        events += row.wedges_propagated;
        Ok(())
    })
    .unwrap();
    let full: u64 = near
        .iter()
        .map(|&v| {
            exact_geodesics::propagate::<f64>(
                &mesh,
                &[SurfacePoint::Vertex(v)],
                &PropagateOptions::default(),
            )
            .unwrap()
            .stats()
            .wedges_propagated
        })
        .sum();
    assert!(2 * events < full, "{events} events against {full}");
}

#[test]
fn symmetrize_min_gives_the_smaller_of_each_pair() {
    let mesh = bumpy_sphere(6);
    let vertices = random_vertices(&mesh, 20, 9);
    let one_way = dense::<f64>(&mesh, &vertices, &MatrixOptions::default());
    let mut symmetric = one_way.clone();
    symmetric.symmetrize_min().unwrap();
    for i in 0..vertices.len() {
        assert_eq!(symmetric.get(i, i), 0.0);
        for j in 0..vertices.len() {
            let (a, b) = (one_way.get(i, j), one_way.get(j, i));
            assert!(
                (a - b).abs() <= 1e-12 * a.max(1.0),
                "d(i, j) and d(j, i) agree"
            );
            assert_eq!(symmetric.get(i, j), a.min(b));
            assert_eq!(symmetric.get(i, j), symmetric.get(j, i));
        }
    }
}

#[test]
fn radius_limited_rows_are_the_dense_entries_within_the_radius() {
    let mesh = bumpy_sphere(7);
    let vertices = random_vertices(&mesh, 25, 10);
    let full = dense::<f64>(&mesh, &vertices, &MatrixOptions::default());
    let radius = 0.9;
    let mut sparse = SparseMatrix::new();
    let options = MatrixOptions::default()
        .with_max_distance(radius)
        .with_threads(2);
    distance_matrix::<f64, Infallible>(&mesh, &points(&vertices), &vertices, &options, |row| {
        sparse.insert(&row);
        Ok(())
    })
    .unwrap();
    sparse.sort();
    let within: Vec<(u32, u32, f64)> = (0..vertices.len())
        .flat_map(|i| (0..vertices.len()).map(move |j| (i, j)))
        .filter(|&(i, j)| full.get(i, j) <= radius)
        .map(|(i, j)| (i as u32, j as u32, full.get(i, j)))
        .collect();
    assert!(!within.is_empty() && within.len() < vertices.len() * vertices.len());
    assert_eq!(sparse.entries(), within.as_slice());
    sparse.symmetrize_min();
    for &(i, j, d) in sparse.entries() {
        assert!(sparse.entries().contains(&(j, i, d)));
    }
}

#[test]
fn a_vertex_no_face_uses_is_at_infinity() {
    let mut positions = shapes::cube().positions().to_vec();
    positions.push(DVec3::splat(5.0));
    let mesh = TriMesh::new(positions, shapes::cube().faces().to_vec()).unwrap();
    let vertices = [0, 8, 6].map(VertexId);
    let matrix = dense::<f64>(&mesh, &vertices, &MatrixOptions::default());
    assert_eq!(matrix.get(1, 1), 0.0);
    for k in [0, 2] {
        assert_eq!(matrix.get(1, k), f64::INFINITY);
        assert_eq!(matrix.get(k, 1), f64::INFINITY);
    }
    assert!((matrix.get(0, 2) - 5f64.sqrt()).abs() < 1e-12);
}

#[test]
fn bad_selections_are_errors() {
    let cube = shapes::cube();
    let ignore = |_: MatrixRow| Ok::<(), Infallible>(());
    let options = MatrixOptions::default();
    let one = [VertexId(1)];
    assert!(matches!(
        distance_matrix::<f64, _>(&cube, &[], &one, &options, ignore),
        Err(MatrixError::Empty)
    ));
    assert!(matches!(
        distance_matrix::<f64, _>(&cube, &points(&one), &[], &options, ignore),
        Err(MatrixError::Empty)
    ));
    let beyond = [VertexId(1), VertexId(8)];
    assert!(matches!(
        distance_matrix::<f64, _>(&cube, &points(&one), &beyond, &options, ignore),
        Err(MatrixError::Target {
            index: 1,
            error: PointError::VertexOutOfRange { vertex: 8, .. }
        })
    ));
    let edge = SurfacePoint::Edge {
        edge: EdgeId(0),
        t: 1.5,
    };
    assert!(matches!(
        distance_matrix::<f64, _>(&cube, &[edge], &one, &options, ignore),
        Err(MatrixError::Source {
            index: 0,
            error: PointError::EdgeParameter { .. }
        })
    ));
    let none = MatrixOptions::default().with_threads(0);
    assert!(matches!(
        distance_matrix::<f64, _>(&cube, &points(&one), &one, &none, ignore),
        Err(MatrixError::NoThreads)
    ));
}

#[test]
fn a_failing_sink_stops_the_run() {
    let mesh = bumpy_sphere(8);
    let vertices = random_vertices(&mesh, 40, 11);
    let mut seen = 0;
    let options = MatrixOptions::default().with_threads(2);
    let sources = points(&vertices);
    let result = distance_matrix::<f64, _>(&mesh, &sources, &vertices, &options, |row| {
        seen += 1;
        if seen == 3 {
            Err(format!("disk full at row {}", row.index))
        } else {
            Ok(())
        }
    });
    assert!(matches!(result, Err(MatrixError::Sink(ref m)) if m.starts_with("disk full")));
    assert_eq!(seen, 3);
}

#[test]
fn points_to_other_targets_make_a_rectangular_matrix() {
    let mesh = bumpy_sphere(9);
    let mut rng = SplitMix64::new(12);
    let sources: Vec<SurfacePoint> = (0..5)
        .map(|_| {
            let face = FaceId((rng.next_u64() % mesh.face_count() as u64) as u32);
            SurfacePoint::Face {
                face,
                bary: [0.2, 0.3, 0.5],
            }
        })
        .collect();
    let targets = random_vertices(&mesh, 9, 13);
    let mut matrix = DenseMatrix::new(5, 9);
    let options = MatrixOptions::default().with_threads(2);
    distance_matrix::<f64, _>(&mesh, &sources, &targets, &options, |row| {
        matrix.insert(&row)
    })
    .unwrap();
    for (i, source) in sources.iter().enumerate() {
        let single = geodesic_distances::<f64>(
            &mesh,
            std::slice::from_ref(source),
            &PropagateOptions::default(),
        )
        .unwrap();
        for (j, t) in targets.iter().enumerate() {
            assert_eq!(matrix.get(i, j).to_bits(), single[t.index()].to_bits());
        }
    }
    assert_eq!(
        matrix.symmetrize_min(),
        Err(ShapeError::NotSquare {
            rows: 5,
            columns: 9
        })
    );
    let mut wrong = DenseMatrix::new(9, 5);
    let mut first = None;
    distance_matrix::<f64, Infallible>(&mesh, &sources[..1], &targets, &options, |row| {
        first = Some(row);
        Ok(())
    })
    .unwrap();
    assert!(matches!(
        wrong.insert(&first.unwrap()),
        Err(ShapeError::Row {
            length: 9,
            columns: 5,
            ..
        })
    ));
}

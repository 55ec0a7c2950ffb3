//! Non-manifold meshes propagate (issue 15): a "book" of flat pages sharing one edge, two cones
//! joined at their apex (a bowtie), and copies of faces, in every backend. Expected values come
//! from the coordinates: across the spine of a book, the distance is the straight line after
//! rotating the target's page flat against the source's; across the bowtie, the two generators
//! to the apex.

mod common;

use common::{edge_graph_dijkstra, planar_straight_distance};
use exact_geodesics::scalar::{Adaptive, Real};
use exact_geodesics::{
    propagate, FaceId, GeodesicField, PropagateOptions, Scalar, SurfacePoint, TriMesh, VertexId,
};

/// Where a vertex of a book lies: its page (`None` on the spine), its position along the
/// spine and its distance from it.
#[derive(Clone, Copy, Debug)]
struct PagePoint {
    page: Option<usize>,
    x: f64,
    r: f64,
}

impl PagePoint {
    /// The geodesic distance between two points of a book: on one page (or the spine), the
    /// straight line in that page; on two pages, the straight line once one page is turned
    /// about the spine to lie flat against the other, which crosses the spine between the two
    /// points' x (inside the spine).
    fn distance(self, other: PagePoint) -> f64 {
        let same = self.page.is_none() || other.page.is_none() || self.page == other.page;
        let dr = if same {
            self.r - other.r
        } else {
            self.r + other.r
        };
        (self.x - other.x).hypot(dr)
    }
}

struct Book {
    mesh: TriMesh,
    at: Vec<PagePoint>,
}

/// Side of a grid cell (all coordinates are integers).
const CELL: f64 = 5.0;

/// Pages around the spine on the x axis, from `-nx/2` to `nx/2` cells: page `p` runs in
/// direction `(0, c, s) / n` for `pages[p] = [c, s, n]` (integers with `c^2 + s^2 = n^2`, so
/// that its points, `r / n` apart with `r` a multiple of `CELL = 5`, are integers), and is a
/// grid of `nx` by `nr` cells. The spine's `nx` edges are each shared by every page.
fn book(pages: &[[i32; 3]], nx: usize, nr: usize) -> Book {
    let x = |i: usize| (i as f64 - (nx / 2) as f64) * CELL;
    let mut positions = Vec::new();
    let mut at = Vec::new();
    for i in 0..=nx {
        positions.push([x(i), 0.0, 0.0]);
        at.push(PagePoint {
            page: None,
            x: x(i),
            r: 0.0,
        });
    }
    for (p, &[c, s, n]) in pages.iter().enumerate() {
        for j in 1..=nr {
            let r = j as f64 * CELL;
            let k = r / f64::from(n);
            for i in 0..=nx {
                positions.push([x(i), k * f64::from(c), k * f64::from(s)]);
                at.push(PagePoint {
                    page: Some(p),
                    x: x(i),
                    r,
                });
            }
        }
    }
    let index = |p: usize, i: usize, j: usize| {
        if j == 0 {
            i as u32
        } else {
            ((nx + 1) * (1 + p * nr + j - 1) + i) as u32
        }
    };
    let mut faces = Vec::new();
    for p in 0..pages.len() {
        for j in 0..nr {
            for i in 0..nx {
                let [a, b, c, d] = [
                    index(p, i, j),
                    index(p, i + 1, j),
                    index(p, i + 1, j + 1),
                    index(p, i, j + 1),
                ];
                faces.extend([[a, b, c], [a, c, d]]);
            }
        }
    }
    Book {
        mesh: TriMesh::new(positions, faces).expect("a book is a usable mesh"),
        at,
    }
}

/// Three pages: two making a plane (y > 0 and y < 0) and one standing up (z > 0).
const THREE_PAGES: [[i32; 3]; 3] = [[1, 0, 1], [0, 1, 1], [-1, 0, 1]];
/// Four pages, the fourth at an angle that is no multiple of 90 degrees.
const FOUR_PAGES: [[i32; 3]; 4] = [[1, 0, 1], [0, 1, 1], [-1, 0, 1], [-3, -4, 5]];

fn field<'m, S: Scalar>(mesh: &'m TriMesh, source: SurfacePoint) -> GeodesicField<'m, S> {
    propagate::<S>(mesh, &[source], &PropagateOptions::default()).expect("valid source")
}

fn assert_close(got: f64, want: f64, what: &str) {
    assert!(
        (got - want).abs() <= 1e-12 * want.max(1.0),
        "{what}: got {got}, want {want}"
    );
}

/// Every vertex's distance from `source` (at `from` in the book) against the closed form, and
/// the centroid of every face on another page than the source's: its distance and the length
/// of the path traced back from it.
fn book_matches_unfolding<S: Scalar>(book: &Book, source: SurfacePoint, from: PagePoint) {
    let field = field::<S>(&book.mesh, source);
    for (v, &q) in book.at.iter().enumerate() {
        let got = field.vertex_distance(VertexId(v as u32));
        assert_close(got, from.distance(q), &format!("d(v{v} at {q:?})"));
    }
    for f in 0..book.mesh.face_count() {
        let corners = book.mesh.face(FaceId(f as u32)).map(|v| book.at[v.index()]);
        let Some(page) = corners.iter().find_map(|c| c.page) else {
            continue;
        };
        let centroid = PagePoint {
            page: Some(page),
            x: corners.iter().map(|c| c.x).sum::<f64>() / 3.0,
            r: corners.iter().map(|c| c.r).sum::<f64>() / 3.0,
        };
        let point = SurfacePoint::Face {
            face: FaceId(f as u32),
            bary: [1.0; 3],
        };
        let want = from.distance(centroid);
        let what = format!("centroid of f{f} on page {page}");
        assert_close(field.distance_at(&point).expect("a point"), want, &what);
        let path = field.trace_back(&point).expect("a path back");
        assert!(
            (path.length() - want).abs() <= 1e-9 * want,
            "{what}: path of length {} for {want}",
            path.length()
        );
    }
}

fn book_from_a_page_vertex<S: Scalar>(pages: &[[i32; 3]], nx: usize, nr: usize) {
    let book = book(pages, nx, nr);
    assert_eq!(book.mesh.validation().non_manifold_edges.len(), nx);
    assert!(book
        .mesh
        .validation()
        .non_manifold_edges
        .iter()
        .all(|e| e.face_count == pages.len()));
    // A vertex of page 0 one cell from the spine and right of its middle: the straight lines
    // to the other pages cross the spine inside its edges (and some at its vertices).
    let v = (nx + 1) + nx / 2 + 1;
    assert_eq!(book.at[v].page, Some(0));
    book_matches_unfolding::<S>(&book, SurfacePoint::Vertex(VertexId(v as u32)), book.at[v]);
}

fn book_from_the_spine<S: Scalar>(pages: &[[i32; 3]], nx: usize, nr: usize) {
    let book = book(pages, nx, nr);
    // A point of the spine's first edge, shared by every page: all pages are at the same
    // straight distance, as if each were the only one.
    let edge = book
        .mesh
        .edge_between(VertexId(0), VertexId(1))
        .expect("a spine edge");
    let t = 0.25;
    let from = PagePoint {
        page: None,
        x: book.at[0].x + t * CELL,
        r: 0.0,
    };
    book_matches_unfolding::<S>(&book, SurfacePoint::Edge { edge, t }, from);
}

fn book_in_backend<S: Scalar>() {
    book_from_a_page_vertex::<S>(&THREE_PAGES, 2, 1);
    book_from_a_page_vertex::<S>(&FOUR_PAGES, 4, 2);
    book_from_the_spine::<S>(&FOUR_PAGES, 2, 1);
}

#[test]
fn book_distances_are_straight_lines_through_the_spine_in_f64() {
    book_in_backend::<f64>();
}

#[test]
fn book_distances_are_straight_lines_through_the_spine_in_adaptive() {
    book_in_backend::<Adaptive>();
}

#[test]
fn book_distances_are_straight_lines_through_the_spine_in_exact() {
    book_in_backend::<Real>();
}

/// Two open cones with apex at the origin, over the squares `(+-1, 0, h)`, `(0, +-1, h)`
/// (`h = 1`) and the same at `z = -1`, turned by 45 degrees: vertex 0 joins two fans.
fn bowtie_cones() -> TriMesh {
    let s = std::f64::consts::FRAC_1_SQRT_2;
    let positions = vec![
        [0.0, 0.0, 0.0],
        [1.0, 0.0, 1.0],
        [0.0, 1.0, 1.0],
        [-1.0, 0.0, 1.0],
        [0.0, -1.0, 1.0],
        [s, s, -1.0],
        [-s, s, -1.0],
        [-s, -s, -1.0],
        [s, -s, -1.0],
    ];
    let faces = (0..4)
        .flat_map(|k| {
            let (a, b) = (1 + k, 1 + (k + 1) % 4);
            [[0, a, b], [0, b + 4, a + 4]]
        })
        .collect();
    TriMesh::new(positions, faces).expect("a bowtie is a usable mesh")
}

fn bowtie_in_backend<S: Scalar>() {
    let mesh = bowtie_cones();
    assert_eq!(mesh.validation().non_manifold_vertices, vec![VertexId(0)]);
    let field = field::<S>(&mesh, SurfacePoint::Vertex(VertexId(1)));
    // Every face of the upper cone is equilateral with side sqrt(2): unrolled, the cone is four
    // triangles of 60 degrees at the apex, so the ring vertex two steps away is at
    // 2 sqrt(2) sin(60 degrees) = sqrt(6); its neighbours are at sqrt(2) (their edge).
    let root2 = 2f64.sqrt();
    for (v, want) in [(0, root2), (2, root2), (3, 6f64.sqrt()), (4, root2)] {
        assert_close(
            field.vertex_distance(VertexId(v)),
            want,
            &format!("d(v{v})"),
        );
    }
    // The lower cone: through the apex, along a generator of each cone.
    for v in 5..9 {
        assert_close(
            field.vertex_distance(VertexId(v)),
            2.0 * root2,
            &format!("d(v{v})"),
        );
    }
    // Any point of a lower face: the generator to the apex, then the segment from it.
    let lower = FaceId(1);
    let bary = [1.0, 2.0, 3.0];
    let corners = mesh.face(lower).map(|v| mesh.position(v));
    let p = [0, 1, 2].map(|i| (0..3).map(|k| bary[k] * corners[k][i]).sum::<f64>() / 6.0);
    let want = root2 + p.iter().map(|c| c * c).sum::<f64>().sqrt();
    let point = SurfacePoint::Face { face: lower, bary };
    assert_close(
        field.distance_at(&point).expect("a point"),
        want,
        "lower face point",
    );
    let path = field.trace_back(&point).expect("a path back");
    assert!(path.simplices.contains(&SurfacePoint::Vertex(VertexId(0))));
    assert!((path.length() - want).abs() < 1e-9, "{path:?}");
}

#[test]
fn bowtie_cones_meet_at_their_apex_in_every_backend() {
    bowtie_in_backend::<f64>();
    bowtie_in_backend::<Adaptive>();
    bowtie_in_backend::<Real>();
}

#[test]
fn distances_lie_between_the_straight_line_and_the_edge_graph_at_every_vertex() {
    let meshes = [
        book(&THREE_PAGES, 4, 2).mesh,
        book(&FOUR_PAGES, 4, 2).mesh,
        bowtie_cones(),
    ];
    for mesh in &meshes {
        for s in 0..mesh.vertex_count() {
            let d = field::<f64>(mesh, SurfacePoint::Vertex(VertexId(s as u32))).vertex_distances();
            let graph = edge_graph_dijkstra(mesh, s);
            for (t, &got) in d.iter().enumerate() {
                let straight = planar_straight_distance(mesh, s, t);
                assert!(
                    got >= straight * (1.0 - 1e-12),
                    "d(v{s}, v{t}) = {got} < {straight}"
                );
                assert!(
                    got <= graph[t] * (1.0 + 1e-12),
                    "d(v{s}, v{t}) = {got} > {}",
                    graph[t]
                );
            }
        }
    }
}

#[test]
fn a_copy_of_a_face_is_reported_and_ignored() {
    let plain = book(&THREE_PAGES, 2, 1).mesh;
    let mut faces = plain.faces().to_vec();
    let copied = FaceId(5);
    let [a, b, c] = faces[copied.index()];
    faces.push([c, b, a]);
    let mesh = TriMesh::new(plain.positions().to_vec(), faces).expect("a copy is usable");
    let report = mesh.validation();
    assert_eq!(report.duplicate_faces.len(), 1);
    assert_eq!(report.duplicate_faces[0].copy_of, copied);
    assert_eq!(
        report.non_manifold_edges,
        plain.validation().non_manifold_edges
    );
    assert_eq!(report.components, 1);
    let copy = report.duplicate_faces[0].face;
    for s in 0..mesh.vertex_count() {
        let source = SurfacePoint::Vertex(VertexId(s as u32));
        let (with, without) = (field::<f64>(&mesh, source), field::<f64>(&plain, source));
        assert_eq!(with.vertex_distances(), without.vertex_distances());
        // A point of the copy is that point of the face it copies (corners in another order).
        let in_copy = SurfacePoint::Face {
            face: copy,
            bary: [0.5, 0.3, 0.2],
        };
        let in_face = SurfacePoint::Face {
            face: copied,
            bary: [0.2, 0.3, 0.5],
        };
        assert_eq!(with.distance_at(&in_copy), without.distance_at(&in_face));
    }
}

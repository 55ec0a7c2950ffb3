//! [LZT §3] Example 4: the final wedges on the edges of Face 20 = (v5, v4, v13) as 7-tuples
//! (b0, b1, d0, d1, tau, s, sigma), tau relative to Face 20, and the face's 2D subdivision
//! (Fig. 15, Property 4).

use exact_geodesics::mesh::shapes;
use exact_geodesics::paper::subdivision_summary;
use exact_geodesics::paper::table::face_rows;
use exact_geodesics::subdivision::face_subdivision;
use exact_geodesics::{propagate, FaceId, PropagateOptions, SurfacePoint, VertexId};

fn main() {
    let mesh = shapes::paper_example4();
    let field = propagate::<f64>(
        &mesh,
        &[SurfacePoint::Vertex(VertexId(2))],
        &PropagateOptions::default(),
    )
    .expect("v2 is a vertex of the mesh");
    println!("Example 4: source v2; Face 20: f20 = (v5, v4, v13)");
    for rows in face_rows(&field, FaceId(20)) {
        print!("{rows}");
    }
    print!(
        "{}",
        subdivision_summary(&face_subdivision(&field, FaceId(20)))
    );
    println!("Drawing: cargo run --release -- subdivision paper-examples/example4.obj --source v:2 --face 20 --svg face20.svg");
}

//! [LZT §3] Example 2, on a mesh of our own (the paper's 8-shape is not given): a source P and a
//! pseudo-source P' with P - P' parallel to the edge they both reach, so that eq. (2) has
//! A = B = 0 and C != 0: no solution, and P keeps the whole shared range.

use exact_geodesics::mesh::shapes;
use exact_geodesics::paper::examples::{
    eq2_line, eq2_of, six_tuple, unfold_named, EXAMPLE2, EXAMPLE2_EDGE,
};
use exact_geodesics::paper::table::edge_rows;
use exact_geodesics::{propagate, PropagateOptions, SurfacePoint, VertexId};

fn main() {
    let mesh = shapes::l_shape(1);
    let field = propagate::<f64>(
        &mesh,
        &[SurfacePoint::Vertex(VertexId(5))],
        &PropagateOptions::default(),
    )
    .expect("v5 is a vertex of the mesh");
    let wedges = unfold_named::<f64>(&mesh, &EXAMPLE2, EXAMPLE2_EDGE, |v| {
        field.vertex_distance(v)
    });
    println!("Example 2 (our L-shape): source P = v5 = (2, 1), pseudo-source P' = v2 = (1, 1), edge I = (v0, v1) on y = 0");
    for (named, w) in EXAMPLE2.iter().zip(&wedges) {
        println!("{}: {}", named.name, six_tuple(&mesh, w));
    }
    println!("Eq. (2) in f64:");
    println!(
        "{}",
        eq2_line((EXAMPLE2[0].name, EXAMPLE2[1].name), &eq2_of(&wedges, 0, 1))
    );
    println!("Eq. (2) cases met by the engine: {:?}", field.stats().eq2);
    let edge = mesh.edge_between(VertexId(0), VertexId(1)).expect("edge I");
    println!("Final wedges of the engine on I:");
    print!("{}", edge_rows(&field, VertexId(0), edge, None));
    let top = mesh
        .edge_between(VertexId(7), VertexId(6))
        .expect("edge (v7, v6) on y = 2");
    println!("P' is a real pseudo-source: it alone reaches the arm behind the corner, e.g.");
    print!("{}", edge_rows(&field, VertexId(7), top, None));
}

//! [LZT §3] Example 3: source v0 reaches edge e0 = (v5, v7) from both of its sides; eq. (2)
//! between w1 and w2 has one solution, and the final wedges lie on different sides (Property 3).

use exact_geodesics::mesh::shapes;
use exact_geodesics::paper::examples::{
    eq2_line, eq2_of, six_tuple, unfold_named, EXAMPLE3, EXAMPLE3_EDGE,
};
use exact_geodesics::paper::table::edge_rows;
use exact_geodesics::scalar::{Adaptive, Real};
use exact_geodesics::{propagate, PropagateOptions, Scalar, SurfacePoint, TriMesh, VertexId};

fn main() {
    let mesh = shapes::paper_example3();
    let wedges = unfold_named::<f64>(&mesh, &EXAMPLE3, EXAMPLE3_EDGE, |_| 0.0);
    println!("Example 3: source v0, edge e0 = (v5, v7); 6-tuples (b0, b1, d0, d1, sigma, tau)");
    for (named, w) in EXAMPLE3.iter().zip(&wedges) {
        println!("{}: {}", named.name, six_tuple(&mesh, w));
    }
    eq2_in::<f64>("f64", &mesh);
    eq2_in::<Adaptive>("adaptive", &mesh);
    eq2_in::<Real>("exact", &mesh);
    let field = propagate::<f64>(
        &mesh,
        &[SurfacePoint::Vertex(VertexId(0))],
        &PropagateOptions::default(),
    )
    .expect("v0 is a vertex of the mesh");
    let e0 = mesh
        .edge_between(VertexId(5), VertexId(7))
        .expect("edge e0");
    println!("Final wedges of the engine (tau: the face the wedge comes from; f8 = Δv5v7v6, f9 = Δv5v8v7):");
    print!("{}", edge_rows(&field, VertexId(5), e0, None));
}

/// Eq. (2) between w1 and w2, unfolded and decided in the backend `S`.
fn eq2_in<S: Scalar>(backend: &str, mesh: &TriMesh) {
    let wedges = unfold_named::<S>(mesh, &EXAMPLE3, EXAMPLE3_EDGE, |_| S::zero());
    println!("Eq. (2) in {backend}:");
    println!(
        "  {}",
        eq2_line((EXAMPLE3[0].name, EXAMPLE3[1].name), &eq2_of(&wedges, 0, 1))
    );
}

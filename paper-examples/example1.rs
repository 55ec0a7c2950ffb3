//! [LZT §3] Example 1: the four wedges of source v0 on edge e2 = (v5, v7), and eq. (2) between
//! w1 and w2 (no solution in the shared range) and between w1 and w3 (A = B = C = 0).

use exact_geodesics::mesh::shapes;
use exact_geodesics::paper::examples::{
    eq2_line, eq2_of, six_tuple, unfold_named, EXAMPLE1, EXAMPLE1_EDGE,
};
use exact_geodesics::paper::table::edge_rows;
use exact_geodesics::scalar::{Adaptive, Real};
use exact_geodesics::{propagate, PropagateOptions, Scalar, SurfacePoint, TriMesh, VertexId};

fn main() {
    let mesh = shapes::paper_example1();
    let wedges = unfold_named::<f64>(&mesh, &EXAMPLE1, EXAMPLE1_EDGE, |_| 0.0);
    println!("Example 1: source v0, edge e2 = (v5, v7); 6-tuples (b0, b1, d0, d1, sigma, tau)");
    for (named, w) in EXAMPLE1.iter().zip(&wedges) {
        let faces: Vec<String> = named
            .faces
            .iter()
            .map(|c| format!("Δv{}v{}v{}", c[0], c[1], c[2]))
            .collect();
        println!("{}: {}", named.name, six_tuple(&mesh, w));
        println!("    through {}", faces.join(", "));
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
    let e2 = mesh
        .edge_between(VertexId(5), VertexId(7))
        .expect("edge e2");
    println!("Final wedges of the engine (tau: the face the wedge comes from):");
    print!("{}", edge_rows(&field, VertexId(5), e2, None));
}

/// Eq. (2) between the example's wedges, unfolded and decided in the backend `S`, with how the
/// backend settled its sign decisions.
fn eq2_in<S: Scalar>(backend: &str, mesh: &TriMesh) {
    S::take_counts();
    let wedges = unfold_named::<S>(mesh, &EXAMPLE1, EXAMPLE1_EDGE, |_| S::zero());
    println!("Eq. (2) in {backend}:");
    for (i, j) in [(0, 1), (0, 2), (1, 3)] {
        let names = (EXAMPLE1[i].name, EXAMPLE1[j].name);
        println!("  {}", eq2_line(names, &eq2_of(&wedges, i, j)));
    }
    let c = S::take_counts();
    if c.decisions > 0 {
        println!(
            "  ({} sign decisions: {} by the f64 filter, {} by the exact stage, {} certified zeros, {} uncertified)",
            c.decisions, c.by_filter, c.by_refinement, c.certified_zeros, c.uncertified
        );
    }
}

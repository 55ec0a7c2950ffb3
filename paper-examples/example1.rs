//! [LZT §3] Example 1: the four wedges of source v0 on edge e2 = (v5, v7), and eq. (2) between
//! w1 and w2 (no solution in the shared range) and between w1 and w3 (A = B = C = 0).

use exact_geodesics::mesh::shapes;
use exact_geodesics::paper::examples::{
    engine_wedges, eq2_by_backend, six_tuple, unfold_named, EXAMPLE1, EXAMPLE1_EDGE,
};

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
    print!(
        "{}",
        eq2_by_backend(&mesh, &EXAMPLE1, EXAMPLE1_EDGE, &[(0, 1), (0, 2), (1, 3)])
    );
    println!("Final wedges of the engine (tau: the face the wedge comes from):");
    print!("{}", engine_wedges(&mesh, 0, EXAMPLE1_EDGE));
}

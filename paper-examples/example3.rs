//! [LZT §3] Example 3: source v0 reaches edge e0 = (v5, v7) from both of its sides; eq. (2)
//! between w1 and w2 has one solution, and the final wedges lie on different sides (Property 3).

use exact_geodesics::mesh::shapes;
use exact_geodesics::paper::examples::{
    engine_wedges, eq2_by_backend, six_tuple, unfold_named, EXAMPLE3, EXAMPLE3_EDGE,
};

fn main() {
    let mesh = shapes::paper_example3();
    let wedges = unfold_named::<f64>(&mesh, &EXAMPLE3, EXAMPLE3_EDGE, |_| 0.0);
    println!("Example 3: source v0, edge e0 = (v5, v7); 6-tuples (b0, b1, d0, d1, sigma, tau)");
    for (named, w) in EXAMPLE3.iter().zip(&wedges) {
        println!("{}: {}", named.name, six_tuple(&mesh, w));
    }
    print!(
        "{}",
        eq2_by_backend(&mesh, &EXAMPLE3, EXAMPLE3_EDGE, &[(0, 1)])
    );
    println!("Final wedges of the engine (tau: the face the wedge comes from; f8 = Δv5v7v6, f9 = Δv5v8v7):");
    print!("{}", engine_wedges(&mesh, 0, EXAMPLE3_EDGE));
}

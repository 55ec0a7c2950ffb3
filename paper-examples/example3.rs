//! [LZT §3] Example 3: source v0 reaches edge e0 = (v5, v7) from both of its sides; eq. (2)
//! between w1 and w2 has one solution (Property 3). The mirror symmetry x <-> y gives each of
//! them a twin from the other side with the same distance function (eq. (2): infinitely many
//! solutions), so the side of each final wedge is that of whichever twin came first.

use exact_geodesics::mesh::shapes;
use exact_geodesics::paper::examples::{
    engine_wedges, eq2_by_backend, six_tuple, unfold_named, EXAMPLE3, EXAMPLE3_EDGE,
    EXAMPLE3_MIRRORS,
};

fn main() {
    let mesh = shapes::paper_example3();
    let [w1, w2] = EXAMPLE3;
    let [w1m, w2m] = EXAMPLE3_MIRRORS;
    let strips = [w1, w2, w1m, w2m];
    let wedges = unfold_named::<f64>(&mesh, &strips, EXAMPLE3_EDGE, |_| 0.0);
    println!("Example 3: source v0, edge e0 = (v5, v7); 6-tuples (b0, b1, d0, d1, sigma, tau)");
    for (named, w) in strips.iter().zip(&wedges) {
        println!("{}: {}", named.name, six_tuple(&mesh, w));
    }
    print!(
        "{}",
        eq2_by_backend(&mesh, &strips, EXAMPLE3_EDGE, &[(0, 1), (0, 2), (1, 3)])
    );
    println!("Final wedges of the engine (tau: the face the wedge comes from; f8 = Δv5v7v6, f9 = Δv5v8v7):");
    print!("{}", engine_wedges(&mesh, 0, EXAMPLE3_EDGE));
}

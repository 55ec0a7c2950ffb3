use exact_geodesics::scalar::Real;
use exact_geodesics::{propagate, EdgeId, PropagateOptions, Scalar, SurfacePoint, VertexId};
fn go<S: Scalar>(name: &str, file: &str, s: u32) {
    let mesh = exact_geodesics::mesh::io::read_path(std::path::Path::new(file), &Default::default()).expect("mesh");
    let field = propagate::<S>(&mesh, &[SurfacePoint::Vertex(VertexId(s))], &PropagateOptions::default()).expect("ok");
    for e in std::env::var("E").unwrap().split(',') {
        let e: u32 = e.parse().unwrap();
        eprintln!("{name} e{e} {:?} len {}", mesh.edge(EdgeId(e)).vertices, field.edge_length(EdgeId(e)).to_f64());
        for w in field.wedges(EdgeId(e)) {
            eprintln!("   ps {:?} tau {:?} b0 {:.17e} b1 {:.17e} src ({:.17e},{:.17e}) sigma {:.17e}", w.pseudo_source, w.tau, w.b0.to_f64(), w.b1.to_f64(), w.source_x.to_f64(), w.source_y.to_f64(), w.sigma.to_f64());
        }
    }
}
#[test]
fn scratch() {
    let f = std::env::var("F").unwrap();
    let s: u32 = std::env::var("S").unwrap().parse().unwrap();
    go::<f64>("f64", &f, s);
    go::<Real>("exact", &f, s);
}

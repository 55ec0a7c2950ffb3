//! The data of Examples 1-3 [LZT §3] (and of our stand-in for Example 2): which wedges reach
//! which edge through which faces, and their text in the paper's notation.

use super::strip::{eq2_pair, face_with_corners, unfold_strip, Eq2Pair, StripWedge};
use crate::mesh::{TriMesh, VertexId};
use crate::scalar::{BisectorRoots, Scalar};

/// A wedge as an example names it: its name, its (pseudo-)source vertex, and the faces it
/// passes through, each by its corners.
#[derive(Clone, Copy, Debug)]
pub struct NamedStrip {
    /// The paper's name (`w1`, `P`, ...).
    pub name: &'static str,
    /// The vertex the wedge's rays start from.
    pub source: u32,
    /// The faces, in the order the rays cross them.
    pub faces: &'static [[u32; 3]],
}

/// Example 1, source v0: the four wedges reaching `e2 = (v5, v7)` as Fig. 4 lists them (w4, the
/// mirror image of w2, through the mirror images of its faces).
pub const EXAMPLE1: [NamedStrip; 4] = [
    NamedStrip {
        name: "w1",
        source: 0,
        faces: &[[0, 1, 2], [1, 6, 2], [2, 6, 5], [5, 6, 7]],
    },
    NamedStrip {
        name: "w2",
        source: 0,
        faces: &[[0, 2, 3], [2, 4, 3], [2, 5, 4], [2, 6, 5], [5, 6, 7]],
    },
    NamedStrip {
        name: "w3",
        source: 0,
        faces: &[[0, 2, 3], [2, 4, 3], [2, 5, 4], [4, 5, 7]],
    },
    NamedStrip {
        name: "w4",
        source: 0,
        faces: &[[0, 1, 2], [1, 6, 2], [2, 6, 5], [2, 5, 4], [4, 5, 7]],
    },
];

/// Example 1's edge `e2`.
pub const EXAMPLE1_EDGE: (u32, u32) = (5, 7);

/// Our Example 2 on [`l_shape(1)`](crate::mesh::shapes::l_shape): the source `P = v5 = (2, 1)`
/// reaches the edge `(v0, v1)` on `y = 0` across the face `(v1, v5, v2)`; the reflex corner
/// `P' = v2 = (1, 1)`, a pseudo-source at distance 1, reaches it across its own face
/// `(v0, v1, v2)`. `P - P'` is parallel to the edge.
pub const EXAMPLE2: [NamedStrip; 2] = [
    NamedStrip {
        name: "P",
        source: 5,
        faces: &[[1, 5, 2], [0, 1, 2]],
    },
    NamedStrip {
        name: "P'",
        source: 2,
        faces: &[[0, 1, 2]],
    },
];

/// Example 2's edge `I(a, b)`.
pub const EXAMPLE2_EDGE: (u32, u32) = (0, 1);

/// Example 3, source v0: the two wedges reaching `e0 = (v5, v7)` from its two sides (Fig. 9).
pub const EXAMPLE3: [NamedStrip; 2] = [
    NamedStrip {
        name: "w1",
        source: 0,
        faces: &[[0, 1, 2], [1, 6, 2], [1, 5, 6], [5, 7, 6]],
    },
    NamedStrip {
        name: "w2",
        source: 0,
        faces: &[[0, 3, 4], [3, 7, 4], [4, 7, 8], [5, 8, 7]],
    },
];

/// Example 3: the mirror images of `w1` and `w2` under the symmetry x <-> y, which fixes `e0`
/// pointwise: `w1'` over the side x = 0 and `w2'` over the side x = 1 reach `e0` from the other
/// side with the same distance function (eq. (2) has infinitely many solutions), so each final
/// wedge of `e0` is whichever of a tied pair reached it first.
pub const EXAMPLE3_MIRRORS: [NamedStrip; 2] = [
    NamedStrip {
        name: "w1'",
        source: 0,
        faces: &[[0, 4, 1], [1, 4, 8], [1, 8, 5], [5, 8, 7]],
    },
    NamedStrip {
        name: "w2'",
        source: 0,
        faces: &[[0, 2, 3], [2, 7, 3], [2, 6, 7], [5, 7, 6]],
    },
];

/// Example 3's edge `e0`.
pub const EXAMPLE3_EDGE: (u32, u32) = (5, 7);

/// Unfolds each named wedge onto `edge`; `sigma(v)` is the distance of a pseudo-source vertex
/// back to the source. Panics if a named face does not exist or a strip is not one, which would
/// be an error in the constants above.
pub fn unfold_named<S: Scalar>(
    mesh: &TriMesh,
    strips: &[NamedStrip],
    edge: (u32, u32),
    sigma: impl Fn(VertexId) -> S,
) -> Vec<StripWedge<S>> {
    strips
        .iter()
        .map(|n| {
            let faces: Vec<_> = n
                .faces
                .iter()
                .map(|&c| face_with_corners(mesh, c).expect("a face of the example"))
                .collect();
            let v = VertexId(n.source);
            unfold_strip(
                mesh,
                v,
                sigma(v),
                &faces,
                (VertexId(edge.0), VertexId(edge.1)),
            )
            .expect("the example's strip")
        })
        .collect()
}

/// A wedge as the 6-tuple of Definition 1 `(b0, b1, d0, d1, sigma, tau)`, tau named by the
/// face the wedge comes from.
pub fn six_tuple<S: Scalar>(mesh: &TriMesh, w: &StripWedge<S>) -> String {
    let c = mesh.face(w.face).map(|v| v.0);
    format!(
        "({:.4}, {:.4}, {:.4}, {:.4}, {:.4}, Δv{}v{}v{})",
        w.b0.to_f64(),
        w.b1.to_f64(),
        w.d0().to_f64(),
        w.d1().to_f64(),
        w.sigma.to_f64(),
        c[0],
        c[1],
        c[2]
    )
}

/// Eq. (2) between two wedges in one line: the shared range, `A, B, C` (values and the signs
/// the backend `S` decides) and the solutions in the range [LZT §2, Property 1].
pub fn eq2_line<S: Scalar>(names: (&str, &str), pair: &Option<Eq2Pair<S>>) -> String {
    let Some(pair) = pair else {
        return format!("{} / {}: no shared range", names.0, names.1);
    };
    let c = &pair.coefficients;
    let roots = match &pair.roots {
        BisectorRoots::None => "no solution".to_string(),
        BisectorRoots::One(t) => format!("one solution at {:.4}", t.to_f64()),
        BisectorRoots::Touch(t) => format!("one solution at {:.4} (touching)", t.to_f64()),
        BisectorRoots::Two(t, u) => {
            format!("two solutions at {:.4}, {:.4}", t.to_f64(), u.to_f64())
        }
        BisectorRoots::Infinite => "infinitely many solutions".to_string(),
    };
    format!(
        "{} / {}: shared range ({:.4}, {:.4}), A = {:.3e} ({:?}), B = {:.3e} ({:?}), C = {:.3e} ({:?}): {roots}",
        names.0,
        names.1,
        pair.range.0.to_f64(),
        pair.range.1.to_f64(),
        c.a.to_f64(),
        c.a.sign(),
        c.b.to_f64(),
        c.b.sign(),
        c.c.to_f64(),
        c.c.sign(),
    )
}

/// Eq. (2) for wedges `i` and `j` of a list.
pub fn eq2_of<S: Scalar>(wedges: &[StripWedge<S>], i: usize, j: usize) -> Option<Eq2Pair<S>> {
    eq2_pair(&wedges[i], &wedges[j])
}

/// Eq. (2) between pairs of an example's wedges from the source (sigma 0), unfolded and decided
/// in the backend `S`: one line per pair, then how the backend settled its sign decisions if it
/// counts them.
pub fn eq2_report<S: Scalar>(
    mesh: &TriMesh,
    strips: &[NamedStrip],
    edge: (u32, u32),
    pairs: &[(usize, usize)],
) -> Vec<String> {
    S::take_counts();
    let wedges = unfold_named::<S>(mesh, strips, edge, |_| S::zero());
    let mut lines: Vec<String> = pairs
        .iter()
        .map(|&(i, j)| eq2_line((strips[i].name, strips[j].name), &eq2_of(&wedges, i, j)))
        .collect();
    let c = S::take_counts();
    if c.decisions > 0 {
        lines.push(format!(
            "({} sign decisions: {} by the f64 filter, {} by the exact stage, {} certified zeros, {} uncertified)",
            c.decisions, c.by_filter, c.by_refinement, c.certified_zeros, c.uncertified
        ));
    }
    lines
}

/// [`eq2_report`] in every backend, f64, adaptive and exact, one after the other.
pub fn eq2_by_backend(
    mesh: &TriMesh,
    strips: &[NamedStrip],
    edge: (u32, u32),
    pairs: &[(usize, usize)],
) -> String {
    let sections = [
        ("f64", eq2_report::<f64>(mesh, strips, edge, pairs)),
        (
            "adaptive",
            eq2_report::<crate::scalar::Adaptive>(mesh, strips, edge, pairs),
        ),
        (
            "exact",
            eq2_report::<crate::scalar::Real>(mesh, strips, edge, pairs),
        ),
    ];
    let mut text = String::new();
    for (backend, lines) in sections {
        text.push_str(&format!("Eq. (2) in {backend}:\n"));
        for line in lines {
            text.push_str(&format!("  {line}\n"));
        }
    }
    text
}

/// The engine's final wedges on `edge` for a source at vertex `source`, in f64, read from the
/// edge's first vertex, as the 7-tuple table.
pub fn engine_wedges(mesh: &TriMesh, source: u32, edge: (u32, u32)) -> String {
    let field = crate::propagate::<f64>(
        mesh,
        &[crate::SurfacePoint::Vertex(VertexId(source))],
        &crate::PropagateOptions::default(),
    )
    .expect("the example's source is a vertex");
    let e = mesh
        .edge_between(VertexId(edge.0), VertexId(edge.1))
        .expect("the example's edge");
    super::table::edge_rows(&field, VertexId(edge.0), e, None).to_string()
}

//! Reproductions of the examples of [LZT §3]: data and text for the runnable examples in
//! `paper-examples/` and for the tests. Nothing here prints; the examples do.
//!
//! Unstable: this module serves the reproductions and may change with them; it is not part of
//! the library's API for distances and paths.

pub mod examples;
pub mod strip;
pub mod table;

use crate::subdivision::{BisectorKind, FaceSubdivision};
use std::fmt::Write;

/// A face subdivision as text: one line per region (label, sigma, area, image) and per
/// bisector (the two labels, line or hyperbola) [LZT Fig. 15].
pub fn subdivision_summary(sub: &FaceSubdivision) -> String {
    let mut s = String::new();
    let c = sub.corners.map(|v| v.0);
    writeln!(
        s,
        "Face {} = (v{}, v{}, v{}), area {:.4}: {} regions",
        sub.face.0,
        c[0],
        c[1],
        c[2],
        sub.face_area(),
        sub.regions.len()
    )
    .expect("String");
    for r in &sub.regions {
        writeln!(
            s,
            "  region {:>5}: sigma {:.3}, area {:.5}, image ({:.3}, {:.3})",
            r.label,
            r.sigma,
            r.area(),
            r.image.x,
            r.image.y
        )
        .expect("String");
    }
    for b in &sub.bisectors {
        let kind = match b.kind {
            BisectorKind::Line => "line segment",
            BisectorKind::Hyperbola => "hyperbolic curve",
        };
        writeln!(
            s,
            "  bisector {{{}, {}}}: {kind}",
            sub.regions[b.regions[0]].label, sub.regions[b.regions[1]].label
        )
        .expect("String");
    }
    s
}

//! SVG drawing of a face subdivision in the manner of Fig. 15 [LZT §3]: the face unfolded, each
//! region filled and labelled with its pseudo-source, bisectors drawn over the fills, corners
//! named.

use crate::subdivision::{FaceSubdivision, Point2};
use glam::DVec2;
use std::fmt::Write;

/// Width and height of the drawing in pixels.
const SIZE: f64 = 800.0;

/// A distinct fill colour for region `i` of `n` (hues spread around the circle).
fn colour(i: usize, n: usize) -> String {
    format!(
        "hsl({:.0}, 70%, {}%)",
        360.0 * i as f64 / n.max(1) as f64,
        if i % 2 == 0 { 72 } else { 58 }
    )
}

/// The centroid of a polygon's area (its first vertex if degenerate).
fn centroid(polygon: &[Point2]) -> Point2 {
    let n = polygon.len();
    let (mut a, mut moment) = (0.0, DVec2::ZERO);
    for i in 0..n {
        let (p, q) = (polygon[i], polygon[(i + 1) % n]);
        let c = p.perp_dot(q);
        a += c;
        moment += (p + q) * c;
    }
    if a.abs() < 1e-300 {
        polygon[0]
    } else {
        moment / (3.0 * a)
    }
}

/// The subdivision as an SVG document.
pub fn subdivision_svg(sub: &FaceSubdivision) -> String {
    let (lo, hi) = sub
        .layout
        .iter()
        .fold((DVec2::INFINITY, DVec2::NEG_INFINITY), |(lo, hi), &p| {
            (lo.min(p), hi.max(p))
        });
    let margin = 60.0;
    let scale = (SIZE - 2.0 * margin) / (hi - lo).max_element();
    // To pixels, y pointing down.
    let map = |p: Point2| {
        let q = (p - lo) * scale;
        DVec2::new(margin + q.x, SIZE - margin - q.y)
    };
    let path = |points: &[Point2], close: bool| {
        let mut d = String::new();
        for (i, &p) in points.iter().enumerate() {
            let DVec2 { x, y } = map(p);
            write!(d, "{}{x:.2},{y:.2} ", if i == 0 { "M" } else { "L" }).expect("String");
        }
        if close {
            d.push('Z');
        }
        d
    };
    let mut svg = String::new();
    writeln!(
        svg,
        r#"<svg xmlns="http://www.w3.org/2000/svg" width="{SIZE}" height="{SIZE}" viewBox="0 0 {SIZE} {SIZE}" font-family="sans-serif">"#
    )
    .expect("String");
    writeln!(svg, r#"<rect width="100%" height="100%" fill="white"/>"#).expect("String");
    let n = sub.regions.len();
    for (i, r) in sub.regions.iter().enumerate() {
        writeln!(
            svg,
            r#"<path d="{}" fill="{}" stroke="{1}" stroke-width="0.8"><title>{} (sigma {:.4})</title></path>"#,
            path(&r.polygon, true),
            colour(i, n),
            r.label,
            r.sigma
        )
        .expect("String");
    }
    for b in &sub.bisectors {
        let dash = match b.kind {
            crate::subdivision::BisectorKind::Line => "",
            crate::subdivision::BisectorKind::Hyperbola => r#" stroke-dasharray="8,3""#,
        };
        writeln!(
            svg,
            r#"<path d="{}" fill="none" stroke="black" stroke-width="2"{dash}/>"#,
            path(&b.points, false)
        )
        .expect("String");
    }
    writeln!(
        svg,
        r#"<path d="{}" fill="none" stroke="black" stroke-width="3"/>"#,
        path(&sub.layout, true)
    )
    .expect("String");
    for r in &sub.regions {
        let DVec2 { x, y } = map(centroid(&r.polygon));
        writeln!(
            svg,
            r#"<text x="{x:.2}" y="{y:.2}" font-size="20" text-anchor="middle" dominant-baseline="middle">{}</text>"#,
            r.label
        )
        .expect("String");
    }
    let centre = map(centroid(&sub.layout));
    for (k, &p) in sub.layout.iter().enumerate() {
        let at = map(p);
        let d = at - centre;
        // The corner's name 28 pixels out from the face's centroid.
        let name = at + 28.0 * d / d.x.hypot(d.y).max(1e-9);
        writeln!(
            svg,
            r#"<circle cx="{:.2}" cy="{:.2}" r="5" fill="black"/><text x="{:.2}" y="{:.2}" font-size="22" font-weight="bold" text-anchor="middle" dominant-baseline="middle">v{}</text>"#,
            at.x,
            at.y,
            name.x,
            name.y,
            sub.corners[k].0
        )
        .expect("String");
    }
    svg.push_str("</svg>\n");
    svg
}

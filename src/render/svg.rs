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
        let (p, q) = (DVec2::from(polygon[i]), DVec2::from(polygon[(i + 1) % n]));
        let c = p.perp_dot(q);
        a += c;
        moment += (p + q) * c;
    }
    if a.abs() < 1e-300 {
        polygon[0]
    } else {
        (moment / (3.0 * a)).to_array()
    }
}

/// The subdivision as an SVG document.
pub fn subdivision_svg(sub: &FaceSubdivision) -> String {
    let xs = sub.layout.map(|p| p[0]);
    let ys = sub.layout.map(|p| p[1]);
    let (x0, x1) = (
        xs.iter().copied().fold(f64::INFINITY, f64::min),
        xs.iter().copied().fold(f64::NEG_INFINITY, f64::max),
    );
    let (y0, y1) = (
        ys.iter().copied().fold(f64::INFINITY, f64::min),
        ys.iter().copied().fold(f64::NEG_INFINITY, f64::max),
    );
    let margin = 60.0;
    let scale = (SIZE - 2.0 * margin) / (x1 - x0).max(y1 - y0);
    let map = |p: Point2| {
        [
            margin + (p[0] - x0) * scale,
            SIZE - margin - (p[1] - y0) * scale,
        ]
    };
    let path = |points: &[Point2], close: bool| {
        let mut d = String::new();
        for (i, &p) in points.iter().enumerate() {
            let [x, y] = map(p);
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
        let [x, y] = map(centroid(&r.polygon));
        writeln!(
            svg,
            r#"<text x="{x:.2}" y="{y:.2}" font-size="20" text-anchor="middle" dominant-baseline="middle">{}</text>"#,
            r.label
        )
        .expect("String");
    }
    let [cx, cy] = map(centroid(&sub.layout));
    for (k, &p) in sub.layout.iter().enumerate() {
        let [x, y] = map(p);
        let (dx, dy) = (x - cx, y - cy);
        let l = dx.hypot(dy).max(1e-9);
        writeln!(
            svg,
            r#"<circle cx="{x:.2}" cy="{y:.2}" r="5" fill="black"/><text x="{:.2}" y="{:.2}" font-size="22" font-weight="bold" text-anchor="middle" dominant-baseline="middle">v{}</text>"#,
            x + 28.0 * dx / l,
            y + 28.0 * dy / l,
            sub.corners[k].0
        )
        .expect("String");
    }
    svg.push_str("</svg>\n");
    svg
}

//! The plane part of the model [LZT §5, Fig. 16c]: a constrained Delaunay triangulation of the
//! rectangle with p, q and the obstacle boundaries, optionally refined, with the obstacles'
//! insides removed.

use super::geometry::{bounding_box, locate, orient, Location, Point};
use super::scene::Rectangle;
use super::{BenchmarkError, ModelOptions};
use glam::DVec2;
use spade::handles::FixedVertexHandle;
use spade::{
    AngleLimit, ConstrainedDelaunayTriangulation, Point2, RefinementParameters, Triangulation,
};
use std::cmp::Ordering;

type Cdt = ConstrainedDelaunayTriangulation<Point2<f64>>;

/// The triangulated free space: vertices in the plane, counter-clockwise triangles, and each
/// obstacle's boundary as the triangulation has it.
pub(crate) struct Floor {
    pub positions: Vec<Point>,
    pub triangles: Vec<[u32; 3]>,
    pub p: u32,
    pub q: u32,
    pub rings: Vec<Ring>,
}

/// An obstacle boundary in the floor: its vertices counter-clockwise, the obstacle's corners and
/// the points refinement inserted on its edges.
pub(crate) struct Ring {
    pub vertices: Vec<u32>,
    /// Where in `vertices` each corner of the obstacle is, in corner order.
    pub corners: Vec<usize>,
}

/// Triangulates the rectangle minus the (counter-clockwise, valid) obstacles.
pub(crate) fn triangulate_floor(
    rectangle: &Rectangle,
    obstacles: &[Vec<Point>],
    p: Point,
    q: Point,
    options: &ModelOptions,
) -> Result<Floor, BenchmarkError> {
    let mut cdt = Cdt::new();
    let insert = |cdt: &mut Cdt, x: Point| {
        cdt.insert(Point2::new(x[0], x[1]))
            .map_err(|e| BenchmarkError::Triangulation(format!("point {x:?}: {e}")))
    };
    // The rectangle is a constraint too, so that refinement's parity of crossed constraints
    // marks exactly the obstacles as outer faces and leaves them unrefined.
    let mut loops = vec![rectangle.corners().to_vec()];
    loops.extend(obstacles.iter().cloned());
    let mut corner_handles = Vec::with_capacity(loops.len());
    for polygon in &loops {
        let handles = polygon
            .iter()
            .map(|&x| insert(&mut cdt, x))
            .collect::<Result<Vec<_>, _>>()?;
        for i in 0..handles.len() {
            cdt.add_constraint(handles[i], handles[(i + 1) % handles.len()]);
        }
        corner_handles.push(handles);
    }
    let p_handle = insert(&mut cdt, p)?;
    let q_handle = insert(&mut cdt, q)?;
    if options.min_angle > 0.0 || options.max_area.is_some() {
        let mut parameters = RefinementParameters::new()
            .with_angle_limit(AngleLimit::from_deg(options.min_angle))
            .exclude_outer_faces(true)
            .with_max_additional_vertices(options.max_additional_vertices);
        if let Some(area) = options.max_area {
            parameters = parameters.with_max_allowed_area(area);
        }
        if !cdt.refine(parameters).refinement_complete {
            return Err(BenchmarkError::RefinementIncomplete {
                budget: options.max_additional_vertices,
            });
        }
    }

    // Keep the faces whose centroid is outside every obstacle; a face lies on one side of each
    // obstacle boundary, since those are triangulation edges.
    let boxes: Vec<[Point; 2]> = obstacles.iter().map(|o| bounding_box(o)).collect();
    let mut used = vec![u32::MAX; cdt.num_vertices()];
    let mut positions = Vec::with_capacity(cdt.num_vertices());
    let mut triangles = Vec::with_capacity(cdt.num_inner_faces());
    for face in cdt.inner_faces() {
        let corners = face.vertices();
        let xy = corners.map(|v| [v.position().x, v.position().y]);
        let [a, b, c] = xy.map(DVec2::from);
        let centroid = (a + b + c) / 3.0;
        let in_obstacle = obstacles.iter().zip(&boxes).any(|(o, [lo, hi])| {
            DVec2::from(*lo).cmple(centroid).all()
                && centroid.cmple(DVec2::from(*hi)).all()
                && locate(o, centroid.to_array()) == Location::Inside
        });
        if in_obstacle {
            continue;
        }
        if orient(xy[0], xy[1], xy[2]) != Ordering::Greater {
            return Err(BenchmarkError::Triangulation(format!(
                "degenerate or clockwise face at {xy:?}"
            )));
        }
        triangles.push(corners.map(|v| {
            let slot = &mut used[v.fix().index()];
            if *slot == u32::MAX {
                *slot = positions.len() as u32;
                positions.push([v.position().x, v.position().y]);
            }
            *slot
        }));
    }

    let rings = corner_handles[1..]
        .iter()
        .map(|handles| ring(&cdt, handles, &used))
        .collect::<Result<Vec<_>, _>>()?;
    Ok(Floor {
        positions,
        triangles,
        p: used[p_handle.index()],
        q: used[q_handle.index()],
        rings,
    })
}

/// Walks an obstacle's boundary along constraint edges, from each corner to the next through
/// the vertices refinement inserted on that edge.
fn ring(cdt: &Cdt, corners: &[FixedVertexHandle], used: &[u32]) -> Result<Ring, BenchmarkError> {
    let lost =
        || BenchmarkError::Triangulation("an obstacle boundary is not a closed chain".into());
    let xy = |h: FixedVertexHandle| {
        let p = cdt.vertex(h).position();
        DVec2::new(p.x, p.y)
    };
    let mut vertices = Vec::new();
    let mut positions = Vec::with_capacity(corners.len());
    for (i, &corner) in corners.iter().enumerate() {
        let target = corners[(i + 1) % corners.len()];
        let direction = xy(target) - xy(corner);
        positions.push(vertices.len());
        let (mut previous, mut at) = (None, corner);
        while at != target {
            vertices.push(used[at.index()]);
            let next = cdt
                .vertex(at)
                .out_edges()
                .filter(|e| e.is_constraint_edge() && Some(e.to().fix()) != previous)
                .map(|e| e.to().fix())
                // At a corner two constraint edges leave: take the one along this edge. Inserted
                // vertices lie on the edge up to rounding, so the directions differ clearly.
                .max_by(|&a, &b| {
                    let along = |h: FixedVertexHandle| {
                        let d = xy(h) - xy(at);
                        d.dot(direction) / d.x.hypot(d.y)
                    };
                    along(a).total_cmp(&along(b))
                })
                .ok_or_else(lost)?;
            (previous, at) = (Some(at), next);
            if vertices.len() > used.len() {
                return Err(lost());
            }
        }
    }
    if vertices.contains(&u32::MAX) {
        return Err(lost());
    }
    Ok(Ring {
        vertices,
        corners: positions,
    })
}

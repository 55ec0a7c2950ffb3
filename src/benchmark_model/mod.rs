//! The benchmark test model of [LZT §5]: a surface whose geodesic between two points is known
//! exactly, so that computed geodesics can be checked against it.
//!
//! "Given a set S of disjoint polygonal obstacles in a plane", bounded by a rectangle R, the
//! Euclidean shortest path between p and q is computed from the visibility graph VG(S ∪ {p, q})
//! ([`shortest_path`]). A constrained Delaunay triangulation of R with p, q and the boundaries
//! of S, optionally refined so that "the complexity of the benchmark model can be controlled by
//! the user at will", is the floor; "at the place of each obstacle, a polygonal cylinder is
//! lifted and sewed with the planar triangulation along the obstacle's boundary". With tall
//! enough cylinders the geodesic from p to q goes around them and is the planar shortest path.
//!
//! ```
//! use exact_geodesics::benchmark_model::{BenchmarkModel, ModelOptions, Scene};
//! use exact_geodesics::{propagate, PropagateOptions, SurfacePoint};
//! let model = BenchmarkModel::build(&Scene::random(7, 3), &ModelOptions::default())?;
//! let field = propagate::<f64>(&model.mesh, &[SurfacePoint::Vertex(model.p)], &PropagateOptions::default())?;
//! let error = (field.vertex_distance(model.q) - model.ground_truth.length).abs();
//! assert!(error <= 1e-9 * model.ground_truth.length);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

mod compare;
mod error;
mod generate;
mod geometry;
mod lift;
mod scene;
mod triangulate;
mod visibility;

pub use compare::{path_deviation, PathDeviation};
pub use error::BenchmarkError;
pub use geometry::Point;
pub use scene::{Rectangle, Scene};
pub use visibility::{shortest_path, ShortestPath};

use crate::{TriMesh, VertexId};
use serde::{Deserialize, Serialize};

/// How the model is meshed.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct ModelOptions {
    /// Delaunay refinement's smallest angle in degrees (Ruppert), at most 34; 0 refines by
    /// area only, or not at all without `max_area`.
    pub min_angle: f64,
    /// Largest area of a floor triangle after refinement.
    pub max_area: Option<f64>,
    /// Rows of quads in each cylinder wall: at least 1, and at most 2^22 wall triangles in all.
    pub wall_rows: usize,
    /// Most vertices refinement may add before giving up.
    pub max_additional_vertices: usize,
}

impl Default for ModelOptions {
    fn default() -> Self {
        ModelOptions {
            min_angle: 20.0,
            max_area: None,
            wall_rows: 1,
            max_additional_vertices: 10_000_000,
        }
    }
}

impl ModelOptions {
    fn check(&self) -> Result<(), BenchmarkError> {
        let invalid = |name, reason: &str| {
            Err(BenchmarkError::InvalidOption {
                name,
                reason: reason.to_owned(),
            })
        };
        if !(0.0..=34.0).contains(&self.min_angle) {
            return invalid("min_angle", "must be in [0, 34] degrees");
        }
        if self.max_area.is_some_and(|a| !(a.is_finite() && a > 0.0)) {
            return invalid("max_area", "must be a positive number");
        }
        if self.wall_rows == 0 {
            return invalid("wall_rows", "must be at least 1");
        }
        Ok(())
    }
}

/// A benchmark model: the lifted mesh, its vertices p and q, and the exact geodesic between them.
#[derive(Clone, Debug)]
pub struct BenchmarkModel {
    /// The scene it was built from.
    pub scene: Scene,
    /// The surface: floor, cylinder walls and caps; consistently oriented and manifold, with
    /// the rectangle as its only boundary.
    pub mesh: TriMesh,
    /// The mesh vertex at p.
    pub p: VertexId,
    /// The mesh vertex at q.
    pub q: VertexId,
    /// The shortest path from p to q in the plane, which is the geodesic on the mesh.
    pub ground_truth: ShortestPath,
    /// The height of the cylinders.
    pub wall_height: f64,
    /// The options it was built with.
    pub options: ModelOptions,
}

impl BenchmarkModel {
    /// Builds the model of a scene [LZT §5, Fig. 16].
    ///
    /// The cylinders are as tall as the ground-truth length L, which is enough: a path on the
    /// surface is at least as long as its projection to the plane. A path that stays on the
    /// floor and walls projects into the closure of the free space, so it is at least L long,
    /// and equal to L only if it stays on the floor (any climb adds length). A path that reaches
    /// a cap climbs the height and comes down again, so it is at least 2L long. Hence the
    /// geodesic from p to q is the planar shortest path.
    ///
    /// # Errors
    /// Scene errors of [`Scene::validate`], [`BenchmarkError::InvalidOption`], and
    /// [`BenchmarkError::RefinementIncomplete`] when refinement exceeds its vertex budget.
    pub fn build(scene: &Scene, options: &ModelOptions) -> Result<BenchmarkModel, BenchmarkError> {
        options.check()?;
        let obstacles = scene.counter_clockwise_obstacles()?;
        let ground_truth = visibility::shortest_path_among(&obstacles, scene.p, scene.q);
        let floor = triangulate::triangulate_floor(
            &scene.rectangle,
            &obstacles,
            scene.p,
            scene.q,
            options,
        )?;
        let wall_height = ground_truth.length;
        let mesh = lift::lift(&floor, &obstacles, wall_height, options.wall_rows)?;
        Ok(BenchmarkModel {
            scene: scene.clone(),
            mesh,
            p: VertexId(floor.p),
            q: VertexId(floor.q),
            ground_truth,
            wall_height,
            options: options.clone(),
        })
    }

    /// What to store next to the mesh file `mesh` so that the model can be checked later.
    pub fn description(&self, mesh: &str, seed: Option<u64>) -> ModelDescription {
        ModelDescription {
            mesh: mesh.to_owned(),
            p_vertex: self.p.0,
            q_vertex: self.q.0,
            ground_truth: self.ground_truth.clone(),
            wall_height: self.wall_height,
            vertex_count: self.mesh.vertex_count(),
            face_count: self.mesh.face_count(),
            seed,
            options: self.options.clone(),
            scene: self.scene.clone(),
        }
    }
}

/// A benchmark model as stored in JSON next to its mesh file.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct ModelDescription {
    /// The mesh file, relative to the JSON file.
    pub mesh: String,
    /// The vertex at p, 0-based.
    pub p_vertex: u32,
    /// The vertex at q, 0-based.
    pub q_vertex: u32,
    /// The exact geodesic from p to q: its length and its corners in the plane z = 0.
    pub ground_truth: ShortestPath,
    /// The height of the cylinders.
    pub wall_height: f64,
    /// Vertices of the mesh.
    pub vertex_count: usize,
    /// Faces of the mesh.
    pub face_count: usize,
    /// The seed of a generated scene.
    pub seed: Option<u64>,
    /// How the mesh was built.
    pub options: ModelOptions,
    /// The scene.
    pub scene: Scene,
}

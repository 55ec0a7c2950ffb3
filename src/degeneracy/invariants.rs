//! Invariants every geodesic distance field must satisfy, whatever the mesh: checked on one
//! source pair `(a, b)` by propagating from both, in the backend under test and in a reference
//! backend.
//!
//! - `d(a, a) = 0`;
//! - `|a - v| <= d(a, v) <= ` the shortest path along mesh edges, for every vertex `v` the
//!   edges reach (exactly in the exact backend, within [`Tolerances::bounds`] otherwise);
//! - vertices no edge path reaches are at `f64::INFINITY` with no nearest source, and those it
//!   reaches are finite;
//! - `d(a, b) = d(b, a)`;
//! - the back-trace [LZT §2] of a reachable point succeeds, steps from face to face, ends at
//!   the source, and is as long as the distance; that of an unreachable point is refused;
//! - the backend under test and the reference agree on every vertex distance.
//!
//! Violations are values ([`Violation`]), one per kind and check, counting how often the
//! invariant failed and describing the first failure.

use super::measure::{distance_in, EdgePaths};
use crate::mesh::shapes::SplitMix64;
use crate::mesh::{FaceId, SourceId, TriMesh, VertexId};
use crate::mmp::{propagate, GeodesicField, PropagateOptions, SurfacePoint, TraceError};
use crate::scalar::{Scalar, Sign};
use serde::Serialize;
use std::cmp::Ordering;

/// Which invariant a [`Violation`] breaks.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum ViolationKind {
    /// The source's own distance is not zero.
    SourceNotZero,
    /// A distance is shorter than the straight line in space.
    BelowStraightLine,
    /// A distance is longer than the shortest path along mesh edges.
    AboveEdgePath,
    /// A vertex the edges reach is at infinity or has no nearest source.
    ReachableInfinite,
    /// A vertex no edge path reaches has a finite distance, a nearest source or a path.
    UnreachableFinite,
    /// `d(a, b)` and `d(b, a)` differ.
    Asymmetric,
    /// The back-trace of a reachable point failed.
    TraceFailed,
    /// Two consecutive points of a traced path share no face.
    TraceDisconnected,
    /// A traced path does not end at the source.
    TraceWrongEnd,
    /// A traced path's length differs from the distance.
    TraceLength,
    /// The backend under test and the reference backend give different vertex distances.
    BackendsDisagree,
    /// Propagation returned an error.
    Error,
    /// Propagation or a query panicked.
    Panic,
}

/// One broken invariant in one check.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Violation {
    /// The invariant.
    pub kind: ViolationKind,
    /// The first failure, with its vertices and values.
    pub detail: String,
    /// How many times the invariant failed in this check (vertices, paths, ...).
    pub occurrences: usize,
}

/// Relative tolerances of the checks, one per invariant that needs one.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Tolerances {
    /// Of the straight-line and edge-path bounds; zero compares exactly, in the backend's own
    /// arithmetic.
    pub bounds: f64,
    /// Of `d(a, b) = d(b, a)`.
    pub symmetry: f64,
    /// Of a traced path's length against the distance, beyond what its `f64` points can
    /// resolve (an ulp of their coordinates each).
    pub trace_length: f64,
    /// Of a vertex distance against the reference backend's.
    pub agreement: f64,
}

impl Tolerances {
    /// For the exact backend: bounds hold exactly.
    pub const EXACT: Tolerances = Tolerances {
        bounds: 0.0,
        symmetry: 1e-9,
        trace_length: 1e-9,
        agreement: 1e-9,
    };

    /// For backends with `f64` values: bounds within `1e-12`, the rest within `1e-9`.
    pub const FLOAT: Tolerances = Tolerances {
        bounds: 1e-12,
        symmetry: 1e-9,
        trace_length: 1e-9,
        agreement: 1e-9,
    };
}

/// What [`check_invariants`] found.
#[derive(Clone, Debug, Default, PartialEq, Serialize)]
pub struct InvariantReport {
    /// The broken invariants, in the order first found.
    pub violations: Vec<Violation>,
    /// Decisions the backend under test could not certify (only the exact backend has any);
    /// not a violation: they are reported by the engine, never passed off as exact.
    pub uncertified_decisions: u64,
}

/// Whether `x >= bound` within `rel` (relative to `bound`), compared in `S`: with `rel = 0`
/// the comparison is exact in an exact backend.
///
/// # Example
/// ```
/// use exact_geodesics::degeneracy::at_least;
/// assert!(at_least(&(1.0 - 1e-13), &1.0, 1e-12));
/// assert!(!at_least(&(1.0 - 1e-11), &1.0, 1e-12));
/// ```
pub fn at_least<S: Scalar>(x: &S, bound: &S, rel: f64) -> bool {
    x.compare(&(bound.clone() * S::from_f64(1.0 - rel))) != Ordering::Less
}

/// Whether `x <= bound` within `rel` (relative to `bound`), compared in `S`.
///
/// # Example
/// ```
/// use exact_geodesics::degeneracy::at_most;
/// assert!(at_most(&(1.0 + 1e-13), &1.0, 1e-12));
/// assert!(!at_most(&f64::NAN, &1.0, 1e-12));
/// ```
pub fn at_most<S: Scalar>(x: &S, bound: &S, rel: f64) -> bool {
    x.compare(&(bound.clone() * S::from_f64(1.0 + rel))) != Ordering::Greater
}

/// Whether `x` and `y` agree within `rel` of the larger magnitude; an infinity agrees only
/// with itself, NaN with nothing.
///
/// # Example
/// ```
/// use exact_geodesics::degeneracy::relatively_close;
/// assert!(relatively_close(1.0, 1.0 + 1e-10, 1e-9));
/// assert!(relatively_close(f64::INFINITY, f64::INFINITY, 1e-9));
/// assert!(!relatively_close(0.0, 1e-300, 1e-9));
/// ```
pub fn relatively_close(x: f64, y: f64, rel: f64) -> bool {
    x == y || (x.is_finite() && y.is_finite() && (x - y).abs() <= rel * x.abs().max(y.abs()))
}

/// Violations being collected: one per kind, counting repeats.
#[derive(Default)]
struct Findings(Vec<Violation>);

impl Findings {
    fn add(&mut self, kind: ViolationKind, detail: impl FnOnce() -> String) {
        match self.0.iter_mut().find(|v| v.kind == kind) {
            Some(v) => v.occurrences += 1,
            None => self.0.push(Violation {
                kind,
                detail: detail(),
                occurrences: 1,
            }),
        }
    }
}

/// One propagation in the backend under test and its reference.
struct Run<'m, S: Scalar, R: Scalar> {
    source: VertexId,
    field: GeodesicField<'m, S>,
    reference: GeodesicField<'m, R>,
    paths: EdgePaths,
}

/// Checks every invariant of the module docs for sources `a` and `b` on `mesh`, in backend `S`
/// against reference backend `R`; `probe_seed` chooses the extra points whose paths are traced
/// (three vertices and one point inside a face).
///
/// Panics of the engine are not caught here (see [`run_case`](super::run_case)).
///
/// # Example
/// ```
/// use exact_geodesics::degeneracy::{check_invariants, Tolerances};
/// use exact_geodesics::{mesh::shapes, scalar::Adaptive, VertexId};
/// let mesh = shapes::cube();
/// let report = check_invariants::<f64, Adaptive>(&mesh, VertexId(0), VertexId(6), 1, &Tolerances::FLOAT);
/// assert!(report.violations.is_empty(), "{:?}", report.violations);
/// ```
pub fn check_invariants<S: Scalar, R: Scalar>(
    mesh: &TriMesh,
    a: VertexId,
    b: VertexId,
    probe_seed: u64,
    tolerances: &Tolerances,
) -> InvariantReport {
    let mut findings = Findings::default();
    let mut runs: Vec<Run<'_, S, R>> = Vec::with_capacity(2);
    for source in [a, b] {
        let sources = [SurfacePoint::Vertex(source)];
        let options = PropagateOptions::default();
        match (
            propagate::<S>(mesh, &sources, &options),
            propagate::<R>(mesh, &sources, &options),
        ) {
            (Ok(field), Ok(reference)) => runs.push(Run {
                source,
                field,
                reference,
                paths: EdgePaths::new(mesh, source),
            }),
            (Err(e), _) | (_, Err(e)) => {
                findings.add(ViolationKind::Error, || format!("from {source}: {e}"));
            }
        }
    }
    let uncertified_decisions = runs
        .iter()
        .map(|run| run.field.stats().backend.uncertified)
        .sum();
    let probes = probes(mesh, probe_seed);
    for run in &runs {
        check_vertices(run, tolerances, &mut findings);
        let other = if run.source == a { b } else { a };
        let targets = std::iter::once(SurfacePoint::Vertex(other)).chain(probes.iter().copied());
        for target in targets {
            check_trace(run, &target, tolerances, &mut findings);
        }
    }
    if let [from_a, from_b] = &runs[..] {
        let (ab, ba) = (
            from_a.field.vertex_distance(b),
            from_b.field.vertex_distance(a),
        );
        if !relatively_close(ab, ba, tolerances.symmetry) {
            findings.add(ViolationKind::Asymmetric, || {
                format!("d({a}, {b}) = {ab:e} but d({b}, {a}) = {ba:e}")
            });
        }
    }
    InvariantReport {
        violations: findings.0,
        uncertified_decisions,
    }
}

/// Three random vertices and a random point inside a random face.
fn probes(mesh: &TriMesh, seed: u64) -> Vec<SurfacePoint> {
    let mut rng = SplitMix64::new(seed);
    let mut below = |n: usize| (rng.next_u64() % n.max(1) as u64) as u32;
    let mut out: Vec<SurfacePoint> = (0..3)
        .map(|_| SurfacePoint::Vertex(VertexId(below(mesh.vertex_count()))))
        .collect();
    if mesh.face_count() > 0 {
        let face = FaceId(below(mesh.face_count()));
        let weights = [0; 3].map(|_| 1.0 + f64::from(below(1 << 20)));
        let sum: f64 = weights.iter().sum();
        out.push(SurfacePoint::Face {
            face,
            bary: weights.map(|w| w / sum),
        });
    }
    out
}

/// The source's distance, the bounds, reachability and agreement, at every vertex.
fn check_vertices<S: Scalar, R: Scalar>(
    run: &Run<'_, S, R>,
    tolerances: &Tolerances,
    findings: &mut Findings,
) {
    let (a, field) = (run.source, &run.field);
    let mesh = field.mesh();
    if field
        .vertex_distance_exact(a)
        .is_none_or(|d| d.sign() != Sign::Zero)
    {
        findings.add(ViolationKind::SourceNotZero, || {
            format!("d({a}, {a}) = {:e}", field.vertex_distance(a))
        });
    }
    for v in (0..mesh.vertex_count()).map(|v| VertexId(v as u32)) {
        let d = field.vertex_distance(v);
        let expected = run.reference.vertex_distance(v);
        if !relatively_close(d, expected, tolerances.agreement) {
            findings.add(ViolationKind::BackendsDisagree, || {
                format!("from {a}: d({v}) = {d:e} but the reference gives {expected:e}")
            });
        }
        if !run.paths.reaches(v) {
            if d != f64::INFINITY || field.nearest_source(v).is_some() {
                findings.add(ViolationKind::UnreachableFinite, || {
                    format!("from {a}: {v} shares no edge path with the source, d = {d:e}")
                });
            }
            continue;
        }
        // The distance in the backend's own number type, for comparisons without rounding.
        let own = field.vertex_distance_exact(v);
        let Some(own) = own.filter(|_| d.is_finite() && field.nearest_source(v).is_some()) else {
            findings.add(ViolationKind::ReachableInfinite, || {
                format!("from {a}: {v} is joined to the source by edges, d = {d:e}")
            });
            continue;
        };
        let p = |v: VertexId| mesh.position(v);
        let straight = distance_in::<S>(p(a), p(v));
        if !at_least(&own, &straight, tolerances.bounds) {
            findings.add(ViolationKind::BelowStraightLine, || {
                format!(
                    "from {a}: d({v}) = {d:e} < straight line {:e}",
                    straight.to_f64()
                )
            });
        }
        let along = run.paths.length_in::<S>(mesh, v).expect("reached");
        if !at_most(&own, &along, tolerances.bounds) {
            findings.add(ViolationKind::AboveEdgePath, || {
                format!("from {a}: d({v}) = {d:e} > edge path {:e}", along.to_f64())
            });
        }
    }
}

/// The back-trace of `target` in the field of `run`.
fn check_trace<S: Scalar, R: Scalar>(
    run: &Run<'_, S, R>,
    target: &SurfacePoint,
    tolerances: &Tolerances,
    findings: &mut Findings,
) {
    let (a, field) = (run.source, &run.field);
    let mesh = field.mesh();
    let reachable = match *target {
        SurfacePoint::Vertex(v) => run.paths.reaches(v),
        SurfacePoint::Face { face, .. } => run.paths.reaches(mesh.face(face)[0]),
        SurfacePoint::Edge { edge, .. } => run.paths.reaches(mesh.edge(edge).vertices[0]),
    };
    let distance = field.distance_at(target).unwrap_or(f64::NAN);
    let traced = field.trace_back(target);
    if !reachable {
        if !matches!(traced, Err(TraceError::Unreachable)) {
            findings.add(ViolationKind::UnreachableFinite, || {
                format!("from {a}: the trace of unreachable {target:?} gave {traced:?}")
            });
        }
        return;
    }
    if !distance.is_finite() {
        return; // Reported by the vertex checks, or by the agreement of the backends.
    }
    let path = match traced {
        Ok(path) => path,
        Err(e) => {
            findings.add(ViolationKind::TraceFailed, || {
                format!("from {a} to {target:?} (d = {distance:e}): {e}")
            });
            return;
        }
    };
    if let Some(gap) = path.simplices.windows(2).position(|w| {
        !w[0]
            .faces(mesh)
            .iter()
            .any(|f| w[1].faces(mesh).contains(f))
    }) {
        findings.add(ViolationKind::TraceDisconnected, || {
            format!(
                "from {a} to {target:?}: step {gap} from {:?} to {:?} crosses no face",
                path.simplices[gap],
                path.simplices[gap + 1]
            )
        });
    }
    if path.simplices.last() != Some(&SurfacePoint::Vertex(a)) || path.source != SourceId(0) {
        findings.add(ViolationKind::TraceWrongEnd, || {
            format!(
                "from {a} to {target:?}: the path ends at {:?}",
                path.simplices.last()
            )
        });
    }
    let length = path.length();
    let as_long = path.is_as_long_as_its_distance(tolerances.trace_length);
    if !as_long {
        findings.add(ViolationKind::TraceLength, || {
            format!(
                "from {a} to {target:?}: path length {length:e} but d = {distance:e} ({} points)",
                path.points.len()
            )
        });
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::shapes;
    use crate::scalar::{Adaptive, Field, Real, Ring};
    use glam::DVec3;

    #[test]
    fn bounds_refuse_a_distance_just_outside_them() {
        assert!(at_least(&1.0, &1.0, 0.0));
        assert!(!at_least(&(1.0 - 1e-11), &1.0, 1e-12));
        assert!(!at_most(&(1.0 + 1e-11), &1.0, 1e-12));
        assert!(!at_most(&f64::INFINITY, &1.0, 1e-12));
    }

    #[test]
    fn exact_bounds_refuse_a_distance_one_part_in_10_30_too_short() {
        let two = Real::from_f64(2.0);
        let root2 = two.sqrt();
        let short = root2.clone() - Real::from_f64(1e-30);
        assert!(at_least(&root2, &root2, 0.0));
        assert!(!at_least(&short, &root2, 0.0));
        assert!(at_most(&short, &root2, 0.0));
    }

    #[test]
    fn relative_closeness_is_symmetric_and_strict_at_zero() {
        assert!(relatively_close(2.0, 2.0 + 1e-9, 1e-9));
        assert!(!relatively_close(2.0, 2.0 + 1e-8, 1e-9));
        assert!(!relatively_close(0.0, f64::MIN_POSITIVE, 1e-9));
        assert!(!relatively_close(f64::NAN, f64::NAN, 1e-9));
        assert!(!relatively_close(1.0, f64::INFINITY, 1e-9));
    }

    #[test]
    fn findings_count_repeats_of_one_kind_once() {
        let mut findings = Findings::default();
        findings.add(ViolationKind::Asymmetric, || "first".into());
        findings.add(ViolationKind::Asymmetric, || "second".into());
        findings.add(ViolationKind::TraceLength, || "other".into());
        assert_eq!(findings.0.len(), 2);
        assert_eq!(findings.0[0].occurrences, 2);
        assert_eq!(findings.0[0].detail, "first");
    }

    #[test]
    fn unreachable_vertices_at_infinity_break_no_invariant() {
        let mut positions = shapes::tetrahedron().positions().to_vec();
        let mut faces = shapes::tetrahedron().faces().to_vec();
        positions.extend(positions.clone().iter().map(|&p| p + 3.0 * DVec3::X));
        faces.extend(
            shapes::tetrahedron()
                .faces()
                .iter()
                .map(|f| f.map(|v| v + 4)),
        );
        positions.push(DVec3::splat(9.0));
        let mesh = TriMesh::new(positions, faces).expect("two tetrahedra and a loose vertex");
        for (a, b) in [(0, 5), (8, 1), (2, 3)] {
            let report = check_invariants::<f64, Adaptive>(
                &mesh,
                VertexId(a),
                VertexId(b),
                5,
                &Tolerances::FLOAT,
            );
            assert!(report.violations.is_empty(), "{:?}", report.violations);
        }
    }

    #[test]
    fn a_clean_mesh_breaks_no_invariant_in_any_backend() {
        let mesh = shapes::l_shape(2);
        let (a, b) = (VertexId(0), VertexId(mesh.vertex_count() as u32 - 1));
        let f = check_invariants::<f64, Adaptive>(&mesh, a, b, 3, &Tolerances::FLOAT);
        assert!(f.violations.is_empty(), "{:?}", f.violations);
        let e = check_invariants::<Real, f64>(&mesh, a, b, 3, &Tolerances::EXACT);
        assert!(e.violations.is_empty(), "{:?}", e.violations);
    }
}

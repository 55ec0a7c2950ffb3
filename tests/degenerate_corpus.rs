//! The degenerate-mesh corpus (issue 10: no silently wrong answer on degenerate input, in any
//! backend): every invariant of `degeneracy::check_invariants` on random cases of every kind of
//! degeneracy, in each backend, and each failure once found kept as a named case. The meshes of
//! the issue itself are in `degenerate_regressions.rs`, with their closed-form answers.

mod common;

use common::strategies::degenerate_case;
use exact_geodesics::degeneracy::{
    run_case, run_case_of_size, Backend, CaseReport, DegenerateKind, MeshSize,
};
use proptest::prelude::*;
use proptest::test_runner::RngSeed;

fn describe(report: &CaseReport) -> String {
    serde_json::to_string_pretty(report).expect("JSON of plain values")
}

fn assert_keeps_invariants(backend: Backend, kind: DegenerateKind, seed: u64) {
    let report = run_case(backend, kind, seed);
    assert!(report.violations.is_empty(), "{}", describe(&report));
}

/// The property test of one backend over `$cases` random cases.
macro_rules! corpus_suite {
    ($module:ident, $backend:expr, $cases:expr) => {
        mod $module {
            use super::*;

            proptest! {
                #![proptest_config(ProptestConfig {
                    cases: $cases,
                    // The same cases on every run, so that CI is repeatable; the `degeneracy`
                    // command runs fresh ones.
                    rng_seed: RngSeed::Fixed(10),
                    // A smaller seed is another mesh, not a simpler one: nothing to shrink.
                    max_shrink_iters: 0,
                    ..ProptestConfig::default()
                })]

                #[test]
                fn every_invariant_holds_on_degenerate_meshes((kind, seed) in degenerate_case()) {
                    let report = run_case($backend, kind, seed);
                    prop_assert!(report.violations.is_empty(), "{}", describe(&report));
                }
            }
        }
    };
}

corpus_suite!(float, Backend::F64, 1000);
corpus_suite!(adaptive, Backend::Adaptive, 1000);
corpus_suite!(exact, Backend::Exact, 100);

/// Cases the corpus once failed, each kept by name: `name: backend, kind, seed;` (rebuilt by
/// `run_case`, which also picks the same sources and probes). The name says what broke first.
macro_rules! regressions {
    ($($name:ident: $backend:ident, $kind:ident, $seed:literal;)*) => {$(
        #[test]
        fn $name() {
            assert_keeps_invariants(Backend::$backend, DegenerateKind::$kind, $seed);
        }
    )*};
}

regressions! {
    // Every backend.
    f64_coincident_vertices_15781000307351985879_distances_stay_below_edge_paths:
        F64, CoincidentVertices, 15781000307351985879;
    f64_coincident_vertices_2606146612446147118_coincident_copy_is_at_distance_zero:
        F64, CoincidentVertices, 2606146612446147118;
    f64_zero_area_faces_14038607207048404726_t_junction_source_stays_below_edge_paths:
        F64, ZeroAreaFaces, 14038607207048404726;
    f64_pyramid_8898481838737274279_trace_finds_its_way:
        F64, Pyramid, 8898481838737274279;
    f64_scaled_9018883062403043925_reachable_vertices_are_finite_at_1e82:
        F64, Scaled, 9018883062403043925;
    f64_scaled_4504985774214511021_distances_stay_above_straight_lines_at_1e_134:
        F64, Scaled, 4504985774214511021;
    f64_scaled_14181954673717202388_trace_reaches_a_reached_vertex_at_1e160:
        F64, Scaled, 14181954673717202388;
    // The adaptive backend.
    adaptive_flat_grid_17146877070824583018_agrees_with_f64:
        Adaptive, FlatGrid, 17146877070824583018;
    adaptive_flat_grid_6386018607373095707_reaches_every_vertex:
        Adaptive, FlatGrid, 6386018607373095707;
    adaptive_flat_fan_385107482673595689_agrees_with_f64:
        Adaptive, FlatFan, 385107482673595689;
    adaptive_pyramid_7593930394342328515_agrees_with_f64:
        Adaptive, Pyramid, 7593930394342328515;
    adaptive_coincident_vertices_3964739607747407278_reaches_every_vertex:
        Adaptive, CoincidentVertices, 3964739607747407278;
}

/// Cases the exact backend once failed on meshes of at most 20 faces (its size then).
macro_rules! tiny_regressions {
    ($($name:ident: $kind:ident, $seed:literal;)*) => {$(
        #[test]
        fn $name() {
            let report =
                run_case_of_size(Backend::Exact, DegenerateKind::$kind, $seed, MeshSize::Tiny);
            assert!(report.violations.is_empty(), "{}", describe(&report));
        }
    )*};
}

tiny_regressions! {
    exact_coincident_vertices_16294208416658607535_distances_stay_below_edge_paths:
        CoincidentVertices, 16294208416658607535;
    exact_coincident_vertices_7313543279846440201_trace_steps_from_face_to_face:
        CoincidentVertices, 7313543279846440201;
    exact_zero_area_faces_16079692208719082326_distances_stay_below_edge_paths:
        ZeroAreaFaces, 16079692208719082326;
    exact_zero_area_faces_6192573367858229616_trace_steps_from_face_to_face:
        ZeroAreaFaces, 6192573367858229616;
}

/// Cases whose float results were wrong beyond any tolerance (rays through an edge 1e-12 the
/// size of its neighbours): their edge lengths span more than `ValidationReport::WIDE_SPAN`,
/// which the mesh report warns of, and they keep every invariant.
macro_rules! beyond_float_range {
    ($($name:ident: $kind:ident, $seed:literal;)*) => {$(
        #[test]
        fn $name() {
            let report = run_case(Backend::F64, DegenerateKind::$kind, $seed);
            assert!(report.beyond_float_range, "{}", describe(&report));
            assert!(report.violations.is_empty(), "{}", describe(&report));
        }
    )*};
}

beyond_float_range! {
    f64_slivers_7310232572051094699_is_beyond_float_range_and_keeps_reachability:
        Slivers, 7310232572051094699;
    f64_slivers_1961750202426094747_needle_is_beyond_float_range_and_keeps_reachability:
        Slivers, 1961750202426094747;
    f64_mixed_magnitudes_17189161910051005891_is_beyond_float_range_and_keeps_reachability:
        MixedMagnitudes, 17189161910051005891;
    f64_mixed_magnitudes_3916747395894956443_is_beyond_float_range_and_keeps_reachability:
        MixedMagnitudes, 3916747395894956443;
}

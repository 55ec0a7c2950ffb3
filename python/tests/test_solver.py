"""The solver and its field: distances, sources of every kind, paths on the surface, wedges,
stats, backends, index dtypes, and the GIL released while propagating."""

from __future__ import annotations

import math
import threading
import time

import numpy as np
import pytest

import exact_geodesics as eg
from conftest import faces_of, position_of

INDEX_DTYPES = [np.int8, np.int16, np.int32, np.int64, np.uint8, np.uint16, np.uint32, np.uint64]


def test_cube_opposite_corner_is_at_sqrt5():
    vertices, triangles = eg.generate_mesh("cube")
    field = eg.GeodesicSolver(vertices, triangles).propagate(0)
    assert field.distances[0] == 0.0
    assert math.isclose(field.distances.max(), math.sqrt(5), rel_tol=1e-12)


@pytest.mark.parametrize("dtype", INDEX_DTYPES, ids=lambda d: np.dtype(d).name)
def test_indices_of_any_integer_dtype_give_the_same_distances(dtype):
    vertices, triangles = eg.generate_mesh("icosphere:1")  # 42 vertices: even int8 holds them
    sources, targets = [3, 37], [0, 5, 20, 41]
    expected = eg.compute_gdist(vertices, triangles, sources, targets)
    got = eg.compute_gdist(
        vertices,
        triangles.astype(dtype),
        np.array(sources, dtype=dtype),
        np.array(targets, dtype=dtype),
    )
    np.testing.assert_array_equal(got, expected)
    solver = eg.GeodesicSolver(vertices, triangles.astype(dtype))
    field = solver.propagate(np.array(sources, dtype=dtype))
    np.testing.assert_array_equal(field.distances[targets], expected)
    matrix = solver.distance_matrix(np.array([3], dtype=dtype), np.array(targets, dtype=dtype))
    assert matrix.shape == (1, 4)
    assert field.path(dtype(20)).source in (0, 1)


def test_unreachable_is_inf_and_has_no_nearest_source(two_components):
    vertices, triangles = two_components
    field = eg.GeodesicSolver(vertices, triangles).propagate([1])
    assert np.all(np.isfinite(field.distances[:3]))
    assert np.all(np.isinf(field.distances[3:]))
    np.testing.assert_array_equal(field.nearest_source, [0, 0, 0, -1, -1, -1, -1])
    assert np.isinf(eg.compute_gdist(vertices, triangles, [0], [6]))[0]


def test_max_distance_makes_farther_vertices_inf(icosphere):
    vertices, triangles = icosphere
    full = eg.GeodesicSolver(vertices, triangles).propagate(0).distances
    limited = eg.compute_gdist(vertices, triangles, [0], max_distance=1.0)
    near = full <= 1.0
    np.testing.assert_allclose(limited[near], full[near], rtol=1e-12)
    assert np.all(np.isinf(limited[full > 1.0 + 1e-9]))


def sources_of_every_kind(solver):
    a, b = (int(x) for x in solver.edges[10])
    return [4, ("edge", a, b, 0.25), ("face", 7, (1.0, 2.0, 1.0)), ("vertex", 9)]


def test_sources_of_every_kind_are_accepted(icosphere):
    vertices, triangles = icosphere
    solver = eg.GeodesicSolver(vertices, triangles)
    sources = sources_of_every_kind(solver)
    field = solver.propagate(sources)
    # The library's canonical names: the edge by its index, barycentrics divided by their sum.
    assert field.sources == [
        ("vertex", 4, ()),
        ("edge", 10, (0.25,)),
        ("face", 7, (0.25, 0.5, 0.25)),
        ("vertex", 9, ()),
    ]
    assert field.distance_at(4) == field.distance_at(("vertex", 9)) == 0.0
    nearest = field.nearest_source
    assert nearest[4] == 0 and nearest[9] == 3
    assert set(np.unique(nearest)) == {0, 1, 2, 3}
    assert field.distance_at(("face", 7, (0.2501, 0.5, 0.2499))) < 1e-3


def test_distance_at_an_edge_or_face_source_is_zero(icosphere):
    vertices, triangles = icosphere
    solver = eg.GeodesicSolver(vertices, triangles)
    sources = sources_of_every_kind(solver)
    field = solver.propagate(sources)
    assert [field.distance_at(p) for p in sources] == [0.0] * 4


def test_distance_next_to_an_edge_source_is_small(icosphere):
    vertices, triangles = icosphere
    solver = eg.GeodesicSolver(vertices, triangles)
    field = solver.propagate(sources_of_every_kind(solver))
    assert field.distance_at(("edge", 10, (0.2501,))) < 1e-3


def test_distance_at_a_vertex_is_its_distance(icosphere):
    vertices, triangles = icosphere
    field = eg.GeodesicSolver(vertices, triangles).propagate(0)
    for v in (0, 17, 161):
        assert field.distance_at(v) == field.distances[v]
        assert field.distance_at(np.int64(v)) == field.distances[v]


@pytest.mark.parametrize(
    "target", [120, ("face", 200, (0.2, 0.3, 0.5)), ("edge", 300, (0.6,))], ids=str
)
def test_path_runs_on_the_surface_from_target_to_source(icosphere, target):
    vertices, triangles = icosphere
    solver = eg.GeodesicSolver(vertices, triangles)
    field = solver.propagate([("face", 3, (1, 1, 1)), 60])
    path = field.path(target)
    assert path.points.shape == (len(path), 3)
    # Every point is where its simplex says, on the mesh.
    for point, simplex in zip(path.points, path.simplices):
        np.testing.assert_allclose(point, position_of(solver, simplex), atol=1e-12)
    # Each segment lies in one face: consecutive simplices share a face.
    for here, there in zip(path.simplices, path.simplices[1:]):
        assert faces_of(solver, here) & faces_of(solver, there), (here, there)
    # From the target to the source, as long as the distance.
    np.testing.assert_allclose(path.points[0], position_of(solver, eg_simplex(solver, target)))
    assert path.simplices[-1] == field.sources[path.source]
    assert path.distance == pytest.approx(field.distance_at(target), rel=1e-12)
    assert path.length == pytest.approx(path.distance, rel=1e-9)
    assert path.length == pytest.approx(
        np.linalg.norm(np.diff(path.points, axis=0), axis=1).sum(), rel=1e-12
    )


def eg_simplex(solver, point):
    """A test point as ``(kind, index, parameters)``."""
    if isinstance(point, int):
        return ("vertex", point, ())
    kind, index, parameters = point
    if kind == "face":
        parameters = tuple(np.asarray(parameters) / np.sum(parameters))
    return (kind, index, parameters)


def test_wedges_tile_their_edge(icosphere):
    vertices, triangles = icosphere
    solver = eg.GeodesicSolver(vertices, triangles)
    field = solver.propagate(0)
    a, b = (int(x) for x in solver.edges[100])
    wedges = field.wedges(100)
    assert wedges == field.wedges((a, b)) == field.wedges((b, a))
    length = np.linalg.norm(vertices[a] - vertices[b])
    assert wedges and wedges[0]["b0"] == pytest.approx(0.0, abs=1e-12)
    assert wedges[-1]["b1"] == pytest.approx(length, rel=1e-12)
    for w, after in zip(wedges, wedges[1:]):
        assert w["b1"] == pytest.approx(after["b0"], abs=1e-12)
    for w in wedges:
        assert set(w) == {
            "b0", "b1", "d0", "d1", "sigma", "tau", "source_x", "source_y", "pseudo_source",
            "source",
        }
        assert w["tau"] in (0, 1) and w["source"] == 0
        assert w["pseudo_source"][0] in ("source", "vertex")
    # Definition 1: the distance at an end of the range is sigma plus d0 (or d1) there.
    distances = field.distances
    assert wedges[0]["sigma"] + wedges[0]["d0"] == pytest.approx(distances[a], rel=1e-9)
    assert wedges[-1]["sigma"] + wedges[-1]["d1"] == pytest.approx(distances[b], rel=1e-9)


def test_stats_is_a_dict_of_counters(icosphere):
    vertices, triangles = icosphere
    stats = eg.GeodesicSolver(vertices, triangles).propagate(0).stats()
    assert stats["wedges_created"] >= stats["wedges_propagated"] > 0
    assert set(stats["eq2"]) == {"none", "one", "two", "infinite"}
    assert stats["propagation_seconds"] >= 0
    assert stats["backend"]["uncertified"] == 0


def test_backends_agree(icosphere):
    vertices, triangles = eg.generate_mesh("icosphere:1")
    fields = {
        b: eg.GeodesicSolver(vertices, triangles, backend=b).propagate([0, 30])
        for b in ("f64", "adaptive", "exact")
    }
    reference = fields["f64"].distances
    for backend, field in fields.items():
        assert field.backend == backend
        np.testing.assert_allclose(field.distances, reference, rtol=1e-9)


def fold():
    """Two unit squares folded along their shared edge by a height of 7e-46 at one corner
    (tests/exact_certified.rs, `FOLD`): signs that need more than 128 bits."""
    vertices = np.array(
        [[0, 0, 0], [1, 0, 0], [0, 1, 0], [1, 1, 7.006492321624085e-46], [2, 0, 0], [2, 1, 0]],
        dtype=np.float64,
    )
    return vertices, np.array([[0, 1, 3], [0, 3, 2], [1, 4, 5], [1, 5, 3]])


def test_exact_backend_reports_whether_it_certified_every_decision():
    # A flat grid is certified throughout; a fold of 7e-46 is not within a precision cap of
    # 128 bits: a few decisions reach it.
    vertices, triangles = eg.generate_mesh("grid:4,4")
    certified = eg.GeodesicSolver(vertices, triangles, backend="exact").propagate(0)
    assert certified.is_certified
    assert certified.stats()["backend"]["uncertified"] == 0
    assert certified.stats()["backend"]["decisions"] > 0

    vertices, triangles = fold()
    solver = eg.GeodesicSolver(vertices, triangles, backend="exact", precision_cap=128)
    field = solver.propagate(0)
    assert not field.is_certified
    assert field.stats()["backend"]["uncertified"] > 0
    # The float backends certify nothing, and claim nothing uncertified.
    assert eg.GeodesicSolver(vertices, triangles).propagate(0).is_certified


def test_distance_matrix_rows_are_single_source_fields(icosphere):
    vertices, triangles = icosphere
    solver = eg.GeodesicSolver(vertices, triangles)
    sources = np.array([0, 50, 100], dtype=np.uint32)
    matrix = solver.distance_matrix(sources, threads=2)
    assert matrix.shape == (3, len(vertices))
    for row, source in zip(matrix, sources):
        np.testing.assert_array_equal(row, solver.propagate(int(source)).distances)
    np.testing.assert_array_equal(solver.distance_matrix(sources, [7, 8], threads=1), matrix[:, 7:9])
    # Symmetric up to rounding.
    square = solver.distance_matrix(sources, sources)
    np.testing.assert_allclose(square, square.T, rtol=1e-9)


def test_stop_points_give_the_full_runs_distances_with_fewer_events():
    vertices, triangles = eg.generate_mesh("icosphere:3")
    solver = eg.GeodesicSolver(vertices, triangles)
    full = solver.propagate(0)
    stops = [5, 40, ("face", 100, (1, 2, 3))]
    stopped = solver.propagate(0, stop_points=stops)
    stats = stopped.stats()
    assert stats["stopped_at_stop_points"] and not full.stats()["stopped_at_stop_points"]
    assert stats["wedges_propagated"] < full.stats()["wedges_propagated"]
    # Vertices no farther than the farthest stop point: the full run's values, bit for bit.
    radius = max(full.distance_at(p) for p in stops)
    near = full.distances <= radius
    assert 0 < near.sum() < len(vertices)
    np.testing.assert_array_equal(stopped.distances[near], full.distances[near])
    assert (stopped.distances[~near] >= full.distances[~near]).all()
    assert math.isclose(stopped.distance_at(stops[2]), full.distance_at(stops[2]), rel_tol=1e-12)
    with pytest.raises(ValueError, match="face 9999 is out of range"):
        solver.propagate(0, stop_points=[("face", 9999, (1, 1, 1))])


def test_matrix_among_selected_vertices_is_the_single_source_runs(icosphere):
    vertices, triangles = icosphere
    solver = eg.GeodesicSolver(vertices, triangles)
    selected = np.array([3, 70, 11, 150, 42])
    square = solver.distance_matrix(selected, selected, threads=2)
    for row, source in zip(square, selected):
        np.testing.assert_array_equal(row, solver.propagate(int(source)).distances[selected])
    sparse = eg.distance_matrix_of_selected_points(vertices, triangles, selected)
    for i, p in enumerate(selected):
        for j, q in enumerate(selected):
            if i < j:
                assert sparse[p, q] == sparse[q, p] == square[i, j]


def test_mesh_io_round_trip(tmp_path, icosphere):
    vertices, triangles = icosphere
    obj = tmp_path / "sphere.obj"
    lines = [f"v {float(x)!r} {float(y)!r} {float(z)!r}" for x, y, z in vertices]
    lines += [f"f {a + 1} {b + 1} {c + 1}" for a, b, c in triangles]
    obj.write_text("\n".join(lines) + "\n")
    read_vertices, read_triangles = eg.read_mesh(obj)
    np.testing.assert_array_equal(read_vertices, vertices)
    np.testing.assert_array_equal(read_triangles, triangles)


def test_propagation_releases_the_gil():
    vertices, triangles = eg.generate_mesh("icosphere:5")
    solver = eg.GeodesicSolver(vertices, triangles)
    done = threading.Event()
    started = time.perf_counter()

    def propagate():
        solver.distance_matrix(np.arange(4), targets=[0], threads=1)
        done.set()

    worker = threading.Thread(target=propagate)
    worker.start()
    spins = 0
    while not done.is_set():
        spins += 1
    worker.join()
    seconds = time.perf_counter() - started
    # Holding the GIL for the whole call would leave this thread a few switch intervals.
    assert seconds > 0.2 and spins > 10_000, (seconds, spins)


def test_exact_backend_gives_certified_digits_of_sqrt5():
    import decimal

    vertices, triangles = eg.generate_mesh("cube")
    field = eg.GeodesicSolver(vertices, triangles, backend="exact").propagate(0)
    decimal.getcontext().prec = 60
    root5 = decimal.Decimal(5).sqrt()
    digits = field.exact_distances(digits=40)
    assert digits[0] == "0"
    far = decimal.Decimal(digits[6])
    # Within one unit of the 40th significant digit (the 39th decimal place of 2.23...).
    assert abs(far - root5) <= decimal.Decimal("1e-39")
    at = decimal.Decimal(field.exact_distance_at(6, digits=40))
    assert abs(at - root5) <= decimal.Decimal("1e-39")


def test_exact_values_are_refused_for_float_backends():
    vertices, triangles = eg.generate_mesh("cube")
    field = eg.GeodesicSolver(vertices, triangles).propagate(0)
    with pytest.raises(ValueError, match="exact backend"):
        field.exact_distances()
    exact = eg.GeodesicSolver(vertices, triangles, backend="exact").propagate(0)
    with pytest.raises(ValueError, match="digits"):
        exact.exact_distances(digits=0)


def test_exact_path_crosses_the_cube_edge_at_one_half():
    import decimal

    vertices, triangles = eg.generate_mesh("cube")
    field = eg.GeodesicSolver(vertices, triangles, backend="exact").propagate(0)
    far = int(np.argmax(field.distances))
    path, distance, offsets = field.exact_path(far, digits=30)
    assert len(offsets) == len(path.simplices)
    crossings = [o for o in offsets if o is not None]
    # The diagonal of the unfolded 1 x 2 rectangle crosses the shared edge at its middle.
    assert len(crossings) == 1 and decimal.Decimal(crossings[0]) == decimal.Decimal("0.5")
    decimal.getcontext().prec = 50
    assert abs(decimal.Decimal(distance) - decimal.Decimal(5).sqrt()) <= decimal.Decimal("1e-29")


def test_vertex_distances_are_the_fields_without_it(icosphere):
    vertices, triangles = icosphere
    solver = eg.GeodesicSolver(vertices, triangles)
    # Several sources: one engine, so bit for bit the field's values.
    field = solver.propagate([3, 17], max_distance=1.5)
    distances, nearest = solver.vertex_distances([3, 17], max_distance=1.5)
    np.testing.assert_array_equal(distances, field.distances)
    np.testing.assert_array_equal(nearest, field.nearest_source)
    assert distances.dtype == np.float64 and nearest.dtype == np.int64


@pytest.mark.parametrize("backend", ["f64", "adaptive"])
def test_vertex_distances_of_one_source_on_two_threads_are_one_threads(backend):
    vertices, triangles = eg.generate_mesh("icosphere:4")
    solver = eg.GeodesicSolver(vertices, triangles, backend=backend)
    one, nearest_one = solver.vertex_distances(5, threads=1)
    two, nearest_two = solver.vertex_distances(5, threads=2)
    np.testing.assert_array_equal(one, solver.propagate(5).distances)
    np.testing.assert_allclose(two, one, rtol=1e-12, atol=0)
    assert np.all(nearest_one == 0) and np.all(nearest_two == 0)
    # The icosphere's vertices lie on the unit sphere, around it: the nearest-point map onto
    # a convex body is 1-Lipschitz, so no geodesic on the icosphere is longer than the great
    # circle's arc between its ends, nor shorter than their chord.
    np.testing.assert_allclose(np.linalg.norm(vertices, axis=1), 1.0, rtol=1e-12)
    chord = np.linalg.norm(vertices - vertices[5], axis=1)
    arc = np.arccos(np.clip(vertices @ vertices[5], -1.0, 1.0))
    assert np.all(two >= chord * (1 - 1e-12)) and np.all(two <= arc * (1 + 1e-12) + 1e-15)


def test_vertex_distances_on_the_cube_reach_the_opposite_corner_at_sqrt_5():
    vertices, triangles = eg.generate_mesh("cube")
    distances, _ = eg.GeodesicSolver(vertices, triangles).vertex_distances(0, threads=2)
    assert distances[0] == 0.0
    assert math.isclose(distances.max(), math.sqrt(5), rel_tol=1e-12)


def test_vertex_distances_refuse_no_thread_and_a_negative_limit(icosphere):
    solver = eg.GeodesicSolver(*icosphere)
    with pytest.raises(ValueError, match="threads"):
        solver.vertex_distances(0, threads=0)
    with pytest.raises(ValueError, match="max_distance"):
        solver.vertex_distances(0, max_distance=-1.0)

"""loop_subdivision: the rules checked against closed forms on a regular icosahedron and a flat
square; common.read_obj, which reads the models it subdivides."""

import math

import pytest

from bench_vs_gdist import grid_mesh, icosphere_mesh
from common import read_obj
from loop_subdivision import loop_subdivide


def norm(p):
    return math.sqrt(sum(c * c for c in p))


def test_icosahedron_points_have_the_closed_forms_of_the_rules():
    vertices, triangles = icosphere_mesh(0)
    points, finer = loop_subdivide(vertices, triangles)
    assert (len(points), len(finer)) == (12 + 30, 80)
    # Unit circumradius: neighbours meet at a dot product of 1/sqrt 5, so the five of a vertex
    # sum to sqrt 5 times it, and it moves to (5/8 + 3 sqrt 5 / 40) times itself.
    scale = 5 / 8 + 3 * math.sqrt(5) / 40
    for old, new in zip(vertices, points):
        assert all(abs(n - scale * o) < 1e-14 for o, n in zip(old, new))
    # An edge's point lies on the 2-fold axis through its middle, where the faces' third corners
    # c, d add up to their projection onto it: 3/8 s + 1/2 (1 / sqrt 5) / s, s = |a + b|.
    s = math.sqrt(2 + 2 / math.sqrt(5))
    expected = 3 / 8 * s + 0.5 / math.sqrt(5) / s
    for p in points[12:]:
        assert abs(norm(p) - expected) < 1e-14


def test_a_flat_square_stays_flat_and_its_boundary_edges_split_at_their_middles():
    n = 4
    vertices, triangles = grid_mesh(n)
    points, finer = loop_subdivide(vertices, triangles)
    edges = 3 * n * n + 2 * n
    assert (len(points), len(finer)) == ((n + 1) ** 2 + edges, 4 * len(triangles))
    assert all(p[2] == 0.0 and 0.0 <= p[0] <= 1.0 and 0.0 <= p[1] <= 1.0 for p in points)
    # The boundary edges' points are their middles: on the square's sides at odd sixteenths...
    on_sides = [p for p in points[(n + 1) ** 2:] if p[0] in (0.0, 1.0) or p[1] in (0.0, 1.0)]
    assert len(on_sides) == 4 * n
    for p in on_sides:
        along = p[1] if p[0] in (0.0, 1.0) else p[0]
        assert (along * 2 * n) % 2 == 1
    # ... and a vertex on a side between two others stays where it is (3/4 p + 1/8 (q + r)).
    assert points[2] == vertices[2]
    # Every triangle keeps its orientation (the square's normal is +z throughout).
    for a, b, c in finer:
        (ax, ay, _), (bx, by, _), (cx, cy, _) = points[a], points[b], points[c]
        assert (bx - ax) * (cy - ay) - (by - ay) * (cx - ax) > 0


def test_read_obj_reads_vertices_and_triangles_and_refuses_polygons(tmp_path):
    path = tmp_path / "mesh.obj"
    path.write_text("# a comment\nv 0 0 0\nv 1 0 0  # trailing\nv 0 1 0\nvn 0 0 1\nf 1/1/1 2/2/1 -1\n")
    assert read_obj(path) == ([(0.0, 0.0, 0.0), (1.0, 0.0, 0.0), (0.0, 1.0, 0.0)], [(0, 1, 2)])
    path.write_text("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nf 1 2 4 3\n")
    with pytest.raises(ValueError, match="mesh.obj:5"):
        read_obj(path)

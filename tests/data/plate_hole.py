"""Writes plate_hole_24.obj and plate_hole_40.obj (tests/exact_certified.rs): a quadrilateral
plate 0.75 thick with an irregular polygonal hole through it (N vertices at jittered angles and
radii, NumPy's default_rng with seeds 2 and 3), extruded by trimesh, coordinates rounded to 7
decimals: a CAD-like part whose hole wall is vertical below a concave polygonal rim. Needs
numpy, shapely, mapbox-earcut and trimesh."""
import numpy as np
import shapely.geometry as geometry
import trimesh


def plate(n, seed, name):
    rng = np.random.default_rng(seed)
    t = np.linspace(0, 2 * np.pi, n, endpoint=False) + rng.uniform(-0.1, 0.1, n)
    r = 0.5 + rng.uniform(-0.05, 0.05, n)
    hole = np.c_[0.1 + r * np.cos(t), 0.05 + r * np.sin(t)]
    outer = [(-1.5, -1.2), (1.3, -1.1), (1.4, 1.25), (-1.2, 1.3)]
    mesh = trimesh.creation.extrude_polygon(geometry.Polygon(outer, [hole]), height=0.75)
    mesh.vertices = np.round(mesh.vertices, 7)
    mesh.export(name)


plate(24, 2, "plate_hole_24.obj")
plate(40, 3, "plate_hole_40.obj")

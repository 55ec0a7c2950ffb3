"""Writes plate_rotated_hole.obj (tests/exact_certified.rs): a rectangular plate 0.75 thick with
a rectangular hole turned by 30 degrees, its sides subdivided every 0.1 (shapely's segmentize),
extruded by trimesh, coordinates rounded to 7 decimals: a CAD-like part whose hole walls meet
the top along straight rims of many collinear vertices. Needs numpy, shapely, mapbox-earcut and
trimesh."""
import numpy as np
import shapely.affinity as affinity
import shapely.geometry as geometry
import trimesh

hole = affinity.rotate(geometry.box(-0.45, -0.3, 0.55, 0.4), 30, origin=(0, 0)).segmentize(0.1)
outer = geometry.box(-1.5, -1.2, 1.4, 1.3)
plate = geometry.Polygon(outer.exterior.coords, [hole.exterior.coords])
mesh = trimesh.creation.extrude_polygon(plate, height=0.75)
mesh.vertices = np.round(mesh.vertices, 7)
mesh.export("plate_rotated_hole.obj")

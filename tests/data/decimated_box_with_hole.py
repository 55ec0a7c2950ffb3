"""Writes decimated_box_with_hole.obj (tests/exact_certified.rs): a CAD-like part, a 2 x 1.2 x
0.8 box with a cylindrical hole of radius 0.35 (48 sections) bored through it (trimesh's
boolean difference, by manifold3d), each face split into 16 (pyvista's linear subdivision,
twice) and decimated by 80 % (pyvista's `decimate`, VTK's quadric decimation): 664 faces of
float coordinates, flat walls cut into slivers. Needs trimesh, manifold3d and pyvista."""
import numpy as np
import pyvista as pv
import trimesh

part = trimesh.creation.box(extents=[2, 1.2, 0.8]).difference(
    trimesh.creation.cylinder(radius=0.35, height=2.0, sections=48)
)
faces = np.hstack([np.full((len(part.faces), 1), 3), part.faces]).ravel()
mesh = pv.PolyData(np.asarray(part.vertices), faces).clean().triangulate()
mesh = mesh.subdivide(2, "linear").decimate(0.8).triangulate().clean()
with open("decimated_box_with_hole.obj", "w") as f:
    for p in mesh.points:
        f.write("v %r %r %r\n" % tuple(float(c) for c in p))
    for a, b, c in mesh.faces.reshape(-1, 4)[:, 1:]:
        f.write("f %d %d %d\n" % (a + 1, b + 1, c + 1))

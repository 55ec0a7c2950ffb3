"""Writes subdivided_icosahedron.obj and subdivided_octahedron.obj (tests/exact_certified.rs):
pyvista's icosahedron and octahedron, each face split linearly into 16 (`subdivide(2)`),
cleaned, their float32 coordinates written exactly. 320 and 128 faces; the coordinates keep
the mirror symmetries in the coordinate planes. Needs pyvista."""
import pyvista as pv

for name, solid in [("icosahedron", pv.Icosahedron()), ("octahedron", pv.Octahedron())]:
    m = solid.triangulate().subdivide(2).clean()
    with open(f"subdivided_{name}.obj", "w") as f:
        for p in m.points:
            f.write("v %r %r %r\n" % tuple(float(c) for c in p))
        for a, b, c in m.faces.reshape(-1, 4)[:, 1:]:
            f.write("f %d %d %d\n" % (a + 1, b + 1, c + 1))

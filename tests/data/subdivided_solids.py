"""Writes the subdivided solids of tests/exact_certified.rs: pyvista's icosahedron and
octahedron, each face split linearly into 16 (`subdivide(2)`), cleaned, their float32
coordinates written exactly (subdivided_icosahedron.obj, subdivided_octahedron.obj: 320 and
128 faces); and the octahedron split into 64 (`subdivide(3)`, 512 faces) with its coordinates
written to 8 decimals (subdivided_octahedron_512.obj), which leaves the big faces only nearly
flat; likewise the icosahedron split into 16 (subdivided_icosahedron_8_decimals.obj) and
the tetrahedron into 64 (subdivided_tetrahedron_8_decimals.obj, 256 faces); and the
dodecahedron (its pentagons cut into three triangles) split into 16
(subdivided_dodecahedron.obj, 576 faces, float32 coordinates written exactly). The coordinates
keep the mirror symmetries in the coordinate planes. Needs pyvista."""
import pyvista as pv


def write(name, mesh, coordinate):
    with open(name, "w") as f:
        for p in mesh.points:
            f.write("v %s %s %s\n" % tuple(coordinate(float(c)) for c in p))
        for a, b, c in mesh.faces.reshape(-1, 4)[:, 1:]:
            f.write("f %d %d %d\n" % (a + 1, b + 1, c + 1))


for name, solid in [("icosahedron", pv.Icosahedron()), ("octahedron", pv.Octahedron())]:
    write(f"subdivided_{name}.obj", solid.triangulate().subdivide(2).clean(), repr)
write("subdivided_octahedron_512.obj", pv.Octahedron().triangulate().subdivide(3).clean(), lambda c: "%.8f" % c)
write("subdivided_icosahedron_8_decimals.obj", pv.Icosahedron().triangulate().subdivide(2).clean(), lambda c: "%.8f" % c)
write("subdivided_tetrahedron_8_decimals.obj", pv.Tetrahedron().triangulate().subdivide(3).clean(), lambda c: "%.8f" % c)
write("subdivided_dodecahedron.obj", pv.Dodecahedron().triangulate().subdivide(2).clean(), repr)

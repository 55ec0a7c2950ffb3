"""Writes superquadric.obj (tests/exact_certified.rs): pyvista's Superquadric (theta roundness
0.3, phi roundness 0.7, its default resolutions) triangulated and cleaned, its float32
coordinates written exactly. Needs pyvista."""
import pyvista as pv

m = pv.Superquadric(theta_roundness=0.3, phi_roundness=0.7).triangulate().clean()
with open("superquadric.obj", "w") as f:
    for p in m.points:
        f.write("v %r %r %r\n" % tuple(float(c) for c in p))
    for a, b, c in m.faces.reshape(-1, 4)[:, 1:]:
        f.write("f %d %d %d\n" % (a + 1, b + 1, c + 1))

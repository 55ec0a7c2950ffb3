"""Writes parametric_torus.obj (tests/exact_certified.rs): pyvista's ParametricTorus
(ring radius 1, tube radius 0.5) sampled 30 by 20, triangulated and cleaned, its float32 coordinates written
exactly. Needs pyvista."""
import pyvista as pv

m = pv.ParametricTorus(u_res=30, v_res=20, w_res=20).triangulate().clean()
with open("parametric_torus.obj", "w") as f:
    for p in m.points:
        f.write("v %r %r %r\n" % tuple(float(c) for c in p))
    for a, b, c in m.faces.reshape(-1, 4)[:, 1:]:
        f.write("f %d %d %d\n" % (a + 1, b + 1, c + 1))

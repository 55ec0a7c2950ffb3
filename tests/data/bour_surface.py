"""Writes bour_surface.obj (tests/exact_certified.rs): pyvista's ParametricBour (Bour's minimal
surface) sampled 12 by 12, triangulated and cleaned, its float32 coordinates written exactly.
Needs pyvista."""
import pyvista as pv

m = pv.ParametricBour(u_res=12, v_res=12, w_res=10).triangulate().clean()
with open("bour_surface.obj", "w") as f:
    for p in m.points:
        f.write("v %r %r %r\n" % tuple(float(c) for c in p))
    for a, b, c in m.faces.reshape(-1, 4)[:, 1:]:
        f.write("f %d %d %d\n" % (a + 1, b + 1, c + 1))

"""Writes the pyvista surfaces of tests/exact_certified.rs, each triangulated and cleaned, its
float32 coordinates written exactly: parametric_torus.obj (ParametricTorus, ring radius 1,
tube radius 0.5, sampled 30 by 20), parametric_torus_50_30.obj (the same, 50 by 30),
superquadric.obj (Superquadric, theta roundness 0.3, phi roundness 0.7, its default
resolutions) and bour_surface.obj (ParametricBour, Bour's minimal surface, sampled 12 by 12).
Needs pyvista."""
import pyvista as pv


def write(mesh, name):
    m = mesh.triangulate().clean()
    with open(name, "w") as f:
        for p in m.points:
            f.write("v %r %r %r\n" % tuple(float(c) for c in p))
        for a, b, c in m.faces.reshape(-1, 4)[:, 1:]:
            f.write("f %d %d %d\n" % (a + 1, b + 1, c + 1))


write(pv.ParametricTorus(u_res=30, v_res=20, w_res=20), "parametric_torus.obj")
write(pv.ParametricTorus(u_res=50, v_res=30, w_res=30), "parametric_torus_50_30.obj")
write(pv.Superquadric(theta_roundness=0.3, phi_roundness=0.7), "superquadric.obj")
write(pv.ParametricBour(u_res=12, v_res=12, w_res=10), "bour_surface.obj")

"""Writes open_cylinder_32_6.obj, _48_8.obj and _32_10.obj (tests/exact_certified.rs): open
cylinders of radius 1 and height 1.5, 32, 48 and 32 sections (numpy's cos and sin of linspace
angles) by 6, 8 and 10 rings, each quad split along its diagonal. Every quad is an exact rectangle
(its sides are vertical and horizontal), so the surface is a band of flat strips between
vertical creases: unrolled, a rectangle whose width is the perimeter of the polygon. Needs
numpy."""
import numpy as np

for sections, rings in [(32, 6), (48, 8), (32, 10)]:
    angles = np.linspace(0, 2 * np.pi, sections, endpoint=False)
    heights = np.linspace(0, 1.5, rings)
    with open(f"open_cylinder_{sections}_{rings}.obj", "w") as f:
        for a in angles:
            for z in heights:
                f.write("v %r %r %r\n" % (float(np.cos(a)), float(np.sin(a)), float(z)))
        for i in range(sections):
            for j in range(rings - 1):
                a = i * rings + j
                b = (i + 1) % sections * rings + j
                f.write("f %d %d %d\n" % (a + 1, b + 1, b + 2))
                f.write("f %d %d %d\n" % (a + 1, b + 2, a + 2))

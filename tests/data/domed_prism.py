"""Writes domed_prism.obj (tests/exact_certified.rs): a prism over a random convex-ish decagon
(numpy's default_rng seed 6), extruded in 8 steps, each side a flat strip between straight
creases; one end closed by a bulging dome of 3 jittered rings and an apex (faces in no common
plane), the other by a flat fan. Coordinates are rounded to float32. From the dome's apex
(v120) the image of the source enters the strips from curved faces, crosses their creases, and
reaches the vertices on them from both sides. Needs numpy."""
import numpy as np

rng = np.random.default_rng(6)
n, steps, rings = 10, 8, 3


def f32(a):
    return np.asarray(a).astype(np.float32).astype(np.float64)


ang = np.sort(rng.uniform(0, 2 * np.pi, n))
r = rng.uniform(20, 40, n)
section = f32(np.c_[900 + r * np.cos(ang), 100 + r * np.sin(ang)])
ys = f32(np.arange(steps + 1) * rng.uniform(15, 25) + 0.49)
vertices = [(x, y, z) for y in ys for (x, z) in section]
faces = []
for k in range(steps):
    for i in range(n):
        j = (i + 1) % n
        a, b, c, d = k * n + i, k * n + j, (k + 1) * n + j, (k + 1) * n + i
        faces += [(a, c, b), (a, d, c)] if (i + k) % 2 else [(a, d, b), (b, d, c)]
cx, cz = section[:, 0].mean(), section[:, 1].mean()
previous = list(range(n))
for q in range(1, rings + 1):
    t = q / (rings + 1)
    ring = f32(
        np.c_[
            cx + (section[:, 0] - cx) * (1 - t),
            ys[0] - 25 * np.sin(t * np.pi / 2) + rng.normal(0, 0.3, n),
            cz + (section[:, 1] - cz) * (1 - t),
        ]
    )
    current = list(range(len(vertices), len(vertices) + n))
    vertices += [tuple(p) for p in ring]
    for i in range(n):
        j = (i + 1) % n
        faces += [(previous[i], previous[j], current[j]), (previous[i], current[j], current[i])]
    previous = current
apex = len(vertices)
vertices.append((cx + 1.3, ys[0] - 27.7, cz - 0.9))
faces += [(previous[i], previous[(i + 1) % n], apex) for i in range(n)]
centre = len(vertices)
vertices.append((cx, ys[-1], cz))
faces += [(centre, steps * n + (i + 1) % n, steps * n + i) for i in range(n)]
with open("domed_prism.obj", "w") as f:
    for v in vertices:
        f.write("v %r %r %r\n" % tuple(float(c) for c in v))
    for t in faces:
        f.write("f %d %d %d\n" % tuple(i + 1 for i in t))

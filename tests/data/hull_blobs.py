"""Writes hull_blob_60.obj and hull_blob_100.obj (tests/exact_certified.rs): the convex hull of
N random unit vectors (NumPy's default_rng, seed 1030), outward faces, then every vertex
moved out radially by a factor 1 + 0.3 U (U uniform in [0, 1), seed + 1): an irregular
triangulation with slivers and saddle vertices. Needs numpy and scipy."""
import numpy as np
from scipy.spatial import ConvexHull


def blob(n, seed):
    rng = np.random.default_rng(seed)
    points = rng.normal(size=(n, 3))
    points /= np.linalg.norm(points, axis=1)[:, None]
    faces = ConvexHull(points).simplices.copy()
    centre = points[faces].mean(1)
    normal = np.cross(points[faces[:, 1]] - points[faces[:, 0]], points[faces[:, 2]] - points[faces[:, 0]])
    inward = (normal * centre).sum(1) < 0
    faces[inward] = faces[inward][:, ::-1]
    radii = 1 + 0.3 * np.random.default_rng(seed + 1).random((n, 1))
    return points * radii, faces


for n in (60, 100):
    vertices, faces = blob(n, 1030)
    with open(f"hull_blob_{n}.obj", "w") as out:
        for v in vertices:
            out.write("v %r %r %r\n" % tuple(float(x) for x in v))
        for f in faces:
            out.write("f %d %d %d\n" % tuple(int(i) + 1 for i in f))

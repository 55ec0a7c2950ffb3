"""Writes delaunay_terrain.obj (tests/exact_certified.rs): 400 uniform random points of the unit
square (numpy's default_rng seed 7), triangulated by scipy's Delaunay (782 faces, irregular
valences), raised to a smooth height field plus normal noise (sigma 0.02), coordinates rounded to
6 decimals: an open float mesh with no structure the algorithm could lean on. Needs numpy and
scipy."""
import numpy as np
from scipy.spatial import Delaunay

rng = np.random.default_rng(7)
p = rng.uniform(0, 1, (400, 2))
z = 0.1 * np.sin(6 * p[:, 0]) * np.cos(4 * p[:, 1]) + 0.02 * rng.standard_normal(400)
v = np.round(np.c_[p, z], 6)
with open("delaunay_terrain.obj", "w") as f:
    for x in v:
        f.write("v %r %r %r\n" % tuple(float(c) for c in x))
    for t in Delaunay(p).simplices:
        f.write("f %d %d %d\n" % tuple(int(i) + 1 for i in t))

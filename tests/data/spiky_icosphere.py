"""Writes spiky_icosphere_1.obj and spiky_icosphere_4.obj (tests/exact_certified.rs): trimesh's
icosphere of 1,280 faces, each vertex moved along its radius by a normal factor (sigma 0.15,
numpy's default_rng seeds 1 and 4), coordinates rounded to 6 decimals: a float mesh full of
saddle vertices whose neighbours are reached straight through them. Needs numpy and trimesh."""
import numpy as np
import trimesh

for seed in (1, 4):
    rng = np.random.default_rng(seed)
    mesh = trimesh.creation.icosphere(subdivisions=3)
    mesh.vertices = np.round(mesh.vertices * (1 + 0.15 * rng.standard_normal(len(mesh.vertices)))[:, None], 6)
    mesh.export(f"spiky_icosphere_{seed}.obj")

"""Writes subdivided_icosahedron_trimesh.obj for tests/exact_certified.rs: trimesh's icosahedron
with each face split into four twice (`subdivide()`: at the edges' midpoints, not projected to
the sphere; 320 faces), as trimesh's own OBJ export writes it (8 decimals). Rounded so, each big
face is exactly flat only in pieces: flat regions of up to 7 faces that meet along straight
lines. The mirror symmetries in the coordinate planes stay exact. Needs trimesh."""
import trimesh

mesh = trimesh.creation.icosahedron().subdivide().subdivide()
with open("subdivided_icosahedron_trimesh.obj", "w") as f:
    f.write(trimesh.exchange.obj.export_obj(mesh))

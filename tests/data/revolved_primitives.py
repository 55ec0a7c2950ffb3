"""Writes cylinder64.obj, annulus32.obj, cone24.obj and cone64.obj (tests/exact_certified.rs):
trimesh's revolved primitives as it exports them (8 decimals), a cylinder of radius 1 and height
2 with 64 sections, an annulus of radii 0.5 and 1 and height 1 (32 sections), and cones of
radius 1 and height 2 with 24 and 64 sections. Their rims are symmetric, so images of one source
reach an edge along chains of faces that are mirror images of each other, or, round the cone's
apex, the same corners in the opposite order. Needs numpy and trimesh."""
import trimesh

trimesh.creation.cylinder(radius=1, height=2, sections=64).export("cylinder64.obj")
trimesh.creation.annulus(r_min=0.5, r_max=1, height=1).export("annulus32.obj")
trimesh.creation.cone(radius=1, height=2, sections=24).export("cone24.obj")
trimesh.creation.cone(radius=1, height=2, sections=64).export("cone64.obj")

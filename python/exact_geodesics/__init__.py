"""Exact geodesic distances and paths on triangle meshes.

The MMP algorithm in the wedge form of Surazhsky et al. [SSK+05], as analysed in Liu, Zhang and
Tang [LZT], from the Rust library ``exact-geodesics``, generic over its number type: ``"f64"``,
``"adaptive"`` (float values, exact predicates) or ``"exact"`` (certified exact reals).

- :class:`GeodesicSolver`: a mesh and a backend; ``propagate`` returns a
  :class:`GeodesicField` (distances, nearest sources, distances anywhere, paths, wedges, stats).
- :func:`compute_gdist`, :func:`local_gdist_matrix`, :func:`distance_matrix_of_selected_points`:
  the functions of the ``gdist`` package, with the same arguments.
- :mod:`exact_geodesics.geodesic`: ``PyGeodesicAlgorithmExact``, the class of the
  ``pygeodesic`` package, with the same methods and results.
- :func:`read_mesh`, :func:`generate_mesh`: meshes as ``(vertices, triangles)`` arrays.

Bad input raises ``ValueError`` with the library's message; nothing is printed.
"""

from ._compat import compute_gdist, distance_matrix_of_selected_points, local_gdist_matrix
from ._native import GeodesicField, GeodesicPath, GeodesicSolver, generate_mesh, read_mesh
from .geodesic import PyGeodesicAlgorithmExact

__all__ = [
    "GeodesicField",
    "GeodesicPath",
    "GeodesicSolver",
    "PyGeodesicAlgorithmExact",
    "compute_gdist",
    "distance_matrix_of_selected_points",
    "generate_mesh",
    "local_gdist_matrix",
    "read_mesh",
]

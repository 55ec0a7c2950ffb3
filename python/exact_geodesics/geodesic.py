"""The class of the ``pygeodesic`` package (``pygeodesic.geodesic``), with its methods and
results, on this library: ``from exact_geodesics import geodesic`` in place of
``import pygeodesic.geodesic as geodesic``.

Differences from pygeodesic, all deliberate: an error (a target no source reaches, an index out
of range) raises ``ValueError`` instead of printing and returning ``(None, None)``; ``inf``, not
1e100, is the distance of an unreachable vertex, whose best source is ``-1``; indices may have
any integer dtype; and a ``backend`` may be chosen (``"f64"``, ``"adaptive"`` or ``"exact"``).
"""

from __future__ import annotations

import numpy as np

from ._native import GeodesicSolver

__all__ = ["PyGeodesicAlgorithmExact"]


class PyGeodesicAlgorithmExact:
    """Exact geodesics on a triangle mesh, as pygeodesic's class of the same name.

    Args:
        points: (n, 3) vertex coordinates.
        faces: (m, 3) vertex indices of the triangles, any integer dtype.
        backend: the number type (``"f64"`` by default, as pygeodesic's doubles).

    Raises:
        ValueError: for a mesh the library refuses.
    """

    def __init__(self, points, faces, backend: str = "f64"):
        self._solver = GeodesicSolver(points, faces, backend=backend)

    def geodesicDistance(self, sourceIndex, targetIndex):  # noqa: N802 (pygeodesic's name)
        """The geodesic distance between two vertices and the path between them.

        Returns:
            ``(distance, path)``: the distance (float) and the path's points, a (k, 3) float64
            array from the target to the source.

        Raises:
            ValueError: for an index out of range, or a target the source does not reach.
        """
        # The run stops once the target is final: the path's wedges are then final too.
        target = int(targetIndex)
        field = self._solver.propagate([int(sourceIndex)], stop_points=[target])
        path = field.path(target)
        return path.distance, path.points

    def geodesicDistances(  # noqa: N802 (pygeodesic's name)
        self, source_indices, target_indices=None, max_distance=None
    ):
        """Distances from the nearest of ``source_indices`` to each target.

        Args:
            source_indices: source vertices, any integer dtype.
            target_indices: target vertices (every vertex if ``None``).
            max_distance: stop there; farther vertices are at ``inf`` (pygeodesic's 1e100 and
                ``None`` both mean no limit).

        Returns:
            ``(distances, best_source)``: float64 distances (``inf`` where unreachable) and, for
            each target, the index into ``source_indices`` of its nearest source (``-1`` where
            unreachable), as int64 arrays of the targets' length.

        Raises:
            ValueError: for an index out of range or no source.
        """
        limit = None if max_distance is None or max_distance >= 1e100 else max_distance
        sources = np.asarray(source_indices).reshape(-1)
        distances, best = self._solver.vertex_distances(sources, max_distance=limit)
        if target_indices is None:
            return distances, best
        targets = np.asarray(target_indices).reshape(-1)
        if not np.issubdtype(targets.dtype, np.integer):
            raise ValueError("target_indices must be integers")
        if targets.size and (targets.min() < 0 or targets.max() >= len(distances)):
            raise ValueError(
                f"target_indices must lie in 0..{len(distances) - 1} (the mesh's vertices)"
            )
        return distances[targets], best[targets]

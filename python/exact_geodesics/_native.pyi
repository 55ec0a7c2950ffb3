"""Type stubs of the Rust extension ``exact_geodesics._native`` (see ``python/src``)."""

from os import PathLike
from typing import Any, Literal, Optional, Sequence, Tuple, Union

import numpy as np
import numpy.typing as npt

Backend = Literal["f64", "adaptive", "exact"]

#: A surface point: a vertex index, ``("edge", a, b, t)`` (fraction ``t`` from vertex ``a`` to
#: vertex ``b``), ``("edge", e, (t,))`` (``t`` from ``GeodesicSolver.edges[e][0]``),
#: ``("face", f, (u, v, w))`` (barycentric, homogeneous) or ``("vertex", v)``.
Point = Union[
    int,
    np.integer,
    Tuple[Literal["vertex"], int],
    Tuple[Literal["vertex"], int, Tuple[()]],
    Tuple[Literal["edge"], int, int, float],
    Tuple[Literal["edge"], int, Tuple[float]],
    Tuple[Literal["face"], int, Tuple[float, float, float]],
]

#: A point as the library names it: ``("vertex", v, ())``, ``("edge", e, (t,))`` or
#: ``("face", f, (u, v, w))``.
Simplex = Union[
    Tuple[Literal["vertex"], int, Tuple[()]],
    Tuple[Literal["edge"], int, Tuple[float]],
    Tuple[Literal["face"], int, Tuple[float, float, float]],
]

#: Vertex indices of any integer dtype.
Indices = Union[npt.NDArray[np.integer], Sequence[int]]

class GeodesicSolver:
    """Geodesic distances and paths on one triangle mesh with the number type ``backend``.

    Raises ``ValueError`` with the library's message for a mesh it refuses.
    """

    def __init__(
        self,
        vertices: npt.ArrayLike,
        triangles: npt.ArrayLike,
        backend: Backend = "f64",
        precision_cap: Optional[int] = None,
        is_one_indexed: bool = False,
    ) -> None: ...
    def propagate(
        self,
        sources: Union[Point, Indices, Sequence[Point]],
        max_distance: Optional[float] = None,
        stop_points: Optional[Union[Point, Indices, Sequence[Point]]] = None,
    ) -> GeodesicField:
        """The distance field of ``sources``, stopped once ``stop_points`` are final (GIL
        released while propagating)."""
    def vertex_distances(
        self,
        sources: Union[Point, Indices, Sequence[Point]],
        max_distance: Optional[float] = None,
        threads: Optional[int] = None,
    ) -> Tuple[npt.NDArray[np.float64], npt.NDArray[np.int64]]:
        """``(distances, nearest_source)`` of every vertex, as ``propagate`` gives them, without
        the field: a run's memory is its front's, and a single source vertex's directions are
        split between two threads (all cores if ``threads`` is ``None``)."""
    def distance_matrix(
        self,
        sources: Union[Point, Indices, Sequence[Point]],
        targets: Optional[Indices] = None,
        max_distance: Optional[float] = None,
        threads: Optional[int] = None,
    ) -> npt.NDArray[np.float64]:
        """Distances from each source alone to ``targets``: shape (len(sources), len(targets))."""
    def local_distances(
        self,
        max_distance: Optional[float],
        sources: Optional[Indices] = None,
        threads: Optional[int] = None,
    ) -> Tuple[npt.NDArray[np.float64], npt.NDArray[np.int64], npt.NDArray[np.int64]]:
        """``(data, rows, columns)`` of the distances within ``max_distance`` of each source."""
    @property
    def backend(self) -> Backend: ...
    @property
    def vertex_count(self) -> int: ...
    @property
    def face_count(self) -> int: ...
    @property
    def vertices(self) -> npt.NDArray[np.float64]:
        """(n, 3) coordinates."""
    @property
    def triangles(self) -> npt.NDArray[np.uint32]:
        """(m, 3) 0-based vertex indices."""
    @property
    def edges(self) -> npt.NDArray[np.uint32]:
        """(e, 2) vertex pairs; edge ``i`` runs from ``edges[i][0]`` to ``edges[i][1]``."""
    @property
    def warnings(self) -> list[str]:
        """What is unusual but acceptable about the mesh."""

class GeodesicField:
    """The geodesic distance field of a set of sources; unreachable is ``inf``."""

    @property
    def distances(self) -> npt.NDArray[np.float64]:
        """Distance of every vertex to its nearest source."""
    @property
    def nearest_source(self) -> npt.NDArray[np.int64]:
        """Index into ``sources`` of every vertex's nearest source, ``-1`` where unreachable."""
    @property
    def sources(self) -> list[Simplex]: ...
    @property
    def backend(self) -> Backend: ...
    @property
    def is_certified(self) -> bool:
        """Whether the backend certified every decision (``False`` only for ``exact``)."""
    def distance_at(self, point: Point) -> float: ...
    def exact_distances(self, digits: int = 20) -> list[Optional[str]]:
        """Certified decimal digits of every vertex's distance (exact backend only)."""
    def exact_distance_at(self, point: Point, digits: int = 20) -> Optional[str]:
        """Certified decimal digits of the distance at a point (exact backend only)."""
    def path(self, target: Point) -> GeodesicPath: ...
    def exact_path(
        self, target: Point, digits: int = 20
    ) -> Tuple[GeodesicPath, str, list[Optional[str]]]:
        """The path, the target's distance and each edge crossing's offset, as certified
        digits (exact backend only)."""
    def wedges(self, edge: Union[int, Tuple[int, int]]) -> list[dict[str, Any]]: ...
    def stats(self) -> dict[str, Any]: ...

class GeodesicPath:
    """A shortest path from a target back to its nearest source."""

    @property
    def points(self) -> npt.NDArray[np.float64]:
        """(k, 3) points from the target to the source."""
    @property
    def simplices(self) -> list[Simplex]: ...
    @property
    def distance(self) -> float: ...
    @property
    def source(self) -> int: ...
    @property
    def length(self) -> float: ...
    def __len__(self) -> int: ...

def read_mesh(
    path: Union[str, PathLike[str]], triangulate: bool = False
) -> Tuple[npt.NDArray[np.float64], npt.NDArray[np.int64]]:
    """``(vertices, triangles)`` of an OBJ, OFF or PLY file."""

def generate_mesh(shape: str) -> Tuple[npt.NDArray[np.float64], npt.NDArray[np.int64]]:
    """``(vertices, triangles)`` of a generated mesh such as ``"icosphere:3"``."""

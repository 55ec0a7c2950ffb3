"""Loop's subdivision of a triangle mesh [Loo87], for benchmarks on larger versions of the shared
models: each step splits every triangle into four, so a model of 20k faces becomes one of 80k,
smoothed a little, of the same genus: larger models of real shapes, as issue 13 asks to time.

Rules: a vertex inside the surface moves to ``(1 - n b) p + b (sum of its n neighbours)``,
``b = 3/16`` for ``n = 3`` and ``3 / (8 n)`` otherwise; an edge between two faces gets the
point ``3/8 (a + b) + 1/8 (c + d)`` (``c``, ``d`` the faces' third corners). Edges of one face or
of more than two are creases: their points are their midpoints, and a vertex on exactly two of
them moves to ``3/4 p + 1/8 (q + r)`` along them; other vertices on creases, and vertices of no
face, stay. A vertex keeps its index (new vertices come after the old ones), so a source
``v:S`` names the same point of the model at every level.

[Loo87]: C. Loop, Smooth subdivision surfaces based on triangles, M.S. thesis, University of
Utah, 1987.

Needs only the standard library.
"""


def loop_subdivide(vertices, triangles):
    """One step of Loop's subdivision (see the module's docs): the new vertices and triangles."""
    third_corners = {}
    for a, b, c in triangles:
        for u, v, w in ((a, b, c), (b, c, a), (c, a, b)):
            third_corners.setdefault((min(u, v), max(u, v)), []).append(w)
    neighbours = [set() for _ in vertices]
    along_creases = [[] for _ in vertices]
    for (u, v), thirds in third_corners.items():
        neighbours[u].add(v)
        neighbours[v].add(u)
        if len(thirds) != 2:
            along_creases[u].append(v)
            along_creases[v].append(u)

    def combination(terms):
        return tuple(sum(weight * vertices[i][k] for weight, i in terms) for k in range(3))

    points = []
    for i, p in enumerate(vertices):
        crease = along_creases[i]
        n = len(neighbours[i])
        if len(crease) == 2:
            points.append(combination([(0.75, i), (0.125, crease[0]), (0.125, crease[1])]))
        elif crease or n < 3:
            points.append(p)
        else:
            b = 3 / 16 if n == 3 else 3 / (8 * n)
            points.append(combination([(1 - n * b, i)] + [(b, j) for j in sorted(neighbours[i])]))
    edge_point = {}
    for (u, v), thirds in third_corners.items():
        edge_point[(u, v)] = len(points)
        if len(thirds) == 2:
            terms = [(0.375, u), (0.375, v), (0.125, thirds[0]), (0.125, thirds[1])]
        else:
            terms = [(0.5, u), (0.5, v)]
        points.append(combination(terms))

    return points, split_in_four(triangles, lambda a, b: edge_point[(min(a, b), max(a, b))])


def split_in_four(triangles, middle):
    """Each triangle as four, by the vertex ``middle(a, b)`` of each of its edges (the same for
    both orders of its ends), with the orientation kept."""
    finer = []
    for a, b, c in triangles:
        ab, bc, ca = middle(a, b), middle(b, c), middle(c, a)
        finer += [(a, ab, ca), (b, bc, ab), (c, ca, bc), (ab, bc, ca)]
    return finer

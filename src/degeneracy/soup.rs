//! A triangle list under construction: the mesh surgery the degenerate corpus is built with
//! (grids, midpoint subdivision, a vertex split along a zero-length edge, a point inserted on an
//! edge with a zero-area face to close the T-junction).
//!
//! No operation repeats a vertex in a face, so [`Soup::into_mesh`] always satisfies
//! [`TriMesh::new`]'s preconditions for finite positions. Each keeps every edge in at most two
//! faces, but for the non-manifold kind's, which glue pages along a spine and stand fins on
//! edges.

use crate::mesh::TriMesh;
use glam::DVec3;
use std::collections::{HashMap, HashSet};

/// Which diagonal splits a grid cell.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Diagonal {
    /// From the lower left corner to the upper right one.
    Rising,
    /// From the lower right corner to the upper left one.
    Falling,
}

/// Positions and counter-clockwise triangles, freely editable.
#[derive(Clone, Debug, Default)]
pub(crate) struct Soup {
    pub(crate) positions: Vec<DVec3>,
    pub(crate) faces: Vec<[u32; 3]>,
}

impl Soup {
    /// An `nx` by `ny` grid of cells; vertex `j * (nx + 1) + i` is at `position(i, j)` and cell
    /// `(i, j)` is split along `diagonal(i, j)`.
    pub(crate) fn grid(
        nx: usize,
        ny: usize,
        mut position: impl FnMut(usize, usize) -> DVec3,
        mut diagonal: impl FnMut(usize, usize) -> Diagonal,
    ) -> Soup {
        let mut soup = Soup::default();
        for j in 0..=ny {
            for i in 0..=nx {
                soup.positions.push(position(i, j));
            }
        }
        let id = |i: usize, j: usize| (j * (nx + 1) + i) as u32;
        for j in 0..ny {
            for i in 0..nx {
                let [a, b, c, d] = [id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)];
                match diagonal(i, j) {
                    Diagonal::Rising => soup.faces.extend([[a, b, c], [a, c, d]]),
                    Diagonal::Falling => soup.faces.extend([[a, b, d], [b, c, d]]),
                }
            }
        }
        soup
    }

    /// Adds a vertex and returns its index.
    pub(crate) fn add_vertex(&mut self, p: DVec3) -> u32 {
        self.positions.push(p);
        (self.positions.len() - 1) as u32
    }

    /// Appends `other`, identifying each `(theirs, ours)` pair of `glue` (their vertex is
    /// dropped); returns the new index of every vertex of `other`.
    pub(crate) fn append(&mut self, other: &Soup, glue: &[(u32, u32)]) -> Vec<u32> {
        let glued: HashMap<u32, u32> = glue.iter().copied().collect();
        let map: Vec<u32> = (0..other.positions.len() as u32)
            .map(|v| match glued.get(&v) {
                Some(&ours) => ours,
                None => self.add_vertex(other.positions[v as usize]),
            })
            .collect();
        self.faces
            .extend(other.faces.iter().map(|f| f.map(|v| map[v as usize])));
        map
    }

    /// Each triangle split into four at its edge midpoints (shared between neighbours).
    pub(crate) fn subdivide(&self) -> Soup {
        let mut out = Soup {
            positions: self.positions.clone(),
            faces: Vec::with_capacity(4 * self.faces.len()),
        };
        let mut midpoints: HashMap<(u32, u32), u32> = HashMap::new();
        let mut midpoint = |out: &mut Soup, a: u32, b: u32| {
            *midpoints.entry((a.min(b), a.max(b))).or_insert_with(|| {
                let (p, q) = (out.positions[a as usize], out.positions[b as usize]);
                out.add_vertex(0.5 * (p + q))
            })
        };
        for &[a, b, c] in &self.faces {
            let (ab, bc, ca) = (
                midpoint(&mut out, a, b),
                midpoint(&mut out, b, c),
                midpoint(&mut out, c, a),
            );
            out.faces
                .extend([[a, ab, ca], [ab, b, bc], [ca, bc, c], [ab, bc, ca]]);
        }
        out
    }

    /// The star of an interior manifold vertex: its neighbours `u_0, .., u_{k-1}` in order, each
    /// with the face `(v, u_t, u_{t+1})` (faces are rotated as needed); `None` if `v` is on the
    /// boundary, has no face, or its faces do not form one closed fan.
    pub(crate) fn star(&self, v: u32) -> Option<Vec<(u32, usize)>> {
        let mut next: HashMap<u32, (u32, usize)> = HashMap::new();
        for (index, f) in self.faces.iter().enumerate() {
            if let Some(k) = f.iter().position(|&c| c == v) {
                let (x, y) = (f[(k + 1) % 3], f[(k + 2) % 3]);
                if next.insert(x, (y, index)).is_some() {
                    return None;
                }
            }
        }
        let &start = next.keys().min()?;
        let mut star = Vec::with_capacity(next.len());
        let mut at = start;
        loop {
            let &(to, face) = next.get(&at)?;
            star.push((at, face));
            at = to;
            if at == start || star.len() > next.len() {
                break;
            }
        }
        (at == start && star.len() == next.len() && star.len() >= 3).then_some(star)
    }

    /// Splits the interior vertex `v`: a copy at `at` takes over the `span` faces of its star
    /// starting with face `first` (`1 <= span < k`); with `close`, two faces with the edge
    /// `(v, copy)` join the two fans again (two coincident corners when `at` is `v`'s position),
    /// otherwise a crack opens between them. Returns the copy, or `None` if `v` is not an
    /// interior manifold vertex.
    pub(crate) fn split_vertex(
        &mut self,
        v: u32,
        at: DVec3,
        first: usize,
        span: usize,
        close: bool,
    ) -> Option<u32> {
        let star = self.star(v)?;
        let k = star.len();
        let span = span.clamp(1, k - 1);
        let copy = self.add_vertex(at);
        for t in 0..span {
            let face = &mut self.faces[star[(first + t) % k].1];
            for corner in face.iter_mut().filter(|c| **c == v) {
                *corner = copy;
            }
        }
        if close {
            let (ui, uj) = (star[first % k].0, star[(first + span) % k].0);
            self.faces.extend([[v, ui, copy], [copy, uj, v]]);
        }
        Some(copy)
    }

    /// Inserts a vertex at `at` on edge `corner` of `face` (from its corner `corner` to the
    /// next): the face becomes two, and a third face spans the whole edge and the new vertex
    /// (zero area when `at` lies on the edge). Returns the new vertex.
    pub(crate) fn insert_on_edge(&mut self, face: usize, corner: usize, at: DVec3) -> u32 {
        let f = self.faces[face];
        let (p, q, r) = (f[corner % 3], f[(corner + 1) % 3], f[(corner + 2) % 3]);
        let m = self.add_vertex(at);
        self.faces[face] = [p, m, r];
        self.faces.extend([[m, q, r], [p, q, m]]);
        m
    }

    /// The `(face, corner)` of every edge with one face (edge `corner` of the face).
    pub(crate) fn boundary_edges(&self) -> Vec<(usize, usize)> {
        let directed: HashSet<(u32, u32)> = self
            .faces
            .iter()
            .flat_map(|f| (0..3).map(move |i| (f[i], f[(i + 1) % 3])))
            .collect();
        let mut out = Vec::new();
        for (index, f) in self.faces.iter().enumerate() {
            for i in 0..3 {
                let (a, b) = (f[i], f[(i + 1) % 3]);
                if !directed.contains(&(b, a)) {
                    out.push((index, i));
                }
            }
        }
        out
    }

    /// Renumbers the vertices: vertex `v` becomes `order[v]`.
    pub(crate) fn renumber(&mut self, order: &[u32]) {
        let mut positions = vec![DVec3::ZERO; self.positions.len()];
        for (v, &to) in order.iter().enumerate() {
            positions[to as usize] = self.positions[v];
        }
        self.positions = positions;
        for f in &mut self.faces {
            *f = f.map(|v| order[v as usize]);
        }
    }

    /// The mesh.
    pub(crate) fn into_mesh(self) -> TriMesh {
        TriMesh::new(self.positions, self.faces)
            .expect("the surgery keeps the corners of every face distinct")
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn square(n: usize) -> Soup {
        Soup::grid(
            n,
            n,
            |i, j| DVec3::new(i as f64, j as f64, 0.0),
            |_, _| Diagonal::Rising,
        )
    }

    #[test]
    fn star_of_a_grid_vertex_is_its_six_neighbours_in_order() {
        let soup = square(2);
        let star = soup.star(4).expect("interior vertex");
        assert_eq!(star.len(), 6);
        for (t, &(u, face)) in star.iter().enumerate() {
            let f = soup.faces[face];
            let k = f.iter().position(|&c| c == 4).expect("corner");
            assert_eq!(f[(k + 1) % 3], u);
            assert_eq!(f[(k + 2) % 3], star[(t + 1) % 6].0);
        }
        assert!(soup.star(0).is_none(), "corner on the boundary");
    }

    #[test]
    fn closed_split_adds_a_zero_length_edge_with_two_faces() {
        let mut soup = square(2);
        let at = soup.positions[4];
        let copy = soup.split_vertex(4, at, 1, 3, true).expect("interior");
        let mesh = soup.into_mesh();
        let edge = mesh
            .edge_between(crate::VertexId(4), crate::VertexId(copy))
            .expect("the zero-length edge");
        assert_eq!(mesh.edge_lengths()[edge.index()], 0.0);
        assert!(!mesh.edge(edge).is_boundary());
        assert_eq!(mesh.validation().zero_area_faces.len(), 2);
        assert_eq!(mesh.validation().inconsistently_oriented_edges, 0);
    }

    #[test]
    fn inserted_midpoint_makes_one_zero_area_face() {
        let mut soup = square(1);
        soup.insert_on_edge(0, 0, DVec3::new(0.5, 0.0, 0.0));
        let mesh = soup.into_mesh();
        assert_eq!(mesh.validation().zero_area_faces.len(), 1);
        assert_eq!(mesh.validation().inconsistently_oriented_edges, 0);
    }

    #[test]
    fn subdivision_quadruples_faces_and_shares_midpoints() {
        let soup = square(1).subdivide();
        assert_eq!(soup.faces.len(), 8);
        assert_eq!(soup.positions.len(), 9);
    }
}

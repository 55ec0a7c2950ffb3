//! Distance matrices gathered in memory from their rows, dense or sparse, and made symmetric.

use super::{MatrixRow, RowSizeError};

/// A square matrix of distances, row-major, gathered from [`MatrixRow`]s.
#[derive(Clone, Debug, PartialEq)]
pub struct DenseMatrix {
    size: usize,
    values: Vec<f64>,
}

impl DenseMatrix {
    /// A `size` by `size` matrix, every entry `f64::INFINITY` until its row arrives.
    pub fn new(size: usize) -> Self {
        DenseMatrix {
            size,
            values: vec![f64::INFINITY; size * size],
        }
    }

    /// The number of rows (and of columns).
    pub fn size(&self) -> usize {
        self.size
    }

    /// Stores a row.
    ///
    /// # Errors
    /// [`RowSizeError`] if the row's index or length does not fit the matrix.
    pub fn insert(&mut self, row: &MatrixRow) -> Result<(), RowSizeError> {
        if row.index >= self.size || row.distances.len() != self.size {
            return Err(RowSizeError {
                index: row.index,
                length: row.distances.len(),
                size: self.size,
            });
        }
        let at = row.index * self.size;
        self.values[at..at + self.size].copy_from_slice(&row.distances);
        Ok(())
    }

    /// The entry in row `i`, column `j`.
    pub fn get(&self, i: usize, j: usize) -> f64 {
        self.values[i * self.size + j]
    }

    /// The entries, row after row.
    pub fn values(&self) -> &[f64] {
        &self.values
    }

    /// Replaces `d(i, j)` and `d(j, i)` by the smaller of the two.
    pub fn symmetrize_min(&mut self) {
        let n = self.size;
        for i in 0..n {
            for j in i + 1..n {
                let d = self.values[i * n + j].min(self.values[j * n + i]);
                self.values[i * n + j] = d;
                self.values[j * n + i] = d;
            }
        }
    }
}

/// The finite entries of a matrix of distances, as `(row, column, distance)`, gathered from
/// [`MatrixRow`]s (radius-limited rows, where `f64::INFINITY` means beyond the radius).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct SparseMatrix {
    entries: Vec<(u32, u32, f64)>,
}

impl SparseMatrix {
    /// An empty matrix.
    pub fn new() -> Self {
        SparseMatrix::default()
    }

    /// Stores the finite entries of a row.
    pub fn insert(&mut self, row: &MatrixRow) {
        self.entries.extend(row.finite_entries());
    }

    /// The entries, sorted by row and column once [`sort`](Self::sort) or
    /// [`symmetrize_min`](Self::symmetrize_min) ran, else in the order the rows came.
    pub fn entries(&self) -> &[(u32, u32, f64)] {
        &self.entries
    }

    /// Sorts the entries by row, then column.
    pub fn sort(&mut self) {
        self.entries.sort_unstable_by_key(|&(i, j, _)| (i, j));
    }

    /// Makes the matrix symmetric, each entry the smaller of `d(i, j)` and `d(j, i)`; an entry
    /// present in one direction only (within the radius one way, rounded past it the other) is
    /// taken as it is. Sorts the entries.
    pub fn symmetrize_min(&mut self) {
        let transposed: Vec<_> = self.entries.iter().map(|&(i, j, d)| (j, i, d)).collect();
        self.entries.extend(transposed);
        self.sort();
        self.entries.dedup_by(|later, kept| {
            let same = (later.0, later.1) == (kept.0, kept.1);
            if same {
                kept.2 = kept.2.min(later.2);
            }
            same
        });
    }
}

//! Distance matrices gathered in memory from their rows, dense or sparse, and made symmetric.

use super::{MatrixRow, ShapeError};

/// A matrix of distances, row-major, gathered from [`MatrixRow`]s.
#[derive(Clone, Debug, PartialEq)]
pub struct DenseMatrix {
    rows: usize,
    columns: usize,
    values: Vec<f64>,
}

impl DenseMatrix {
    /// A `rows` by `columns` matrix, every entry `f64::INFINITY` until its row arrives.
    pub fn new(rows: usize, columns: usize) -> Self {
        DenseMatrix {
            rows,
            columns,
            values: vec![f64::INFINITY; rows * columns],
        }
    }

    /// The number of rows and of columns.
    pub fn shape(&self) -> (usize, usize) {
        (self.rows, self.columns)
    }

    /// Stores a row.
    ///
    /// # Errors
    /// [`ShapeError::Row`] if the row's index or length does not fit the matrix.
    pub fn insert(&mut self, row: &MatrixRow) -> Result<(), ShapeError> {
        if row.index >= self.rows || row.distances.len() != self.columns {
            return Err(ShapeError::Row {
                index: row.index,
                length: row.distances.len(),
                rows: self.rows,
                columns: self.columns,
            });
        }
        let at = row.index * self.columns;
        self.values[at..at + self.columns].copy_from_slice(&row.distances);
        Ok(())
    }

    /// The entry in row `i`, column `j`.
    ///
    /// # Panics
    /// If `i` or `j` is out of the matrix, as slice indexing does.
    pub fn get(&self, i: usize, j: usize) -> f64 {
        assert!(j < self.columns, "column {j} of {}", self.columns);
        self.values[i * self.columns + j]
    }

    /// The entries, row after row.
    pub fn values(&self) -> &[f64] {
        &self.values
    }

    /// Replaces `d(i, j)` and `d(j, i)` by the smaller of the two, in a matrix among selected
    /// vertices (the same vertices as sources and as targets).
    ///
    /// # Errors
    /// [`ShapeError::NotSquare`] if the matrix is not square.
    pub fn symmetrize_min(&mut self) -> Result<(), ShapeError> {
        if self.rows != self.columns {
            return Err(ShapeError::NotSquare {
                rows: self.rows,
                columns: self.columns,
            });
        }
        let n = self.rows;
        for i in 0..n {
            for j in i + 1..n {
                let d = self.values[i * n + j].min(self.values[j * n + i]);
                self.values[i * n + j] = d;
                self.values[j * n + i] = d;
            }
        }
        Ok(())
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

    /// Makes a matrix among selected vertices symmetric, each entry the smaller of `d(i, j)`
    /// and `d(j, i)`; an entry
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

//! The files of the `matrix` command: NumPy `.npy` (dense, rows written in place as they come),
//! Matrix Market `.mtx` (sparse, entries appended as they come) and CSV (small, written whole).
//! Every error names the file.

use crate::distance::Shortest;
use exact_geodesics::matrix::DenseMatrix;
use std::fs::File;
use std::io::{BufWriter, Seek, SeekFrom, Write};
use std::path::{Path, PathBuf};

/// The format of an output file, by its extension.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Format {
    Npy,
    Mtx,
    Csv,
}

impl Format {
    pub fn of(path: &Path) -> Result<Format, String> {
        match path.extension().and_then(|e| e.to_str()) {
            Some("npy") => Ok(Format::Npy),
            Some("mtx") => Ok(Format::Mtx),
            Some("csv") => Ok(Format::Csv),
            _ => Err(format!(
                "{}: unknown output format (expected .npy, .mtx or .csv)",
                path.display()
            )),
        }
    }
}

/// An output file with errors that name it.
struct Named {
    path: PathBuf,
    file: BufWriter<File>,
}

impl Named {
    fn create(path: &Path) -> Result<Named, String> {
        let file = File::create(path).map_err(|e| format!("{}: {e}", path.display()))?;
        Ok(Named {
            path: path.to_owned(),
            file: BufWriter::new(file),
        })
    }

    fn fail(&self, e: std::io::Error) -> String {
        format!("{}: {e}", self.path.display())
    }

    fn write(&mut self, bytes: &[u8]) -> Result<(), String> {
        self.file.write_all(bytes).map_err(|e| self.fail(e))
    }

    fn seek(&mut self, at: u64) -> Result<(), String> {
        self.file
            .seek(SeekFrom::Start(at))
            .map(drop)
            .map_err(|e| self.fail(e))
    }

    fn finish(mut self) -> Result<(), String> {
        self.file.flush().map_err(|e| self.fail(e))
    }
}

/// A `size` by `size` array of little-endian `f64` in NumPy's format 1.0, every row written at
/// its place as it arrives.
pub struct NpyFile {
    out: Named,
    size: usize,
    data_start: u64,
}

impl NpyFile {
    pub fn create(path: &Path, size: usize) -> Result<NpyFile, String> {
        let mut out = Named::create(path)?;
        let dict =
            format!("{{'descr': '<f8', 'fortran_order': False, 'shape': ({size}, {size}), }}");
        // Magic (6 bytes), version (2), header length (2), then the header: padded with spaces
        // and ended by a newline so that the data starts on a multiple of 64 bytes.
        let unpadded = 10 + dict.len() + 1;
        let header_len = dict.len() + 1 + (64 - unpadded % 64) % 64;
        let mut header = b"\x93NUMPY\x01\x00".to_vec();
        let len = u16::try_from(header_len).expect("a short header");
        header.extend_from_slice(&len.to_le_bytes());
        header.extend_from_slice(dict.as_bytes());
        header.resize(10 + header_len - 1, b' ');
        header.push(b'\n');
        out.write(&header)?;
        let data_start = header.len() as u64;
        let bytes = data_start + 8 * (size as u64) * (size as u64);
        out.file.get_ref().set_len(bytes).map_err(|e| out.fail(e))?;
        Ok(NpyFile {
            out,
            size,
            data_start,
        })
    }

    pub fn row(&mut self, index: usize, distances: &[f64]) -> Result<(), String> {
        self.out
            .seek(self.data_start + 8 * (index * self.size) as u64)?;
        let bytes: Vec<u8> = distances.iter().flat_map(|d| d.to_le_bytes()).collect();
        self.out.write(&bytes)
    }

    pub fn finish(self) -> Result<(), String> {
        self.out.finish()
    }
}

/// Width of the entry count in a Matrix Market size line, filled in at the end.
const COUNT_WIDTH: usize = 20;

/// A `size` by `size` sparse matrix in Matrix Market coordinate form (1-based indices),
/// entries appended as they arrive and counted into the size line at the end.
pub struct MtxFile {
    out: Named,
    size_line_at: u64,
    size: usize,
    entries: u64,
}

impl MtxFile {
    pub fn create(path: &Path, size: usize, comment: &str) -> Result<MtxFile, String> {
        let mut out = Named::create(path)?;
        let head = format!("%%MatrixMarket matrix coordinate real general\n% {comment}\n");
        out.write(head.as_bytes())?;
        let mut file = MtxFile {
            out,
            size_line_at: head.len() as u64,
            size,
            entries: 0,
        };
        file.size_line()?;
        Ok(file)
    }

    /// The size line, of the same length whatever the count (padded to `COUNT_WIDTH`).
    fn size_line(&mut self) -> Result<(), String> {
        let (n, count) = (self.size, self.entries);
        self.out
            .write(format!("{n} {n} {count:<COUNT_WIDTH$}\n").as_bytes())
    }

    pub fn entries(
        &mut self,
        entries: impl Iterator<Item = (u32, u32, f64)>,
    ) -> Result<(), String> {
        let mut text = String::new();
        for (i, j, d) in entries {
            text.push_str(&format!("{} {} {}\n", i + 1, j + 1, Shortest(d)));
            self.entries += 1;
        }
        self.out.write(text.as_bytes())
    }

    pub fn finish(mut self) -> Result<(), String> {
        self.out.seek(self.size_line_at)?;
        self.size_line()?;
        self.out.finish()
    }
}

/// The whole matrix as CSV: a header `source,v<j>...` naming the columns' vertices, then one
/// row per source vertex (`inf` where unreachable or beyond the maximum distance).
pub fn write_csv(path: &Path, vertices: &[u32], matrix: &DenseMatrix) -> Result<(), String> {
    let mut out = Named::create(path)?;
    let mut text = String::from("source");
    for v in vertices {
        text.push_str(&format!(",v{v}"));
    }
    text.push('\n');
    for (i, v) in vertices.iter().enumerate() {
        text.push_str(&v.to_string());
        for j in 0..vertices.len() {
            text.push_str(&format!(",{}", Shortest(matrix.get(i, j))));
        }
        text.push('\n');
        out.write(text.as_bytes())?;
        text.clear();
    }
    out.finish()
}

//! Drawings of results, as text in standard formats.
//!
//! Unstable: drawings serve the command-line tool and the reproductions, and their form may
//! change; they are not part of the library's API for distances and paths.

pub mod svg;

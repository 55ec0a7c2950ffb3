//! Drawings of results, as text in standard formats.

pub mod svg;

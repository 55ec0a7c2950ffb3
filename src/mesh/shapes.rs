//! Meshes the program generates itself: for tests, examples and the README's first command.

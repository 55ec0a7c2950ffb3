//! Reading and writing OBJ, OFF and PLY (ASCII and binary) meshes.

//! Lecture 03: boxes by slabs, polygons and triangles.

//! Lecture 04: cylinders and cones, transformed objects and their normals.

//! Lecture 02: ray casting, spheres, planes and the closest hit of a group.

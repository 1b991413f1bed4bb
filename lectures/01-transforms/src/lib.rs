//! Lecture 01: vectors, transforms, look-at and the pinhole camera.

//! What lecture 01 lends the stages (`stages::Lent`): its camera, each pixel's primary ray, which
//! every stage draws with.

use raylab::Scene;

use crate::stages::{Lent, PixelRays};

/// Lends lecture 01's camera.
pub fn lend(lent: &mut Lent) {
    lent.camera = Some(pixel_rays);
}

/// The primary ray of each pixel of `scene`, from the student's camera.
fn pixel_rays(scene: &Scene) -> Result<PixelRays, String> {
    let camera = l01_transforms::Camera::from_scene(&scene.camera, scene.width, scene.height)
        .map_err(|e| e.to_string())?;
    let (w, h) = (scene.width, scene.height);
    Ok(Box::new(move |x, y| camera.pixel_ray(x, y, w, h)))
}

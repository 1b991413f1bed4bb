//! What lecture 02 lends the stages (`stages::Lent`): its group of spheres and planes (stage 02's
//! intersections) and its geometry images, which the geometry checks and a failed picture's
//! diagnosis draw.

use raylab::{Color, Image, Intersector, Scene};

use crate::stages::{Finds, Geometry, GeometryImage, Lent};

/// Lends lecture 02's group and geometry images.
pub fn lend(lent: &mut Lent) {
    lent.finders.push((Finds::Group, |scene| Box::new(l02_ray_casting::Group::new(&scene.objects))));
    lent.geometry = Some(Geometry { image, id_color });
}

/// Geometry image `which` of `scene` through `objects`, from the student's camera.
fn image(scene: &Scene, which: GeometryImage, objects: &dyn Intersector) -> Result<Image, String> {
    use l02_ray_casting::{depth_image, normal_image, object_id_image};
    let camera = l01_transforms::Camera::from_scene(&scene.camera, scene.width, scene.height)
        .map_err(|e| e.to_string())?;
    let (w, h) = (scene.width, scene.height);
    Ok(match which {
        GeometryImage::Id => object_id_image(&camera, &objects, w, h),
        GeometryImage::Depth => depth_image(&camera, &objects, w, h),
        GeometryImage::Normal => normal_image(&camera, &objects, w, h),
    })
}

/// The colour of object `index` in an id image.
fn id_color(index: usize) -> Color {
    l02_ray_casting::id_color(Some(index))
}

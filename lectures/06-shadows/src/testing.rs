//! Test support: a tiny brute-force [`Intersector`] over spheres, planes and
//! boxes (this lecture may not use lectures 02–04, so the tests carry their
//! own), scene objects to feed it, and a seeded pseudo-random generator.

use raylab::scene::{Material, Object, Shape};
use raylab::{Color, Float, Hit, Intersector, Interval, Ray, Vec3};

/// The scene's spheres, planes and boxes as an [`Intersector`]; other shapes
/// and transformed objects are never hit. `skip` leaves one object out: for
/// convex objects that is an exact alternative to the offset (a convex
/// surface cannot shadow its own lit side), which the tests compare against.
#[derive(Clone, Copy, Debug)]
pub struct Shapes<'a> {
    pub objects: &'a [Object],
    pub skip: Option<usize>,
}

impl<'a> Shapes<'a> {
    pub fn new(objects: &'a [Object]) -> Self {
        Self { objects, skip: None }
    }

    /// The same objects without object `index`.
    pub fn without(self, index: usize) -> Self {
        Self { skip: Some(index), ..self }
    }
}

impl Intersector for Shapes<'_> {
    fn closest_hit(&self, ray: &Ray, range: Interval) -> Option<Hit> {
        let mut range = range;
        let mut closest = None;
        for (index, object) in self.objects.iter().enumerate() {
            if Some(index) == self.skip || object.transform.is_some() {
                continue;
            }
            if let Some(mut hit) = hit_shape(&object.shape, ray, range) {
                range = range.with_max(hit.t);
                hit.object = index;
                hit.material = object.material;
                closest = Some(hit);
            }
        }
        closest
    }

    fn any_hit(&self, ray: &Ray, range: Interval) -> bool {
        self.objects.iter().enumerate().any(|(index, object)| {
            Some(index) != self.skip
                && object.transform.is_none()
                && hit_shape(&object.shape, ray, range).is_some()
        })
    }
}

fn hit_shape(shape: &Shape, ray: &Ray, range: Interval) -> Option<Hit> {
    match *shape {
        Shape::Sphere { center, radius } => hit_sphere(ray, center, radius, range),
        Shape::Plane { normal, offset } => hit_plane(ray, normal, offset, range),
        Shape::Box { min, max } => hit_box(ray, min, max, range),
        _ => None,
    }
}

/// The nearer root in `range`, else the farther one.
fn pick(t0: Float, t1: Float, range: Interval) -> Option<Float> {
    [t0, t1].into_iter().find(|&t| range.contains(t))
}

/// The sphere by the robust quadratic (as lecture 02's `hit_sphere_stable`):
/// discriminant a·(r − l)(r + l) with l the distance from the centre to the
/// line, roots c/q and q/a with q = −(b' + sign(b')·√Δ).
pub fn hit_sphere(ray: &Ray, center: Vec3, radius: Float, range: Interval) -> Option<Hit> {
    let f = ray.origin - center;
    let a = ray.dir.dot(ray.dir);
    let b_half = f.dot(ray.dir);
    let c = f.dot(f) - radius * radius;
    let l = (f - (b_half / a) * ray.dir).length();
    let discriminant = a * (radius - l) * (radius + l);
    if discriminant < 0.0 {
        return None;
    }
    let q = -(b_half + b_half.signum() * discriminant.sqrt());
    let (t0, t1) = if q == 0.0 { (0.0, 0.0) } else { ((c / q).min(q / a), (c / q).max(q / a)) };
    let t = pick(t0, t1, range)?;
    Some(Hit::new(ray, t, ray.at(t) - center))
}

/// The plane n·p = offset: t = (offset − n·o)/(n·d); parallel rays miss.
pub fn hit_plane(ray: &Ray, normal: Vec3, offset: Float, range: Interval) -> Option<Hit> {
    let denominator = normal.dot(ray.dir);
    if denominator == 0.0 {
        return None;
    }
    let t = (offset - normal.dot(ray.origin)) / denominator;
    range.contains(t).then(|| Hit::new(ray, t, normal))
}

/// The box min ≤ p ≤ max by slabs: the ray is inside from the last entry to
/// the first exit; the normal is that of the face crossed there.
pub fn hit_box(ray: &Ray, min: Vec3, max: Vec3, range: Interval) -> Option<Hit> {
    let (mut t_enter, mut t_exit) = (Float::NEG_INFINITY, Float::INFINITY);
    let (mut axis_enter, mut axis_exit) = (0, 0);
    for axis in 0..3 {
        let (o, d) = (ray.origin[axis], ray.dir[axis]);
        if d == 0.0 {
            // Parallel to this slab: inside it for every t, or never.
            if o < min[axis] || o > max[axis] {
                return None;
            }
            continue;
        }
        let (ta, tb) = ((min[axis] - o) / d, (max[axis] - o) / d);
        let (near, far) = if ta < tb { (ta, tb) } else { (tb, ta) };
        if near > t_enter {
            (t_enter, axis_enter) = (near, axis);
        }
        if far < t_exit {
            (t_exit, axis_exit) = (far, axis);
        }
    }
    if t_enter > t_exit {
        return None;
    }
    // The entry face's outward normal points against the ray, the exit face's along it.
    let mut normal = Vec3::ZERO;
    let t = if range.contains(t_enter) {
        normal[axis_enter] = -ray.dir[axis_enter].signum();
        t_enter
    } else if range.contains(t_exit) {
        normal[axis_exit] = ray.dir[axis_exit].signum();
        t_exit
    } else {
        return None;
    };
    Some(Hit::new(ray, t, normal))
}

/// A world-space object of material `material`.
pub fn object(shape: Shape, material: usize) -> Object {
    Object { shape, material, transform: None }
}

pub fn sphere(center: Vec3, radius: Float, material: usize) -> Object {
    object(Shape::Sphere { center, radius }, material)
}

pub fn plane(normal: Vec3, offset: Float, material: usize) -> Object {
    object(Shape::Plane { normal, offset }, material)
}

/// A white diffuse material that lets `transparent` through.
pub fn see_through(transparent: Color) -> Material {
    Material { transparent, ..Material::default() }
}

/// SplitMix64 (Steele, Lea, Flood 2014): a tiny seeded generator, so the
/// tests draw the same rays on every machine.
pub struct Rng(u64);

impl Rng {
    pub fn new(seed: u64) -> Self {
        Self(seed)
    }

    fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    /// Uniform in [0, 1), with 53 random bits.
    pub fn unit(&mut self) -> f64 {
        (self.next_u64() >> 11) as f64 / (1u64 << 53) as f64
    }

    /// Uniform in [lo, hi), rounded to `Float`.
    pub fn range(&mut self, lo: f64, hi: f64) -> Float {
        (lo + (hi - lo) * self.unit()) as Float
    }

    /// Uniform on the unit sphere (rejection from the cube), rounded to `Float`.
    pub fn direction(&mut self) -> Vec3 {
        loop {
            let v = [self.unit() * 2.0 - 1.0, self.unit() * 2.0 - 1.0, self.unit() * 2.0 - 1.0];
            let len2 = v[0] * v[0] + v[1] * v[1] + v[2] * v[2];
            if len2 > 1e-4 && len2 <= 1.0 {
                let len = len2.sqrt();
                return Vec3::new((v[0] / len) as Float, (v[1] / len) as Float, (v[2] / len) as Float)
                    .normalize();
            }
        }
    }

    /// Uniform in the ball of radius `radius` around the origin.
    pub fn in_ball(&mut self, radius: f64) -> Vec3 {
        self.direction() * (radius * self.unit().cbrt()) as Float
    }
}

/// The unit in the last place of `x`: the gap from |x| to the next float up.
pub fn ulp(x: Float) -> Float {
    let x = x.abs();
    x.next_up() - x
}

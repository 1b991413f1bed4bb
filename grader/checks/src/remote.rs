//! The student's functions the hidden checks call, by name.
//!
//! Graded as a submission, a hidden check runs in the judge alone: its code, inputs and answers
//! are built into no binary and lie in no file the student's process can read. Each call of the
//! student's code it makes goes to the subject (`raylab-checks serve --channel ADDR`, built from
//! the student's lectures without the hidden checks), which makes the call and sends the value
//! back (`judge::call`). Graded locally, the call is made in place.

use serde::{Deserialize, Serialize};

#[allow(unused_imports, reason = "each lecture's types are used where its feature is on")]
use raylab::{Float, Hit, Interval, Mat4, Ray, Vec3};

/// Declares the calls: each a variant of [`Call`], an arm of [`answer`] (behind its lecture's
/// feature) and a function of the same name that makes the call through [`crate::judge::call`]
/// (the judge knows calls only as bytes: [`answer_encoded`] makes one).
macro_rules! remote_calls {
    ($($feature:literal fn $name:ident($($arg:ident: $ty:ty),*) -> $ret:ty = $body:expr;)+) => {
        /// A call of the student's code that the judge asks of the subject.
        #[derive(Debug, Serialize, Deserialize)]
        #[allow(non_camel_case_types, reason = "each variant is named as the function it calls")]
        pub enum Call {
            $($name { $($arg: $ty),* }),+
        }

        /// Makes `call` with the student's code: its value, encoded for the judge.
        pub fn answer(call: Call) -> Result<Vec<u8>, String> {
            match call {
                $(
                    #[allow(unused_variables)]
                    Call::$name { $($arg),* } => {
                        #[cfg(feature = $feature)]
                        {
                            let value: $ret = $body;
                            return postcard::to_stdvec(&value).map_err(|e| e.to_string());
                        }
                        #[allow(unreachable_code)]
                        Err(format!("lecture {} is not in this build", &$feature[1..]))
                    }
                )+
            }
        }

        $(
            #[doc = concat!("`", stringify!($name), "` of the student's code, made where the student's code runs.")]
            #[allow(dead_code, reason = "called by the hidden checks, which only instructors' builds have")]
            pub fn $name($($arg: $ty),*) -> $ret {
                let call = Call::$name { $($arg),* };
                let bytes = postcard::to_stdvec(&call).expect("a call encodes");
                crate::judge::call(bytes, move || answer(call))
            }
        )+
    };
}

remote_calls! {
    "l01" fn rotate_z(angle: Float) -> Mat4 = l01_transforms::rotate_z(angle);
    "l01" fn transform_vector(m: Mat4, v: Vec3) -> Vec3 = l01_transforms::transform_vector(&m, v);
    "l02" fn hit_sphere_stable(ray: Ray, center: Vec3, radius: Float, range: Interval) -> Option<Hit> =
        l02_ray_casting::hit_sphere_stable(&ray, center, radius, range);
    "l03" fn hit_slabs(ray: Ray, min: Vec3, max: Vec3, range: Interval) -> Option<(Float, Float)> =
        l03_polygons_triangles::hit_slabs(&ray, min, max, range);
    "l05" fn lambert(n: Vec3, l: Vec3) -> Float = l05_shading::lambert(n, l);
    "l07" fn refract(i: Vec3, n: Vec3, eta_ratio: Float) -> Option<Vec3> =
        l07_reflection_refraction::refract(i, n, eta_ratio);
    "l09" fn aabb_surface_area(min: Vec3, max: Vec3) -> Float =
        l09_acceleration::Aabb::new(min, max).surface_area();
}

/// Makes the call `bytes` encode (the judge's frame) with the student's code: its value, encoded.
pub fn answer_encoded(bytes: &[u8]) -> Result<Vec<u8>, String> {
    let call: Call = postcard::from_bytes(bytes).map_err(|e| format!("a call: {e}"))?;
    answer(call)
}

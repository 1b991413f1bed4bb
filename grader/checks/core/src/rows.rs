//! The student's functions as the checks call them: a row per function, its signature written
//! once outside the lecture ([`student_fns!`]), which yields the judged proxy (its value through
//! `judge::student`), its type, and the call a hidden check makes of it (`remote.rs`).

/// Functions of a lecture crate, each wrapped so that its value goes through
/// `judge::student`: a lecture's checks import these instead of the crate's own,
/// and their code reads as before. The signature is written once outside the
/// lecture, here, and a row may add:
///
/// - `as NameFn`: the function's type, for the checks that take the function under test as
///   an argument (the lecture's, or a planted mistake in the checks' tests);
/// - `= EXPR`: what the row calls, where that is not the crate's function of the same name
///   (a method: `Aabb::new(min, max).surface_area()`);
/// - `=> EXPR`: the proxy's whole body, where the value crosses otherwise than whole (a lecture's
///   type field by field, `boxed(|| a.union(b))`; a generator's state with it);
/// - `, remote`: the call a hidden check makes of it, as a module of the same name (`remote.rs`:
///   `name::call`, made by the subject, and `name::answer`, the subject's side).
///
/// ```ignore
/// student_fns! { l02_ray_casting:
///     fn hit_plane(ray: &Ray, normal: Vec3, offset: Float, range: Interval) -> Option<Hit> as PlaneFn;
///     fn hit_sphere_stable(ray: &Ray, center: Vec3, radius: Float, range: Interval) -> Option<Hit>, remote;
/// }
/// ```
#[macro_export]
macro_rules! student_fns {
    ($krate:ident: $(
        fn $name:ident($($arg:ident: $ty:ty),* $(,)?) -> $ret:ty $(as $alias:ident)? $(= $body:expr)? $(=> $proxy:expr)? $(, $remote:ident)?;
    )+) => {
        $(
            #[doc = concat!("`", stringify!($krate), "::", stringify!($name), "`, its value taken through `judge::student`.")]
            #[track_caller]
            pub(super) fn $name($($arg: $ty),*) -> $ret {
                $crate::rows::proxy_body!([$($proxy)?] $crate::judge::student(|| $crate::rows::row_call!([$($body)?] $krate::$name($($arg),*))))
            }
            $crate::rows::fn_type! { [$($alias)?] $name ($($ty),*) -> $ret }
            $crate::rows::remote_row! { [$($remote)?] $krate::$name($($arg: $ty),*) -> $ret = [$($body)?] }
        )+
    };
}
pub use crate::student_fns;

/// What a row of [`student_fns!`] calls: its `= EXPR`, or the crate's function of its name.
#[doc(hidden)]
#[macro_export]
macro_rules! row_call {
    ([] $krate:ident::$name:ident($($arg:ident),*)) => {
        $krate::$name($($arg),*)
    };
    ([$body:expr] $krate:ident::$name:ident($($arg:ident),*)) => {
        $body
    };
}
pub use crate::row_call;

/// A proxy's body: the row's `=> EXPR`, or its value taken whole through `judge::student`.
#[doc(hidden)]
#[macro_export]
macro_rules! proxy_body {
    ([] $whole:expr) => {
        $whole
    };
    ([$proxy:expr] $whole:expr) => {
        $proxy
    };
}
pub use crate::proxy_body;

/// The type a row of [`student_fns!`] names, `pub(super) type NameFn = fn(…) -> …;`, or nothing
/// for a row without `as NameFn`.
#[doc(hidden)]
#[macro_export]
macro_rules! fn_type {
    ([] $name:ident ($($ty:ty),*) -> $ret:ty) => {};
    ([$alias:ident] $name:ident ($($ty:ty),*) -> $ret:ty) => {
        #[doc = concat!("The type of `", stringify!($name), "` and of the mistakes planted in its place.")]
        pub(super) type $alias = fn($($ty),*) -> $ret;
    };
}
pub use crate::fn_type;

/// A row of [`student_fns!`] marked `remote`: `mod name` beside its proxy, with the row's
/// `NAME`, its `call` (a hidden check's, through [`call`]) and its `answer` (the subject's);
/// nothing for the other rows.
#[doc(hidden)]
#[macro_export]
macro_rules! remote_row {
    ([] $($row:tt)*) => {};
    ([remote] $krate:ident::$name:ident($($arg:ident: $ty:ty),*) -> $ret:ty = [$($body:expr)?]) => {
        #[doc = concat!("`", stringify!($name), "` as a hidden check calls it (`remote.rs`).")]
        #[allow(dead_code, reason = "called by the hidden checks, which only instructors' builds have")]
        pub mod $name {
            use super::*;

            /// The call's name in the judge's frames.
            pub const NAME: &str = concat!(stringify!($krate), "::", stringify!($name));

            /// The call, made by the student's code where it runs.
            pub fn call($($arg: $ty),*) -> $ret {
                $crate::remote::call(NAME, &($($arg,)*), answer)
            }

            /// The subject's side: the arguments decoded, the call made, its value encoded.
            pub fn answer(args: &[u8]) -> Result<Vec<u8>, String> {
                let ($($arg,)*): ($(<$ty as $crate::remote::Param<'_>>::Owned,)*) =
                    $crate::remote::postcard::from_bytes(args).map_err(|e| format!("{NAME}'s arguments: {e}"))?;
                $(let $arg: $ty = $crate::remote::Param::lend(&$arg);)*
                let value: $ret = $crate::rows::row_call!([$($body)?] $krate::$name($($arg),*));
                $crate::remote::postcard::to_stdvec(&value).map_err(|e| e.to_string())
            }
        }
    };
}
pub use crate::remote_row;

//! The student's functions the hidden checks call, by name.
//!
//! Graded as a submission, a hidden check runs in the judge alone: its code, inputs and answers
//! are built into no binary and lie in no file the student's process can read. Each call of the
//! student's code it makes goes to the subject (`raylab-checks serve --channel ADDR`, built from
//! the student's lectures without the hidden checks), which makes the call and sends the value
//! back (`judge::call`). Graded locally, the call is made in place.
//!
//! The calls are the rows of `judge::student_fns!` marked `remote`: each yields a module of the
//! function's name beside its proxy, with the call ([`remote_row!`]); [`ANSWERS`] is what the
//! subject can answer.

use serde::de::DeserializeOwned;
use serde::{Deserialize, Serialize};

#[allow(unused_imports, reason = "each lecture's types are used where its feature is on")]
use raylab::{Float, Interval, Mat4, Vec3};

/// A call of the student's code that the judge asks of the subject: the row's name
/// (`crate::function`) and its arguments, encoded.
#[derive(Debug, Serialize, Deserialize)]
struct Call {
    function: String,
    args: Vec<u8>,
}

/// The subject's side of a call: its arguments encoded in, its value encoded out.
type Answer = fn(&[u8]) -> Result<Vec<u8>, String>;

/// The calls the subject makes, by name: each row of `student_fns!` marked `remote`.
const ANSWERS: &[(&str, Answer)] = &[
    #[cfg(feature = "l01")]
    (crate::lectures::l01::common::rotate_z::NAME, crate::lectures::l01::common::rotate_z::answer),
    #[cfg(feature = "l01")]
    (
        crate::lectures::l01::common::transform_vector::NAME,
        crate::lectures::l01::common::transform_vector::answer,
    ),
    #[cfg(feature = "l02")]
    (
        crate::lectures::l02::common::hit_sphere_stable::NAME,
        crate::lectures::l02::common::hit_sphere_stable::answer,
    ),
    #[cfg(feature = "l03")]
    (crate::lectures::l03::common::hit_slabs::NAME, crate::lectures::l03::common::hit_slabs::answer),
    #[cfg(feature = "l05")]
    (crate::lectures::l05::common::lambert::NAME, crate::lectures::l05::common::lambert::answer),
    #[cfg(feature = "l07")]
    (crate::lectures::l07::common::refract::NAME, crate::lectures::l07::common::refract::answer),
    #[cfg(feature = "l09")]
    (
        crate::lectures::l09::common::aabb_surface_area::NAME,
        crate::lectures::l09::common::aabb_surface_area::answer,
    ),
];

/// Makes the call `bytes` encode (the judge's frame) with the student's code: its value, encoded.
pub fn answer_encoded(bytes: &[u8]) -> Result<Vec<u8>, String> {
    let call: Call = postcard::from_bytes(bytes).map_err(|e| format!("a call: {e}"))?;
    let Some((_, answer)) = ANSWERS.iter().find(|(name, _)| *name == call.function) else {
        return Err(format!("{} is not in this build", call.function));
    };
    answer(&call.args)
}

/// Makes the call of `function` (a row's `NAME`) with `args`, where the student's code runs:
/// in place locally (`answer`), through the subject when judged.
pub fn call<A: Serialize, T: DeserializeOwned>(function: &str, args: &A, answer: Answer) -> T {
    let args = postcard::to_stdvec(args).expect("a call's arguments encode");
    let call = postcard::to_stdvec(&Call { function: function.to_owned(), args: args.clone() })
        .expect("a call encodes");
    crate::judge::call(call, move || answer(&args))
}

/// An argument of a remote call as its row writes it: decoded as `Owned`, passed on as the row's
/// type (a reference to it, or a copy).
pub trait Param<'a> {
    type Owned: DeserializeOwned;
    fn lend(owned: &'a Self::Owned) -> Self;
}

impl<'a, T: DeserializeOwned> Param<'a> for &'a T {
    type Owned = T;
    fn lend(owned: &'a T) -> &'a T {
        owned
    }
}

/// The argument types passed by value.
macro_rules! by_value {
    ($($t:ty),+) => {
        $(impl Param<'_> for $t {
            type Owned = $t;
            fn lend(owned: &$t) -> $t {
                *owned
            }
        })+
    };
}
by_value!(Float, Vec3, Interval, Mat4);

/// A row of `judge::student_fns!` marked `remote`: `mod name` beside its proxy, with the row's
/// `NAME`, its `call` (a hidden check's, through [`call`]) and its `answer` (the subject's);
/// nothing for the other rows.
macro_rules! remote_row {
    ([] $($row:tt)*) => {};
    ([remote] $krate:ident::$name:ident($($arg:ident: $ty:ty),*) -> $ret:ty = [$($body:expr)?]) => {
        #[doc = concat!("`", stringify!($name), "` as a hidden check calls it (`remote.rs`).")]
        #[allow(dead_code, reason = "called by the hidden checks, which only instructors' builds have")]
        pub(crate) mod $name {
            use super::*;

            /// The call's name in the judge's frames.
            pub(crate) const NAME: &str = concat!(stringify!($krate), "::", stringify!($name));

            /// The call, made by the student's code where it runs.
            pub(crate) fn call($($arg: $ty),*) -> $ret {
                crate::remote::call(NAME, &($($arg,)*), answer)
            }

            /// The subject's side: the arguments decoded, the call made, its value encoded.
            pub(crate) fn answer(args: &[u8]) -> Result<Vec<u8>, String> {
                let ($($arg,)*): ($(<$ty as crate::remote::Param<'_>>::Owned,)*) =
                    postcard::from_bytes(args).map_err(|e| format!("{NAME}'s arguments: {e}"))?;
                $(let $arg: $ty = crate::remote::Param::lend(&$arg);)*
                let value: $ret = crate::judge::row_call!([$($body)?] $krate::$name($($arg),*));
                postcard::to_stdvec(&value).map_err(|e| e.to_string())
            }
        }
    };
}
pub(crate) use remote_row;

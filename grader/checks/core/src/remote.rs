//! The student's functions the hidden checks call, by name.
//!
//! Graded as a submission, a hidden check runs in the judge alone: its code, inputs and answers
//! are built into no binary and lie in no file the student's process can read. Each call of the
//! student's code it makes goes to the subject (`raylab-checks serve --channel ADDR`, built from
//! the student's lectures without the hidden checks), which makes the call and sends the value
//! back (`judge::call`). Graded locally, the call is made in place.
//!
//! The calls are the rows of `rows::student_fns!` marked `remote`: each yields a module of the
//! function's name beside its proxy, with its call and the subject's answer (`rows::remote_row!`);
//! `lectures::ANSWERS` lists what the subject answers.

#[doc(hidden)]
pub use postcard;
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
pub type Answer = fn(&[u8]) -> Result<Vec<u8>, String>;

/// Makes the call `bytes` encode (the judge's frame) with the student's code, by `answers` (the
/// calls this build answers, by name: `lectures::ANSWERS`): its value, encoded.
pub fn answer_encoded(answers: &[(&str, Answer)], bytes: &[u8]) -> Result<Vec<u8>, String> {
    let call: Call = postcard::from_bytes(bytes).map_err(|e| format!("a call: {e}"))?;
    let Some((_, answer)) = answers.iter().find(|(name, _)| *name == call.function) else {
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

//! The course's worked problems as a gallery (tooling of `mechkit gallery`, not library API):
//! the case file (`cases.jsonl`: inputs, the quantity asked, the expected value and its
//! tolerance, [`Case`]), the scripts of command-line calls that answer the one-line
//! questions ([`Script`]), the comparison of a computed value with the expected one
//! ([`Check`]) and the validation report ([`report`]).
//!
//! Running a case is `commands/gallery_run.rs`'s part (scenarios through
//! `mechkit::scenario`, scripts through this same binary): this module never knows the
//! answer, only how to compare one.

mod case;
mod check;
pub mod report;
mod script;

#[cfg(test)]
mod book;
#[cfg(test)]
mod tests;

pub use case::{Case, case_of};
pub use check::Check;
pub use report::CaseRun;
pub use script::Script;

//! Whole numbers given to options (counts and seeds), parsed with a message that says what is
//! wanted.

/// A count (a whole number ≥ 0) of an option: a negative or fractional value gets a message
/// that says what is wanted instead of Rust's "invalid digit found in string".
pub(super) fn whole_count(text: &str) -> Result<usize, String> {
    whole_u64(text).and_then(|n| usize::try_from(n).map_err(|_| format!("`{text}` is too large")))
}

/// A whole number ≥ 0 (a count or a seed), with our own message.
pub(super) fn whole_u64(text: &str) -> Result<u64, String> {
    text.trim()
        .parse::<u64>()
        .map_err(|_| format!("`{text}` is not a whole number ≥ 0 (a count, e.g. 20)"))
}

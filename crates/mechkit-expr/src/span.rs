//! Byte spans into a formula's source text, and the caret line that points at them.

use std::fmt;

/// A half-open byte range `start..end` into the source text of a formula.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub struct Span {
    /// First byte of the span.
    pub start: usize,
    /// One past the last byte of the span.
    pub end: usize,
}

impl Span {
    /// A span from `start` to `end` (bytes).
    pub fn new(start: usize, end: usize) -> Self {
        assert!(start <= end, "span start {start} is after its end {end}");
        Self { start, end }
    }

    /// The smallest span covering both.
    #[must_use]
    pub fn to(self, other: Span) -> Span {
        Span::new(self.start.min(other.start), self.end.max(other.end))
    }

    /// The same span moved right by `offset` bytes (to place a formula inside a larger file).
    #[must_use]
    pub fn shifted(self, offset: usize) -> Span {
        Span::new(self.start + offset, self.end + offset)
    }

    /// 1-based column of the span's start within `source` (counted in characters).
    pub fn column(self, source: &str) -> usize {
        let start = self.start.min(source.len());
        source[..floor_char_boundary(source, start)].chars().count() + 1
    }
}

impl fmt::Display for Span {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}..{}", self.start, self.end)
    }
}

fn floor_char_boundary(s: &str, mut i: usize) -> usize {
    while i > 0 && !s.is_char_boundary(i) {
        i -= 1;
    }
    i
}

/// Renders `source` with a caret line under `span`:
///
/// ```text
/// -m*g*Dmgg*v
///      ^^^^
/// ```
///
/// Only the first line of a multi-line source is shown. The caret line has at least one `^`.
pub fn caret_lines(source: &str, span: Span) -> String {
    let line = source.lines().next().unwrap_or("");
    let start = floor_char_boundary(line, span.start.min(line.len()));
    let end = floor_char_boundary(line, span.end.min(line.len())).max(start);
    let pad = line[..start].chars().count();
    let width = line[start..end].chars().count().max(1);
    format!("{line}\n{}{}", " ".repeat(pad), "^".repeat(width))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn caret_points_at_span() {
        let s = caret_lines("a + bb * c", Span::new(4, 6));
        assert_eq!(s, "a + bb * c\n    ^^");
    }

    #[test]
    fn caret_at_end_of_input_is_visible() {
        let s = caret_lines("a +", Span::new(3, 3));
        assert_eq!(s, "a +\n   ^");
    }

    #[test]
    fn column_counts_characters() {
        assert_eq!(Span::new(3, 4).column("µ +x"), 3);
        assert_eq!(Span::new(0, 1).column("x"), 1);
    }
}

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

/// The most characters of a source line an error shows. A longer line (a formula of
/// thousands of terms) is cut to this many around the place it points at, with `…` where
/// it is cut.
pub const SHOWN_LINE: usize = 120;

/// A value an error echoes (a cell of a data file, a column name, a flag's text), cut to at
/// most [`SHOWN_LINE`] characters: its beginning and its end with `…` between them, and its
/// length. A 100,000-character cell made a 100 KB message.
///
/// ```
/// use mechkit_expr::span::{SHOWN_LINE, clip};
/// assert_eq!(clip("1.5x"), "1.5x");
/// let long = "1".repeat(100_000);
/// let shown = clip(&long);
/// assert!(shown.chars().count() <= SHOWN_LINE + 30, "{shown}");
/// assert!(shown.contains('…') && shown.ends_with("(100000 characters)"));
/// ```
pub fn clip(text: &str) -> std::borrow::Cow<'_, str> {
    let count = text.chars().count();
    if count <= SHOWN_LINE {
        return text.into();
    }
    let half = SHOWN_LINE / 2 - 1;
    let head: String = text.chars().take(half).collect();
    let tail: String = text.chars().skip(count - half).collect();
    format!("{head}…{tail} ({count} characters)").into()
}

/// `text` as a terminal may show it: control characters (C0 but tab, DEL, C1) and the
/// bidirectional overrides and isolates (U+202A–U+202E, U+2066–U+2069) written as `\u{1b}`,
/// so that a title or a name from a file cannot move the cursor, recolour the terminal or
/// reverse the text around it. Everything else, accented letters and emoji included, is kept.
///
/// ```
/// use mechkit_expr::span::printable;
/// assert_eq!(printable("Block é 🚀"), "Block é 🚀");
/// assert_eq!(printable("a\u{1b}[31mb\u{202e}c"), "a\\u{1b}[31mb\\u{202e}c");
/// ```
pub fn printable(text: &str) -> std::borrow::Cow<'_, str> {
    use std::fmt::Write as _;
    let unsafe_char = |c: char| {
        (c.is_control() && c != '\t')
            || ('\u{202a}'..='\u{202e}').contains(&c)
            || ('\u{2066}'..='\u{2069}').contains(&c)
    };
    if !text.chars().any(unsafe_char) {
        return text.into();
    }
    let mut out = String::with_capacity(text.len() + 8);
    for c in text.chars() {
        if unsafe_char(c) {
            let _ = write!(out, "\\u{{{:x}}}", c as u32);
        } else {
            out.push(c);
        }
    }
    out.into()
}

/// The part of `line` an error shows around the `width` characters from character `start`
/// (0-based): the line itself when it has at most [`SHOWN_LINE`] characters, else a window
/// of that many that begins a little before `start`, with `…` at a cut end. Returns the
/// text, and where the span begins in it and how wide it is, in characters.
///
/// ```
/// use mechkit_expr::span::excerpt;
/// assert_eq!(excerpt("a + b", 4, 1), ("a + b".to_string(), 4, 1));
/// let long = "x+".repeat(1000) + "x";
/// let (text, start, width) = excerpt(&long, 1000, 1);
/// assert!(text.starts_with('…') && text.ends_with('…'));
/// assert_eq!(text.chars().nth(start), long.chars().nth(1000));
/// assert_eq!(width, 1);
/// ```
pub fn excerpt(line: &str, start: usize, width: usize) -> (String, usize, usize) {
    let count = line.chars().count();
    if count <= SHOWN_LINE {
        return (line.to_string(), start, width);
    }
    let begin = start.saturating_sub(SHOWN_LINE / 3).min(count - SHOWN_LINE);
    let end = begin + SHOWN_LINE;
    let mut text: String = line.chars().skip(begin).take(SHOWN_LINE).collect();
    let mut at = start - begin.min(start);
    if begin > 0 {
        text.insert(0, '…');
        at += 1;
    }
    if end < count {
        text.push('…');
    }
    let shown = text.chars().count();
    (
        text,
        at.min(shown),
        width.min(shown.saturating_sub(at)).max(1),
    )
}

/// Renders `source` with a caret line under `span`:
///
/// ```text
/// -m*g*Dmgg*v
///      ^^^^
/// ```
///
/// Only the first line of a multi-line source is shown, and of a long line only an
/// [`excerpt`]. The caret line has at least one `^`.
pub fn caret_lines(source: &str, span: Span) -> String {
    let line = source.lines().next().unwrap_or("");
    let start = floor_char_boundary(line, span.start.min(line.len()));
    let end = floor_char_boundary(line, span.end.min(line.len())).max(start);
    let pad = line[..start].chars().count();
    let width = line[start..end].chars().count().max(1);
    let (line, pad, width) = excerpt(line, pad, width);
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
    fn a_long_line_is_cut_around_the_span() {
        let src = "1+".repeat(5000) + "x";
        let at = src.len() - 1;
        let s = caret_lines(&src, Span::new(at, at + 1));
        let (line, carets) = s.split_once('\n').unwrap();
        assert!(line.starts_with('…') && line.ends_with('x'), "{line}");
        assert!(line.chars().count() <= SHOWN_LINE + 2);
        assert_eq!(carets.trim_start().len(), 1);
        assert_eq!(carets.len() - 1, line.chars().count() - 1);
    }

    #[test]
    fn column_counts_characters() {
        assert_eq!(Span::new(3, 4).column("µ +x"), 3);
        assert_eq!(Span::new(0, 1).column("x"), 1);
    }
}

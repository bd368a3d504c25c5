//! The one XML escape of the SVG files mechkit writes (plots and animation frames) and of the
//! HTML player: text made well-formed XML 1.0 whatever it holds (a title with control
//! characters from a scenario file or a flag).
//!
//! XML 1.0 allows tab, newline, carriage return and the characters from U+0020 except the
//! surrogates (which a Rust string cannot hold), U+FFFE and U+FFFF; every other character is
//! dropped, not escaped, since XML 1.0 has no escape for them (`&#1;` is ill-formed too).

use std::borrow::Cow;

/// Whether XML 1.0 allows `c` in a document.
pub fn allowed(c: char) -> bool {
    matches!(c, '\t' | '\n' | '\r') || (c >= ' ' && c != '\u{FFFE}' && c != '\u{FFFF}')
}

/// `text` without the characters XML 1.0 forbids ([`allowed`]); borrowed when it has none.
pub fn drop_forbidden(text: &str) -> Cow<'_, str> {
    if text.chars().all(allowed) {
        Cow::Borrowed(text)
    } else {
        Cow::Owned(text.chars().filter(|&c| allowed(c)).collect())
    }
}

/// `text` as XML character data or an attribute value: `& < > " '` escaped, the characters
/// XML 1.0 forbids dropped ([`drop_forbidden`]), and C1 control characters and carriage
/// returns dropped as well (they draw nothing).
pub fn escape(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for c in text.chars() {
        match c {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            '\'' => out.push_str("&apos;"),
            c if !allowed(c) || (c.is_control() && c != '\t' && c != '\n') => {}
            c => out.push(c),
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn issue_026_every_character_xml_forbids_is_dropped() {
        let nasty = "a\u{0}\u{8}\u{b}\u{c}\u{e}\u{1f}b\u{fffe}\u{ffff}c\t\n\r<&>";
        assert_eq!(drop_forbidden(nasty), "abc\t\n\r<&>");
        assert_eq!(escape(nasty), "abc\t\n&lt;&amp;&gt;");
        assert!(matches!(drop_forbidden("plain é ✓"), Cow::Borrowed(_)));
        for c in [
            '\u{0}', '\u{1}', '\u{b}', '\u{c}', '\u{1f}', '\u{fffe}', '\u{ffff}',
        ] {
            assert!(!allowed(c), "{c:?}");
        }
        for c in [' ', '\t', '\u{7f}', '\u{85}', '\u{fffd}', '\u{10000}'] {
            assert!(allowed(c), "{c:?}");
        }
    }
}

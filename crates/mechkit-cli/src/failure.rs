//! How failures reach the user: an error as `error: ` with its causes, and a panic (a bug) as
//! an `error: internal error` line instead of Rust's `thread 'main' panicked at …`.

use std::panic::PanicHookInfo;

/// The error's message with its causes after its first line (`cannot read p.csv: No such
/// file or directory`, then the hint lines if any), each cause once: a cause whose text the
/// message already contains is skipped.
pub fn message(e: &anyhow::Error) -> String {
    let text = e.to_string();
    let (mut first, rest) = match text.split_once('\n') {
        Some((first, rest)) => (first.to_string(), Some(rest)),
        None => (text.clone(), None),
    };
    for cause in e.chain().skip(1) {
        let cause = cause.to_string();
        if !text.contains(&cause) && !first.contains(&cause) {
            first.push_str(": ");
            first.push_str(&cause);
        }
    }
    let text = match rest {
        Some(rest) => format!("{first}\n{rest}"),
        None => first,
    };
    // each line terminal-safe: a value with ESC or a bidi override is echoed escaped
    let lines: Vec<String> = clip_quoted(&text)
        .split('\n')
        .map(|line| mechkit::expr::span::printable(line).into_owned())
        .collect();
    lines.join("\n")
}

/// Every `` `value` `` a message echoes cut to `mechkit_expr::span::SHOWN_LINE` characters
/// (`span::clip`), as source lines are: a 100,000-character flag or cell is not echoed whole.
fn clip_quoted(text: &str) -> String {
    let parts: Vec<&str> = text.split('`').collect();
    if parts.len() < 3 {
        return text.to_string();
    }
    let mut out = String::with_capacity(text.len().min(4096));
    for (i, part) in parts.iter().enumerate() {
        if i > 0 {
            out.push('`');
        }
        // the odd parts are quoted, when their closing backtick follows
        if i % 2 == 1 && i + 1 < parts.len() {
            out.push_str(&mechkit::expr::span::clip(part));
        } else {
            out.push_str(part);
        }
    }
    out
}

/// Replaces Rust's panic message by [`internal_error`]. With `RUST_BACKTRACE` set, the
/// default message (and backtrace) is printed as well, for whoever debugs it. The exit status
/// of a panic stays 101.
///
/// Installed once per process: [`crate::main_with_args`] runs once per command, and a caller
/// that runs many commands in one process (the Python package, the `command_line` fuzz
/// target) would otherwise wrap the hook once more each time, a chain that grows without end.
pub fn install_panic_hook() {
    static INSTALLED: std::sync::Once = std::sync::Once::new();
    INSTALLED.call_once(install);
}

fn install() {
    let default = std::panic::take_hook();
    std::panic::set_hook(Box::new(move |info: &PanicHookInfo<'_>| {
        if std::env::var_os("RUST_BACKTRACE").is_some_and(|v| v != "0") {
            default(info);
        }
        let what = info
            .payload()
            .downcast_ref::<&str>()
            .map(ToString::to_string)
            .or_else(|| info.payload().downcast_ref::<String>().cloned());
        let at = info
            .location()
            .map(|l| format!("{}:{}", l.file(), l.line()));
        eprintln!("{}", internal_error(what.as_deref(), at.as_deref()));
    }));
}

/// The message for a bug: what failed and where in mechkit's source, and what to do.
pub fn internal_error(what: Option<&str>, at: Option<&str>) -> String {
    let what = what.unwrap_or("an unexpected failure");
    let at = at.map(|a| format!(" (at {a})")).unwrap_or_default();
    format!(
        "error: internal error, a bug in mechkit: {what}{at}\n = hint: please report it with \
         the command and its input files; the output written so far may be incomplete"
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn causes_follow_the_first_line_once() {
        let e = anyhow::Error::new(std::io::Error::other("disk full"))
            .context("cannot write out.csv\n  = hint: check the directory");
        assert_eq!(
            message(&e),
            "cannot write out.csv: disk full\n  = hint: check the directory"
        );
        let e = anyhow::Error::new(std::io::Error::other("disk full"))
            .context("cannot write out.csv: disk full");
        assert_eq!(message(&e), "cannot write out.csv: disk full");
    }

    /// Found by the `command_line` fuzz target, which runs a command per input: each run
    /// wrapped the panic hook in one more closure.
    #[test]
    fn issue_026_fuzz_the_panic_hook_is_installed_once() {
        install_panic_hook();
        let first = std::panic::take_hook();
        let first_at = std::ptr::from_ref(&*first).cast::<()>();
        std::panic::set_hook(first);
        install_panic_hook();
        let second = std::panic::take_hook();
        let second_at = std::ptr::from_ref(&*second).cast::<()>();
        std::panic::set_hook(second);
        assert_eq!(first_at, second_at, "a second hook wraps the first");
    }

    #[test]
    fn a_bug_is_reported_without_rust_panic_wording() {
        let text = internal_error(Some("index out of bounds"), Some("src/x.rs:3"));
        assert!(text.starts_with(
            "error: internal error, a bug in mechkit: index out of bounds (at src/x.rs:3)"
        ));
        assert!(text.contains("hint: please report it"));
        assert!(!text.contains("panicked"));
        assert!(internal_error(None, None).contains("an unexpected failure"));
    }
}

//! Issue 26, messages: no number is shown to people as hundreds of digits. Rust's `{}` of
//! `1e300` is 301 digits and `{:.6}` of it more; every message, warning and table goes through
//! `short_number`/`short_fixed` (`1e300`, `1.000000e300`). An audit found about 200 places in
//! the library's and the CLI's messages that still printed with `{}`; these cases reach some of
//! them through each front door, with values at both ends of the double range.

use super::util::Dir;

/// Commands whose message, warning or report shows a value near 1e±300, and the short
/// spelling it must contain.
const CASES: &[(&[&str], &str)] = &[
    (
        &[
            "collide",
            "--m1",
            "-1e300",
            "--v1",
            "1",
            "--m2",
            "1",
            "--v2",
            "0",
            "--restitution",
            "1",
        ],
        "-1e300",
    ),
    (
        &[
            "collide",
            "--m1",
            "1",
            "--v1",
            "1",
            "--m2",
            "1",
            "--v2",
            "0",
            "--restitution",
            "1e300",
        ],
        "1e300",
    ),
    (
        &[
            "rocket",
            "--m0",
            "1",
            "--m1",
            "1e300",
            "--mass-rate",
            "1",
            "--exhaust-speed",
            "1",
        ],
        "m1 = 1e300 kg",
    ),
    (
        &[
            "spin",
            "--moments",
            "1e300, 1, 1",
            "--omega",
            "0, 0, 1",
            "--t-max",
            "1",
        ],
        "I1 = 1e300",
    ),
    (
        &[
            "friction", "--mass", "1", "--mu-s", "1e-300", "--mu-d", "1e300", "--angle", "30 deg",
        ],
        "μs = 1e-300 is below μd = 1e300",
    ),
    (
        &[
            "roll", "--mass", "1", "--radius", "-1e300", "--mu", "0.5", "--t-max", "1",
        ],
        "-1e300 m",
    ),
    (
        &[
            "relative",
            "--speed",
            "1e-300",
            "--current",
            "1e300",
            "--track",
            "N",
        ],
        "(1e-300 m/s)",
    ),
    (
        &["integrate", "1/x", "--from", "-1e300", "--to", "1e-300"],
        "[-1e300, 1e-300]",
    ),
    (&["md", "--dt", "1e300", "--steps", "1"], "e300"),
    (&["units", "1e-300 m", "--to", "km"], "e-303 km"),
];

/// The longest run of ASCII digits in `text`.
fn longest_digit_run(text: &str) -> usize {
    text.split(|c: char| !c.is_ascii_digit())
        .map(str::len)
        .max()
        .unwrap_or(0)
}

#[test]
fn issue_026_no_message_shows_a_number_of_hundreds_of_digits() {
    let dir = Dir::new();
    for (args, short) in CASES {
        let out = dir.run(args);
        let text = format!("{}{}", out.stdout, out.stderr);
        assert!(text.contains(short), "{args:?}: no `{short}` in\n{text}");
        // 17 significant digits and an exponent at most; a 20-digit run is a number printed in
        // full
        assert!(
            longest_digit_run(&text) < 20,
            "{args:?}: a long number in\n{text}"
        );
    }
}

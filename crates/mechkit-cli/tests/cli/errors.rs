//! Bad input: exit code 2, `error:` first, the file location and the specific message.

use crate::util::{self, Dir};

fn bad_input(name: &str, text: &str, needles: &[&str]) -> util::Output {
    let dir = Dir::new();
    dir.create(name, text);
    let out = dir.run(&["run", name, "--out", "out"]);
    out.assert_bad_input(needles);
    assert!(
        !dir.path().join("out").exists(),
        "a scenario with an error must not create the output directory"
    );
    out
}

/// Checks that stderr shows `line_text` followed by a caret line whose carets start under
/// `target` within it.
fn assert_caret_under(stderr: &str, line_text: &str, target: &str) {
    let lines: Vec<&str> = stderr.lines().collect();
    let i = lines
        .iter()
        .position(|l| l.ends_with(line_text))
        .unwrap_or_else(|| panic!("stderr does not quote {line_text:?}:\n{stderr}"));
    let quoted = lines[i];
    let carets = lines
        .get(i + 1)
        .expect("a caret line follows the quoted line");
    let want = quoted.find(line_text).expect("the line is quoted")
        + line_text.find(target).expect("target is in the line");
    assert_eq!(
        carets.find('^'),
        Some(want),
        "the caret is not under `{target}`:\n{stderr}"
    );
    assert_eq!(
        carets[want..].chars().take_while(|c| *c == '^').count(),
        target.chars().count(),
        "the carets do not underline `{target}`:\n{stderr}"
    );
}

#[test]
fn unknown_key_is_named_with_the_nearest_valid_key() {
    let out = bad_input(
        "unknown.toml",
        r#"
dimensions = 1
[[body]]
name = "ball"
masss = "1 g"
[integrator]
dt = "1 ms"
[stop]
t_max = "1 s"
"#,
        &["unknown.toml:4:1", "`masss`", "`mass`"],
    );
    assert_caret_under(&out.stderr, r#"masss = "1 g""#, "masss");
}

#[test]
fn missing_mass_is_an_error() {
    bad_input(
        "missing_mass.toml",
        r#"
dimensions = 1
[[body]]
name = "ball"
position = "1 m"
[integrator]
dt = "1 ms"
[stop]
t_max = "1 s"
"#,
        &["missing_mass.toml:2:1", "`mass`", "ball"],
    );
}

#[test]
fn negative_mass_is_an_error() {
    bad_input(
        "negative_mass.toml",
        r#"
dimensions = 1
[[body]]
name = "ball"
mass = "-2 kg"
[integrator]
dt = "1 ms"
[stop]
t_max = "1 s"
"#,
        &["negative_mass.toml:4:8", "mass", "positive", "-2"],
    );
}

#[test]
fn zero_mass_is_an_error() {
    bad_input(
        "zero_mass.toml",
        r#"
dimensions = 1
[[body]]
name = "ball"
mass = "0 kg"
[integrator]
dt = "1 ms"
[stop]
t_max = "1 s"
"#,
        &["zero_mass.toml:4:8", "mass", "positive"],
    );
}

#[test]
fn zero_dt_is_an_error() {
    bad_input(
        "zero_dt.toml",
        r#"
dimensions = 1
[[body]]
name = "ball"
mass = "1 kg"
[integrator]
method = "rk4"
dt = "0 s"
[stop]
t_max = "1 s"
"#,
        &["zero_dt.toml:7:6", "`dt`", "positive"],
    );
}

#[test]
fn negative_dt_is_an_error() {
    bad_input(
        "negative_dt.toml",
        r#"
dimensions = 1
[[body]]
name = "ball"
mass = "1 kg"
[integrator]
method = "rk4"
dt = "-1 ms"
[stop]
t_max = "1 s"
"#,
        &["negative_dt.toml:7:6", "`dt`", "positive"],
    );
}

#[test]
fn unknown_unit_is_named_with_a_suggestion() {
    let out = bad_input(
        "unknown_unit.toml",
        r#"
dimensions = 1
[[body]]
name = "ball"
mass = "1 kg"
velocity = "3 mps"
[integrator]
dt = "1 ms"
[stop]
t_max = "1 s"
"#,
        &["unknown_unit.toml:5:15", "`mps`", "`m/s`"],
    );
    assert_caret_under(&out.stderr, r#"velocity = "3 mps""#, "mps");
}

#[test]
fn wrong_dimension_names_both_dimensions() {
    bad_input(
        "wrong_dimension.toml",
        r#"
dimensions = 1
[[body]]
name = "ball"
mass = "3 m"
[integrator]
dt = "1 ms"
[stop]
t_max = "1 s"
"#,
        &["wrong_dimension.toml:4:8", "`mass`", "kg", "m (length)"],
    );
}

#[test]
fn undefined_name_in_a_formula_is_located_in_the_line() {
    let out = bad_input(
        "undefined_name.toml",
        r#"
dimensions = 1
[constants]
k = "10 N/m"
[[body]]
name = "block"
mass = "1 kg"
position = "0.1 m"
[[force]]
name = "spring"
kind = "expression"
F = "-k*xx"
[integrator]
dt = "1 ms"
[stop]
t_max = "1 s"
"#,
        // `xx` starts at column 9 of `F = "-k*xx"`
        &["undefined_name.toml:11:9", "`xx`"],
    );
    assert_caret_under(&out.stderr, r#"F = "-k*xx""#, "xx");
}

#[test]
fn invalid_toml_is_located() {
    bad_input(
        "syntax.toml",
        r#"
dimensions = 1
[[body]]
name = "ball"
mass = = "1 kg"
[integrator]
dt = "1 ms"
"#,
        &["syntax.toml:4:8", "invalid TOML"],
    );
}

#[test]
fn nonexistent_scenario_file_is_an_error() {
    let dir = Dir::new();
    let out = dir.run(&["run", "no_such_file.toml", "--out", "out"]);
    out.assert_bad_input(&["no_such_file.toml"]);
    assert!(!dir.path().join("out").exists());
}

#[test]
fn unwritable_output_directory_is_an_error() {
    let dir = Dir::new();
    dir.create(
        "ok.toml",
        r#"
dimensions = 1
[[body]]
name = "ball"
mass = "1 kg"
[integrator]
dt = "0.1 s"
[stop]
t_max = "1 s"
"#,
    );
    dir.create("afile", "a regular file, not a directory\n");
    let out = dir.run(&["run", "ok.toml", "--out", "afile/sub"]);
    out.assert_bad_input(&["afile/sub"]);
    assert!(dir.path().join("afile").is_file());
}

// ---------------------------------------------------------------------------------------------
// Runs that fail or do not end by themselves.

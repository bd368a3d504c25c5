//! Scripts of command-line calls that answer a case: each line `mechkit …` is a call (with
//! `--json`), and the lines `#> key = /json/pointer` after it say which value of its output is
//! the case's expected `key`. Other lines starting with `#` are comments; a script is valid
//! POSIX shell, runnable as it is with `mechkit` on the PATH.
//!
//! For example, `mechkit solve "k*x = m*g" --for k --json` followed by the line
//! `#> answer = /solutions/0` binds the first solution to the expected value `answer`.

use serde_json::Value;

/// A parsed script.
#[derive(Debug, Clone, PartialEq)]
pub struct Script {
    /// The calls in order.
    pub steps: Vec<Step>,
    /// The comment lines before the first call (the case's description).
    pub header: Vec<String>,
}

/// One `mechkit …` call and the values read from its output.
#[derive(Debug, Clone, PartialEq)]
pub struct Step {
    /// 1-based line of the call.
    pub line: usize,
    /// The words after `mechkit`.
    pub args: Vec<String>,
    /// The `#> key = /pointer` lines after it.
    pub bindings: Vec<Binding>,
}

/// `#> key = /pointer`: the value at `pointer` of the call's JSON output is expected `key`.
#[derive(Debug, Clone, PartialEq)]
pub struct Binding {
    /// 1-based line.
    pub line: usize,
    /// The expected key.
    pub key: String,
    /// A JSON pointer (RFC 6901) into the output.
    pub pointer: String,
}

/// A script line that cannot be read.
#[derive(Debug, Clone, PartialEq)]
pub struct ScriptError {
    /// 1-based line.
    pub line: usize,
    /// What is wrong, and what to write.
    pub message: String,
}

impl std::fmt::Display for ScriptError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "line {}: {}", self.line, self.message)
    }
}

impl std::error::Error for ScriptError {}

impl Script {
    /// Parses a script.
    pub fn parse(text: &str) -> Result<Script, ScriptError> {
        let mut script = Script {
            steps: Vec::new(),
            header: Vec::new(),
        };
        for (n, raw) in text.lines().enumerate() {
            let line = raw.trim();
            let err = |message: &str| ScriptError {
                line: n + 1,
                message: message.to_string(),
            };
            if let Some(rest) = line.strip_prefix("mechkit ") {
                script.steps.push(Step {
                    line: n + 1,
                    args: shell_words(rest).map_err(|m| err(&m))?,
                    bindings: Vec::new(),
                });
            } else if let Some(binding) = line.strip_prefix("#>") {
                let (key, pointer) = binding
                    .split_once('=')
                    .ok_or_else(|| err("write `#> key = /json/pointer`"))?;
                let (key, pointer) = (key.trim(), pointer.trim());
                if key.is_empty() || !(pointer.is_empty() || pointer.starts_with('/')) {
                    return Err(err("write `#> key = /json/pointer`"));
                }
                let step = script
                    .steps
                    .last_mut()
                    .ok_or_else(|| err("a binding before any `mechkit …` call"))?;
                step.bindings.push(Binding {
                    line: n + 1,
                    key: key.to_string(),
                    pointer: pointer.to_string(),
                });
            } else if let Some(comment) = line.strip_prefix('#') {
                if script.steps.is_empty() {
                    script.header.push(comment.trim().to_string());
                }
            } else if !line.is_empty() {
                return Err(err(
                    "a script holds `mechkit …` calls, `#> key = /pointer` bindings and comments",
                ));
            }
        }
        Ok(script)
    }

    /// The expected keys the script binds.
    #[cfg(test)]
    pub fn keys(&self) -> impl Iterator<Item = &str> {
        self.steps
            .iter()
            .flat_map(|s| s.bindings.iter().map(|b| b.key.as_str()))
    }
}

impl Binding {
    /// The bound value of an output, or `None` when the pointer names nothing.
    pub fn value<'v>(&self, output: &'v Value) -> Option<&'v Value> {
        output.pointer(&self.pointer)
    }
}

/// Splits a command line into words as a POSIX shell does for the quoting used in scripts:
/// whitespace separates, `"…"` (with `\"` and `\\`) and `'…'` group. An unclosed quote is an
/// error.
pub fn shell_words(line: &str) -> Result<Vec<String>, String> {
    let mut words = Vec::new();
    let mut word = String::new();
    let mut in_word = false;
    let mut chars = line.chars();
    while let Some(c) = chars.next() {
        match c {
            '"' => {
                in_word = true;
                let mut closed = false;
                while let Some(c) = chars.next() {
                    match c {
                        '"' => {
                            closed = true;
                            break;
                        }
                        '\\' => {
                            if let Some(n) = chars.next() {
                                if n != '"' && n != '\\' {
                                    word.push('\\');
                                }
                                word.push(n);
                            }
                        }
                        c => word.push(c),
                    }
                }
                if !closed {
                    return Err("a `\"` is not closed".into());
                }
            }
            '\'' => {
                in_word = true;
                if !chars.by_ref().any(|c| {
                    let end = c == '\'';
                    if !end {
                        word.push(c);
                    }
                    end
                }) {
                    return Err("a `'` is not closed".into());
                }
            }
            c if c.is_whitespace() => {
                if in_word {
                    words.push(std::mem::take(&mut word));
                    in_word = false;
                }
            }
            c => {
                in_word = true;
                word.push(c);
            }
        }
    }
    if in_word {
        words.push(word);
    }
    Ok(words)
}

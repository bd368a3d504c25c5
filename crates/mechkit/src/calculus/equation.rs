//! Equations as written: `lhs = rhs` split into `lhs − rhs`, the names written in them, and
//! the check that an unknown is one of those names.

use mechkit_expr::{Sym, parse};

use super::CalculusError;

/// Splits `lhs = rhs` (a single `=`, not `==`, `<=`, `>=`, `!=`) into `lhs - rhs`, with the
/// names written in it (sorted, without the constants `pi` and `e`; a name that cancels out,
/// like `x` in `x = x + 1`, is still written).
pub(super) fn equation(text: &str) -> Result<(Sym, Vec<String>), CalculusError> {
    let b = text.as_bytes();
    let positions: Vec<usize> = (0..b.len())
        .filter(|&i| {
            b[i] == b'='
                && !(i > 0 && matches!(b[i - 1], b'=' | b'<' | b'>' | b'!'))
                && !(i + 1 < b.len() && b[i + 1] == b'=')
        })
        .collect();
    let written = |parts: &[&mechkit_expr::Parsed]| {
        let mut names: Vec<String> = parts
            .iter()
            .flat_map(|p| p.names.iter().map(|(n, _)| n.clone()))
            .filter(|n| n != "pi" && n != "e")
            .collect();
        names.sort();
        names.dedup();
        names
    };
    match positions.as_slice() {
        [] => {
            let whole = parse(text)?;
            Ok((Sym::from_expr(&whole.expr), written(&[&whole])))
        }
        [i] => {
            let lhs = parse(&text[..*i])?;
            let rhs = parse(&text[i + 1..]).map_err(|mut e| {
                e.span = e.span.shifted(i + 1);
                e.source = text.to_string();
                e
            })?;
            Ok((
                Sym::difference(Sym::from_expr(&lhs.expr), Sym::from_expr(&rhs.expr)),
                written(&[&lhs, &rhs]),
            ))
        }
        _ => Err(CalculusError::Invalid(format!(
            "`{text}` has more than one `=`; separate equations with `;`"
        ))),
    }
}

/// Refuses an unknown that is not written in the equation(s) `text` (whose names are `names`).
pub(super) fn check_unknown(x: &str, text: &str, names: &[String]) -> Result<(), CalculusError> {
    super::check_variable(x, crate::inputs::Input::Unknowns)?;
    if names.iter().any(|n| n == x) {
        return Ok(());
    }
    let hint = match names {
        [] => "it has no names: there is nothing to solve for".to_string(),
        [one] => format!("the only name in it is `{one}`: solve for it with --for {one}"),
        _ => format!(
            "the names in it are {}: solve for one of them, e.g. --for {}",
            names
                .iter()
                .map(|n| format!("`{n}`"))
                .collect::<Vec<_>>()
                .join(", "),
            names[0]
        ),
    };
    Err(CalculusError::Invalid(format!(
        "`{x}` does not appear in `{text}`; {hint}"
    )))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn issue_011_an_unknown_not_written_is_refused_with_the_names() {
        let (_, names) = equation("a*x + b = pi*c").unwrap();
        assert_eq!(names, ["a", "b", "c", "x"]);
        let e = check_unknown("y", "a*x + b = pi*c", &names)
            .unwrap_err()
            .to_string();
        assert!(
            e.contains("`y` does not appear") && e.contains("`a`, `b`, `c`, `x`"),
            "{e}"
        );
        // a name that cancels out is still written
        let (_, names) = equation("x = x + 1").unwrap();
        assert!(check_unknown("x", "x = x + 1", &names).is_ok());
    }
}

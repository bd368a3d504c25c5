//! Whether a column can serve as an abscissa: strictly increasing or strictly decreasing in
//! file order, as a path integral or a time derivative takes the rows.

use super::{DataError, Table};
use crate::Real;

/// The direction of a strictly monotone abscissa.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[non_exhaustive]
pub enum Order {
    /// Every value is larger than the one before.
    Increasing,
    /// Every value is smaller than the one before.
    Decreasing,
}

impl Order {
    /// `+1` for increasing, `−1` for decreasing.
    pub fn sign(self) -> Real {
        match self {
            Self::Increasing => 1.0,
            Self::Decreasing => -1.0,
        }
    }
}

/// Checks that `x`, a column of `table` or values computed row by row from it, is strictly
/// monotone, and returns its direction. `label` names `x` in messages (`x`, `t [s]`) and `what`
/// is what needs it (`"the work integral"`, `"the derivative"`); lines come from `table`.
///
/// Errors: the same value on two consecutive rows ([`DataError::DuplicateAbscissa`], naming
/// both lines), or a reversal of direction ([`DataError::NotMonotone`], naming the first line
/// where it reverses).
///
/// # Panics
/// If `x` has not one value per row of `table`, or a value is not finite (a [`Table`] holds
/// finite numbers only).
///
/// # Example
/// ```
/// use mechkit::data::{ColumnRef, Order, Table, check_abscissa};
///
/// let table = Table::parse("x F\n0.1 2\n0.2 3\n0.3 5\n0.3 4\n", "forcedata.d").unwrap();
/// let x = table.column(&ColumnRef::parse("x").unwrap()).unwrap();
/// let error = check_abscissa(x, &table, "x", "the work integral").unwrap_err();
/// assert_eq!(
///     error.to_string(),
///     "forcedata.d:5: x = 0.3 appears on lines 4 and 5; the work integral needs distinct \
///      points: remove one or average them"
/// );
/// ```
pub fn check_abscissa(
    x: &[Real],
    table: &Table,
    label: &str,
    what: &str,
) -> Result<Order, DataError> {
    assert_eq!(
        x.len(),
        table.len(),
        "one abscissa value per row of the table"
    );
    assert!(
        x.iter().all(|v| v.is_finite()),
        "abscissa values must be finite"
    );
    let mut order = None;
    for i in 1..x.len() {
        let (previous, value) = (x[i - 1], x[i]);
        if value == previous {
            return Err(DataError::DuplicateAbscissa {
                file: table.source().to_string(),
                label: label.to_string(),
                value,
                first_line: table.line_of(i - 1),
                second_line: table.line_of(i),
                what: what.to_string(),
            });
        }
        let step = if value > previous {
            Order::Increasing
        } else {
            Order::Decreasing
        };
        match order {
            None => order = Some(step),
            Some(o) if o == step => {}
            Some(o) => {
                return Err(DataError::NotMonotone {
                    file: table.source().to_string(),
                    label: label.to_string(),
                    line: table.line_of(i),
                    value,
                    previous_line: table.line_of(i - 1),
                    previous,
                    increasing: o == Order::Increasing,
                    what: what.to_string(),
                });
            }
        }
    }
    Ok(order.unwrap_or(Order::Increasing))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::data::ColumnRef;

    fn check(text: &str) -> Result<Order, DataError> {
        let t = Table::parse(text, "f.d").unwrap();
        let x = t.column(&ColumnRef::Index(0)).unwrap();
        check_abscissa(x, &t, "x", "the work integral")
    }

    #[test]
    fn directions() {
        assert_eq!(check("0 1\n1 2\n2 3\n").unwrap(), Order::Increasing);
        assert_eq!(check("2 1\n1 2\n-2 3\n").unwrap(), Order::Decreasing);
        assert_eq!(Order::Decreasing.sign(), -1.0);
    }

    #[test]
    fn duplicate_names_both_lines() {
        let e = check("0 1\n# c\n1 2\n1 3\n2 4\n").unwrap_err();
        assert!(matches!(
            e,
            DataError::DuplicateAbscissa {
                first_line: 3,
                second_line: 4,
                ..
            }
        ));
    }

    #[test]
    fn reversal_names_the_first_line_that_turns_back() {
        let e = check("0 1\n1 2\n3 3\n2 4\n1 5\n").unwrap_err();
        assert_eq!(
            e.to_string(),
            "f.d:4: x turns back here: it was increasing, but goes from 3 on line 3 to 2 on \
             line 4; the work integral follows the path in file order, so x must increase (or \
             decrease) along it; sort the file by x if the rows are not in path order"
        );
    }
}

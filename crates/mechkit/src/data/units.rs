//! Units of columns: the unit a data file's header gives a column (`t [s]`, `F (N)`), and the
//! units of columns computed from others (`W = ∫F dx` in `N*m`, shown as `J`; `dx/dt` in
//! `m/s`).

use mechkit_expr::units::Unit;

/// The unit in brackets or parentheses after a header name (`s` for `t [s]`, `N` for
/// `F(N)`), if it is a unit mechkit knows.
///
/// ```
/// use mechkit::data::header_unit;
/// assert_eq!(header_unit("t [s]").as_deref(), Some("s"));
/// assert_eq!(header_unit("F (kN)").as_deref(), Some("kN"));
/// assert_eq!(header_unit("x"), None);
/// assert_eq!(header_unit("x [parsecs per fortnight]"), None);
/// ```
pub fn header_unit(name: &str) -> Option<String> {
    let open = name.find(['[', '('])?;
    let close = if name[open..].starts_with('[') {
        ']'
    } else {
        ')'
    };
    let inner = name[open + 1..].strip_suffix(close).or_else(|| {
        let end = name.rfind(close)?;
        (end > open).then(|| &name[open + 1..end])
    })?;
    let inner = inner.trim();
    (!inner.is_empty() && Unit::parse(inner).is_ok()).then(|| inner.to_string())
}

/// The plain name of a header name, for a CSV column: the part before its unit (`t` for
/// `t [s]`), with every character that is not a letter, a digit, `_` or `.` replaced by `_`
/// (`x_1` for `x-1`), so that pandas and numpy read it as it is.
///
/// ```
/// use mechkit::data::plain_name;
/// assert_eq!(plain_name("t [s]"), "t");
/// assert_eq!(plain_name("pos x(m)"), "pos");
/// assert_eq!(plain_name("x-1"), "x_1");
/// assert_eq!(plain_name("ball.y"), "ball.y");
/// ```
pub fn plain_name(name: &str) -> String {
    let short = name
        .find(|c: char| c.is_whitespace() || c == '[' || c == '(')
        .map_or(name, |end| &name[..end])
        .trim();
    let short = if short.is_empty() { name.trim() } else { short };
    let mut out: String = short
        .chars()
        .map(|c| {
            if c.is_ascii_alphanumeric() || c == '_' || c == '.' {
                c
            } else {
                '_'
            }
        })
        .collect();
    if out.is_empty() || out.starts_with(|c: char| c.is_ascii_digit()) {
        out.insert(0, '_');
    }
    out
}

/// The unit of a product of quantities in units `a` and `b` (`N` and `m` give `J`, `N` and
/// `s` give `N*s`).
///
/// ```
/// use mechkit::data::product_unit;
/// assert_eq!(product_unit("N", "m"), "J");
/// assert_eq!(product_unit("N", "s"), "N*s");
/// assert_eq!(product_unit("kN", "cm"), "kN*cm");
/// ```
pub fn product_unit(a: &str, b: &str) -> String {
    named(format!("{}*{}", group(a), group(b)))
}

/// The unit of a quotient of a quantity in unit `a` by one in unit `b` raised to `power`
/// (`m` by `s` gives `m/s`; by `s` squared, `m/s^2`; `J` by `m` gives `N`).
///
/// ```
/// use mechkit::data::quotient_unit;
/// assert_eq!(quotient_unit("m", "s", 1), "m/s");
/// assert_eq!(quotient_unit("m", "s", 2), "m/s^2");
/// assert_eq!(quotient_unit("J", "m", 1), "N");
/// assert_eq!(quotient_unit("cm", "ms", 2), "cm/ms^2");
/// ```
pub fn quotient_unit(a: &str, b: &str, power: u32) -> String {
    let den = if power == 1 {
        group(b)
    } else {
        format!("{}^{power}", group(b))
    };
    named(format!("{}/{den}", group(a)))
}

/// `u` in parentheses when it is a compound unit.
fn group(u: &str) -> String {
    if u.contains(['*', '/', '^', ' ']) {
        format!("({u})")
    } else {
        u.to_string()
    }
}

/// A compound SI unit by its plain name: the derived symbol (`J`), else as written unless it
/// needed parentheses (`(m/s)/s` is `m/s^2`); a unit that is not SI (`cm/ms`) stays as
/// written.
fn named(text: String) -> String {
    match Unit::parse(&text) {
        #[allow(clippy::float_cmp)] // an exact SI factor of 1 is what makes it SI
        Ok(u) if u.factor == 1.0 => match u.dim.derived_symbol() {
            Some(symbol) => symbol.to_string(),
            None if text.contains('(') => u.dim.to_string(),
            None => text,
        },
        _ => text,
    }
}

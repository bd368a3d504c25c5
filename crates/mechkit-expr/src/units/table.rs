//! The table of units: SI base and derived units with prefixes, and the everyday units of a
//! mechanics course (km/h, rpm, deg, rev, min, h, g, u, eV, Å, AU, …).
//!
//! Values are the exact SI definitions where one exists (CODATA 2018 for u and eV, IAU 2012
//! for the astronomical unit).

use super::dimension::Dimension;

/// A named unit: its size in SI and its dimension.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct UnitDef {
    /// Symbol as written.
    pub symbol: &'static str,
    /// Size of one of these in SI units.
    pub factor: f64,
    /// Dimension.
    pub dim: Dimension,
    /// Whether SI prefixes apply (km, ms, µs, keV).
    pub prefixable: bool,
}

const fn d(e: [i8; 7]) -> Dimension {
    Dimension::base(e)
}

const L: Dimension = Dimension::LENGTH;
const M: Dimension = Dimension::MASS;
const T: Dimension = Dimension::TIME;
const NONE: Dimension = Dimension::NONE;

macro_rules! u {
    ($sym:literal, $factor:expr, $dim:expr, $p:literal) => {
        UnitDef {
            symbol: $sym,
            factor: $factor,
            dim: $dim,
            prefixable: $p,
        }
    };
}

const PI: f64 = std::f64::consts::PI;
const STANDARD_GRAVITY: f64 = 9.806_65;

/// Every unit, by symbol.
pub const UNITS: &[UnitDef] = &[
    // SI base units (the kilogram is the prefixed gram).
    u!("m", 1.0, L, true),
    u!("g", 1e-3, M, true),
    u!("s", 1.0, T, true),
    u!("A", 1.0, Dimension::CURRENT, true),
    u!("K", 1.0, Dimension::TEMPERATURE, true),
    u!("mol", 1.0, Dimension::AMOUNT, true),
    u!("cd", 1.0, Dimension::LUMINOSITY, true),
    // SI derived units.
    u!("N", 1.0, Dimension::FORCE, true),
    u!("J", 1.0, Dimension::ENERGY, true),
    u!("W", 1.0, Dimension::POWER, true),
    u!("Pa", 1.0, Dimension::PRESSURE, true),
    u!("Hz", 1.0, Dimension::FREQUENCY, true),
    u!("C", 1.0, d([0, 0, 1, 1, 0, 0, 0]), true),
    u!("V", 1.0, d([2, 1, -3, -1, 0, 0, 0]), true),
    u!("ohm", 1.0, d([2, 1, -3, -2, 0, 0, 0]), true),
    u!("Ω", 1.0, d([2, 1, -3, -2, 0, 0, 0]), true),
    u!("F", 1.0, d([-2, -1, 4, 2, 0, 0, 0]), true),
    u!("T", 1.0, d([0, 1, -2, -1, 0, 0, 0]), true),
    u!("Wb", 1.0, d([2, 1, -2, -1, 0, 0, 0]), true),
    u!("rad", 1.0, NONE, true),
    u!("sr", 1.0, NONE, false),
    // Angles and rotation.
    u!("deg", PI / 180.0, NONE, false),
    u!("°", PI / 180.0, NONE, false),
    u!("rev", 2.0 * PI, NONE, false),
    u!("rpm", 2.0 * PI / 60.0, Dimension::FREQUENCY, false),
    // Time.
    u!("min", 60.0, T, false),
    u!("h", 3600.0, T, false),
    u!("d", 86_400.0, T, false),
    u!("day", 86_400.0, T, false),
    u!("yr", 365.25 * 86_400.0, T, false),
    // Length.
    u!("Å", 1e-10, L, false),
    u!("AU", 1.495_978_707e11, L, false),
    u!("au", 1.495_978_707e11, L, false),
    u!("ly", 9.460_730_472_580_8e15, L, false),
    u!("pc", 3.085_677_581_491_367e16, L, false),
    u!("ft", 0.3048, L, false),
    u!("in", 0.0254, L, false),
    u!("yd", 0.9144, L, false),
    u!("mi", 1609.344, L, false),
    u!("nmi", 1852.0, L, false),
    // Mass.
    u!("t", 1000.0, M, false),
    u!("u", 1.660_539_066_60e-27, M, false),
    u!("Da", 1.660_539_066_60e-27, M, true),
    u!("lb", 0.453_592_37, M, false),
    // Speed.
    u!("mph", 0.447_04, Dimension::VELOCITY, false),
    u!("kn", 1852.0 / 3600.0, Dimension::VELOCITY, false),
    // Energy.
    u!("eV", 1.602_176_634e-19, Dimension::ENERGY, true),
    u!("cal", 4.184, Dimension::ENERGY, true),
    u!("Wh", 3600.0, Dimension::ENERGY, true),
    // Force.
    u!("kgf", STANDARD_GRAVITY, Dimension::FORCE, false),
    u!("lbf", 4.448_221_615_260_5, Dimension::FORCE, false),
    u!("dyn", 1e-5, Dimension::FORCE, false),
    // Acceleration: standard gravity as a unit ("3 gn").
    u!("gn", STANDARD_GRAVITY, Dimension::ACCELERATION, false),
    // Pressure and volume.
    u!("bar", 1e5, Dimension::PRESSURE, true),
    u!("atm", 101_325.0, Dimension::PRESSURE, false),
    u!("L", 1e-3, d([3, 0, 0, 0, 0, 0, 0]), true),
    u!("l", 1e-3, d([3, 0, 0, 0, 0, 0, 0]), false),
];

/// Spelled-out names accepted for the common units (singular or with a plural `s`).
const ALIASES: &[(&str, &str)] = &[
    ("meter", "m"),
    ("metre", "m"),
    ("kilometer", "km"),
    ("kilometre", "km"),
    ("centimeter", "cm"),
    ("centimetre", "cm"),
    ("millimeter", "mm"),
    ("millimetre", "mm"),
    ("gram", "g"),
    ("kilogram", "kg"),
    ("second", "s"),
    ("sec", "s"),
    ("millisecond", "ms"),
    ("minute", "min"),
    ("hour", "h"),
    ("year", "yr"),
    ("newton", "N"),
    ("joule", "J"),
    ("watt", "W"),
    ("pascal", "Pa"),
    ("hertz", "Hz"),
    ("radian", "rad"),
    ("degree", "deg"),
    ("revolution", "rev"),
    ("angstrom", "Å"),
];

/// SI prefixes. `u` is accepted for micro, as are both Unicode micro signs.
pub const PREFIXES: &[(&str, f64)] = &[
    ("Y", 1e24),
    ("Z", 1e21),
    ("E", 1e18),
    ("P", 1e15),
    ("T", 1e12),
    ("G", 1e9),
    ("M", 1e6),
    ("k", 1e3),
    ("h", 1e2),
    ("da", 1e1),
    ("d", 1e-1),
    ("c", 1e-2),
    ("m", 1e-3),
    ("µ", 1e-6),
    ("μ", 1e-6),
    ("u", 1e-6),
    ("n", 1e-9),
    ("p", 1e-12),
    ("f", 1e-15),
    ("a", 1e-18),
    ("z", 1e-21),
    ("y", 1e-24),
];

fn exact(symbol: &str) -> Option<&'static UnitDef> {
    UNITS.iter().find(|u| u.symbol == symbol)
}

/// Looks a unit symbol up: an exact symbol first, then a spelled-out alias, then a prefixed
/// symbol. Returns the size in SI and the dimension.
pub fn lookup(symbol: &str) -> Option<(f64, Dimension)> {
    if let Some(u) = exact(symbol) {
        return Some((u.factor, u.dim));
    }
    let singular = symbol.strip_suffix('s').filter(|s| s.len() > 2);
    for name in [Some(symbol), singular].into_iter().flatten() {
        if let Some((_, target)) = ALIASES.iter().find(|(a, _)| *a == name)
            && *target != name
        {
            return lookup(target);
        }
    }
    for (prefix, scale) in PREFIXES {
        if let Some(rest) = symbol.strip_prefix(prefix)
            && let Some(u) = exact(rest).filter(|u| u.prefixable)
        {
            return Some((scale * u.factor, u.dim));
        }
    }
    None
}

/// Names worth suggesting for a misspelt unit: every symbol, the common prefixed forms and
/// the spelled-out aliases.
pub fn suggestion_candidates() -> Vec<String> {
    let mut out: Vec<String> = UNITS.iter().map(|u| u.symbol.to_string()).collect();
    for common in [
        "km", "cm", "mm", "µm", "nm", "pm", "kg", "mg", "ms", "µs", "ns", "kN", "kJ", "kW", "MW",
        "keV", "MeV", "kPa", "MPa", "mL", "km/h", "m/s", "m/s^2", "N*m",
    ] {
        out.push(common.to_string());
    }
    out.extend(ALIASES.iter().map(|(a, _)| (*a).to_string()));
    out
}

/// Common misspellings with the unit meant.
pub fn known_misspelling(symbol: &str) -> Option<&'static str> {
    Some(match symbol {
        "mps" => "m/s",
        "kmh" | "kph" | "kmph" => "km/h",
        "hr" | "hrs" => "h",
        "secs" => "s",
        "mins" => "min",
        "kgs" => "kg",
        "Nm" => "N*m",
        "degs" | "degrees" => "deg",
        "rads" => "rad",
        "ms2" | "mps2" => "m/s^2",
        "gs" | "gees" => "gn",
        "ang" => "Å",
        _ => return None,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn factor(s: &str) -> f64 {
        lookup(s).unwrap_or_else(|| panic!("unit {s}")).0
    }

    #[test]
    fn prefixes_and_exact_names() {
        assert_eq!(factor("kg"), 1.0);
        assert_eq!(factor("km"), 1000.0);
        assert_eq!(factor("ms"), 1e-3);
        assert!((factor("µs") - 1e-6).abs() < 1e-21);
        assert!((factor("us") - 1e-6).abs() < 1e-21);
        assert_eq!(factor("min"), 60.0);
        assert_eq!(factor("mm"), 1e-3);
        assert_eq!(factor("cd"), 1.0); // candela, not centi-day
        assert!((factor("pm") - 1e-12).abs() < 1e-27);
        assert!((factor("keV") - 1.602_176_634e-16).abs() < 1e-30);
        assert_eq!(lookup("h").unwrap().1, Dimension::TIME);
        assert_eq!(lookup("rpm").unwrap().1, Dimension::FREQUENCY);
    }

    #[test]
    fn aliases() {
        assert_eq!(factor("meters"), 1.0);
        assert_eq!(factor("seconds"), 1.0);
        assert_eq!(factor("kilograms"), 1.0);
        assert_eq!(factor("degrees"), PI / 180.0);
    }

    #[test]
    fn not_prefixable() {
        assert!(lookup("kmin").is_none());
        assert!(lookup("kdeg").is_none());
        assert!(lookup("xyz").is_none());
    }
}

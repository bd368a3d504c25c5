//! The unit system of a problem: SI, or reduced (dimensionless) units.

/// The units a problem's numbers are in: SI (values with units converted to SI, dimensions
/// checked), or reduced units (every value a pure number in units the user chose, as in
/// molecular dynamics with lengths in σ and energies in ε: no dimensions to check, outputs
/// labelled [`UnitSystem::REDUCED_UNIT`]).
///
/// ```
/// use mechkit_expr::units::UnitSystem;
/// assert_eq!(UnitSystem::from_name("reduced"), Some(UnitSystem::Reduced));
/// assert_eq!(UnitSystem::default().name(), "SI");
/// assert_eq!(UnitSystem::Reduced.label("m/s"), "1");
/// assert_eq!(UnitSystem::Si.label("m/s"), "m/s");
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub enum UnitSystem {
    /// SI units.
    #[default]
    Si,
    /// Reduced (dimensionless) units.
    Reduced,
}

impl UnitSystem {
    /// The unit that labels every quantity in reduced units.
    pub const REDUCED_UNIT: &'static str = "1";

    /// Every unit system, in the order of [`UnitSystem::name`]s in messages.
    pub const ALL: [UnitSystem; 2] = [UnitSystem::Si, UnitSystem::Reduced];

    /// Its name: `"SI"` or `"reduced"`.
    pub fn name(self) -> &'static str {
        match self {
            UnitSystem::Si => "SI",
            UnitSystem::Reduced => "reduced",
        }
    }

    /// The unit system called `name` (`"SI"`, `"reduced"`; case-insensitive).
    pub fn from_name(name: &str) -> Option<UnitSystem> {
        UnitSystem::ALL
            .into_iter()
            .find(|u| u.name().eq_ignore_ascii_case(name))
    }

    /// `si` in SI units; [`UnitSystem::REDUCED_UNIT`] in reduced units.
    pub fn label(self, si: &str) -> &str {
        match self {
            UnitSystem::Si => si,
            UnitSystem::Reduced => UnitSystem::REDUCED_UNIT,
        }
    }
}

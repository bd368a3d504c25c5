//! Energy diagrams: `U(x)` on a range with its equilibria (every root of `F`, with its
//! stability from the sign of `U''`), the singular points, and for a total energy `E` the
//! turning points (`U = E`) and the allowed (`U ≤ E`) and forbidden regions.
//!
//! The range is sampled on a uniform grid; every sign change of `F`, of `U - E` (and, to find
//! poles, of `U`) between neighbours is refined by Brent's method. A "root" where the function
//! grows instead of vanishing is a pole and is reported as a singular point, never as an
//! equilibrium. Roots where `F` touches zero without changing sign (an inflection of `U`) are
//! found as roots of `F'` where `F` is zero to rounding. Two roots closer than the grid step can
//! be missed: raise the number of samples to look closer.

use super::potential::{Origin, Potential};
use crate::Real;
use crate::roots::{brent_with_values, find_all};

/// Whether a small displacement from an equilibrium grows or is restored.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "lowercase"))]
#[non_exhaustive]
pub enum Stability {
    /// A minimum of `U` (`U'' > 0`, or higher-order minimum): restoring.
    Stable,
    /// A maximum of `U` (`U'' < 0`, or higher-order maximum).
    Unstable,
    /// An inflection of `U` (`U'' = 0` and `U` rises on one side, falls on the other).
    Neutral,
}

impl Stability {
    /// `"stable"`, `"unstable"`, `"neutral"`.
    pub fn name(self) -> &'static str {
        match self {
            Stability::Stable => "stable",
            Stability::Unstable => "unstable",
            Stability::Neutral => "neutral",
        }
    }
}

/// A point where `F = 0`.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct Equilibrium {
    /// Where.
    pub x: Real,
    /// `U` there.
    pub potential: Real,
    /// `U''` there.
    pub curvature: Real,
    /// Its stability.
    pub stability: Stability,
    /// For a stable point: the lowest barrier to escape, `U(neighbouring maximum) - U(here)`,
    /// over the neighbouring unstable equilibria in the range.
    pub barrier: Option<Real>,
}

/// A stretch of the range between boundaries (turning points, singular points, range ends).
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct Region {
    /// Start.
    pub from: Real,
    /// End.
    pub to: Real,
    /// `U ≤ E` inside (kinetic energy is positive there).
    pub allowed: bool,
}

/// What a total energy `E` allows (serialized with `E` as `value`).
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct EnergyCut {
    /// `E`.
    #[cfg_attr(feature = "serde", serde(rename = "value"))]
    pub energy: Real,
    /// Where `U = E`, ascending.
    pub turning_points: Vec<Real>,
    /// The range split into allowed and forbidden regions.
    pub regions: Vec<Region>,
}

/// An energy diagram on a range.
#[derive(Debug, Clone, PartialEq)]
pub struct Diagram {
    /// The sampled points.
    pub x: Vec<Real>,
    /// `U` at them (NaN where undefined).
    pub potential: Vec<Real>,
    /// `F` at them.
    pub force: Vec<Real>,
    /// Equilibria, ascending.
    pub equilibria: Vec<Equilibrium>,
    /// Where `U` or `F` is infinite or undefined, ascending.
    pub singularities: Vec<Real>,
    /// The allowed and forbidden regions, if an energy was given.
    pub energy: Option<EnergyCut>,
}

/// The grid values of a diagram, and `U` anywhere from its nearest grid point.
struct Grid<'a> {
    p: &'a Potential,
    x: Vec<Real>,
    u: Vec<Real>,
}

impl Grid<'_> {
    fn potential(&self, x: Real) -> Real {
        let k = self.x.partition_point(|&g| g <= x).saturating_sub(1);
        if self.u[k].is_finite() {
            return self.p.potential_between(self.x[k], x, self.u[k]);
        }
        if let Some(&u1) = self.u.get(k + 1).filter(|u| u.is_finite()) {
            return self.p.potential_between(self.x[k + 1], x, u1);
        }
        match self.p.origin() {
            // neither neighbour was reachable by quadrature from the reference
            // (`potential_on` tried): nor is `x`, unless the reference lies between them
            Origin::Numeric { reference }
                if !(self.x[k] < reference
                    && self.x.get(k + 1).is_some_and(|&b| reference < b)) =>
            {
                Real::NAN
            }
            _ => self.p.potential(x),
        }
    }
}

impl Potential {
    /// The energy diagram on `[from, to]` with `samples` grid intervals (2000 is plenty for a
    /// few wells), and the regions a total energy `energy` allows.
    ///
    /// ```
    /// use mechkit::energy::{Potential, Stability};
    /// let p = Potential::from_force("-sin(2*pi*x)", "x", &[], 0.0).unwrap();
    /// let d = p.diagram(-0.3, 1.3, Some(0.0), 2000);
    /// let kinds: Vec<_> = d.equilibria.iter().map(|e| e.stability).collect();
    /// assert_eq!(kinds, [Stability::Stable, Stability::Unstable, Stability::Stable]);
    /// assert!((d.equilibria[0].barrier.unwrap() - 1.0 / std::f64::consts::PI).abs() < 1e-12);
    /// assert_eq!(d.energy.unwrap().turning_points.len(), 4);
    /// ```
    ///
    /// # Panics
    /// If `from` or `to` is not finite (a grid needs a finite range).
    pub fn diagram(&self, from: Real, to: Real, energy: Option<Real>, samples: usize) -> Diagram {
        assert!(
            from.is_finite() && to.is_finite(),
            "an energy diagram needs a finite range, not [{from}, {to}]"
        );
        let (a, b) = (from.min(to), from.max(to));
        let n = samples.max(2);
        let x: Vec<Real> = (0..=n)
            .map(|i| {
                if i == n {
                    b
                } else {
                    a + (b - a) * i as Real / n as Real
                }
            })
            .collect();
        let grid = Grid {
            p: self,
            u: self.potential_on(&x),
            x,
        };
        let force: Vec<Real> = grid.x.iter().map(|&x| self.force(x)).collect();
        let singularities = singular_points(&grid, &force);
        // roots are refined to rounding (Brent's own bound, 2ε|x|); `tol` only merges duplicates
        let tol = 8.0 * Real::EPSILON * a.abs().max(b.abs()).max(Real::MIN_POSITIVE);
        let mut eq_x = find_all(|x| self.force(x), a, b, n, 0.0);
        eq_x.extend(touching_roots(self, &force, a, b, n));
        eq_x.retain(|r| !singularities.iter().any(|s| (s - r).abs() <= 2.0 * tol));
        eq_x.sort_by(Real::total_cmp);
        eq_x.dedup_by(|p, q| (*p - *q).abs() <= 4.0 * tol);
        let mut equilibria: Vec<Equilibrium> = eq_x
            .into_iter()
            .map(|x| {
                let curvature = self.curvature(x);
                Equilibrium {
                    x,
                    potential: grid.potential(x),
                    curvature,
                    stability: stability(&grid, x, curvature, (b - a) / n as Real),
                    barrier: None,
                }
            })
            .collect();
        set_barriers(&mut equilibria, &singularities);
        let energy = energy.map(|e| energy_cut(&grid, e, &singularities, tol));
        Diagram {
            potential: grid.u,
            x: grid.x,
            force,
            equilibria,
            singularities,
            energy,
        }
    }
}

/// Where `U` or `F` is not finite at a grid point, or jumps through a pole between two.
fn singular_points(grid: &Grid<'_>, force: &[Real]) -> Vec<Real> {
    let (x, u) = (&grid.x, &grid.u);
    let mut out: Vec<Real> = Vec::new();
    for i in 0..x.len() {
        if !u[i].is_finite() || !force[i].is_finite() {
            out.push(x[i]);
        }
    }
    for i in 1..x.len() {
        let f = |v: Real| grid.p.force(v);
        // U inside the interval from its left end (a closed form, or quadrature over one step)
        let u_here = |v: Real| grid.p.potential_between(x[i - 1], v, u[i - 1]);
        for (values, g) in [
            ((force[i - 1], force[i]), &f as &dyn Fn(Real) -> Real),
            ((u[i - 1], u[i]), &u_here),
        ] {
            let (g0, g1) = values;
            if !(g0.is_finite() && g1.is_finite()) || g0.signum() == g1.signum() {
                continue;
            }
            if let Some(r) = brent_with_values(g, x[i - 1], x[i], Some(values), 0.0) {
                let gr = g(r);
                if !gr.is_finite() || gr.abs() > 1e3 * g0.abs().max(g1.abs()) {
                    out.push(r);
                }
            }
        }
    }
    let step = (x[x.len() - 1] - x[0]) / (x.len() - 1) as Real;
    // a pole at 0 converges to ±1e-300-ish values; a root this close to 0 is 0
    for s in &mut out {
        if s.abs() <= 1e-12 * step {
            *s = 0.0;
        }
    }
    out.sort_by(Real::total_cmp);
    out.dedup_by(|p, q| (*p - *q).abs() <= 1.5 * step);
    out
}

/// Roots of `F'` where `F` is zero to rounding: equilibria without a sign change of `F`.
fn touching_roots(p: &Potential, force: &[Real], a: Real, b: Real, n: usize) -> Vec<Real> {
    let scale = force
        .iter()
        .filter(|f| f.is_finite())
        .fold(0.0, |m: Real, f| m.max(f.abs()));
    find_all(|x| -p.curvature(x), a, b, n, 0.0)
        .into_iter()
        .filter(|&r| p.force(r).abs() <= 1e-10 * scale.max(Real::MIN_POSITIVE))
        .collect()
}

/// The sign of `U''`, or of the change of `U` on both sides when `U''` vanishes.
fn stability(grid: &Grid<'_>, x: Real, curvature: Real, step: Real) -> Stability {
    let delta = 0.01 * step;
    let u0 = grid.potential(x);
    let (left, right) = (
        grid.potential(x - delta) - u0,
        grid.potential(x + delta) - u0,
    );
    // U'' is trusted when it dominates the change it predicts over delta
    let predicted = 0.5 * curvature * delta * delta;
    if predicted.abs() > 1e-6 * u0.abs().max(left.abs()).max(right.abs()) {
        if curvature > 0.0 {
            Stability::Stable
        } else {
            Stability::Unstable
        }
    } else if left > 0.0 && right > 0.0 {
        Stability::Stable
    } else if left < 0.0 && right < 0.0 {
        Stability::Unstable
    } else {
        Stability::Neutral
    }
}

fn set_barriers(eq: &mut [Equilibrium], singularities: &[Real]) {
    let between = |p: Real, q: Real| singularities.iter().any(|&s| s > p && s < q);
    for i in 0..eq.len() {
        if eq[i].stability != Stability::Stable {
            continue;
        }
        let mut barrier: Option<Real> = None;
        for j in [i.wrapping_sub(1), i + 1] {
            let Some(n) = eq.get(j) else { continue };
            if n.stability == Stability::Unstable && !between(n.x.min(eq[i].x), n.x.max(eq[i].x)) {
                let h = n.potential - eq[i].potential;
                barrier = Some(barrier.map_or(h, |b| b.min(h)));
            }
        }
        eq[i].barrier = barrier;
    }
}

fn energy_cut(grid: &Grid<'_>, e: Real, singularities: &[Real], tol: Real) -> EnergyCut {
    let (x, u) = (&grid.x, &grid.u);
    let mut turning = Vec::new();
    for i in 1..x.len() {
        let (g0, g1) = (u[i - 1] - e, u[i] - e);
        if g0 == 0.0 {
            turning.push(x[i - 1]);
            continue;
        }
        if !(g0.is_finite() && g1.is_finite()) || g0.signum() == g1.signum() || g1 == 0.0 {
            continue;
        }
        let g = |v: Real| grid.p.potential_between(x[i - 1], v, u[i - 1]) - e;
        if let Some(r) = brent_with_values(g, x[i - 1], x[i], Some((g0, g1)), 0.0)
            && g(r).abs() <= g0.abs().max(g1.abs())
        {
            turning.push(r);
        }
    }
    if u.last().is_some_and(|&v| v == e) {
        turning.push(x[x.len() - 1]);
    }
    turning.retain(|t| !singularities.iter().any(|s| (s - t).abs() <= 2.0 * tol));
    let mut bounds = vec![x[0]];
    bounds.extend(turning.iter().chain(singularities).copied());
    bounds.push(x[x.len() - 1]);
    bounds.sort_by(Real::total_cmp);
    bounds.dedup_by(|p, q| (*p - *q).abs() <= 2.0 * tol);
    let mut regions: Vec<Region> = Vec::new();
    for w in bounds.windows(2) {
        let mid = w[0].midpoint(w[1]);
        let allowed = grid.potential(mid) <= e;
        match regions.last_mut() {
            // merge across a boundary that is not a turning point or a singular point
            Some(r)
                if r.allowed == allowed
                    && !turning.contains(&w[0])
                    && !singularities.contains(&w[0]) =>
            {
                r.to = w[1];
            }
            _ => regions.push(Region {
                from: w[0],
                to: w[1],
                allowed,
            }),
        }
    }
    EnergyCut {
        energy: e,
        turning_points: turning,
        regions,
    }
}

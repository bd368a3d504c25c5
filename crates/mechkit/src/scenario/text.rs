//! The human-readable summary that `mechkit run` prints.

use std::fmt::Write as _;

use super::summary::{StartEnd, Summary};
use crate::Real;

impl Summary {
    /// A short report for people: final state, stop reason, energy ledger, observables
    /// (warnings are left to the caller, for stderr). Numbers carry SI units, none in reduced
    /// units.
    pub fn to_text(&self) -> String {
        let reduced = self.is_reduced();
        // the SI unit after a number (" m/s"), or nothing in reduced units
        let u = |si: &'static str| if reduced { "" } else { si };
        let sec = u(" s");
        let mut s = String::new();
        let _ = writeln!(s, "{}", mechkit_expr::span::printable(&self.title));
        let c = &self.step_control;
        if c.mode == "adaptive" {
            let tol = match (c.rtol, c.atol) {
                (Some(r), Some(a)) => format!("rtol {}, atol {}", num(r), num(a)),
                (Some(r), None) => format!("rtol {}, atol per component", num(r)),
                _ => "per-component tolerances".into(),
            };
            let _ = writeln!(
                s,
                "  {}, adaptive ({tol}): {} steps accepted, {} rejected, {} evaluations; step {} … {}{sec}; t = {} → {}{sec}, stopped by {}",
                self.method,
                c.accepted,
                c.rejected,
                c.evaluations,
                c.h_min.map_or("-".into(), num),
                c.h_max.map_or("-".into(), num),
                num(self.t_start),
                num(self.t_end),
                self.stop_reason
            );
        } else {
            let _ = writeln!(
                s,
                "  {} with dt = {}{sec}: {} steps, t = {} → {}{sec}, stopped by {}",
                self.method,
                num(self.dt),
                self.steps,
                num(self.t_start),
                num(self.t_end),
                self.stop_reason
            );
        }
        for e in self.events.iter().take(SHOWN_EVENTS) {
            let occurrence = if self.events.iter().filter(|o| o.name == e.name).count() > 1 {
                format!(" #{}", e.occurrence)
            } else {
                String::new()
            };
            let detail = if e.terminal {
                format!(
                    " (last step before it: t = {}{sec}), ended the run",
                    num(e.last_step.t)
                )
            } else {
                String::new()
            };
            let _ = writeln!(
                s,
                "  event `{}`{occurrence} at t = {}{sec}{detail}",
                e.name,
                num(e.t)
            );
        }
        if self.events.len() > SHOWN_EVENTS {
            let _ = writeln!(
                s,
                "  … and {} more events (all in summary.json)",
                self.events.len() - SHOWN_EVENTS
            );
        }
        if let Some(d) = &self.divergence {
            let label = if self.stop_reason == "diverged" {
                "DIVERGED"
            } else {
                "FAILED"
            };
            let _ = writeln!(s, "  {label}: {}", d.message);
        }
        let _ = writeln!(s, "final state");
        let angle = self.coordinates == Some("angle");
        for (name, b) in &self.bodies {
            if angle && reduced {
                let _ = writeln!(
                    s,
                    "  {name}: theta {}, omega {} (I = {} about the axis)",
                    vec_text(&b.position),
                    vec_text(&b.velocity),
                    num(b.mass)
                );
            } else if angle {
                let _ = writeln!(
                    s,
                    "  {name}: theta {} rad, omega {} rad/s (I = {} kg m² about the axis)",
                    vec_text(&b.position),
                    vec_text(&b.velocity),
                    num(b.mass)
                );
            } else {
                let _ = writeln!(
                    s,
                    "  {name}: position {}{}, velocity {}{}",
                    vec_text(&b.position),
                    u(" m"),
                    vec_text(&b.velocity),
                    u(" m/s")
                );
            }
            if let Some(r) = &b.rotation {
                let _ = writeln!(
                    s,
                    "    angle {}{}, angular velocity {}{}",
                    num(r.theta),
                    u(" rad"),
                    num(r.omega),
                    u(" rad/s")
                );
            }
            if let Some(r) = &b.spin {
                let _ = writeln!(
                    s,
                    "    orientation {}, angular velocity {}{}, angular momentum {}{}",
                    vec_text(&r.orientation),
                    vec_text(&r.omega),
                    u(" rad/s"),
                    vec_text(&r.angular_momentum),
                    u(" kg m²/s")
                );
            }
        }
        if self.bodies.len() > 1 && !angle {
            let c = &self.centre_of_mass;
            let _ = writeln!(
                s,
                "centre of mass (M = {}{})\n  position {} → {}{}, velocity {} → {}{}",
                num(c.total_mass),
                u(" kg"),
                vec_text(&c.start.position),
                vec_text(&c.end.position),
                u(" m"),
                vec_text(&c.start.velocity),
                vec_text(&c.end.velocity),
                u(" m/s")
            );
            let _ = writeln!(
                s,
                "  kinetic energy about it {} → {}{}",
                num(c.internal_kinetic_start),
                num(c.internal_kinetic_end),
                u(" J")
            );
        }
        let p = &self.momentum;
        if self.bodies.len() > 1 || p.events_change.iter().any(|x| *x != 0.0) {
            let _ = writeln!(
                s,
                "{}\n  total                  {} → {}\n  impulse of the forces  {}",
                match (angle, reduced) {
                    (true, false) => "angular momentum about the axes (kg m²/s)",
                    (true, true) => "angular momentum about the axes",
                    (false, false) => "momentum (kg·m/s)",
                    (false, true) => "momentum",
                },
                vec_text(&p.start),
                vec_text(&p.end),
                vec_text(&p.external_impulse)
            );
            if p.events_change.iter().any(|x| *x != 0.0) {
                let _ = writeln!(s, "  changed by events      {}", vec_text(&p.events_change));
            }
        }
        let _ = writeln!(s, "energy ledger{}", if reduced { "" } else { " (J)" });
        for (name, w) in &self.work {
            let _ = writeln!(s, "  work of {name:<16} {}", num(*w));
        }
        let (k0, k1) = (
            self.kinetic_energy.start.unwrap_or(0.0),
            self.kinetic_energy.end.unwrap_or(0.0),
        );
        let _ = writeln!(
            s,
            "  kinetic energy         {} → {} (ΔK = {})",
            num(k0),
            num(k1),
            num(k1 - k0)
        );
        if let Some(StartEnd {
            start: Some(r0),
            end: Some(r1),
        }) = self.rotational_kinetic_energy
        {
            let _ = writeln!(
                s,
                "    of which turning     {} → {} (translation {} → {})",
                num(r0),
                num(r1),
                num(k0 - r0),
                num(k1 - r1)
            );
        }
        if let (Some(u0), Some(u1)) = (self.potential_energy.start, self.potential_energy.end) {
            let _ = writeln!(
                s,
                "  potential energy       {} → {} (ΔU = {})",
                num(u0),
                num(u1),
                num(u1 - u0)
            );
            let _ = writeln!(
                s,
                "  mechanical energy      {} → {} (ΔE = {})",
                num(self.energy.start),
                num(self.energy.end),
                num(self.energy.change)
            );
        }
        if self.energy.events_change != 0.0 {
            let _ = writeln!(
                s,
                "  changed by events      {}",
                num(self.energy.events_change)
            );
        }
        if let Some(d) = self.energy.relative_drift {
            let _ = writeln!(
                s,
                "  relative energy drift  {} (ΔE minus the work of non-conservative forces, over |E|)",
                num(d)
            );
        }
        let _ = writeln!(
            s,
            "  work-energy residual   {} (Σ work - ΔK)",
            num(self.work_energy_residual)
        );
        if !self.observables.is_empty() {
            let _ = writeln!(s, "observables");
            for (name, v) in &self.observables {
                let unit = self
                    .observable_units
                    .get(name)
                    .filter(|u| !u.is_empty() && !reduced);
                match unit {
                    Some(u) => {
                        let _ = writeln!(s, "  {name} = {} {u}", num(*v));
                    }
                    None => {
                        let _ = writeln!(s, "  {name} = {}", num(*v));
                    }
                }
            }
        }
        s
    }
}

/// Events listed in the text summary (all are in `summary.json`).
const SHOWN_EVENTS: usize = 12;

/// A number with 7 significant digits, for people.
fn num(x: Real) -> String {
    if x == 0.0 {
        return "0".into();
    }
    if !x.is_finite() {
        return format!("{x}");
    }
    let a = x.abs();
    if (1e-4..1e7).contains(&a) {
        let digits = (6 - a.log10().floor() as i32).max(0) as usize;
        let s = format!("{x:.digits$}");
        if s.contains('.') {
            s.trim_end_matches('0').trim_end_matches('.').to_string()
        } else {
            s
        }
    } else {
        let t = format!("{x:.6e}");
        match t.split_once('e') {
            Some((mantissa, exp)) if mantissa.contains('.') => {
                format!(
                    "{}e{exp}",
                    mantissa.trim_end_matches('0').trim_end_matches('.')
                )
            }
            _ => t,
        }
    }
}

fn vec_text(v: &[Real]) -> String {
    if v.len() == 1 {
        num(v[0])
    } else {
        format!(
            "({})",
            v.iter().map(|x| num(*x)).collect::<Vec<_>>().join(", ")
        )
    }
}

#[cfg(test)]
mod tests {
    use super::num;

    #[test]
    fn numbers_for_people() {
        assert_eq!(num(4.834_559_8), "4.83456");
        assert_eq!(num(-0.499_999_999), "-0.5");
        assert_eq!(num(2.8e-4), "0.00028");
        assert_eq!(num(1.5e-9), "1.5e-9");
        assert_eq!(num(1e-10), "1e-10");
        assert_eq!(num(-1.234_567e-5), "-1.234567e-5");
        assert_eq!(num(1538.0), "1538");
        assert_eq!(num(-0.0), "0");
    }
}

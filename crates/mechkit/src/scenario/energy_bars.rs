//! The energy ledger of a run as a bar chart (`plots = ["energy-bars"]`): the work-energy
//! theorem `K_start + Σ W + (change by events) = K_end`, drawn as a waterfall.

use super::summary::Summary;
use crate::Real;
use crate::figure::{Bar, BarKind, PlotData};

/// How the chart is written in `[output] plots`, and its file stem.
pub const ENERGY_BARS: &str = "energy-bars";

/// A change smaller than this fraction of the chart's largest amount is rounding, not a bar.
const NEGLIGIBLE: Real = 1e-9;

impl Summary {
    /// The energy ledger as a waterfall: the kinetic energy at the start, then the work of each
    /// force and the energy the events' state changes gave or took (a bounce's loss; left out
    /// when there is none) added to the running total in turn, gains first (a gain rises, a
    /// loss falls), and the kinetic energy at the end. The running total meets the final
    /// kinetic energy up to the work-energy residual, which the horizontal axis label gives.
    pub fn energy_bars(&self) -> PlotData {
        let k0 = self.kinetic_energy.start.unwrap_or(0.0);
        let k1 = self.kinetic_energy.end.unwrap_or(0.0);
        let total_work: Real = self.work.values().sum();
        // residual = Σ W − (ΔK − ΔK_events), so the events' share follows from the ledger
        let by_events = k1 - k0 - total_work + self.work_energy_residual;
        let scale = self
            .work
            .values()
            .fold(k0.abs().max(k1.abs()), |m, w| m.max(w.abs()));
        let mut bars = vec![Bar {
            label: "K start".into(),
            from: 0.0,
            to: k0,
            kind: BarKind::Total,
        }];
        let mut running = k0;
        let mut changes: Vec<(String, Real)> = self
            .work
            .iter()
            .map(|(name, w)| (format!("W {name}"), *w))
            .chain((by_events.abs() > NEGLIGIBLE * scale).then(|| ("events".into(), by_events)))
            .collect();
        // gains before losses: the running total then stays above zero, as a kinetic energy does
        changes.sort_by_key(|(_, change)| *change < 0.0);
        for (label, change) in changes {
            bars.push(Bar {
                label,
                from: running,
                to: running + change,
                kind: BarKind::Change,
            });
            running += change;
        }
        bars.push(Bar {
            label: "K end".into(),
            from: 0.0,
            to: k1,
            kind: BarKind::Total,
        });
        let mut plot = PlotData::new(
            ENERGY_BARS,
            ENERGY_BARS,
            format!(
                "work-energy residual Σ W + events − ΔK = {:.3e}{}",
                self.work_energy_residual,
                if self.is_reduced() { "" } else { " J" }
            ),
            if self.is_reduced() {
                "energy [1]"
            } else {
                "energy [J]"
            },
        );
        plot.bars = bars;
        plot
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scenario::Scenario;

    fn bars(toml: &str) -> (Summary, Vec<Bar>) {
        let s = Scenario::from_str("bars.toml", toml).unwrap_or_else(|e| panic!("{e}"));
        let out = s.run().expect("the run");
        let plot = out
            .plots
            .iter()
            .find(|p| p.spec == ENERGY_BARS)
            .expect("the energy bars are drawn");
        (out.summary.clone(), plot.bars.clone())
    }

    /// A 2 kg ball thrown up at 10 m/s against gravity and linear drag, bouncing on a floor: the
    /// waterfall starts at K = 100 J, each force's bar is its work, the bounce takes its share,
    /// and the last change ends at the final kinetic energy.
    #[test]
    fn the_waterfall_adds_up_to_the_final_kinetic_energy() {
        let (summary, bars) = bars(
            r#"
dimensions = 2
[[body]]
name = "ball"
mass = "2 kg"
position = ["0 m", "1 m"]
velocity = ["0 m/s", "10 m/s"]
radius = "5 cm"
[[force]]
name = "gravity"
kind = "uniform-gravity"
g = "9.81 m/s^2"
[[force]]
name = "drag"
kind = "linear-drag"
b = "0.3 kg/s"
[[wall]]
name = "floor"
point = ["0 m", "0 m"]
normal = [0, 1]
restitution = 0.5
[integrator]
method = "dopri5"
rtol = 1e-10
[stop]
t_max = "3 s"
[output]
plots = ["energy-bars"]
"#,
        );
        let labels: Vec<&str> = bars.iter().map(|b| b.label.as_str()).collect();
        assert_eq!(
            labels,
            ["K start", "W gravity", "W drag", "events", "K end"]
        );
        assert_eq!((bars[0].from, bars[0].to), (0.0, 100.0));
        let close = |a: Real, b: Real| (a - b).abs() <= 1e-12 * b.abs();
        assert!(close(bars[1].to - bars[1].from, summary.work["gravity"]));
        assert!(close(bars[2].to - bars[2].from, summary.work["drag"]));
        assert!(bars[2].to < bars[2].from, "drag takes energy");
        // the bounce with e = 0.5 keeps a quarter of the kinetic energy at impact
        let lost = bars[3].from - bars[3].to;
        assert!(lost > 0.0, "{lost}");
        assert!(!summary.events.is_empty());
        let k_end = summary.kinetic_energy.end.unwrap();
        assert_eq!((bars[4].from, bars[4].to), (0.0, k_end));
        assert!(
            (bars[3].to - k_end).abs() < 1e-9 * 100.0,
            "{} vs {k_end}",
            bars[3].to
        );
    }

    /// Without events there is no events bar: a free fall under gravity alone.
    #[test]
    fn a_run_without_events_has_no_events_bar() {
        let (_, bars) = bars(
            r#"
dimensions = 1
[[body]]
name = "stone"
mass = "1 kg"
position = "0 m"
velocity = "0 m/s"
[[force]]
name = "gravity"
kind = "uniform-gravity"
g = "10 m/s^2"
[integrator]
method = "rk4"
dt = "10 ms"
[stop]
t_max = "2 s"
[output]
plots = ["x(t)", "energy-bars"]
"#,
        );
        let labels: Vec<&str> = bars.iter().map(|b| b.label.as_str()).collect();
        assert_eq!(labels, ["K start", "W gravity", "K end"]);
        // falling 20 m under 10 m/s^2: 200 J of work, all of it kinetic energy
        assert!((bars[1].to - 200.0).abs() < 1e-9, "{:?}", bars[1]);
        assert!((bars[2].to - 200.0).abs() < 1e-9, "{:?}", bars[2]);
    }
}

//! The points of every plot, collected during a run: at the output times, thinned to at most
//! [`MAX_POINTS`] per series (every other point dropped, the stride doubled).

use super::output::Keep;
use super::plot::PlotSpec;
use crate::Real;
use crate::figure::{PlotData, Series};
use crate::particles::{Sample, StateVar};
use crate::simulate::{Observer, ObserverError};

/// Points kept per series before thinning (every other point is dropped, and the stride
/// doubles).
const MAX_POINTS: usize = 20_000;

/// Collects the points of every plot during a run.
pub(crate) struct PlotRecorder<'a> {
    specs: &'a [PlotSpec],
    points: Vec<Vec<Vec<(Real, Real)>>>,
    keep: Keep,
    stride: u64,
    seen: u64,
    dim: usize,
    mass: &'a [Real],
}

impl<'a> PlotRecorder<'a> {
    pub fn new(specs: &'a [PlotSpec], keep: Keep, dim: usize, mass: &'a [Real]) -> Self {
        Self {
            points: specs
                .iter()
                .map(|p| vec![Vec::new(); p.series.len()])
                .collect(),
            specs,
            keep,
            stride: 1,
            seen: 0,
            dim,
            mass,
        }
    }

    fn push(&mut self, s: &Sample<'_>) {
        for (spec, pts) in self.specs.iter().zip(&mut self.points) {
            for (series, p) in spec.series.iter().zip(pts.iter_mut()) {
                let x = series.x.value(s, self.dim, self.mass, series.body);
                let y = series.y.value(s, self.dim, self.mass, series.body);
                p.push((x, y));
            }
        }
    }

    fn thin(&mut self) {
        let full = self.points.iter().flatten().any(|p| p.len() > MAX_POINTS);
        if full {
            for p in self.points.iter_mut().flatten() {
                let mut i = 0;
                p.retain(|_| {
                    i += 1;
                    i % 2 == 1
                });
            }
            self.stride *= 2;
        }
    }

    pub fn into_data(self) -> Vec<PlotData> {
        self.specs
            .iter()
            .zip(self.points)
            .map(|(spec, pts)| {
                let mut plot = PlotData::new(
                    spec.spec.clone(),
                    spec.file_stem(),
                    spec.x_label.clone(),
                    spec.y_label.clone(),
                );
                plot.series = spec
                    .series
                    .iter()
                    .zip(pts)
                    .filter(|(_, p)| p.iter().any(|(x, y)| x.is_finite() && y.is_finite()))
                    .map(|(s, p)| Series::line(s.label.clone(), p))
                    .collect();
                if let Some(a) = &spec.analytic {
                    a.draw_over(&mut plot);
                }
                plot.equal_aspect = spec.series.iter().all(|s| {
                    matches!(s.x, StateVar::Position(..)) && matches!(s.y, StateVar::Position(..))
                });
                plot
            })
            .collect()
    }
}

impl Observer for PlotRecorder<'_> {
    fn observe(&mut self, s: &Sample<'_>) -> Result<(), ObserverError> {
        if self.keep.keeps(s) {
            if self.seen.is_multiple_of(self.stride) {
                self.push(s);
                self.thin();
            }
            self.seen += 1;
        }
        Ok(())
    }

    fn next_step(&self, step: u64) -> Option<u64> {
        if self.specs.is_empty() {
            None
        } else {
            self.keep.next_step(step)
        }
    }

    fn finish(&mut self, s: &Sample<'_>) -> Result<(), ObserverError> {
        // Always end on the final state (an event, t_max), whatever the stride; a repeated
        // last point draws nothing extra.
        self.push(s);
        Ok(())
    }
}

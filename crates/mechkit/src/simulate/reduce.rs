//! Reductions of a quantity over a run: `min`, `max`, `argmin`/`argmax` (the time at which),
//! `initial`, `final`, `mean` (time average) and `integral` (over time, trapezoidal).

use crate::Real;
use crate::particles::SampleKind;

/// How a quantity is reduced over the samples of a run.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[non_exhaustive]
pub enum Reduction {
    /// Smallest value.
    Min,
    /// Largest value.
    Max,
    /// Time of the smallest value (the first, on ties).
    ArgMin,
    /// Time of the largest value (the first, on ties).
    ArgMax,
    /// Value at the start.
    Initial,
    /// Value at the end.
    Final,
    /// Time average, `∫ f dt / (t_end - t_start)`.
    Mean,
    /// Time integral `∫ f dt`.
    Integral,
    /// Value at the last step taken before a located stop event (what a `while` loop on the
    /// condition ends with); the final value when no event was located.
    LastStep,
}

impl Reduction {
    /// Every reduction.
    pub const ALL: [Reduction; 9] = [
        Reduction::Min,
        Reduction::Max,
        Reduction::ArgMin,
        Reduction::ArgMax,
        Reduction::Initial,
        Reduction::Final,
        Reduction::Mean,
        Reduction::Integral,
        Reduction::LastStep,
    ];

    /// Name as written in `[observe]`.
    pub fn name(self) -> &'static str {
        match self {
            Reduction::Min => "min",
            Reduction::Max => "max",
            Reduction::ArgMin => "argmin",
            Reduction::ArgMax => "argmax",
            Reduction::Initial => "initial",
            Reduction::Final => "final",
            Reduction::Mean => "mean",
            Reduction::Integral => "integral",
            Reduction::LastStep => "last_step",
        }
    }

    /// Looks a reduction up by name.
    pub fn from_name(name: &str) -> Option<Reduction> {
        Reduction::ALL.into_iter().find(|r| r.name() == name)
    }
}

/// Accumulates one reduction over a sequence of `(t, value)` samples.
#[derive(Debug, Clone, PartialEq)]
pub struct Reducer {
    reduction: Reduction,
    count: u64,
    best: Real,
    best_t: Real,
    first: Real,
    first_t: Real,
    last: Real,
    last_t: Real,
    integral: Real,
    last_step: Real,
}

impl Reducer {
    /// An empty accumulator.
    pub fn new(reduction: Reduction) -> Self {
        Self {
            reduction,
            count: 0,
            best: Real::NAN,
            best_t: Real::NAN,
            first: Real::NAN,
            first_t: Real::NAN,
            last: Real::NAN,
            last_t: Real::NAN,
            integral: 0.0,
            last_step: Real::NAN,
        }
    }

    /// Adds a sample that is a step.
    pub fn push(&mut self, t: Real, value: Real) {
        self.push_sample(t, value, SampleKind::Step);
    }

    /// Adds a sample of any kind (only steps count for `last_step`).
    pub fn push_sample(&mut self, t: Real, value: Real, kind: SampleKind) {
        if kind.is_step() {
            self.last_step = value;
        }
        if self.count == 0 {
            self.first = value;
            self.first_t = t;
            self.best = value;
            self.best_t = t;
        } else {
            self.integral += 0.5 * (t - self.last_t) * (self.last + value);
            let better = match self.reduction {
                Reduction::Min | Reduction::ArgMin => value < self.best,
                Reduction::Max | Reduction::ArgMax => value > self.best,
                _ => false,
            };
            if better || (self.best.is_nan() && !value.is_nan()) {
                self.best = value;
                self.best_t = t;
            }
        }
        self.last = value;
        self.last_t = t;
        self.count += 1;
    }

    /// The result (NaN before any sample).
    pub fn value(&self) -> Real {
        match self.reduction {
            Reduction::Min | Reduction::Max => self.best,
            Reduction::ArgMin | Reduction::ArgMax => self.best_t,
            Reduction::Initial => self.first,
            Reduction::Final => self.last,
            Reduction::LastStep => self.last_step,
            Reduction::Integral => self.integral,
            Reduction::Mean => {
                let span = self.last_t - self.first_t;
                if span > 0.0 {
                    self.integral / span
                } else {
                    self.last
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reductions_of_a_parabola() {
        let run = |r| {
            let mut acc = Reducer::new(r);
            for i in 0..=100 {
                let t = f64::from(i) * 0.01;
                acc.push(t, 1.0 - (t - 0.3) * (t - 0.3));
            }
            acc.value()
        };
        assert!((run(Reduction::Max) - 1.0).abs() < 1e-15);
        assert!((run(Reduction::ArgMax) - 0.3).abs() < 1e-12);
        assert!((run(Reduction::Min) - (1.0 - 0.49)).abs() < 1e-12);
        assert!((run(Reduction::ArgMin) - 1.0).abs() < 1e-12);
        assert_eq!(run(Reduction::Initial), 1.0 - 0.09);
        // ∫0^1 1 - (t-0.3)² dt = 1 - (0.7³ + 0.3³)/3 = 0.87667; trapezoid error ~ h²/12·2
        assert!((run(Reduction::Integral) - (1.0 - (0.343 + 0.027) / 3.0)).abs() < 2e-5);
        assert!((run(Reduction::Mean) - run(Reduction::Integral)).abs() < 1e-15);
    }
}

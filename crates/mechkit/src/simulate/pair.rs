//! The integrator of adaptive runs: an explicit Runge-Kutta pair, Radau IIA(5), BDF, or
//! `auto`, DOP853 that hands over to Radau IIA(5) where the problem turns stiff.

use super::stepping::WorkSystem;
use crate::Real;
use crate::ode::{
    AdaptiveConfig, AdaptiveError, AdaptiveRk, AdaptiveStats, Bdf, ConfigError, Method, MethodKind,
    Radau5, State, StepPolynomial, Tableau,
};

#[allow(clippy::large_enum_variant)] // held in a Box by `Engine`
pub(crate) enum Pair {
    Explicit(AdaptiveRk),
    Radau5(Radau5),
    Bdf(Bdf),
    Auto(Box<Auto>),
}

/// `method = "auto"`: DOP853 while its stiffness test is quiet, then Radau IIA(5) for the rest
/// of the run (one way: LSODA also switches back; a run that turns stiff once usually stays
/// so, and radau5 is accurate on smooth stretches too).
pub(crate) struct Auto {
    explicit: AdaptiveRk,
    implicit: Option<Radau5>,
    config: AdaptiveConfig,
    /// When the implicit method took over.
    pub switched_at: Option<Real>,
}

impl Pair {
    /// The integrator of `method`, an adaptive or implicit one.
    pub fn new(method: Method, config: &AdaptiveConfig) -> Result<Pair, ConfigError> {
        Ok(match method {
            Method::Bdf => Pair::Bdf(Bdf::new(config.clone())),
            Method::Radau5 => Pair::Radau5(Radau5::new(config.clone())),
            Method::Auto => Pair::Auto(Box::new(Auto {
                explicit: AdaptiveRk::new(Tableau::dop853(), config.clone())?,
                implicit: None,
                config: config.clone(),
                switched_at: None,
            })),
            m => {
                let tableau = m
                    .tableau()
                    .filter(|_| m.kind() == MethodKind::Adaptive)
                    .ok_or(ConfigError::NotAdaptive(m.name()))?;
                Pair::Explicit(AdaptiveRk::new(tableau, config.clone())?)
            }
        })
    }

    pub fn reset(&mut self) {
        match self {
            Pair::Explicit(rk) => rk.reset(),
            Pair::Radau5(r) => r.reset(),
            Pair::Bdf(b) => b.reset(),
            Pair::Auto(a) => match &mut a.implicit {
                Some(r) => r.reset(),
                None => a.explicit.reset(),
            },
        }
    }

    pub fn stats(&self) -> AdaptiveStats {
        match self {
            Pair::Explicit(rk) => rk.stats(),
            Pair::Radau5(r) => r.stats(),
            Pair::Bdf(b) => b.stats(),
            Pair::Auto(a) => {
                let mut s = a.explicit.stats();
                if let Some(r) = &a.implicit {
                    let i = r.stats();
                    s.accepted += i.accepted;
                    s.rejected += i.rejected;
                    s.evaluations += i.evaluations;
                }
                s
            }
        }
    }

    pub fn step(
        &mut self,
        sys: &WorkSystem<'_>,
        state: &mut State,
        t_bound: Real,
    ) -> Result<Real, AdaptiveError> {
        match self {
            Pair::Explicit(rk) => rk.step(sys, state, t_bound),
            Pair::Radau5(r) => r.step(sys, state, t_bound),
            Pair::Bdf(b) => b.step(sys, state, t_bound),
            Pair::Auto(a) => {
                if a.implicit.is_none() && a.explicit.stiff_from().is_some() {
                    let mut r = Radau5::new(a.config.clone());
                    if let Some(h) = a.explicit.next_step() {
                        r.reset_to_step(h);
                    }
                    a.implicit = Some(r);
                    a.switched_at = Some(state.t);
                }
                match &mut a.implicit {
                    Some(r) => r.step(sys, state, t_bound),
                    None => a.explicit.step(sys, state, t_bound),
                }
            }
        }
    }

    /// The dense output of the last step (after a switch, the implicit method took it).
    pub fn dense_into(&mut self, sys: &WorkSystem<'_>, t: Real, out: &mut [Real]) {
        match self {
            Pair::Explicit(rk) => rk.dense_into(sys, t, out),
            Pair::Radau5(r) => r.dense_into(t, out),
            Pair::Bdf(b) => b.dense_into(t, out),
            Pair::Auto(a) => match &mut a.implicit {
                Some(r) => r.dense_into(t, out),
                None => a.explicit.dense_into(sys, t, out),
            },
        }
    }

    pub fn dense_polynomial_into(&mut self, sys: &WorkSystem<'_>, out: &mut StepPolynomial) {
        match self {
            Pair::Explicit(rk) => rk.dense_polynomial_into(sys, out),
            Pair::Radau5(r) => r.dense_polynomial_into(out),
            Pair::Bdf(b) => b.dense_polynomial_into(out),
            Pair::Auto(a) => match &mut a.implicit {
                Some(r) => r.dense_polynomial_into(out),
                None => a.explicit.dense_polynomial_into(sys, out),
            },
        }
    }
}

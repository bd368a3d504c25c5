//! A run of many steps: thermo rows every `thermo_every` steps (and at the last), frames every
//! `frame_every` steps, handed to an observer as they are taken (a front streams them to
//! files, draws a progress bar); stopped early by a [`Cancel`] handle, by the observer (an
//! output reached its size limit) or by a diverging energy.

use std::time::Instant;

use crate::Real;
use crate::simulate::Cancel;

use super::{Md, MdError, MdInput, PairPotential, Thermo};

/// How long to run and what to record: the number of velocity-Verlet steps, a thermo row every
/// `thermo_every` steps (and one at the start and the end), a frame every `frame_every` steps
/// (and one at the start) when it is given.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct RunPlan {
    /// Steps to take.
    pub steps: usize,
    /// Steps between thermo rows (≥ 1).
    pub thermo_every: usize,
    /// Steps between frames (≥ 1), or no frames.
    pub frame_every: Option<usize>,
}

impl RunPlan {
    /// A plan, checked: the intervals are at least one step, and the steps at most
    /// [`crate::simulate::MAX_STEPS`] (10^9), the bound of every run of mechkit.
    pub fn new(
        steps: usize,
        thermo_every: usize,
        frame_every: Option<usize>,
    ) -> Result<Self, MdError> {
        let max = crate::simulate::MAX_STEPS;
        if steps as u64 > max {
            return Err(MdError::TooMany {
                input: MdInput::Steps,
                value: steps as u64,
                max,
                hint: "a longer simulation is several runs, each started from the last frame of the one before (--positions and --velocities)",
            });
        }
        if thermo_every == 0 {
            return Err(MdError::NotPositive {
                input: MdInput::ThermoEvery,
                value: 0.0,
            });
        }
        if frame_every == Some(0) {
            return Err(MdError::NotPositive {
                input: MdInput::FrameEvery,
                value: 0.0,
            });
        }
        Ok(Self {
            steps,
            thermo_every,
            frame_every,
        })
    }
}

/// What a run hands out as it goes. Every method has a default that does nothing.
pub trait MdObserver<P: PairPotential> {
    /// What the observer's own work can fail with (writing a file).
    type Error;

    /// A thermo row was taken.
    fn thermo(&mut self, _row: &Thermo) -> Result<(), Self::Error> {
        Ok(())
    }

    /// A frame is due: the state is `md` now.
    fn frame(&mut self, _md: &Md<P>) -> Result<(), Self::Error> {
        Ok(())
    }

    /// A step was taken; `done` steps of this run so far.
    fn step(&mut self, _done: usize) {}

    /// Whether the run must stop before its next step (an output reached its size limit).
    fn full(&self) -> bool {
        false
    }
}

/// An observer that keeps nothing: the run's rows are in its [`MdRun`].
impl<P: PairPotential> MdObserver<P> for () {
    type Error = std::convert::Infallible;
}

/// Why a run ended.
#[derive(Debug, Clone, PartialEq)]
pub enum MdStop {
    /// Every step was taken.
    Completed,
    /// The cancellation handle was raised (Ctrl-C).
    Cancelled,
    /// The observer asked to stop (an output reached its size limit).
    Full,
    /// The energy stopped being finite.
    Diverged(MdError),
}

/// A finished run: its thermo rows (the start, every `thermo_every` steps, the end), why it
/// ended and how long it took.
#[derive(Debug, Clone, PartialEq)]
pub struct MdRun {
    /// The thermo rows in order, the last one at the state reached.
    pub rows: Vec<Thermo>,
    /// Why it ended.
    pub stop: MdStop,
    /// Wall-clock seconds of the steps.
    pub seconds: Real,
}

impl<P: PairPotential> Md<P> {
    /// Runs `plan.steps` steps, handing `observer` each thermo row and frame as it is taken;
    /// `cancel` (or the observer being full) ends the run after the current step, a
    /// non-finite energy ends it at once. The last row is always of the state reached.
    ///
    /// ```
    /// use mechkit::md::{Lattice, LennardJones, Md, MdConfig, MdStop, RunPlan, maxwell_boltzmann};
    /// use mechkit::simulate::Cancel;
    /// let (sim_box, x) = Lattice::Fcc.build(4, 0.8442).unwrap();
    /// let v = maxwell_boltzmann(1.44, 1.0, 3, x.len(), 1).unwrap();
    /// let mut md = Md::new(sim_box, LennardJones::reduced(2.5).unwrap(), x, v, MdConfig::default()).unwrap();
    /// let plan = RunPlan::new(20, 5, None).unwrap();
    /// let run = md.run_observed(&plan, &Cancel::new(), &mut ()).unwrap();
    /// assert_eq!(run.stop, MdStop::Completed);
    /// assert_eq!(run.rows.iter().map(|r| r.step).collect::<Vec<_>>(), [0, 5, 10, 15, 20]);
    /// ```
    pub fn run_observed<O: MdObserver<P>>(
        &mut self,
        plan: &RunPlan,
        cancel: &Cancel,
        observer: &mut O,
    ) -> Result<MdRun, O::Error> {
        let thermo_every = plan.thermo_every.max(1);
        let mut rows = vec![self.thermo()];
        observer.thermo(&rows[0])?;
        if plan.frame_every.is_some() {
            observer.frame(self)?;
        }
        let start = Instant::now();
        let mut stop = MdStop::Completed;
        for step in 1..=plan.steps {
            if cancel.is_cancelled() {
                stop = MdStop::Cancelled;
                break;
            }
            if observer.full() {
                stop = MdStop::Full;
                break;
            }
            let row_due = step % thermo_every == 0 || step == plan.steps;
            let frame_due = plan.frame_every.is_some_and(|k| step % k.max(1) == 0);
            // the energy is summed at the steps whose rows or frames are taken
            if let Err(e) = self.step_checked(row_due || frame_due) {
                stop = MdStop::Diverged(e);
                break;
            }
            observer.step(step);
            if row_due {
                let row = self.thermo();
                // the finiteness rule: a row that is not all numbers is not written
                if let Some(e) = not_finite(&row) {
                    stop = MdStop::Diverged(e);
                    break;
                }
                observer.thermo(&row)?;
                rows.push(row);
            }
            if frame_due {
                observer.frame(self)?;
            }
        }
        if stop == MdStop::Completed && observer.full() {
            stop = MdStop::Full;
        }
        if rows.last().is_none_or(|r| r.step != self.steps()) {
            self.refresh_sums();
            let row = self.thermo();
            match not_finite(&row) {
                None => {
                    observer.thermo(&row)?;
                    rows.push(row);
                }
                Some(e) if stop == MdStop::Completed => stop = MdStop::Diverged(e),
                Some(_) => {}
            }
        }
        Ok(MdRun {
            rows,
            stop,
            seconds: start.elapsed().as_secs_f64(),
        })
    }
}

/// The first quantity of a thermo row that is not finite, as the error that stops the run.
fn not_finite(row: &Thermo) -> Option<MdError> {
    [
        ("kinetic energy", row.kinetic),
        ("potential energy", row.potential),
        ("total energy", row.total),
        ("temperature", row.temperature),
        ("pressure", row.pressure),
    ]
    .into_iter()
    .find(|(_, v)| !v.is_finite())
    .map(|(quantity, value)| MdError::NotFinite {
        step: row.step,
        quantity,
        value,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::md::{Lattice, LennardJones, MdConfig, maxwell_boltzmann};

    fn melt() -> Md<LennardJones> {
        let (sim_box, x) = Lattice::Fcc.build(4, 0.8442).unwrap();
        let v = maxwell_boltzmann(1.44, 1.0, 3, x.len(), 7).unwrap();
        Md::new(
            sim_box,
            LennardJones::reduced(2.5).unwrap(),
            x,
            v,
            MdConfig::default(),
        )
        .unwrap()
    }

    /// Records what it is handed; full after `limit` frames.
    struct Recorder {
        rows: Vec<usize>,
        frames: Vec<usize>,
        steps: usize,
        limit: usize,
    }

    impl MdObserver<LennardJones> for Recorder {
        type Error = ();
        fn thermo(&mut self, row: &Thermo) -> Result<(), ()> {
            self.rows.push(row.step);
            Ok(())
        }
        fn frame(&mut self, md: &Md<LennardJones>) -> Result<(), ()> {
            self.frames.push(md.steps());
            Ok(())
        }
        fn step(&mut self, done: usize) {
            self.steps = done;
        }
        fn full(&self) -> bool {
            self.frames.len() >= self.limit
        }
    }

    #[test]
    fn rows_and_frames_at_their_intervals_and_the_last_row_at_the_end() {
        let mut md = melt();
        let mut rec = Recorder {
            rows: Vec::new(),
            frames: Vec::new(),
            steps: 0,
            limit: usize::MAX,
        };
        let plan = RunPlan::new(12, 5, Some(4)).unwrap();
        let run = md.run_observed(&plan, &Cancel::new(), &mut rec).unwrap();
        assert_eq!(run.stop, MdStop::Completed);
        assert_eq!(rec.rows, [0, 5, 10, 12]);
        assert_eq!(rec.frames, [0, 4, 8, 12]);
        assert_eq!(rec.steps, 12);
        let steps: Vec<usize> = run.rows.iter().map(|r| r.step).collect();
        assert_eq!(steps, rec.rows);
    }

    #[test]
    fn a_full_observer_or_a_cancel_stops_with_a_row_of_the_state_reached() {
        let mut md = melt();
        let mut rec = Recorder {
            rows: Vec::new(),
            frames: Vec::new(),
            steps: 0,
            limit: 2,
        };
        let plan = RunPlan::new(100, 50, Some(3)).unwrap();
        let run = md.run_observed(&plan, &Cancel::new(), &mut rec).unwrap();
        assert_eq!(run.stop, MdStop::Full);
        assert_eq!(md.steps(), 3);
        assert_eq!(rec.rows, [0, 3]);
        let cancel = Cancel::new();
        cancel.cancel();
        let mut md = melt();
        let run = md.run_observed(&plan, &cancel, &mut ()).unwrap();
        assert_eq!(run.stop, MdStop::Cancelled);
        assert_eq!(run.rows.len(), 1, "the start is the state reached");
    }

    /// Issue 26: `md --steps 1e18` ran for ever; it is refused before the system is built.
    #[test]
    fn issue_026_a_run_of_more_steps_than_any_run_takes_is_refused() {
        let e = RunPlan::new(1_000_000_000_000_000_000, 50, None).unwrap_err();
        assert_eq!(e.input(), Some(MdInput::Steps));
        assert!(e.to_string().contains("more than 1000000000"), "{e}");
        assert!(RunPlan::new(1_000_000_000, 50, None).is_ok());
    }

    #[test]
    fn intervals_of_zero_steps_are_refused() {
        assert_eq!(
            RunPlan::new(10, 0, None).unwrap_err().input(),
            Some(MdInput::ThermoEvery)
        );
        assert_eq!(
            RunPlan::new(10, 1, Some(0)).unwrap_err().input(),
            Some(MdInput::FrameEvery)
        );
    }

    /// Issue 26: starts that cannot work are refused by `Md::new`, naming the input; a run
    /// stops at the first thermo row that is not finite and hands none such out.
    #[test]
    fn issue_026_starts_that_cannot_work_are_refused_and_no_row_is_not_finite() {
        let (sim_box, x) = Lattice::Fcc.build(4, 0.8442).unwrap();
        let lj = || LennardJones::reduced(2.5).unwrap();
        let v = maxwell_boltzmann(1.44, 1.0, 3, x.len(), 7).unwrap();
        let config = |dt: Real, mass: Real| MdConfig {
            dt,
            mass,
            ..MdConfig::default()
        };
        let refused = |x: Vec<[Real; 3]>, v: Vec<[Real; 3]>, c: MdConfig| match Md::new(
            sim_box,
            lj(),
            x,
            v,
            c,
        ) {
            Ok(_) => panic!("accepted"),
            Err(e) => e,
        };
        let e = refused(x.clone(), v.clone(), config(0.005, 1e-320));
        assert_eq!(e.input(), Some(MdInput::Mass));
        assert!(matches!(e, MdError::Subnormal { .. }), "{e}");
        let e = refused(x.clone(), v.clone(), config(1e308, 1.0));
        assert_eq!(e.input(), Some(MdInput::TimeStep));
        let hot = maxwell_boltzmann(1e100, 1.0, 3, x.len(), 7).unwrap();
        let e = refused(x.clone(), hot, config(0.005, 1.0));
        assert!(matches!(e, MdError::StepTooLong { .. }), "{e}");
        let mut twins = x.clone();
        twins[9] = twins[3];
        let e = refused(twins, v.clone(), config(0.005, 1.0));
        assert!(
            matches!(
                e,
                MdError::Coincident {
                    first: 4,
                    second: 10,
                    ..
                }
            ),
            "{e}"
        );
        // a step far too long for the forces (but within the box): the run stops at the
        // first row that is not finite, and every row handed out is finite
        let mut md = Md::new(sim_box, lj(), x, v, config(0.4, 1.0)).unwrap();
        let mut rec = Recorder {
            rows: Vec::new(),
            frames: Vec::new(),
            steps: 0,
            limit: usize::MAX,
        };
        let run = md
            .run_observed(
                &RunPlan::new(200, 1, None).unwrap(),
                &Cancel::new(),
                &mut rec,
            )
            .unwrap();
        assert!(matches!(run.stop, MdStop::Diverged(_)), "{:?}", run.stop);
        assert!(not_finite(run.rows.last().unwrap()).is_none());
        assert!(run.rows.iter().all(|r| not_finite(r).is_none()));
        assert_eq!(rec.rows.len(), run.rows.len());
    }
}

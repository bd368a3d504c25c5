//! `Md`: N equal particles with a pair potential in a box, advanced by velocity Verlet.
//!
//! One step (Swope et al. 1982): v ← v + (dt/2m) F; x ← x + dt v; F ← F(x); v ← v + (dt/2m) F.
//! The neighbour list is rebuilt (positions wrapped into the periodic box first) whenever
//! some particle has moved more than half the skin since the last build. At each build the
//! particles are stored again in the list's order (by cell), so the forces read and write
//! them in place and neighbours lie close in memory; their original numbers go with them
//! (`id`), and what the particles are read as from outside ([`Md::positions`], frames,
//! exports) is in the original order. The per-particle loops run in fixed chunks on the
//! thread pool when there is one, and buffers are reused: nothing is allocated per step or
//! per rebuild once they have grown.

use rayon::prelude::*;

use crate::Real;

use super::forces::{CHUNK, forces_summed};
use super::reorder::{gather, permute};
use super::start::check_start;
use super::{ForceScratch, MdError, MdInput, NeighbourList, PairPotential, PairSums, SimBox};

/// One particle's position and velocity (updated) with its force and its position at the
/// last list build.
type DriftItem<'a> = (
    (&'a mut [Real; 3], &'a mut [Real; 3]),
    (&'a [Real; 3], &'a [f32; 3]),
);

/// Run settings of [`Md`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MdConfig {
    /// Time step (reduced units: τ).
    pub dt: Real,
    /// Verlet skin added to the cut-off for the neighbour list.
    pub skin: Real,
    /// Mass of every particle.
    pub mass: Real,
    /// Threads for forces and list builds (1 = serial); the results do not depend on it.
    pub threads: usize,
    /// Steps between neighbour-list checks (LAMMPS's `neigh_modify every N`): 1 checks
    /// after every step, which never misses a pair; a larger N saves the checks' builds
    /// between them and counts the builds that came late ([`Md::dangerous_builds`]).
    pub neigh_every: usize,
    /// At a due check: rebuild only if some particle has moved more than half the skin since
    /// the last build (`check yes`, the default), or always (`check no`).
    pub neigh_check: bool,
}

impl Default for MdConfig {
    /// The LJ melt's settings: dt = 0.005 τ, skin 0.3 σ, m = 1, one thread, the list
    /// checked after every step.
    fn default() -> Self {
        Self {
            dt: 0.005,
            skin: 0.3,
            mass: 1.0,
            threads: 1,
            neigh_every: 1,
            neigh_check: true,
        }
    }
}

/// A many-particle system: positions, velocities, forces, the neighbour list and the pair
/// sums of the current state.
pub struct Md<P: PairPotential> {
    pub(crate) sim_box: SimBox,
    pub(crate) potential: P,
    pub(crate) config: MdConfig,
    /// Positions, velocities and forces, in the order of the last list build.
    pub(crate) x: Vec<[Real; 3]>,
    pub(crate) v: Vec<[Real; 3]>,
    pub(crate) f: Vec<[Real; 3]>,
    /// The original number of each stored particle.
    pub(crate) id: Vec<u32>,
    /// Positions at the last list build, to 32 bits, to measure displacements.
    x_built: Vec<[f32; 3]>,
    /// How far a displacement measured from `x_built` may be short of the true one.
    built_error: Real,
    /// Box lengths that wrapping has subtracted from each position: unwrapped = x + image L.
    pub(crate) image: Vec<[i32; 3]>,
    /// Unwrapped positions at the start, in the original order, for the mean-square
    /// displacement.
    pub(crate) x0: Vec<[Real; 3]>,
    pub(crate) list: NeighbourList,
    pub(crate) sums: PairSums,
    /// Whether `sums` are of the current positions (a step may skip them).
    sums_current: bool,
    scratch: ForceScratch,
    /// Bits of the particles placed, while sorting at a build.
    visited: Vec<u64>,
    pool: Option<rayon::ThreadPool>,
    pub(crate) steps: usize,
    rebuilds: usize,
    /// Steps since the last list build.
    since_build: usize,
    /// Whether a particle has moved more than half the skin since the last build.
    moved_far: bool,
    /// Builds that came after a particle had moved more than half the skin.
    dangerous: usize,
}

impl<P: PairPotential> Md<P> {
    /// A system of particles at `x` with velocities `v` (same length) in `sim_box`; forces
    /// are evaluated at once.
    pub fn new(
        sim_box: SimBox,
        potential: P,
        x: Vec<[Real; 3]>,
        v: Vec<[Real; 3]>,
        config: MdConfig,
    ) -> Result<Self, MdError> {
        if v.len() != x.len() {
            return Err(MdError::Length {
                what: "the velocities",
                got: v.len(),
                expected: x.len(),
            });
        }
        for (input, value) in [
            (MdInput::TimeStep, config.dt),
            (MdInput::Mass, config.mass),
            (MdInput::Skin, config.skin),
        ] {
            if !(value.is_finite() && value > 0.0) {
                return Err(MdError::NotPositive { input, value });
            }
            if value < Real::MIN_POSITIVE {
                return Err(MdError::Subnormal { input, value });
            }
        }
        let lengths = sim_box.lengths();
        let edge = lengths[..sim_box.dim()]
            .iter()
            .copied()
            .fold(Real::INFINITY, Real::min);
        check_start(&x, &v, config.dt, edge)?;
        if config.neigh_every == 0 {
            return Err(MdError::NotPositive {
                input: MdInput::NeighEvery,
                value: 0.0,
            });
        }
        if config.threads == 0 {
            return Err(MdError::NotPositive {
                input: MdInput::Threads,
                value: 0.0,
            });
        }
        if config.threads > super::MAX_THREADS {
            return Err(MdError::TooMany {
                input: MdInput::Threads,
                value: config.threads as u64,
                max: super::MAX_THREADS as u64,
                hint: "more threads than cores only slow a run down",
            });
        }
        if x.len() > super::MAX_ATOMS {
            return Err(MdError::TooMany {
                input: MdInput::Atoms,
                value: x.len() as u64,
                max: super::MAX_ATOMS as u64,
                hint: "give fewer atoms",
            });
        }
        sim_box.check_range(potential.cutoff() + config.skin)?;
        let pool = if config.threads > 1 {
            rayon::ThreadPoolBuilder::new()
                .num_threads(config.threads)
                .build()
                .ok()
        } else {
            None
        };
        let n = x.len();
        let mut md = Self {
            sim_box,
            potential,
            config,
            x0: x.clone(),
            x,
            v,
            f: vec![[0.0; 3]; n],
            id: (0..n as u32).collect(),
            x_built: Vec::new(),
            built_error: 0.0,
            image: vec![[0; 3]; n],
            list: NeighbourList::default(),
            sums: PairSums::default(),
            sums_current: false,
            scratch: ForceScratch::default(),
            visited: Vec::new(),
            pool,
            steps: 0,
            rebuilds: 0,
            since_build: 0,
            moved_far: false,
            dangerous: 0,
        };
        md.rebuild();
        md.update_forces();
        // atoms that overlap without coinciding: no finite energy to start from
        if !md.sums.potential.is_finite() {
            return Err(MdError::Diverged {
                step: 0,
                energy: md.sums.potential,
            });
        }
        Ok(md)
    }

    /// Wraps the positions into the box, sorts the particles by cell and rebuilds the
    /// neighbour list.
    fn rebuild(&mut self) {
        let sim_box = self.sim_box;
        let lengths = sim_box.lengths();
        let wrap = |(x, n): (&mut [Real; 3], &mut [i32; 3])| {
            let before = *x;
            sim_box.wrap(x);
            for a in 0..3 {
                if before[a] != x[a] {
                    // (saturates in a run that has diverged, which stops at this step)
                    n[a] = n[a].saturating_add(((before[a] - x[a]) / lengths[a]).round() as i32);
                }
            }
        };
        match &self.pool {
            Some(pool) => pool.install(|| {
                self.x
                    .par_iter_mut()
                    .zip(&mut self.image)
                    .with_min_len(CHUNK)
                    .for_each(wrap);
            }),
            None => self.x.iter_mut().zip(&mut self.image).for_each(wrap),
        }
        let range = self.potential.cutoff() + self.config.skin;
        let pool = self.pool.as_ref();
        self.list.sort(&self.sim_box, &self.x, range, pool);
        let order = self.list.order();
        // (through the forces' buffer: they are computed again after a build)
        gather(&mut self.x, &mut self.f, order, pool);
        gather(&mut self.v, &mut self.f, order, pool);
        permute(&mut self.id, order, &mut self.visited);
        permute(&mut self.image, order, &mut self.visited);
        // the list's order is now the original numbers, as its users read it
        self.list.cells.order.copy_from_slice(&self.id);
        self.x_built.clear();
        self.x_built
            .extend(self.x.iter().map(|p| p.map(|c| c as f32)));
        // each coordinate rounded to 24 bits: off by at most 2^-24 of the largest
        let largest = self
            .x
            .iter()
            .flatten()
            .fold(0.0, |m: Real, c| m.max(c.abs()));
        self.built_error = 3.0_f64.sqrt() * largest * (-23.0_f64).exp2();
        self.list.build_sorted(&self.sim_box, &self.x, pool);
        self.rebuilds += 1;
        // a particle moved more than half the skin before this build: a pair may have come
        // within the cut-off unlisted
        self.dangerous += usize::from(self.moved_far);
        self.moved_far = false;
        self.since_build = 0;
    }

    /// `a` (in the stored order) in the original order.
    pub(crate) fn unsorted<T: Copy + Default>(&self, a: &[T]) -> Vec<T> {
        let mut out = vec![T::default(); a.len()];
        for (&i, v) in self.id.iter().zip(a) {
            out[i as usize] = *v;
        }
        out
    }

    /// Forces, energy and virial at the current positions.
    fn update_forces(&mut self) {
        self.update(true);
    }

    /// Forces at the current positions, and the energy and the virial when `energy`.
    fn update(&mut self, energy: bool) {
        let sums = forces_summed(
            &self.potential,
            &self.sim_box,
            &self.list,
            &self.x,
            &mut self.f,
            self.pool.as_ref(),
            &mut self.scratch,
            energy,
        );
        if energy {
            self.sums = sums;
        }
        self.sums_current = energy;
    }

    /// Sums the energy and the virial of the current positions if the last step skipped
    /// them (the forces come out the same, bit for bit).
    pub(crate) fn refresh_sums(&mut self) {
        if !self.sums_current {
            self.update_forces();
        }
    }

    /// One velocity-Verlet step; the energy and the virial are up to date after it.
    pub fn step(&mut self) {
        self.advance(true);
    }

    /// One velocity-Verlet step, summing the energy and the virial only when `energy` (a
    /// step whose energy nobody reads skips them; [`Md::pair_sums`] is then stale until the
    /// next step with it). Returns whether every new velocity is finite.
    fn advance(&mut self, energy: bool) -> bool {
        let h = 0.5 * self.config.dt / self.config.mass;
        let dt = self.config.dt;
        // half the skin, less what the 32-bit positions of the build may hide
        let reach = (0.5 * self.config.skin - self.built_error).max(0.0);
        let limit = reach * reach;
        // Half kick and drift; reports whether the particle left its skin/2 sphere.
        let drift = |((x, v), (f, x_b)): DriftItem<'_>| -> bool {
            let mut d2 = 0.0;
            for a in 0..3 {
                v[a] += h * f[a];
                x[a] += dt * v[a];
                let d = x[a] - Real::from(x_b[a]);
                d2 += d * d;
            }
            d2 > limit
        };
        let moved_far = match &self.pool {
            Some(pool) => pool.install(|| {
                self.x
                    .par_iter_mut()
                    .zip(&mut self.v)
                    .zip(self.f.par_iter().zip(&self.x_built))
                    .with_min_len(CHUNK)
                    .map(drift)
                    .reduce(|| false, |a, b| a | b)
            }),
            None => self
                .x
                .iter_mut()
                .zip(&mut self.v)
                .zip(self.f.iter().zip(&self.x_built))
                .map(drift)
                .fold(false, |a, b| a | b),
        };
        self.since_build += 1;
        let due = self.since_build.is_multiple_of(self.config.neigh_every);
        if due && (moved_far || !self.config.neigh_check) {
            self.rebuild();
        } else {
            self.moved_far |= moved_far;
        }
        self.update(energy);
        // Second half kick; reports whether the velocity is finite.
        let kick = |(v, f): (&mut [Real; 3], &[Real; 3])| -> bool {
            for a in 0..3 {
                v[a] += h * f[a];
            }
            v.iter().all(|c| c.is_finite())
        };
        let finite = match &self.pool {
            Some(pool) => pool.install(|| {
                self.v
                    .par_iter_mut()
                    .zip(&self.f)
                    .with_min_len(CHUNK)
                    .map(kick)
                    .reduce(|| true, |a, b| a & b)
            }),
            None => self
                .v
                .iter_mut()
                .zip(&self.f)
                .map(kick)
                .fold(true, |a, b| a & b),
        };
        self.steps += 1;
        finite
    }

    /// `steps` steps; fails if a velocity or the energy stops being finite (velocities
    /// checked after each step, the energy after the last; the energy and the virial are
    /// summed at the last step only).
    pub fn run(&mut self, steps: usize) -> Result<(), MdError> {
        for k in 1..=steps {
            self.step_checked(k == steps)?;
        }
        Ok(())
    }

    /// One step, the energy summed when `energy`; fails as [`Md::run`] does.
    pub(crate) fn step_checked(&mut self, energy: bool) -> Result<(), MdError> {
        let finite = self.advance(energy);
        if !finite {
            self.refresh_sums();
        }
        if !finite || (energy && !self.sums.potential.is_finite()) {
            return Err(self.divergence());
        }
        Ok(())
    }

    /// Why the state reached is not a state: the energy if it is not finite, else the
    /// kinetic energy (a velocity that overflowed).
    fn divergence(&self) -> MdError {
        if self.sums.potential.is_finite() {
            MdError::NotFinite {
                step: self.steps,
                quantity: "kinetic energy",
                value: self.kinetic_energy(),
            }
        } else {
            MdError::Diverged {
                step: self.steps,
                energy: self.sums.potential,
            }
        }
    }

    /// Positions (wrapped into the box at the last list build), in the original order.
    pub fn positions(&self) -> Vec<[Real; 3]> {
        self.unsorted(&self.x)
    }

    /// Velocities, in the original order.
    pub fn velocities(&self) -> Vec<[Real; 3]> {
        self.unsorted(&self.v)
    }

    /// Forces at the current positions, in the original order.
    pub fn forces(&self) -> Vec<[Real; 3]> {
        self.unsorted(&self.f)
    }

    /// The box.
    pub fn sim_box(&self) -> &SimBox {
        &self.sim_box
    }

    /// The settings.
    pub fn config(&self) -> &MdConfig {
        &self.config
    }

    /// The number of particles.
    pub fn len(&self) -> usize {
        self.x.len()
    }

    /// Whether there are no particles.
    pub fn is_empty(&self) -> bool {
        self.x.is_empty()
    }

    /// Steps taken.
    pub fn steps(&self) -> usize {
        self.steps
    }

    /// Neighbour-list builds so far (the first included).
    pub fn rebuilds(&self) -> usize {
        self.rebuilds
    }

    /// Builds that came after some particle had moved more than half the skin since the
    /// build before (LAMMPS's "dangerous builds"): between them a pair may have come within
    /// the cut-off without being listed. Always 0 with `neigh_every = 1` and `check yes`.
    pub fn dangerous_builds(&self) -> usize {
        self.dangerous
    }

    /// The neighbour list in use; its [`order`](NeighbourList::order) and
    /// [`pairs`](NeighbourList::pairs) are in the particles' original numbers.
    pub fn neighbour_list(&self) -> &NeighbourList {
        &self.list
    }

    /// Potential energy and virial of the current positions.
    pub fn pair_sums(&self) -> PairSums {
        debug_assert!(self.sums_current, "the sums of a step that skipped them");
        self.sums
    }
}

//! The trajectory's row layout, shared by the CSV file and the in-memory table: its columns
//! with their units, which samples are kept, and each row's values.

use crate::Real;
use crate::csv::Column;
use crate::particles::{ParticleSystem, Sample, SampleKind, spin};
use crate::simulate::{Observer, ObserverError, StopReason};

/// The trajectory's columns with their units: `t`, positions, velocities, with two or more
/// bodies the centre of mass (`cm.x`, `cm.vx`, `cm.ax`) and the split `K = K_cm + K_internal`,
/// then `K`, `U`, `E`, the work of each force and its power `F·v`. Hinged bodies' coordinates
/// are angles (rad, rad/s).
pub fn csv_columns(sys: &ParticleSystem, has_potential: bool) -> Vec<Column> {
    let axes = &["x", "y", "z"][..sys.dim()];
    let coordinates = sys.coordinates();
    let [position, velocity, _] = coordinates.component_names(sys.dim());
    let (q_unit, v_unit) = match coordinates {
        crate::particles::Coordinates::Angle => ("rad", "rad/s"),
        crate::particles::Coordinates::Cartesian => ("m", "m/s"),
    };
    let mut cols = vec![Column::new("t", "s")];
    for b in sys.bodies() {
        cols.extend(
            position
                .iter()
                .map(|a| Column::new(format!("{}.{a}", b.name), q_unit)),
        );
        cols.extend(
            velocity
                .iter()
                .map(|a| Column::new(format!("{}.{a}", b.name), v_unit)),
        );
    }
    for e in sys.extras().iter().filter(|e| e.body.is_some()) {
        cols.push(Column::new(format!("{}.theta", e.name), "rad"));
        cols.push(Column::new(format!("{}.omega", e.name), "rad/s"));
    }
    for sp in sys.spinners() {
        let b = &sys.bodies()[sp.body].name;
        cols.extend((0..4).map(|k| Column::new(format!("{b}.q{k}"), "1")));
        cols.extend(["wx", "wy", "wz"].map(|w| Column::new(format!("{b}.{w}"), "rad/s")));
    }
    for e in sys.extras().iter().filter(|e| e.mass_of.is_some()) {
        cols.push(Column::new(e.name.clone(), "kg"));
    }
    if sys.bodies().len() > 1 {
        for (prefix, unit) in [("", "m"), ("v", "m/s"), ("a", "m/s^2")] {
            cols.extend(
                axes.iter()
                    .map(|a| Column::new(format!("cm.{prefix}{a}"), unit)),
            );
        }
        cols.push(Column::new("K_cm", "J"));
        cols.push(Column::new("K_internal", "J"));
    }
    if sys.has_rotation() {
        cols.push(Column::new("K_rot", "J"));
    }
    cols.push(Column::new("K", "J"));
    if has_potential {
        cols.push(Column::new("U", "J"));
        cols.push(Column::new("E", "J"));
    }
    cols.extend(
        sys.forces()
            .iter()
            .map(|f| Column::new(format!("work.{}", f.name()), "J")),
    );
    cols.extend(
        sys.forces()
            .iter()
            .map(|f| Column::new(format!("power.{}", f.name()), "W")),
    );
    cols
}

/// [`csv_columns`] labelled in the scenario's units: as they are in SI, every unit `1` in
/// reduced units (`units = "reduced"`).
pub fn csv_columns_in(
    sys: &ParticleSystem,
    has_potential: bool,
    units: mechkit_expr::units::UnitSystem,
) -> Vec<Column> {
    let mut cols = csv_columns(sys, has_potential);
    for c in &mut cols {
        if let Some(u) = &mut c.unit {
            *u = units.label(u).to_string();
        }
    }
    cols
}

/// The trajectory's column names ([`csv_columns`] without the units).
pub fn csv_header(sys: &ParticleSystem, has_potential: bool) -> Vec<String> {
    csv_columns(sys, has_potential)
        .into_iter()
        .map(|c| c.name)
        .collect()
}

/// Which samples go to the trajectory file and the plots.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) struct Keep {
    /// Every n-th step (when there are no output times).
    pub every: u64,
    /// Output times were requested: keep those (and the start), not the steps.
    pub grid: bool,
}

impl Keep {
    pub fn keeps(&self, s: &Sample<'_>) -> bool {
        match s.kind {
            SampleKind::Event | SampleKind::Grid => true,
            SampleKind::Step if self.grid => s.step == 0,
            SampleKind::Step => s.step.is_multiple_of(self.every.max(1)),
        }
    }

    /// The first step after `step` that [`Keep::keeps`].
    pub fn next_step(&self, step: u64) -> Option<u64> {
        if self.grid {
            return None;
        }
        let every = self.every.max(1);
        Some((step / every + 1) * every)
    }
}

/// Where the kept rows of a run go (a CSV file, a table in memory): each is an [`Observer`]
/// that receives the samples [`Keep`] keeps, and the last.
pub(crate) trait RowSink {
    /// Which samples it keeps.
    fn keep(&self) -> Keep;
    /// The time of the last row it received.
    fn last_t(&self) -> Option<Real>;
    /// Receives the row of `s`.
    fn write(&mut self, s: &Sample<'_>);
    /// Why the run must stop (a limit reached, a write failed).
    fn stop(&self) -> Option<(StopReason, String)>;
}

impl<T: RowSink> Observer for T {
    fn observe(&mut self, s: &Sample<'_>) -> Result<(), ObserverError> {
        if self.keep().keeps(s) {
            self.write(s);
        }
        Ok(())
    }

    fn next_step(&self, step: u64) -> Option<u64> {
        self.keep().next_step(step)
    }

    fn halt(&self) -> Option<(StopReason, String)> {
        self.stop()
    }

    fn finish(&mut self, s: &Sample<'_>) -> Result<(), ObserverError> {
        if self.last_t() != Some(s.t) {
            self.write(s);
        }
        Ok(())
    }
}

/// Where a row's values come from in a sample of one system, in the order of
/// [`csv_columns`].
#[derive(Debug, Clone)]
pub(crate) struct RowLayout {
    dim: usize,
    bodies: usize,
    /// Indices in `q` of the rigid bodies' angles.
    rotors: Vec<usize>,
    /// The first orientation coordinate of each rigid body turning in space.
    spinners: Vec<usize>,
    /// Indices in `q` of the variable masses.
    variable_masses: Vec<usize>,
    /// The masses, when there are two or more bodies (for the centre-of-mass columns).
    masses: Option<Vec<Real>>,
    has_potential: bool,
}

impl RowLayout {
    /// The layout of `sys`'s rows (`has_potential`: with `U` and `E`).
    pub fn new(sys: &ParticleSystem, has_potential: bool) -> Self {
        let extras = |f: fn(&crate::particles::Extra) -> bool| -> Vec<usize> {
            sys.extras()
                .iter()
                .enumerate()
                .filter(|(_, e)| f(e))
                .map(|(i, _)| sys.extras_start() + i)
                .collect()
        };
        Self {
            dim: sys.dim(),
            bodies: sys.bodies().len(),
            rotors: extras(|e| e.body.is_some()),
            spinners: sys.spinners().iter().map(|s| s.first).collect(),
            variable_masses: extras(|e| e.mass_of.is_some()),
            masses: (sys.masses().len() > 1).then(|| sys.masses().to_vec()),
            has_potential,
        }
    }

    /// Clears `out` and puts the row of sample `s` into it.
    pub fn values(&self, s: &Sample<'_>, out: &mut Vec<Real>) {
        out.clear();
        out.push(s.t);
        let d = self.dim;
        for b in 0..self.bodies {
            out.extend_from_slice(&s.q[b * d..(b + 1) * d]);
            out.extend_from_slice(&s.v[b * d..(b + 1) * d]);
        }
        for &i in &self.rotors {
            out.extend([s.q[i], s.v[i]]);
        }
        for &f in &self.spinners {
            let q = [s.q[f], s.q[f + 1], s.q[f + 2], s.q[f + 3]];
            let n = spin::norm2(q).sqrt();
            let w = spin::omega_world(q, [s.v[f], s.v[f + 1], s.v[f + 2], s.v[f + 3]]);
            out.extend(q.iter().map(|x| x / n).chain(w));
        }
        out.extend(self.variable_masses.iter().map(|&i| s.q[i]));
        if let Some(masses) = &self.masses {
            centre_of_mass(d, masses, s, out);
        }
        if !self.rotors.is_empty() || !self.spinners.is_empty() {
            out.push(s.eval.kinetic_rotation);
        }
        out.push(s.eval.kinetic);
        if self.has_potential {
            let u = s.eval.potential_total.unwrap_or(Real::NAN);
            out.extend([u, s.eval.kinetic + u]);
        }
        out.extend_from_slice(s.work);
        out.extend_from_slice(&s.eval.power);
    }
}

/// `cm.x…, cm.vx…, cm.ax…, K_cm, K_internal`: mass-weighted means of the bodies' positions,
/// velocities and accelerations, and König's split of the kinetic energy.
fn centre_of_mass(d: usize, masses: &[Real], s: &Sample<'_>, out: &mut Vec<Real>) {
    let total: Real = masses.iter().sum();
    let mut v_cm = [0.0; 3];
    for (k, values) in [s.q, s.v, s.eval.a.as_slice()].into_iter().enumerate() {
        let mut mean = [0.0; 3];
        for (m, body) in masses.iter().zip(values.chunks_exact(d)) {
            for (o, x) in mean.iter_mut().zip(body) {
                *o += m * x;
            }
        }
        for x in &mut mean[..d] {
            *x /= total;
        }
        out.extend_from_slice(&mean[..d]);
        if k == 1 {
            v_cm = mean;
        }
    }
    let k_cm = 0.5 * total * v_cm[..d].iter().map(|x| x * x).sum::<Real>();
    out.extend([k_cm, s.eval.kinetic - k_cm]);
}

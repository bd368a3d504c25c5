//! Output files: the trajectory CSV, streamed during the run, and atomic writes (a temporary
//! file renamed into place, so a reader never sees half a file).
//!
//! The CSV is written to `trajectory.csv.partial` and renamed to `trajectory.csv` when the run
//! ends for any reason (including divergence), so everything computed is kept.

use std::fs::{self, File};
use std::io::{self, BufWriter, Write};
use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

use crate::Real;
use crate::csv::Column;
use crate::particles::{ParticleSystem, Sample, SampleKind, spin};
use crate::simulate::{Observer, ObserverError, StopReason};

use crate::csv::partial_path as temp_path;
pub use crate::csv::write_atomic;

/// How often a [`StreamFile`] hands its buffer to the operating system, at the least: a
/// process killed outright loses at most about this much of its output.
pub const FLUSH_INTERVAL: Duration = Duration::from_secs(1);

/// A file written as a stream: to `NAME.partial` beside it, flushed at least every
/// [`FLUSH_INTERVAL`], held to a size limit, and renamed into place by
/// [`StreamFile::finish`], so a reader never sees half a file under the final name.
pub struct StreamFile {
    out: BufWriter<File>,
    tmp: PathBuf,
    path: PathBuf,
    written: u64,
    limit: u64,
    full: bool,
    last_flush: Instant,
    appends: u32,
}

impl StreamFile {
    /// Starts `path.partial`; the file may hold at most `limit` bytes.
    pub fn create(path: &Path, limit: u64) -> io::Result<Self> {
        let tmp = temp_path(path);
        Ok(Self {
            out: BufWriter::with_capacity(1 << 16, File::create(&tmp)?),
            tmp,
            path: path.to_path_buf(),
            written: 0,
            limit,
            full: false,
            last_flush: Instant::now(),
            appends: 0,
        })
    }

    /// Appends `bytes`, unless they would take the file past its limit: then nothing is
    /// written, now or later, and the result is `false` ([`StreamFile::is_full`]).
    pub fn append(&mut self, bytes: &[u8]) -> io::Result<bool> {
        if self.full || self.written + bytes.len() as u64 > self.limit {
            self.full = true;
            return Ok(false);
        }
        self.out.write_all(bytes)?;
        self.written += bytes.len() as u64;
        self.appends += 1;
        if self.appends.is_multiple_of(64) && self.last_flush.elapsed() >= FLUSH_INTERVAL {
            self.out.flush()?;
            self.last_flush = Instant::now();
        }
        Ok(true)
    }

    /// Whether an append was refused because of the limit.
    pub fn is_full(&self) -> bool {
        self.full
    }

    /// Bytes written so far.
    pub fn len(&self) -> u64 {
        self.written
    }

    /// Whether nothing was written.
    pub fn is_empty(&self) -> bool {
        self.written == 0
    }

    /// The size limit.
    pub fn limit(&self) -> u64 {
        self.limit
    }

    /// The final path (the file is written beside it until [`StreamFile::finish`]).
    pub fn path(&self) -> &Path {
        &self.path
    }

    /// The temporary path being written.
    pub fn partial_path(&self) -> &Path {
        &self.tmp
    }

    /// Flushes, syncs and renames the file into place.
    pub fn finish(mut self) -> io::Result<()> {
        self.out.flush()?;
        self.out.get_ref().sync_all()?;
        fs::rename(&self.tmp, &self.path)
    }

    /// After a failed write: renames what reached the disk into place, without insisting on
    /// the rest of the buffer.
    pub fn keep_what_was_written(mut self) -> io::Result<()> {
        let _ = self.out.flush();
        fs::rename(&self.tmp, &self.path)
    }
}

/// The message of a run stopped by an output file reaching its limit: which file, the limit,
/// when (`at`, e.g. `t = 1.02 s`), and `how` to raise the limit or write less.
pub fn output_limit_message(file: &Path, limit: u64, at: &str, how: &str) -> String {
    format!(
        "{} reached the output limit of {} at {at}, so the run stopped there; {how}",
        file.file_name().map_or_else(
            || file.display().to_string(),
            |n| n.to_string_lossy().into_owned()
        ),
        super::limits::format_size(limit),
    )
}

/// How to raise a scenario run's output limit.
const SCENARIO_LIMIT_HINT: &str = "raise the limit with `[output] max_size = \"10 GB\"` (or `mechkit run --max-output 10GB`), or write fewer rows with `[output] every = 10` or `interval`";

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

pub use crate::csv::push_number;

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

/// Streams samples to a CSV file (the kept ones, see [`Keep`], and the last).
pub(crate) struct CsvWriter {
    out: StreamFile,
    keep: Keep,
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
    last_t: Option<Real>,
    line: String,
    rows: u64,
    /// Why the run must stop: the file reached its limit, or could not be written.
    halt: Option<(StopReason, String)>,
}

impl CsvWriter {
    pub fn create(
        path: &Path,
        sys: &ParticleSystem,
        has_potential: bool,
        keep: Keep,
        limit: u64,
    ) -> std::io::Result<Self> {
        let mut out = StreamFile::create(path, limit)?;
        let header = format!("{}\n", csv_header(sys, has_potential).join(","));
        if !out.append(header.as_bytes())? {
            return Err(io::Error::other(format!(
                "the output limit of {limit} bytes is too small for even the header of {}",
                path.display()
            )));
        }
        Ok(Self {
            out,
            keep,
            dim: sys.dim(),
            bodies: sys.bodies().len(),
            spinners: sys.spinners().iter().map(|s| s.first).collect(),
            rotors: sys
                .extras()
                .iter()
                .enumerate()
                .filter(|(_, e)| e.body.is_some())
                .map(|(i, _)| sys.extras_start() + i)
                .collect(),
            variable_masses: sys
                .extras()
                .iter()
                .enumerate()
                .filter(|(_, e)| e.mass_of.is_some())
                .map(|(i, _)| sys.extras_start() + i)
                .collect(),
            masses: (sys.masses().len() > 1).then(|| sys.masses().to_vec()),
            has_potential,
            last_t: None,
            line: String::with_capacity(256),
            rows: 0,
            halt: None,
        })
    }

    fn write(&mut self, s: &Sample<'_>) {
        self.line.clear();
        push_number(&mut self.line, s.t);
        for b in 0..self.bodies {
            for &x in s.q[b * self.dim..(b + 1) * self.dim]
                .iter()
                .chain(&s.v[b * self.dim..(b + 1) * self.dim])
            {
                self.line.push(',');
                push_number(&mut self.line, x);
            }
        }
        for &i in &self.rotors {
            for x in [s.q[i], s.v[i]] {
                self.line.push(',');
                push_number(&mut self.line, x);
            }
        }
        for &f in &self.spinners {
            let q = [s.q[f], s.q[f + 1], s.q[f + 2], s.q[f + 3]];
            let n = spin::norm2(q).sqrt();
            let w = spin::omega_world(q, [s.v[f], s.v[f + 1], s.v[f + 2], s.v[f + 3]]);
            for x in q.iter().map(|x| x / n).chain(w) {
                self.line.push(',');
                push_number(&mut self.line, x);
            }
        }
        for &i in &self.variable_masses {
            self.line.push(',');
            push_number(&mut self.line, s.q[i]);
        }
        if let Some(masses) = self.masses.take() {
            self.push_centre_of_mass(&masses, s);
            self.masses = Some(masses);
        }
        if !self.rotors.is_empty() || !self.spinners.is_empty() {
            self.line.push(',');
            push_number(&mut self.line, s.eval.kinetic_rotation);
        }
        self.line.push(',');
        push_number(&mut self.line, s.eval.kinetic);
        if self.has_potential {
            let u = s.eval.potential_total.unwrap_or(Real::NAN);
            self.line.push(',');
            push_number(&mut self.line, u);
            self.line.push(',');
            push_number(&mut self.line, s.eval.kinetic + u);
        }
        for &w in s.work.iter().chain(&s.eval.power) {
            self.line.push(',');
            push_number(&mut self.line, w);
        }
        self.line.push('\n');
        if self.halt.is_some() {
            return;
        }
        match self.out.append(self.line.as_bytes()) {
            Ok(true) => {}
            Ok(false) => {
                self.halt = Some((
                    StopReason::OutputLimit,
                    output_limit_message(
                        self.out.path(),
                        self.out.limit(),
                        &format!("t = {} s", s.t),
                        SCENARIO_LIMIT_HINT,
                    ),
                ));
                return;
            }
            Err(e) => {
                // a full disk, a quota: stop cleanly, keep the rows already on disk
                self.halt = Some((
                    StopReason::OutputError,
                    format!(
                        "cannot write {} at t = {} s ({e}), so the run stopped there; the rows written before are kept; free space or choose another --out",
                        self.out.partial_path().display(),
                        s.t
                    ),
                ));
                return;
            }
        }
        self.last_t = Some(s.t);
        self.rows += 1;
    }

    /// `cm.x…, cm.vx…, cm.ax…, K_cm, K_internal`: mass-weighted means of the bodies'
    /// positions, velocities and accelerations, and König's split of the kinetic energy.
    fn push_centre_of_mass(&mut self, masses: &[Real], s: &Sample<'_>) {
        let d = self.dim;
        let total: Real = masses.iter().sum();
        let mut v_cm = [0.0; 3];
        for values in [s.q, s.v, s.eval.a.as_slice()] {
            let mut mean = [0.0; 3];
            for (m, body) in masses.iter().zip(values.chunks_exact(d)) {
                for (o, x) in mean.iter_mut().zip(body) {
                    *o += m * x;
                }
            }
            for x in &mut mean[..d] {
                *x /= total;
                self.line.push(',');
                push_number(&mut self.line, *x);
            }
            if std::ptr::eq(values, s.v) {
                v_cm = mean;
            }
        }
        let k_cm = 0.5 * total * v_cm[..d].iter().map(|x| x * x).sum::<Real>();
        self.line.push(',');
        push_number(&mut self.line, k_cm);
        self.line.push(',');
        push_number(&mut self.line, s.eval.kinetic - k_cm);
    }

    /// Flushes and renames the file into place; returns the number of rows written.
    /// After a failed write, what reached the disk is renamed into place.
    pub fn close(self) -> std::io::Result<u64> {
        if matches!(self.halt, Some((StopReason::OutputError, _))) {
            self.out.keep_what_was_written()?;
        } else {
            self.out.finish()?;
        }
        Ok(self.rows)
    }
}

impl Observer for CsvWriter {
    fn observe(&mut self, s: &Sample<'_>) -> Result<(), ObserverError> {
        if self.keep.keeps(s) {
            self.write(s);
        }
        Ok(())
    }

    fn next_step(&self, step: u64) -> Option<u64> {
        self.keep.next_step(step)
    }

    fn halt(&self) -> Option<(StopReason, String)> {
        self.halt.clone()
    }

    fn finish(&mut self, s: &Sample<'_>) -> Result<(), ObserverError> {
        if self.last_t != Some(s.t) {
            self.write(s);
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::{FLUSH_INTERVAL, StreamFile, push_number};

    #[test]
    fn a_stream_reaches_the_disk_within_the_flush_interval_and_keeps_to_its_limit() {
        let dir = tempfile::tempdir().expect("a temporary directory");
        let path = dir.path().join("rows.csv");
        let mut f = StreamFile::create(&path, 1000).expect("created");
        let partial = f.partial_path().to_path_buf();
        assert!(f.append(b"first\n").expect("written"));
        let on_disk = || std::fs::metadata(&partial).expect("the partial file").len();
        assert_eq!(on_disk(), 0, "a fresh row waits in the buffer");
        std::thread::sleep(FLUSH_INTERVAL + std::time::Duration::from_millis(20));
        for _ in 0..63 {
            assert!(f.append(b"row\n").expect("written"));
        }
        assert_eq!(on_disk(), 6 + 63 * 4, "flushed once the interval passed");
        assert!(!path.exists(), "the final name appears only at the end");
        // 258 bytes so far; 185 rows of 4 bytes would pass 1000
        let accepted = (0..200)
            .take_while(|_| f.append(b"row\n").expect("ok"))
            .count();
        assert_eq!(accepted, (1000 - 258) / 4);
        assert!(
            f.is_full() && !f.append(b"\n").expect("ok"),
            "nothing more once full"
        );
        assert_eq!(f.len(), 258 + 185 * 4);
        f.finish().expect("renamed");
        assert_eq!(std::fs::metadata(&path).expect("final").len(), 998);
        assert!(!partial.exists());
    }

    #[test]
    fn numbers_round_trip_compactly() {
        for (x, text) in [
            (0.0, "0"),
            (2.4, "2.4"),
            (1.5e-9, "1.5e-9"),
            (-4.8e-21, "-4.8e-21"),
            (1e20, "1e20"),
            (f64::NAN, "NaN"),
        ] {
            let mut s = String::new();
            push_number(&mut s, x);
            assert_eq!(s, text);
            if x.is_finite() {
                assert_eq!(s.parse::<f64>().unwrap(), x);
            }
        }
    }
}

//! Output files: the trajectory CSV, streamed during the run, and atomic writes (a temporary
//! file renamed into place, so a reader never sees half a file).
//!
//! The CSV is written to `trajectory.csv.partial` and renamed to `trajectory.csv` when the run
//! ends for any reason (including divergence), so everything computed is kept.

use std::fs::{self, File};
use std::io::{BufWriter, Write};
use std::path::{Path, PathBuf};

use crate::Real;
use crate::particles::{ParticleSystem, Sample, SampleKind};
use crate::simulate::{Observer, ObserverError};

/// Writes `bytes` to `path` atomically: to a temporary file beside it, then renamed.
pub fn write_atomic(path: &Path, bytes: &[u8]) -> std::io::Result<()> {
    let tmp = temp_path(path);
    {
        let mut f = File::create(&tmp)?;
        f.write_all(bytes)?;
        f.sync_all()?;
    }
    fs::rename(&tmp, path)
}

fn temp_path(path: &Path) -> PathBuf {
    let mut name = path
        .file_name()
        .map(std::ffi::OsStr::to_os_string)
        .unwrap_or_default();
    name.push(".partial");
    path.with_file_name(name)
}

/// The CSV header for a system: `t`, positions, velocities, with two or more bodies the
/// centre of mass (`cm.x`, `cm.vx`, `cm.ax`) and the split `K = K_cm + K_internal`, then `K`,
/// `U`, `E`, the work of each force and its power `F·v`.
pub fn csv_header(sys: &ParticleSystem, has_potential: bool) -> Vec<String> {
    let axes = &["x", "y", "z"][..sys.dim()];
    let [position, velocity, _] = sys.coordinates().component_names(sys.dim());
    let mut cols = vec!["t".to_string()];
    for b in sys.bodies() {
        cols.extend(position.iter().map(|a| format!("{}.{a}", b.name)));
        cols.extend(velocity.iter().map(|a| format!("{}.{a}", b.name)));
    }
    if sys.bodies().len() > 1 {
        for prefix in ["", "v", "a"] {
            cols.extend(axes.iter().map(|a| format!("cm.{prefix}{a}")));
        }
        cols.push("K_cm".into());
        cols.push("K_internal".into());
    }
    cols.push("K".into());
    if has_potential {
        cols.push("U".into());
        cols.push("E".into());
    }
    cols.extend(sys.forces().iter().map(|f| format!("work.{}", f.name())));
    cols.extend(sys.forces().iter().map(|f| format!("power.{}", f.name())));
    cols
}

/// Appends `x` with the fewest digits that read back as the same number, in exponent form
/// when that is shorter (`1.5e-9`, not `0.0000000015`).
pub fn push_number(out: &mut String, x: Real) {
    use std::fmt::Write as _;
    let a = x.abs();
    if a == 0.0 || (1e-4..1e16).contains(&a) || !x.is_finite() {
        let _ = write!(out, "{x}");
    } else {
        let _ = write!(out, "{x:e}");
    }
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

/// Streams samples to a CSV file (the kept ones, see [`Keep`], and the last).
pub(crate) struct CsvWriter {
    out: BufWriter<File>,
    tmp: PathBuf,
    path: PathBuf,
    keep: Keep,
    dim: usize,
    /// The masses, when there are two or more bodies (for the centre-of-mass columns).
    masses: Option<Vec<Real>>,
    has_potential: bool,
    last_t: Option<Real>,
    line: String,
    rows: u64,
}

impl CsvWriter {
    pub fn create(
        path: &Path,
        sys: &ParticleSystem,
        has_potential: bool,
        keep: Keep,
    ) -> std::io::Result<Self> {
        let tmp = temp_path(path);
        let mut out = BufWriter::with_capacity(1 << 16, File::create(&tmp)?);
        writeln!(out, "{}", csv_header(sys, has_potential).join(","))?;
        Ok(Self {
            out,
            tmp,
            path: path.to_path_buf(),
            keep,
            dim: sys.dim(),
            masses: (sys.masses().len() > 1).then(|| sys.masses().to_vec()),
            has_potential,
            last_t: None,
            line: String::with_capacity(256),
            rows: 0,
        })
    }

    fn write(&mut self, s: &Sample<'_>) -> Result<(), ObserverError> {
        self.line.clear();
        push_number(&mut self.line, s.t);
        let n = s.q.len() / self.dim;
        for b in 0..n {
            for &x in s.q[b * self.dim..(b + 1) * self.dim]
                .iter()
                .chain(&s.v[b * self.dim..(b + 1) * self.dim])
            {
                self.line.push(',');
                push_number(&mut self.line, x);
            }
        }
        if let Some(masses) = self.masses.take() {
            self.push_centre_of_mass(&masses, s);
            self.masses = Some(masses);
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
        self.out
            .write_all(self.line.as_bytes())
            .map_err(|e| ObserverError(format!("writing {}: {e}", self.tmp.display())))?;
        self.last_t = Some(s.t);
        self.rows += 1;
        Ok(())
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
    pub fn close(mut self) -> std::io::Result<u64> {
        self.out.flush()?;
        self.out.get_ref().sync_all()?;
        fs::rename(&self.tmp, &self.path)?;
        Ok(self.rows)
    }
}

impl Observer for CsvWriter {
    fn observe(&mut self, s: &Sample<'_>) -> Result<(), ObserverError> {
        if self.keep.keeps(s) {
            self.write(s)?;
        }
        Ok(())
    }

    fn next_step(&self, step: u64) -> Option<u64> {
        self.keep.next_step(step)
    }

    fn finish(&mut self, s: &Sample<'_>) -> Result<(), ObserverError> {
        if self.last_t != Some(s.t) {
            self.write(s)?;
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::push_number;

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

//! A sweep's table as bytes, to carry a shard's table from the process that ran it to the
//! one that merges it ([`super::merge_tables`]): every number as its 8 bytes (so NaN and the
//! last bit survive, which text through JSON would not promise), every row with its recorded
//! plot as the overlay draws it (the axes and the curves). The bytes open with the crate's
//! version: a part made by another version of mechkit is refused, not misread.
//!
//! ```text
//! "mechkit sweep part " version "\n"  manifest runs shard params units observables rows
//! string = u64 length, UTF-8     number = f64 little-endian     count = u64 little-endian
//! ```

use super::{Shard, SweepError, SweepRow, SweepTable};
use crate::Real;
use crate::figure::{PlotData, Series};

const MAGIC: &str = concat!("mechkit sweep part ", env!("CARGO_PKG_VERSION"), "\n");

impl SweepTable {
    /// The table as bytes ([`SweepTable::from_bytes`] reads them back): for a process that
    /// runs a shard to hand its table to the one that merges the shards.
    pub fn to_bytes(&self) -> Vec<u8> {
        let mut w = Vec::new();
        w.extend_from_slice(MAGIC.as_bytes());
        string(&mut w, &self.manifest);
        count(&mut w, self.runs);
        match self.shard {
            Some(s) => {
                w.push(1);
                count(&mut w, s.k);
                count(&mut w, s.n);
            }
            None => w.push(0),
        }
        for list in [&self.params, &self.units, &self.observables] {
            count(&mut w, list.len());
            for s in list {
                string(&mut w, s);
            }
        }
        count(&mut w, self.rows.len());
        for r in &self.rows {
            row(&mut w, r);
        }
        w
    }

    /// Reads the bytes of [`SweepTable::to_bytes`]. Rows keep their recorded plot's axes and
    /// curves (what [`SweepTable::overlay`] draws), not its markers or bands. An error when
    /// the bytes are not a table's, or were written by another version of mechkit.
    pub fn from_bytes(bytes: &[u8]) -> Result<SweepTable, SweepError> {
        let mut r = Reader { bytes, at: 0 };
        if !bytes.starts_with(MAGIC.as_bytes()) {
            let version = bytes
                .strip_prefix(b"mechkit sweep part ".as_slice())
                .and_then(|b| b.split(|&c| c == b'\n').next())
                .map(String::from_utf8_lossy);
            return Err(SweepError::BadPart(match version {
                Some(v) => format!(
                    "the part was made by mechkit {v}, and this is mechkit {}\n  = hint: \
                     install the same mechkit where the shards run and where they are merged",
                    env!("CARGO_PKG_VERSION")
                ),
                None => "these bytes are not a sweep's part (SweepTable::to_bytes)".into(),
            }));
        }
        r.at = MAGIC.len();
        let manifest = r.string()?;
        let runs = r.count()?;
        let shard = match r.byte()? {
            0 => None,
            _ => Some(Shard {
                k: r.count()?,
                n: r.count()?,
            }),
        };
        let params = r.strings()?;
        let units = r.strings()?;
        let observables = r.strings()?;
        let n = r.count()?;
        let rows = (0..n).map(|_| r.row()).collect::<Result<Vec<_>, _>>()?;
        if r.at != bytes.len() {
            return Err(r.bad("bytes after the last row"));
        }
        Ok(SweepTable {
            manifest,
            runs,
            shard,
            params,
            units,
            observables,
            rows,
        })
    }
}

fn count(w: &mut Vec<u8>, n: usize) {
    w.extend_from_slice(&(n as u64).to_le_bytes());
}

fn number(w: &mut Vec<u8>, x: Real) {
    w.extend_from_slice(&x.to_le_bytes());
}

fn numbers(w: &mut Vec<u8>, xs: &[Real]) {
    count(w, xs.len());
    for &x in xs {
        number(w, x);
    }
}

fn string(w: &mut Vec<u8>, s: &str) {
    count(w, s.len());
    w.extend_from_slice(s.as_bytes());
}

fn option<T>(w: &mut Vec<u8>, value: Option<T>, write: impl FnOnce(&mut Vec<u8>, T)) {
    match value {
        Some(v) => {
            w.push(1);
            write(w, v);
        }
        None => w.push(0),
    }
}

fn row(w: &mut Vec<u8>, r: &SweepRow) {
    count(w, r.index);
    numbers(w, &r.values);
    string(w, &r.stop_reason);
    number(w, r.t_end);
    w.extend_from_slice(&r.steps.to_le_bytes());
    numbers(w, &r.observables);
    number(w, r.kinetic_end);
    option(w, r.potential_end, number);
    number(w, r.energy_end);
    number(w, r.work_energy_residual);
    option(w, r.diagnosis.as_deref(), string);
    option(w, r.plot.as_ref(), |w, p| {
        for s in [&p.spec, &p.file_stem, &p.x_label, &p.y_label] {
            string(w, s);
        }
        w.push(u8::from(p.equal_aspect));
        count(w, p.series.len());
        for s in &p.series {
            string(w, &s.label);
            count(w, s.points.len());
            for &(x, y) in &s.points {
                number(w, x);
                number(w, y);
            }
        }
    });
}

/// Reads the bytes of [`SweepTable::to_bytes`] from the front.
struct Reader<'a> {
    bytes: &'a [u8],
    at: usize,
}

impl Reader<'_> {
    fn bad(&self, what: &str) -> SweepError {
        SweepError::BadPart(format!(
            "the sweep's part is damaged: {what} at byte {}",
            self.at
        ))
    }

    fn take(&mut self, n: usize) -> Result<&[u8], SweepError> {
        let end = self.at.checked_add(n).filter(|&e| e <= self.bytes.len());
        let end = end.ok_or_else(|| self.bad("it ends early"))?;
        let out = &self.bytes[self.at..end];
        self.at = end;
        Ok(out)
    }

    fn eight(&mut self) -> Result<[u8; 8], SweepError> {
        let b = self.take(8)?;
        Ok(b.try_into().expect("8 bytes taken"))
    }

    fn byte(&mut self) -> Result<u8, SweepError> {
        Ok(self.take(1)?[0])
    }

    fn count(&mut self) -> Result<usize, SweepError> {
        let n = u64::from_le_bytes(self.eight()?);
        usize::try_from(n).map_err(|_| self.bad("a count too large"))
    }

    /// A count of items of at least `size` bytes each, no more than the bytes left hold.
    fn items(&mut self, size: usize) -> Result<usize, SweepError> {
        let n = self.count()?;
        if n.saturating_mul(size) > self.bytes.len() - self.at {
            return Err(self.bad("a count larger than the bytes left"));
        }
        Ok(n)
    }

    fn number(&mut self) -> Result<Real, SweepError> {
        Ok(Real::from_le_bytes(self.eight()?))
    }

    fn numbers(&mut self) -> Result<Vec<Real>, SweepError> {
        let n = self.items(8)?;
        (0..n).map(|_| self.number()).collect()
    }

    fn string(&mut self) -> Result<String, SweepError> {
        let n = self.items(1)?;
        let b = self.take(n)?.to_vec();
        String::from_utf8(b).map_err(|_| self.bad("text that is not UTF-8"))
    }

    fn strings(&mut self) -> Result<Vec<String>, SweepError> {
        let n = self.items(8)?;
        (0..n).map(|_| self.string()).collect()
    }

    fn present(&mut self) -> Result<bool, SweepError> {
        match self.byte()? {
            0 => Ok(false),
            1 => Ok(true),
            _ => Err(self.bad("a flag that is neither 0 nor 1")),
        }
    }

    fn row(&mut self) -> Result<SweepRow, SweepError> {
        let index = self.count()?;
        let values = self.numbers()?;
        let stop_reason = self.string()?;
        let t_end = self.number()?;
        let steps = u64::from_le_bytes(self.eight()?);
        let observables = self.numbers()?;
        let kinetic_end = self.number()?;
        let potential_end = if self.present()? {
            Some(self.number()?)
        } else {
            None
        };
        let energy_end = self.number()?;
        let work_energy_residual = self.number()?;
        let diagnosis = if self.present()? {
            Some(self.string()?)
        } else {
            None
        };
        let plot = if self.present()? {
            Some(self.plot()?)
        } else {
            None
        };
        Ok(SweepRow {
            index,
            values,
            stop_reason,
            t_end,
            steps,
            observables,
            kinetic_end,
            potential_end,
            energy_end,
            work_energy_residual,
            plot,
            diagnosis,
        })
    }

    fn plot(&mut self) -> Result<PlotData, SweepError> {
        let (spec, stem, x, y) = (
            self.string()?,
            self.string()?,
            self.string()?,
            self.string()?,
        );
        let mut plot = PlotData::new(spec, stem, x, y);
        plot.equal_aspect = self.present()?;
        let n = self.items(16)?;
        for _ in 0..n {
            let label = self.string()?;
            let m = self.items(16)?;
            let points = (0..m)
                .map(|_| Ok((self.number()?, self.number()?)))
                .collect::<Result<Vec<_>, SweepError>>()?;
            plot.series.push(Series::line(label, points));
        }
        Ok(plot)
    }
}

#[cfg(test)]
mod tests {
    use super::{SweepError, SweepTable};

    #[test]
    fn damaged_or_foreign_bytes_are_refused() {
        let err = SweepTable::from_bytes(b"mechkit sweep part 0.0.1\nxyz").unwrap_err();
        assert!(matches!(&err, SweepError::BadPart(m) if m.contains("made by mechkit 0.0.1")));
        let err = SweepTable::from_bytes(b"a,b\n1,2\n").unwrap_err();
        assert!(err.to_string().contains("not a sweep's part"), "{err}");
        let mut bytes = super::MAGIC.as_bytes().to_vec();
        bytes.extend_from_slice(&u64::MAX.to_le_bytes());
        let err = SweepTable::from_bytes(&bytes).unwrap_err();
        assert!(err.to_string().contains("damaged"), "{err}");
    }
}

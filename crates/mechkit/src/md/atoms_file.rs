//! Initial positions or velocities of a few particles, read from a small text file.
//!
//! Two formats:
//! - CSV: one particle per line, 1 to 3 numbers separated by commas (the count is the
//!   dimension, the same on every line); blank lines and lines starting with `#` are
//!   skipped, and a first line that is not numeric (`x,y,z`) is a header;
//! - XYZ: the particle count, a comment line, then `species x y z` per particle (further
//!   columns ignored); always 3-D.
//!
//! Errors give the 1-based line number.

use crate::Real;

use super::MdError;

/// Vectors read from a file: one per particle, and their dimension.
#[derive(Debug, Clone, PartialEq)]
pub struct AtomsFile {
    /// 1, 2 or 3 (unused components are zero).
    pub dim: usize,
    /// One vector per particle.
    pub vectors: Vec<[Real; 3]>,
}

fn error(line: usize, message: impl Into<String>) -> MdError {
    MdError::Parse {
        line,
        message: message.into(),
    }
}

fn number(field: &str, line: usize) -> Result<Real, MdError> {
    let field = field.trim();
    match field.parse::<Real>() {
        Ok(v) if v.is_finite() => Ok(v),
        _ => Err(error(
            line,
            format!(
                "`{field}` is not a finite number; a coordinate is a number such as 1.5 or -2e-3"
            ),
        )),
    }
}

impl AtomsFile {
    /// Parses CSV text (see the module docs).
    ///
    /// # Example
    /// ```
    /// use mechkit::md::AtomsFile;
    /// let f = AtomsFile::parse_csv("# two atoms\nx,y\n0, 0\n1.5, 0\n").unwrap();
    /// assert_eq!((f.dim, f.vectors.len()), (2, 2));
    /// assert_eq!(f.vectors[1], [1.5, 0.0, 0.0]);
    /// assert!(AtomsFile::parse_csv("0,0\n1,x\n").unwrap_err().to_string().contains("line 2"));
    /// ```
    pub fn parse_csv(text: &str) -> Result<Self, MdError> {
        let mut dim = 0;
        let mut vectors = Vec::new();
        let mut seen_data = false;
        for (k, raw) in text.lines().enumerate() {
            let line = k + 1;
            let row = raw.trim();
            if row.is_empty() || row.starts_with('#') {
                continue;
            }
            let fields: Vec<&str> = row.split(',').collect();
            let numeric = fields.iter().all(|f| f.trim().parse::<Real>().is_ok());
            if !seen_data && !numeric {
                seen_data = true; // a header
                continue;
            }
            seen_data = true;
            if !(1..=3).contains(&fields.len()) {
                return Err(error(
                    line,
                    format!(
                        "{} columns, but a line holds 1 to 3 coordinates, comma-separated: x[,y[,z]]",
                        fields.len()
                    ),
                ));
            }
            if dim == 0 {
                dim = fields.len();
            } else if fields.len() != dim {
                return Err(error(
                    line,
                    format!(
                        "{} columns, but the first row has {dim}; every particle needs the same number of coordinates",
                        fields.len()
                    ),
                ));
            }
            let mut v = [0.0; 3];
            for (c, f) in v.iter_mut().zip(&fields) {
                *c = number(f, line)?;
            }
            vectors.push(v);
        }
        if vectors.is_empty() {
            return Err(error(
                text.lines().count().max(1),
                "no particles in the file; write one particle per line as x[,y[,z]]",
            ));
        }
        Ok(Self { dim, vectors })
    }

    /// The 1-based line of `text` (a file named `name`, read by [`AtomsFile::parse`]) that
    /// holds particle `index` (0-based), for a message that points at it.
    ///
    /// ```
    /// use mechkit::md::AtomsFile;
    /// assert_eq!(AtomsFile::line_of("p.csv", "# pair\nx,y\n0,0\n\n1,0\n", 1), Some(5));
    /// assert_eq!(AtomsFile::line_of("p.xyz", "2\npair\nAr 0 0 0\nAr 1 0 0\n", 1), Some(4));
    /// ```
    pub fn line_of(name: &str, text: &str, index: usize) -> Option<usize> {
        if name.to_ascii_lowercase().ends_with(".xyz") {
            return Some(index + 3);
        }
        let mut seen_data = false;
        let mut k = 0;
        for (i, raw) in text.lines().enumerate() {
            let row = raw.trim();
            if row.is_empty() || row.starts_with('#') {
                continue;
            }
            let numeric = row.split(',').all(|f| f.trim().parse::<Real>().is_ok());
            let header = !seen_data && !numeric;
            seen_data = true;
            if header {
                continue;
            }
            if k == index {
                return Some(i + 1);
            }
            k += 1;
        }
        None
    }

    /// Parses XYZ text (see the module docs).
    ///
    /// # Example
    /// ```
    /// use mechkit::md::AtomsFile;
    /// let f = AtomsFile::parse_xyz("2\npair\nAr 0 0 0\nAr 1.5 0 0\n").unwrap();
    /// assert_eq!((f.dim, f.vectors[1][0]), (3, 1.5));
    /// ```
    pub fn parse_xyz(text: &str) -> Result<Self, MdError> {
        // (fuzz finding `data_file/xyz-count-27958181655`: the count alone used to size the
        // allocation, and a count of 2.8·10^10 aborted the process)
        let mut lines = text.lines();
        let count = lines.next().unwrap_or("").trim();
        let n: usize = count
            .parse()
            .map_err(|_| {
                error(
                    1,
                    format!(
                        "`{count}` is not a particle count; an XYZ file starts with the number of particles, then a comment line, then `species x y z` per particle"
                    ),
                )
            })?;
        if n == 0 {
            return Err(error(
                1,
                "the particle count is 0; an XYZ file needs at least one particle",
            ));
        }
        if n > super::MAX_ATOMS {
            return Err(error(
                1,
                format!(
                    "the particle count is {n}, more than mechkit md runs ({}); check the count on line 1",
                    super::MAX_ATOMS
                ),
            ));
        }
        lines.next().ok_or_else(|| {
            error(
                2,
                "the comment line is missing; line 2 of an XYZ file is a comment (it may be empty)",
            )
        })?;
        // the lines the text holds bound what the count may claim
        let mut vectors = Vec::with_capacity(n.min(text.len() / 8 + 1));
        for k in 0..n {
            let line = k + 3;
            let row = lines
                .next()
                .ok_or_else(|| {
                    error(
                        line,
                        format!(
                            "the file ends after {k} of {n} particles; fix the count on line 1 or add the missing lines"
                        ),
                    )
                })?;
            let fields: Vec<&str> = row.split_whitespace().collect();
            if fields.len() < 4 {
                return Err(error(
                    line,
                    format!(
                        "{} fields, but a particle line is `species x y z`, e.g. `Ar 0.0 1.5 0.0`",
                        fields.len()
                    ),
                ));
            }
            vectors.push([
                number(fields[1], line)?,
                number(fields[2], line)?,
                number(fields[3], line)?,
            ]);
        }
        Ok(Self { dim: 3, vectors })
    }

    /// The edge lengths of an open box around the particles: their extent along each of the
    /// `dim` axes plus `margin` on both sides (0 on unused axes).
    ///
    /// ```
    /// use mechkit::md::AtomsFile;
    /// let f = AtomsFile::parse_csv("0, 1\n1.5, -1\n").unwrap();
    /// assert_eq!(f.extent_with_margin(2.5), [6.5, 7.0, 0.0]);
    /// ```
    pub fn extent_with_margin(&self, margin: Real) -> [Real; 3] {
        std::array::from_fn(|a| {
            if a >= self.dim {
                return 0.0;
            }
            let (lo, hi) = self
                .vectors
                .iter()
                .fold((Real::MAX, Real::MIN), |(lo, hi), p| {
                    (lo.min(p[a]), hi.max(p[a]))
                });
            hi - lo + 2.0 * margin
        })
    }

    /// Parses `text` as XYZ if `name` ends in `.xyz`, as CSV otherwise.
    pub fn parse(name: &str, text: &str) -> Result<Self, MdError> {
        if name.to_ascii_lowercase().ends_with(".xyz") {
            Self::parse_xyz(text)
        } else {
            Self::parse_csv(text)
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Fuzz finding `data_file/xyz-count-27958181655`: an XYZ count line of 2.8·10^10 sized the
    /// allocation before a particle was read, and the process aborted. The count is bounded
    /// now, and a count the text cannot hold ends where the lines end.
    #[test]
    fn fuzz_xyz_count_does_not_size_the_allocation() {
        let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("../../fuzz/regressions/data_file/xyz-count-27958181655");
        let text =
            String::from_utf8_lossy(&std::fs::read(path).expect("the saved input")).into_owned();
        let e = AtomsFile::parse_xyz(&text).unwrap_err().to_string();
        assert!(e.contains("more than mechkit md runs"), "{e}");
        let e = AtomsFile::parse_xyz("9000000\nc\nAr 0 0 0\n")
            .unwrap_err()
            .to_string();
        assert!(e.contains("ends after 1 of 9000000"), "{e}");
    }

    #[test]
    fn bad_files_name_the_line() {
        let line = |r: Result<AtomsFile, MdError>| match r {
            Err(MdError::Parse { line, .. }) => line,
            other => panic!("{other:?}"),
        };
        assert_eq!(line(AtomsFile::parse_csv("0,0\n\n1,2,3\n")), 3);
        assert_eq!(line(AtomsFile::parse_csv("1\n2\ninf\n")), 3);
        assert_eq!(line(AtomsFile::parse_csv("1,2,3,4\n")), 1);
        assert_eq!(line(AtomsFile::parse_csv("# nothing\n")), 1);
        assert_eq!(line(AtomsFile::parse_xyz("two\n")), 1);
        assert_eq!(line(AtomsFile::parse_xyz("3\nc\nAr 0 0 0\nAr 1 1 1\n")), 5);
        assert_eq!(line(AtomsFile::parse_xyz("1\nc\nAr 0 zero 0\n")), 3);
        let f = AtomsFile::parse("a.XYZ", "1\n\nAr 1 2 3 9 9 9\n").unwrap();
        assert_eq!(f.vectors, vec![[1.0, 2.0, 3.0]]);
        let f = AtomsFile::parse("a.csv", "x\n0.5\n1.5\n").unwrap();
        assert_eq!((f.dim, f.vectors.len()), (1, 2));
    }
}

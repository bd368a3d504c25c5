//! `mechkit.md`'s keyword arguments as plain data: the options of `mechkit md` under the
//! same names (`--rest-length` is `rest_length`), their defaults the command's; and the
//! positions or velocities, a file as the command reads it or an `(N, d)` array.

use std::path::PathBuf;

use mechkit::md::{AtomsFile, MdError};
use numpy::{PyReadonlyArray2, PyUntypedArrayMethods};
use pyo3::exceptions::PyTypeError;
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyString};

use super::arguments::{count, flag, number, text, type_name, whole};
use crate::errors::MechkitError;

/// The keyword arguments `mechkit.md` takes.
pub const NAMES: [&str; 23] = [
    "lattice",
    "cells",
    "density",
    "temperature",
    "positions",
    "velocities",
    "box",
    "boundary",
    "potential",
    "epsilon",
    "sigma",
    "k",
    "rest_length",
    "mass",
    "seed",
    "steps",
    "dt",
    "cutoff",
    "shift",
    "skin",
    "threads",
    "thermo_every",
    "xyz_every",
];

/// Positions or velocities and where they came from.
pub struct Atoms {
    /// The vectors and their dimension.
    pub atoms: AtomsFile,
    /// The file's path as given, or None for an array.
    pub path: Option<PathBuf>,
}

/// What `mechkit md` is given, as its flags give it; `None` where a flag has no default.
pub struct MdOptions {
    pub lattice: String,
    pub cells: usize,
    pub density: f64,
    pub temperature: Option<f64>,
    pub positions: Option<Atoms>,
    pub velocities: Option<Atoms>,
    pub box_lengths: Option<Vec<f64>>,
    pub boundary: Option<String>,
    pub potential: String,
    pub epsilon: f64,
    pub sigma: f64,
    pub k: f64,
    pub rest_length: f64,
    pub mass: f64,
    pub seed: u64,
    pub steps: usize,
    pub dt: f64,
    pub cutoff: f64,
    pub shift: bool,
    pub skin: f64,
    pub threads: usize,
    pub thermo_every: usize,
    pub xyz_every: Option<usize>,
}

impl Default for MdOptions {
    /// `mechkit md`'s defaults: the Lennard-Jones melt (fcc, 20 cells, ρ = 0.8442, T = 1.44,
    /// dt = 0.005, 100 steps).
    fn default() -> Self {
        Self {
            lattice: "fcc".into(),
            cells: 20,
            density: 0.8442,
            temperature: None,
            positions: None,
            velocities: None,
            box_lengths: None,
            boundary: None,
            potential: "lj".into(),
            epsilon: 1.0,
            sigma: 1.0,
            k: 1.0,
            rest_length: 1.0,
            mass: 1.0,
            seed: 87287,
            steps: 100,
            dt: 0.005,
            cutoff: 2.5,
            shift: false,
            skin: 0.3,
            threads: 1,
            thermo_every: 50,
            xyz_every: None,
        }
    }
}

impl MdOptions {
    /// The options from `mechkit.md`'s keyword arguments (None stands for a flag left out);
    /// the rules between flags are the command's: `velocities` and `temperature` exclude
    /// each other, `velocities`, `box` and `boundary` go with `positions`.
    pub fn from_kwargs(kwargs: Option<&Bound<'_, PyDict>>) -> PyResult<Self> {
        let mut o = Self::default();
        let Some(kwargs) = kwargs else {
            return Ok(o);
        };
        for (key, value) in kwargs.iter() {
            let key: String = key.extract()?;
            if !value.is_none() {
                o.set(&key, &value)?;
            } else if !NAMES.contains(&key.as_str()) {
                return Err(unknown(&key));
            }
        }
        for key in ["velocities", "box", "boundary"] {
            let given = match key {
                "velocities" => o.velocities.is_some(),
                "box" => o.box_lengths.is_some(),
                _ => o.boundary.is_some(),
            };
            if given && o.positions.is_none() {
                return Err(MechkitError::new_err(format!(
                    "{key} goes with positions: a lattice's box and velocities follow from \
                     cells, density and temperature"
                )));
            }
        }
        if o.temperature.is_some() && o.velocities.is_some() {
            return Err(MechkitError::new_err(
                "temperature and velocities cannot both be given: the velocities are drawn \
                 at the temperature, or given",
            ));
        }
        Ok(o)
    }

    fn set(&mut self, key: &str, value: &Bound<'_, PyAny>) -> PyResult<()> {
        match key {
            "lattice" => self.lattice = text(key, value)?,
            "cells" => self.cells = count(key, value)?,
            "density" => self.density = number(key, value)?,
            "temperature" => self.temperature = Some(number(key, value)?),
            "positions" => self.positions = Some(atoms(key, value)?),
            "velocities" => self.velocities = Some(atoms(key, value)?),
            "box" => self.box_lengths = Some(lengths(value)?),
            "boundary" => self.boundary = Some(text(key, value)?),
            "potential" => self.potential = text(key, value)?,
            "epsilon" => self.epsilon = number(key, value)?,
            "sigma" => self.sigma = number(key, value)?,
            "k" => self.k = number(key, value)?,
            "rest_length" => self.rest_length = number(key, value)?,
            "mass" => self.mass = number(key, value)?,
            "seed" => self.seed = whole(key, value)?,
            "steps" => self.steps = count(key, value)?,
            "dt" => self.dt = number(key, value)?,
            "cutoff" => self.cutoff = number(key, value)?,
            "shift" => self.shift = flag(key, value)?,
            "skin" => self.skin = number(key, value)?,
            "threads" => self.threads = count(key, value)?,
            "thermo_every" => self.thermo_every = count(key, value)?,
            "xyz_every" => self.xyz_every = Some(count(key, value)?),
            other => return Err(unknown(other)),
        }
        Ok(())
    }
}

/// A keyword `mechkit.md` does not take, with the nearest ones.
fn unknown(key: &str) -> PyErr {
    let near = mechkit::expr::nearest(key, NAMES);
    let hint = mechkit::expr::did_you_mean(&near).map_or_else(String::new, |h| format!("; {h}"));
    PyTypeError::new_err(format!(
        "md() got an unexpected keyword argument `{key}`{hint}"
    ))
}

/// `box`: one length for every axis, or one per axis.
fn lengths(value: &Bound<'_, PyAny>) -> PyResult<Vec<f64>> {
    if let Ok(x) = number("box", value) {
        return Ok(vec![x]);
    }
    if !value.is_instance_of::<PyString>()
        && let Ok(list) = value.extract::<Vec<f64>>()
    {
        return Ok(list);
    }
    Err(PyTypeError::new_err(format!(
        "box is a {}: give a length for every axis (10.0) or one per axis ([10, 10, 10])",
        type_name(value)
    )))
}

/// `positions` or `velocities`: a file (CSV or XYZ, as `mechkit md` reads it) or an `(N, d)`
/// array of numbers, d = 1, 2 or 3.
fn atoms(key: &str, value: &Bound<'_, PyAny>) -> PyResult<Atoms> {
    if value.is_instance_of::<PyString>() || value.hasattr("__fspath__")? {
        let path: PathBuf = value.extract()?;
        return read(key, path);
    }
    let py = value.py();
    let array = py
        .import("numpy")?
        .call_method1("asarray", (value, "float64"))
        .map_err(|_| not_vectors(key, value))?;
    let array: PyReadonlyArray2<'_, f64> = array.extract().map_err(|_| not_vectors(key, value))?;
    let [n, dim] = [array.shape()[0], array.shape()[1]];
    if !(1..=3).contains(&dim) || n == 0 {
        return Err(MechkitError::new_err(format!(
            "{key}: an array of shape ({n}, {dim}); give one row per particle of 1, 2 or 3 \
             numbers (an (N, d) array, d = 1, 2 or 3)"
        )));
    }
    let array = array.as_array();
    let mut vectors = Vec::with_capacity(n);
    for (i, row) in array.rows().into_iter().enumerate() {
        let mut vector = [0.0; 3];
        for (a, &x) in row.iter().enumerate() {
            if !x.is_finite() {
                return Err(MechkitError::new_err(format!(
                    "{key}: row {i} holds {x}, not a finite number"
                )));
            }
            vector[a] = x;
        }
        vectors.push(vector);
    }
    Ok(Atoms {
        atoms: AtomsFile { dim, vectors },
        path: None,
    })
}

fn not_vectors(key: &str, value: &Bound<'_, PyAny>) -> PyErr {
    PyTypeError::new_err(format!(
        "{key} is a {}: give a path (a CSV or XYZ file) or an (N, d) array of numbers",
        type_name(value)
    ))
}

/// Reads a positions or velocities file as `mechkit md` does, its errors named as there.
fn read(key: &str, path: PathBuf) -> PyResult<Atoms> {
    let text = std::fs::read_to_string(&path).map_err(|e| {
        MechkitError::new_err(format!("{key}: cannot read {}: {e}", path.display()))
    })?;
    let atoms = AtomsFile::parse(&path.to_string_lossy(), &text).map_err(|e| {
        MechkitError::new_err(match e {
            MdError::Parse { line, message } => {
                format!("{key}: {}:{line}: {message}", path.display())
            }
            e => format!("{key}: {}: {e}", path.display()),
        })
    })?;
    Ok(Atoms {
        atoms,
        path: Some(path),
    })
}

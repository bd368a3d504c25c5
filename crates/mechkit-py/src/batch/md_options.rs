//! `mechkit.md`'s keyword arguments as plain data: the options of `mechkit md` under the
//! same names (`--rest-length` is `rest_length`), their defaults the command's; and the
//! positions or velocities, a file as the command reads it or an `(N, d)` array.

use std::path::{Path, PathBuf};

use mechkit::md::{Atoms, AtomsFile, MdOptions};
use numpy::{PyReadonlyArray2, PyUntypedArrayMethods};
use pyo3::exceptions::PyTypeError;
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyString};

use super::arguments::{count, flag, number, text, type_name, whole};
use crate::errors::MechkitError;

/// The keyword arguments `mechkit.md` takes.
pub const NAMES: [&str; 26] = [
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
    "neigh_every",
    "neigh_check",
    "threads",
    "thermo_every",
    "xyz_every",
    "export_lammps",
];

/// The options from `mechkit.md`'s keyword arguments (None stands for a flag left out);
/// the rules between flags are the command's: `velocities` and `temperature` exclude
/// each other, `velocities`, `box` and `boundary` go with `positions`.
pub fn from_kwargs(kwargs: Option<&Bound<'_, PyDict>>) -> PyResult<MdOptions> {
    let mut o = MdOptions::default();
    let Some(kwargs) = kwargs else {
        return Ok(o);
    };
    for (key, value) in kwargs.iter() {
        let key: String = key.extract()?;
        if key == "export_lammps" {
            // not an option of the run: `export_lammps`
        } else if !value.is_none() {
            set(&mut o, &key, &value)?;
        } else if !NAMES.contains(&key.as_str()) {
            return Err(unknown(&key));
        }
    }
    for key in ["velocities", "box", "boundary"] {
        let given = match key {
            "velocities" => o.velocities.is_some(),
            "box" => !o.box_lengths.is_empty(),
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

/// `export_lammps`: the directory of a LAMMPS export of the run's start (a `str` or a path),
/// or None.
pub fn export_lammps(kwargs: Option<&Bound<'_, PyDict>>) -> PyResult<Option<PathBuf>> {
    let Some(value) = kwargs
        .map(|k| k.get_item("export_lammps"))
        .transpose()?
        .flatten()
    else {
        return Ok(None);
    };
    if value.is_none() {
        return Ok(None);
    }
    if value.is_instance_of::<PyString>() || value.hasattr("__fspath__")? {
        return Ok(Some(value.extract()?));
    }
    Err(PyTypeError::new_err(format!(
        "export_lammps: a {}; give the directory to write in.lammps and data.lammps into, \
         as a str or a path",
        type_name(&value)
    )))
}

fn set(o: &mut MdOptions, key: &str, value: &Bound<'_, PyAny>) -> PyResult<()> {
    match key {
        "lattice" => o.lattice = text(key, value)?,
        "cells" => o.cells = count(key, value)?,
        "density" => o.density = number(key, value)?,
        "temperature" => o.temperature = Some(number(key, value)?),
        "positions" => o.positions = Some(atoms(key, value)?),
        "velocities" => o.velocities = Some(atoms(key, value)?),
        "box" => o.box_lengths = lengths(value)?,
        "boundary" => o.boundary = Some(text(key, value)?),
        "potential" => o.potential = text(key, value)?,
        "epsilon" => o.epsilon = number(key, value)?,
        "sigma" => o.sigma = number(key, value)?,
        "k" => o.k = number(key, value)?,
        "rest_length" => o.rest_length = number(key, value)?,
        "mass" => o.mass = number(key, value)?,
        "seed" => o.seed = whole(key, value)?,
        "steps" => o.steps = count(key, value)?,
        "dt" => o.dt = number(key, value)?,
        "cutoff" => o.cutoff = number(key, value)?,
        "shift" => o.shift = flag(key, value)?,
        "skin" => o.skin = number(key, value)?,
        "neigh_every" => o.neigh_every = count(key, value)?,
        "neigh_check" => o.neigh_check = flag(key, value)?,
        "threads" => o.threads = count(key, value)?,
        "thermo_every" => o.thermo_every = count(key, value)?,
        "xyz_every" => o.xyz_every = Some(count(key, value)?),
        other => return Err(unknown(other)),
    }
    Ok(())
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
        return read(key, &path);
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
fn read(key: &str, path: &Path) -> PyResult<Atoms> {
    Atoms::read(path).map_err(|e| MechkitError::new_err(format!("{key}: {e}")))
}

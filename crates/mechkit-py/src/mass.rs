//! `mechkit.com(...)` and `mechkit.inertia(...)`: `mechkit com` and `mechkit inertia` from
//! Python. The centre of mass of point masses (the library's `PointMasses::report`), of a
//! body file (`BodySummary::centre_of_mass`) or of an image (`image.rs`); the inertia tensor
//! of a body file about a point and an axis (`BodySummary::inertia`). Each result is the
//! command's `--json` as a dict.

use std::path::PathBuf;

use mechkit::mass::image::FileFormat;
use mechkit::mass::{BodySummary, MassError, MassInput, PointMassInput, PointMasses, Vec3};
use mechkit::scenario::BodyFile;
use mechkit::units::Dimension;
use mechkit::values::split_top_level;
use pyo3::exceptions::PyTypeError;
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyString};

use crate::arguments::{
    error, from_json, items, json_error, output_unit, quantity, type_name, vector,
};
use crate::errors::scenario_error;
use crate::image::{ImageArgs, ImageSource, com_image};

/// What `unit=` of a centre of mass may be.
const LENGTH_UNIT: (&str, &str, &str) = ("m", "a positive length", "\"6371 km\" or \"pm\"");

/// `mechkit com` as a function: the centre of mass, as the command's `--json` (a dict), of
///
/// - point masses: a list of `(mass, position)` pairs, with their `velocities` (momentum,
///   centre-of-mass frame, kinetic energy split); `unit` also gives the centre in a length;
/// - a body file (TOML parts: its path, or its text as `text=`), rescaled to `total_mass`,
///   with the distance from `about`;
/// - an image: a PNG or JPEG path, or a numpy array of pixels (`(h, w)` grey, `(h, w, 3)`
///   RGB or `(h, w, 4)` RGBA; `uint8` levels or floats from 0 to 1). The body is the pixels
///   whose `channel` (`"sum"`, `"r"`, `"g"`, `"b"`) is below `threshold` (above with
///   `invert`), weighed by their shade with `density_from_darkness`; `pixel_size` or
///   `scale` (`"240 px = 12 cm"`) give physical units, `origin` the pixel of the origin,
///   `total_mass` the mass, `about` a point for `I_zz`; `mark` writes a PNG of what was
///   measured. An array reports what the same pixels read from a file do (its `file` is
///   `"<array>"`).
#[pyfunction]
#[pyo3(signature = (
    body = None, *, text = None, velocities = None, unit = None, total_mass = None,
    about = None, threshold = None, channel = None, invert = false,
    density_from_darkness = false, pixel_size = None, scale = None, origin = None, mark = None
))]
#[allow(clippy::too_many_arguments)] // the command's flags
pub fn com<'py>(
    py: Python<'py>,
    body: Option<&Bound<'py, PyAny>>,
    text: Option<String>,
    velocities: Option<&Bound<'py, PyAny>>,
    unit: Option<&str>,
    total_mass: Option<&Bound<'py, PyAny>>,
    about: Option<&Bound<'py, PyAny>>,
    threshold: Option<f64>,
    channel: Option<String>,
    invert: bool,
    density_from_darkness: bool,
    pixel_size: Option<&Bound<'py, PyAny>>,
    scale: Option<&Bound<'py, PyAny>>,
    origin: Option<&Bound<'py, PyAny>>,
    mark: Option<PathBuf>,
) -> PyResult<Bound<'py, PyDict>> {
    let image = ImageArgs {
        threshold,
        channel,
        invert,
        density_from_darkness,
        pixel_size,
        scale,
        origin,
        total_mass,
        about,
        mark,
    };
    let other = Other {
        velocities,
        unit,
        total_mass,
        about,
    };
    let Some(body) = body else {
        let Some(text) = text else {
            return Err(error(
                "give the body: a list of (mass, position) pairs, an image (a path or a numpy array), or a body file (a path, or its TOML as text=)",
            ));
        };
        return body_file(py, &Source::Text(text), &image, &other);
    };
    if text.is_some() {
        return Err(error("give either the body or its TOML as text=, not both"));
    }
    if is_array(body)? {
        other.reject_for_image()?;
        return com_image(py, &ImageSource::Array(body), &image);
    }
    if let Ok(path) = body.extract::<PathBuf>() {
        if FileFormat::names_an_image(&path) {
            other.reject_for_image()?;
            return com_image(py, &ImageSource::File(path), &image);
        }
        return body_file(py, &Source::File(path), &image, &other);
    }
    match items(body) {
        Some(pairs) => point_masses(py, &pairs, &image, &other),
        None => Err(PyTypeError::new_err(format!(
            "the body is a {}: give a list of (mass, position) pairs, an image (a path or a numpy array) or a body file's path",
            type_name(body)
        ))),
    }
}

/// The arguments of `com` that are not an image's.
struct Other<'a, 'py> {
    velocities: Option<&'a Bound<'py, PyAny>>,
    unit: Option<&'a str>,
    total_mass: Option<&'a Bound<'py, PyAny>>,
    about: Option<&'a Bound<'py, PyAny>>,
}

impl Other<'_, '_> {
    /// Point masses' arguments have no meaning with an image.
    fn reject_for_image(&self) -> PyResult<()> {
        for (given, name) in [
            (self.velocities.is_some(), "velocities"),
            (self.unit.is_some(), "unit"),
        ] {
            if given {
                return Err(error(format!(
                    "{name} is for point masses and body files; it cannot be used with an image"
                )));
            }
        }
        Ok(())
    }
}

/// Whether `obj` is a numpy array.
fn is_array(obj: &Bound<'_, PyAny>) -> PyResult<bool> {
    let ndarray = obj.py().import("numpy")?.getattr("ndarray")?;
    obj.is_instance(&ndarray)
}

/// `com([(m, r), ...], velocities=[...])`.
fn point_masses<'py>(
    py: Python<'py>,
    pairs: &[Bound<'py, PyAny>],
    image: &ImageArgs<'_, '_>,
    other: &Other<'_, 'py>,
) -> PyResult<Bound<'py, PyDict>> {
    if let Some(name) = image.image_only() {
        return Err(error(format!(
            "{name} applies to an image of the body; it cannot be used with point masses"
        )));
    }
    if other.total_mass.is_some() {
        return Err(error(
            "total_mass applies to an image or a body file; with point masses the total is the sum of the masses",
        ));
    }
    if other.about.is_some() {
        return Err(error(
            "about applies to an image or a body file; it cannot be used with point masses",
        ));
    }
    let mut masses = Vec::with_capacity(pairs.len());
    let mut positions = Vec::with_capacity(pairs.len());
    for (k, pair) in pairs.iter().enumerate() {
        let n = k + 1;
        let Some([m, r]) = items(pair).and_then(|p| <[_; 2]>::try_from(p).ok()) else {
            return Err(PyTypeError::new_err(format!(
                "body {n} is a {}: give each point mass as a pair (mass, position), e.g. (\"2 kg\", \"1 m, 0 m\")",
                type_name(pair)
            )));
        };
        masses.push(quantity(&m, &format!("mass {n}"), Dimension::MASS)?);
        positions.push(vector(&r, &format!("position {n}"), Dimension::LENGTH)?);
    }
    let velocities = match other.velocities {
        Some(v) => {
            let list = items(v).ok_or_else(|| {
                PyTypeError::new_err("velocities: give one velocity per body, e.g. [\"1 m/s\", 0]")
            })?;
            let vectors = list
                .iter()
                .enumerate()
                .map(|(k, v)| vector(v, &format!("velocity {}", k + 1), Dimension::VELOCITY))
                .collect::<PyResult<Vec<_>>>()?;
            Some(vectors)
        }
        None => None,
    };
    let (scale, unit) = output_unit(other.unit, Dimension::LENGTH, LENGTH_UNIT, true)?;
    let points = PointMasses::from_bodies(&masses, &positions, velocities.as_deref()).map_err(
        |e| match e.input() {
            Some(PointMassInput::Velocity) => error(format!("velocities: {e}")),
            _ => error(format!("body: {e}")),
        },
    )?;
    let report = points.report(&unit, scale);
    from_json(py, &serde_json::to_string(&report).map_err(json_error)?)
}

/// A body file: its path, or its TOML text (`text=`).
enum Source {
    File(PathBuf),
    Text(String),
}

impl Source {
    /// How messages name it.
    fn name(&self) -> String {
        match self {
            Self::File(path) => path.display().to_string(),
            Self::Text(_) => "<string>".to_string(),
        }
    }

    /// The body's whole and its parts, rescaled to `total_mass`.
    fn load(&self, py: Python<'_>, total_mass: Option<&Bound<'_, PyAny>>) -> PyResult<BodySummary> {
        let file = py
            .detach(|| match self {
                Self::File(path) => BodyFile::load(path),
                Self::Text(text) => BodyFile::from_str("<string>", text, None),
            })
            .map_err(|e| scenario_error(py, &e))?;
        let total_mass = total_mass
            .map(|m| quantity(m, "total_mass", Dimension::MASS))
            .transpose()?;
        file.body
            .summary(&file.title, total_mass)
            .map_err(|e| self.mass_error(&e))
    }

    /// A library error with the argument it is about, else the file's name.
    fn mass_error(&self, e: &MassError) -> PyErr {
        match e.input() {
            Some(MassInput::TotalMass) => error(format!("total_mass: {e}")),
            Some(MassInput::Axis) => error(format!("axis: {e}")),
            _ => error(format!("{}: {e}", self.name())),
        }
    }
}

/// `com("body.toml")`: the mass and centre of mass of the body and of each part.
fn body_file<'py>(
    py: Python<'py>,
    source: &Source,
    image: &ImageArgs<'_, '_>,
    other: &Other<'_, 'py>,
) -> PyResult<Bound<'py, PyDict>> {
    if other.velocities.is_some() {
        return Err(error(format!(
            "velocities does not apply to a body file ({})",
            source.name()
        )));
    }
    if let Some(name) = image.image_only() {
        return Err(error(format!(
            "{name} does not apply to a body file ({})",
            source.name()
        )));
    }
    let body = source.load(py, other.total_mass)?;
    let (scale, unit) = output_unit(other.unit, Dimension::LENGTH, LENGTH_UNIT, true)?;
    let about = other
        .about
        .map(|a| point(a, "about", Dimension::LENGTH))
        .transpose()?;
    let result = body.centre_of_mass(&unit, scale, about);
    from_json(py, &serde_json::to_string(&result).map_err(json_error)?)
}

/// `mechkit inertia` as a function: the mass, centre of mass, inertia tensor about the centre
/// of mass and about the point `about` (parallel-axis theorem; default the origin), and the
/// principal moments and axes of a body file (its path, or its TOML as `text=`), as the
/// command's `--json` (a dict); with `axis`, the moment and radius of gyration about the axis
/// through `about` along it. `total_mass` rescales the parts; `unit` gives the moments in
/// another unit (`"g*cm^2"`).
#[pyfunction]
#[pyo3(signature = (body = None, *, text = None, about = None, axis = None, total_mass = None, unit = None))]
pub fn inertia<'py>(
    py: Python<'py>,
    body: Option<PathBuf>,
    text: Option<String>,
    about: Option<&Bound<'py, PyAny>>,
    axis: Option<&Bound<'py, PyAny>>,
    total_mass: Option<&Bound<'py, PyAny>>,
    unit: Option<&str>,
) -> PyResult<Bound<'py, PyDict>> {
    let source = match (body, text) {
        (Some(path), None) => Source::File(path),
        (None, Some(text)) => Source::Text(text),
        (Some(_), Some(_)) => {
            return Err(error(
                "give either the body file or its TOML as text=, not both",
            ));
        }
        (None, None) => {
            return Err(error(
                "give the body file (mechkit.inertia(\"body.toml\")) or its TOML as text=",
            ));
        }
    };
    let body = source.load(py, total_mass)?;
    let (scale, unit) = output_unit(
        unit,
        Dimension::MOMENT_OF_INERTIA,
        (
            "kg*m^2",
            "a unit of moment of inertia (mass × length²)",
            "\"g*cm^2\" or \"u*pm^2\"",
        ),
        false,
    )?;
    let about = match about {
        Some(p) => point(p, "about", Dimension::LENGTH)?,
        None => Vec3::zeros(),
    };
    let axis = axis
        .map(|a| point(a, "axis", Dimension::NONE))
        .transpose()?;
    let result = body
        .inertia(&unit, scale, about, axis)
        .map_err(|e| source.mass_error(&e))?;
    from_json(py, &serde_json::to_string(&result).map_err(json_error)?)
}

/// A point (or direction) of 1 to 3 components, padded with zeros: a string `"x, y, z"` with
/// units of `dim`, or a sequence of values.
fn point(obj: &Bound<'_, PyAny>, name: &str, dim: Dimension) -> PyResult<Vec3> {
    let components: Vec<f64> = if obj.is_instance_of::<PyString>() {
        let text: String = obj.extract()?;
        let parts = split_top_level(&text, ',');
        if !(1..=3).contains(&parts.len()) {
            return Err(error(format!(
                "{name} `{text}` needs 1 to 3 components, e.g. \"0.5 m, 0, 0\""
            )));
        }
        parts
            .iter()
            .map(|c| {
                let c = PyString::new(obj.py(), c);
                quantity(c.as_any(), name, dim)
            })
            .collect::<PyResult<_>>()?
    } else {
        let parts = items(obj).unwrap_or_else(|| vec![obj.clone()]);
        if !(1..=3).contains(&parts.len()) {
            return Err(error(format!(
                "{name} needs 1 to 3 components, not {}, e.g. (0.5, 0, 0)",
                parts.len()
            )));
        }
        parts
            .iter()
            .map(|c| quantity(c, name, dim))
            .collect::<PyResult<_>>()?
    };
    let mut p = Vec3::zeros();
    for (k, c) in components.into_iter().enumerate() {
        p[k] = c;
    }
    Ok(p)
}

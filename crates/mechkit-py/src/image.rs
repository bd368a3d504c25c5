//! `mechkit.com(image)`: the centre of mass and moments of the body in an image, as
//! `mechkit com IMAGE` measures it (the library's `PixelBody::measure` and `report`), from a
//! PNG or JPEG file or from a numpy array: `(height, width)` grey, `(height, width, 3)` RGB
//! or `(height, width, 4)` RGBA, as `uint8` levels (or another integer type, 0 to 255) or
//! floats from 0 to 1, made into the library's `Raster` without a file.

use std::path::PathBuf;

use mechkit::csv::write_atomic;
use mechkit::mass::image::{
    Channel, ImageError, ImageOptions, PixelBody, Raster, Selection, marked_png,
};
use mechkit::units::Dimension;
use mechkit::values::{self, split_top_level};
use numpy::{PyArrayDescrMethods, PyReadonlyArrayDyn, PyUntypedArray, PyUntypedArrayMethods};
use pyo3::exceptions::PyTypeError;
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyString};

use crate::arguments::{
    Scalar, error, from_json, items, json_error, quantity, scalar, shape_text, type_name,
    value_error,
};

/// What an array is called in messages and in the result's `file`.
const ARRAY: &str = "<array>";

/// Where the image comes from.
pub enum ImageSource<'a, 'py> {
    /// A PNG or JPEG file.
    File(PathBuf),
    /// A numpy array of pixels.
    Array(&'a Bound<'py, PyAny>),
}

/// The image's arguments of `com` (`total_mass` and `about` serve a body file too).
pub struct ImageArgs<'a, 'py> {
    pub threshold: Option<f64>,
    pub channel: Option<String>,
    pub invert: bool,
    pub density_from_darkness: bool,
    pub pixel_size: Option<&'a Bound<'py, PyAny>>,
    pub scale: Option<&'a Bound<'py, PyAny>>,
    pub origin: Option<&'a Bound<'py, PyAny>>,
    pub total_mass: Option<&'a Bound<'py, PyAny>>,
    pub about: Option<&'a Bound<'py, PyAny>>,
    pub mark: Option<PathBuf>,
}

impl ImageArgs<'_, '_> {
    /// The first argument given that only an image has, if any.
    pub fn image_only(&self) -> Option<&'static str> {
        [
            (self.mark.is_some(), "mark"),
            (self.threshold.is_some(), "threshold"),
            (self.channel.is_some(), "channel"),
            (self.invert, "invert"),
            (self.density_from_darkness, "density_from_darkness"),
            (self.pixel_size.is_some(), "pixel_size"),
            (self.scale.is_some(), "scale"),
            (self.origin.is_some(), "origin"),
        ]
        .into_iter()
        .find_map(|(given, name)| given.then_some(name))
    }
}

/// The report of the body in an image, as `mechkit com IMAGE --json` prints it.
pub fn com_image<'py>(
    py: Python<'py>,
    source: &ImageSource<'_, 'py>,
    args: &ImageArgs<'_, 'py>,
) -> PyResult<Bound<'py, PyDict>> {
    let channel = Channel::parse(args.channel.as_deref().unwrap_or("sum"))
        .map_err(|e| error(format!("channel: {e}")))?;
    let selection = Selection::from_options(
        channel,
        args.threshold,
        args.invert,
        args.density_from_darkness,
    )
    .map_err(|e| error(format!("threshold: {e}, e.g. threshold=1.5")))?;
    let size = pixel_size(args)?;
    let total_mass = match args.total_mass {
        Some(m) => {
            let m = quantity(m, "total_mass", Dimension::MASS)?;
            if !(m.is_finite() && m > 0.0) {
                return Err(error(
                    "total_mass must be a positive mass, e.g. total_mass=\"2 kg\"",
                ));
            }
            Some(m)
        }
        None => None,
    };
    let (raster, name) = match source {
        ImageSource::File(path) => (
            py.detach(|| Raster::open(path))
                .map_err(|e| error(e.to_string()))?,
            path.display().to_string(),
        ),
        ImageSource::Array(array) => (raster(array)?, ARRAY.to_string()),
    };
    let origin = match args.origin {
        Some(o) => {
            let [x, y] = pair(o, "origin", "200, 400")?;
            Some([pixels(&x, "origin")?, pixels(&y, "origin")?])
        }
        None => None,
    };
    let about = match args.about {
        Some(a) => {
            let [x, y] = pair(a, "about", "0, 0")?;
            Some([
                coordinate(&x, size.is_some())?,
                coordinate(&y, size.is_some())?,
            ])
        }
        None => None,
    };
    let body = py
        .detach(|| PixelBody::measure(&raster, &selection))
        .map_err(|e| error(format!("{name}: {}", image_error(&e))))?;
    let options = ImageOptions {
        selection,
        pixel_size: size,
        origin,
        total_mass,
        about,
    };
    let mut result = body
        .report(&name, &options)
        .map_err(|e| error(e.to_string()))?;
    if let Some(out) = &args.mark {
        if !out
            .extension()
            .is_some_and(|e| e.eq_ignore_ascii_case("png"))
        {
            return Err(error(
                "mark writes a PNG image: name the file .png, e.g. mark=\"marked.png\"",
            ));
        }
        py.detach(|| {
            let png = marked_png(&raster, &selection, &body).map_err(|e| format!("mark: {e}"))?;
            write_atomic(out, &png)
                .map_err(|e| format!("mark: cannot write {}: {e}", out.display()))
        })
        .map_err(error)?;
        result.mark = Some(out.display().to_string());
    }
    from_json(py, &serde_json::to_string(&result).map_err(json_error)?)
}

/// The image's error, with the arguments that change a selection that marks nothing or all.
fn image_error(e: &ImageError) -> String {
    match e {
        ImageError::SelectsNothing { .. } | ImageError::SelectsEverything { .. } => format!(
            "{e} (threshold=; channel=\"sum\", \"r\", \"g\" or \"b\"; invert=True for a bright body on a dark background)"
        ),
        e => e.to_string(),
    }
}

/// The pixels of a numpy array as a `Raster`: levels checked to be 0-255 (integers) or 0-1
/// (floats, rounded to the nearest level as `Raster::from_fn` does), RGBA composed on white
/// as a PNG's transparency is.
fn raster(obj: &Bound<'_, PyAny>) -> PyResult<Raster> {
    let numpy = obj.py().import("numpy")?;
    let array = obj.cast::<PyUntypedArray>()?;
    let shape = array.shape().to_vec();
    let (height, width, channels) = match shape.as_slice() {
        [h, w] => (*h, *w, 1),
        [h, w, c @ (1 | 3 | 4)] => (*h, *w, *c),
        _ => {
            return Err(error(format!(
                "image array: an array of shape {} is not an image; give (height, width) grey, (height, width, 3) RGB or (height, width, 4) RGBA pixels",
                shape_text(&shape)
            )));
        }
    };
    let levels: Vec<u8> = match array.dtype().kind() {
        b'u' | b'i' => {
            let ints = numpy.call_method1("asarray", (obj, "int64"))?;
            let ints: PyReadonlyArrayDyn<'_, i64> = ints.extract()?;
            let ints = ints.as_array();
            if let Some(v) = ints.iter().find(|v| !(0..=255).contains(*v)) {
                return Err(error(format!(
                    "image array: an integer array holds levels from 0 to 255, not {v}"
                )));
            }
            ints.iter().map(|&v| v as u8).collect()
        }
        b'f' => {
            let floats = numpy.call_method1("asarray", (obj, "float64"))?;
            let floats: PyReadonlyArrayDyn<'_, f64> = floats.extract()?;
            let floats = floats.as_array();
            if let Some(v) = floats.iter().find(|v| !(0.0..=1.0).contains(*v)) {
                return Err(error(format!(
                    "image array: a float array holds values from 0 to 1, not {}; for levels 0 to 255 give a uint8 array (array.astype(numpy.uint8))",
                    mechkit::expr::short_number(*v)
                )));
            }
            floats.iter().map(|&v| Raster::level(v)).collect()
        }
        _ => {
            return Err(PyTypeError::new_err(format!(
                "image array: an array of {} is not an image: give uint8 levels (0 to 255) or floats (0 to 1); for a mask of the body, numpy.where(mask, 0, 255).astype(numpy.uint8)",
                array.dtype()
            )));
        }
    };
    let made = match channels {
        1 => Raster::from_rgb8(
            width,
            height,
            levels.iter().flat_map(|&g| [g, g, g]).collect(),
        ),
        3 => Raster::from_rgb8(width, height, levels),
        _ => Raster::from_rgba8(width, height, &levels),
    };
    made.map_err(|e| error(format!("image array: {e}")))
}

/// The side of a pixel (m) from `pixel_size` or `scale`, or `None` to work in pixels.
fn pixel_size(args: &ImageArgs<'_, '_>) -> PyResult<Option<f64>> {
    let size = match (args.pixel_size, args.scale) {
        (Some(_), Some(_)) => return Err(error("give either pixel_size or scale, not both")),
        (None, None) => return Ok(None),
        (Some(s), None) => quantity(s, "pixel_size", Dimension::LENGTH)?,
        (None, Some(s)) => scale(s)?,
    };
    if !(size.is_finite() && size > 0.0) {
        return Err(error(
            "the pixel size must be a positive length, e.g. pixel_size=\"0.5 mm\"",
        ));
    }
    Ok(Some(size))
}

/// `scale="240 px = 12 cm"` (either way round) or `(240, "12 cm")` → metres per pixel.
fn scale(obj: &Bound<'_, PyAny>) -> PyResult<f64> {
    if obj.is_instance_of::<PyString>() {
        let text: String = obj.extract()?;
        return values::pixel_scale(&text, "scale").map_err(value_error);
    }
    let Some([px, length]) = items(obj).and_then(|p| <[_; 2]>::try_from(p).ok()) else {
        return Err(PyTypeError::new_err(format!(
            "scale is a {}: give (pixels, length), e.g. (240, \"12 cm\"), or \"240 px = 12 cm\"",
            type_name(obj)
        )));
    };
    values::pixels_to_length(
        pixels(&scalar(&px, "scale")?, "scale")?,
        quantity(&length, "scale", Dimension::LENGTH)?,
        "scale",
    )
    .map_err(value_error)
}

/// A number of pixels: a number, `"240"`, `"240 px"`, `"240 pixels"`.
fn pixels(value: &Scalar, name: &str) -> PyResult<f64> {
    match value {
        Scalar::Number(x) if x.is_finite() => Ok(*x),
        Scalar::Number(x) => values::pixels(&x.to_string(), name).map_err(value_error),
        Scalar::Text(t) => values::pixels(t, name).map_err(value_error),
    }
}

/// A point `"x, y"` or `(x, y)`, as its two values.
fn pair(obj: &Bound<'_, PyAny>, name: &str, example: &str) -> PyResult<[Scalar; 2]> {
    if obj.is_instance_of::<PyString>() {
        let text: String = obj.extract()?;
        return match split_top_level(&text, ',').as_slice() {
            [x, y] if !x.is_empty() && !y.is_empty() => Ok([
                Scalar::Text((*x).to_string()),
                Scalar::Text((*y).to_string()),
            ]),
            _ => Err(error(format!(
                "{name} takes two coordinates \"x, y\", e.g. {name}=\"{example}\", not `{text}`"
            ))),
        };
    }
    match items(obj).and_then(|p| <[_; 2]>::try_from(p).ok()) {
        Some([x, y]) => Ok([scalar(&x, name)?, scalar(&y, name)?]),
        None => Err(PyTypeError::new_err(format!(
            "{name} is a {}: give two coordinates (x, y) or \"x, y\", e.g. {name}=\"{example}\"",
            type_name(obj)
        ))),
    }
}

/// A coordinate of `about`: a length with a scale, pixels without one.
fn coordinate(value: &Scalar, scaled: bool) -> PyResult<f64> {
    match value {
        Scalar::Text(text) => {
            values::image_coordinate(text, "about", scaled, "pixel_size or scale")
                .map_err(value_error)
        }
        Scalar::Number(x) if scaled && !x.is_finite() => {
            Err(error(format!("about: {x} is not a finite number")))
        }
        Scalar::Number(x) if scaled => Ok(*x),
        Scalar::Number(_) => pixels(value, "about"),
    }
}

//! Plot data, ready to render: curves, marked points, shaded bands, bars, the scale of the
//! vertical axis, and a colour scale for a family of curves. The library computes figures;
//! drawing them (SVG) is the command line's job.

use crate::Real;

/// How a curve is drawn.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
#[non_exhaustive]
pub enum LineStyle {
    /// A solid line.
    #[default]
    Solid,
    /// A dashed line (reference levels, such as a total energy).
    Dashed,
    /// Unconnected markers (values to compare with a curve).
    Markers,
}

/// A curve's points.
#[derive(Debug, Clone, PartialEq)]
pub struct Series {
    /// Legend label.
    pub label: String,
    /// Points `(x, y)`.
    pub points: Vec<(Real, Real)>,
    /// How it is drawn.
    pub style: LineStyle,
    /// Its value on the plot's [`ColourScale`] (a sweep's parameter): with a colour scale, a
    /// curve with a value is drawn in the scale's colour for it and is named by the colour
    /// bar, not by a legend entry.
    pub value: Option<Real>,
}

impl Series {
    /// A solid curve.
    pub fn line(label: impl Into<String>, points: Vec<(Real, Real)>) -> Self {
        Self {
            label: label.into(),
            points,
            style: LineStyle::Solid,
            value: None,
        }
    }

    /// The same curve with its value on the plot's colour scale.
    #[must_use]
    pub fn valued(mut self, value: Real) -> Self {
        self.value = Some(value);
        self
    }

    /// The same curve drawn with `style`.
    #[must_use]
    pub fn styled(mut self, style: LineStyle) -> Self {
        self.style = style;
        self
    }
}

/// The shape of a marked point.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[non_exhaustive]
pub enum MarkerShape {
    /// A filled disc (a stable equilibrium).
    Filled,
    /// A ring (an unstable equilibrium).
    Open,
    /// A cross (a neutral point, a singular point).
    Cross,
    /// A triangle (a turning point).
    Triangle,
}

/// A marked, labelled point.
#[derive(Debug, Clone, PartialEq)]
pub struct Marker {
    /// Position.
    pub at: (Real, Real),
    /// Legend label (markers with the same label share one legend entry).
    pub label: String,
    /// Shape.
    pub shape: MarkerShape,
}

/// A vertical band shaded across the plot (a forbidden region).
#[derive(Debug, Clone, PartialEq)]
pub struct Band {
    /// Start on the horizontal axis.
    pub from: Real,
    /// End.
    pub to: Real,
    /// Legend label.
    pub label: String,
}

/// What a bar of a bar chart stands for.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[non_exhaustive]
pub enum BarKind {
    /// An amount, drawn up from zero (a kinetic energy).
    Total,
    /// A change, drawn from the running total before it to the one after it (the work of a
    /// force); a gain and a loss are told apart by colour.
    Change,
}

/// One bar, from `from` to `to` on the vertical axis.
#[derive(Debug, Clone, PartialEq)]
pub struct Bar {
    /// Label under the bar.
    pub label: String,
    /// Bottom (a change: the running total before it).
    pub from: Real,
    /// Top (a change: the running total after it; below `from` for a loss).
    pub to: Real,
    /// What it stands for.
    pub kind: BarKind,
}

/// How an axis maps values to lengths.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
#[non_exhaustive]
pub enum Scale {
    /// Equal lengths for equal differences.
    #[default]
    Linear,
    /// Equal lengths for equal ratios (decades), for values over many orders of magnitude
    /// (errors). Only positive values can be shown: a curve is cut where it is zero or
    /// negative.
    Log,
}

/// A colour scale: a family of curves coloured by a value (a sweep's parameter, from `from`
/// to `to`) through a perceptual colour map, named by a colour bar beside the plot.
#[derive(Debug, Clone, PartialEq)]
pub struct ColourScale {
    /// The bar's label, with the unit: `v0 [m/s]`.
    pub label: String,
    /// The value at the bottom of the bar (the first colour of the map).
    pub from: Real,
    /// The value at the top (the last colour).
    pub to: Real,
}

impl ColourScale {
    /// The position of `value` on the scale, 0 at `from` to 1 at `to`, clamped (0.5 for a
    /// scale of one value).
    ///
    /// # Example
    /// ```
    /// use mechkit::figure::ColourScale;
    /// let s = ColourScale { label: "v0 [m/s]".into(), from: 1.0, to: 5.0 };
    /// assert_eq!(s.fraction(2.0), 0.25);
    /// assert_eq!(s.fraction(9.0), 1.0);
    /// ```
    pub fn fraction(&self, value: Real) -> Real {
        let span = self.to - self.from;
        if span == 0.0 || !span.is_finite() || !value.is_finite() {
            return 0.5;
        }
        ((value - self.from) / span).clamp(0.0, 1.0)
    }
}

/// The data of one plot, ready to render.
#[derive(Debug, Clone, PartialEq)]
pub struct PlotData {
    /// As written, e.g. `v(x)`; used as the title.
    pub spec: String,
    /// Suggested file name without extension.
    pub file_stem: String,
    /// Axis labels with units.
    pub x_label: String,
    /// Axis labels with units.
    pub y_label: String,
    /// The curves (a curve whose values are all NaN, such as `U` without potentials, is left
    /// out).
    pub series: Vec<Series>,
    /// Whether both axes are positions, so the plot should keep lengths equal (a circle stays
    /// round).
    pub equal_aspect: bool,
    /// Marked points.
    pub markers: Vec<Marker>,
    /// Shaded bands.
    pub bands: Vec<Band>,
    /// The vertical range to show, when the curves' own range would hide the interesting part
    /// (a potential that diverges at the edge of its range).
    pub y_limits: Option<(Real, Real)>,
    /// Bars, left to right: a plot with bars is a bar chart, drawn with the labels along the
    /// horizontal axis instead of a scale.
    pub bars: Vec<Bar>,
    /// The scale of the vertical axis.
    pub y_scale: Scale,
    /// The colour scale of the curves that have a value, if they are coloured by it.
    pub colour_scale: Option<ColourScale>,
}

impl PlotData {
    /// An empty plot with a title, a file stem and axis labels.
    pub fn new(
        spec: impl Into<String>,
        file_stem: impl Into<String>,
        x_label: impl Into<String>,
        y_label: impl Into<String>,
    ) -> Self {
        Self {
            spec: spec.into(),
            file_stem: file_stem.into(),
            x_label: x_label.into(),
            y_label: y_label.into(),
            series: Vec::new(),
            equal_aspect: false,
            markers: Vec::new(),
            bands: Vec::new(),
            y_limits: None,
            bars: Vec::new(),
            y_scale: Scale::Linear,
            colour_scale: None,
        }
    }

    /// The same plot with its vertical axis on `scale`.
    #[must_use]
    pub fn with_y_scale(mut self, scale: Scale) -> Self {
        self.y_scale = scale;
        self
    }

    /// The same plot with its valued curves coloured by `scale`.
    #[must_use]
    pub fn with_colour_scale(mut self, scale: ColourScale) -> Self {
        self.colour_scale = Some(scale);
        self
    }

    /// Adds a curve.
    #[must_use]
    pub fn with_series(mut self, series: Series) -> Self {
        self.series.push(series);
        self
    }
}

//! Plot data, ready to render: curves, marked points, shaded bands, bars. The library computes
//! figures; drawing them (SVG) is the command line's job.

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
}

impl Series {
    /// A solid curve.
    pub fn line(label: impl Into<String>, points: Vec<(Real, Real)>) -> Self {
        Self {
            label: label.into(),
            points,
            style: LineStyle::Solid,
        }
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
        }
    }

    /// Adds a curve.
    #[must_use]
    pub fn with_series(mut self, series: Series) -> Self {
        self.series.push(series);
        self
    }
}

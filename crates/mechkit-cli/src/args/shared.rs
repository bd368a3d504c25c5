//! The options many commands share, flattened into each: [`Report`] (`--json`, `-q`) and
//! [`PlotFormat`] (`--format`, `--dpi`, `--style`).

/// The flags every command has: `--json` and `-q/--quiet`.
#[derive(Debug, Clone, Copy, Default, clap::Args)]
pub struct Report {
    /// Print the result as JSON on stdout (instead of the text report).
    #[arg(long)]
    pub json: bool,
    /// Quiet: no text report, progress bar or notes (the files asked for are still written,
    /// --json still prints; warnings and errors still go to stderr).
    #[arg(short, long)]
    pub quiet: bool,
}

/// How plots are written: `--format svg|png`, `--dpi` and `--style paper|slides` (flattened
/// into every command that draws plots into a directory; where a command takes a plot's path,
/// its extension decides the format).
#[derive(clap::Args, Debug, Clone, Copy, PartialEq, Eq)]
pub struct PlotFormat {
    /// Plot files: svg (vector, for documents) or png (raster, for slides).
    #[arg(long = "format", value_enum, default_value_t = PlotKind::Svg)]
    pub kind: PlotKind,
    /// Resolution of PNG plots in dots per inch; 96 gives the SVG's own 900x600 pixels.
    #[arg(long, default_value_t = 192, value_parser = clap::value_parser!(u32).range(24..=1200), allow_hyphen_values = true)]
    pub dpi: u32,
    /// Look of the plots: paper, or slides (larger type, thicker lines, larger markers).
    #[arg(long, value_enum, default_value_t = PlotStyle::Paper, allow_hyphen_values = true)]
    pub style: PlotStyle,
}

impl Default for PlotFormat {
    fn default() -> Self {
        Self {
            kind: PlotKind::Svg,
            dpi: 192,
            style: PlotStyle::Paper,
        }
    }
}

impl PlotFormat {
    /// The file name of the plot `stem`: `stem.svg` or `stem.png`.
    pub fn file(self, stem: &str) -> String {
        match self.kind {
            PlotKind::Svg => format!("{stem}.svg"),
            PlotKind::Png => format!("{stem}.png"),
        }
    }
}

/// A plot file format.
#[derive(clap::ValueEnum, Debug, Clone, Copy, PartialEq, Eq)]
pub enum PlotKind {
    /// Scalable vector graphics.
    Svg,
    /// Portable network graphics, at `--dpi`.
    Png,
}

/// The look of a plot: the sizes of its type, lines and markers.
#[derive(clap::ValueEnum, Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum PlotStyle {
    /// For documents, read close up.
    #[default]
    Paper,
    /// For slides, read from the back of a room: type about 1.6 times larger, lines and
    /// markers thicker.
    Slides,
}

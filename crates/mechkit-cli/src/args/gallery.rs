//! `mechkit gallery`: the course's worked problems, bundled.

use std::path::PathBuf;

/// `mechkit gallery`. With no argument or `--list`: the bundled cases. With a case id (or
/// the start of one, e.g. `c08-B9`): run its scenario or script, print the computed values
/// against the expected ones, write its outputs and plots to `--out/<file stem>`. With
/// `--all`: every case. With `--report FILE`: every case, and the table between the gallery
/// markers of FILE rewritten (plots next to it in `gallery/`); `--check` only compares.
#[derive(Debug, clap::Args)]
#[allow(
    clippy::struct_excessive_bools,
    reason = "independent command-line flags, each a switch"
)]
pub struct GalleryArgs {
    /// A case id, or the start of one that names a single case, e.g. "c08-B9".
    #[arg(conflicts_with_all = ["list", "all", "report"])]
    pub case: Option<String>,
    /// List the bundled cases: id, chapter, topic, the files that reproduce it.
    #[arg(long)]
    pub list: bool,
    /// Run every case.
    #[arg(long, conflicts_with = "list")]
    pub all: bool,
    /// Run every case and write the validation table into this Markdown file, between the
    /// lines `<!-- gallery:begin … -->` and `<!-- gallery:end -->`.
    #[arg(long, conflicts_with = "list")]
    pub report: Option<PathBuf>,
    /// With --report: do not write; fail (exit 1) when the file's table differs from the
    /// computed one.
    #[arg(long, requires = "report")]
    pub check: bool,
    /// Output directory: one folder per case file with its outputs and plots [default:
    /// out/gallery, or gallery/ next to the --report file].
    #[arg(short, long)]
    pub out: Option<PathBuf>,
    /// Run the case files of DIR/examples/book (a checkout, or a copy with cases you edited)
    /// instead of the bundled ones.
    #[arg(long, value_name = "DIR")]
    pub root: Option<PathBuf>,
    /// Do not draw the scenarios' plots.
    #[arg(long)]
    pub no_plots: bool,
    /// Print JSON.
    #[arg(long)]
    pub json: bool,
}

//! The bodies of mechkit's fuzz targets, one function per kind of user input.
//!
//! Each function takes arbitrary bytes, feeds them through the same library calls the CLI
//! makes for that input, and renders every error the way the CLI would. Whatever the bytes,
//! it must return: a panic, a hang or unbounded memory is a finding. The functions hold no
//! fuzzing machinery, so the libFuzzer binaries under `fuzz/` and the ordinary test that
//! replays the seed and regression inputs (`tests/replay.rs`) run exactly the same code.
//!
//! See `docs/reliability.md` for how the targets are run and what they found.

pub mod browser;
pub mod command_line;
pub mod python_front;

use std::sync::OnceLock;

use mechkit::Real;
use mechkit::calculus;
use mechkit::collisions::Restitution;
use mechkit::data::{ColumnRef, Order, Table};
use mechkit::deriv::{Derivation, Difference, SavitzkyGolay, kinematics, uniform_step};
use mechkit::energy::{ForceField, SampledIntegral};
use mechkit::expr::{Formula, MapScope, simplify};
use mechkit::mass::TriangleMesh;
use mechkit::mass::image::{Channel, Density, PixelBody, PixelFrame, Raster, Selection};
use mechkit::md::AtomsFile;
use mechkit::quad::SampleRule;
use mechkit::scenario::sweep::{Parameter, Sampling, Shard, SweepGrid};
use mechkit::scenario::{BodyFile, Scenario, format_size, parse_size};
use mechkit::units::{Quantity, Unit};

/// The names a fuzzed formula may use: what a force formula sees in a 2-D scenario, plus a
/// parameter.
fn formula_scope() -> MapScope {
    ["t", "x", "y", "vx", "vy", "v", "r", "m"]
        .iter()
        .enumerate()
        .fold(MapScope::new(), |s, (i, n)| s.slot(n, i))
        .constant("k", 2.5)
}

/// The values of [`formula_scope`]'s slots.
const SLOT_VALUES: [Real; 8] = [0.5, 1.25, -0.75, 3.0, -2.0, 3.6, 1.46, 0.2];

/// Parameters the calculus calls get for names other than the variable.
fn params() -> Vec<(String, Real)> {
    [("a", 2.0), ("b", -0.5), ("k", 3.0), ("m", 0.25)]
        .iter()
        .map(|&(n, v)| (n.to_string(), v))
        .collect()
}

fn text(data: &[u8]) -> Option<&str> {
    std::str::from_utf8(data).ok()
}

/// A formula as typed into a scenario or `mechkit diff`: parsed, its errors rendered,
/// compiled and evaluated (interpreter and native code must agree bit for bit), simplified,
/// and differentiated (symbolically, and numerically at a point). The costlier symbolic
/// integration and equation solving have their own target, [`calculus()`](fn@calculus), so
/// that the parser and simplifier get most of the inputs.
pub fn expression(data: &[u8]) {
    let Some(src) = text(data) else { return };
    let formula = match Formula::parse(src) {
        Ok(f) => f,
        Err(e) => {
            let _ = e.to_string();
            return;
        }
    };
    let scope = formula_scope();
    match formula.compile(&scope) {
        Ok(program) => {
            let interpreted = program.eval(&SLOT_VALUES);
            let native = program.native().eval(&SLOT_VALUES);
            assert!(
                interpreted.to_bits() == native.to_bits()
                    || (interpreted.is_nan() && native.is_nan()),
                "interpreter {interpreted:e} and native code {native:e} disagree on {src:?}"
            );
        }
        Err(e) => {
            let _ = e.to_string();
        }
    }
    let _ = simplify(formula.expr()).to_string();
    match calculus::derivative(src, "x") {
        Ok(d) => {
            let _ = d.result.to_string();
        }
        Err(e) => {
            let _ = e.to_string();
        }
    }
    let _ = calculus::derivative_at(src, "x", 0.7, &params(), 0.1).map_err(|e| e.to_string());
}

/// A formula or equation as typed into `mechkit integrate` or `mechkit solve`: a formula is
/// integrated symbolically (with its check by differentiation) and on `[0, 1]`; an equation
/// (`lhs = rhs`, which does not parse as a formula) is solved on `[-10, 10]`. The inputs are
/// the [`expression`] target's.
pub fn calculus(data: &[u8]) {
    let Some(src) = text(data) else { return };
    if Formula::parse(src).is_err() {
        // equations (`=`) are not formulas; `solve` reads them
        if src.contains('=') {
            let _ = calculus::solve(src, "x", Some((-10.0, 10.0)), &params())
                .map_err(|e| e.to_string());
        }
        return;
    }
    match calculus::integral(src, "x", Some((0.0, 1.0)), &params()) {
        Ok(i) => {
            let _ = i.antiderivative.map(|a| a.to_string());
        }
        Err(e) => {
            let _ = e.to_string();
        }
    }
}

/// A quantity with a unit, as in a scenario value or `mechkit convert`: the first line is
/// the quantity, the second (if any) the unit to convert to.
pub fn units(data: &[u8]) {
    let Some(src) = text(data) else { return };
    let (quantity, to) = match src.split_once('\n') {
        Some((q, u)) => (q, Some(u)),
        None => (src, None),
    };
    let _ = Quantity::parse(quantity).map_err(|e| (e.to_string(), e.snippet()));
    if let Some(u) = to {
        let _ = Unit::parse(u).map_err(|e| (e.to_string(), e.snippet()));
    }
    let _ = calculus::convert(quantity, to).map_err(|e| e.to_string());
}

/// Steps a fuzzed scenario may run: enough to reach events, plots and the ledger, few enough
/// that every input finishes in milliseconds.
pub const SCENARIO_STEPS: u64 = 200;

/// Output limit of a fuzzed scenario's run: it bounds the output times as the step budget
/// bounds the steps (a few hundred steps can hold 10^15 output times of `interval = "2 fs"`).
pub const SCENARIO_OUTPUT: u64 = 1_000_000;

/// A scenario file: loaded and built into a model (every error rendered with its location),
/// then, when it loads, run in memory for at most [`SCENARIO_STEPS`] steps and
/// [`SCENARIO_OUTPUT`] bytes of output, and summarised.
/// The same text is also read as a body file of `mechkit body`.
pub fn scenario(data: &[u8]) {
    let Some(src) = text(data) else { return };
    if let Ok(body) = BodyFile::from_str("fuzz.toml", src, None).map_err(|e| e.to_string()) {
        let _ = body.body.properties().map_err(|e| e.to_string());
    }
    match Scenario::from_str("fuzz.toml", src) {
        Ok(mut s) => {
            s.max_steps = Some(
                s.max_steps
                    .map_or(SCENARIO_STEPS, |n| n.min(SCENARIO_STEPS)),
            );
            s.max_output = s.max_output.min(SCENARIO_OUTPUT);
            match s.run() {
                Ok(out) => {
                    let _ = out.summary.stop_reason.len();
                }
                Err(e) => {
                    let _ = e.to_string();
                }
            }
        }
        Err(e) => {
            let _ = e.to_string();
        }
    }
}

/// A data file: as a measured table (CSV or whitespace-separated) the way `mechkit derive`
/// and `mechkit work` read it (the first column as abscissa, then velocities and
/// accelerations of the second column by every scheme, and its integral by every rule), as
/// an atoms file of `mechkit md --positions` (CSV and XYZ), and as an OBJ mesh of a body.
pub fn data_file(data: &[u8]) {
    let Some(src) = text(data) else { return };
    let _ = AtomsFile::parse_csv(src).map_err(|e| e.to_string());
    let _ = AtomsFile::parse_xyz(src).map_err(|e| e.to_string());
    if let Ok(mesh) = TriangleMesh::from_obj(src).map_err(|e| e.to_string()) {
        let _ = mesh.unit_properties();
    }
    let table = match Table::parse(src, "fuzz.csv") {
        Ok(t) => t,
        Err(e) => {
            let _ = e.to_string();
            return;
        }
    };
    for i in 0..table.width() {
        let _ = table.label(i);
        let _ = table
            .column(&ColumnRef::Index(i))
            .map_err(|e| e.to_string());
    }
    if let Some(names) = table.names() {
        for n in names {
            let _ = table.column_index(&ColumnRef::Name(n.clone()));
        }
    }
    if table.width() < 2 {
        return;
    }
    let t_ref = ColumnRef::Index(0);
    let Ok((t, order)) = table.abscissa(&t_ref, "fuzzing").map_err(|e| e.to_string()) else {
        return;
    };
    let Ok(x) = table.column(&ColumnRef::Index(1)) else {
        return;
    };
    for rule in [
        SampleRule::Left,
        SampleRule::Right,
        SampleRule::Midpoint,
        SampleRule::Trapezoid,
        SampleRule::Simpson,
    ] {
        let _ = SampledIntegral::new(t, x, rule).map_err(|e| e.to_string());
    }
    if order != Order::Increasing {
        return;
    }
    for scheme in [
        Difference::Forward,
        Difference::Backward,
        Difference::Central,
    ] {
        let _ = kinematics(t, x, Derivation::Differences(scheme)).map_err(|e| e.to_string());
    }
    if uniform_step(t).is_some()
        && let Ok(sg) = SavitzkyGolay::new(5, 2)
    {
        let _ = kinematics(t, x, Derivation::SavitzkyGolay(sg)).map_err(|e| e.to_string());
    }
}

/// The largest image the `image` target decodes.
pub const FUZZ_MAX_PIXELS: u64 = 1 << 16;

/// An image for `mechkit com --image`: decoded (PNG or JPEG, anything else refused by what
/// it is), the body selected by the default threshold of each channel, its pixels measured
/// and its mass properties computed.
pub fn image(data: &[u8]) {
    // images up to 256 × 256: a larger one runs the same code for longer (the corpus had
    // grown to a median of 400 × 400 pixels, 917 of its 1283 PNGs above this limit, and the
    // target ran at 225 inputs/s); the refusal from the header is the real limit's code
    let raster = match Raster::decode_at_most(data, "fuzz.png", FUZZ_MAX_PIXELS) {
        Ok(r) => r,
        Err(e) => {
            let _ = e.to_string();
            return;
        }
    };
    let Ok(frame) = PixelFrame::new(0.01, [0.0, raster.height() as Real]) else {
        return;
    };
    for (name, invert, density) in [
        ("sum", false, Density::Uniform),
        ("r", true, Density::Darkness),
    ] {
        let Ok(channel) = Channel::parse(name) else {
            continue;
        };
        let selection = Selection::new(channel)
            .threshold(channel.default_threshold())
            .inverted(invert)
            .density(density);
        match PixelBody::measure(&raster, &selection) {
            Ok(body) => {
                let _ = body
                    .mass_properties(&frame, Some(2.0))
                    .map_err(|e| e.to_string());
            }
            Err(e) => {
                let _ = e.to_string();
            }
        }
    }
}

/// A fuzz target's body.
pub type Target = fn(&[u8]);

/// The values of command-line options that have their own small languages: `--set` parameter
/// lists and the other value parsers of `mechkit::values` (quantities, intervals, vectors), sweep ranges and grids, shards, sizes, data columns, restitutions, image channels,
/// force fields. Each line of the input is given to every parser.
pub fn options(data: &[u8]) {
    let Some(src) = text(data) else { return };
    let mut params = Vec::new();
    for line in src.lines().take(8) {
        if let Ok(p) = calculus::parse_params(line).map_err(|e| e.to_string()) {
            params = p;
        }
        match Parameter::parse(line) {
            Ok(p) => {
                let grid = SweepGrid::new(vec![p.clone(), p], Sampling::Grid);
                if grid.check().is_ok() {
                    let n = grid.len();
                    let _ = grid.point(n / 2);
                }
            }
            Err(e) => {
                let _ = e.to_string();
            }
        }
        if let Ok(shard) = Shard::parse(line).map_err(|e| e.to_string()) {
            let _ = shard.indices(1000);
        }
        let _ = parse_size(line).map(format_size);
        let _ = ColumnRef::parse(line).map_err(|e| e.to_string());
        let _ = Restitution::parse(line).map_err(|e| e.to_string());
        let _ = Channel::parse(line).map_err(|e| e.to_string());
        let components: Vec<&str> = line.split(';').collect();
        let _ = ForceField::parse(&components, &params).map_err(|e| e.to_string());
        // the library's value parsers (mechkit::values): every front reads values with them
        let _ = mechkit::values::value(line, "--x", &params).map_err(|e| e.to_string());
        let _ = mechkit::values::increasing_interval(line, "--range", &params)
            .map_err(|e| e.to_string());
        let _ = mechkit::values::vector(line, "--v", mechkit::units::Dimension::VELOCITY)
            .map_err(|e| e.to_string());
        let _ = mechkit::scenario::ConstantOverride::parse_list(line).map_err(|e| e.to_string());
        values(line, &params);
    }
}

/// The rest of `mechkit::values`, which the command line and the Python package read their
/// values with: a quantity of each dimension the commands ask for, an interval in either
/// order, pixels and pixel scales (`com --image`), an image coordinate with and without a
/// scale, a parameter list, and lists split outside brackets as vectors and `--at` lists are.
fn values(line: &str, params: &[(String, Real)]) {
    use mechkit::units::Dimension;
    use mechkit::values;
    for dim in [
        Dimension::NONE,
        Dimension::LENGTH,
        Dimension::MASS,
        Dimension::TIME,
        Dimension::VELOCITY,
        Dimension::FORCE,
    ] {
        let _ = values::quantity(line, "--q", dim).map_err(|e| e.to_string());
    }
    let _ = values::interval(line, "--in", params).map_err(|e| e.to_string());
    let _ = values::pixels(line, "--at").map_err(|e| e.to_string());
    let _ = values::pixel_scale(line, "--scale").map_err(|e| e.to_string());
    for scaled in [false, true] {
        let _ =
            values::image_coordinate(line, "--about", scaled, "--scale").map_err(|e| e.to_string());
    }
    let _ = values::params(line).map_err(|e| e.to_string());
    for sep in [',', ';', ':'] {
        for item in values::split_top_level(line, sep) {
            let _ = values::value(item, "--at", params).map_err(|e| e.to_string());
        }
    }
}

/// A whole `mechkit` command line, run in-process in a private working directory: see
/// [`command_line`](mod@command_line).
///
/// # Panics
/// When the working directory cannot be made, or the command panics.
pub fn command_line(data: &[u8]) {
    static WORKDIR: OnceLock<command_line::Workdir> = OnceLock::new();
    let workdir = WORKDIR.get_or_init(|| {
        // as in the `mechkit` binary, whose Rust runtime ignores SIGPIPE: a write to a closed
        // pipe is an error the command reports, not the end of the process (libFuzzer's
        // `main` leaves SIGPIPE at its default, and the CI smoke was killed by it)
        let _ = signal_hook::flag::register(
            signal_hook::consts::SIGPIPE,
            std::sync::Arc::new(std::sync::atomic::AtomicBool::new(false)),
        );
        command_line::Workdir::enter().expect("a working directory for the commands")
    });
    let _ = command_line::run_in(workdir, data);
}

/// A request to `mechkit serve`'s routes: see [`browser`](mod@browser).
///
/// # Panics
/// When the workspace cannot be made, or a check of [`browser`](mod@browser) fails.
pub fn browser(data: &[u8]) {
    static SITE: OnceLock<browser::Site> = OnceLock::new();
    SITE.get_or_init(|| browser::Site::new().expect("a workspace for the server"))
        .request(data);
}

pub use python_front::python_front;

/// The targets by name, as the fuzz binaries and the replay test know them.
pub const TARGETS: &[(&str, Target)] = &[
    ("command_line", command_line),
    ("browser", browser),
    ("python_front", python_front),
    ("expression", expression),
    ("calculus", calculus),
    ("units", units),
    ("scenario", scenario),
    ("data_file", data_file),
    ("image", image),
    ("options", options),
];

//! The `python_front` target: what the Python package (`crates/mechkit-py`) hands the library
//! from keyword arguments, without Python.
//!
//! The package converts Python values and calls shared library functions; the conversions
//! are its own (pyo3), the calls are these:
//! - `mechkit.md(**kw)` (`batch/md_options.rs`, `batch/md_run.rs`): the keywords fill an
//!   [`MdOptions`] (floats as Python gives them, `nan` and `inf` included; `positions`,
//!   `velocities` as `(N, d)` arrays; `box` as one length or one per axis), checked by the
//!   package's rules, then `plan`, `Potential::from_options`, `Setup::from_options`,
//!   `Md::new`, `run_observed`, `report` and `radial_distribution`;
//! - `mechkit.run(file, **constants)` (`scenario.rs`): a string is read as `--set
//!   NAME=TEXT` by [`ConstantOverride::parse_list`], a float is SI; then
//!   [`Scenario::from_str_with`] and the run.
//!
//! The package's other value conversions call `mechkit::values` (`quantity`, `value`,
//! `vector`, `increasing_interval`, `pixels`, `pixel_scale`, `image_coordinate`,
//! `split_top_level`), which the `options` target fuzzes, and the calculus, data-file and
//! image functions of the `expression`, `calculus`, `data_file` and `image` targets.
//!
//! The input is lines of `key=value`: an `md` keyword (a line `md` alone, or none, runs it), or
//! `set NAME=TEXT` and `num NAME=NUMBER` for a run of [`SCENARIO`]. Steps are at most
//! [`crate::SCENARIO_STEPS`] and cells at most 4, as in the other targets.

use std::convert::Infallible;

use mechkit::md::{
    Atoms, AtomsFile, Md, MdConfig, MdObserver, MdOptions, PairPotential, Potential, RDF_BINS,
    RunPlan, Setup, WithPotential,
};
use mechkit::scenario::{ConstantOverride, Scenario};
use mechkit::simulate::Cancel;

/// The scenario `set` and `num` lines give constants to: a spring with a dashpot and a
/// thrown mass under gravity, with the constants the overrides name.
pub const SCENARIO: &str = r#"title = "python front"
dimensions = 2
[constants]
k = "40 N/m"
c = "0.5 kg/s"
m0 = "2 kg"
v0 = "3 m/s"
th = "pi/4"
g = "9.8 m/s^2"
[[body]]
name = "ball"
mass = "m0"
position = ["0 m", "1 m"]
velocity = ["v0*cos(th)", "v0*sin(th)"]
[[force]]
name = "gravity"
kind = "uniform-gravity"
g = "g"
[[force]]
name = "spring"
kind = "expression"
on = "ball"
F = ["-k*x - c*vx", "-k*(y-1) - c*vy"]
[integrator]
method = "dopri5"
rtol = 1e-6
[stop]
when = "y < 0"
t_max = "2 s"
[observe]
y_max = "max(y)"
"#;

/// Runs one input; see the module's documentation.
pub fn python_front(data: &[u8]) {
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    let mut md = MdOptions {
        cells: 2,
        steps: 20,
        ..MdOptions::default()
    };
    let mut md_given = false;
    let mut constants = Vec::new();
    for line in text.lines().take(32) {
        if let Some(rest) = line.strip_prefix("set ") {
            let (name, value) = rest.split_once('=').unwrap_or((rest, ""));
            // `parse_override`: one value for the name given
            match ConstantOverride::parse_list(&format!("{name}={value}")) {
                Ok(mut parsed) => {
                    if let (Some(o), true) = (parsed.pop(), parsed.is_empty())
                        && o.name == name
                    {
                        constants.push(o);
                    }
                }
                Err(e) => {
                    let _ = e.to_string();
                }
            }
        } else if let Some(rest) = line.strip_prefix("num ") {
            let (name, value) = rest.split_once('=').unwrap_or((rest, ""));
            // a Python float: finite, or refused by the package
            if let Ok(value) = value.trim().parse::<f64>()
                && value.is_finite()
            {
                constants.push(ConstantOverride {
                    name: name.to_string(),
                    value,
                    dim: None,
                });
            }
        } else if line == "md" {
            md_given = true;
        } else if let Some((key, value)) = line.split_once('=') {
            if set(&mut md, key.trim(), value.trim()).is_err() {
                return;
            }
            md_given = true;
        }
    }
    if !constants.is_empty() {
        run_scenario(&constants);
    }
    if md_given || constants.is_empty() {
        run_md(&md);
    }
}

/// [`SCENARIO`] with `constants`, run for at most [`crate::SCENARIO_STEPS`] steps.
fn run_scenario(constants: &[ConstantOverride]) {
    match Scenario::from_str_with("python.toml", SCENARIO, constants) {
        Ok(mut s) => {
            s.max_steps = Some(
                s.max_steps
                    .map_or(crate::SCENARIO_STEPS, |n| n.min(crate::SCENARIO_STEPS)),
            );
            s.max_output = s.max_output.min(crate::SCENARIO_OUTPUT);
            let _ = s.run().map_err(|e| e.to_string());
        }
        Err(e) => {
            let _ = e.to_string();
        }
    }
}

/// One keyword of `mechkit.md`, as the package converts it; `Err` where the package raises
/// (a value of the wrong type). Counts are clamped for time.
fn set(o: &mut MdOptions, key: &str, value: &str) -> Result<(), ()> {
    let number = || value.parse::<f64>().map_err(|_| ());
    let count = || value.parse::<usize>().map_err(|_| ());
    match key {
        "lattice" => o.lattice = value.to_string(),
        "cells" => o.cells = count()?.min(4),
        "density" => o.density = number()?,
        "temperature" => o.temperature = Some(number()?),
        "positions" => o.positions = Some(atoms(value)?),
        "velocities" => o.velocities = Some(atoms(value)?),
        "box" => {
            o.box_lengths = value
                .split(',')
                .map(|x| x.trim().parse::<f64>().map_err(|_| ()))
                .collect::<Result<_, _>>()?;
        }
        "boundary" => o.boundary = Some(value.to_string()),
        "potential" => o.potential = value.to_string(),
        "epsilon" => o.epsilon = number()?,
        "sigma" => o.sigma = number()?,
        "k" => o.k = number()?,
        "rest_length" => o.rest_length = number()?,
        "mass" => o.mass = number()?,
        "seed" => o.seed = value.parse().map_err(|_| ())?,
        "steps" => o.steps = count()?.min(crate::SCENARIO_STEPS as usize),
        "dt" => o.dt = number()?,
        "cutoff" => o.cutoff = number()?,
        "shift" => o.shift = value == "True",
        "skin" => o.skin = number()?,
        "threads" => o.threads = count()?.min(2),
        "thermo_every" => o.thermo_every = count()?,
        "xyz_every" => o.xyz_every = Some(count()?),
        _ => return Err(()),
    }
    Ok(())
}

/// An `(N, d)` array written as rows `x,y,z` separated by `;`, with the package's checks:
/// d of 1, 2 or 3, the same for every row, at least one row, every number finite.
fn atoms(value: &str) -> Result<Atoms, ()> {
    let mut vectors = Vec::new();
    let mut dim = None;
    for row in value.split(';') {
        let numbers = row
            .split(',')
            .map(|x| x.trim().parse::<f64>().map_err(|_| ()))
            .collect::<Result<Vec<_>, _>>()?;
        if *dim.get_or_insert(numbers.len()) != numbers.len()
            || !(1..=3).contains(&numbers.len())
            || numbers.iter().any(|x| !x.is_finite())
        {
            return Err(());
        }
        let mut vector = [0.0; 3];
        vector[..numbers.len()].copy_from_slice(&numbers);
        vectors.push(vector);
    }
    Ok(Atoms {
        atoms: AtomsFile {
            dim: dim.ok_or(())?,
            vectors,
        },
        path: None,
    })
}

/// `mechkit.md`'s run (`batch/md_run.rs`), after the package's rules between keywords.
fn run_md(o: &MdOptions) {
    let given = o.velocities.is_some() || !o.box_lengths.is_empty() || o.boundary.is_some();
    if (given && o.positions.is_none()) || (o.temperature.is_some() && o.velocities.is_some()) {
        return;
    }
    let plan = match o.plan() {
        Ok(p) => p,
        Err(e) => {
            let _ = e.message(|_| "option");
            return;
        }
    };
    let potential = match Potential::from_options(o) {
        Ok(p) => p,
        Err(e) => {
            let _ = e.message(|_| "option");
            return;
        }
    };
    let setup = match Setup::from_options(o, potential.cutoff()) {
        Ok(s) => s,
        Err(e) => {
            let _ = e.message(|_| "option");
            return;
        }
    };
    potential.apply(Runner {
        options: o,
        plan: &plan,
        setup,
    });
}

struct Runner<'a> {
    options: &'a MdOptions,
    plan: &'a RunPlan,
    setup: Setup,
}

/// Counts the frames, as the package's observer keeps them.
struct Frames(usize);

impl<P: PairPotential> MdObserver<P> for Frames {
    type Error = Infallible;

    fn frame(&mut self, _md: &Md<P>) -> Result<(), Infallible> {
        self.0 += 1;
        Ok(())
    }
}

impl WithPotential for Runner<'_> {
    type Output = ();

    fn call<P: PairPotential>(self, potential: P) {
        let Self {
            options: o,
            plan,
            setup: s,
        } = self;
        let cutoff = potential.cutoff();
        let mut md = match Md::new(s.sim_box, potential, s.x, s.v, MdConfig::from(o)) {
            Ok(md) => md,
            Err(e) => {
                let _ = e.to_string();
                return;
            }
        };
        let Ok(run) = md.run_observed(plan, &Cancel::new(), &mut Frames(0));
        let _ = md.report(&run, &s.origin, &o.potential);
        let _ = md.radial_distribution(RDF_BINS, cutoff + o.skin);
    }
}

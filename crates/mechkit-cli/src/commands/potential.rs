//! `mechkit potential`: the force from a potential (or the potential from a force), the
//! equilibria with their stability, turning points for an energy, and the energy diagram
//! (`mechkit::energy::analyse_potential`); in 2-D and 3-D the force `F = -∇U`
//! (`mechkit::energy::potential_field`).

use std::fmt::Write as _;
use std::path::Path;

use anyhow::{Result, anyhow, bail};
use mechkit::calculus::CalculusError;
use mechkit::energy::{
    AxisUnits, Bound, FieldForce, Given, Motion, Origin, PotentialAnalysis, PotentialQuestion,
    Release, analyse_potential, potential_field,
};
use mechkit::expr::units::{Dimension, Quantity};
use mechkit::inputs::Input;

use super::input::{fixed, increasing_interval, params, quantity, show, split_top_level, value};
use super::outputs::{create_dir, write_plots, write_table};
use super::{Outcome, note, report};
use crate::args::PotentialArgs;

/// The flag of an input of `potential`.
fn flag(input: Input) -> &'static str {
    match input {
        Input::Range => "--range",
        Input::Samples => "--samples",
        Input::Energy => "--energy",
        Input::Mass => "--mass",
        Input::StartPosition => "--x0",
        Input::StartSpeed => "--v0",
        Input::At => "--at",
        Input::Variable => "--var",
        Input::Force => "--force",
        Input::Params => "--set",
        _ => "the potential",
    }
}

fn check<T>(r: Result<T, CalculusError>) -> Result<T> {
    r.map_err(|e| match e {
        CalculusError::Input(e) => anyhow!("{}: {}", flag(e.input), e.message),
        other => anyhow!("{other}"),
    })
}

pub fn potential(args: &PotentialArgs) -> Result<Outcome> {
    let p = params(args.set.as_deref())?;
    if args.var.contains(',') {
        return gradient(args, &p);
    }
    let Some(range) = &args.range else {
        bail!("give the range to analyse, e.g. --range 0.8:3 or --range -1:2");
    };
    let (a, b) = increasing_interval(range, "--range", &p)?;
    let given = match (&args.potential, &args.force) {
        (Some(u), None) => Given::Potential(u),
        (None, Some(f)) => Given::Force(f),
        (Some(_), Some(_)) => bail!("give either a potential U or --force F, not both"),
        (None, None) => bail!(
            "give a potential, e.g. mechkit potential \"k*x^2/2\" --range -1:1 --set k=1, or a force with --force"
        ),
    };
    let release = match (&args.mass, &args.x0, &args.v0) {
        (None, None, None) => None,
        (Some(m), Some(x0), v0) => {
            if args.energy.is_some() {
                bail!("--energy and --mass/--x0/--v0 both set the energy: give one of them");
            }
            Some(Release {
                mass: quantity(m, "--mass", Dimension::MASS)?,
                x0: value(x0, "--x0", &p)?,
                v0: v0.as_deref().map_or(Ok(0.0), |v| value(v, "--v0", &p))?,
            })
        }
        _ => bail!("the motion needs --mass and --x0 (and --v0, default 0)"),
    };
    let at = match &args.at {
        Some(list) => split_top_level(list, ',')
            .into_iter()
            .map(|v| value(v, "--at", &p))
            .collect::<Result<_>>()?,
        None => Vec::new(),
    };
    let question = PotentialQuestion {
        given,
        var: &args.var,
        range: (a, b),
        params: &p,
        energy: args
            .energy
            .as_deref()
            .map(|e| value(e, "--energy", &p))
            .transpose()?,
        release,
        at,
        samples: args.samples,
        units: axis_units(args, given),
    };
    let mut analysis = check(analyse_potential(&question))?;
    if let Some(dir) = &args.out {
        write_files(args, dir, &mut analysis)?;
    }
    report(args.report, &analysis, || text(&analysis))?;
    Ok(Outcome::Success)
}

/// The units of the axes: what the range and the `--set` values were given in (a bare number
/// has no unit we know).
fn axis_units(args: &PotentialArgs, given: Given<'_>) -> AxisUnits {
    let dim = |text: &str| {
        Quantity::parse(text.trim())
            .ok()
            .map(|q| q.dim)
            .filter(|d| !d.is_none())
    };
    let range_dim = args
        .range
        .as_deref()
        .and_then(|r| split_top_level(r, ':').into_iter().find_map(dim));
    let set: Vec<(String, Option<Dimension>)> = args
        .set
        .as_deref()
        .map(|s| {
            split_top_level(s, ',')
                .into_iter()
                .filter_map(|item| item.split_once('='))
                .map(|(k, v)| (k.trim().to_string(), dim(v)))
                .collect()
        })
        .unwrap_or_default();
    let dims = |name: &str| {
        if name == args.var {
            return range_dim;
        }
        set.iter().find(|(k, _)| k == name).and_then(|(_, d)| *d)
    };
    AxisUnits::infer(given, &args.var, &dims)
}

/// With `-o DIR`: the table, the diagram `U_x`, and the speed `v_x` with a released body.
fn write_files(args: &PotentialArgs, dir: &Path, a: &mut PotentialAnalysis) -> Result<()> {
    create_dir(dir)?;
    let csv = write_table(dir, "potential", &a.table())?;
    note(args.report, &format!("wrote {csv}"));
    a.csv = Some(csv);
    if args.no_plots {
        return Ok(());
    }
    let title = match (&args.potential, &args.force) {
        (Some(u), _) => format!("U = {u}"),
        (None, f) => format!("F = {}", f.as_deref().unwrap_or_default()),
    };
    let plots: Vec<_> = std::iter::once(a.diagram_plot())
        .chain(a.speed_plot())
        .collect();
    let mut paths = write_plots(dir, &plots, &title, args.plots)?.into_iter();
    a.plot = paths.next();
    a.speed_plot = paths.next();
    for path in a.plot.iter().chain(&a.speed_plot) {
        note(args.report, &format!("wrote {path}"));
    }
    Ok(())
}

/// `F = -∇U` of a potential of 2 or 3 coordinates.
fn gradient(args: &PotentialArgs, p: &[(String, f64)]) -> Result<Outcome> {
    let vars: Vec<&str> = args.var.split(',').map(str::trim).collect();
    let Some(u) = &args.potential else {
        bail!("a field from --force has no single formula to take the gradient of: give U(x, y)");
    };
    let points: Vec<Vec<f64>> = match &args.at {
        Some(list) => split_top_level(list, ';')
            .into_iter()
            .map(|pt| {
                split_top_level(pt, ',')
                    .into_iter()
                    .map(|v| value(v, "--at", p))
                    .collect::<Result<Vec<f64>>>()
            })
            .collect::<Result<_>>()?,
        None => Vec::new(),
    };
    let field = check(potential_field(u, &vars, p, &points))?;
    report(args.report, &field, || gradient_text(&field))?;
    Ok(Outcome::Success)
}

fn gradient_text(f: &FieldForce) -> String {
    let components: Vec<String> = f.force.iter().map(ToString::to_string).collect();
    let mut out = format!(
        "U = {}\nF = -∇U = ({})\n",
        f.potential,
        components.join(", ")
    );
    for point in &f.at {
        let _ = writeln!(out, "at ({}): F = ({})", join(&point.r), join(&point.force));
    }
    out
}

fn text(a: &PotentialAnalysis) -> String {
    let x = &a.var;
    let short = mechkit::expr::short_number;
    let (lo, hi) = (short(a.range.0), short(a.range.1));
    let mut out = String::new();
    match &a.potential {
        Some(u) if a.potential_origin == Origin::Given => {
            let _ = writeln!(out, "U({x}) = {u}");
        }
        Some(u) => {
            let _ = writeln!(out, "U({x}) = {u}   (= -∫F d{x}, symbolic)");
        }
        None => {
            let _ = writeln!(
                out,
                "U({x}) = -∫F d{x}: no closed form, computed by quadrature with U({lo}) = 0"
            );
        }
    }
    let _ = writeln!(out, "F({x}) = {}", a.force);
    let _ = writeln!(out, "U''({x}) = {}", a.curvature);
    if a.equilibria.is_empty() {
        let _ = writeln!(out, "no equilibrium (F = 0) for {x} in [{lo}, {hi}]");
    } else {
        let _ = writeln!(out, "equilibria in [{lo}, {hi}]:");
        for e in &a.equilibria {
            let _ = write!(
                out,
                "  {x} = {:<22} {:<9} U = {:<12} U'' = {}",
                short(e.x),
                e.stability.name(),
                fixed(e.potential, 6),
                fixed(e.curvature, 6)
            );
            if let Some(h) = e.barrier {
                let _ = write!(out, "   barrier {}", fixed(h, 6));
            }
            out.push('\n');
        }
    }
    for s in &a.singularities {
        let _ = writeln!(
            out,
            "singular near {x} = {}: U or F is infinite or undefined there",
            short(*s)
        );
    }
    if let Some(c) = &a.energy {
        let _ = writeln!(out, "with E = {}:", short(c.energy));
        if c.turning_points.is_empty() {
            let _ = writeln!(out, "  no turning point in [{lo}, {hi}]");
        } else {
            let list: Vec<String> = c.turning_points.iter().map(|t| short(*t)).collect();
            let _ = writeln!(out, "  turning points {x} = {}", list.join(", "));
        }
        for r in &c.regions {
            let _ = writeln!(
                out,
                "  [{}, {}] {}",
                short(r.from),
                short(r.to),
                if r.allowed { "allowed" } else { "forbidden" }
            );
        }
    }
    if let Some(m) = &a.motion {
        out.push_str(&motion_text(a, m));
    }
    for v in &a.at {
        let _ = write!(
            out,
            "at {x} = {}: U = {}, F = {}",
            show(v.x),
            v.potential.map_or_else(|| "undefined".into(), show),
            v.force.map_or_else(|| "undefined".into(), show),
        );
        if a.motion.is_some() {
            let speed = v
                .speed
                .map_or_else(|| "none (U > E: it cannot get there)".into(), show);
            let _ = write!(out, ", v = {speed}");
        }
        out.push('\n');
    }
    out
}

/// Where the released body goes, in words: its turning points, or where it leaves the range
/// or meets a singular point, and in which direction.
fn motion_text(a: &PotentialAnalysis, m: &Motion) -> String {
    let x = &a.var;
    let mut out = format!(
        "released at {x} = {} with velocity {} (m = {}): E = {}\n",
        show(m.x0),
        show(m.v0),
        show(m.mass),
        show(m.energy)
    );
    let end = |b: Bound, side: &str| match b {
        Bound::TurningPoint { x: t } => format!("turns at {x} = {} ({side})", show(t)),
        Bound::SingularPoint { x: s } => format!(
            "reaches the singular point at {x} = {} ({side}), where U or F is infinite",
            show(s)
        ),
        _ => format!("leaves the range at {x} = {} moving {side}", show(b.x())),
    };
    let turns = |b: Bound| matches!(b, Bound::TurningPoint { .. });
    let sentence = match (turns(m.left), turns(m.right)) {
        (true, true) => format!(
            "  turns at {x} = {} (left) and {x} = {} (right): it oscillates between them\n",
            show(m.left.x()),
            show(m.right.x())
        ),
        (true, false) => format!(
            "  {}, then {}\n",
            end(m.left, "left"),
            end(m.right, "right")
        ),
        (false, true) => format!(
            "  {}, then {}\n",
            end(m.right, "right"),
            end(m.left, "left")
        ),
        (false, false) => {
            // no turning point: the body keeps the direction it starts with
            let right = m.moves_right_first(&a.model);
            let (lo, hi) = (
                mechkit::expr::short_number(m.left.x()),
                mechkit::expr::short_number(m.right.x()),
            );
            let (bound, side) = if right {
                (m.right, "right")
            } else {
                (m.left, "left")
            };
            format!(
                "  no turning point in [{lo}, {hi}]: the body {}\n",
                end(bound, side)
            )
        }
    };
    out.push_str(&sentence);
    out
}

/// Coordinates for the terminal: `1, 2.5` (not the `Debug` form `[1.0, 2.5]`).
fn join(v: &[f64]) -> String {
    let parts: Vec<String> = v.iter().map(|x| show(*x)).collect();
    parts.join(", ")
}

//! `mechkit potential`: the force from a potential (or the potential from a force), the
//! equilibria with their stability, turning points for an energy, and the energy diagram.

use std::fmt::Write as _;
use std::path::PathBuf;

use anyhow::{Result, anyhow, bail};
use mechkit::energy::{Diagram, ForceField, Motion, Origin, Potential, Stability};
use mechkit::expr::units::Dimension;
use mechkit::figure::{Band, LineStyle, Marker, MarkerShape, PlotData, Series};
use serde_json::{Value, json};

use super::input::{increasing_interval, params, quantity, show, split_top_level, value};
use super::{Outcome, print};
use crate::args::PotentialArgs;
use crate::plot::render;

pub fn potential(args: &PotentialArgs) -> Result<Outcome> {
    let p = params(args.set.as_deref())?;
    if args.var.contains(',') {
        return gradient(args, &p);
    }
    let Some(range) = &args.range else {
        bail!("give the range to analyse, e.g. --range 0.8:3 or --range -1:2");
    };
    let (a, b) = increasing_interval(range, "--range", &p)?;
    if !(a.is_finite() && b.is_finite()) {
        bail!(
            "--range {range}: a diagram samples its range, so both ends must be finite (for the speed far away use a large end, e.g. --range 0.01:1e9, or --at 1e15)"
        );
    }
    let (a, b) = (a.min(b), a.max(b));
    let x = args.var.as_str();
    let pot = match (&args.potential, &args.force) {
        (Some(u), None) => Potential::from_potential(u, x, &p),
        (None, Some(f)) => Potential::from_force(f, x, &p, a),
        (Some(_), Some(_)) => bail!("give either a potential U or --force F, not both"),
        (None, None) => bail!(
            "give a potential, e.g. mechkit potential \"k*x^2/2\" --range -1:1 --set k=1, or a force with --force"
        ),
    }
    .map_err(|e| anyhow!("{e}"))?;
    let samples = args.samples.max(10);
    let motion = match (&args.mass, &args.x0, &args.v0) {
        (None, None, None) => None,
        (Some(m), Some(x0), v0) => {
            if args.energy.is_some() {
                bail!("--energy and --mass/--x0/--v0 both set the energy: give one of them");
            }
            let m = quantity(m, "--mass", Dimension::MASS)?;
            if m.is_nan() || m <= 0.0 {
                bail!("--mass must be positive, not {m}");
            }
            let x0 = value(x0, "--x0", &p)?;
            if !(a..=b).contains(&x0) {
                bail!("--x0 {x0} is outside --range {a}:{b}");
            }
            let v0 = v0.as_deref().map_or(Ok(0.0), |v| value(v, "--v0", &p))?;
            Some(pot.motion(m, x0, v0.abs(), a, b, samples))
        }
        _ => bail!("the motion needs --mass and --x0 (and --v0, default 0)"),
    };
    let energy = args
        .energy
        .as_deref()
        .map(|e| value(e, "--energy", &p))
        .transpose()?;
    let diagram = match &motion {
        Some(m) => m.diagram.clone(),
        None => pot.diagram(a, b, energy, samples),
    };
    let at: Vec<f64> = match &args.at {
        Some(list) => split_top_level(list, ',')
            .into_iter()
            .map(|v| value(v, "--at", &p))
            .collect::<Result<_>>()?,
        None => Vec::new(),
    };
    let plot_path = if args.no_plot {
        None
    } else {
        let path = args
            .plot
            .clone()
            .unwrap_or_else(|| PathBuf::from("out/energy_diagram.svg"));
        if let Some(dir) = path.parent().filter(|d| !d.as_os_str().is_empty()) {
            std::fs::create_dir_all(dir)
                .map_err(|e| anyhow!("cannot create {}: {e}", dir.display()))?;
        }
        let title = args.potential.as_deref().map_or_else(
            || format!("F = {}", args.force.as_deref().unwrap_or_default()),
            |u| format!("U = {u}"),
        );
        render(&figure(&diagram, x), &title, &path, args.dpi)?;
        if let Some(m) = &motion {
            let speed = speed_figure(m, x);
            // next to the diagram, in its format
            let ext = path.extension().map_or_else(
                || "svg".into(),
                |e| e.to_string_lossy().to_ascii_lowercase(),
            );
            let ext = if ext == "png" { "png" } else { "svg" };
            let speed_path = path.with_file_name(format!("{}_speed.{ext}", stem(&path)));
            render(&speed, &title, &speed_path, args.dpi)?;
        }
        Some(path)
    };
    let points: Vec<Value> = at
        .iter()
        .map(|&v| {
            json!({
                "x": v,
                "potential": finite(pot.potential(v)),
                "force": finite(pot.force(v)),
                "speed": motion.as_ref().map(|m| finite(m.speed_at(&pot, v))),
            })
        })
        .collect();
    if args.json {
        // the positions of each kind, for a reader that wants the stable ones only
        let by_stability: serde_json::Map<String, serde_json::Value> =
            ["stable", "unstable", "neutral"]
                .into_iter()
                .map(|kind| {
                    let xs: Vec<f64> = diagram
                        .equilibria
                        .iter()
                        .filter(|e| e.stability.name() == kind)
                        .map(|e| e.x)
                        .collect();
                    (kind.to_string(), json!(xs))
                })
                .collect();
        let j = json!({
            "var": x,
            "range": [a, b],
            "parameters": p.iter().map(|(k, v)| (k.clone(), json!(v))).collect::<serde_json::Map<_, _>>(),
            "potential": pot.potential_formula().map(ToString::to_string),
            "potential_origin": origin_name(pot.origin()),
            "force": pot.force_formula().to_string(),
            "curvature": pot.curvature_formula().to_string(),
            "equilibria": diagram.equilibria.iter().map(|e| json!({
                "x": e.x, "potential": e.potential, "curvature": e.curvature,
                "stability": e.stability.name(), "barrier": e.barrier,
            })).collect::<Vec<_>>(),
            "by_stability": by_stability,
            "singularities": diagram.singularities,
            "energy": diagram.energy.as_ref().map(|c| json!({
                "value": c.energy,
                "turning_points": c.turning_points,
                "regions": c.regions.iter().map(|r| json!({"from": r.from, "to": r.to, "allowed": r.allowed})).collect::<Vec<_>>(),
            })),
            "motion": motion.as_ref().map(|m| json!({
                "mass": m.mass, "x0": m.x0, "v0": m.v0, "energy": m.energy,
                "left_turn": m.left_turn, "right_turn": m.right_turn,
            })),
            "at": points,
            "plot": plot_path.as_ref().map(|p| p.display().to_string()),
        });
        print(&format!("{j:#}\n"))?;
    } else {
        print(&text(
            &pot,
            &diagram,
            motion.as_ref(),
            &at,
            x,
            (a, b),
            plot_path.as_ref(),
        ))?;
    }
    Ok(Outcome::Success)
}

/// `F = -∇U` of a potential of 2 or 3 coordinates.
fn gradient(args: &PotentialArgs, p: &[(String, f64)]) -> Result<Outcome> {
    let vars: Vec<&str> = args.var.split(',').map(str::trim).collect();
    let expected = &["x", "y", "z"][..vars.len().min(3)];
    if vars.len() > 3 || vars != expected {
        bail!(
            "--var for a potential field is x,y or x,y,z, not `{}`",
            args.var
        );
    }
    let Some(u) = &args.potential else {
        bail!("a field from --force has no single formula to take the gradient of: give U(x, y)");
    };
    let field = ForceField::from_potential(u, vars.len(), p).map_err(|e| anyhow!("{e}"))?;
    let components: Vec<String> = field.formulas().iter().map(ToString::to_string).collect();
    let points: Vec<Vec<f64>> = match &args.at {
        Some(list) => split_top_level(list, ';')
            .into_iter()
            .map(|pt| {
                let c = split_top_level(pt, ',')
                    .into_iter()
                    .map(|v| value(v, "--at", p))
                    .collect::<Result<Vec<f64>>>()?;
                if c.len() == vars.len() {
                    Ok(c)
                } else {
                    bail!("--at `{pt}`: a point needs {} coordinates", vars.len())
                }
            })
            .collect::<Result<_>>()?,
        None => Vec::new(),
    };
    let forces: Vec<Vec<f64>> = points
        .iter()
        .map(|r| {
            let mut f = vec![0.0; vars.len()];
            field.at(r, &mut f);
            // -0.0 prints as 0
            f.iter().map(|v| v + 0.0).collect()
        })
        .collect();
    if args.json {
        let j = json!({
            "potential": u,
            "vars": vars,
            "force": components,
            "at": points.iter().zip(&forces).map(|(r, f)| json!({"r": r, "force": f})).collect::<Vec<_>>(),
        });
        print(&format!("{j:#}\n"))?;
    } else {
        let mut out = format!("U = {u}\nF = -∇U = ({})\n", components.join(", "));
        for (r, f) in points.iter().zip(&forces) {
            let _ = writeln!(out, "at ({}): F = ({})", join(r), join(f));
        }
        print(&out)?;
    }
    Ok(Outcome::Success)
}

fn finite(v: f64) -> Option<f64> {
    v.is_finite().then_some(v)
}

fn stem(path: &std::path::Path) -> String {
    path.file_stem().map_or_else(
        || "energy_diagram".into(),
        |s| s.to_string_lossy().into_owned(),
    )
}

fn origin_name(o: Origin) -> &'static str {
    match o {
        Origin::Given => "given",
        Origin::Symbolic => "symbolic integral of the force",
        _ => "numeric integral of the force (U = 0 at the range start)",
    }
}

fn text(
    pot: &Potential,
    d: &Diagram,
    motion: Option<&Motion>,
    at: &[f64],
    x: &str,
    (a, b): (f64, f64),
    plot: Option<&PathBuf>,
) -> String {
    let mut out = String::new();
    match pot.potential_formula() {
        Some(u) if pot.origin() == Origin::Given => {
            let _ = writeln!(out, "U({x}) = {u}");
        }
        Some(u) => {
            let _ = writeln!(out, "U({x}) = {u}   (= -∫F d{x}, symbolic)");
        }
        None => {
            let _ = writeln!(
                out,
                "U({x}) = -∫F d{x}: no closed form, computed by quadrature with U({a}) = 0"
            );
        }
    }
    let _ = writeln!(out, "F({x}) = {}", pot.force_formula());
    let _ = writeln!(out, "U''({x}) = {}", pot.curvature_formula());
    if d.equilibria.is_empty() {
        let _ = writeln!(out, "no equilibrium (F = 0) for {x} in [{a}, {b}]");
    } else {
        let _ = writeln!(out, "equilibria in [{a}, {b}]:");
        for e in &d.equilibria {
            let _ = write!(
                out,
                "  {x} = {:<22} {:<9} U = {:<12.6} U'' = {:.6}",
                e.x,
                e.stability.name(),
                e.potential,
                e.curvature
            );
            if let Some(h) = e.barrier {
                let _ = write!(out, "   barrier {h:.6}");
            }
            out.push('\n');
        }
    }
    for s in &d.singularities {
        let _ = writeln!(
            out,
            "singular near {x} = {s}: U or F is infinite or undefined there"
        );
    }
    if let Some(c) = &d.energy {
        let _ = writeln!(out, "with E = {}:", c.energy);
        if c.turning_points.is_empty() {
            let _ = writeln!(out, "  no turning point in the range");
        } else {
            let list: Vec<String> = c.turning_points.iter().map(|t| format!("{t}")).collect();
            let _ = writeln!(out, "  turning points {x} = {}", list.join(", "));
        }
        for r in &c.regions {
            let _ = writeln!(
                out,
                "  [{}, {}] {}",
                r.from,
                r.to,
                if r.allowed { "allowed" } else { "forbidden" }
            );
        }
    }
    if let Some(m) = motion {
        let side = |t: Option<f64>, edge: &str| {
            t.map_or_else(
                || format!("none inside the range (reaches {edge})"),
                |v| v.to_string(),
            )
        };
        let _ = writeln!(
            out,
            "released at {x} = {} with speed {} (m = {}): E = {}\n  turns at {} (below) and {} (above)",
            m.x0,
            m.v0,
            m.mass,
            m.energy,
            side(m.left_turn, "the range start or a singular point"),
            side(m.right_turn, "the range end or a singular point"),
        );
    }
    for &v in at {
        let _ = write!(
            out,
            "at {x} = {}: U = {}, F = {}",
            show(v),
            show(pot.potential(v)),
            show(pot.force(v))
        );
        if let Some(m) = motion {
            let _ = write!(out, ", v = {}", show(m.speed_at(pot, v)));
        }
        out.push('\n');
    }
    if let Some(p) = plot {
        let _ = writeln!(out, "energy diagram: {}", p.display());
    }
    out
}

/// U(x) with the energy line, equilibria, turning points, forbidden regions and singular
/// points, on a vertical range that shows the wells rather than a divergence at the edge.
fn figure(d: &Diagram, x: &str) -> PlotData {
    // a NaN at each singular point breaks the curve there
    let mut curve: Vec<(f64, f64)> =
        d.x.iter()
            .copied()
            .zip(d.potential.iter().copied())
            .collect();
    for &s in &d.singularities {
        let k = curve.partition_point(|p| p.0 < s);
        curve.insert(k, (s, f64::NAN));
    }
    let mut plot = PlotData::new("energy diagram", "energy_diagram", x.to_string(), "U [J]")
        .with_series(Series::line(format!("U({x})"), curve));
    let (lo, hi) = (d.x[0], d.x[d.x.len() - 1]);
    for e in &d.equilibria {
        let (shape, label) = match e.stability {
            Stability::Stable => (MarkerShape::Filled, "stable equilibrium"),
            Stability::Unstable => (MarkerShape::Open, "unstable equilibrium"),
            _ => (MarkerShape::Cross, "neutral equilibrium"),
        };
        plot.markers.push(Marker {
            at: (e.x, e.potential),
            label: label.into(),
            shape,
        });
    }
    let mut core: Vec<f64> = d.equilibria.iter().map(|e| e.potential).collect();
    if let Some(c) = &d.energy {
        plot.series.push(
            Series::line(
                format!("E = {:.6}", c.energy),
                vec![(lo, c.energy), (hi, c.energy)],
            )
            .styled(LineStyle::Dashed),
        );
        for &t in &c.turning_points {
            plot.markers.push(Marker {
                at: (t, c.energy),
                label: "turning point".into(),
                shape: MarkerShape::Triangle,
            });
        }
        for r in c.regions.iter().filter(|r| !r.allowed) {
            plot.bands.push(Band {
                from: r.from,
                to: r.to,
                label: "forbidden (U > E)".into(),
            });
        }
        core.push(c.energy);
    }
    plot.y_limits = y_limits(&d.potential, &core);
    if let Some((y0, _)) = plot.y_limits {
        for &s in &d.singularities {
            plot.markers.push(Marker {
                at: (s, y0),
                label: "singular point".into(),
                shape: MarkerShape::Cross,
            });
        }
    }
    plot
}

/// The vertical range: the equilibria and the energy line, and the bulk of the curve (its 5th
/// to 95th percentile), so that a curve running off to infinity (a 1/r^12 wall, a pole) is cut
/// instead of flattening the wells.
fn y_limits(u: &[f64], core: &[f64]) -> Option<(f64, f64)> {
    let mut finite: Vec<f64> = u.iter().copied().filter(|v| v.is_finite()).collect();
    if finite.is_empty() {
        return None;
    }
    finite.sort_by(f64::total_cmp);
    let pick = |q: f64| finite[((finite.len() - 1) as f64 * q).round() as usize];
    let (umin, umax) = (finite[0], finite[finite.len() - 1]);
    let lo = core.iter().copied().fold(pick(0.05), f64::min);
    let hi = core.iter().copied().fold(pick(0.95), f64::max);
    let span = (hi - lo)
        .max(1e-12 * hi.abs().max(lo.abs()))
        .max(f64::MIN_POSITIVE);
    Some((
        (lo - 0.15 * span).max(umin - 0.05 * span),
        (hi + 0.15 * span).min(umax + 0.05 * span),
    ))
}

fn speed_figure(m: &Motion, x: &str) -> PlotData {
    PlotData::new(
        format!("speed from the work-energy theorem, m = {}", m.mass),
        "speed",
        x.to_string(),
        "v [m/s]",
    )
    .with_series(Series::line(
        format!("v({x})"),
        m.diagram
            .x
            .iter()
            .copied()
            .zip(m.speed.iter().copied())
            .collect(),
    ))
}

/// Coordinates for the terminal: `1, 2.5` (not the `Debug` form `[1.0, 2.5]`).
fn join(v: &[f64]) -> String {
    let parts: Vec<String> = v.iter().map(ToString::to_string).collect();
    parts.join(", ")
}

//! Issue 23, `kind = "pair"`: a pair force given by its potential `U(r)`, the force `-dU/dr`
//! derived symbolically.
//!
//! Physics checked: a Lennard-Jones dimer released from rest at `r0` oscillates between the
//! two roots of `U(r) = U(r0)`, with the period of the quadrature
//! `T = 2 ∫ dr / sqrt(2 (U(r0) - U(r)) / μ)` and its energy conserved; a harmonic pair potential
//! is the spring of `kind = "spring"` in 1, 2 and 3 dimensions; three bodies interacting pairwise
//! (`between = "all"`) keep their momentum; a cut-off potential is shifted, so the energy is
//! conserved when a pair flies apart past it. Bad input is refused where it is written.

use mechkit::quad::{Tolerance, integrate};
use mechkit::roots::brent;
use mechkit::scenario::{ErrorKind, Scenario, ScenarioError, Summary};

fn run(text: &str) -> Summary {
    Scenario::from_str("pair.toml", text)
        .unwrap_or_else(|e| panic!("{e}"))
        .run()
        .unwrap()
        .summary
}

fn error(text: &str) -> ScenarioError {
    Scenario::from_str("pair.toml", text).expect_err("the scenario should be rejected")
}

fn lj(r: f64) -> f64 {
    4.0 * (r.powi(-12) - r.powi(-6))
}

/// The LJ dimer of `examples/md/lj_dimer.toml` (ε = σ = 1, unit masses, from rest at r0).
fn dimer(r0: f64, dims: usize) -> String {
    let zeros = |x: &str| {
        if dims == 1 {
            x.to_string()
        } else {
            let mut v = vec!["0.0"; dims];
            v[0] = x;
            format!("[{}]", v.join(", "))
        }
    };
    format!(
        r#"
dimensions = {dims}
[constants]
eps = 1.0
s   = 1.0
[[body]]
name = "a"
mass = 1.0
position = {}
velocity = {}
[[body]]
name = "b"
mass = 1.0
position = {}
velocity = {}
[[force]]
name = "lj"
kind = "pair"
between = ["a", "b"]
U = "4*eps*((s/r)^12 - (s/r)^6)"
[integrator]
method = "dop853"
rtol = 1e-12
atol = 1e-12
[stop]
t_max = 30.0
[[event]]
name = "inner"
function = "b.vx - a.vx"
direction = "rising"
[[event]]
name = "outer"
function = "b.vx - a.vx"
direction = "falling"
[observe]
r_min = "min(b.x - a.x)"
r_max = "max(b.x - a.x)"
"#,
        zeros("0.0"),
        zeros("0.0"),
        zeros(&format!("{r0:?}")),
        zeros("0.0"),
    )
    .replace(
        "b.vx - a.vx",
        if dims == 1 {
            "b.v - a.v"
        } else {
            "b.vx - a.vx"
        },
    )
}

/// The inner turning point: the root of U(r) = U(r0) on the repulsive wall.
fn inner_turning_point(r0: f64) -> f64 {
    let r_min = 2f64.powf(1.0 / 6.0);
    brent(|r| lj(r) - lj(r0), 0.8, r_min, 1e-15).unwrap()
}

/// The period from the quadrature of `dt = dr / |v_rel|`, with `r = c - h cos θ` so that the
/// inverse square roots at the turning points become finite.
fn period(r0: f64) -> f64 {
    let r_in = inner_turning_point(r0);
    let (c, h) = (f64::midpoint(r0, r_in), (r0 - r_in) / 2.0);
    let mu = 0.5;
    let f = |th: f64| {
        let r = c - h * th.cos();
        h * th.sin() / (2.0 * (lj(r0) - lj(r)) / mu).sqrt()
    };
    let tol = Tolerance {
        abs: 1e-13,
        rel: 1e-12,
    };
    2.0 * integrate(f, 0.0, std::f64::consts::PI, tol).unwrap().value
}

#[test]
fn lennard_jones_dimer_turns_where_u_equals_u0() {
    for (r0, dims) in [(1.5, 1), (1.3, 2), (1.8, 3)] {
        let s = run(&dimer(r0, dims));
        let r_in = inner_turning_point(r0);
        assert!(
            (s.observables["r_min"] - r_in).abs() < 1e-9,
            "r0 = {r0}, {dims}-D: r_min {} against {r_in}",
            s.observables["r_min"]
        );
        assert!((s.observables["r_max"] - r0).abs() < 1e-9);
        // energy: the ledger balances and E = U(r0) throughout
        assert!(
            s.work_energy_residual.abs() < 1e-9,
            "{}",
            s.work_energy_residual
        );
        assert!((s.energy.end - lj(r0)).abs() < 1e-9 * lj(r0).abs());
        assert!((s.potential_energy.start.unwrap() - lj(r0)).abs() < 1e-15);
        assert!((s.work["lj"] + (s.potential_energy.end.unwrap() - lj(r0))).abs() < 1e-9);
        // the period: from one inner turning point to the next
        let inner: Vec<f64> = s
            .events
            .iter()
            .filter(|e| e.name == "inner")
            .map(|e| e.t)
            .collect();
        assert!(inner.len() >= 3, "{} inner turning points", inner.len());
        let t = period(r0);
        for w in inner.windows(2) {
            assert!(
                (w[1] - w[0] - t).abs() < 1e-8 * t,
                "r0 = {r0}: period {} against the quadrature's {t}",
                w[1] - w[0]
            );
        }
    }
}

#[test]
fn the_example_dimer_reports_its_turning_points() {
    let path =
        std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/md/lj_dimer.toml");
    let s = Scenario::load(&path).unwrap().run().unwrap().summary;
    let r0 = 1.5;
    assert!((s.observables["r_inner"] - inner_turning_point(r0)).abs() < 1e-8);
    assert!((s.observables["r_outer"] - r0).abs() < 1e-8);
    assert!((s.observables["period"] - period(r0)).abs() < 1e-7);
    assert!(s.observables["energy_drift"].abs() < 1e-8);
}

fn bond(kind: &str, dims: usize) -> String {
    let (a, va, b, vb) = match dims {
        1 => ("0.0", "0.3", "0.8", "-0.1"),
        2 => ("[0.0, 0.0]", "[0.3, 0.5]", "[0.8, 0.1]", "[-0.1, -0.2]"),
        _ => (
            "[0.0, 0.0, 0.1]",
            "[0.3, 0.5, -0.2]",
            "[0.8, 0.1, 0.0]",
            "[-0.1, -0.2, 0.4]",
        ),
    };
    let force = if kind == "spring" {
        "kind = \"spring\"\nk = \"k\"\nrest_length = \"L\""
    } else {
        "kind = \"pair\"\nU = \"k*(r - L)^2/2\""
    };
    format!(
        r#"
dimensions = {dims}
[constants]
k = "40 N/m"
L = "0.5 m"
[[body]]
name = "a"
mass = "1 kg"
position = {a}
velocity = {va}
[[body]]
name = "b"
mass = "2 kg"
position = {b}
velocity = {vb}
[[force]]
name = "bond"
between = ["a", "b"]
{force}
[integrator]
method = "rk4"
dt = "1 ms"
[stop]
t_max = "2 s"
"#
    )
}

#[test]
fn harmonic_pair_is_the_spring() {
    for dims in 1..=3 {
        let spring = run(&bond("spring", dims));
        let pair = run(&bond("pair", dims));
        assert_eq!(spring.steps, pair.steps);
        let close = |a: f64, b: f64| (a - b).abs() <= 1e-12 * a.abs().max(1.0);
        for body in ["a", "b"] {
            let (s, p) = (&spring.bodies[body], &pair.bodies[body]);
            for (x, y) in s.position.iter().zip(&p.position) {
                assert!(close(*x, *y), "{dims}-D {body}: {x} against {y}");
            }
            for (x, y) in s.velocity.iter().zip(&p.velocity) {
                assert!(close(*x, *y), "{dims}-D {body}: {x} against {y}");
            }
        }
        assert!(close(spring.work["bond"], pair.work["bond"]));
        assert!(close(
            spring.potential_energy.end.unwrap(),
            pair.potential_energy.end.unwrap()
        ));
        // an internal force: no momentum changes hands with the outside
        for (p0, p1) in pair.momentum.start.iter().zip(&pair.momentum.end) {
            assert!((p0 - p1).abs() < 1e-12, "{dims}-D: {p0} -> {p1}");
        }
    }
}

#[test]
fn three_bodies_interacting_pairwise_keep_their_momentum() {
    let text = r#"
dimensions = 2
[constants]
D  = 4.7
b  = 1.9
re = 0.74
[[body]]
name = "p"
mass = 1.0
position = [0.0, 0.0]
velocity = [0.4, -0.3]
[[body]]
name = "q"
mass = 2.0
position = [0.9, 0.2]
velocity = [-0.2, 0.5]
[[body]]
name = "w"
mass = 3.0
position = [0.3, 0.8]
velocity = [0.1, 0.1]
[[force]]
name = "morse"
kind = "potential"
between = "all"
U = "D*(1 - exp(-b*(r - re)))^2"
[integrator]
method = "dopri5"
rtol = 1e-10
atol = 1e-12
[stop]
t_max = 10.0
"#;
    let s = run(text);
    let p0 = [1.0 * 0.4 + 2.0 * -0.2 + 3.0 * 0.1, -0.3 + 2.0 * 0.5 + 0.3];
    for (axis, p) in p0.iter().enumerate() {
        assert!((s.momentum.start[axis] - p).abs() < 1e-15);
        assert!(
            (s.momentum.end[axis] - p).abs() < 1e-9,
            "axis {axis}: {p} -> {}",
            s.momentum.end[axis]
        );
        assert!(s.momentum.external_impulse[axis].abs() < 1e-12);
    }
    assert!(
        s.work_energy_residual.abs() < 1e-8,
        "{}",
        s.work_energy_residual
    );
    assert!(s.energy.change.abs() < 1e-7 * s.energy.start.abs().max(1.0));
    // all three pairs act: the work of the one force is -ΔU of the three pair energies
    let u = |d: f64| 4.7 * (1.0 - (-1.9 * (d - 0.74)).exp()).powi(2);
    let dist = |a: [f64; 2], b: [f64; 2]| ((a[0] - b[0]).powi(2) + (a[1] - b[1]).powi(2)).sqrt();
    let u0 = u(dist([0.0, 0.0], [0.9, 0.2]))
        + u(dist([0.0, 0.0], [0.3, 0.8]))
        + u(dist([0.9, 0.2], [0.3, 0.8]));
    assert!((s.potential_energy.start.unwrap() - u0).abs() < 1e-14);
}

#[test]
fn a_cut_off_potential_is_shifted_so_energy_is_conserved() {
    // two unit masses pushed apart from r = 1 by a Lennard-Jones repulsion cut at 2.5: past the
    // cut-off the kinetic energy is all of U(1) - U(2.5)
    let text = r#"
dimensions = 1
[constants]
eps = 1.0
s   = 1.0
[[body]]
name = "a"
mass = 1.0
position = 0.0
[[body]]
name = "b"
mass = 1.0
position = 1.0
[[force]]
name = "lj"
kind = "pair-potential"
between = ["a", "b"]
U = "4*eps*((s/r)^12 - (s/r)^6)"
cutoff = "2.5*s"
[integrator]
method = "dopri5"
rtol = 1e-11
atol = 1e-12
[stop]
t_max = 5.0
"#;
    let s = run(text);
    let released = lj(1.0) - lj(2.5);
    assert_eq!(s.potential_energy.end, Some(0.0));
    assert!((s.potential_energy.start.unwrap() - released).abs() < 1e-14);
    assert!(
        (s.kinetic_energy.end.unwrap() - released).abs() < 1e-8 * released,
        "K = {:?}, U(1) - U(rc) = {released}",
        s.kinetic_energy.end
    );
    assert!((s.work["lj"] - released).abs() < 1e-8 * released);
    let gap = s.bodies["b"].position[0] - s.bodies["a"].position[0];
    assert!(gap > 2.5, "the pair flew apart past the cut-off: {gap}");
}

#[test]
fn bodies_at_one_point_are_refused_when_the_file_is_read() {
    // the run stopped at its first evaluation (exit 1, no location); the start is checked
    // when the file is read, with the run's own diagnosis, located at the body's position
    let text = dimer(1.5, 2).replace("position = [1.5, 0.0]", "position = [0.0, 0.0]");
    let e = error(&text);
    assert_eq!(e.kind, ErrorKind::Invalid);
    assert!(e.message.contains("`lj`"), "{e}");
    assert!(e.message.contains("b at (0, 0) m"), "{e}");
    let line = text
        .lines()
        .position(|l| l.starts_with("position"))
        .expect("a position")
        + 1;
    assert_eq!(at(&e), (line, 12));
}

const BASE: &str = r#"
dimensions = 1
[constants]
eps = "1e-21 J"
s   = "3.4e-10 m"
[[body]]
name = "a"
mass = "6.6e-26 kg"
position = "0 m"
[[body]]
name = "b"
mass = "6.6e-26 kg"
position = "4e-10 m"
[[force]]
name = "lj"
kind = "pair"
between = ["a", "b"]
U = "4*eps*((s/r)^12 - (s/r)^6)"
[integrator]
method = "verlet"
dt = "1e-15 s"
[stop]
t_max = "1e-12 s"
"#;

fn with(from: &str, to: &str) -> String {
    assert!(BASE.contains(from), "{from}");
    BASE.replacen(from, to, 1)
}

fn at(e: &ScenarioError) -> (usize, usize) {
    let l = e
        .location
        .as_ref()
        .unwrap_or_else(|| panic!("no location: {e}"));
    (l.line, l.column)
}

#[test]
fn the_base_scenario_runs_in_si_units() {
    // argon-like atoms 0.4 nm apart, oscillating about 2^(1/6) σ with a period near 1.6 ps
    let s = run(BASE);
    assert_eq!(s.stop_reason, "t_max");
    assert!(
        s.work_energy_residual.abs() < 1e-7 * 1e-21,
        "{}",
        s.work_energy_residual
    );
    assert!(s.energy.change.abs() < 1e-6 * s.energy.start.abs());
    assert!(s.potential_energy.start.unwrap() < 0.0, "inside the well");
}

#[test]
fn names_that_u_cannot_use_are_located() {
    let e = error(&with(
        "U = \"4*eps*((s/r)^12 - (s/r)^6)\"",
        "U = \"4*eps*(s/r)^12 - x\"",
    ));
    assert_eq!(e.kind, ErrorKind::Formula);
    assert!(e.message.contains("undefined name `x`"), "{e}");
    // line 18, the `x` after `U = "` (5 columns) and 17 characters of the formula
    assert_eq!(at(&e), (18, 23));
    let hint = e.hint.clone().unwrap_or_default();
    assert!(
        hint.contains("separation `r`") && hint.contains("eps, s"),
        "{hint}"
    );
}

#[test]
fn u_must_be_an_energy() {
    let e = error(&with("U = \"4*eps*((s/r)^12 - (s/r)^6)\"", "U = \"eps/r\""));
    assert_eq!(e.kind, ErrorKind::Dimension);
    assert!(e.message.contains("energy"), "{e}");
    assert_eq!(at(&e).0, 18);
}

#[test]
fn between_is_required_and_needs_two_bodies() {
    let e = error(&with("between = [\"a\", \"b\"]\n", ""));
    assert!(e.message.contains("between"), "{e}");
    let e = error(&with("between = [\"a\", \"b\"]", "between = [\"a\"]"));
    assert!(e.message.contains("at least two bodies"), "{e}");
    assert_eq!(at(&e), (17, 1));
    let e = error(&with(
        "between = [\"a\", \"b\"]",
        "between = [\"a\", \"c\"]",
    ));
    assert!(e.message.contains("no body named `c`"), "{e}");
    let e = error(&with("between = [\"a\", \"b\"]", "on = \"a\""));
    assert!(
        e.message.contains("`on` does not go with a pair force"),
        "{e}"
    );
}

#[test]
fn u_is_required() {
    let e = error(&with("U = \"4*eps*((s/r)^12 - (s/r)^6)\"\n", ""));
    assert!(e.message.contains("`U`"), "{e}");
    assert!(e.hint.unwrap_or_default().contains("separation `r`"));
}

#[test]
fn the_cutoff_is_a_positive_length_where_u_is_finite() {
    let lj = "U = \"4*eps*((s/r)^12 - (s/r)^6)\"";
    let e = error(&with(lj, &format!("{lj}\ncutoff = \"-1 nm\"")));
    assert!(e.message.contains("cutoff"), "{e}");
    assert_eq!(at(&e).0, 19);
    let e = error(&with(lj, &format!("{lj}\ncutoff = \"1 s\"")));
    assert_eq!(e.kind, ErrorKind::Dimension);
    let e = error(&with(lj, "U = \"eps*s/(r - s)\"\ncutoff = \"s\""));
    assert!(e.message.contains("not a finite number"), "{e}");
}

#[test]
fn in_reduced_units_the_potential_needs_no_constants() {
    // `r` is a pure number there: `r^-12 - r^-6` is consistent, as in SI (1/m^12 - 1/m^6) it is not
    let text = dimer(1.5, 1)
        .replace("dimensions = 1", "units = \"reduced\"\ndimensions = 1")
        .replace(
            "U = \"4*eps*((s/r)^12 - (s/r)^6)\"",
            "U = \"4*(r^-12 - r^-6)\"",
        );
    let s = run(&text);
    assert!((s.observables["r_min"] - inner_turning_point(1.5)).abs() < 1e-9);
    assert!((s.energy.end - lj(1.5)).abs() < 1e-9);
    let si = error(&dimer(1.5, 1).replace(
        "U = \"4*eps*((s/r)^12 - (s/r)^6)\"",
        "U = \"4*(r^-12 - r^-6)\"",
    ));
    assert_eq!(si.kind, ErrorKind::Dimension, "{si}");
}

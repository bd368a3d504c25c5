//! Stiff scenarios with `method = "radau5"` (issue 28): van der Pol at μ = 1000 as a particle
//! with a formula force, and a stiff damped spring against its closed form.

use mechkit::scenario::Scenario;

fn run(text: &str) -> mechkit::scenario::Summary {
    Scenario::from_str("stiff.toml", text)
        .unwrap()
        .run()
        .unwrap()
        .summary
}

const VAN_DER_POL: &str = r#"
title = "Van der Pol, mu = 1000"
dimensions = 1
[constants]
mu = "1000 1/s"
w2 = "1 1/s^2"
L = "1 m"
[[body]]
name = "p"
mass = "1 kg"
position = "2 m"
velocity = "0 m/s"
[[force]]
name = "vdp"
kind = "expression"
F = "m*(mu*(1 - x^2/L^2)*v - w2*x)"
[integrator]
method = "radau5"
rtol = 1e-6
atol = 1e-6
[stop]
t_max = "2000 s"
[observe]
x_end = "final(x)"
"#;

/// SciPy's Radau takes 617 steps and 5,167 evaluations at rtol = atol = 1e-6 (issue 28); the
/// state at t = 2000 s agrees with a run at 1e-10 to 1e-5.
#[test]
fn van_der_pol_at_mu_1000_in_fewer_steps_than_scipy_radau() {
    let loose = run(VAN_DER_POL);
    let tight = run(&VAN_DER_POL
        .replace("rtol = 1e-6", "rtol = 1e-10")
        .replace("atol = 1e-6", "atol = 1e-10"));
    let (x, reference) = (loose.observables["x_end"], tight.observables["x_end"]);
    assert!((x - reference).abs() < 1e-5, "{x} vs {reference}");
    assert!((reference - 1.706_167_7).abs() < 1e-6, "{reference}");
    assert!(loose.steps < 617, "{} steps", loose.steps);
    assert!(
        loose.evaluations < 5167,
        "{} evaluations",
        loose.evaluations
    );
}

/// `x'' + c x' + k x = 0` with k = 10⁶ and c = 2·10⁴ (overdamped: rates −50 and −19,950 s⁻¹):
/// an explicit method needs steps below 2.8/19,950 s; Radau5 follows the slow mode.
#[test]
fn a_stiff_damped_spring_follows_its_closed_form() {
    let text = r#"
dimensions = 1
[constants]
k = "1e6 N/m"
c = "2e4 N*s/m"
[[body]]
name = "p"
mass = "1 kg"
position = "1 m"
velocity = "0 m/s"
[[force]]
name = "spring"
kind = "expression"
F = "-k*x - c*v"
[integrator]
method = "radau5"
rtol = 1e-8
atol = 1e-12
[stop]
t_max = "0.1 s"
[observe]
x_end = "final(x)"
"#;
    let s = run(text);
    let (k, c) = (1e6_f64, 2e4_f64);
    let d = (c * c - 4.0 * k).sqrt();
    let (r1, r2) = (0.5 * (d - c), -0.5 * (c + d));
    let x = |t: f64| (-r2 * (r1 * t).exp() + r1 * (r2 * t).exp()) / (r1 - r2);
    let want = x(0.1);
    assert!(
        (s.observables["x_end"] - want).abs() < 1e-7 * want,
        "{} vs {want}",
        s.observables["x_end"]
    );
    assert!(s.steps < 300, "{} steps", s.steps);
    // dt = 1e-4 s, the explicit stability bound, would be 1000 steps for the same 0.1 s
}

#[test]
fn radau5_takes_no_fixed_step() {
    let text = VAN_DER_POL
        .replace("rtol = 1e-6", "dt = \"1 ms\"")
        .replace("atol = 1e-6", "");
    let e = Scenario::from_str("stiff.toml", &text)
        .unwrap_err()
        .to_string();
    assert!(e.contains("chooses its own steps"), "{e}");
}

/// Hairer's stiffness test in DOP853 (and DOPRI5): the stiff spring names the implicit method;
/// a smooth orbit gets no such warning.
#[test]
fn an_explicit_pair_on_a_stiff_problem_says_so_and_names_radau5() {
    let spring = r#"
dimensions = 1
[constants]
k = "1e6 N/m"
c = "2e4 N*s/m"
[[body]]
name = "p"
mass = "1 kg"
position = "1 m"
velocity = "0 m/s"
[[force]]
name = "spring"
kind = "expression"
F = "-k*x - c*v"
[integrator]
method = "METHOD"
rtol = 1e-6
atol = 1e-9
[stop]
t_max = "0.1 s"
"#;
    for method in ["dop853", "dopri5"] {
        let s = run(&spring.replace("METHOD", method));
        assert!(
            s.warnings
                .iter()
                .any(|w| w.contains("stiff from t =") && w.contains("radau5")),
            "{method}: {:?}",
            s.warnings
        );
        let s = run(&spring.replace("METHOD", "radau5"));
        assert!(
            !s.warnings.iter().any(|w| w.contains("stiff")),
            "{:?}",
            s.warnings
        );
    }
    let orbit = r#"
dimensions = 2
[constants]
GM = "1 m^3/s^2"
[[body]]
name = "p"
mass = "1 kg"
position = ["1 m", "0 m"]
velocity = ["0 m/s", "1 m/s"]
[[force]]
name = "sun"
kind = "expression"
F = ["-GM*m*x/(x^2 + y^2)^(3/2)", "-GM*m*y/(x^2 + y^2)^(3/2)"]
[integrator]
method = "dop853"
rtol = 1e-9
atol = 1e-12
[stop]
t_max = "50 s"
"#;
    let s = run(orbit);
    assert!(
        !s.warnings.iter().any(|w| w.contains("stiff")),
        "{:?}",
        s.warnings
    );
}

/// Formula forces give radau5 their Jacobian compiled from the symbolic engine: no
/// evaluations spent on finite differences.
#[test]
fn radau5_uses_the_compiled_jacobian_of_formula_forces() {
    let s = run(VAN_DER_POL);
    // with differences each Jacobian costs 2 + 1 (the work) evaluations; ~4,890 before
    assert!(s.evaluations < 4700, "{} evaluations", s.evaluations);
}

/// A ball dropped 1 mm onto a Hertz floor of k = 10¹⁰ N/m^1.5 with contact damping comes to
/// rest at the static compression `(m g/k)^(2/3)`; radau5 takes a small fraction of DOP853's
/// steps (held by the contact's stability bound) and DOP853 says the problem is stiff.
#[test]
fn a_ball_settles_on_a_hertz_floor_of_k_1e10() {
    let text = r#"
dimensions = 1
[constants]
k = "1e10 N/m^1.5"
c = "1e4 N*s/m"
g = "9.81 m/s^2"
[[body]]
name = "ball"
mass = "0.1 kg"
position = "1 mm"
velocity = "0 m/s"
[[force]]
name = "floor"
kind = "expression"
F = "k*max(-x, 0)^1.5 - c*v*heaviside(-x) - m*g"
[integrator]
method = "METHOD"
rtol = 1e-8
atol = 1e-12
[stop]
t_max = "0.5 s"
[observe]
x_end = "final(x)"
"#;
    let implicit = run(&text.replace("METHOD", "radau5"));
    let rest = -(0.1_f64 * 9.81 / 1e10).powf(2.0 / 3.0);
    let x = implicit.observables["x_end"];
    assert!((x - rest).abs() < 1e-6 * rest.abs(), "{x} vs {rest}");
    let explicit = run(&text.replace("METHOD", "dop853"));
    assert!((explicit.observables["x_end"] - rest).abs() < 1e-6 * rest.abs());
    assert!(
        implicit.steps * 10 < explicit.steps,
        "{} vs {} steps",
        implicit.steps,
        explicit.steps
    );
    assert!(explicit.warnings.iter().any(|w| w.contains("stiff from")));
}

/// The same with `method = "bdf"` (variable-order NDF, as SciPy's BDF, which takes 847 steps
/// and 2,620 evaluations here and ends 1.1e-4 from the reference): at rtol = atol = 1e-6 the
/// state at t = 2000 s is within 2e-4 of the reference, at 1e-7 within 3e-5.
#[test]
fn van_der_pol_at_mu_1000_with_bdf() {
    let bdf = VAN_DER_POL.replace("method = \"radau5\"", "method = \"bdf\"");
    let s = run(&bdf);
    let x = s.observables["x_end"];
    eprintln!(
        "bdf at 1e-6: x = {x}, {} steps, {} evaluations",
        s.steps, s.evaluations
    );
    assert!((x - 1.706_167_7).abs() < 2e-4, "{x}");
    assert!(s.steps < 900, "{} steps", s.steps);
    assert!(s.evaluations < 3000, "{} evaluations", s.evaluations);
    let tight = run(&bdf
        .replace("rtol = 1e-6", "rtol = 1e-7")
        .replace("atol = 1e-6", "atol = 1e-7"));
    let x = tight.observables["x_end"];
    eprintln!(
        "bdf at 1e-7: x = {x}, {} steps, {} evaluations",
        tight.steps, tight.evaluations
    );
    assert!((x - 1.706_167_7).abs() < 3e-5, "{x}");
}

/// The stiff damped spring with `method = "bdf"` against its closed form.
#[test]
fn a_stiff_damped_spring_with_bdf_follows_its_closed_form() {
    let text = r#"
dimensions = 1
[constants]
k = "1e6 N/m"
c = "2e4 N*s/m"
[[body]]
name = "p"
mass = "1 kg"
position = "1 m"
velocity = "0 m/s"
[[force]]
name = "spring"
kind = "expression"
F = "-k*x - c*v"
[integrator]
method = "bdf"
rtol = 1e-8
atol = 1e-12
[stop]
t_max = "0.1 s"
[observe]
x_end = "final(x)"
"#;
    let s = run(text);
    let (k, c) = (1e6_f64, 2e4_f64);
    let d = (c * c - 4.0 * k).sqrt();
    let (r1, r2) = (0.5 * (d - c), -0.5 * (c + d));
    let x = |t: f64| (-r2 * (r1 * t).exp() + r1 * (r2 * t).exp()) / (r1 - r2);
    let want = x(0.1);
    assert!(
        (s.observables["x_end"] - want).abs() < 1e-6 * want,
        "{} vs {want}",
        s.observables["x_end"]
    );
    assert!(s.steps < 1000, "{} steps", s.steps);
}

#[test]
fn bdf_takes_no_fixed_step() {
    let text = VAN_DER_POL
        .replace("method = \"radau5\"", "method = \"bdf\"")
        .replace("rtol = 1e-6", "dt = \"1 ms\"")
        .replace("atol = 1e-6", "");
    let e = Scenario::from_str("stiff.toml", &text)
        .unwrap_err()
        .to_string();
    assert!(e.contains("chooses its own steps"), "{e}");
}

/// The bouncing ball of `examples/bouncing_ball.toml` with `method = "bdf"`: every bounce and
/// apex at the times of a DOP853 run, the energy left after the bounces the same, and the
/// ledger's work-energy residual small (the work is integrated with the motion).
#[test]
fn events_and_the_ledger_of_a_bdf_run_match_an_explicit_one() {
    let text = include_str!("../../../../examples/bouncing_ball.toml");
    let reference = run(&text.replace("method = \"dopri5\"", "method = \"dop853\""));
    let bdf = run(&text.replace("method = \"dopri5\"", "method = \"bdf\""));
    assert_eq!(bdf.method, "bdf");
    assert_eq!(bdf.events.len(), reference.events.len());
    assert!(bdf.events.len() > 10, "{}", bdf.events.len());
    for (a, b) in bdf.events.iter().zip(&reference.events) {
        assert_eq!((&a.name, a.occurrence), (&b.name, b.occurrence));
        assert!(
            (a.t - b.t).abs() < 1e-7,
            "{} {}: {} vs {}",
            a.name,
            a.occurrence,
            a.t,
            b.t
        );
    }
    let (e, e_ref) = (
        bdf.observables["energy_remaining"],
        reference.observables["energy_remaining"],
    );
    assert!((e - e_ref).abs() < 1e-7, "{e} vs {e_ref}");
    assert!(
        bdf.work_energy_residual.abs() < 1e-8,
        "{}",
        bdf.work_energy_residual
    );
    eprintln!(
        "bouncing ball, bdf: {} steps, {} evaluations, {} events, residual {:e}",
        bdf.steps,
        bdf.evaluations,
        bdf.events.len(),
        bdf.work_energy_residual
    );
}

/// `method = "auto"` runs DOP853 until its stiffness test fires, then Radau IIA(5): van der Pol
/// at μ = 1000 comes out right in about as many steps as radau5 alone (DOP853 alone: 600,000),
/// and says where it switched.
#[test]
fn auto_switches_to_radau5_where_the_problem_turns_stiff() {
    let s = run(&VAN_DER_POL.replace("method = \"radau5\"", "method = \"auto\""));
    let x = s.observables["x_end"];
    assert!((x - 1.706_167_7).abs() < 1e-4, "{x}");
    assert!(s.steps < 1000, "{} steps", s.steps);
    assert!(
        s.warnings
            .iter()
            .any(|w| w.contains("switched from dop853 to radau5 at t =")),
        "{:?}",
        s.warnings
    );
    // a problem that is not stiff stays with DOP853, step for step
    let spring = r#"
dimensions = 1
[[body]]
name = "p"
mass = "1 kg"
position = "1 m"
velocity = "0 m/s"
[[force]]
name = "spring"
kind = "spring"
k = "4 N/m"
anchor = "0 m"
[integrator]
method = "METHOD"
rtol = 1e-9
atol = 1e-12
[stop]
t_max = "20 s"
[observe]
x_end = "final(x)"
"#;
    let auto = run(&spring.replace("METHOD", "auto"));
    let dop853 = run(&spring.replace("METHOD", "dop853"));
    assert_eq!(auto.steps, dop853.steps);
    assert_eq!(auto.observables["x_end"], dop853.observables["x_end"]);
    assert!(auto.warnings.iter().all(|w| !w.contains("switched")));
}

/// A chain of `count` 1 kg masses on springs of k = 10⁶ N/m with dashpots (a pair force for the
/// damping), the first tied to a wall, the last pulled by 1 kN: the compiled Jacobian's
/// structural zeros make the Newton matrices banded (q and v interleaved), and radau5 and bdf
/// end where a tight explicit run ends, in a third of the explicit steps at their tolerance.
fn spring_chain(method: &str, rtol: f64, count: usize) -> String {
    use std::fmt::Write as _;
    let mut s = format!(
        "dimensions = 1\n[constants]\nk = \"1e6 N/m\"\nc = \"2e4 N*s/m\"\nF0 = \"1000 N\"\n\
         [integrator]\nmethod = \"{method}\"\nrtol = {rtol}\natol = {}\n\
         [stop]\nt_max = \"0.1 s\"\n[observe]\nx_end = \"final(m{}.x)\"\nx_mid = \"final(m{}.x)\"\n",
        rtol * 1e-3,
        count - 1,
        count / 2 - 1,
    );
    for i in 0..count {
        write!(
            s,
            "[[body]]\nname = \"m{i}\"\nmass = \"1 kg\"\nposition = \"{} m\"\nvelocity = \"0 m/s\"\n",
            i + 1
        )
        .unwrap();
    }
    s += "[[force]]\nname = \"wall\"\nkind = \"expression\"\non = \"m0\"\nF = \"-k*(x - 1) - c*v\"\n";
    for i in 1..count {
        write!(
            s,
            "[[force]]\nname = \"s{i}\"\nkind = \"spring\"\nk = \"k\"\nrest_length = \"1 m\"\n\
             between = [\"m{}\", \"m{i}\"]\n\
             [[force]]\nname = \"d{i}\"\nkind = \"expression\"\non = \"m{i}\"\n\
             F = \"-c*(v - m{}.v)\"\n[[force]]\nname = \"e{i}\"\nkind = \"expression\"\n\
             on = \"m{}\"\nF = \"-c*(v - m{i}.v)\"\n",
            i - 1,
            i - 1,
            i - 1
        )
        .unwrap();
    }
    write!(
        s,
        "[[force]]\nname = \"pull\"\nkind = \"expression\"\non = \"m{}\"\nF = \"F0\"\n",
        count - 1
    )
    .unwrap();
    s
}

#[test]
fn a_chain_of_stiff_springs_banded_matches_an_explicit_run() {
    let reference = run(&spring_chain("dop853", 1e-10, 10));
    let explicit = run(&spring_chain("dop853", 1e-7, 10));
    for method in ["radau5", "bdf"] {
        let s = run(&spring_chain(method, 1e-7, 10));
        for x in ["x_end", "x_mid"] {
            let (got, want) = (s.observables[x], reference.observables[x]);
            assert!((got - want).abs() < 1e-7, "{method} {x}: {got} vs {want}");
        }
        assert!(
            s.steps * 3 < explicit.steps,
            "{method}: {} steps, dop853 {}",
            s.steps,
            explicit.steps
        );
    }
}

/// The same chain of 100 masses (100 coordinates, past the dense Jacobian's 96): still an
/// exact compiled Jacobian, sparse, so the Jacobians cost no evaluations of the forces (by
/// differences each would cost 201), and the banded solver; radau5 and bdf agree with a
/// tight radau5 run (the ten-mass chain above checks radau5 against dop853).
#[test]
fn a_long_chain_of_stiff_springs_keeps_its_exact_jacobian() {
    let reference = run(&spring_chain("radau5", 1e-10, 100));
    for method in ["radau5", "bdf"] {
        let s = run(&spring_chain(method, 1e-7, 100));
        for x in ["x_end", "x_mid"] {
            let (got, want) = (s.observables[x], reference.observables[x]);
            assert!((got - want).abs() < 1e-7, "{method} {x}: {got} vs {want}");
        }
        // radau5 takes about 6.5 evaluations a step, bdf about 2; a Jacobian by differences
        // would add 201 to either
        let per_step = if method == "radau5" { 7.0 } else { 2.5 };
        assert!(
            (s.evaluations as f64) < per_step * s.steps as f64,
            "{method}: {} evaluations in {} steps",
            s.evaluations,
            s.steps
        );
    }
}

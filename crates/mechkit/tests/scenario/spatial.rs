//! Free rigid bodies in space (`dimensions = 3` with `[[rigid_body]]`): the orientation is a
//! quaternion turned by Euler's equations `I ω̇ = τ − ω × I ω` (body frame), the centre of
//! mass moves by Newton's law, forces act at body points with their torque `r × F`. Checked
//! against closed forms: the torque-free symmetric top (ω precessing about the figure axis at
//! `Ω = (I₃ − I₁) ω₃ / I₁`), small oscillations about a stable principal axis, the exact
//! Euler-Poinsot motion and `mechkit::rigid::free3d` for the tennis-racket flip, spin-up by
//! a constant torque, the first accelerations of a body pushed at a point, a spinning body
//! thrown in uniform gravity, and the inertia of bodies made of parts.

use mechkit::mass::Vec3;
use mechkit::rigid::free3d::{FreeBody, Poinsot, SpinIntegrator, SpinOptions, SpinningBody};
use mechkit::scenario::sweep::ConstantOverride;
use mechkit::scenario::{Scenario, ScenarioError, Summary};
use nalgebra::{Unit, UnitQuaternion};

use crate::util::workspace;

fn run_text(text: &str) -> Summary {
    Scenario::from_str("test.toml", text)
        .unwrap_or_else(|e| panic!("{e}"))
        .run()
        .unwrap()
        .summary
}

/// A scenario in space: `tables` run by DOP853 at `rtol` (absolute `1e-2 rtol`) for `t_max`
/// seconds, with the `[observe]` lines `observe`.
fn space(tables: &str, rtol: f64, t_max: f64, observe: &str) -> String {
    format!(
        "dimensions = 3\n{tables}\n[integrator]\nmethod = \"dop853\"\nrtol = {rtol:e}\natol = {:e}\n\
         [stop]\nt_max = \"{t_max} s\"\n[observe]\n{observe}\n",
        1e-2 * rtol
    )
}

/// The mean time between the occurrences of the event `name` (more than five of them).
fn mean_period(s: &Summary, name: &str) -> f64 {
    let times: Vec<f64> = s
        .events
        .iter()
        .filter(|e| e.name == name)
        .map(|e| e.t)
        .collect();
    assert!(times.len() > 5, "{name}: {} occurrences", times.len());
    (times[times.len() - 1] - times[0]) / (times.len() - 1) as f64
}

fn close(a: f64, b: f64, tol: f64) {
    assert!((a - b).abs() <= tol, "{a} vs {b} (tolerance {tol})");
}

fn close3(a: [f64; 3], b: [f64; 3], tol: f64) {
    for k in 0..3 {
        assert!(
            (a[k] - b[k]).abs() <= tol,
            "{a:?} vs {b:?} (tolerance {tol})"
        );
    }
}

fn norm(v: [f64; 3]) -> f64 {
    v.iter().map(|x| x * x).sum::<f64>().sqrt()
}

/// `v` turned by `angle` about the unit vector `axis` (Rodrigues).
fn turned(v: [f64; 3], axis: [f64; 3], angle: f64) -> [f64; 3] {
    let r = UnitQuaternion::from_axis_angle(&Unit::new_normalize(Vec3::from(axis)), angle);
    (r * Vec3::from(v)).into()
}

#[test]
fn torque_free_symmetric_body_precesses_about_its_figure_axis() {
    // I₁ = I₂: in the body, ω⊥ turns about axis 3 at Ω = (I₃ − I₁) ω₃ / I₁ while ω₃ stays;
    // in the world L is fixed and ω turns about it at |L| / I₁
    for (i1, i3, wp, w3) in [
        (1.0_f64, 2.0_f64, 0.3_f64, 2.0_f64),
        (2.0, 0.5, 1.0, -1.5),
        (0.4, 0.7, 0.05, 4.0),
    ] {
        let t_max = 3.0;
        let tables = format!(
            r#"
[constants]
I1 = "{i1} kg m^2"
I3 = "{i3} kg m^2"
wp = "{wp} rad/s"
w3 = "{w3} rad/s"
Om = "(I3 - I1)/I1*w3"
[[rigid_body]]
name = "top"
mass = "1 kg"
inertia = ["I1", "I1", "I3"]
omega = ["wp", "0 rad/s", "w3"]
"#
        );
        let s = run_text(&space(
            &tables,
            1e-12,
            t_max,
            r#"
w1_error = "max(abs(top.w1 - wp*cos(Om*t)))"
w2_error = "max(abs(top.w2 - wp*sin(Om*t)))"
w3_error = "max(abs(top.w3 - w3))"
Lx_drift = "max(top.Lx) - min(top.Lx)"
Ly_drift = "max(top.Ly) - min(top.Ly)"
Lz_drift = "max(top.Lz) - min(top.Lz)"
omega_drift = "max(top.omega) - min(top.omega)"
L = "initial(top.L)"
"#,
        ));
        let o = &s.observables;
        let l = (i1 * i1 * wp * wp + i3 * i3 * w3 * w3).sqrt();
        close(o["L"], l, 1e-14 * l);
        for k in ["w1_error", "w2_error", "w3_error"] {
            assert!(o[k] < 1e-10 * wp.max(w3.abs()), "{k}: {}", o[k]);
        }
        for k in ["Lx_drift", "Ly_drift", "Lz_drift"] {
            assert!(o[k] < 1e-10 * l, "{k}: {}", o[k]);
        }
        assert!(o["omega_drift"] < 1e-10 * w3.abs(), "{}", o["omega_drift"]);
        // the world ω at the end: ω(0) turned about L by |L| t / I₁
        let spin = s.bodies["top"].spin.unwrap();
        let l0 = [i1 * wp, 0.0, i3 * w3];
        let expected = turned([wp, 0.0, w3], l0.map(|x| x / l), l * t_max / i1);
        close3(spin.omega, expected, 1e-9 * norm(expected));
        close3(spin.angular_momentum, l0, 1e-10 * l);
    }
}

#[test]
fn small_oscillations_about_a_stable_axis_have_the_linearised_frequency() {
    // spun about axis k (the largest or the smallest moment) and nudged about axis i:
    // Ω² = ω_k² (I_k − I_i)(I_k − I_j) / (I_i I_j)
    for (moments, k, i, w0) in [
        ([1.0_f64, 2.0, 3.0], 2, 0, 2.0_f64),
        ([0.5, 0.8, 1.1], 2, 0, 3.0),
        ([1.0, 2.0, 3.0], 0, 2, 2.5),
        ([0.3, 0.45, 0.6], 0, 1, 1.0),
    ] {
        let j = 3 - k - i;
        let eps = 1e-3 * w0;
        let [ik, ii, ij] = [moments[k], moments[i], moments[j]];
        let freq = w0 * ((ik - ii) * (ik - ij) / (ii * ij)).sqrt();
        let period = 2.0 * std::f64::consts::PI / freq;
        let mut omega = ["0 rad/s"; 3].map(String::from);
        omega[k] = format!("{w0} rad/s");
        omega[i] = format!("{eps} rad/s");
        let tables = format!(
            r#"
[[rigid_body]]
name = "top"
mass = "1 kg"
inertia = [{}, {}, {}]
omega = ["{}", "{}", "{}"]
[[event]]
name = "turn"
function = "top.w{}"
direction = "falling"
"#,
            moments[0],
            moments[1],
            moments[2],
            omega[0],
            omega[1],
            omega[2],
            i + 1
        );
        let s = run_text(&space(&tables, 1e-12, 8.5 * period, ""));
        let measured = mean_period(&s, "turn");
        // the exact period of the (nonlinear) motion, by elliptic functions
        let mut w = [0.0; 3];
        w[k] = w0;
        w[i] = eps;
        let exact = Poinsot::new(moments, Vec3::from(w)).unwrap().period();
        // the amplitude ε/ω₀ = 1e-3 shifts the period by ~1e-6 relative
        close(measured, period, 5e-6 * period);
        close(measured, exact, 1e-9 * exact);
    }
}

/// The tennis racket: spun about the intermediate axis, the body flips over and back.
#[test]
fn intermediate_axis_flips_as_free3d_and_euler_poinsot_say() {
    let moments = [1.0, 2.0, 3.0];
    let omega_body = Vec3::new(0.01, 1.0, 0.02);
    let axis = [1.0, -2.0, 0.5];
    let angle = 0.7_f64;
    let q = UnitQuaternion::from_axis_angle(&Unit::new_normalize(Vec3::from(axis)), angle);
    let w = q * omega_body;
    let exact = Poinsot::new(moments, omega_body).unwrap();
    let t_max = 3.3 * exact.period();
    let tables = format!(
        r#"
[[rigid_body]]
name = "racket"
mass = "0.3 kg"
inertia = {moments:?}
orientation = {{ axis = {axis:?}, angle = "{angle}" }}
omega = [{}, {}, {}]
[[event]]
name = "flip"
function = "racket.w2"
"#,
        w.x, w.y, w.z
    );
    let s = run_text(&space(
        &tables,
        1e-13,
        t_max,
        r#"
w1 = "final(racket.w1)"
w2 = "final(racket.w2)"
w3 = "final(racket.w3)"
energy_error = "(max(racket.K) - min(racket.K))/initial(racket.K)"
L_error = "(max(racket.L) - min(racket.L))/initial(racket.L)"
"#,
    ));
    let o = &s.observables;
    let got = [o["w1"], o["w2"], o["w3"]];
    // mechkit spin's solver, from the same start
    let body = SpinningBody::free(FreeBody::new(moments, 0.3).unwrap());
    let start = body.attitude(q, omega_body).unwrap();
    let options = SpinOptions {
        integrator: SpinIntegrator::dop853(1e-13),
        ..SpinOptions::default()
    };
    let run = body.simulate(&start, t_max, &options).unwrap();
    let reference: [f64; 3] = body.omega_body(&run.end).into();
    let poinsot: [f64; 3] = exact.omega(t_max).into();
    close3(got, reference, 1e-8);
    close3(got, poinsot, 1e-8);
    // the orientation too (q and −q are the same turn)
    let end = s.bodies["racket"].spin.unwrap();
    let q_ref = run.end.q.quaternion();
    let q_ref = [q_ref.w, q_ref.i, q_ref.j, q_ref.k];
    let sign = if end.orientation[0] * q_ref[0] < 0.0 {
        -1.0
    } else {
        1.0
    };
    for (x, r) in end.orientation.into_iter().zip(q_ref) {
        close(x, sign * r, 1e-8);
    }
    close3(end.angular_momentum, start.l.into(), 1e-10);
    assert!(o["energy_error"] < 1e-11, "{}", o["energy_error"]);
    assert!(o["L_error"] < 1e-11, "{}", o["L_error"]);
    // ω₂ changes sign twice per period: the flips
    let flips = mean_period(&s, "flip");
    close(2.0 * flips, exact.period(), 1e-8 * exact.period());
}

#[test]
fn constant_torque_spins_a_body_up_from_rest() {
    // about a principal axis from rest: ω = τ t / I, K = τ² t² / (2 I), and the torque's
    // work is K
    let moments = [0.2, 0.5, 0.6];
    let (tau, t_max) = (0.3, 2.0);
    for k in 0..3 {
        // formulas take no units: a zero torque is written in terms of `tau`
        let mut torque = ["0*tau"; 3].map(String::from);
        torque[k] = "tau".into();
        let tables = format!(
            r#"
[constants]
tau = "{tau} N*m"
[[rigid_body]]
name = "wheel"
mass = "2 kg"
inertia = {moments:?}
[[force]]
name = "motor"
kind = "torque"
on = "wheel"
T = ["{}", "{}", "{}"]
"#,
            torque[0], torque[1], torque[2]
        );
        let s = run_text(&space(
            &tables,
            1e-12,
            t_max,
            r#"
wx = "final(wheel.wx)"
wy = "final(wheel.wy)"
wz = "final(wheel.wz)"
w_body = "final(wheel.w1 + wheel.w2 + wheel.w3)"
K_rot = "final(K_rot)"
K = "final(wheel.K)"
work = "final(work.motor)"
alpha = "initial(wheel.alphax + wheel.alphay + wheel.alphaz)"
"#,
        ));
        let o = &s.observables;
        let i = moments[k];
        let w = tau * t_max / i;
        let mut expected = [0.0; 3];
        expected[k] = w;
        close3([o["wx"], o["wy"], o["wz"]], expected, 1e-12 * w);
        close(o["w_body"], w, 1e-12 * w);
        close(o["alpha"], tau / i, 1e-13 * tau / i);
        let kin = 0.5 * tau * tau * t_max * t_max / i;
        close(o["K_rot"], kin, 1e-12 * kin);
        close(o["K"], kin, 1e-12 * kin);
        close(o["work"], kin, 1e-11 * kin);
        close(s.work["motor"], kin, 1e-11 * kin);
        close(s.work_energy_residual, 0.0, 1e-11 * kin);
    }
}

#[test]
fn a_torque_formula_of_the_spin_brakes_it_exponentially() {
    // τ = −b ω about the figure axis: ω₃ = ω₀ exp(−b t / I₃), and the brake's work is −ΔK
    let (i3, b, w0, t_max) = (0.6_f64, 0.2_f64, 5.0_f64, 3.0_f64);
    let tables = format!(
        r#"
[constants]
b = "{b} N*m*s"
[[rigid_body]]
name = "wheel"
mass = "2 kg"
inertia = ["0.4 kg m^2", "0.4 kg m^2", "{i3} kg m^2"]
omega = ["0 rad/s", "0 rad/s", "{w0} rad/s"]
[[force]]
name = "brake"
kind = "torque"
T = ["-b*wheel.wx", "-b*wheel.wy", "-b*wheel.wz"]
"#
    );
    let s = run_text(&space(&tables, 1e-12, t_max, "w = \"final(wheel.w3)\""));
    let w = w0 * (-b * t_max / i3).exp();
    close(s.observables["w"], w, 1e-11 * w0);
    let dk = 0.5 * i3 * (w * w - w0 * w0);
    close(s.work["brake"], dk, 1e-10 * dk.abs());
}

/// A box at rest, inertia diag(I₁, I₂, I₃), pushed by a constant `F` at its body point `r`,
/// turned by `orientation` (a quarter turn about z or none).
fn pushed(r: [f64; 3], f: [f64; 3], quarter_turn: bool, t_max: f64) -> Summary {
    let orientation = if quarter_turn {
        "orientation = { axis = [0, 0, 1], angle = \"90 deg\" }"
    } else {
        ""
    };
    let tables = format!(
        r#"
[[rigid_body]]
name = "box"
mass = "2 kg"
inertia = ["0.2 kg m^2", "0.5 kg m^2", "0.6 kg m^2"]
position = ["1 m", "-2 m", "0.5 m"]
{orientation}
points = {{ p = ["{} m", "{} m", "{} m"] }}
[[force]]
name = "push"
kind = "constant"
F = ["{} N", "{} N", "{} N"]
at = "box.p"
"#,
        r[0], r[1], r[2], f[0], f[1], f[2]
    );
    run_text(&space(
        &tables,
        1e-12,
        t_max,
        r#"
ax = "initial(box.ax)"
ay = "initial(box.ay)"
az = "initial(box.az)"
alphax = "initial(box.alphax)"
alphay = "initial(box.alphay)"
alphaz = "initial(box.alphaz)"
px0 = "initial(box.p.x)"
py0 = "initial(box.p.y)"
pz0 = "initial(box.p.z)"
px = "final(box.p.x)"
py = "final(box.p.y)"
pz = "final(box.p.z)"
"#,
    ))
}

#[test]
fn a_force_at_a_body_point_accelerates_the_centre_and_turns_the_body() {
    let (m, moments) = (2.0, [0.2, 0.5, 0.6]);
    for (r, f) in [
        ([0.3, 0.0, 0.0], [0.0, 1.5, 0.0]),
        ([0.1, -0.2, 0.25], [0.7, 0.4, -1.1]),
        ([0.0, 0.0, -0.4], [2.0, -1.0, 0.0]),
    ] {
        for quarter_turn in [false, true] {
            let s = pushed(r, f, quarter_turn, 1.5);
            let o = &s.observables;
            // the point in the world: turned by a quarter turn about z, (x, y, z) → (−y, x, z)
            let rw = if quarter_turn { [-r[1], r[0], r[2]] } else { r };
            let tau = [
                rw[1] * f[2] - rw[2] * f[1],
                rw[2] * f[0] - rw[0] * f[2],
                rw[0] * f[1] - rw[1] * f[0],
            ];
            // α = R I⁻¹ Rᵀ τ; the quarter turn swaps the roles of I₁ and I₂
            let alpha = if quarter_turn {
                [
                    tau[0] / moments[1],
                    tau[1] / moments[0],
                    tau[2] / moments[2],
                ]
            } else {
                [
                    tau[0] / moments[0],
                    tau[1] / moments[1],
                    tau[2] / moments[2],
                ]
            };
            close3([o["ax"], o["ay"], o["az"]], f.map(|x| x / m), 1e-13);
            close3([o["alphax"], o["alphay"], o["alphaz"]], alpha, 1e-13);
            close3(
                [o["px0"], o["py0"], o["pz0"]],
                [1.0 + rw[0], -2.0 + rw[1], 0.5 + rw[2]],
                1e-14,
            );
            // a constant force's work is F · (how far its point moved), and the ledger closes
            let moved = [o["px"] - o["px0"], o["py"] - o["py0"], o["pz"] - o["pz0"]];
            let w: f64 = (0..3).map(|k| f[k] * moved[k]).sum();
            let k_end = s.kinetic_energy.end.unwrap();
            close(s.work["push"], w, 1e-9 * w.abs());
            close(s.work["push"], k_end, 1e-9 * k_end);
            close(s.work_energy_residual, 0.0, 1e-10 * k_end);
        }
    }
}

#[test]
fn a_spinning_body_thrown_in_gravity_follows_the_parabola_and_keeps_its_spin() {
    let (m, g, t_max) = (0.5, 9.81, 1.7);
    for (inertia, omega) in [
        ("\"0.4 kg m^2\"", [1.0, -2.0, 3.0]),
        ("[0.2, 0.5, 0.6]", [0.5, 4.0, -1.0]),
    ] {
        let (x0, v0) = ([1.0, 2.0, 3.0], [4.0, -1.0, 12.0]);
        let tables = format!(
            r#"
[[rigid_body]]
name = "ball"
mass = "{m} kg"
inertia = {inertia}
position = ["{} m", "{} m", "{} m"]
velocity = ["{} m/s", "{} m/s", "{} m/s"]
omega = ["{} rad/s", "{} rad/s", "{} rad/s"]
[[force]]
name = "gravity"
kind = "uniform-gravity"
g = "{g} m/s^2"
"#,
            x0[0], x0[1], x0[2], v0[0], v0[1], v0[2], omega[0], omega[1], omega[2]
        );
        let s = run_text(&space(
            &tables,
            1e-12,
            t_max,
            r#"
L_drift = "max(ball.L) - min(ball.L)"
Lx_drift = "max(ball.Lx) - min(ball.Lx)"
Lz_drift = "max(ball.Lz) - min(ball.Lz)"
K_rot_drift = "max(K_rot) - min(K_rot)"
"#,
        ));
        let b = &s.bodies["ball"];
        let spin = b.spin.unwrap();
        let expected = [
            x0[0] + v0[0] * t_max,
            x0[1] + v0[1] * t_max,
            x0[2] + v0[2] * t_max - 0.5 * g * t_max * t_max,
        ];
        close3(
            [b.position[0], b.position[1], b.position[2]],
            expected,
            1e-10,
        );
        close(b.velocity[2], v0[2] - g * t_max, 1e-11);
        let o = &s.observables;
        for k in ["L_drift", "Lx_drift", "Lz_drift", "K_rot_drift"] {
            assert!(o[k] < 1e-11, "{inertia} {k}: {}", o[k]);
        }
        if inertia.starts_with('"') {
            // a sphere-like body: ω and L stay as they were
            close3(spin.omega, omega, 1e-12);
            close3(spin.angular_momentum, omega.map(|w| 0.4 * w), 1e-12);
        }
        // gravity's work is the kinetic energy gained, all of it by the centre
        close(s.work["gravity"], m * g * (x0[2] - b.position[2]), 1e-9);
        close(s.work_energy_residual, 0.0, 1e-10);
    }
}

#[test]
fn orientation_turns_body_points_and_the_world_angular_velocity() {
    let tables = r#"
[[rigid_body]]
name = "box"
mass = "1 kg"
inertia = [0.2, 0.5, 0.6]
position = ["1 m", "2 m", "3 m"]
orientation = { axis = [0, 0, 1], angle = "90 deg" }
omega = ["1 rad/s", "0 rad/s", "0 rad/s"]
points = { p = ["1 m", "0 m", "0 m"] }
[[rigid_body]]
name = "tilted"
mass = "1 kg"
inertia = "0.1 kg m^2"
orientation = [1, 1, 0, 0]
points = { p = ["0 m", "1 m", "0 m"] }
"#;
    let s = run_text(&space(
        tables,
        1e-10,
        0.01,
        r#"
px = "initial(box.p.x)"
py = "initial(box.p.y)"
pz = "initial(box.p.z)"
w1 = "initial(box.w1)"
w2 = "initial(box.w2)"
w3 = "initial(box.w3)"
q0 = "initial(tilted.q0)"
q1 = "initial(tilted.q1)"
q2 = "initial(tilted.q2)"
q3 = "initial(tilted.q3)"
tx = "initial(tilted.p.x)"
ty = "initial(tilted.p.y)"
tz = "initial(tilted.p.z)"
"#,
    ));
    let o = &s.observables;
    // a quarter turn about z takes the body's x axis to the world's y axis
    close3([o["px"], o["py"], o["pz"]], [1.0, 3.0, 3.0], 1e-15);
    // ω is given in the world: along world x is along the body's −y
    close3([o["w1"], o["w2"], o["w3"]], [0.0, -1.0, 0.0], 1e-15);
    // [1, 1, 0, 0] is normalised: a quarter turn about x takes y to z
    let h = 0.5_f64.sqrt();
    close(o["q0"], h, 1e-15);
    close(o["q1"], h, 1e-15);
    close(o["q2"], 0.0, 1e-15);
    close(o["q3"], 0.0, 1e-15);
    close3([o["tx"], o["ty"], o["tz"]], [0.0, 0.0, 1.0], 1e-15);
    let q = s.bodies["tilted"].spin.unwrap().orientation;
    close3([q[0], q[1], q[2]], [h, h, 0.0], 1e-15);
}

#[test]
fn a_body_of_parts_has_the_inertia_of_the_mass_library() {
    // a solid box a × b × c: m(b² + c²)/12, m(a² + c²)/12, m(a² + b²)/12
    for ([a, b, c], m) in [([0.3, 0.2, 0.1], 2.0), ([0.05, 0.4, 0.25], 0.7)] {
        let w = 1.3;
        let tables = format!(
            r#"
[[rigid_body]]
name = "brick"
omega = ["0 rad/s", "{w} rad/s", "0 rad/s"]
  [[rigid_body.part]]
  shape = "box"
  size = ["{a} m", "{b} m", "{c} m"]
  mass = "{m} kg"
"#
        );
        let s = run_text(&space(&tables, 1e-10, 0.5, "Ly = \"initial(brick.Ly)\""));
        let body = &s.bodies["brick"];
        let inertia = body.spin.unwrap().inertia;
        let expected = [
            m * (b * b + c * c) / 12.0,
            m * (a * a + c * c) / 12.0,
            m * (a * a + b * b) / 12.0,
        ];
        for (i, row) in inertia.iter().enumerate() {
            for (j, x) in row.iter().enumerate() {
                let e = if i == j { expected[i] } else { 0.0 };
                close(*x, e, 1e-15);
            }
        }
        close(body.mass, m, 1e-15);
        close(s.observables["Ly"], expected[1] * w, 1e-15);
    }
}

#[test]
fn a_body_of_parts_turns_about_its_centre_of_mass() {
    // a box M at the origin and a ball ms at (d, 0, 0): the centre of mass is at
    // x_c = ms d/(M + ms); about it I₂ = I₃ gain the reduced mass' M ms d²/(M + ms)
    let (big_m, a, b, c) = (3.0, 0.4, 0.2, 0.1);
    let (ms, radius, d) = (1.0, 0.05, 0.5);
    let tables = format!(
        r#"
[[rigid_body]]
name = "hammer"
position = ["1 m", "0 m", "0 m"]
points = {{ centre = ["0 m", "0 m", "0 m"], ball = ["{d} m", "0 m", "0 m"] }}
  [[rigid_body.part]]
  shape = "box"
  size = ["{a} m", "{b} m", "{c} m"]
  mass = "{big_m} kg"
  [[rigid_body.part]]
  shape = "sphere"
  radius = "{radius} m"
  mass = "{ms} kg"
  position = ["{d} m", "0 m", "0 m"]
"#
    );
    let s = run_text(&space(
        &tables,
        1e-10,
        0.1,
        "centre = \"initial(hammer.centre.x)\"\nball = \"initial(hammer.ball.x)\"",
    ));
    let xc = ms * d / (big_m + ms);
    close(s.observables["centre"], 1.0 - xc, 1e-15);
    close(s.observables["ball"], 1.0 + d - xc, 1e-15);
    let sphere = 0.4 * ms * radius * radius;
    let reduced = big_m * ms * d * d / (big_m + ms);
    let expected = [
        big_m * (b * b + c * c) / 12.0 + sphere,
        big_m * (a * a + c * c) / 12.0 + sphere + reduced,
        big_m * (a * a + b * b) / 12.0 + sphere + reduced,
    ];
    let inertia = s.bodies["hammer"].spin.unwrap().inertia;
    close3(
        [inertia[0][0], inertia[1][1], inertia[2][2]],
        expected,
        1e-14,
    );
    close(s.bodies["hammer"].mass, big_m + ms, 1e-14);
}

/// A rigid body and a particle joined by a spring from the particle to a body point,
/// written as two `expression` forces (the one on the body applied at the point): no
/// potential is declared, so `K + ½ k d²` is formed in `[observe]`.
const TETHERED: &str = r#"
[constants]
k = "40 N/m"
[[body]]
name = "ball"
mass = "0.3 kg"
position = ["0.8 m", "0.3 m", "-0.2 m"]
velocity = ["0 m/s", "0.5 m/s", "0.2 m/s"]
[[rigid_body]]
name = "box"
mass = "1.2 kg"
inertia = [0.02, 0.05, 0.06]
omega = ["0.5 rad/s", "-1 rad/s", "2 rad/s"]
points = { tip = ["0.2 m", "0.05 m", "0 m"] }
[[force]]
name = "pull_ball"
kind = "expression"
on = "ball"
F = ["-k*(ball.x - box.tip.x)", "-k*(ball.y - box.tip.y)", "-k*(ball.z - box.tip.z)"]
[[force]]
name = "pull_box"
kind = "expression"
at = "box.tip"
F = ["k*(ball.x - box.tip.x)", "k*(ball.y - box.tip.y)", "k*(ball.z - box.tip.z)"]
"#;

#[test]
fn a_spring_from_a_particle_to_a_body_point_keeps_the_energy() {
    let s = run_text(&space(
        TETHERED,
        1e-12,
        4.0,
        r#"
E_error = "(max(K + k/2*((ball.x - box.tip.x)^2 + (ball.y - box.tip.y)^2 + (ball.z - box.tip.z)^2)) - min(K + k/2*((ball.x - box.tip.x)^2 + (ball.y - box.tip.y)^2 + (ball.z - box.tip.z)^2)))/initial(K)"
Lx = "max(ball.m*(ball.y*ball.vz - ball.z*ball.vy) + box.m*(box.y*box.vz - box.z*box.vy) + box.Lx) - min(ball.m*(ball.y*ball.vz - ball.z*ball.vy) + box.m*(box.y*box.vz - box.z*box.vy) + box.Lx)"
turned = "max(box.omega) - min(box.omega)"
"#,
    ));
    let o = &s.observables;
    assert!(o["E_error"] < 1e-10, "{}", o["E_error"]);
    // internal forces: the total angular momentum about the origin is kept
    assert!(o["Lx"] < 1e-10, "{}", o["Lx"]);
    // and the spring does turn the body
    assert!(o["turned"] > 0.1, "{}", o["turned"]);
    // total momentum is kept
    for k in 0..3 {
        close(s.momentum.end[k], s.momentum.start[k], 1e-10);
    }
}

fn error(text: &str) -> ScenarioError {
    Scenario::from_str("bad.toml", text).expect_err("the scenario should be rejected")
}

/// The line of the error's location.
fn line(e: &ScenarioError) -> usize {
    e.location
        .as_ref()
        .unwrap_or_else(|| panic!("no location: {e}"))
        .line
}

const ONE_BODY: &str = r#"dimensions = 3
[[body]]
name = "ball"
mass = "1 kg"
[[rigid_body]]
name = "box"
mass = "1 kg"
inertia = [0.2, 0.5, 0.6]
points = { p = ["1 m", "0 m", "0 m"] }
[integrator]
method = "dop853"
[stop]
t_max = "1 s"
"#;

fn with(from: &str, to: &str) -> String {
    assert!(ONE_BODY.contains(from), "{from}");
    ONE_BODY.replacen(from, to, 1)
}

#[test]
fn the_base_of_the_error_cases_is_valid() {
    Scenario::from_str("ok.toml", ONE_BODY).unwrap();
}

#[test]
fn impossible_inertia_is_refused_where_it_is_written() {
    let e = error(&with(
        "inertia = [0.2, 0.5, 0.6]",
        "inertia = [[0.2, 0.3, 0], [0.3, 0.2, 0], [0, 0, 0.6]]",
    ));
    assert!(e.message.contains("positive principal moments"), "{e}");
    assert_eq!(line(&e), 8, "{e}");
    let e = error(&with(
        "inertia = [0.2, 0.5, 0.6]",
        "inertia = [0.2, -0.5, 0.6]",
    ));
    assert!(e.message.contains("positive principal moments"), "{e}");
    let e = error(&with(
        "inertia = [0.2, 0.5, 0.6]",
        "inertia = [0.2, 0.3, 0.6]",
    ));
    assert!(
        e.message.contains("the largest must be at most the sum"),
        "{e}"
    );
    assert_eq!(line(&e), 8, "{e}");
    // a thin rod is the limit the triangle inequality allows
    Scenario::from_str(
        "rod.toml",
        &with("inertia = [0.2, 0.5, 0.6]", "inertia = [0.5, 0.5, 1.0]"),
    )
    .unwrap();
}

#[test]
fn an_orientation_of_zero_length_is_refused() {
    let e = error(&with(
        "points = {",
        "orientation = [0, 0, 0, 0]\npoints = {",
    ));
    assert!(e.message.contains("is not a rotation"), "{e}");
    assert_eq!(line(&e), 9, "{e}");
    let e = error(&with(
        "points = {",
        "orientation = { axis = [0, 0, 0], angle = \"1 deg\" }\npoints = {",
    ));
    assert!(e.message.contains("no direction"), "{e}");
}

#[test]
fn a_torque_on_a_particle_is_refused() {
    let e = error(&format!(
        "{ONE_BODY}[[force]]\nname = \"motor\"\nkind = \"torque\"\non = \"ball\"\nT = [\"0 N*m\", \"0 N*m\", \"1 N*m\"]\n"
    ));
    assert!(e.message.contains("`ball` is not a rigid body"), "{e}");
    assert_eq!(line(&e), 17, "{e}");
    assert!(e.hint.as_deref().unwrap_or("").contains("box"), "{e}");
}

#[test]
fn a_force_at_an_unknown_point_is_refused() {
    let e = error(&format!(
        "{ONE_BODY}[[force]]\nname = \"push\"\nkind = \"constant\"\nF = [\"1 N\", \"0 N\", \"0 N\"]\nat = \"box.q\"\n"
    ));
    assert!(e.message.contains("`box` has no point `q`"), "{e}");
    assert!(e.message.contains("its points are: p"), "{e}");
    assert_eq!(line(&e), 18, "{e}");
    let e = error(&format!(
        "{ONE_BODY}[[force]]\nname = \"push\"\nkind = \"constant\"\nF = [\"1 N\", \"0 N\", \"0 N\"]\nat = \"ball.p\"\n"
    ));
    assert!(e.message.contains("`ball` is a particle"), "{e}");
}

#[test]
fn plane_only_joints_and_fixed_axis_torques_are_refused_in_space() {
    let e = error(&format!(
        "{ONE_BODY}[[joint]]\nname = \"wire\"\nkind = \"curve\"\non = \"box.p\"\ny = \"x^2\"\n"
    ));
    assert!(e.message.contains("works in a plane"), "{e}");
    assert!(e.hint.as_deref().unwrap_or("").contains("hinge"), "{e}");
    assert_eq!(line(&e), 16, "{e}");
    let e = error(&format!(
        "{ONE_BODY}[[torque]]\nname = \"bearing\"\nkind = \"friction\"\ntorque = \"1 N*m\"\n"
    ));
    assert!(e.message.contains("cannot have `torque`"), "{e}");
    assert!(
        e.hint.as_deref().unwrap_or("").contains("kind \"torque\""),
        "{e}"
    );
    assert_eq!(line(&e), 14, "{e}");
}

#[test]
fn the_tumbling_box_example_flips_with_the_period_of_euler_poinsot() {
    let path = workspace().join("examples/rigid/tumbling_box.toml");
    let (a, b, c, m) = (0.2, 0.12, 0.03, 0.6);
    let moments = [b * b + c * c, a * a + c * c, a * a + b * b].map(|x| m * x / 12.0);
    for (w0, eps) in [(12.0, 0.05), (5.0, 0.5), (20.0, 0.1)] {
        let set =
            ConstantOverride::parse_list(&format!("w0 = {w0} rad/s, eps = {eps} rad/s")).unwrap();
        let s = Scenario::load_with(&path, &set)
            .unwrap()
            .run()
            .unwrap()
            .summary;
        let o = &s.observables;
        let exact = Poinsot::new(moments, Vec3::new(0.0, w0, eps))
            .unwrap()
            .period();
        assert_eq!(s.stop_reason, "event");
        close(o["flip_period"], exact, 1e-7 * exact);
        assert!(o["energy_error"] < 1e-9, "{}", o["energy_error"]);
        assert!(o["L_error"] < 1e-9, "{}", o["L_error"]);
    }
}

/// A `spring` between a particle and a body point (`at` with `between`) stretches from the
/// point and keeps its potential: the same motion as the pair of formula forces above, with
/// `U` the spring's energy at the point.
#[test]
fn a_spring_kind_tied_to_a_body_point_stretches_from_the_point() {
    let springs = TETHERED.replace(
        r#"[[force]]
name = "pull_ball"
kind = "expression"
on = "ball"
F = ["-k*(ball.x - box.tip.x)", "-k*(ball.y - box.tip.y)", "-k*(ball.z - box.tip.z)"]
[[force]]
name = "pull_box"
kind = "expression"
at = "box.tip"
F = ["k*(ball.x - box.tip.x)", "k*(ball.y - box.tip.y)", "k*(ball.z - box.tip.z)"]"#,
        r#"[[force]]
name = "tether"
kind = "spring"
k = "k"
between = ["ball", "box"]
at = "box.tip""#,
    );
    assert_ne!(springs, TETHERED);
    let observe = r#"
U_point = "initial(U) - initial(k/2*((ball.x - box.tip.x)^2 + (ball.y - box.tip.y)^2 + (ball.z - box.tip.z)^2))"
E_error = "(max(E) - min(E))/initial(K)"
x_end = "final(ball.x)"
w_end = "final(box.wz)"
"#;
    let spring = run_text(&space(&springs, 1e-12, 2.0, observe));
    let formulas = run_text(&space(
        TETHERED,
        1e-12,
        2.0,
        r#"
x_end = "final(ball.x)"
w_end = "final(box.wz)"
"#,
    ));
    let o = &spring.observables;
    assert!(o["U_point"].abs() < 1e-12, "{}", o["U_point"]);
    assert!(o["E_error"] < 1e-9, "{}", o["E_error"]);
    close(o["x_end"], formulas.observables["x_end"], 1e-8);
    close(o["w_end"], formulas.observables["w_end"], 1e-8);
}

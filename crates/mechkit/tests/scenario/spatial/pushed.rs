//! Forces at body points, a spinning body thrown in gravity, the orientation, bodies of
//! parts, and springs tied to body points.

use super::*;

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

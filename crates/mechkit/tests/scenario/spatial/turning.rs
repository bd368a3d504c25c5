//! Free turning (the symmetric top, small oscillations, the tennis-racket flip) and torques
//! that spin a body up or brake it.

use super::*;

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

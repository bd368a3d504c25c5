//! The heavy top: steady precession and the nutation's bottom against the closed forms.

use super::*;

// ---------------------------------------------------------------------------------------
// 3. The heavy top

const TOP: &str = "rigid/heavy_top.toml";

fn run_top(set: &str) -> Summary {
    let path = workspace().join("examples").join(TOP);
    Scenario::load_with(&path, &ConstantOverride::parse_list(set).unwrap())
        .unwrap_or_else(|e| panic!("{e}"))
        .run()
        .unwrap()
        .summary
}

#[test]
fn heavy_top_precesses_steadily_at_the_slow_root() {
    for (w3, tilt) in [(150.0, 30.0_f64.to_radians()), (200.0, 0.3), (400.0, 1.2)] {
        let s = run_top(&format!("w3 = {w3}, tilt = {tilt}"));
        let o = &s.observables;
        let w = o["W"];
        // the slow root, near the fast-top approximation m g l / (I3 ω3)
        let (m, l, i1, i3) = (0.5, 0.04, 2e-4, 3e-4);
        let a = (i1 + m * l * l - i3) * tilt.cos();
        let slow = (i3 * w3 - ((i3 * w3).powi(2) - 4.0 * a * m * G * l).sqrt()) / (2.0 * a);
        close(w, slow, 1e-12 * slow);
        close(o["precession"], w, 1e-6 * w);
        assert!(o["nutation"] < 1e-9, "{w3} {tilt}: {o:?}");
        assert!(o["drift"] < 1e-9, "{o:?}");
        close(o["pivot_work"], 0.0, 1e-9);
        close(s.work["pivot"], 0.0, 1e-9);
    }
}

/// The example's top released with its spin alone (no precession): it nods down to the
/// other root of the turning points and precesses on average.
fn top_released(w3: f64, tilt: f64) -> String {
    let text = std::fs::read_to_string(workspace().join("examples").join(TOP)).unwrap();
    let from_v = "velocity = [\"W*l*sin(tilt)\", 0, 0]";
    let from_w = "\"w3*cos(tilt) + W\"";
    assert!(text.contains(from_v) && text.contains(from_w));
    text.replace(from_v, "velocity = [0, 0, 0]")
        .replace(from_w, "\"w3*cos(tilt)\"")
        .replace("w3 = \"150 rad/s\"", &format!("w3 = \"{w3} rad/s\""))
        .replace("tilt = \"30 deg\"", &format!("tilt = {tilt}"))
        + "z_min = \"min(top.z)\"\nenergy_error = \"max(E) - min(E)\"\n\
           [[event]]\nname = \"bottom\"\nfunction = \"top.vz\"\ndirection = \"rising\"\n"
}

#[test]
fn heavy_top_released_without_precession_nods_to_the_closed_form_bottom() {
    let (m, l, i1, i3) = (0.5_f64, 0.04_f64, 2e-4_f64, 3e-4_f64);
    for (w3, tilt) in [(150.0_f64, 0.5_f64), (100.0, 0.3), (300.0, 1.0)] {
        let s = run_text(&top_released(w3, tilt));
        // turning points from E, L_z and L_3: with u = cos θ, L3 = I3 ω3, J = I1 + m l²,
        // (u0 − u) L3² = 2 J m g l (1 − u²); the start u0 is one root, the bottom the other
        let (j, l3, u0) = (i1 + m * l * l, i3 * w3, tilt.cos());
        let beta = 2.0 * j * m * G * l / (l3 * l3);
        let u1 = (1.0 - (1.0 - 4.0 * beta * (u0 - beta)).sqrt()) / (2.0 * beta);
        let bottoms = s
            .events
            .iter()
            .filter(|e| e.name == "bottom")
            .collect::<Vec<_>>();
        assert!(!bottoms.is_empty(), "{:?}", s.events);
        for b in &bottoms {
            close(b.state["top"].position[2], l * u1, 1e-9 * l);
        }
        close(s.observables["z_min"], l * u1, 1e-6 * l);
        assert!(s.observables["energy_error"] < 1e-10, "{:?}", s.observables);
        close(s.work["pivot"], 0.0, 1e-9);

        // the library's own heavy top, from the same start, at t = 0.5 s
        let top = SpinningBody::on_pivot(
            FreeBody::new([i1, i1, i3], m).unwrap(),
            Vec3::new(0.0, 0.0, l),
            G,
        )
        .unwrap();
        let turn = UnitQuaternion::from_axis_angle(&Vector3::x_axis(), tilt);
        let start = top.attitude(turn, Vec3::new(0.0, 0.0, w3)).unwrap();
        let spin = top.simulate(&start, 0.5, &SpinOptions::default()).unwrap();
        let cm = spin.end.q * Vec3::new(0.0, 0.0, l);
        close3(&s.bodies["top"].position, [cm.x, cm.y, cm.z], 1e-8 * l);
        let omega = top.omega_world(&spin.end);
        let got = s.bodies["top"].spin.unwrap().omega;
        close3(&got, [omega.x, omega.y, omega.z], 1e-7 * w3);
    }
}

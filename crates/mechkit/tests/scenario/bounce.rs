//! Issue 28: a 0.1 kg ball of radius 1 cm dropped from 1 mm on a stiff Hertz floor
//! (k = 10¹⁰ N/m^1.5) with light Hunt-Crossley damping (α = 2 s/m), so it bounces many times
//! in 0.5 s. `radau5` ended 1.4 mm above the drop height (energy from nowhere): the Newton
//! iteration of the first step into the floor stopped after one pass on the contraction rate
//! remembered from free flight. Now it ends where a tight DOP853 run does, at every tolerance.

use mechkit::scenario::Scenario;

const REPRO: &str = include_str!("bounce_repro.toml");

fn run(method: &str, rtol: &str) -> mechkit::scenario::Summary {
    let text = REPRO
        .replace("method = \"radau5\"", &format!("method = \"{method}\""))
        .replace("rtol = 1e-8", &format!("rtol = {rtol}"));
    Scenario::from_str("bounce_repro.toml", &text)
        .unwrap()
        .run()
        .unwrap()
        .summary
}

#[test]
fn radau5_ends_where_dop853_does_on_a_bouncing_ball() {
    let reference = run("dop853", "1e-12");
    let x_ref = reference.observables["x_end"];
    let e0 = reference.kinetic_energy.start.unwrap() + reference.potential_energy.start.unwrap();
    for rtol in ["1e-6", "1e-8", "1e-11"] {
        let s = run("radau5", rtol);
        let x = s.observables["x_end"];
        assert!((x - x_ref).abs() < 1e-6, "rtol {rtol}: {x} vs {x_ref}");
        let e = s.kinetic_energy.end.unwrap() + s.potential_energy.end.unwrap();
        assert!(
            e < e0,
            "rtol {rtol}: energy {e} J at the end, {e0} J at the start"
        );
    }
}

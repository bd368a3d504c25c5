//! Power: a simulated engine force `P/v` reproduces the closed form of constant-power motion,
//! and the summary's average power of that force is `P`.

use mechkit::energy::ConstantPower;
use mechkit::scenario::Scenario;

const ENGINE: &str = r#"
title = "Motorbike at constant power, from 1 m/s"
dimensions = 1

[constants]
P = "20 kW"

[[body]]
name     = "bike"
mass     = "200 kg"
velocity = "1 m/s"

[[force]]
name = "engine"
kind = "expression"
F    = "P/v"

[integrator]
method = "dop853"
rtol   = 1e-11
atol   = 1e-11

[stop]
t_max = "5 s"

[observe]
v = "final(v)"
x = "final(x)"
P_mean = "mean(power.engine)"
"#;

#[test]
fn simulated_engine_matches_the_closed_form() {
    let out = Scenario::from_str("engine.toml", ENGINE)
        .unwrap()
        .run()
        .unwrap();
    let s = &out.summary;
    let exact = ConstantPower::new(20e3, 200.0, 1.0, 0.0).unwrap();
    let (v, x) = (s.observables["v"], s.observables["x"]);
    assert!(
        (v - exact.speed(5.0)).abs() < 1e-8 * v,
        "{v} vs {}",
        exact.speed(5.0)
    );
    assert!(
        (x - exact.position(5.0)).abs() < 1e-8 * x,
        "{x} vs {}",
        exact.position(5.0)
    );
    // the work of the engine is P t, so its average power is P
    let p = s.average_power["engine"].unwrap();
    assert!((p - 20e3).abs() < 1e-6 * 20e3, "{p}");
    assert!((s.observables["P_mean"] - 20e3).abs() < 1e-6 * 20e3);
    assert!((s.work["engine"] - exact.work(5.0)).abs() < 1e-6 * exact.work(5.0));
}

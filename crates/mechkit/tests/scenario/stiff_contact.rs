//! A ball dropped 1 mm on a stiff Hertz floor (k = 10¹⁰ N/m^1.5, issue 28) with `radau5` and
//! `bdf`: the contact law gives the implicit methods its exact Jacobian, compiled (no force
//! evaluations spent on differences), and the run ends where a tight DOP853 run does, at the
//! static compression `(m g/k)^(2/3)`. The Hunt-Crossley damping, α = 2000 s/m, makes the
//! ball stick at the first touch (`α v ≈ 280`) and the oscillation about the rest overdamped
//! (`α m g` against `2 sqrt(1.5 k sqrt(δ) m)` ≈ 1660 N·s/m): a stiff problem, with
//! eigenvalues near -10⁴ 1/s and a slow mode, that the explicit pair crosses in steps held by
//! stability.

use mechkit::forces::{ContactDamping, ContactForce, ContactLaw, Force, UniformGravity};
use mechkit::ode::{AdaptiveConfig, Method, State, Tolerance};
use mechkit::particles::{CompiledJacobian, Kinematics, ParticleSystem};
use mechkit::scenario::Scenario;
use mechkit::simulate::{RunReport, Simulation};

const DROP: &str = r#"
dimensions = 1
[[body]]
name = "ball"
mass = "0.1 kg"
radius = "1 cm"
position = "11 mm"
velocity = "0 m/s"
[[force]]
name = "gravity"
kind = "uniform-gravity"
g = "9.81 m/s^2"
[[wall]]
name = "floor"
point = "0 m"
normal = 1
[contact]
model = "hertz"
stiffness = 1e10
damping = 2000.0
[integrator]
method = "METHOD"
rtol = RTOL
atol = 1e-12
[stop]
t_max = "0.5 s"
[observe]
x_end = "final(x)"
"#;

fn scenario(method: &str, rtol: &str) -> Scenario {
    let text = DROP.replace("METHOD", method).replace("RTOL", rtol);
    Scenario::from_str("drop.toml", &text).unwrap()
}

#[test]
fn radau5_and_bdf_settle_where_dop853_does_with_the_compiled_jacobian() {
    let reference = scenario("dop853", "1e-12").run().unwrap().summary;
    let x_ref = reference.observables["x_end"];
    let rest = 0.01 - (0.1_f64 * 9.81 / 1e10).powf(2.0 / 3.0);
    let depth = 0.01 - rest;
    assert!((x_ref - rest).abs() < 1e-6 * depth, "{x_ref} vs {rest}");
    for method in ["radau5", "bdf"] {
        let sc = scenario(method, "1e-8");
        assert!(
            CompiledJacobian::build(&sc.system).is_some(),
            "{method}: the contact's Jacobian is compiled"
        );
        let s = sc.run().unwrap().summary;
        let x = s.observables["x_end"];
        assert!((x - x_ref).abs() < 1e-6 * depth, "{method}: {x} vs {x_ref}");
        assert!(
            s.steps * 2 < reference.steps && s.evaluations * 5 < reference.evaluations,
            "{method}: {} steps, {} evaluations; DOP853 at 1e-12: {}, {}",
            s.steps,
            s.evaluations,
            reference.steps,
            reference.evaluations
        );
    }
}

/// The contact with its `emit` hidden: the implicit methods then take differences.
#[derive(Debug)]
struct Opaque(Box<dyn Force>);

impl Force for Opaque {
    fn name(&self) -> &str {
        self.0.name()
    }
    fn add_forces(&self, k: &Kinematics<'_>, out: &mut [f64]) {
        self.0.add_forces(k, out);
    }
    fn potential(&self, k: &Kinematics<'_>) -> Option<f64> {
        self.0.potential(k)
    }
    fn velocity_dependent(&self) -> bool {
        self.0.velocity_dependent()
    }
    fn bodies(&self) -> Vec<usize> {
        self.0.bodies()
    }
    fn internal(&self) -> bool {
        self.0.internal()
    }
}

fn drop(method: Method, opaque: bool) -> RunReport {
    let contact = ContactForce::builder(1)
        .law(ContactLaw::hertz(1e10))
        .damping(ContactDamping::HuntCrossley { alpha: 2000.0 })
        .wall(&[0.0], &[1.0], &[(0, 0.01)])
        .build()
        .unwrap();
    let mut b = ParticleSystem::builder(1)
        .body("ball", 0.1)
        .force(UniformGravity::new("gravity", vec![0], 9.81));
    for f in contact.into_forces() {
        b = if opaque {
            b.force(Opaque(f))
        } else {
            b.boxed_force(f)
        };
    }
    let sys = b.build().unwrap();
    assert_eq!(CompiledJacobian::build(&sys).is_some(), !opaque);
    let config = AdaptiveConfig {
        rtol: Tolerance::Scalar(1e-8),
        atol: Tolerance::Scalar(1e-12),
        ..AdaptiveConfig::default()
    };
    Simulation::adaptive(&sys, method, config)
        .t_max(0.5)
        .run(State::from_qv(0.0, &[0.011], &[0.0]), &mut [])
        .unwrap()
}

/// Each Jacobian by differences costs one evaluation per component of the augmented state
/// (position, velocity and the three forces' work); the compiled one costs none, so the
/// compiled runs take fewer evaluations for the same answer.
#[test]
fn the_compiled_jacobian_saves_the_evaluations_of_differences() {
    for method in [Method::Radau5, Method::Bdf] {
        let (exact, differences) = (drop(method, false), drop(method, true));
        let (x, y) = (exact.final_state.y[0], differences.final_state.y[0]);
        assert!((x - y).abs() < 1e-13, "{method:?}: {x} vs {y}");
        assert!(
            exact.evaluations < differences.evaluations,
            "{method:?}: {} evaluations compiled, {} by differences",
            exact.evaluations,
            differences.evaluations
        );
        eprintln!(
            "{method:?}: compiled {} steps {} evaluations; differences {} steps {} evaluations",
            exact.steps, exact.evaluations, differences.steps, differences.evaluations
        );
    }
}

/// Two balls tied by a stiff pair potential (a bond of 10⁶ N/m) hit a damped spring floor:
/// pair potentials and spring contacts are compiled into the Jacobian too, and radau5 ends
/// where a tight DOP853 run does. (The bond is undamped: its fast oscillation has to be
/// followed, which no implicit method does in fewer steps than DOP853.)
#[test]
fn pair_potentials_and_spring_contacts_are_compiled_too() {
    let text = r#"
dimensions = 2
[constants]
kb = "1e6 N/m"
L = "0.1 m"
[[body]]
name = "a"
mass = "0.1 kg"
radius = "2 cm"
position = ["0 m", "0.021 m"]
velocity = ["0.2 m/s", "0 m/s"]
[[body]]
name = "b"
mass = "0.1 kg"
radius = "2 cm"
position = ["0.1 m", "0.05 m"]
velocity = ["0 m/s", "0 m/s"]
[[force]]
name = "gravity"
kind = "uniform-gravity"
g = "9.81 m/s^2"
[[force]]
name = "bond"
kind = "pair"
between = ["a", "b"]
U = "kb*(r - L)^2/2"
cutoff = "1 m"
[[wall]]
name = "floor"
point = ["0 m", "0 m"]
normal = [0, 1]
[contact]
model = "spring"
stiffness = 1e6
damping = 200
[integrator]
method = "METHOD"
rtol = RTOL
atol = 1e-12
[stop]
t_max = "0.03 s"
[observe]
ya = "final(a.y)"
xb = "final(b.x)"
"#;
    let sc = |method: &str, rtol: &str| {
        let t = text.replace("METHOD", method).replace("RTOL", rtol);
        Scenario::from_str("bond.toml", &t).unwrap()
    };
    let reference = sc("dop853", "1e-12").run().unwrap().summary;
    let implicit = sc("radau5", "1e-9");
    assert!(CompiledJacobian::build(&implicit.system).is_some());
    let s = implicit.run().unwrap().summary;
    for key in ["ya", "xb"] {
        let (x, r) = (s.observables[key], reference.observables[key]);
        assert!((x - r).abs() < 1e-7, "{key}: {x} vs {r}");
    }
    // the floor was hit: its damper took energy
    assert!(s.work["contact_damping"] < -1e-5, "{:?}", s.work);
}

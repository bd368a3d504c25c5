//! Head-on contacts of two balls on a line against their closed forms: an elastic contact of
//! equal balls exchanges their velocities, lasts half a period `π sqrt(m/k)` of the reduced
//! mass and keeps `K + U_elastic`; the linear spring-dashpot's restitution is
//! `exp(-π ζ/sqrt(1-ζ²))` with attraction, or Schwager and Pöschel's when the force is clamped
//! at zero; a Hertz contact reaches `δ_max = (5 m v²/(4k))^(2/5)` and lasts `2.943 δ_max/v`.

use mechkit::forces::{
    ContactDamping, ContactForce, ContactLaw, hertz_contact_time, hertz_max_overlap,
    linear_contact_time, linear_restitution, linear_restitution_clamped,
};
use mechkit::particles::Sample;
use mechkit::prelude::*;
use mechkit::simulate::{Observer, RunReport};

use super::setup::{EnergyWatch, dop853, system};

/// Two balls on a line (R = 0.1 m each) approaching at `v` each: the run, with events at the
/// touch, the deepest overlap and the parting.
fn head_on(
    law: ContactLaw,
    damping: ContactDamping,
    attraction: bool,
    masses: [f64; 2],
    v: f64,
    watch: &mut EnergyWatch,
) -> RunReport {
    let contact = ContactForce::builder(1)
        .law(law)
        .damping(damping)
        .allow_attraction(attraction)
        .spheres(&[(0, 0.1), (1, 0.1)])
        .build()
        .unwrap();
    let sys = system(1, &masses, contact, vec![]);
    let overlap = |s: &Sample<'_>, _: &ParticleSystem| 0.2 - (s.q[1] - s.q[0]);
    Simulation::adaptive(&sys, Method::Dop853, dop853(1e-12))
        .t_max(0.4)
        .event(Event::new("touch", overlap).direction(Direction::Rising))
        .event(Event::new("part", overlap).direction(Direction::Falling))
        .event(Event::new("deepest", |s, _| s.v[1] - s.v[0]).direction(Direction::Rising))
        .run(
            State::from_qv(0.0, &[0.0, 0.5], &[v, -v]),
            &mut [watch as &mut dyn Observer],
        )
        .unwrap()
}

fn event_time(r: &RunReport, name: &str) -> f64 {
    r.events.iter().find(|e| e.name == name).unwrap().t
}

fn deepest_overlap(r: &RunReport) -> f64 {
    let q = &r
        .events
        .iter()
        .find(|e| e.name == "deepest")
        .unwrap()
        .state
        .q;
    0.2 - (q[1] - q[0])
}

fn apart(q: &[f64]) -> bool {
    q[1] - q[0] > 0.2
}

#[test]
fn equal_balls_exchange_velocities_in_an_elastic_linear_contact() {
    let (k, m) = (1e4, 1.0);
    let mut watch = EnergyWatch::with_apart(apart);
    let r = head_on(
        ContactLaw::linear(k),
        ContactDamping::None,
        false,
        [m, m],
        1.0,
        &mut watch,
    );
    let v = &r.final_state.y[2..];
    let duration = event_time(&r, "part") - event_time(&r, "touch");
    let exact = linear_contact_time(k, m / 2.0);
    let e0 = r.ledger.energy().0;
    println!(
        "linear: v = {v:?}, contact {duration:.9} s (exact {exact:.9}), max |ΔE|/E = {:e}, \
         U_max = {} J, {} steps",
        watch.max_dev / e0,
        watch.max_u,
        r.steps
    );
    assert!(
        (v[0] + 1.0).abs() < 1e-6 && (v[1] - 1.0).abs() < 1e-6,
        "{v:?}"
    );
    assert!((duration - exact).abs() < 1e-3 * exact);
    assert!(watch.max_dev < 1e-8 * e0);
    // all the kinetic energy (1 J) is elastic at the deepest point, none when apart
    assert!((watch.max_u - 1.0).abs() < 1e-8, "{}", watch.max_u);
    assert_eq!(watch.u_apart, 0.0);
    // and the deepest overlap is v_rel sqrt(m_red/k)
    assert!((deepest_overlap(&r) - 2.0 * (0.5 / k).sqrt()).abs() < 1e-9);
}

#[test]
fn spring_dashpot_restitution_matches_the_closed_forms() {
    let (k, masses): (f64, [f64; 2]) = (1e4, [1.0, 3.0]);
    let m_red = 0.75;
    for zeta in [0.05, 0.2, 0.5] {
        let c = 2.0 * zeta * (k * m_red).sqrt();
        for (attraction, exact) in [
            (true, linear_restitution(k, c, m_red)),
            (false, linear_restitution_clamped(k, c, m_red)),
        ] {
            let mut watch = EnergyWatch::default();
            let r = head_on(
                ContactLaw::linear(k),
                ContactDamping::Linear { c },
                attraction,
                masses,
                1.0,
                &mut watch,
            );
            let v = &r.final_state.y[2..];
            let e = (v[1] - v[0]) / 2.0;
            println!(
                "ζ = {zeta}, attraction {attraction}: e = {e:.9}, closed form {exact:.9}, \
                 error {:e}",
                e - exact
            );
            assert!((e - exact).abs() < 1e-4, "ζ = {zeta}: {e} vs {exact}");
            // momentum is conserved through the contact
            assert!((masses[0] * v[0] + masses[1] * v[1] - (1.0 - 3.0)).abs() < 1e-9);
        }
    }
}

#[test]
fn hertz_contact_reaches_the_closed_form_overlap_and_is_elastic() {
    let (k, m, v) = (1e6, 1.0, 1.0);
    let mut watch = EnergyWatch::with_apart(apart);
    let r = head_on(
        ContactLaw::hertz(k),
        ContactDamping::None,
        false,
        [m, m],
        v,
        &mut watch,
    );
    let (d, exact) = (deepest_overlap(&r), hertz_max_overlap(k, m / 2.0, 2.0 * v));
    let duration = event_time(&r, "part") - event_time(&r, "touch");
    let t_exact = hertz_contact_time(k, m / 2.0, 2.0 * v);
    let vf = &r.final_state.y[2..];
    println!(
        "hertz: δ_max = {d:.9} m (closed form {exact:.9}), contact {duration:.9} s \
         ({t_exact:.9}), v = {vf:?}, max |ΔE|/E = {:e}",
        watch.max_dev / r.ledger.energy().0
    );
    assert!((d - exact).abs() < 1e-4 * exact);
    assert!((duration - t_exact).abs() < 1e-4 * t_exact);
    assert!((vf[0] + v).abs() < 1e-6 && (vf[1] - v).abs() < 1e-6);
    assert!(watch.max_dev < 1e-8 * r.ledger.energy().0);
}

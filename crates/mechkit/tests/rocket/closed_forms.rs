//! Without drag the simulated flight must reproduce the rocket equation's closed forms: in free
//! space Tsiolkovsky's `Δv = u ln(m0/m1)`; in uniform gravity `v(T) = u ln(m0/m1) − g T` and
//! `x(T) = u T − (u m1/ṁ) ln(m0/m1) − g T²/2` at burnout, and the ballistic apex
//! `x1 + v1²/(2g)` after it.

use super::{config, rocket};

#[test]
fn free_space_delta_v_is_tsiolkovsky() {
    let r = rocket();
    let run = r.simulate(&config(1e-12), true).unwrap();
    let (t1, _, v1) = run.burnout;
    let exact = 2000.0 * (1000.0f64 / 400.0).ln();
    assert_eq!(r.delta_v(), exact);
    let rel = (v1 - exact).abs() / exact;
    println!(
        "free space: Δv = {v1} m/s, u ln(m0/m1) = {exact}, relative error {rel:e}, {:?}",
        run.stats
    );
    assert!(rel < 1e-10, "{rel:e}");
    assert_eq!(t1, 60.0);
    // no gravity: no apex, and the coast is not integrated
    assert_eq!(run.apex, None);
    assert_eq!(run.samples.last().unwrap().0, t1);
}

#[test]
fn burnout_in_gravity_matches_the_closed_forms() {
    let r = rocket().with_gravity(9.81).unwrap();
    let run = r.simulate(&config(1e-12), false).unwrap();
    let (t1, x1, v1) = run.burnout;
    let (t_c, x_c, v_c) = r.burnout();
    assert_eq!(t1, t_c);
    // the textbook form of x(T), written out
    let (u, m0, m1, rate, g) = (2000.0, 1000.0f64, 400.0, 10.0, 9.81);
    let x_book = u * t1 - u * m1 / rate * (m0 / m1).ln() - 0.5 * g * t1 * t1;
    assert!((x_c - x_book).abs() < 1e-12 * x_book, "{x_c} {x_book}");
    let (ev, ex) = ((v1 - v_c).abs() / v_c, (x1 - x_c).abs() / x_c);
    println!(
        "gravity: v(T) = {v1} vs {v_c} (relative {ev:e}), x(T) = {x1} vs {x_c} (relative {ex:e})"
    );
    assert!(ev < 1e-9 && ex < 1e-9, "{ev:e} {ex:e}");
    // every sample of the burn lies on the closed forms
    let worst = run
        .samples
        .iter()
        .map(|&(t, x, v, m)| {
            assert!((m - r.mass(t)).abs() < 1e-9 * m);
            ((v - r.speed(t)).abs() / v_c).max((x - r.height(t)).abs() / x_c)
        })
        .fold(0.0, f64::max);
    assert!(worst < 1e-9, "{worst:e}");
}

#[test]
fn the_coast_ends_at_the_ballistic_apex() {
    let r = rocket().with_gravity(9.81).unwrap();
    let run = r.simulate(&config(1e-12), true).unwrap();
    let (t1, x1, v1) = run.burnout;
    let (t_top, x_top) = run.apex.unwrap();
    let g = 9.81;
    let (t_book, x_book) = (t1 + v1 / g, x1 + v1 * v1 / (2.0 * g));
    let (et, ex) = (
        (t_top - t_book).abs() / t_book,
        (x_top - x_book).abs() / x_book,
    );
    println!("apex: t = {t_top} vs {t_book} ({et:e}), x = {x_top} vs {x_book} ({ex:e})");
    assert!(et < 1e-10 && ex < 1e-10, "{et:e} {ex:e}");
    let (_, x_closed) = r.apex().unwrap();
    assert!((x_top - x_closed).abs() < 1e-9 * x_closed);
    // the samples end on the apex, with zero speed and the burnout mass
    let &(t, x, v, m) = run.samples.last().unwrap();
    assert_eq!((t, x, m), (t_top, x_top, 400.0));
    assert!(v.abs() < 1e-9 * v1, "{v:e}");
}

#[test]
fn a_rocket_too_weak_to_lift_off_sinks_and_its_apex_is_burnout() {
    // thrust 20 kN against a weight of 35 kN at ignition
    let r = rocket().with_gravity(35.0).unwrap();
    assert!(!r.lifts_off());
    let run = r.simulate(&config(1e-10), true).unwrap();
    assert!(run.samples[1].2 < 0.0);
    let (t1, x1, v1) = run.burnout;
    assert!(v1 < 0.0);
    assert_eq!(run.apex, Some((t1, x1)));
    assert_eq!(r.apex(), Some((t1, r.burnout().1)));
}

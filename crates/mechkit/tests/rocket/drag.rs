//! Quadratic drag `F = −D v|v|` has no closed form here: the simulation is the answer. It must
//! slow the rocket (burnout speed and apex below the drag-free ones) and converge: halving the
//! tolerance changes the result by less than the tolerance.

use super::{config, rocket};

#[test]
fn drag_slows_the_rocket() {
    let free = rocket().with_gravity(9.81).unwrap();
    let r = free.with_drag(0.02).unwrap();
    let run = r.simulate(&config(1e-10), true).unwrap();
    let (_, x1, v1) = run.burnout;
    let (_, x_free, v_free) = free.burnout();
    println!("drag: v(T) = {v1} < {v_free}, x(T) = {x1} < {x_free}");
    assert!(v1 < v_free && x1 < x_free);
    assert!(v1 > 0.0);
    assert!(run.apex.unwrap().1 < free.apex().unwrap().1);
    // D = 0 is no drag
    let zero = free
        .with_drag(0.0)
        .unwrap()
        .simulate(&config(1e-10), true)
        .unwrap();
    let plain = free.simulate(&config(1e-10), true).unwrap();
    assert_eq!(zero.burnout, plain.burnout);
}

#[test]
fn halving_the_tolerance_changes_less_than_the_tolerance() {
    let r = rocket()
        .with_gravity(9.81)
        .unwrap()
        .with_drag(0.02)
        .unwrap();
    for rtol in [1e-6, 1e-8, 1e-10] {
        let a = r.simulate(&config(rtol), true).unwrap();
        let b = r.simulate(&config(rtol / 2.0), true).unwrap();
        let dv = (a.burnout.2 - b.burnout.2).abs() / b.burnout.2;
        let dx = (a.burnout.1 - b.burnout.1).abs() / b.burnout.1;
        let (ta, xa) = a.apex.unwrap();
        let (tb, xb) = b.apex.unwrap();
        let (dt, dh) = ((ta - tb).abs() / tb, (xa - xb).abs() / xb);
        println!(
            "rtol {rtol:e}: burnout v {dv:.1e}, x {dx:.1e}; apex t {dt:.1e}, x {dh:.1e}; {} vs {} steps",
            a.stats.accepted, b.stats.accepted
        );
        for d in [dv, dx, dt, dh] {
            assert!(d < rtol, "{d:e} at rtol {rtol:e}");
        }
    }
}

//! A tennis ball dropped from 1.6 m, its height recorded every millisecond
//! (`examples/data/fallingtennisball02.txt`, a copy of the course's file): velocity by central
//! differences, acceleration by a Savitzky-Golay derivative of the velocity (window 21 ms,
//! order 2). Before the ball first reaches the floor (at 0.580 s) it falls freely under gravity
//! and quadratic air drag, `a = −g + k v²`: the acceleration starts at −9.8 m/s² and its size
//! shrinks as the ball speeds up.
//!
//! The file turns out to be smooth to its 16 digits (its fourth differences are 3e-13 m), so
//! smoothing changes the velocity by 3e-7 m/s at the first sample (where the one-sided
//! difference and the edge fit differ) and by 2e-10 m/s after it, and the fit of the drag law
//! leaves residuals of 2e-4 m/s²: g = 9.79995 m/s², k = 0.0245 1/m.

use mechkit::Real;
use mechkit::data::{ColumnRef, Table};
use mechkit::deriv::{Difference, SavitzkyGolay, differentiate, second_derivative, uniform_step};

use crate::util::workspace;

const G: Real = 9.8;

struct Fall {
    t: Vec<Real>,
    y: Vec<Real>,
    /// Velocity by central differences.
    v: Vec<Real>,
    /// Velocity smoothed.
    v_smooth: Vec<Real>,
    /// Acceleration: Savitzky-Golay derivative of `v`.
    a: Vec<Real>,
    /// Rows of free fall: up to 20 ms (a window) before the first contact with the floor.
    free: usize,
}

fn fall() -> Fall {
    let path = workspace().join("examples/data/fallingtennisball02.txt");
    let table = Table::read(&path).unwrap_or_else(|e| panic!("{e}"));
    let (t, _) = table
        .abscissa(&ColumnRef::number(1), "the derivative")
        .unwrap();
    let y = table.column(&ColumnRef::number(2)).unwrap();
    let h = uniform_step(t).expect("one sample per millisecond");
    assert!((h - 1e-3).abs() < 1e-12, "{h}");

    let v = differentiate(t, y, Difference::Central).unwrap();
    let filter = SavitzkyGolay::new(21, 2).unwrap();
    let v_smooth = filter.smooth(&v);
    let a = filter.differentiate(t, &v, 1).unwrap();

    let contact = (1..y.len()).find(|&i| y[i] > y[i - 1]).unwrap() - 1;
    assert!(
        (t[contact] - 0.580).abs() < 1e-9,
        "first contact at {}",
        t[contact]
    );
    let free = t.iter().take_while(|&&ti| ti <= t[contact] - 0.020).count();
    Fall {
        t: t.to_vec(),
        y: y.to_vec(),
        v,
        v_smooth,
        a,
        free,
    }
}

#[test]
fn released_from_rest_at_1_6_m() {
    let f = fall();
    assert_eq!(f.y[0], 1.6);
    assert!(f.v[0].abs() < 1e-3, "v(0) = {}", f.v[0]);
    // 0.1 s later: v ≈ −g t, slightly less because of drag.
    let i = f.t.iter().position(|&t| (t - 0.1).abs() < 1e-9).unwrap();
    assert!(
        (f.v_smooth[i] + 0.979).abs() < 1e-3,
        "v(0.1) = {}",
        f.v_smooth[i]
    );
}

#[test]
fn the_first_tenth_of_a_second_is_free_fall_at_g() {
    let f = fall();
    let early = f.t.iter().take_while(|&&t| t <= 0.1 + 1e-9).count();
    assert_eq!(early, 101);
    for (i, a) in f.a[..early].iter().enumerate() {
        assert!((a + G).abs() < 0.005 * G, "a({}) = {a}", f.t[i]);
    }
    // The unsmoothed second derivative agrees: the data has no noise to speak of.
    let a_raw = second_derivative(&f.t, &f.y).unwrap();
    for ((raw, a), t) in a_raw.iter().zip(&f.a).zip(&f.t).take(early) {
        assert!((raw - a).abs() < 1e-3, "t = {t}");
    }
}

#[test]
fn drag_reduces_the_acceleration_as_the_ball_speeds_up() {
    let f = fall();
    let mut a: Vec<Real> = f.a[..f.free].to_vec();
    a.sort_by(Real::total_cmp);
    let median = a[a.len() / 2];
    assert!(median > -G && median < -0.95 * G, "median {median}");
    assert!((median + 9.618).abs() < 0.01, "median {median}");
    // Smoothing a noiseless velocity changes nothing that matters.
    for i in 0..f.free {
        let tolerance = if i < 10 { 1e-6 } else { 1e-9 };
        assert!((f.v_smooth[i] - f.v[i]).abs() < tolerance, "t = {}", f.t[i]);
    }
}

#[test]
fn quadratic_drag_law_fits_the_free_fall() {
    // Least squares a = c0 + c1 v² over the free fall: c0 = −g, c1 = k.
    let f = fall();
    let (mut s, mut sx, mut sxx, mut sy, mut sxy) = (0.0, 0.0, 0.0, 0.0, 0.0);
    for i in 0..f.free {
        let (x, y) = (f.v_smooth[i].powi(2), f.a[i]);
        (s, sx, sxx, sy, sxy) = (s + 1.0, sx + x, sxx + x * x, sy + y, sxy + x * y);
    }
    let k = (s * sxy - sx * sy) / (s * sxx - sx * sx);
    let g = -(sy - k * sx) / s;
    assert!((g - G).abs() < 1e-3, "g = {g}");
    assert!((k - 0.0245).abs() < 1e-4, "k = {k}");
    let worst = (0..f.free)
        .map(|i| (f.a[i] - (-g + k * f.v_smooth[i].powi(2))).abs())
        .fold(0.0, Real::max);
    assert!(worst < 1e-3, "largest residual {worst}");
}

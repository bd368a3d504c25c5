use super::*;

fn cradle(n: usize) -> (Impacts, Vec<Real>) {
    // n touching balls of radius 0.5 along x; the first moves at 1 m/s
    let names = (0..n).map(|i| format!("b{i}")).collect();
    let imp = Impacts::new(1, names, vec![1.0; n], vec![Some(0.5); n]);
    let mut y: Vec<Real> = (0..n).map(|i| i as Real).collect();
    y.resize(2 * n, 0.0);
    y[n] = 1.0;
    (imp, y)
}

#[test]
fn newtons_cradle_hands_the_velocity_down_the_line() {
    for n in [2, 3, 5] {
        let (imp, mut y) = cradle(n);
        assert!(imp.overlap(&y[..n]).is_none());
        let applied = imp.resolve_contacts(&mut y);
        let v = &y[n..];
        assert_eq!(v[n - 1], 1.0, "{n}: {v:?}");
        assert!(v[..n - 1].iter().all(|&x| x == 0.0), "{n}: {v:?}");
        assert_eq!(applied, n - 1);
    }
}

#[test]
fn overlaps_and_walls() {
    let imp = Impacts::new(
        2,
        vec!["a".into(), "b".into()],
        vec![1.0, 1.0],
        vec![Some(0.1), Some(0.1)],
    )
    .with_wall(
        Wall::new(
            "floor",
            vec![0.0, 0.0],
            &[0.0, 2.0],
            Restitution::ELASTIC,
            0.0,
        )
        .unwrap(),
    );
    let o = imp.overlap(&[0.0, 0.5, 0.15, 0.5]).unwrap();
    assert_eq!((o.body, o.other), (0, Some(1)));
    assert!((o.depth - 0.05).abs() < 1e-12);
    let o = imp.overlap(&[0.0, 0.05, 1.0, 0.5]).unwrap();
    assert_eq!((o.body, o.wall), (0, Some(0)));
    // a ball on the floor moving down bounces; one moving up is left alone
    let mut y = vec![0.0, 0.1, 1.0, 0.5, 0.0, -2.0, 0.0, 0.0];
    assert_eq!(imp.resolve_contacts(&mut y), 1);
    assert_eq!(y[5], 2.0);
    assert_eq!(imp.resolve_contacts(&mut y), 0);
}

/// One 60 g ball of radius `r` and an elastic floor through the origin with normal (1, 1).
fn on_oblique_floor(r: Real) -> Impacts {
    let floor = Wall::new(
        "floor",
        vec![0.0, 0.0],
        &[1.0, 1.0],
        Restitution::ELASTIC,
        0.0,
    )
    .unwrap();
    Impacts::new(2, vec!["ball".into()], vec![0.06], vec![Some(r)]).with_wall(floor)
}

/// Fuzz finding (scenario): a point (radius 0) falling onto a wall with normal (1, 1)
/// reached it a few ulps off the plane, outside a touching gap of 1e-9 of its radius (0):
/// the event fired and nothing bounced, and the ball fell through.
#[test]
fn fuzz_a_point_bounces_off_an_oblique_wall() {
    let imp = on_oblique_floor(0.0);
    // on the plane x + y = 0 to rounding, falling straight down
    let x = 5.0;
    let mut y = vec![x, -x + 4.0 * Real::EPSILON * x, 0.0, -7.6];
    assert!(imp.walls()[0].distance(&y[..2]) > 0.0);
    assert_eq!(imp.resolve_contacts(&mut y), 1);
    // reflected about the normal: (0, -7.6) → (7.6, 0)
    assert!((y[2] - 7.6).abs() < 1e-12 && y[3].abs() < 1e-12, "{y:?}");
}

/// Fuzz finding (scenario): a 5 cm ball bouncing on a wall with normal (1, 1) under dop853,
/// with no end, took 10.8 s for 200 steps. The wall event asked for samples in proportion to
/// the normal speed times the step, and the steps of its smooth slide grew without bound. A
/// wall's gap is signed, so a step that ends past the wall shows it at its end: only a normal
/// velocity that turns from approach to retreat inside the step needs samples.
#[test]
fn fuzz_a_wall_asks_for_samples_only_where_the_normal_velocity_turns() {
    let r = 0.05;
    let imp = on_oblique_floor(r);
    let events = imp.events();
    let [wall] = events.as_slice() else {
        panic!("one event: {}", events.len())
    };
    let state = |vx: Real, vy: Real| vec![5.0, 1.05, vx, vy];
    // sliding down the plane and pressed into it by gravity: approach only, however long the step
    for h in [1e-3, 1.0, 1e6] {
        assert_eq!(
            wall.samples_needed(&state(-3.0, 2.9), &state(-40.0, 39.0), h),
            0
        );
        assert_eq!(
            wall.samples_needed(&state(1.0, 1.0), &state(-1.0, -1.0), h),
            0
        );
    }
    // in and out again: the spacing rule, 16 samples per radius of normal travel
    let (y0, y1) = (state(-1.0, -1.0), state(1.0, 1.0));
    let u = 2.0 / Real::sqrt(2.0);
    let h = 0.01;
    let expected = (u * h / (SPACING * r)).ceil() as usize - 1;
    assert_eq!(wall.samples_needed(&y0, &y1, h), expected);
    assert!(expected > 0);
}

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

/// Fuzz finding (scenario): a point (radius 0) falling onto a wall with normal (1, 1)
/// reached it a few ulps off the plane, outside a touching gap of 1e-9 of its radius (0):
/// the event fired and nothing bounced, and the ball fell through.
#[test]
fn fuzz_a_point_bounces_off_an_oblique_wall() {
    let imp = Impacts::new(2, vec!["p".into()], vec![0.06], vec![Some(0.0)]).with_wall(
        Wall::new(
            "floor",
            vec![0.0, 0.0],
            &[1.0, 1.0],
            Restitution::ELASTIC,
            0.0,
        )
        .unwrap(),
    );
    // on the plane x + y = 0 to rounding, falling straight down
    let x = 5.0;
    let mut y = vec![x, -x + 4.0 * Real::EPSILON * x, 0.0, -7.6];
    assert!(imp.walls()[0].distance(&y[..2]) > 0.0);
    assert_eq!(imp.resolve_contacts(&mut y), 1);
    // reflected about the normal: (0, -7.6) → (7.6, 0)
    assert!((y[2] - 7.6).abs() < 1e-12 && y[3].abs() < 1e-12, "{y:?}");
}

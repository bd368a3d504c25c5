use super::super::Geometry;
use super::super::draw::convex_hull;
use super::super::scene::{Attachment, Body};
use super::*;

fn circle_run(n: usize) -> Vec<(String, Vec<Real>)> {
    let t: Vec<Real> = (0..n).map(|i| i as Real * 0.1).collect();
    let col = |f: &dyn Fn(Real) -> Real| t.iter().map(|&t| f(t)).collect::<Vec<_>>();
    vec![
        ("t".into(), t.clone()),
        ("ball.x".into(), col(&|t| t.cos())),
        ("ball.y".into(), col(&|t| t.sin())),
        ("ball.vx".into(), col(&|t| -t.sin())),
        ("ball.vy".into(), col(&|t| t.cos())),
        ("K".into(), col(&|_| 0.5)),
    ]
}

fn scene() -> Scene {
    Scene {
        dim: 2,
        bodies: vec![Body {
            name: "ball".into(),
            shape: BodyShape::Sphere { radius: 0.1 },
            hinge: None,
        }],
        items: vec![SceneItem::Spring {
            a: Attachment::Fixed([0.0; 3]),
            b: Attachment::Body {
                body: 0,
                offset: [0.0; 3],
            },
        }],
        upright: false,
    }
}

#[test]
fn hermite_frames_follow_the_circle_between_rows() {
    let table = circle_run(64);
    let options = AnimationOptions {
        fps: 25.0,
        speed: Some(1.0),
        ..AnimationOptions::default()
    };
    let a = Animation::from_run("circle", &scene(), table.as_slice(), "m", &options).unwrap();
    // 6.3 s at 25 frames per second
    assert_eq!(a.frames.len(), 159);
    for f in &a.frames {
        let Some(Geometry::Circle { centre, .. }) = f
            .shapes
            .iter()
            .map(|s| &s.geometry)
            .find(|g| matches!(g, Geometry::Circle { .. }))
        else {
            panic!("no ball")
        };
        // cubic Hermite on rows 0.1 s apart: error ~ h^4/384
        assert!((centre[0] - f.t.cos()).abs() < 1e-6, "{f:?}");
        assert!((centre[1] - f.t.sin()).abs() < 1e-6);
    }
    assert!(a.view.x_min < -1.1 && a.view.x_max > 1.1 && a.view.y_min < -1.1);
    assert_eq!(a.trails[0].points.len(), a.frames.len());
    assert_eq!(a.energy.as_ref().unwrap().labels, ["K"]);
}

#[test]
fn hulls() {
    let square = vec![[0.0, 0.0], [1.0, 0.0], [0.5, 0.5], [1.0, 1.0], [0.0, 1.0]];
    assert_eq!(convex_hull(square, 1e-12).len(), 4);
    let rod = vec![[0.0, 0.0], [1.0, 1.0], [0.5, 0.5]];
    assert_eq!(convex_hull(rod, 1e-12), [[0.0, 0.0], [1.0, 1.0]]);
}

#[test]
fn a_missing_column_is_named() {
    let mut table = circle_run(5);
    table.retain(|(n, _)| n != "ball.y");
    let e = Animation::from_run(
        "c",
        &scene(),
        table.as_slice(),
        "m",
        &AnimationOptions::default(),
    )
    .unwrap_err();
    assert!(e.to_string().contains("`ball.y`"), "{e}");
}

#[test]
fn playback_is_4_to_12_seconds_unless_a_speed_is_given() {
    let o = AnimationOptions::default();
    let (t, speed) = frame_times(0.0, 100.0, &o).unwrap();
    assert_eq!(t.len(), 301);
    assert!((speed - 100.0 / 12.0).abs() < 1e-9);
    let (t, _) = frame_times(0.0, 0.01, &o).unwrap();
    assert_eq!(t.len(), 101);
    assert!(frame_times(0.0, 1.0, &AnimationOptions { fps: 0.0, ..o }).is_err());
    let with_speed = |speed| AnimationOptions {
        speed: Some(speed),
        ..o
    };
    let (t, speed) = frame_times(0.0, 5.0, &with_speed(0.5)).unwrap();
    assert_eq!((t.len(), speed), (251, 0.5));
}

/// `--speed 1e-300` made one frame (an overflow of the frame count, a panic in a debug
/// build) and `--speed 1e300` silently became 125 s/s: a speed given is kept or refused.
#[test]
fn a_speed_that_does_not_fit_the_run_is_refused_with_the_speeds_that_do() {
    let o = AnimationOptions::default();
    for speed in [1e-300, 1e300, 0.06, 126.0] {
        let e = frame_times(
            0.0,
            5.0,
            &AnimationOptions {
                speed: Some(speed),
                ..o
            },
        )
        .unwrap_err();
        assert!(matches!(e, AnimationError::Speed { .. }), "{e}");
        assert!(e.to_string().contains("from 0.0625"), "{e}");
        assert!(e.to_string().contains("to 125 (2 frames)"), "{e}");
    }
    let (t, _) = frame_times(
        0.0,
        5.0,
        &AnimationOptions {
            speed: Some(125.0),
            ..o
        },
    )
    .unwrap();
    assert_eq!(t.len(), 2);
    let slowest = 5.0 * 25.0 / (MAX_FRAMES - 1) as Real;
    let (t, _) = frame_times(
        0.0,
        5.0,
        &AnimationOptions {
            speed: Some(slowest),
            ..o
        },
    )
    .unwrap();
    assert_eq!(t.len(), MAX_FRAMES);
}

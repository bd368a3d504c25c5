//! Every example scenario animates: at least 20 frames, a view that holds the motion, every
//! number finite, and each body drawn in its shape.

use std::path::{Path, PathBuf};

use mechkit::animation::{Animation, AnimationOptions, BodyShape, Geometry};
use mechkit::scenario::Scenario;

fn examples() -> Vec<PathBuf> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples");
    let mut out = Vec::new();
    for dir in [root.clone(), root.join("rigid"), root.join("friction")] {
        for e in std::fs::read_dir(dir).unwrap() {
            let p = e.unwrap().path();
            if p.extension().is_some_and(|x| x == "toml") {
                out.push(p);
            }
        }
    }
    out.sort();
    out
}

fn points(g: &Geometry) -> Vec<[f64; 2]> {
    match g {
        Geometry::Circle { centre, .. } | Geometry::Dot { centre, .. } => vec![*centre],
        Geometry::Polygon { points } | Geometry::Polyline { points } => points.clone(),
    }
}

#[test]
fn every_example_animates() {
    let mut done = 0;
    for path in examples() {
        let Ok(scenario) = Scenario::load(&path) else {
            continue;
        };
        let (out, trajectory) = scenario.run_with_trajectory().unwrap();
        let a = Animation::from_run(
            &out.summary.title,
            &scenario.scene,
            &trajectory,
            "m",
            &AnimationOptions::default(),
        )
        .unwrap_or_else(|e| panic!("{}: {e}", path.display()));
        assert!(
            a.frames.len() >= 20,
            "{}: {} frames",
            path.display(),
            a.frames.len()
        );
        let v = a.view;
        assert!(v.width() > 0.0 && v.height() > 0.0 && v.x_min.is_finite() && v.y_max.is_finite());
        for f in &a.frames {
            assert!(
                !f.shapes.is_empty() || scenario.scene.bodies.is_empty(),
                "{}",
                path.display()
            );
            for s in &f.shapes {
                for p in points(&s.geometry) {
                    assert!(
                        p[0].is_finite() && p[1].is_finite(),
                        "{}: {s:?}",
                        path.display()
                    );
                }
            }
        }
        // the bodies are in the view at the first frame
        for s in &a.frames[0].shapes {
            if let Geometry::Circle { centre, .. } | Geometry::Dot { centre, .. } = s.geometry {
                assert!(
                    (v.x_min..=v.x_max).contains(&centre[0])
                        && (v.y_min..=v.y_max).contains(&centre[1]),
                    "{}: {centre:?} outside {v:?}",
                    path.display()
                );
            }
        }
        done += 1;
    }
    assert!(done >= 20, "{done} examples animated");
}

#[test]
fn shapes_come_from_the_scenario() {
    let load = |p: &str| {
        Scenario::load(
            &Path::new(env!("CARGO_MANIFEST_DIR"))
                .join("../../examples")
                .join(p),
        )
        .unwrap()
    };
    let ball = load("bouncing_ball_floor.toml");
    assert!(
        matches!(ball.scene.bodies[0].shape, BodyShape::Sphere { radius } if (radius - 0.05).abs() < 1e-12)
    );
    assert!(
        ball.scene
            .items
            .iter()
            .any(|i| matches!(i, mechkit::animation::SceneItem::Wall { .. }))
    );
    let pendulum = load("rigid/physical_pendulum.toml");
    assert!(pendulum.scene.bodies[0].hinge.is_some());
    assert!(matches!(
        pendulum.scene.bodies[0].shape,
        BodyShape::Outline { .. }
    ));
    let double = load("rigid/double_pendulum.toml");
    assert_eq!(
        double
            .scene
            .items
            .iter()
            .filter(|i| matches!(i, mechkit::animation::SceneItem::Rod { .. }))
            .count(),
        2
    );
}

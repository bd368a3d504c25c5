//! Properties every resolved collision must have, over random masses, velocities, normals,
//! restitutions and friction: momentum conserved to 1e-12 relative, kinetic energy never
//! increases (and is conserved to 1e-12 when e = 1 without friction), the normal separation
//! speed is exactly e times the approach speed (so e = 0 leaves equal normal velocities), and
//! the impulse acts along the normal unless friction adds a tangential part no larger than
//! μ J_n.

use mechkit::collisions::{Collision, Resolution, Restitution};
use proptest::prelude::*;

fn vector(d: usize) -> impl Strategy<Value = Vec<f64>> {
    prop::collection::vec(-50.0..50.0f64, d)
}

fn collision() -> impl Strategy<Value = Collision> {
    (1usize..=3).prop_flat_map(|d| {
        (
            1e-3..1e3f64,
            prop_oneof![4 => 1e-3..1e3f64, 1 => Just(f64::INFINITY)],
            vector(d),
            vector(d),
            vector(d).prop_filter("a normal needs a length", |n| {
                n.iter().map(|x| x * x).sum::<f64>() > 1e-6
            }),
            prop_oneof![Just(0.0), Just(1.0), 0.0..=1.0f64],
            prop_oneof![2 => Just(0.0), 1 => 0.0..2.0f64],
        )
            .prop_map(|(m1, m2, v1, v2, normal, e, friction)| Collision {
                m1,
                m2,
                v1,
                // a wall at rest (a moving wall does work on the body)
                v2: if m2.is_finite() {
                    v2
                } else {
                    vec![0.0; v2.len()]
                },
                normal,
                restitution: Restitution::new(e).unwrap(),
                friction,
            })
    })
}

fn dot(a: &[f64], b: &[f64]) -> f64 {
    a.iter().zip(b).map(|(x, y)| x * y).sum()
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(20_000))]

    #[test]
    fn resolved_collisions_obey_the_conservation_laws(c in collision()) {
        let Resolution::Collided(o) = c.resolve().unwrap() else {
            // separating: the approach speed is not positive
            let u: Vec<f64> = c.v1.iter().zip(&c.v2).map(|(a, b)| a - b).collect();
            prop_assert!(dot(&u, &c.normal) <= 0.0);
            return Ok(());
        };
        let d = c.v1.len();
        let len = dot(&c.normal, &c.normal).sqrt();
        let n: Vec<f64> = c.normal.iter().map(|x| x / len).collect();
        let scale = o.kinetic_before.max(1e-300);
        // momentum (when both masses are finite); with a wall, body 1's change is the impulse
        if c.m2.is_finite() {
            let speed = c.v1.iter().chain(&c.v2).fold(0.0f64, |m, v| m.max(v.abs()));
            let p_scale = (c.m1 + c.m2) * speed.max(1e-300);
            for i in 0..d {
                let before = c.m1 * c.v1[i] + c.m2 * c.v2[i];
                let after = c.m1 * o.v1[i] + c.m2 * o.v2[i];
                prop_assert!((after - before).abs() <= 1e-12 * p_scale, "{before} -> {after}");
            }
        } else {
            for i in 0..d {
                let dp = c.m1 * (o.v1[i] - c.v1[i]);
                prop_assert!((dp + o.impulse[i]).abs() <= 1e-12 * c.m1 * 100.0);
            }
        }
        // energy never increases; e = 1 without friction keeps it
        prop_assert!(o.kinetic_after <= o.kinetic_before * (1.0 + 1e-12) + 1e-300);
        if c.restitution.value() == 1.0 && c.friction == 0.0 {
            prop_assert!((o.kinetic_after - o.kinetic_before).abs() <= 1e-12 * scale);
        }
        // the normal separation speed is e times the approach speed
        let e = c.restitution.value();
        let un_after = -dot(&o.v1.iter().zip(&o.v2).map(|(a, b)| a - b).collect::<Vec<_>>(), &n);
        prop_assert!((un_after - e * o.approach_speed).abs() <= 1e-12 * o.approach_speed.max(1.0) * 10.0);
        // the tangential impulse is bounded by friction
        let jn = dot(&o.impulse, &n);
        prop_assert!((jn - o.normal_impulse).abs() <= 1e-12 * o.normal_impulse.max(1e-300) * 10.0);
        prop_assert!(o.tangential_impulse <= c.friction * o.normal_impulse * (1.0 + 1e-12));
    }
}

//! Energy diagrams: equilibria with their stability, barriers, turning points, singular points,
//! and the work-energy theorem's speed, each checked against a closed form.

use std::f64::consts::PI;

use mechkit::energy::{Origin, Potential, Stability};

fn params(text: &str) -> Vec<(String, f64)> {
    mechkit::calculus::parse_params(text).unwrap()
}

#[test]
fn lennard_jones_equilibrium_at_two_to_the_sixth() {
    for (a, b) in [(1.0, 1.0), (1.3, 0.9)] {
        let p = Potential::from_potential(
            "U0*((a/r)^12 - (b/r)^6)",
            "r",
            &params(&format!("U0=2,a={a},b={b}")),
        )
        .unwrap();
        let d = p.diagram(0.8 * a, 3.0 * a, None, 2000);
        assert_eq!(d.equilibria.len(), 1, "{:?}", d.equilibria);
        let eq = d.equilibria[0];
        // F = 0 at r = 2^(1/6) a^2/b, a minimum of depth U0 b^12/(4 a^12)
        let exact = 2f64.powf(1.0 / 6.0) * a * a / b;
        assert!((eq.x - exact).abs() < 1e-12 * exact, "{} vs {exact}", eq.x);
        assert_eq!(eq.stability, Stability::Stable);
        assert!((eq.potential + 2.0 * b.powi(12) / (4.0 * a.powi(12))).abs() < 1e-12);
        assert!(eq.curvature > 0.0);
        assert!(d.singularities.is_empty());
    }
}

#[test]
fn periodic_surface_alternates_stable_and_unstable_with_barrier_one_over_pi() {
    let p = Potential::from_force("-F0*sin(2*pi*x/b)", "x", &params("F0=1.0,b=1.0"), 0.0).unwrap();
    let d = p.diagram(-1.2, 2.2, Some(-0.1), 3000);
    let xs: Vec<f64> = d.equilibria.iter().map(|e| e.x).collect();
    assert_eq!(xs.len(), 7, "{xs:?}");
    for (i, e) in d.equilibria.iter().enumerate() {
        let want = -1.0 + 0.5 * i as f64;
        assert!((e.x - want).abs() < 1e-12, "{} vs {want}", e.x);
        let stable = i % 2 == 0;
        assert_eq!(e.stability == Stability::Stable, stable);
        if stable {
            assert!((e.barrier.unwrap() - 1.0 / PI).abs() < 1e-12);
        }
    }
    // with E = -0.1 the atom is trapped in each well between U = E crossings
    let cut = d.energy.unwrap();
    let arccos = (2.0 * PI * 0.1f64).acos() / (2.0 * PI);
    for well in [-1.0, 0.0, 1.0, 2.0] {
        let (lo, hi) = (well - arccos, well + arccos);
        for t in [lo, hi] {
            if (-1.2..=2.2).contains(&t) {
                assert!(
                    cut.turning_points.iter().any(|&x| (x - t).abs() < 1e-12),
                    "{t}"
                );
            }
        }
        let mid = cut
            .regions
            .iter()
            .find(|r| r.from <= well && well <= r.to)
            .unwrap();
        assert!(mid.allowed);
    }
    assert!(
        cut.regions
            .iter()
            .any(|r| !r.allowed && r.from <= 0.5 && 0.5 <= r.to)
    );
}

#[test]
fn higher_order_and_touching_equilibria() {
    // U = x^4: U'' = 0 at the minimum; U = x^3: an inflection (F touches zero)
    let quartic = Potential::from_potential("x^4", "x", &[]).unwrap();
    let d = quartic.diagram(-1.0, 1.3, None, 1000);
    assert_eq!(d.equilibria.len(), 1);
    assert!(d.equilibria[0].x.abs() < 1e-4);
    assert_eq!(d.equilibria[0].stability, Stability::Stable);
    let cubic = Potential::from_potential("x^3", "x", &[]).unwrap();
    let d = cubic.diagram(-1.0, 1.3, None, 1000);
    assert_eq!(d.equilibria.len(), 1, "{:?}", d.equilibria);
    assert_eq!(d.equilibria[0].stability, Stability::Neutral);
    let none = Potential::from_potential("2*x", "x", &[]).unwrap();
    assert!(none.diagram(-1.0, 1.0, None, 100).equilibria.is_empty());
}

#[test]
fn a_singular_point_is_reported_not_taken_for_an_equilibrium() {
    // poles of odd and even order, a logarithmic singularity, and one off the grid
    for text in ["1/x", "1/x^2", "ln(abs(x))", "1/(x - 0.3)"] {
        let p = Potential::from_potential(text, "x", &[]).unwrap();
        let d = p.diagram(-1.0, 2.0, Some(1.0), 2000);
        let pole = if text.contains("0.3") { 0.3 } else { 0.0 };
        assert_eq!(d.singularities.len(), 1, "{text}: {:?}", d.singularities);
        assert!(
            (d.singularities[0] - pole).abs() < 2e-3,
            "{text}: {:?}",
            d.singularities
        );
        assert!(d.equilibria.is_empty(), "{text}: {:?}", d.equilibria);
    }
}

#[test]
fn numeric_potential_gives_the_same_diagram_as_the_closed_form() {
    // F = -x exp(-x^4) + 0.2: no antiderivative in the table; equilibria where x e^{-x^4} = 0.2
    let p = Potential::from_force("0.2 - x*exp(-x^4)", "x", &[], -2.0).unwrap();
    assert!(matches!(p.origin(), Origin::Numeric { .. }));
    let d = p.diagram(-2.0, 2.0, Some(0.5), 2000);
    assert_eq!(d.equilibria.len(), 2);
    for e in &d.equilibria {
        assert!((e.x * (-e.x.powi(4)).exp() - 0.2).abs() < 1e-13);
    }
    assert_eq!(d.equilibria[0].stability, Stability::Stable);
    assert_eq!(d.equilibria[1].stability, Stability::Unstable);
    // U on the grid agrees with an independent quadrature from the reference
    let q = mechkit::quad::integrate(
        |x| p.force(x),
        -2.0,
        1.0,
        mechkit::quad::Tolerance::default(),
    )
    .unwrap();
    let k = d.x.iter().position(|&x| (x - 1.0).abs() < 1e-12).unwrap();
    assert!((d.potential[k] + q.value).abs() < 1e-11);
}

#[test]
fn ion_head_on_turning_point_and_speed_far_away() {
    // U = C/x, m = 1, starts at x = b = 1 moving in at v0 = 2.5
    let (c, m, b, v0) = (1.0, 1.0, 1.0, 2.5);
    let p = Potential::from_potential("C/x", "x", &params(&format!("C={c}"))).unwrap();
    let motion = p.motion(m, b, v0, 0.05, 1e8, 4000);
    let x1 = c / (0.5 * m * v0 * v0 + c / b);
    assert!((motion.left_turn.unwrap() - x1).abs() < 1e-12);
    assert!(motion.right_turn.is_none());
    let v_inf = (v0 * v0 + 2.0 * c / (m * b)).sqrt();
    assert!((motion.speed_at(&p, 1e12) - v_inf).abs() < 1e-9);
}

#[test]
fn speed_from_the_work_energy_theorem_matches_a_simulation() {
    // the atom on the periodic surface released at x0 = 0.1 with v0 = 0.3 (m = 1)
    let p = Potential::from_force("-sin(2*pi*x)", "x", &[], 0.0).unwrap();
    let motion = p.motion(1.0, 0.1, 0.3, -1.0, 1.0, 2000);
    let e = motion.energy;
    let (l, r) = (motion.left_turn.unwrap(), motion.right_turn.unwrap());
    for t in [l, r] {
        assert!((p.potential(t) - e).abs() < 1e-13);
    }
    assert!(l < 0.0 && r > 0.1);
    let v = motion.speed_at(&p, 0.0);
    let exact = (0.09 + 2.0 * (p.potential(0.1) - p.potential(0.0))).sqrt();
    assert!((v - exact).abs() < 1e-14);
}

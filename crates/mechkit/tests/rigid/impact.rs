//! Rigid impacts in the plane: an impulse J n at the contact with Newton's restitution,
//! J = −(1 + e) m_eff u with 1/m_eff = Σ 1/m + (r × n)²/I. Checked: the hinged rod struck
//! by a block of the course (c16-B6: elastic with m = M/3 the rod stops and the block takes
//! ω₀L; plastic: v = ω₀L/(1 + 3m/M)), angular momentum about the hinge conserved to 1e-12
//! through the impact for every restitution, K_after − K_before = −½(1 − e²) m_eff u², zero
//! hinge impulse at the centre of percussion 2L/3, two free rods conserving P and L, and a
//! rod landing on its end (L about the contact conserved, the end stopped for e = 0).

use mechkit::rigid::impact::{
    Contact, ImpactError, Particle, PivotedBody, PlanarBody, hinged_impact, impact, release_omega,
};

const G: f64 = 9.81;

fn block(m: f64) -> Particle {
    Particle {
        mass: m,
        velocity: [0.0, 0.0],
    }
}

fn at_end(l: f64, e: f64) -> Contact {
    Contact {
        point: [0.0, -l],
        normal: [1.0, 0.0],
        restitution: e,
    }
}

/// c16-B6 with M = 1 kg, L = 1 m, θ₀ = 90°: ω₀ = sqrt(3g/L) = 5.42494 rad/s, elastic with
/// m = M/3: the rod stops (|ω| ≤ 1e-15) and the block takes ω₀L; plastic: ω₀L/(1 + 3m/M).
#[test]
fn c16_b6_rod_hits_block() {
    let (big_m, l) = (1.0, 1.0);
    let rod = PivotedBody::rod(big_m, l, 0.5 * l, 0.0).unwrap();
    let w0 = release_omega(&rod, G, std::f64::consts::FRAC_PI_2);
    assert!((w0 - (3.0 * G / l).sqrt()).abs() < 1e-14);
    assert!((w0 - 5.42494).abs() < 1e-5);
    let rod = PivotedBody { omega: w0, ..rod };
    let m = big_m / 3.0;
    let elastic = hinged_impact(&rod, &block(m), &at_end(l, 1.0)).unwrap();
    assert!(elastic.omega_after.abs() < 1e-15, "{}", elastic.omega_after);
    assert!((elastic.velocity_after[0] - w0 * l).abs() < 1e-14);
    for m in [0.1, 1.0 / 3.0, 1.0, 5.0] {
        let plastic = hinged_impact(&rod, &block(m), &at_end(l, 0.0)).unwrap();
        let v = w0 * l / (1.0 + 3.0 * m / big_m);
        assert!((plastic.velocity_after[0] - v).abs() < 1e-14, "m = {m}");
        assert!(
            (plastic.omega_after * l - v).abs() < 1e-14,
            "moving together"
        );
    }
}

/// For e = 0, 0.3, 0.7, 1 and several contact points and block masses: the angular momentum
/// about the hinge is conserved to 1e-12 (relative), the normal relative velocity reverses by
/// −e (to 1e-13), and the energy change matches −½(1 − e²) m_eff u² (to 1e-12 relative), i.e.
/// K_after/K_before = 1 − (1 − e²) m_eff u²/(2 K_before).
#[test]
fn hinged_impact_conserves_angular_momentum_and_loses_energy_by_e() {
    let rod = PivotedBody::rod(2.0, 1.2, 0.6, 3.0).unwrap();
    for e in [0.0, 0.3, 0.7, 1.0] {
        for (m, y, vx) in [(0.2, -1.2, -1.0), (1.0, -0.8, 0.5), (7.0, -0.3, -4.0)] {
            let particle = Particle {
                mass: m,
                velocity: [vx, 0.3],
            };
            let c = Contact {
                point: [0.0, y],
                normal: [1.0, 0.0],
                restitution: e,
            };
            let r = hinged_impact(&rod, &particle, &c).unwrap();
            let (l0, l1) = r.angular_momentum;
            assert!((l1 - l0).abs() <= 1e-12 * l0.abs(), "e = {e}: {l0} -> {l1}");
            let u = r.normal_speed_before;
            assert!((r.normal_speed_after + e * u).abs() < 1e-13);
            let (k0, k1) = r.kinetic;
            assert!(
                ((k1 - k0) - r.kinetic_change_exact).abs() <= 1e-12 * k0,
                "e = {e}: ΔK = {} vs {}",
                k1 - k0,
                r.kinetic_change_exact
            );
            if e == 1.0 {
                assert!((k1 - k0).abs() <= 1e-12 * k0);
            }
        }
    }
}

/// A strike at the centre of percussion, 2L/3 below the top of a rod hung from its end,
/// leaves no impulse in the hinge (|J_hinge| ≤ 1e-15 N s); struck at the end, the hinge
/// pushes back.
#[test]
fn centre_of_percussion_has_no_hinge_impulse() {
    let l = 0.9;
    let rod = PivotedBody::rod(1.5, l, 0.5 * l, 0.0).unwrap();
    let cp = rod.centre_of_percussion().unwrap();
    assert!((cp - 2.0 * l / 3.0).abs() < 1e-15);
    let ball = Particle {
        mass: 0.2,
        velocity: [-5.0, 0.0],
    };
    for e in [0.0, 0.5, 1.0] {
        let hit = Contact {
            point: [0.0, -cp],
            normal: [1.0, 0.0],
            restitution: e,
        };
        let r = hinged_impact(&rod, &ball, &hit).unwrap();
        assert!(
            r.hinge_impulse[0].hypot(r.hinge_impulse[1]) < 1e-15,
            "{:?}",
            r.hinge_impulse
        );
        // so the linear momentum is conserved too
        assert!((r.momentum.0[0] - r.momentum.1[0]).abs() < 1e-15);
    }
    let end = Contact {
        point: [0.0, -l],
        normal: [1.0, 0.0],
        restitution: 1.0,
    };
    let r = hinged_impact(&rod, &ball, &end).unwrap();
    assert!(r.hinge_impulse[0].abs() > 0.01);
}

/// Two free rods, one spinning, meet at a point: total momentum and angular momentum about
/// any point conserved to 1e-13 for every e, and the energy change as the closed form.
#[test]
fn two_free_rods_conserve_momentum_and_angular_momentum() {
    let rod = |m: f64, l: f64| m * l * l / 12.0;
    let a = PlanarBody::new(1.0, rod(1.0, 1.0), [0.0, 0.0], [1.0, 0.2], 2.0).unwrap();
    let b = PlanarBody::new(3.0, rod(3.0, 2.0), [1.2, 0.4], [-0.5, 0.0], -1.0).unwrap();
    for e in [0.0, 0.5, 1.0] {
        let c = Contact {
            point: [0.5, 0.1],
            normal: [1.0, 0.3],
            restitution: e,
        };
        let r = impact(&a, &b, &c).unwrap();
        let (p0, p1) = r.momentum;
        assert!((p0[0] - p1[0]).abs() < 1e-13 && (p0[1] - p1[1]).abs() < 1e-13);
        let (l0, l1) = r.angular_momentum_origin;
        assert!((l0 - l1).abs() < 1e-13, "{l0} {l1}");
        let q = [3.0, -7.0];
        let lq = |x: &PlanarBody, y: &PlanarBody| x.angular_momentum(q) + y.angular_momentum(q);
        assert!((lq(&a, &b) - lq(&r.a, &r.b)).abs() < 1e-12);
        let (k0, k1) = r.kinetic;
        assert!(((k1 - k0) - r.kinetic_change_exact).abs() < 1e-13);
        assert!((r.normal_speed.1 + e * r.normal_speed.0).abs() < 1e-13);
    }
}

/// A rod falling at an angle lands on its lower end (e = 0 and 0.5): the angular momentum
/// about the contact point is conserved (to 1e-14; the ground's impulse acts there), the
/// end's normal velocity becomes −e times what it was, and the closed form for a rod falling
/// flat holds: ω = 3v/(2L), v_cm = 3v/4 for e = 0.
#[test]
fn a_rod_landing_on_its_end() {
    let (m, l, v) = (2.0, 1.0, 3.0);
    let tilt = 0.4_f64;
    let half = [0.5 * l * tilt.cos(), 0.5 * l * tilt.sin()];
    let rod = PlanarBody::new(m, m * l * l / 12.0, [0.0, 0.0], [0.0, -v], 0.7).unwrap();
    let end = [-half[0], -half[1]];
    for e in [0.0, 0.5] {
        let c = Contact {
            point: end,
            normal: [0.0, 1.0],
            restitution: e,
        };
        let r = impact(&PlanarBody::fixed(end), &rod, &c).unwrap();
        let (l0, l1) = r.angular_momentum_contact;
        assert!((l0 - l1).abs() < 1e-14, "{l0} {l1}");
        let u0 = rod.velocity_at(end)[1];
        assert!((r.b.velocity_at(end)[1] + e * u0).abs() < 1e-14);
    }
    let flat = PlanarBody::new(m, m * l * l / 12.0, [0.0, 0.0], [0.0, -v], 0.0).unwrap();
    let c = Contact {
        point: [-0.5 * l, 0.0],
        normal: [0.0, 1.0],
        restitution: 0.0,
    };
    let r = impact(&PlanarBody::fixed([-0.5 * l, 0.0]), &flat, &c).unwrap();
    assert!((r.b.omega + 1.5 * v / l).abs() < 1e-14);
    assert!((r.b.velocity[1] + 0.75 * v).abs() < 1e-14);
}

/// Bad input: zero moment of inertia about the pivot is an error; a pivot outside the rod
/// and a contact off the rod are warnings; separating bodies, a zero normal, e > 1, and
/// I_O < M d² are errors.
#[test]
fn bad_bodies_and_contacts() {
    assert!(matches!(
        PivotedBody::new(0.0, 1.0, [0.0, -0.5], 1.0),
        Err(ImpactError::ZeroInertia { .. })
    ));
    assert!(matches!(
        PivotedBody::new(0.1, 1.0, [0.0, -0.5], 1.0),
        Err(ImpactError::ParallelAxis { .. })
    ));
    let outside = PivotedBody::rod(1.0, 1.0, 2.0, 1.0).unwrap();
    let w = outside.warnings([0.0, -2.5]);
    assert!(
        w.iter().any(|w| w.contains("pivot is 1.5 m outside")),
        "{w:?}"
    );
    let rod = PivotedBody::rod(1.0, 1.0, 0.5, 1.0).unwrap();
    assert!(rod.warnings([0.0, -1.0]).is_empty());
    assert!(rod.warnings([0.0, -1.7])[0].contains("off the body"));
    let away = Particle {
        mass: 1.0,
        velocity: [5.0, 0.0],
    };
    assert!(matches!(
        hinged_impact(&rod, &away, &at_end(1.0, 1.0)),
        Err(ImpactError::Separating { .. })
    ));
    let zero_n = Contact {
        point: [0.0, -1.0],
        normal: [0.0, 0.0],
        restitution: 1.0,
    };
    assert!(hinged_impact(&rod, &block(1.0), &zero_n).is_err());
    assert!(hinged_impact(&rod, &block(1.0), &at_end(1.0, 1.5)).is_err());
    let point = PlanarBody::new(1.0, 0.0, [0.0, 0.0], [1.0, 0.0], 0.0).unwrap();
    let other = PlanarBody::new(1.0, 1.0, [1.0, 0.0], [0.0, 0.0], 0.0).unwrap();
    let off_centre = Contact {
        point: [0.0, 0.5],
        normal: [1.0, 0.0],
        restitution: 1.0,
    };
    assert!(matches!(
        impact(&point, &other, &off_centre),
        Err(ImpactError::ZeroInertia { .. })
    ));
}

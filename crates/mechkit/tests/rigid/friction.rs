//! Coulomb friction and the stick-slip spring-block model.
//!
//! Physics checked:
//! - a block on an incline stays at rest up to the marginal angle `atan μs` and slides above
//!   it with `a = g (sin α − μd cos α)`; `N = m g cos α` plus other normal loads;
//! - the earthquake model (anchor pulled at `w`, fixed floor): the first stick ends at
//!   `t = μs N/(k w)`; every slip lasts `θ/Ω` with `θ = 2π − 2 atan(Ω D/w)`,
//!   `D = (μs − μd) N/k` (from `v = 0` back to `v = 0` on the shifted harmonic oscillation);
//!   the cycles repeat with period stick + slip;
//! - a block on a belt (`u > 0`) tied to a wall: the same formula with `u` in place of `w`;
//!   every slip phase equals the harmonic solution at every sample;
//! - a block released on a fixed floor: each slip is a half period `π/Ω`, the amplitude drops
//!   by `2 μd N/k` per half cycle, and it stops at the first turning point inside `μs N/k`;
//! - the energy balance `K + U + Q − W_belt − W_anchor` is constant (heat `Q ≥ 0`, the
//!   negative work of friction relative to the surface, non-decreasing);
//! - `μs < μd` warns and uses `μd` as the static bound; negative coefficients are refused.

use mechkit::ode::{AdaptiveConfig, Tolerance};
use mechkit::rigid::friction::{
    Coulomb, FrictionError, Incline, PhaseEnd, Regime, SpringBlock, StickSlipRun,
};
use std::f64::consts::PI;

fn config() -> AdaptiveConfig {
    AdaptiveConfig {
        rtol: Tolerance::Scalar(1e-12),
        atol: Tolerance::Scalar(1e-14),
        ..AdaptiveConfig::default()
    }
}

/// The largest difference between the simulated slip phases and the harmonic solution from
/// each phase's start, relative to the phase's excursion.
fn worst_slip_deviation(block: &SpringBlock, run: &StickSlipRun) -> f64 {
    let mut worst: f64 = 0.0;
    for p in &run.phases {
        let Regime::Slip { direction } = p.regime else {
            continue;
        };
        let scale = (p.end.1 - p.start.1).abs().max(1e-6);
        for s in run
            .samples
            .iter()
            .filter(|s| !s.stuck && s.t >= p.start.0 && s.t <= p.end.0)
        {
            let (x, v) = block.exact_slip(p.start, direction, s.t);
            worst = worst.max((s.x - x).abs() / scale);
            worst = worst.max((s.v - v).abs() * (p.end.0 - p.start.0) / scale);
        }
    }
    worst
}

#[test]
fn incline_marginal_angle_and_acceleration() {
    for (mu_s, mu_d) in [(0.2, 0.1), (0.5, 0.3), (1.0, 0.8)] {
        let c = Coulomb::new(mu_s, mu_d).unwrap();
        let alpha_c = c.marginal_angle();
        assert!((alpha_c.tan() - mu_s).abs() < 1e-15);
        for (alpha, slides) in [
            (alpha_c * (1.0 - 1e-9), false),
            (alpha_c * (1.0 + 1e-9), true),
        ] {
            let r = Incline::new(3.0, alpha, c).unwrap().at_rest().unwrap();
            assert_eq!(r.slides, slides, "μs = {mu_s}, α = {alpha}");
            assert!((r.normal - 3.0 * 9.81 * alpha.cos()).abs() < 1e-13);
        }
        let alpha = alpha_c + 0.1;
        let r = Incline::new(3.0, alpha, c).unwrap().at_rest().unwrap();
        let exact = 9.81 * (alpha.sin() - mu_d * alpha.cos());
        assert!((r.acceleration - exact).abs() < 1e-14, "{}", r.acceleration);
        assert!((r.friction + mu_d * r.normal).abs() < 1e-13);
    }
    // a push into the surface raises N and the bound: a block that slid now stays
    let c = Coulomb::new(0.5, 0.3).unwrap();
    let steep = Incline::new(1.0, 0.5, c).unwrap();
    assert!(steep.at_rest().unwrap().slides);
    let pressed = steep.with_loads(10.0, 0.0).at_rest().unwrap();
    assert!((pressed.normal - (9.81 * 0.5f64.cos() + 10.0)).abs() < 1e-14);
    assert!(!pressed.slides);
}

#[test]
fn earthquake_model_stick_and_slip_at_the_closed_form_times() {
    let (m, k, mu_s, mu_d, w) = (1.0, 100.0, 0.6, 0.4, 0.05);
    let block = SpringBlock::new(m, k, Coulomb::new(mu_s, mu_d).unwrap())
        .unwrap()
        .driven(w);
    let run = block.simulate(8.0, &config()).unwrap();
    let n = m * 9.81;
    let om = (k / m).sqrt();
    let d = (mu_s - mu_d) * n / k;
    let slip = (2.0 * PI - 2.0 * (om * d / w).atan()) / om;
    let t_stick1 = mu_s * n / (k * w);
    let first = &run.phases[0];
    assert_eq!(first.regime, Regime::Stick);
    let e_stick = (first.end.0 - t_stick1).abs() / t_stick1;
    let mut e_slip: f64 = 0.0;
    let mut e_period: f64 = 0.0;
    let slips: Vec<_> = run
        .phases
        .iter()
        .filter(|p| matches!(p.regime, Regime::Slip { .. }) && p.ended == PhaseEnd::Switch)
        .collect();
    assert!(slips.len() >= 5, "{} slips", slips.len());
    for (i, p) in slips.iter().enumerate() {
        assert_eq!(p.regime, Regime::Slip { direction: 1.0 });
        e_slip = e_slip.max(((p.end.0 - p.start.0) - slip).abs() / slip);
        if i > 0 {
            // the cycle repeats: stick + slip
            let stick = slips[i].start.0 - slips[i - 1].end.0;
            let period = p.start.0 - slips[i - 1].start.0;
            let exact_stick = (slips[i - 1].end.1 - w * slips[i - 1].end.0 + mu_s * n / k) / w;
            e_period = e_period.max((stick - exact_stick).abs() / period);
        }
    }
    let e_shape = worst_slip_deviation(&block, &run);
    println!(
        "earthquake: first stick {e_stick:.1e}, slip duration {e_slip:.1e}, stick durations {e_period:.1e}, slip motion {e_shape:.1e} (relative); {:?}",
        run.stats
    );
    assert!(e_stick < 1e-12 && e_slip < 1e-10 && e_period < 1e-10 && e_shape < 1e-9);
    // in the steady cycle every slip covers the same distance
    let d0 = slips[1].slip_distance;
    assert!(
        slips[1..]
            .iter()
            .all(|p| (p.slip_distance - d0).abs() < 1e-10 * d0)
    );
}

#[test]
fn block_on_a_belt_each_slip_is_the_harmonic_solution() {
    let (m, k, mu_s, mu_d, u) = (0.5, 50.0, 0.5, 0.3, 0.2);
    let block = SpringBlock::new(m, k, Coulomb::new(mu_s, mu_d).unwrap())
        .unwrap()
        .on_belt(u);
    // placed at rest on the moving belt: it slips until it moves with the belt, then
    // stick-slip cycles
    let run = block.simulate(4.0, &config()).unwrap();
    assert_eq!(run.phases[0].regime, Regime::Slip { direction: -1.0 });
    let n = m * 9.81;
    let om = (k / m).sqrt();
    let d = (mu_s - mu_d) * n / k;
    let slip = (2.0 * PI - 2.0 * (om * d / u).atan()) / om;
    let mut worst_end: f64 = 0.0;
    let mut count = 0;
    for p in &run.phases {
        match p.regime {
            Regime::Stick if p.ended == PhaseEnd::Switch => {
                // the stick ends where k x = μs N (the block pulled forward by the belt)
                let t = block.exact_stick_end(p.start.0, p.start.1).unwrap();
                worst_end = worst_end.max((p.end.0 - t).abs());
                assert!((p.end.1 - mu_s * n / k).abs() < 1e-12);
            }
            Regime::Slip { direction } if p.ended == PhaseEnd::Switch => {
                assert_eq!(
                    direction, -1.0,
                    "the block slides back relative to the belt"
                );
                count += 1;
                let t = block.exact_slip_end(p.start, direction).unwrap();
                worst_end = worst_end.max((p.end.0 - t).abs());
                // a slip out of a stick (not the first, from rest on the moving belt) lasts
                // 2π − 2 atan(Ω D/u) over Ω
                if p.start.2 == u {
                    assert!(((p.end.0 - p.start.0) - slip).abs() < 1e-10 * slip, "{p:?}");
                }
                assert!(p.slip_distance < 0.0);
            }
            _ => {}
        }
    }
    let e_shape = worst_slip_deviation(&block, &run);
    println!(
        "belt: {count} slips, switch times within {worst_end:.1e} s, slip motion {e_shape:.1e}"
    );
    assert!(count >= 3 && worst_end < 1e-11 && e_shape < 1e-9);
}

#[test]
fn released_block_stops_after_whole_half_cycles() {
    let (m, k, mu_s, mu_d, a) = (2.0, 80.0, 0.35, 0.25, 0.3);
    let block = SpringBlock::new(m, k, Coulomb::new(mu_s, mu_d).unwrap())
        .unwrap()
        .starting_at(a, 0.0);
    let run = block.simulate(10.0, &config()).unwrap();
    let n = m * 9.81;
    let (delta, bound) = (mu_d * n / k, mu_s * n / k);
    // turning points y_j = ±(A − 2 j δ) while the spring force exceeds μs N
    let mut amp = a;
    let mut expected = 0;
    while amp > bound {
        amp -= 2.0 * delta;
        expected += 1;
    }
    let half = PI / (k / m).sqrt();
    let slips: Vec<_> = run
        .phases
        .iter()
        .filter(|p| matches!(p.regime, Regime::Slip { .. }))
        .collect();
    assert_eq!(slips.len(), expected);
    for p in &slips {
        assert!(((p.end.0 - p.start.0) - half).abs() < 1e-11, "{p:?}");
    }
    let last = run.phases.last().unwrap();
    assert_eq!(last.regime, Regime::Stick);
    assert_eq!(last.ended, PhaseEnd::TimeLimit);
    let x_end = last.end.1;
    let x_exact = if expected % 2 == 0 { amp } else { -amp };
    println!("released: {expected} half cycles, x_end = {x_end} (exact {x_exact})");
    assert!((x_end - x_exact).abs() < 1e-12);
    // the heat is exactly the spring energy lost
    let heat = 0.5 * k * (a * a - x_exact * x_exact);
    assert!((run.heat() - heat).abs() < 1e-12 * heat);
}

#[test]
fn energy_ledger_closes_and_heat_only_grows() {
    let c = Coulomb::new(0.6, 0.4).unwrap();
    let cases = [
        SpringBlock::new(1.0, 100.0, c).unwrap().driven(0.05),
        SpringBlock::new(1.0, 100.0, c).unwrap().on_belt(0.1),
        SpringBlock::new(1.0, 100.0, c)
            .unwrap()
            .on_belt(0.3)
            .driven(-0.1)
            .starting_at(0.02, 1.0),
    ];
    for block in cases {
        let run = block.simulate(5.0, &config()).unwrap();
        let b = &run.balance;
        let spring = b.potential.as_ref().unwrap();
        assert_eq!(spring.parts[0].name, "spring");
        let (heat, w_belt, w_anchor) = (run.heat(), run.work_belt(), run.work_anchor());
        let scale = b.kinetic.start + spring.start + heat + w_belt.abs() + w_anchor.abs();
        println!(
            "balance: heat {heat:.6} J, W_belt {w_belt:.6} J, W_anchor {w_anchor:.6} J, residual {:.1e} J ({} phases)",
            b.residual(),
            run.phases.len()
        );
        assert!(b.residual().abs() < 1e-11 * scale.max(1.0), "{b:?}");
        // the same balance in the form K + U + Q − (K0 + U0 + W_belt + W_anchor)
        let (e0, e1) = b.energy();
        assert!(((e1 + heat) - (e0 + w_belt + w_anchor)).abs() < 1e-11 * scale.max(1.0));
        assert_eq!(b.work_of("friction"), Some(-heat));
        assert!((run.work_friction() - (w_belt - heat)).abs() < 1e-15 * scale.max(1.0));
        assert!(heat > 0.0);
        assert!(
            run.samples
                .windows(2)
                .all(|w| w[1].heat >= w[0].heat - 1e-15)
        );
        // sticking the block moves with the belt and static friction balances the spring
        for s in run.samples.iter().filter(|s| s.stuck) {
            assert_eq!(s.v, block.belt_speed);
            assert_eq!(s.friction, -s.spring_force);
            assert!(s.spring_force.abs() <= block.stick_bound() * (1.0 + 1e-12));
        }
    }
}

#[test]
fn mu_static_below_mu_dynamic_warns_and_bounds_with_mu_dynamic() {
    let c = Coulomb::new(0.3, 0.5).unwrap();
    assert!(c.warning().is_some());
    let block = SpringBlock::new(1.0, 100.0, c).unwrap().driven(0.05);
    let run = block.simulate(1.0, &config()).unwrap();
    // the block cannot start to slide before the spring pulls with μd N
    let t_stick = 0.5 * 9.81 / (100.0 * 0.05);
    assert!((run.phases[0].end.0 - t_stick).abs() < 1e-12);
    // with μs = μd the slip starts without a jump in friction: from v = 0 it ends at v = 0
    assert!(run.balance.residual().abs() < 1e-12);
}

#[test]
fn bad_input_is_refused() {
    assert!(matches!(
        Coulomb::new(-0.2, 0.1),
        Err(FrictionError::Coefficient {
            which: "static",
            ..
        })
    ));
    assert!(matches!(
        Coulomb::new(0.2, -0.1),
        Err(FrictionError::Coefficient {
            which: "dynamic",
            ..
        })
    ));
    let c = Coulomb::single(0.3).unwrap();
    assert!(matches!(
        SpringBlock::new(0.0, 1.0, c),
        Err(FrictionError::NotPositive { .. })
    ));
    assert!(SpringBlock::new(1.0, -1.0, c).is_err());
    let block = SpringBlock::new(1.0, 1.0, c).unwrap();
    assert!(block.on_belt(f64::NAN).simulate(1.0, &config()).is_err());
    assert!(block.simulate(-1.0, &config()).is_err());
    assert!(block.with_gravity(-9.81).validate().is_err());
    let msg = Coulomb::new(-0.2, 0.1).unwrap_err().to_string();
    assert!(msg.contains("static friction coefficient is -0.2"), "{msg}");
}

//! Two Lennard-Jones atoms released from rest at r = 1.5σ oscillate between the turning
//! points of U(r) = E: the outer one is the release point, the inner one the root of
//! U(r) = U(1.5σ) inside the well; the energy is conserved and the centre of mass stays put.

use mechkit::md::{LennardJones, Md, MdConfig, PairPotential, SimBox};
use mechkit::roots::brent;

#[test]
fn lj_pair_from_1_5_sigma_turns_where_u_equals_e() {
    let lj = LennardJones::reduced(2.5).unwrap();
    let b = SimBox::new(3, [10.0; 3], [false; 3]).unwrap();
    let x = vec![[0.0, 0.0, 0.0], [1.5, 0.0, 0.0]];
    let config = MdConfig {
        dt: 1e-4,
        ..MdConfig::default()
    };
    let mut md = Md::new(b, lj, x, vec![[0.0; 3]; 2], config).unwrap();
    let e0 = md.thermo().total;
    let u = |r: f64| lj.energy_force(r * r).0;
    assert!((e0 - u(1.5)).abs() < 1e-15);
    let inner = brent(|r| u(r) - e0, 0.9, 2f64.powf(1.0 / 6.0), 1e-14).unwrap();
    let (mut r_min, mut r_max, mut worst) = (f64::INFINITY, 0.0f64, 0.0f64);
    for _ in 0..40_000 {
        md.step();
        let p = md.positions();
        let r = (0..3)
            .map(|k| (p[1][k] - p[0][k]).powi(2))
            .sum::<f64>()
            .sqrt();
        r_min = r_min.min(r);
        r_max = r_max.max(r);
        worst = worst.max((md.thermo().total - e0).abs());
        let cm: f64 = (0..2).map(|i| p[i][0]).sum::<f64>() / 2.0;
        assert!((cm - 0.75).abs() < 1e-12);
    }
    // Measured: inner turning point within 2e-7 σ, outer within 1e-9 σ, |ΔE| ≤ 3e-7 ε.
    assert!((r_min - inner).abs() < 1e-6, "r_min {r_min} vs {inner}");
    assert!((r_max - 1.5).abs() < 1e-6, "r_max {r_max}");
    assert!(worst < 1e-6 * e0.abs(), "energy error {worst:e}");
    eprintln!(
        "inner {inner}: r_min - inner = {:e}, r_max - 1.5 = {:e}, |dE| = {worst:e}",
        r_min - inner,
        r_max - 1.5
    );
}

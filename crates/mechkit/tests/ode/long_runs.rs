//! Symplectic methods over 10⁶ steps: the energy error of Yoshida 4, Forest-Ruth and PEFRL
//! stays bounded (its largest value over the last tenth of the run is no more than 1.5 times
//! that over the first tenth), while RK4 at the same step drifts monotonically; on the Kepler
//! orbit (e = 0.5) and on a large-amplitude pendulum. Also checks the pendulum's period.

use mechkit::ode::reference::{Kepler, Pendulum};
use mechkit::ode::{Composition, Rk4, SecondOrderSystem, State, Stepper, Symplectic};

const STEPS: usize = 1_000_000;

/// Largest |ΔE/E| in each tenth of the run.
fn tenths<S: SecondOrderSystem>(
    sys: &S,
    stepper: &mut dyn Stepper<S>,
    y0: &[f64],
    h: f64,
    energy: impl Fn(&[f64]) -> f64,
) -> Vec<f64> {
    let mut s = State::new(0.0, y0.to_vec());
    let e0 = energy(&s.y);
    let mut worst = vec![0.0f64; 10];
    for i in 0..STEPS {
        stepper.step(sys, &mut s, h).unwrap();
        let k = i * 10 / STEPS;
        worst[k] = worst[k].max(((energy(&s.y) - e0) / e0).abs());
    }
    worst
}

fn check<S: SecondOrderSystem>(
    name: &str,
    sys: &S,
    y0: &[f64],
    h: f64,
    energy: impl Fn(&[f64]) -> f64 + Copy,
) {
    for c in [
        Composition::yoshida4(),
        Composition::forest_ruth(),
        Composition::pefrl(),
    ] {
        let label = c.name;
        let w = tenths(sys, &mut Symplectic::new(c), y0, h, energy);
        println!(
            "{name}, {label}: max |dE/E| first tenth {:.3e}, last tenth {:.3e}",
            w[0], w[9]
        );
        assert!(w[9] <= 1.5 * w[0], "{name}, {label}: {w:?}");
    }
    let w = tenths(sys, &mut Rk4::new(), y0, h, energy);
    let shown: Vec<String> = w.iter().map(|x| format!("{x:.3e}")).collect();
    println!("{name}, rk4: max |dE/E| by tenth {shown:?}");
    assert!(
        w.windows(2).all(|p| p[1] > p[0]),
        "{name}, rk4 should drift: {w:?}"
    );
    assert!(w[9] > 5.0 * w[0], "{name}, rk4: {w:?}");
}

#[test]
fn kepler_energy_is_bounded_for_symplectic_methods_and_drifts_for_rk4() {
    let k = Kepler { e: 0.5 };
    let h = 2.0 * std::f64::consts::PI / 200.0; // 5000 orbits
    check("Kepler e = 0.5", &k, &k.initial(), h, move |y| k.energy(y));
}

#[test]
fn pendulum_energy_is_bounded_for_symplectic_methods_and_drifts_for_rk4() {
    let p = Pendulum {
        omega0: 1.0,
        theta0: 2.0,
    };
    let h = p.period() / 40.0; // 25 000 periods
    check("pendulum θ0 = 2 rad", &p, &p.initial(), h, move |y| {
        p.energy(y)
    });
}

#[test]
fn pendulum_period_matches_the_elliptic_integral() {
    // T = 4 K(k)/ω0 with k = sin(θ0/2)
    let p = Pendulum {
        omega0: 1.0,
        theta0: 2.0,
    };
    let mut s = State::new(0.0, p.initial().to_vec());
    let mut st = Symplectic::new(Composition::pefrl());
    let h = 1e-3;
    let mut prev = s.y[1];
    let mut crossings = Vec::new();
    while crossings.len() < 2 {
        let t = s.t;
        st.step(&p, &mut s, h).unwrap();
        if prev < 0.0 && s.y[1] >= 0.0 || prev > 0.0 && s.y[1] <= 0.0 {
            crossings.push(t + h * prev / (prev - s.y[1]));
        }
        prev = s.y[1];
    }
    // θ' = 0 at half and full periods
    assert!(
        (crossings[1] - p.period()).abs() < 1e-5,
        "{crossings:?} vs {}",
        p.period()
    );
    // 4 K(sin²1) from scipy.special.ellipk
    assert!(
        (p.period() - 8.349_752_926_918_494).abs() < 1e-12,
        "{}",
        p.period()
    );
}

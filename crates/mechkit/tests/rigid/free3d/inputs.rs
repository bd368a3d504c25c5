//! Bodies from mass properties, and bad input refused with the offending value.

use mechkit::mass::{MassProperties, Mat3, Vec3};
use mechkit::rigid::free3d::{
    Formulation, Free3dError, FreeBody, SpinIntegrator, SpinOptions, SpinningBody,
};
use nalgebra::{UnitQuaternion, Vector3};

use super::{options, start};

#[test]
fn a_body_from_mass_properties_has_its_principal_moments() {
    let i = Mat3::from_diagonal(&Vec3::new(13.0, 10.0, 5.0));
    let props = MassProperties::new(12.0, Vec3::zeros(), i).rotated(
        &nalgebra::Rotation3::from_axis_angle(&Vector3::z_axis(), 0.5),
    );
    let (body, axes) = FreeBody::from_mass_properties(&props).unwrap();
    let m = body.moments();
    assert!(
        (m[0] - 5.0).abs() < 1e-12 && (m[2] - 13.0).abs() < 1e-12,
        "{m:?}"
    );
    assert_eq!(body.mass(), 12.0);
    // the body-frame tensor rotated by the axes is the given one
    let back = axes.to_rotation_matrix().matrix()
        * Mat3::from_diagonal(&Vec3::from(m))
        * axes.to_rotation_matrix().matrix().transpose();
    assert!((back - props.inertia).norm() < 1e-12);
    // a point mass has no rotational inertia
    let point = MassProperties::point(1.0, Vec3::zeros());
    assert!(matches!(
        FreeBody::from_mass_properties(&point),
        Err(Free3dError::Moment { .. })
    ));
}

#[test]
fn bad_input_is_refused_with_the_offending_value() {
    let err = |r: Result<FreeBody, Free3dError>| r.unwrap_err().to_string();
    assert!(err(FreeBody::new([1.0, -2.0, 3.0], 1.0)).contains("I2 = -2"));
    assert!(err(FreeBody::new([1.0, 2.0, f64::NAN], 1.0)).contains("I3"));
    let e = err(FreeBody::new([1.0, 1.0, 2.5], 1.0));
    assert!(e.contains("triangle inequality") && e.contains("I3"), "{e}");
    assert!(err(FreeBody::new([1.0, 2.0, 3.0], 0.0)).contains("mass"));
    let body = FreeBody::new([1.0, 2.0, 3.0], 1.0).unwrap();
    assert!(matches!(
        SpinningBody::on_pivot(body, Vec3::new(0.0, 0.0, 1.0), -9.81),
        Err(Free3dError::Gravity { .. })
    ));
    assert!(matches!(
        SpinningBody::on_pivot(body, Vec3::new(f64::INFINITY, 0.0, 1.0), 9.81),
        Err(Free3dError::NonFinite { .. })
    ));
    let free = SpinningBody::free(body);
    let a = start(&free, [0.0, 1.0, 0.0]);
    assert!(matches!(
        free.simulate(&a, 0.0, &SpinOptions::default()),
        Err(Free3dError::Duration { .. })
    ));
    let fixed = |dt| options(SpinIntegrator::Splitting { dt }, Formulation::World, 1);
    assert!(matches!(
        free.simulate(&a, 1.0, &fixed(-1.0)),
        Err(Free3dError::Step { .. })
    ));
    assert!(matches!(
        free.simulate(&a, 1e6, &fixed(1e-6)),
        Err(Free3dError::TooManySteps { .. })
    ));
    let tilted = SpinningBody::on_pivot(body, Vec3::new(0.1, 0.0, 1.0), 9.81).unwrap();
    assert!(matches!(
        tilted.simulate(&a, 1.0, &fixed(0.01)),
        Err(Free3dError::SplittingOffAxis { .. })
    ));
    assert!(
        free.attitude(UnitQuaternion::identity(), Vec3::new(f64::NAN, 0.0, 0.0))
            .is_err()
    );
}

/// `mechkit spin --t-max 1e300` (and `1e6`) ran for ever, and `--dt 1e-320` printed "inf fixed
/// steps of 0.000…1 s". A subnormal step is refused; fixed steps past the models' budget are
/// refused before the run; adaptive steps stop at the budget, which names the end time.
#[test]
fn a_run_longer_than_the_step_budget_is_refused_at_its_end_time() {
    use mechkit::ode::{AdaptiveConfig, STEP_BUDGET, Tableau};
    use mechkit::rigid::Input;
    let body = SpinningBody::free(FreeBody::new([1.0, 2.0, 3.0], 1.0).unwrap());
    let a = start(&body, [0.01, 1.0, 0.01]);
    let fixed = |dt| {
        options(
            SpinIntegrator::Fixed {
                tableau: Tableau::rk4(),
                dt,
            },
            Formulation::World,
            1,
        )
    };
    let e = body.simulate(&a, 10.0, &fixed(1e-320)).unwrap_err();
    assert!(matches!(e, Free3dError::Step { .. }), "{e}");
    assert!(e.to_string().contains("at least 2.2e-308 s"), "{e}");
    let e = body.simulate(&a, 1e300, &fixed(1e-3)).unwrap_err();
    assert!(matches!(e, Free3dError::TooManySteps { .. }), "{e}");
    assert!(
        e.to_string().starts_with("1e303 fixed steps of 0.001 s"),
        "{e}"
    );
    let steps = 10.0 * STEP_BUDGET as f64;
    assert!(body.simulate(&a, steps * 1e-3, &fixed(1e-3)).is_err());
    let adaptive = SpinIntegrator::Adaptive {
        tableau: Tableau::dop853(),
        config: AdaptiveConfig {
            max_steps: Some(200),
            ..AdaptiveConfig::from_rtol(1e-10)
        },
    };
    let e = body
        .simulate(&a, 1e300, &options(adaptive, Formulation::World, 10))
        .unwrap_err();
    assert!(
        matches!(&e, Free3dError::Integrate(i) if i.is_step_budget()),
        "{e}"
    );
    assert_eq!(e.input(), Some(Input::Duration));
}

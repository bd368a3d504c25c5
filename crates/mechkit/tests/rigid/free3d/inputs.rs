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

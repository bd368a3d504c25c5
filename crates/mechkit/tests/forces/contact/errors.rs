//! Contacts that make no sense are refused when built: a stiffness that is not positive, a
//! negative damping coefficient, a wall without a direction.

use mechkit::forces::{ContactDamping, ContactError, ContactForce, ContactLaw};

#[test]
fn bad_contacts_are_refused() {
    let floor = || ContactForce::builder(2).wall(&[0.0, 0.0], &[0.0, 1.0], &[(0, 0.1)]);
    let err = floor().law(ContactLaw::linear(-5.0)).build().unwrap_err();
    assert_eq!(err, ContactError::BadStiffness(-5.0));
    assert!(err.to_string().contains("positive"), "{err}");
    assert_eq!(
        floor().law(ContactLaw::hertz(0.0)).build().unwrap_err(),
        ContactError::BadStiffness(0.0)
    );
    for (damping, name) in [
        (ContactDamping::Linear { c: -1.0 }, "c"),
        (ContactDamping::HuntCrossley { alpha: -0.1 }, "alpha"),
    ] {
        let err = floor()
            .law(ContactLaw::linear(10.0))
            .damping(damping)
            .build()
            .unwrap_err();
        assert!(matches!(err, ContactError::BadDamping { name: n, .. } if n == name));
    }
    let zero_normal = ContactForce::builder(2)
        .law(ContactLaw::linear(10.0))
        .wall(&[0.0, 0.0], &[0.0, 0.0], &[(0, 0.1)])
        .build()
        .unwrap_err();
    assert_eq!(zero_normal, ContactError::BadNormal(vec![0.0, 0.0]));
    // it converts into the crate's error
    let e: mechkit::Error = zero_normal.into();
    assert!(e.to_string().contains("normal"), "{e}");
}

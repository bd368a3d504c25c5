//! The image method on bodies drawn pixel by pixel, so the expected values are exact: a disk
//! (centre of mass at its centre to the last bit, `I = ½ M R²` within the discretisation),
//! a ring (`I = M (R₁² + R₂²)/2`), an equilateral triangle (`Y_cm = b/√3` above its base),
//! the sign of the product of inertia with y up, inverted selections, density from the shade,
//! selections that mark nothing or everything, and the marked picture.

use super::*;
use crate::Real;
use crate::mass::Vec3;

const WHITE: [Real; 3] = [1.0; 3];
const BLACK: [Real; 3] = [0.0; 3];

/// A black shape on white: `inside(x, y)` at pixel centres.
fn draw(w: usize, h: usize, inside: impl Fn(Real, Real) -> bool) -> Raster {
    Raster::from_fn(w, h, |i, j| {
        if inside(i as Real + 0.5, j as Real + 0.5) {
            BLACK
        } else {
            WHITE
        }
    })
}

/// `(count, Σ |r − c|² + 1/6 per pixel)` over the pixel centres `inside`: the polar moment of
/// the rasterised body about `c`, summed directly.
fn direct_polar(
    w: usize,
    h: usize,
    c: [Real; 2],
    inside: impl Fn(Real, Real) -> bool,
) -> (Real, Real) {
    let (mut n, mut sum) = (0.0, 0.0);
    for j in 0..h {
        for i in 0..w {
            let (x, y) = (i as Real + 0.5, j as Real + 0.5);
            if inside(x, y) {
                n += 1.0;
                sum += (x - c[0]).powi(2) + (y - c[1]).powi(2) + 1.0 / 6.0;
            }
        }
    }
    (n, sum)
}

/// Pixel centres at distances `lo ≤ r < hi` from (200, 200).
fn within(lo: Real, hi: Real) -> impl Fn(Real, Real) -> bool {
    move |x, y| {
        let d2 = (x - 200.0).powi(2) + (y - 200.0).powi(2);
        lo * lo <= d2 && d2 < hi * hi
    }
}

#[test]
fn disk_centre_of_mass_is_exact_and_inertia_is_half_m_r_squared() {
    let r = 150.0;
    let inside = within(0.0, r);
    let body = PixelBody::measure(&draw(400, 400, &inside), &Selection::default()).unwrap();
    assert_eq!(body.centre, [200.0, 200.0]);
    assert_eq!(body.spread[2], 0.0);
    let (n, polar) = direct_polar(400, 400, [200.0, 200.0], &inside);
    assert_eq!(body.count as Real, n);
    assert!((body.area(1.0) / (std::f64::consts::PI * r * r) - 1.0).abs() < 1e-4);
    // R = 150 px = 1 m, M = 1 kg: I_zz is I/(M R²)
    let frame = PixelFrame::bottom_left(400, 1.0 / r).unwrap();
    let p = body.mass_properties(&frame, Some(1.0)).unwrap();
    let ratio = p.inertia[(2, 2)];
    // the direct sum rounds 70 688 additions; the measurement's sums are exact
    assert!(
        (ratio / (polar / n / (r * r)) - 1.0).abs() < 1e-12,
        "{ratio}"
    );
    assert!((ratio - 0.5).abs() < 5e-5, "{ratio}"); // 0.5000227: the rasterised disk
    // thin plate: I_zz = I_xx + I_yy, and by symmetry I_xx = I_yy
    assert!((p.inertia[(0, 0)] - p.inertia[(1, 1)]).abs() < 1e-15);
    assert!((p.inertia[(0, 0)] + p.inertia[(1, 1)] - ratio).abs() < 1e-15);
    assert!((p.centre_of_mass - Vec3::new(200.0 / r, 200.0 / r, 0.0)).norm() < 1e-15);
}

#[test]
fn ring_inertia_is_m_times_mean_square_radius() {
    let (r1, r2) = (80.0, 150.0);
    let inside = within(r1, r2);
    let body = PixelBody::measure(&draw(400, 400, &inside), &Selection::default()).unwrap();
    assert_eq!(body.centre, [200.0, 200.0]);
    let p = body
        .mass_properties(&PixelFrame::new(1.0, [0.0; 2]).unwrap(), Some(2.0))
        .unwrap();
    let (n, polar) = direct_polar(400, 400, [200.0, 200.0], &inside);
    let izz = p.inertia[(2, 2)];
    assert!((izz / (2.0 * polar / n) - 1.0).abs() < 1e-12);
    let analytic = 2.0 * (r1 * r1 + r2 * r2) / 2.0;
    assert!((izz / analytic - 1.0).abs() < 1e-4, "{izz} vs {analytic}");
    // about a point on the outer edge (Steiner): I + M R₂²
    let edge = p.inertia_about(&Vec3::new(200.0 + r2, -200.0, 0.0))[(2, 2)];
    assert!((edge - (izz + 2.0 * r2 * r2)).abs() < 1e-9 * edge);
}

#[test]
fn equilateral_triangle_centre_is_b_over_root_3_above_the_base() {
    // side 2b = 300 px, base on the bottom edge of a 400 × 400 image, centred
    let b = 150.0;
    let inside = |x: Real, y: Real| 400.0 - y < 3f64.sqrt() * (b - (x - 200.0).abs());
    let body = PixelBody::measure(&draw(400, 400, inside), &Selection::default()).unwrap();
    assert_eq!(body.centre[0], 200.0);
    // origin at the base's centre, b = 1
    let frame = PixelFrame::new(1.0 / b, [200.0, 400.0]).unwrap();
    let p = body.mass_properties(&frame, None).unwrap();
    let y_over_b = p.centre_of_mass.y;
    assert!((y_over_b - 1.0 / 3f64.sqrt()).abs() < 5e-4, "{y_over_b}");
    assert!(
        (y_over_b - 0.577_303_363_098_292_9).abs() < 1e-12,
        "{y_over_b}"
    );
    assert_eq!(p.centre_of_mass.x, 0.0);
    // no mass given: areal density 1, so the mass is the area (√3 b² for b = 1)
    assert!((p.mass / 3f64.sqrt() - 1.0).abs() < 1e-3);
    assert!((p.mass - body.area(1.0 / b)).abs() < 1e-15);
}

#[test]
fn products_of_inertia_follow_y_up() {
    // "\" in the image (y down): X and Y anti-correlated with y up, so ∫XY < 0, I_xy > 0
    let img = Raster::from_fn(3, 3, |x, y| if x == y && x < 2 { BLACK } else { WHITE });
    let body = PixelBody::measure(&img, &Selection::default()).unwrap();
    assert_eq!(body.spread, [0.5 + 1.0 / 6.0, 0.5 + 1.0 / 6.0, 0.5]);
    let p = body
        .mass_properties(&PixelFrame::bottom_left(3, 1.0).unwrap(), None)
        .unwrap();
    assert_eq!(p.inertia[(0, 1)], 0.5);
    assert_eq!(p.centre_of_mass, Vec3::new(1.0, 2.0, 0.0));
}

#[test]
fn inverting_selects_the_background() {
    let inside = within(0.0, 50.0);
    let img = draw(300, 200, |x, y| inside(x + 100.0, y + 100.0));
    let disk = PixelBody::measure(&img, &Selection::default()).unwrap();
    let rest = PixelBody::measure(&img, &Selection::default().inverted(true)).unwrap();
    assert_eq!(disk.count + rest.count, img.pixels());
    // the first moments add up to the whole image's
    for k in 0..2 {
        let whole = 0.5 * [300.0, 200.0][k] * img.pixels() as Real;
        let sum = disk.weight * disk.centre[k] + rest.weight * rest.centre[k];
        assert!((sum - whole).abs() < 1e-9 * whole);
    }
    assert_eq!(disk.centre, [100.0, 100.0]);
}

#[test]
fn density_from_darkness_weights_by_shade() {
    // a black column and a grey (level 170, value 2 on the sum) column, on white
    let img = Raster::from_fn(4, 2, |x, _| match x {
        0 => BLACK,
        1 => [2.0 / 3.0; 3],
        _ => WHITE,
    });
    let shade = Selection::default()
        .threshold(2.5)
        .density(Density::Darkness);
    let body = PixelBody::measure(&img, &shade).unwrap();
    // weights 1 and 1/3: x̄ = (0.5·1 + 1.5/3)/(4/3) = 0.75
    assert_eq!(body.count, 4);
    assert!((body.weight - 8.0 / 3.0).abs() < 1e-15);
    assert!((body.centre[0] - 0.75).abs() < 1e-15);
    let uniform = PixelBody::measure(&img, &shade.density(Density::Uniform)).unwrap();
    assert_eq!(uniform.centre[0], 1.0);
}

#[test]
fn nothing_or_everything_selected_reports_the_brightness() {
    let img = draw(20, 10, |x, _| x < 5.0);
    for (threshold, word) in [(0.0, "none"), (4.0, "every")] {
        let e = PixelBody::measure(&img, &Selection::default().threshold(threshold)).unwrap_err();
        let text = e.to_string();
        assert!(
            text.contains(word) && text.contains("from 0 to 3"),
            "{text}"
        );
        let brightness = match e {
            ImageError::SelectsNothing { brightness, .. }
            | ImageError::SelectsEverything { brightness, .. } => brightness,
            other => panic!("{other:?}"),
        };
        assert_eq!(brightness.percentiles[1], (10, 0.0));
        assert_eq!(brightness.percentiles[3], (90, 3.0));
    }
    let e = PixelBody::measure(&img, &Selection::default().threshold(Real::NAN));
    assert!(matches!(e, Err(ImageError::Invalid(_))));
    let body = PixelBody::measure(&img, &Selection::default()).unwrap();
    assert!(
        body.mass_properties(&PixelFrame::new(1.0, [0.0; 2]).unwrap(), Some(-1.0))
            .is_err()
    );
}

#[test]
fn the_marked_picture_tints_the_body_and_marks_the_centre() {
    let inside = within(0.0, 150.0);
    let img = draw(400, 400, &inside);
    let sel = Selection::default();
    let body = PixelBody::measure(&img, &sel).unwrap();
    let marked = img.marked(&sel, body.centre);
    assert_eq!(marked.rgb8(200, 200), MARK);
    assert_eq!(marked.rgb8(100, 200), TINT.map(|c| c / 2));
    // outside the mark, unselected pixels are unchanged
    let arm = 400.0 / 12.0;
    for j in 0..400 {
        for i in 0..400 {
            let (x, y) = (i as Real + 0.5, j as Real + 0.5);
            let near = (x - 200.0).abs().max((y - 200.0).abs()) <= arm + 3.0;
            if !inside(x, y) && !near {
                assert_eq!(marked.rgb8(i, j), img.rgb8(i, j), "({i}, {j})");
            }
        }
    }
}

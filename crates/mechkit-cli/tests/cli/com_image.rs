//! `mechkit com IMAGE`: the course's image method through the command line. A black disk
//! (radius 150 px at (200, 200)) has its centre of mass at (200, 200) px exactly, in the text
//! and the JSON output, and so has the background when the selection is inverted; a pixel
//! size and the equivalent scale give the same physical result, with y up from the
//! bottom-left corner; the marked picture is a PNG of the same size with the centre marked;
//! the ball photo of the course (`ballimage02cut.png`) has a round body of about 300 pixels
//! whose radius of gyration is that of a disk, R/√2. Bad input exits 2 and says what is
//! wrong: GIF bytes (whatever the file's name), text, a missing file, a threshold that
//! selects nothing or everything (with the brightness range), a pixel size that is not a
//! length, a malformed scale or origin, a length for --about without a scale.

use mechkit::mass::image::{MARK, Raster};

use crate::util::{Dir, examples, num};

fn image(name: &str) -> String {
    examples().join("data").join(name).display().to_string()
}

#[test]
fn disk_text_and_json() {
    let dir = Dir::new();
    let disk = image("disk_r150.png");
    let out = dir.run(&["com", &disk]);
    out.assert_code(0);
    assert!(out.stdout.contains("70688 pixels"), "{}", out.stdout);
    assert!(
        out.stdout.contains(
            "centre of mass in pixels (x right, y down from the top-left corner): (200, 200)"
        ),
        "{}",
        out.stdout
    );
    let j = dir.json(&["com", &disk, "--json"]);
    assert_eq!(j["source"], "image");
    assert_eq!((num(&j, "/width"), num(&j, "/height")), (400.0, 400.0));
    assert_eq!(j["channel"], "sum");
    assert_eq!(num(&j, "/threshold"), 1.5);
    assert_eq!(num(&j, "/selected_pixels"), 70688.0);
    assert_eq!(num(&j, "/pixel_centre_of_mass/0"), 200.0);
    assert_eq!(num(&j, "/pixel_centre_of_mass/1"), 200.0);
    // no scale: pixels, y up from the bottom-left corner
    assert_eq!(j["unit"], "px");
    assert!(j["pixel_size"].is_null() && j["mass"].is_null() && j["mark"].is_null());
    assert_eq!(num(&j, "/origin_pixel/1"), 400.0);
    assert_eq!(num(&j, "/centre_of_mass/1"), 200.0);
    assert_eq!(num(&j, "/area"), 70688.0);
    // the polar moment is the sum of the in-plane ones (thin plate)
    let (xx, yy, zz) = (
        num(&j, "/inertia_cm/xx"),
        num(&j, "/inertia_cm/yy"),
        num(&j, "/inertia_cm/zz"),
    );
    assert!((xx + yy - zz).abs() < 1e-9 * zz);
    // the background: the rest of the square, centred on the same point
    let rest = dir.json(&["com", &disk, "--invert", "--json"]);
    assert_eq!(num(&rest, "/selected_pixels"), 160_000.0 - 70688.0);
    assert_eq!(num(&rest, "/pixel_centre_of_mass/0"), 200.0);
}

#[test]
fn pixel_size_scale_mass_and_a_point() {
    let dir = Dir::new();
    let disk = image("disk_r150.png");
    let common = [
        "com",
        &disk,
        "--total-mass",
        "2 kg",
        "--about",
        "0, 0",
        "--json",
    ];
    let a = dir.json(&[&common[..], &["--pixel-size", "0.5 mm"]].concat());
    let b = dir.json(&[&common[..], &["--scale", "2 px = 1 mm"]].concat());
    for key in ["/centre_of_mass/0", "/inertia_cm/zz", "/about/zz", "/area"] {
        assert!(
            (num(&a, key) - num(&b, key)).abs() <= 1e-15 * num(&a, key).abs(),
            "{key}"
        );
    }
    assert_eq!(a["unit"], "m");
    assert_eq!(num(&a, "/pixel_size"), 5e-4);
    assert_eq!(num(&a, "/mass"), 2.0);
    // centre at (0.1 m, 0.1 m); about the origin: I + M d² (Steiner)
    assert!((num(&a, "/centre_of_mass/0") - 0.1).abs() < 1e-15);
    let steiner = num(&a, "/inertia_cm/zz") + 2.0 * 0.02;
    assert!((num(&a, "/about/zz") - steiner).abs() < 1e-12);
    // the radius of gyration of a disk, R/√2 (R = 75 mm)
    assert!((num(&a, "/radius_of_gyration") - 0.075 / 2f64.sqrt()).abs() < 1e-5);
}

#[test]
fn the_marked_picture_is_a_png_with_the_centre_marked() {
    let dir = Dir::new();
    let out = dir.run(&["com", &image("disk_r150.png"), "--mark", "marked.png"]);
    out.assert_code(0);
    assert!(out.stdout.contains("marked image written to marked.png"));
    let bytes = std::fs::read(dir.path().join("marked.png")).unwrap();
    assert!(bytes.starts_with(b"\x89PNG\r\n\x1a\n"));
    let marked = Raster::open(dir.path().join("marked.png")).unwrap();
    assert_eq!((marked.width(), marked.height()), (400, 400));
    assert_eq!(marked.rgb8(200, 200), MARK);
    assert_eq!(marked.rgb8(5, 5), [255; 3]);
    assert_ne!(marked.rgb8(100, 200), [0; 3]); // the body, tinted
    assert!(!dir.path().join("marked.png.partial").exists());
}

#[test]
fn the_ball_photo() {
    let dir = Dir::new();
    let j = dir.json(&["com", &image("ballimage02cut.png"), "--json"]);
    assert_eq!((num(&j, "/width"), num(&j, "/height")), (331.0, 234.0));
    let (x, y) = (
        num(&j, "/pixel_centre_of_mass/0"),
        num(&j, "/pixel_centre_of_mass/1"),
    );
    assert!(
        (x - 147.05).abs() < 0.01 && (y - 44.84).abs() < 0.01,
        "({x}, {y})"
    );
    let n = num(&j, "/selected_pixels");
    assert!((250.0..350.0).contains(&n), "{n}");
    // round: the radius of gyration of a disk of that area, R/√2, within 5 %
    let disk = (n / std::f64::consts::PI).sqrt() / 2f64.sqrt();
    assert!((num(&j, "/radius_of_gyration") / disk - 1.0).abs() < 0.05);
}

#[test]
fn bad_images_and_flags() {
    let dir = Dir::new();
    dir.create("ball.png", "GIF89a\u{1}\u{0}\u{1}\u{0}");
    dir.run(&["com", "ball.png"])
        .assert_bad_input(&["ball.png: this is a GIF image", "PNG and JPEG"]);
    dir.create("anim.gif", "GIF87a");
    dir.run(&["com", "anim.gif"])
        .assert_bad_input(&["a GIF image"]);
    dir.create("notes.jpg", "x, y\n1, 2\n");
    dir.run(&["com", "notes.jpg"])
        .assert_bad_input(&["notes.jpg: this is text"]);
    dir.run(&["com", "missing.png"])
        .assert_bad_input(&["missing.png: no such file"]);
    let disk = image("disk_r150.png");
    dir.run(&["com", &disk, "--threshold", "0"])
        .assert_bad_input(&[
            "R+G+B < 0 marks none of the 160000 pixels",
            "from 0 to 3",
            "--threshold",
        ]);
    dir.run(&["com", &disk, "--threshold", "4"])
        .assert_bad_input(&["marks every one", "50 %: 3"]);
    dir.run(&["com", &disk, "--pixel-size", "2 kg"])
        .assert_bad_input(&["--pixel-size `2 kg`", "m (length) is needed"]);
    dir.run(&["com", &disk, "--scale", "12 cm"])
        .assert_bad_input(&["--scale takes", "240 px = 12 cm"]);
    dir.run(&["com", &disk, "--origin", "200"])
        .assert_bad_input(&["--origin takes two coordinates"]);
    dir.run(&["com", &disk, "--channel", "hue"])
        .assert_bad_input(&["--channel", "sum (R+G+B), r, g or b"]);
    dir.run(&["com", &disk, "--about", "1 cm, 0"])
        .assert_bad_input(&["no scale"]);
    dir.run(&["com", &disk, "--mark", "out.jpg"])
        .assert_bad_input(&["--mark writes a PNG"]);
    dir.run(&["com", &disk, "--mass", "1 kg"])
        .assert_bad_input(&["--mass is for point masses"]);
}

/// Whether a pixel centre is inside a shape.
type Shape = dyn Fn(f64, f64) -> bool;

#[test]
fn shapes_match_their_generator() {
    // examples/data/shapes.py: black where the pixel centre is inside the shape
    let disk = |x: f64, y: f64| (x - 200.0).powi(2) + (y - 200.0).powi(2) < 150f64.powi(2);
    let triangle = |x: f64, y: f64| 400.0 - y < 3f64.sqrt() * (150.0 - (x - 200.0).abs());
    let shapes: [(&str, &Shape); 2] = [("disk_r150.png", &disk), ("triangle_b150.png", &triangle)];
    for (name, inside) in shapes {
        let img = Raster::open(examples().join("data").join(name)).unwrap();
        assert_eq!((img.width(), img.height()), (400, 400));
        for j in 0..400 {
            for i in 0..400 {
                let want = if inside(i as f64 + 0.5, j as f64 + 0.5) {
                    0
                } else {
                    255
                };
                assert_eq!(img.rgb8(i, j), [want; 3], "{name} ({i}, {j})");
            }
        }
    }
}

/// A photo is recognised by its first bytes whatever its name (a file saved without an
/// extension used to be read as a body file: "stream did not contain valid UTF-8").
#[test]
fn an_image_without_an_extension_is_read_as_an_image() {
    let dir = Dir::new();
    std::fs::copy(
        examples().join("data/disk_r150.png"),
        dir.path().join("photo"),
    )
    .expect("copied");
    let out = dir.run(&["com", "photo", "--json"]);
    out.assert_code(0);
    assert_eq!(out.json()["area"], 70688.0);
    assert_eq!(
        out.json()["centre_of_mass"],
        serde_json::json!([200.0, 200.0])
    );
}

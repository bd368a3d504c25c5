//! Images of a body (`mechkit com IMAGE`): unreadable files and selections of the pixels.

use mechkit::mass::image::Raster;

use super::case::{
    Case,
    Contents::{Bytes, Text},
    assert_cases,
};

#[test]
fn image_messages() {
    assert_cases(CASES);
}

/// A 4 × 4 PNG of one grey level.
fn png(level: u8) -> Vec<u8> {
    Raster::from_rgb8(4, 4, vec![level; 4 * 4 * 3])
        .expect("a 4 × 4 raster")
        .to_png()
        .expect("the raster encodes")
}

fn white() -> Vec<u8> {
    png(255)
}

fn black() -> Vec<u8> {
    png(0)
}

/// A 4 × 4 PNG, black on the left half and white on the right.
fn half() -> Vec<u8> {
    let rgb = (0..16)
        .flat_map(|i| [if i % 4 < 2 { 0 } else { 255 }; 3])
        .collect();
    Raster::from_rgb8(4, 4, rgb)
        .expect("a 4 × 4 raster")
        .to_png()
        .expect("the raster encodes")
}

/// The start of a GIF file: enough to be recognised.
fn gif() -> Vec<u8> {
    b"GIF89a\x01\x00\x01\x00\x00\x00\x00".to_vec()
}

fn truncated() -> Vec<u8> {
    let mut bytes = png(0);
    bytes.truncate(40);
    bytes
}

/// A `mechkit com IMAGE …` case.
macro_rules! com {
    ($kind:literal, $name:literal, $make:expr $(, $arg:literal)*) => {
        Case {
            area: "image",
            kind: $kind,
            files: &[($name, $make)],
            args: &["com", $name $(, $arg)*],
            code: 2,
        }
    };
}

pub static CASES: &[Case] = &[
    Case {
        area: "image",
        kind: "file_not_found",
        files: &[],
        args: &["com", "photo.png"],
        code: 2,
    },
    com!("not_an_image", "photo.png", Text("not an image\n")),
    com!("unsupported_format", "photo.gif", Bytes(gif)),
    com!("cannot_decode", "photo.png", Bytes(truncated)),
    com!("selects_nothing", "white.png", Bytes(white)),
    com!("selects_everything", "black.png", Bytes(black)),
    com!("bad_channel", "black.png", Bytes(black), "--channel", "q"),
    com!("bad_scale", "black.png", Bytes(black), "--scale", "240 px"),
    com!(
        "pixel_size_dimension",
        "black.png",
        Bytes(black),
        "--pixel-size",
        "3 kg"
    ),
    com!("bad_origin", "black.png", Bytes(black), "--origin", "1"),
    Case {
        area: "output",
        kind: "unwritable_marked_image",
        files: &[
            ("half.png", Bytes(half)),
            ("afile", Text("a regular file, not a directory\n")),
        ],
        args: &["com", "half.png", "--mark", "afile/marked.png"],
        code: 2,
    },
];

//! The renderers on an animation built by hand: a ball of radius 0.1 m going once round a
//! circle of radius 1 m about the origin in 30 frames (starting at 45°), held by a spring
//! drawn from the origin, beside a wall, with a trail and energy bars K, U, E.
//!
//! The picture's geometry, worked out by hand for the default 640x480 canvas: text 12 px, a
//! header and a footer of 26.4 px, the energy panel the right 160 px; the scene is 480 by
//! 427.2 px, and the view (3 m by 2.5 m) fits it at 160 px/m, its left edge at x = 0 px and
//! its bottom edge at y = 440 px.

use std::f64::consts::PI;

use mechkit::animation::{Animation, Colour, EnergyBars, Frame, Geometry, Shape, Trail, View};

use super::{Canvas, frame_svg, gif, html};

const BALL: Colour = Colour(214, 39, 40);
const TRAIL: Colour = Colour(255, 127, 14);
const FRAMES: usize = 30;

/// Where the ball is at frame `i`.
fn ball(i: usize) -> [f64; 2] {
    let angle = PI / 4.0 + 2.0 * PI * i as f64 / FRAMES as f64;
    [angle.cos(), angle.sin()]
}

/// The pixel of the world point `p` on the default canvas (see the module's docs).
fn pixel(p: [f64; 2]) -> (usize, usize) {
    let x = (p[0] + 1.5) * 160.0;
    let y = 440.0 - (p[1] + 1.25) * 160.0;
    (x.round() as usize, y.round() as usize)
}

/// A zigzag of 8 coils from `a` to `b`.
fn spring(a: [f64; 2], b: [f64; 2]) -> Vec<[f64; 2]> {
    let (dx, dy) = (b[0] - a[0], b[1] - a[1]);
    let length = dx.hypot(dy);
    let (nx, ny) = (-dy / length * 0.06, dx / length * 0.06);
    (0..=18)
        .map(|k| {
            let s = f64::from(k) / 18.0;
            let side = match k {
                0 | 18 => 0.0,
                k if k % 2 == 1 => 1.0,
                _ => -1.0,
            };
            [a[0] + s * dx + side * nx, a[1] + s * dy + side * ny]
        })
        .collect()
}

pub(super) fn animation() -> Animation {
    let frames = (0..FRAMES)
        .map(|i| {
            let centre = ball(i);
            let u = 0.3 * (1.0 + centre[1]);
            Frame {
                t: i as f64 * 0.04,
                shapes: vec![
                    Shape {
                        geometry: Geometry::Polyline {
                            points: spring([0.0, 0.0], centre),
                        },
                        fill: None,
                        stroke: Some(Colour(31, 119, 180)),
                        line_width: 1.5,
                    },
                    Shape {
                        geometry: Geometry::Circle {
                            centre,
                            radius: 0.1,
                        },
                        fill: Some(BALL),
                        stroke: Some(Colour(0, 0, 0)),
                        line_width: 1.0,
                    },
                ],
                energy: vec![0.5, u, 0.5 + u],
            }
        })
        .collect();
    Animation {
        title: "Ball on a circle".into(),
        fps: 25.0,
        speed: 1.0,
        view: View {
            x_min: -1.5,
            x_max: 1.5,
            y_min: -1.25,
            y_max: 1.25,
        },
        length_unit: "m".into(),
        background: vec![
            Shape {
                geometry: Geometry::Polygon {
                    points: vec![[-1.45, -1.2], [-1.3, -1.2], [-1.3, 1.2], [-1.45, 1.2]],
                },
                fill: Some(Colour(150, 150, 150)),
                stroke: None,
                line_width: 0.0,
            },
            Shape {
                geometry: Geometry::Dot {
                    centre: [0.0, 0.0],
                    radius_px: 3.0,
                },
                fill: Some(Colour(0, 0, 0)),
                stroke: None,
                line_width: 0.0,
            },
        ],
        frames,
        trails: vec![Trail {
            name: "ball".into(),
            colour: TRAIL,
            points: (0..FRAMES).map(ball).collect(),
        }],
        energy: Some(EnergyBars {
            labels: vec!["K".into(), "U".into(), "E".into()],
            colours: vec![Colour(44, 160, 44), Colour(31, 119, 180), Colour(0, 0, 0)],
            unit: "J".into(),
            range: (0.0, 1.1),
        }),
    }
}

/// The GIF's logical size, each frame's delay, and each frame's whole picture as RGB: the
/// frames drawn one over the other as a player shows them.
pub(super) fn decode(bytes: &[u8]) -> ((usize, usize), Vec<u16>, Vec<Vec<u8>>) {
    let mut options = ::gif::DecodeOptions::new();
    options.set_color_output(::gif::ColorOutput::RGBA);
    let mut decoder = options.read_info(bytes).expect("a GIF");
    let (width, height) = (decoder.width() as usize, decoder.height() as usize);
    let mut screen = vec![255u8; width * height * 3];
    let (mut delays, mut pictures) = (Vec::new(), Vec::new());
    while let Some(frame) = decoder.read_next_frame().expect("a frame") {
        let (left, top) = (usize::from(frame.left), usize::from(frame.top));
        let w = usize::from(frame.width);
        for (k, p) in frame.buffer.chunks_exact(4).enumerate() {
            let (x, y) = (left + k % w, top + k / w);
            let at = 3 * (y * width + x);
            screen[at..at + 3].copy_from_slice(&p[..3]);
        }
        delays.push(frame.delay);
        pictures.push(screen.clone());
    }
    ((width, height), delays, pictures)
}

fn colour_at(picture: &[u8], width: usize, (x, y): (usize, usize)) -> [u8; 3] {
    let at = 3 * (y * width + x);
    [picture[at], picture[at + 1], picture[at + 2]]
}

fn near(c: [u8; 3], want: Colour) -> bool {
    [want.0, want.1, want.2]
        .iter()
        .zip(c)
        .all(|(&w, c)| w.abs_diff(c) <= 32)
}

#[test]
fn the_gif_has_every_frame_with_the_ball_where_the_world_puts_it() {
    let bytes = gif(&animation(), Canvas::default()).unwrap();
    let ((width, height), delays, pictures) = decode(&bytes);
    assert_eq!((width, height), (640, 480));
    assert_eq!(pictures.len(), FRAMES);
    assert!(delays.iter().all(|&d| d == 4), "1/25 s: {delays:?}");
    let (first, middle) = (pixel(ball(0)), pixel(ball(15)));
    assert_eq!(first, (353, 127));
    assert_eq!(middle, (127, 353));
    let at = |frame: usize, p| colour_at(&pictures[frame], width, p);
    assert!(
        near(at(0, first), BALL),
        "frame 0 at {first:?}: {:?}",
        at(0, first)
    );
    assert!(
        near(at(15, middle), BALL),
        "frame 15 at {middle:?}: {:?}",
        at(15, middle)
    );
    assert!(
        !near(at(15, first), BALL),
        "the ball has left: {:?}",
        at(15, first)
    );
    assert!(
        !near(at(0, middle), BALL),
        "not yet there: {:?}",
        at(0, middle)
    );
    // y up: the ball of frame 0 (45°) is above the origin's pixel row
    assert!(first.1 < pixel([0.0, 0.0]).1);
    // the trail of frame 15 (orange, 70 % opaque, thin: lighter) passes where the ball was
    let orange = |c: [u8; 3]| c[0] > 200 && c[2] < 160 && c[1] > c[2];
    let on_trail = (0..9).any(|d| orange(at(15, (first.0 - 1 + d % 3, first.1 - 1 + d / 3))));
    assert!(on_trail, "{:?}", at(15, first));
}

#[test]
fn odd_data_is_drawn_without_panicking() {
    let mut anim = animation();
    anim.view = View {
        x_min: 1.0,
        x_max: 1.0,
        y_min: f64::NAN,
        y_max: 2.0,
    };
    anim.frames[0].shapes.push(Shape {
        geometry: Geometry::Circle {
            centre: [f64::NAN, 0.0],
            radius: 0.1,
        },
        fill: Some(BALL),
        stroke: None,
        line_width: 1.0,
    });
    anim.trails[0].points[1] = [f64::INFINITY, 0.0];
    anim.energy.as_mut().unwrap().range = (f64::NAN, f64::NAN);
    anim.fps = 0.0;
    let svg = frame_svg(&anim, 0, Canvas::default());
    assert!(!svg.contains("NaN") && !svg.contains("inf"), "{svg}");
    parse(&svg);
    assert!(html(&anim, Canvas::default()).contains("id=\"slider\""));
    anim.frames.clear();
    let svg = frame_svg(&anim, 7, Canvas::default());
    assert!(!svg.contains("t = "), "no frame, no time");
    parse(&svg);
    let (_, delays, pictures) = decode(&gif(&anim, Canvas::default()).unwrap());
    assert_eq!((pictures.len(), delays), (1, vec![4]));
    let e = gif(
        &anim,
        Canvas {
            width: 5000,
            height: 480,
        },
    )
    .unwrap_err();
    assert!(e.to_string().contains("4096"), "{e}");
}

fn parse(svg: &str) -> resvg::usvg::Tree {
    resvg::usvg::Tree::from_str(svg, &resvg::usvg::Options::default())
        .unwrap_or_else(|e| panic!("{e}: {svg}"))
}

#[test]
fn the_svg_is_well_formed_with_markup_in_the_title() {
    let mut anim = animation();
    anim.title = "a <b> & c's \"d\"".into();
    let svg = frame_svg(&anim, 3, Canvas::default());
    assert!(
        svg.contains(">a &lt;b&gt; &amp; c&apos;s &quot;d&quot;</text>"),
        "{svg}"
    );
    assert!(svg.contains(">t = 0.120 s</text>"));
    assert!(svg.contains(">0.5 m</text>"), "a scale bar of 0.5 m: {svg}");
    assert!(svg.contains(">Energy (J)</text>") && svg.contains(">K</text>"));
    let tree = parse(&svg);
    assert_eq!(tree.size().width(), 640.0);
}

#[test]
fn mp4_without_ffmpeg_says_how_to_get_it() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("ball.mp4");
    let e = super::mp4::encode(&animation(), Canvas::default(), &out, None).unwrap_err();
    let e = e.to_string();
    assert!(
        e.contains("ffmpeg") && e.contains("PATH") && e.contains("gif"),
        "{e}"
    );
    assert!(!out.exists());
}

/// An `ffmpeg` that copies its input to its last argument: the frames piped to it are the
/// canvas's raw RGB, and the file is renamed into place.
#[cfg(unix)]
#[test]
fn mp4_pipes_every_frame_to_ffmpeg_and_renames_its_file() {
    use std::os::unix::fs::PermissionsExt as _;
    let dir = tempfile::tempdir().unwrap();
    let ffmpeg = dir.path().join("ffmpeg");
    std::fs::write(
        &ffmpeg,
        "#!/bin/sh\nfor last; do :; done\ncat > \"$last\"\n",
    )
    .unwrap();
    std::fs::set_permissions(&ffmpeg, std::fs::Permissions::from_mode(0o755)).unwrap();
    let canvas = Canvas {
        width: 101,
        height: 80,
    };
    let out = dir.path().join("ball.mp4");
    super::mp4::encode(&animation(), canvas, &out, Some(&ffmpeg)).unwrap();
    let bytes = std::fs::read(&out).unwrap();
    assert_eq!(bytes.len(), FRAMES * 100 * 80 * 3, "even sides: 100x80");
    assert!(!dir.path().join("ball.mp4.partial").exists());
    let e = super::mp4::encode(&animation(), canvas, dir.path(), Some(&ffmpeg)).unwrap_err();
    assert!(format!("{e:#}").contains("not a regular file"), "{e:#}");
    std::fs::write(&ffmpeg, "#!/bin/sh\necho 'Unknown encoder' >&2\nexit 1\n").unwrap();
    let e = super::mp4::encode(&animation(), canvas, &out, Some(&ffmpeg)).unwrap_err();
    assert!(e.to_string().contains("Unknown encoder"), "{e}");
    assert_eq!(std::fs::read(&out).unwrap().len(), bytes.len(), "kept");
}

/// Frames 0 and 15 as the GIF shows them, as PNG files in the directory named by
/// `MECHKIT_ANIM_LOOK`, with the HTML player, to look at (skipped without it).
#[test]
fn pictures_to_look_at() {
    let Some(dir) = std::env::var_os("MECHKIT_ANIM_LOOK") else {
        eprintln!("set MECHKIT_ANIM_LOOK=DIR to write frames to look at");
        return;
    };
    let dir = std::path::PathBuf::from(dir);
    std::fs::create_dir_all(&dir).unwrap();
    let anim = animation();
    let ((width, height), _, pictures) = decode(&gif(&anim, Canvas::default()).unwrap());
    for frame in [0, 15] {
        let file = std::fs::File::create(dir.join(format!("frame{frame}.png"))).unwrap();
        let mut encoder = png::Encoder::new(file, width as u32, height as u32);
        encoder.set_color(png::ColorType::Rgb);
        let mut writer = encoder.write_header().unwrap();
        writer.write_image_data(&pictures[frame]).unwrap();
        std::fs::write(
            dir.join(format!("frame{frame}.svg")),
            frame_svg(&anim, frame, Canvas::default()),
        )
        .unwrap();
    }
    std::fs::write(dir.join("ball.html"), html(&anim, Canvas::default())).unwrap();
}

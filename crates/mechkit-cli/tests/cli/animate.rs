//! `mechkit animate`: GIF and HTML from a scenario, from a run directory (the same player as
//! from the scenario), from an md run's XYZ frames; `[output] animation` in `mechkit run`;
//! MP4 without ffmpeg, and bad input.

use crate::util::{Dir, example};

/// The frames of a GIF file and its size.
fn gif_frames(path: &std::path::Path) -> (usize, u16, u16) {
    let file = std::fs::File::open(path).unwrap();
    let mut options = gif::DecodeOptions::new();
    options.set_color_output(gif::ColorOutput::Indexed);
    let mut decoder = options.read_info(file).unwrap();
    let (w, h) = (decoder.width(), decoder.height());
    let mut n = 0;
    while decoder.read_next_frame().unwrap().is_some() {
        n += 1;
    }
    (n, w, h)
}

#[test]
fn a_scenario_animates_as_gif_and_html() {
    let dir = Dir::new();
    let ball = example("bouncing_ball_floor.toml");
    let out = dir.json(&[
        "animate", &ball, "--out", "anim", "--format", "gif,html", "--fps", "10", "--json",
    ]);
    let frames = out["frames"].as_u64().unwrap() as usize;
    // 4.06 s in real time at 10 frames per second
    assert_eq!(frames, 42);
    let (n, w, h) = gif_frames(&dir.path().join("anim/animation.gif"));
    assert_eq!((n, w, h), (frames, 640, 480));
    let html = dir.read("anim/animation.html");
    assert!(!html.contains("http://") && !html.contains("https://"));
    assert!(html.contains("id=\"slider\"") && html.contains("id=\"play\""));
}

#[test]
fn a_run_directory_animates_as_its_scenario_does() {
    let dir = Dir::new();
    let pendulum = example("rigid/double_pendulum.toml");
    dir.run(&["run", &pendulum, "-o", "run", "-q", "--no-plots"])
        .assert_code(0);
    dir.run(&["animate", "run", "--format", "html", "-q"])
        .assert_code(0);
    dir.run(&[
        "animate", &pendulum, "--format", "html", "--out", "direct", "-q",
    ])
    .assert_code(0);
    // the CSV holds every digit: the same frames, the same player
    assert_eq!(
        dir.read("run/animation.html"),
        dir.read("direct/animation.html")
    );
}

#[test]
fn output_animation_writes_with_the_run() {
    let dir = Dir::new();
    let text = std::fs::read_to_string(example("spring_block.toml")).unwrap();
    let text = if text.contains("[output]") {
        text.replace("[output]", "[output]\nanimation = [\"gif\", \"html\"]")
    } else {
        format!("{text}\n[output]\nanimation = [\"gif\", \"html\"]\n")
    };
    dir.create("spring.toml", &text);
    dir.run(&["run", "spring.toml", "-o", "out", "-q"])
        .assert_code(0);
    let files = dir.files("out");
    assert!(files.contains(&"animation.gif".to_string()), "{files:?}");
    assert!(files.contains(&"animation.html".to_string()), "{files:?}");
    let (n, _, _) = gif_frames(&dir.path().join("out/animation.gif"));
    assert!(n >= 20, "{n} frames");
    dir.create(
        "bad.toml",
        &text.replace("animation = [\"gif\", \"html\"]", "animation = \"avi\""),
    );
    dir.run(&["check", "bad.toml"]).assert_bad_input(&[
        "bad.toml:",
        "unknown animation format `avi`",
        "\"html\"",
    ]);
}

#[test]
fn an_md_run_animates_from_its_xyz_frames() {
    let dir = Dir::new();
    dir.run(&[
        "md",
        "--cells",
        "4",
        "--steps",
        "40",
        "--xyz-every",
        "10",
        "-o",
        "md",
        "-q",
    ])
    .assert_code(0);
    let out = dir.json(&["animate", "md", "--json"]);
    assert_eq!(out["frames"], 5);
    let (n, _, _) = gif_frames(&dir.path().join("md/animation.gif"));
    assert_eq!(n, 5);
}

#[test]
fn mp4_without_ffmpeg_says_what_to_do() {
    let dir = Dir::new();
    let ball = example("bouncing_ball_floor.toml");
    let empty = dir.path().join("bin");
    std::fs::create_dir(&empty).unwrap();
    dir.run_with_env(
        &["animate", &ball, "--format", "mp4", "--out", "anim"],
        &[("PATH", empty.to_str().unwrap())],
    )
    .assert_bad_input(&["ffmpeg", "gif"]);
    assert!(!dir.path().join("anim/animation.mp4").exists());
}

#[test]
fn bad_input() {
    let dir = Dir::new();
    let ball = example("bouncing_ball_floor.toml");
    dir.run(&["animate", &ball]).assert_bad_input(&["--out"]);
    dir.run(&["animate", &ball, "--out", "a", "--format", "avi"])
        .assert_bad_input(&["--format", "`avi`", "gif, mp4 or html"]);
    dir.run(&["animate", &ball, "--out", "a", "--fps", "0"])
        .assert_bad_input(&["frame rate"]);
    dir.run(&["animate", &ball, "--out", "a", "--width", "10"])
        .assert_bad_input(&["width"]);
    std::fs::create_dir(dir.path().join("empty")).unwrap();
    dir.run(&["animate", "empty"])
        .assert_bad_input(&["not a run directory"]);
}

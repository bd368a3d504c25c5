//! The animation as an MP4 video, made by an `ffmpeg` found on the PATH: the frames
//! rasterised as [`gif`](super::gif) does and piped to it as raw RGB, encoded as yuv420p
//! (H.264 where the ffmpeg has it) into `NAME.partial` beside the output, renamed onto it when
//! ffmpeg succeeds.

use std::ffi::{OsStr, OsString};
use std::io::{Read as _, Write as _};
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};

use anyhow::{Context, Result, anyhow, bail};
use mechkit::animation::Animation;
use mechkit::csv::{partial_path, writable_target};
use resvg::tiny_skia::Pixmap;

use super::canvas::Canvas;
use super::gif::DEFAULT_FPS;
use super::pictures;

/// What to do without ffmpeg.
const NO_FFMPEG: &str = "an MP4 needs ffmpeg on the PATH, and none was found: install it \
     (`apt-get install ffmpeg`, `brew install ffmpeg`, `winget install ffmpeg`) or write a GIF \
     or an HTML player instead (`--format gif` or `--format html`)";

/// Writes `anim` to `out` as an MP4 video made by the `ffmpeg` on the PATH: every frame as
/// [`frame_svg`](super::frame_svg) draws it on `canvas` (odd sides one pixel smaller: the
/// video's colours need even ones), at `anim.fps` frames per second. Fails without ffmpeg
/// (saying how to get it), on a canvas outside [`Canvas::SIDES`], when `out` exists and is
/// not a regular file, or when ffmpeg fails (with what it said); `out` is replaced only by a
/// whole video.
pub fn mp4(anim: &Animation, canvas: Canvas, out: &Path) -> Result<()> {
    let ffmpeg = std::env::var_os("PATH").and_then(|path| find_ffmpeg(&path));
    encode(anim, canvas, out, ffmpeg.as_deref())
}

/// The first `ffmpeg` executable in the directories of `path`, a list in the form of the
/// `PATH` variable (`/usr/local/bin:/usr/bin`); empty entries are skipped.
pub fn find_ffmpeg(path: &OsStr) -> Option<PathBuf> {
    let name = if cfg!(windows) {
        "ffmpeg.exe"
    } else {
        "ffmpeg"
    };
    std::env::split_paths(path)
        .filter(|dir| !dir.as_os_str().is_empty())
        .map(|dir| dir.join(name))
        .find(|file| is_executable(file))
}

#[cfg(unix)]
fn is_executable(file: &Path) -> bool {
    use std::os::unix::fs::PermissionsExt as _;
    std::fs::metadata(file).is_ok_and(|m| m.is_file() && m.permissions().mode() & 0o111 != 0)
}

#[cfg(not(unix))]
fn is_executable(file: &Path) -> bool {
    file.is_file()
}

/// [`mp4`] with the ffmpeg found (or not) given.
pub(super) fn encode(
    anim: &Animation,
    canvas: Canvas,
    out: &Path,
    ffmpeg: Option<&Path>,
) -> Result<()> {
    let canvas = canvas.check()?.even();
    let Some(ffmpeg) = ffmpeg else {
        bail!(NO_FFMPEG);
    };
    let target = writable_target(out).with_context(|| format!("cannot write {}", out.display()))?;
    let partial = partial_path(&target);
    let made = run(ffmpeg, anim, canvas, &partial);
    if let Err(e) = made {
        let _ = std::fs::remove_file(&partial);
        return Err(e);
    }
    if let Err(e) = std::fs::rename(&partial, &target) {
        let _ = std::fs::remove_file(&partial);
        return Err(e).with_context(|| format!("cannot write {}", target.display()));
    }
    Ok(())
}

/// Runs `ffmpeg`, feeding it every frame, to write the video to `file`.
fn run(ffmpeg: &Path, anim: &Animation, canvas: Canvas, file: &Path) -> Result<()> {
    let mut child = Command::new(ffmpeg)
        .args(arguments(canvas, anim.fps, file))
        .stdin(Stdio::piped())
        .stdout(Stdio::null())
        .stderr(Stdio::piped())
        .spawn()
        .with_context(|| format!("cannot start {}", ffmpeg.display()))?;
    // read what ffmpeg says while it works, so that it never waits on a full pipe
    let said = child.stderr.take().map(|mut stderr| {
        std::thread::spawn(move || {
            let mut text = String::new();
            let _ = stderr.read_to_string(&mut text);
            text
        })
    });
    let mut stdin = child
        .stdin
        .take()
        .ok_or_else(|| anyhow!("cannot write to ffmpeg"))?;
    let fed = pictures::for_each(anim, canvas, rgb, |bytes| Ok(stdin.write_all(&bytes)?));
    drop(stdin);
    let status = child.wait().context("cannot wait for ffmpeg")?;
    let said = said.and_then(|h| h.join().ok()).unwrap_or_default();
    if !status.success() {
        bail!("ffmpeg failed ({status}): {}", last_lines(&said, 5));
    }
    fed
}

/// ffmpeg's arguments: raw RGB frames of `canvas` at `fps` from its input, an MP4 to `file`.
fn arguments(canvas: Canvas, fps: f64, file: &Path) -> Vec<OsString> {
    let fps = if fps.is_finite() && fps > 0.0 {
        fps
    } else {
        DEFAULT_FPS
    };
    let size = format!("{}x{}", canvas.width, canvas.height);
    let fps = format!("{fps}");
    let mut args: Vec<OsString> = [
        "-hide_banner",
        "-loglevel",
        "error",
        "-y",
        "-f",
        "rawvideo",
        "-pix_fmt",
        "rgb24",
        "-s",
        &size,
        "-r",
        &fps,
        "-i",
        "-",
        "-an",
        "-pix_fmt",
        "yuv420p",
        "-movflags",
        "+faststart",
        "-f",
        "mp4",
    ]
    .iter()
    .map(OsString::from)
    .collect();
    args.push(file.into());
    args
}

/// The picture's pixels as RGB bytes (it is opaque).
fn rgb(picture: &Pixmap) -> Vec<u8> {
    picture
        .data()
        .chunks_exact(4)
        .flat_map(|p| [p[0], p[1], p[2]])
        .collect()
}

/// The last `n` non-empty lines of `text`, joined by `; `.
fn last_lines(text: &str, n: usize) -> String {
    let lines: Vec<&str> = text.lines().filter(|l| !l.trim().is_empty()).collect();
    let said = lines[lines.len().saturating_sub(n)..].join("; ");
    if said.is_empty() {
        "it said nothing".into()
    } else {
        said
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ffmpeg_is_found_in_the_path_directories_if_executable() {
        let dir = tempfile::tempdir().unwrap();
        let (empty, with) = (dir.path().join("empty"), dir.path().join("with"));
        std::fs::create_dir_all(&empty).unwrap();
        std::fs::create_dir_all(&with).unwrap();
        let path = std::env::join_paths([&empty, &with]).unwrap();
        assert_eq!(find_ffmpeg(&path), None);
        let name = if cfg!(windows) {
            "ffmpeg.exe"
        } else {
            "ffmpeg"
        };
        std::fs::write(with.join(name), "#!/bin/sh\n").unwrap();
        #[cfg(unix)]
        {
            use std::os::unix::fs::PermissionsExt as _;
            assert_eq!(find_ffmpeg(&path), None, "not executable");
            let executable = std::fs::Permissions::from_mode(0o755);
            std::fs::set_permissions(with.join(name), executable).unwrap();
        }
        assert_eq!(find_ffmpeg(&path), Some(with.join(name)));
        assert_eq!(find_ffmpeg(OsStr::new("")), None);
    }

    #[test]
    fn the_arguments_give_ffmpeg_the_frames_size_and_rate() {
        let canvas = Canvas {
            width: 640,
            height: 480,
        };
        let args = arguments(canvas, 30.0, Path::new("out.mp4.partial"));
        let args: Vec<&str> = args.iter().map(|a| a.to_str().unwrap()).collect();
        let text = args.join(" ");
        assert!(
            text.contains("-f rawvideo -pix_fmt rgb24 -s 640x480 -r 30 -i -"),
            "{text}"
        );
        assert!(
            text.contains("-pix_fmt yuv420p -movflags +faststart"),
            "{text}"
        );
        assert_eq!(args.last(), Some(&"out.mp4.partial"));
        assert_eq!(last_lines("a\n\nb\nc\n", 2), "b; c");
        assert_eq!(last_lines("", 2), "it said nothing");
    }
}

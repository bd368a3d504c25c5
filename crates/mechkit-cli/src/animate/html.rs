//! The animation as one self-contained HTML file (no network: its script, style and data are
//! inside it) that plays it on a `<canvas>`: the drawing of [`frame_svg`](super::frame_svg),
//! from the same layout, with a play/pause button, a time slider and the time.
//!
//! The page is `player.html` with `player.css`, `player.js` and the data (`json.rs`) put in.
//! The script exposes `window.mechkitPlayer = {frame(), frames, playing(), play(), pause(),
//! seek(i)}` for tests.

use mechkit::animation::Animation;

use super::canvas::Canvas;
use super::json;
use super::layout::Layout;

const PAGE: &str = include_str!("player.html");
/// The player's style.
pub(super) const CSS: &str = include_str!("player.css");
/// The player's script.
pub(super) const SCRIPT: &str = include_str!("player.js");

/// `anim` as one self-contained HTML file that plays it on a `canvas`-sized picture (a
/// canvas outside [`Canvas::SIDES`] is brought within it), at `anim.fps` frames per second,
/// looping; it starts playing.
pub fn html(anim: &Animation, canvas: Canvas) -> String {
    let canvas = canvas.clamped();
    let layout = Layout::new(anim, canvas);
    let title = if anim.title.trim().is_empty() {
        "mechkit animation".to_string()
    } else {
        anim.title.clone()
    };
    fill(PAGE, |name| match name {
        "title" => Some(html_text(&title)),
        "width" => Some(canvas.width.to_string()),
        "height" => Some(canvas.height.to_string()),
        "frames" => Some(anim.frames.len().saturating_sub(1).to_string()),
        "css" => Some(CSS.to_string()),
        "script" => Some(SCRIPT.to_string()),
        "data" => Some(json::data(anim, &layout)),
        _ => None,
    })
}

/// `template` with each `{{name}}` replaced by `value(name)` (kept when that is `None`), in
/// one pass: what is put in is never read for names.
fn fill(template: &str, value: impl Fn(&str) -> Option<String>) -> String {
    let mut out = String::with_capacity(template.len());
    let mut rest = template;
    while let Some(open) = rest.find("{{") {
        let Some(close) = rest[open..].find("}}").map(|c| open + c) else {
            break;
        };
        out.push_str(&rest[..open]);
        match value(&rest[open + 2..close]) {
            Some(v) => out.push_str(&v),
            None => out.push_str(&rest[open..close + 2]),
        }
        rest = &rest[close + 2..];
    }
    out.push_str(rest);
    out
}

/// `text` for an HTML element's content: escaped as for XML ([`super::svg::escape`]: `&`,
/// `<`, `>`, quotes; control characters dropped but tab and newline), and `/` too (so that no
/// web address appears as written).
fn html_text(text: &str) -> String {
    super::svg::escape(text).replace('/', "&#47;")
}

#[cfg(test)]
mod tests {
    use std::path::Path;
    use std::process::Command;

    use super::super::tests::animation;
    use super::super::{Canvas, html};
    use super::{fill, html_text};

    #[test]
    fn names_are_filled_in_once() {
        let got = fill("<{{a}}|{{b}}|{{c}}", |n| match n {
            "a" => Some("{{b}}".into()),
            "b" => Some("B".into()),
            _ => None,
        });
        assert_eq!(got, "<{{b}}|B|{{c}}");
        assert_eq!(
            html_text("a</b> & https://x"),
            "a&lt;&#47;b&gt; &amp; https:&#47;&#47;x"
        );
    }

    /// The text between `open` and the next `</script>`.
    fn between<'a>(page: &'a str, open: &str) -> &'a str {
        let start = page.find(open).expect(open) + open.len();
        let end = start + page[start..].find("</script>").expect("</script>");
        &page[start..end]
    }

    #[test]
    fn the_page_is_self_contained_with_the_player_and_its_data() {
        let mut anim = animation();
        anim.title = "</script> see https://example.org & <b>".into();
        let page = html(&anim, Canvas::default());
        assert!(
            !page.contains("http://") && !page.contains("https://"),
            "no address"
        );
        for id in ["scene", "play", "slider", "time", "mechkit-data"] {
            assert!(page.contains(&format!("id=\"{id}\"")), "{id}");
        }
        assert_eq!(
            page.matches("</script>").count(),
            2,
            "the title ends no script"
        );
        assert!(
            !page.contains(" src=") && !page.contains("<link"),
            "nothing loaded"
        );
        let data = between(&page, "id=\"mechkit-data\">");
        let data: serde_json::Value = serde_json::from_str(data).unwrap();
        assert_eq!(data["frames"].as_array().unwrap().len(), 30);
        assert_eq!(data["fps"], 25);
        assert_eq!(data["layout"]["map"]["scale"], 160.0);
        assert_eq!(data["layout"]["title"]["content"], anim.title.as_str());
        assert_eq!(data["frames"][1][0], 0.04);
        // the spring and the ball: [style, kind, numbers…]
        let ball = &data["frames"][0][1][1];
        assert_eq!(ball[1], 0, "a circle");
        assert_eq!(ball[4], 0.1);
        assert_eq!(
            data["styles"][ball[0].as_u64().unwrap() as usize][0],
            "#d62728"
        );
    }

    /// `node` if it runs, with a note when it does not.
    fn node() -> Option<Command> {
        let found = Command::new("node").arg("--version").output().is_ok();
        if !found {
            eprintln!("node not found: the player's script is not checked");
        }
        found.then(|| Command::new("node"))
    }

    fn run(mut node: Command, args: &[&Path]) {
        let out = node.args(args).output().unwrap();
        let said = String::from_utf8_lossy(&out.stderr);
        assert!(
            out.status.success(),
            "{said}{}",
            String::from_utf8_lossy(&out.stdout)
        );
    }

    #[test]
    fn the_script_passes_node_check() {
        let Some(node) = node() else { return };
        let dir = tempfile::tempdir().unwrap();
        let page = html(&animation(), Canvas::default());
        let file = dir.path().join("player.js");
        std::fs::write(&file, between(&page, "<script>")).unwrap();
        let mut node = node;
        node.arg("--check");
        run(node, &[&file]);
    }

    /// The page's script run by node with a stand-in for the page (`player_test.js`): it
    /// draws, plays (the frames advance), pauses, seeks and loops.
    #[test]
    fn the_player_plays_pauses_and_seeks() {
        let Some(node) = node() else { return };
        let dir = tempfile::tempdir().unwrap();
        let (page, harness) = (dir.path().join("ball.html"), dir.path().join("harness.js"));
        std::fs::write(&page, html(&animation(), Canvas::default())).unwrap();
        std::fs::write(&harness, include_str!("player_test.js")).unwrap();
        run(node, &[&harness, &page]);
    }
}

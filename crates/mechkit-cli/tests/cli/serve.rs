//! `mechkit serve`, spoken to over HTTP/1.1 from a plain `TcpStream`: the URL comes first on
//! stdout; no file outside the workspace is read (`..`, absolute paths, percent-encoded
//! `..`, symbolic links out of it, a scenario's body file out of it); bodies over 1 MB get
//! 413, malformed JSON 400, garbage a refusal, and the server goes on; a check locates its
//! error; a run writes its plots and animation; runs beyond `--max-runs` get 429; a run over
//! `--max-run-seconds` stops with its outputs; SIGTERM ends the server with status 0.

use std::time::Duration;

use serde_json::json;

use super::serve_http::Server;
use super::util::Dir;

/// A short fall: a run of a few steps with plots and an animation.
const DROP: &str = r#"title = "a short drop"
dimensions = 2
[[body]]
name = "ball"
mass = "1 kg"
position = ["0 m", "1 m"]
[[force]]
name = "gravity"
kind = "uniform-gravity"
[integrator]
method = "rk4"
dt = "10 ms"
[stop]
t_max = "0.4 s"
[output]
plots = ["y(t)", "energy-bars"]
"#;

/// A fall that would last for days of computing (1 µs steps to t = 10⁷ s), keeping a row in
/// a million.
const ENDLESS: &str = r#"title = "a long fall"
[[body]]
name = "feather"
mass = "1 g"
position = "2.4 m"
[[force]]
kind = "uniform-gravity"
[integrator]
method = "euler-cromer"
dt = "1 us"
[stop]
t_max = "500 s"
[output]
every = 1000000
plots = []
"#;

#[test]
fn serve_refuses_paths_outside_the_workspace() {
    let outside = Dir::new();
    outside.create("secret.toml", "title = \"secret\"\n");
    let dir = Dir::new();
    dir.create("a.toml", DROP);
    std::fs::create_dir(dir.path().join("sub")).unwrap();
    dir.create("sub/b.toml", DROP);
    std::os::unix::fs::symlink(
        outside.path().join("secret.toml"),
        dir.path().join("link.toml"),
    )
    .unwrap();
    std::os::unix::fs::symlink(outside.path(), dir.path().join("out")).unwrap();
    std::fs::File::create(dir.path().join("big.toml"))
        .unwrap()
        .set_len(16_000_001)
        .unwrap();
    let server = Server::start(&dir, &[]);

    let listed = server.get("/api/files").json(200);
    let paths: Vec<&str> = listed["files"]
        .as_array()
        .unwrap()
        .iter()
        .map(|f| f["path"].as_str().unwrap())
        .collect();
    assert_eq!(
        paths,
        ["a.toml", "big.toml", "sub/b.toml"],
        "symlinks are not listed"
    );
    assert!(!listed["gallery"].as_array().unwrap().is_empty());

    let text = server.get("/api/file?path=sub/b.toml").json(200);
    assert_eq!(text["text"], DROP);
    for path in [
        "../secret.toml",
        "..%2Fsecret.toml",
        "%2e%2e/secret.toml",
        "%2E%2E%2Fsecret.toml",
        "sub/../../secret.toml",
        "/etc/passwd",
        "%2Fetc%2Fpasswd",
        "link.toml",
        "out/secret.toml",
        "gallery:../../../secret.toml",
    ] {
        let e = server.get(&format!("/api/file?path={path}")).error(403);
        assert!(!e.contains("secret\""), "{e}");
    }
    server.get("/api/file?path=none.toml").error(404);
    server.get("/api/file?path=big.toml").error(413);
    // the URL's own path never reaches the disk
    server.get("/../../etc/passwd").error(404);
    server
        .get("/api/run/1/file/..%2F..%2Fetc%2Fpasswd")
        .error(404);
    // a scenario naming a body file outside is refused at that line, before it is read
    let secret = outside.path().join("secret.toml").display().to_string();
    for body in [
        "../../secret.toml",
        "../link.toml",
        "../out/secret.toml",
        secret.as_str(),
    ] {
        let scenario = format!("[[rigid_body]]\nname = \"r\"\nbody = \"{body}\"\n");
        let checked = server
            .post(
                "/api/check",
                &json!({"name": "sub/s.toml", "text": scenario}),
            )
            .json(200);
        assert_eq!(checked["ok"], false);
        assert_eq!(checked["errors"][0]["line"], 3, "{checked}");
        assert!(
            checked["errors"][0]["message"]
                .as_str()
                .unwrap()
                .contains("outside the workspace"),
            "{checked}"
        );
    }
    server
        .post("/api/check", &json!({"name": "/tmp/x.toml", "text": DROP}))
        .error(403);
    // a page of another site (DNS rebinding, a cross-site post) is refused
    server
        .request("GET", "/api/files", &[("Host", "evil.example:80")], b"")
        .error(403);
    let body = json!({"name": "a.toml", "text": DROP}).to_string();
    server
        .request(
            "POST",
            "/api/check",
            &[
                ("Content-Type", "application/json"),
                ("Origin", "http://evil.example"),
            ],
            body.as_bytes(),
        )
        .error(403);
    assert_eq!(server.stop(), Some(0));
}

#[test]
fn serve_answers_bad_requests_with_json_errors() {
    let dir = Dir::new();
    let server = Server::start(&dir, &[]);
    let big = format!(
        r#"{{"name": "a.toml", "text": "{}"}}"#,
        "#".repeat(1_100_000)
    );
    let e = server
        .request(
            "POST",
            "/api/check",
            &[("Content-Type", "application/json")],
            big.as_bytes(),
        )
        .error(413);
    assert!(e.contains("larger than"), "{e}");
    let e = server
        .request(
            "POST",
            "/api/check",
            &[("Content-Type", "application/json")],
            b"{\"text\": ",
        )
        .error(400);
    assert!(e.contains("JSON"), "{e}");
    server
        .request(
            "POST",
            "/api/run",
            &[("Content-Type", "application/json")],
            b"[1, 2]",
        )
        .error(400);
    server
        .request("POST", "/api/check", &[], b"{\"text\": \"\"}")
        .error(415);
    server.get("/api/nothing").error(404);
    server.get("/api/run/12345").error(404);
    server.get("/api/run/abc").error(400);
    server.get("/api/file").error(400);
    server.request("DELETE", "/api/files", &[], b"").error(405);
    // not HTTP at all: refused, and the server goes on
    let garbage = server.raw(b"\x00\x01GARBAGE \xff\r\n\r\n");
    assert!(garbage.status == 0 || garbage.status == 400, "{garbage:?}");
    let page = server.get("/");
    assert_eq!(page.status, 200);
    assert!(page.text().contains("id=\"editor\""));
    assert!(server.get("/app.js").text().contains("/api/check"));
    assert_eq!(server.stop(), Some(0));
}

#[test]
fn serve_check_locates_the_error() {
    let dir = Dir::new();
    let server = Server::start(&dir, &[]);
    let bad = DROP.replace("mass = \"1 kg\"", "mass = \"1 kgg\"");
    let checked = server
        .post("/api/check", &json!({"name": "drop.toml", "text": bad}))
        .json(200);
    assert_eq!(checked["ok"], false);
    let e = &checked["errors"][0];
    assert_eq!(e["line"], 5, "{checked}");
    assert_eq!(e["column"], 11, "{checked}");
    assert!(e["message"].as_str().unwrap().contains("kgg"), "{checked}");
    let checked = server
        .post("/api/check", &json!({"name": "drop.toml", "text": DROP}))
        .json(200);
    assert_eq!(checked["ok"], true, "{checked}");
    assert_eq!(checked["errors"], json!([]));
    assert_eq!(checked["report"]["bodies"][0]["name"], "ball");
    assert_eq!(server.stop(), Some(0));
}

#[test]
fn serve_runs_a_scenario_with_plots_and_animation() {
    let dir = Dir::new();
    let server = Server::start(&dir, &[]);
    let started = server
        .post("/api/run", &json!({"name": "drop.toml", "text": DROP}))
        .json(202);
    let id = started["id"].as_u64().unwrap();
    let view = server.wait(id, Duration::from_mins(2), |v| v["state"] != "running");
    assert_eq!(view["state"], "done", "{view:#}");
    assert_eq!(view["progress"], 1.0);
    assert_eq!(view["summary"]["stop_reason"], "t_max");
    let plots: Vec<&str> = view["plots"]
        .as_array()
        .unwrap()
        .iter()
        .map(|p| p["name"].as_str().unwrap())
        .collect();
    assert_eq!(plots, ["y_t.svg", "energy-bars.svg"]);
    for p in view["plots"].as_array().unwrap() {
        let svg = server.get(p["url"].as_str().unwrap());
        assert_eq!(svg.status, 200);
        assert!(svg.head.contains("image/svg+xml"), "{}", svg.head);
        assert!(svg.text().contains("<svg"));
    }
    let player = server.get(view["animation"].as_str().unwrap());
    assert!(player.head.contains("text/html"), "{}", player.head);
    assert!(player.text().contains("mechkitPlayer"));
    let csv = server.get(&format!("/api/run/{id}/file/trajectory.csv"));
    assert!(csv.text().starts_with("t,"), "{}", csv.text());
    server
        .get(&format!("/api/run/{id}/file/secret.txt"))
        .error(404);
    // the GIF comes last, drawn after the run is done
    let view = server.wait(id, Duration::from_mins(3), |v| {
        v["pending"].as_array().is_some_and(Vec::is_empty)
    });
    let gif = server.get(&format!("/api/run/{id}/file/animation.gif"));
    assert!(gif.body.starts_with(b"GIF89a"), "{view:#}");
    // the workspace is never written to
    assert!(dir.files(".").is_empty(), "{:?}", dir.files("."));
    assert_eq!(server.stop(), Some(0));
}

#[test]
fn serve_refuses_runs_beyond_max_runs() {
    let dir = Dir::new();
    let server = Server::start(&dir, &["--max-runs", "1"]);
    let run = json!({"name": "fall.toml", "text": ENDLESS});
    let first = server.post("/api/run", &run).json(202)["id"]
        .as_u64()
        .unwrap();
    let e = server.post("/api/run", &run).error(429);
    assert!(e.contains("--max-runs"), "{e}");
    std::thread::sleep(Duration::from_millis(300));
    server
        .post(&format!("/api/run/{first}/stop"), &json!({}))
        .json(200);
    let view = server.wait(first, Duration::from_mins(1), |v| v["state"] != "running");
    assert_eq!(view["state"], "failed");
    assert_eq!(view["summary"]["stop_reason"], "interrupted");
    assert!(
        view["error"].as_str().unwrap().contains("was stopped"),
        "{view:#}"
    );
    assert_eq!(
        server.stop(),
        Some(0),
        "a GIF being drawn does not hold the server"
    );
}

#[test]
fn serve_stops_a_run_at_the_time_limit() {
    let dir = Dir::new();
    let server = Server::start(&dir, &["--max-run-seconds", "1"]);
    let id = server
        .post("/api/run", &json!({"name": "fall.toml", "text": ENDLESS}))
        .json(202)["id"]
        .as_u64()
        .unwrap();
    let view = server.wait(id, Duration::from_mins(1), |v| v["state"] != "running");
    assert_eq!(view["state"], "failed", "{view:#}");
    assert_eq!(view["summary"]["stop_reason"], "interrupted");
    let error = view["error"].as_str().unwrap();
    assert!(error.contains("time limit of 1 s"), "{error}");
    assert!(view["seconds"].as_f64().unwrap() >= 1.0);
    let t_end = view["summary"]["t_end"].as_f64().unwrap();
    assert!(t_end > 0.0 && t_end < 500.0, "{t_end}");
    assert_eq!(server.stop(), Some(0));
}

#[test]
fn serve_listens_on_loopback_unless_told_otherwise() {
    let dir = Dir::new();
    let out = dir.run(&["serve", "--host", "0.0.0.0", "--port", "0"]);
    out.assert_bad_input(&["not a loopback address", "--allow-remote"]);
    let out = dir.run(&["serve", "--dir", "no-such-dir", "--port", "0"]);
    out.assert_bad_input(&["--dir no-such-dir"]);
    let out = dir.run(&["serve", "--max-runs", "0", "--port", "0"]);
    out.assert_bad_input(&["--max-runs"]);
}

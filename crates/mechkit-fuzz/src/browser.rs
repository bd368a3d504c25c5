//! The `browser` target: requests to `mechkit serve`'s routes ([`mechkit_cli::serve_routes`]),
//! in-process, without a socket (tower's `oneshot` on the router).
//!
//! The input is structured: byte 0 picks the method (bits 0–1: GET, POST, HEAD, PUT), the
//! `Host` (bit 2: another host than the server's), a foreign `Origin` (bit 3), and whether
//! the body is the rest of the input as it is or a scenario request built from it (bit 4:
//! `{"name": LINE 1, "text": THE REST}`, so that the fuzzer can mutate TOML without
//! keeping JSON's quoting). The first line after it is the request's path and query; the
//! rest is the body.
//!
//! The workspace ([`Site`]) holds two scenarios, a subdirectory, a large file, a binary one
//! and a symlink to a file outside it; beside it lies a folder whose files hold a marker.
//! Checks: no panic; no status 500 (every 500 of the server is a failure of its own); the
//! marker of the files outside the workspace is never in an answer to a request that does
//! not hold it; the workspace and the
//! files outside it are never changed. A run (`POST /api/run`, bounded to 0.3 s, one at a
//! time) is waited for, so that the next input starts with no run going on.

use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

use axum::body::Body;
use axum::http::{Method, Request, StatusCode, header};
use tower::ServiceExt as _;

/// What the files outside the workspace hold; an answer that contains it read them.
pub const MARKER: &str = "OUTSIDE-THE-WORKSPACE-5f1c";

/// The port the router believes it serves (the host guard's).
const PORT: u16 = 8765;

/// The longest run of a request.
const RUN_TIME: Duration = Duration::from_millis(300);

/// The files of the workspace: (relative path, content).
const FILES: &[(&str, &str)] = &[
    (
        "fall.toml",
        "title = \"fall\"\ndimensions = 1\n[[body]]\nname = \"b\"\nmass = \"1 kg\"\nposition = \"1 m\"\nvelocity = 0\n[[force]]\nname = \"g\"\nkind = \"uniform-gravity\"\ng = \"9.8 m/s^2\"\n[integrator]\nmethod = \"rk4\"\ndt = \"10 ms\"\n[stop]\nwhen = \"x < 0\"\nt_max = \"2 s\"\n",
    ),
    (
        "sub/spring.toml",
        "title = \"spring\"\ndimensions = 1\n[constants]\nk = \"4 N/m\"\n[[body]]\nname = \"m\"\nmass = \"1 kg\"\nposition = \"0.1 m\"\nvelocity = 0\n[[force]]\nname = \"s\"\nkind = \"expression\"\non = \"m\"\nF = \"-k*x\"\n[integrator]\nmethod = \"verlet\"\ndt = \"5 ms\"\n[stop]\nt_max = \"1 s\"\n",
    ),
    ("sub/notes.txt", "not a scenario\n"),
];

/// The workspace and the folder beside it, made once per process.
pub struct Site {
    /// The workspace.
    pub workspace: PathBuf,
    /// The folder beside it, whose files hold [`MARKER`].
    pub outside: PathBuf,
    snapshot: Vec<(PathBuf, Vec<u8>, Option<std::time::SystemTime>)>,
    router: axum::Router,
    runtime: tokio::runtime::Runtime,
}

impl Site {
    /// Makes the workspace, the folder beside it and the router.
    ///
    /// # Errors
    /// When a file cannot be written or the router made.
    pub fn new() -> anyhow::Result<Self> {
        let root =
            std::env::temp_dir().join(format!("mechkit-fuzz-browser-{}", std::process::id()));
        let workspace = root.join("workspace");
        let outside = root.join("outside");
        for (rel, text) in FILES {
            let path = workspace.join(rel);
            std::fs::create_dir_all(path.parent().unwrap_or(&workspace))?;
            std::fs::write(path, text)?;
        }
        std::fs::write(workspace.join("big.toml"), "# padding\n".repeat(120_000))?;
        std::fs::write(workspace.join("binary.toml"), [0xff, 0xfe, 0x00, 0x80])?;
        std::fs::create_dir_all(&outside)?;
        let secret = format!("title = \"{MARKER}\"\n");
        std::fs::write(outside.join("secret.toml"), &secret)?;
        std::fs::write(root.join("secret.toml"), &secret)?;
        #[cfg(unix)]
        {
            let link = workspace.join("link.toml");
            if !link.exists() {
                std::os::unix::fs::symlink(outside.join("secret.toml"), link)?;
            }
        }
        let router = mechkit_cli::serve_routes(&workspace, PORT, RUN_TIME, 1_000_000)?;
        let runtime = tokio::runtime::Builder::new_multi_thread()
            .worker_threads(1)
            .enable_time()
            .build()?;
        let mut site = Self {
            workspace,
            outside,
            snapshot: Vec::new(),
            router,
            runtime,
        };
        site.snapshot = site.files();
        Ok(site)
    }

    /// Every file of the workspace and of the folder beside it, with its size (a symlink:
    /// its target) and when it was last changed.
    fn files(&self) -> Vec<(PathBuf, Vec<u8>, Option<std::time::SystemTime>)> {
        let mut out = Vec::new();
        let root = self.workspace.parent().unwrap_or(&self.workspace);
        let mut stack = vec![root.to_path_buf()];
        while let Some(dir) = stack.pop() {
            let Ok(entries) = std::fs::read_dir(&dir) else {
                continue;
            };
            for entry in entries.flatten() {
                let path = entry.path();
                let Ok(meta) = std::fs::symlink_metadata(&path) else {
                    continue;
                };
                if meta.is_dir() {
                    stack.push(path);
                } else if meta.is_symlink() {
                    let to = std::fs::read_link(&path).unwrap_or_default();
                    out.push((path, to.into_os_string().into_encoded_bytes(), None));
                } else {
                    let size = meta.len().to_le_bytes().to_vec();
                    out.push((path, size, meta.modified().ok()));
                }
            }
        }
        out.sort();
        out
    }

    /// Sends `request` and returns the answer's status and body.
    fn send(&self, request: Request<Body>) -> (StatusCode, String) {
        self.runtime.block_on(async {
            let response = self
                .router
                .clone()
                .oneshot(request)
                .await
                .unwrap_or_else(|e| match e {});
            let status = response.status();
            let body = axum::body::to_bytes(response.into_body(), 64 << 20)
                .await
                .map(|b| String::from_utf8_lossy(&b).into_owned())
                .unwrap_or_default();
            (status, body)
        })
    }

    /// Waits (at most 5 s) until run `id` is no longer at work, its GIF included.
    fn settle(&self, id: u64) {
        let start = Instant::now();
        while start.elapsed() < Duration::from_secs(5) {
            let (status, body) = self.send(get(&format!("/api/run/{id}")));
            let working = status == StatusCode::OK
                && (body.contains("\"state\":\"running\"") || !body.contains("\"pending\":[]"));
            if !working {
                return;
            }
            std::thread::sleep(Duration::from_millis(5));
        }
    }

    /// Runs one input; see the module's documentation.
    ///
    /// # Panics
    /// When a check fails: a status 500, the marker in an answer, a file changed.
    pub fn request(&self, data: &[u8]) {
        let Some((&flags, rest)) = data.split_first() else {
            return;
        };
        let Ok(text) = std::str::from_utf8(rest) else {
            return;
        };
        let (uri, body) = text.split_once('\n').unwrap_or((text, ""));
        let uri = if uri.starts_with('/') {
            uri.to_string()
        } else {
            format!("/{uri}")
        };
        let method =
            [Method::GET, Method::POST, Method::HEAD, Method::PUT][usize::from(flags & 3)].clone();
        let host = if flags & 4 == 0 {
            format!("127.0.0.1:{PORT}")
        } else {
            "evil.example:80".to_string()
        };
        let body = if flags & 16 == 0 {
            body.to_string()
        } else {
            let (name, scenario) = body.split_once('\n').unwrap_or(("", body));
            serde_json::json!({ "name": name, "text": scenario }).to_string()
        };
        let mut builder = Request::builder()
            .method(method)
            .uri(uri.as_str())
            .header(header::HOST, host)
            .header(header::CONTENT_TYPE, "application/json");
        if flags & 8 != 0 {
            builder = builder.header(header::ORIGIN, "http://evil.example");
        }
        // a path the http crate refuses never reaches a server
        let Ok(request) = builder.body(Body::from(body)) else {
            return;
        };
        let (status, answer) = self.send(request);
        assert_ne!(
            status,
            StatusCode::INTERNAL_SERVER_ERROR,
            "500 for {uri}: {answer}"
        );
        // (an answer may echo the request, and the fuzzer learns the marker from this check)
        assert!(
            !answer.contains(MARKER) || text.contains(MARKER),
            "{uri} answered with a file outside the workspace: {answer}"
        );
        if status == StatusCode::ACCEPTED
            && let Some(id) = serde_json::from_str::<serde_json::Value>(&answer)
                .ok()
                .and_then(|v| v.get("id").and_then(serde_json::Value::as_u64))
        {
            self.settle(id);
        }
        assert!(
            self.files() == self.snapshot,
            "{uri} changed the workspace or the files beside it"
        );
    }

    /// The workspace's root.
    #[must_use]
    pub fn root(&self) -> &Path {
        &self.workspace
    }
}

fn get(uri: &str) -> Request<Body> {
    Request::builder()
        .uri(uri)
        .header(header::HOST, format!("127.0.0.1:{PORT}"))
        .body(Body::empty())
        .unwrap_or_default()
}

//! Answers only requests meant for this server: on a loopback address, the `Host` header
//! must name it (a page of another site that resolves its own name to 127.0.0.1, DNS
//! rebinding, is refused), and a request that changes something must come from the app's
//! own pages (`Origin`, when the browser sends one, is this server: no cross-site posts).

use std::sync::Arc;

use axum::extract::{Request, State};
use axum::http::{Method, header};
use axum::middleware::Next;
use axum::response::{IntoResponse, Response};

use super::error::ApiError;

/// Which hosts requests may name.
#[derive(Debug, Clone)]
pub struct Guard {
    /// `host:port` values accepted in `Host`; empty accepts any (`--allow-remote`).
    pub hosts: Vec<String>,
}

impl Guard {
    /// The loopback names of `port`: `127.0.0.1`, `localhost` and `[::1]`.
    pub fn loopback(port: u16) -> Self {
        Self {
            hosts: ["127.0.0.1", "localhost", "[::1]"]
                .iter()
                .map(|h| format!("{h}:{port}"))
                .collect(),
        }
    }

    /// Any host (`--allow-remote`: the server is reached by names it cannot know).
    pub fn any() -> Self {
        Self { hosts: Vec::new() }
    }
}

/// The middleware: 403 for a request to another host or from another origin.
pub async fn check(State(guard): State<Arc<Guard>>, req: Request, next: Next) -> Response {
    let host = req
        .headers()
        .get(header::HOST)
        .and_then(|h| h.to_str().ok())
        .unwrap_or("")
        .to_ascii_lowercase();
    if !guard.hosts.is_empty() && !guard.hosts.contains(&host) {
        return ApiError::forbidden(format!(
            "this server answers requests to {} only, not to `{host}`",
            guard.hosts.first().map_or("", String::as_str)
        ))
        .into_response();
    }
    let reads = matches!(*req.method(), Method::GET | Method::HEAD);
    if !reads
        && let Some(origin) = req.headers().get(header::ORIGIN)
        && origin.to_str().ok() != Some(format!("http://{host}").as_str())
    {
        return ApiError::forbidden("a request from another site's page is refused")
            .into_response();
    }
    next.run(req).await
}

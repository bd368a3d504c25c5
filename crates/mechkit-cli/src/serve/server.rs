//! The server's start and end: the options checked, the address bound, its URL printed
//! first on stdout, the routes served until Ctrl-C or SIGTERM (the command's cancel handle),
//! then the runs stopped and the server's folders removed.

use std::net::{IpAddr, Ipv4Addr, SocketAddr};
use std::path::Path;
use std::sync::Arc;
use std::time::Duration;

use anyhow::{Context as _, Result, anyhow, bail};
use axum::Router;
use axum::extract::DefaultBodyLimit;
use axum::routing::{get, post};
use mechkit::scenario::parse_size;
use mechkit::simulate::Cancel;

use super::app::{App, Gallery, Limits, MAX_BODY};
use super::guard::{self, Guard};
use super::registry::Registry;
use super::workspace::Workspace;
use super::{assets, check, error, files, run};
use crate::args::ServeArgs;
use crate::commands::Outcome;

/// What `mechkit serve --json` prints when the server is up.
#[derive(serde::Serialize)]
struct Up {
    url: String,
    workspace: String,
}

/// `mechkit serve`: serves the app until `cancel` is raised (Ctrl-C, SIGTERM).
pub fn serve(args: &ServeArgs, cancel: &Cancel) -> Result<Outcome> {
    let limits = limits(args)?;
    let ip = address(&args.host, args.allow_remote)?;
    let workspace = Workspace::open(&args.dir)?;
    let gallery = Gallery::extract()
        .inspect_err(|e| {
            eprintln!(
                "warning: the gallery is not available: {}",
                crate::failure::message(e)
            );
        })
        .ok();
    let registry = Registry::new(scratch(), limits.runs)
        .context("cannot create the server's folder for the runs")?;
    let listener = std::net::TcpListener::bind((ip, args.port))
        .with_context(|| format!("cannot listen on {}", SocketAddr::new(ip, args.port)))?;
    listener.set_nonblocking(true)?;
    let port = listener.local_addr()?.port();
    let guard = if ip.is_loopback() {
        Guard::loopback(port)
    } else {
        Guard::any()
    };
    let app = Arc::new(App {
        workspace,
        gallery,
        registry,
        limits,
    });
    let up = Up {
        url: format!("http://{}/", SocketAddr::new(ip, port)),
        workspace: app.workspace.root().display().to_string(),
    };
    crate::commands::report(args.report, &up, || {
        format!("mechkit serve: {} (workspace {})\n", up.url, up.workspace)
    })?;
    let runtime = tokio::runtime::Builder::new_multi_thread()
        .worker_threads(2)
        .thread_name("mechkit-serve")
        .enable_io()
        .enable_time()
        .build()
        .context("cannot start the server's threads")?;
    let routes = router(Arc::clone(&app), guard);
    let served: std::io::Result<()> = runtime.block_on(async {
        let listener = tokio::net::TcpListener::from_std(listener)?;
        axum::serve(listener, routes)
            .with_graceful_shutdown(stopped(cancel.clone()))
            .await
    });
    app.registry.stop_all();
    // the runs stop after their current step; a GIF being drawn is not waited for
    runtime.shutdown_timeout(Duration::from_secs(2));
    // the runs' folder and the gallery's go with the last handle on the state
    drop(app);
    served.context("the server failed")?;
    eprintln!("mechkit serve: stopped");
    Ok(Outcome::Success)
}

/// The app's routes over the workspace `dir`, as `mechkit serve --dir DIR --max-runs 1` serves
/// them on `127.0.0.1:port` (the host guard answers only requests that name it), with the
/// gallery when it can be extracted and runs bounded by `run_time` and `output` bytes. For
/// callers that send requests to the router itself, without a socket (the `browser` fuzz
/// target: tower's `oneshot`); the handlers need a tokio runtime. The runs' folder (under the
/// temporary directory) goes with the last handle on the router's state.
pub fn routes(dir: &Path, port: u16, run_time: Duration, output: u64) -> Result<Router> {
    let workspace = Workspace::open(dir)?;
    let registry =
        Registry::new(scratch(), 1).context("cannot create the server's folder for the runs")?;
    let app = Arc::new(App {
        workspace,
        gallery: Gallery::extract().ok(),
        registry,
        limits: Limits {
            run_time,
            output,
            runs: 1,
        },
    });
    Ok(router(app, Guard::loopback(port)))
}

/// The routes, the body limit and the host guard.
fn router(app: Arc<App>, guard: Guard) -> Router {
    Router::new()
        .route("/", get(assets::index))
        .route("/index.html", get(assets::index))
        .route("/app.js", get(assets::script))
        .route("/app.css", get(assets::style))
        .route("/favicon.svg", get(assets::icon))
        .route("/favicon.ico", get(assets::icon))
        .route("/api/files", get(files::list))
        .route("/api/file", get(files::read))
        .route("/api/check", post(check::check))
        .route("/api/run", post(run::start))
        .route("/api/run/{id}", get(run::view))
        .route("/api/run/{id}/stop", post(run::stop))
        .route("/api/run/{id}/file/{name}", get(run::file))
        .fallback(error::no_route)
        .method_not_allowed_fallback(error::wrong_method)
        .layer(DefaultBodyLimit::max(MAX_BODY))
        .layer(axum::middleware::from_fn_with_state(
            Arc::new(guard),
            guard::check,
        ))
        .with_state(app)
}

/// Resolves when `cancel` is raised.
async fn stopped(cancel: Cancel) {
    while !cancel.is_cancelled() {
        tokio::time::sleep(Duration::from_millis(100)).await;
    }
}

/// The limits of the runs, checked.
fn limits(args: &ServeArgs) -> Result<Limits> {
    let run_time = Duration::try_from_secs_f64(args.max_run_seconds)
        .ok()
        .filter(|d| !d.is_zero())
        .ok_or_else(|| {
            anyhow!(
                "--max-run-seconds must be a positive number of seconds, not {}",
                mechkit::expr::short_number(args.max_run_seconds)
            )
        })?;
    let output = parse_size(&args.max_output).map_err(|e| anyhow!("--max-output: {e}"))?;
    if output == 0 {
        bail!("--max-output must be more than 0 bytes");
    }
    if args.max_runs == 0 {
        bail!("--max-runs must be at least 1");
    }
    Ok(Limits {
        run_time,
        output,
        runs: args.max_runs,
    })
}

/// The address to listen on: a loopback one unless `allow_remote`.
fn address(host: &str, allow_remote: bool) -> Result<IpAddr> {
    let ip = if host.eq_ignore_ascii_case("localhost") {
        IpAddr::V4(Ipv4Addr::LOCALHOST)
    } else {
        host.trim_matches(|c| c == '[' || c == ']')
            .parse::<IpAddr>()
            .map_err(|_| {
                anyhow!(
                    "--host `{host}` is not an IP address\n  = hint: give 127.0.0.1 (the default), ::1 or localhost"
                )
            })?
    };
    if !ip.is_loopback() && !allow_remote {
        bail!(
            "--host {host} is not a loopback address: other machines could reach the app, read the workspace's scenarios and run them\n  = hint: leave --host out to serve on 127.0.0.1, or add --allow-remote to serve on {host} anyway"
        );
    }
    Ok(ip)
}

/// A new folder name for the runs, under the temporary directory.
fn scratch() -> std::path::PathBuf {
    let nanos = std::time::SystemTime::now()
        .duration_since(std::time::UNIX_EPOCH)
        .map_or(0, |d| d.as_nanos());
    std::env::temp_dir().join(format!("mechkit-serve-{}-{nanos}", std::process::id()))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn only_loopback_without_allow_remote() {
        assert!(address("127.0.0.1", false).unwrap().is_loopback());
        assert!(address("localhost", false).unwrap().is_loopback());
        assert!(address("::1", false).unwrap().is_loopback());
        assert!(address("[::1]", false).unwrap().is_loopback());
        let e = address("0.0.0.0", false).unwrap_err().to_string();
        assert!(e.contains("--allow-remote"), "{e}");
        assert!(address("0.0.0.0", true).is_ok());
        assert!(address("example.org", true).is_err());
    }
}

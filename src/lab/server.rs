//! The lab's HTTP server (tiny_http: synchronous, no async runtime; see the README's
//! note on crates). One thread accepts requests and answers the page itself; every run
//! and map goes to a worker thread, so a slow run never holds up the page or another
//! run. Every request is bounded: the body ([`super::api::MAX_BODY_BYTES`]), the work
//! (the CLI's budget and the lab's drive cycles, checked before any run), the number of
//! runs at once ([`MAX_RUNS`]) and the wait for an answer ([`TIMEOUT`]). Worker threads
//! never write to stdout or stderr (the terminal belongs to the main thread).

use super::api::{self, ApiError};
use super::map::MapCache;
use serde_json::Value;
use std::io::Read;
use std::net::{IpAddr, SocketAddr};
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::{mpsc, Arc};
use std::time::Duration;
use tiny_http::{Header, Method, Request, Response, Server};

/// Most runs and maps computed at once (with [`super::api::MAX_CYCLES`], a bound on the
/// lab's memory of about 160 MB); a request beyond is answered 503 at once.
pub const MAX_RUNS: usize = 4;
/// Longest wait for a run's answer; the run is answered 503 then (it finishes in the
/// background, bounded by the work checks, and its slot is freed when it ends).
pub const TIMEOUT: Duration = Duration::from_secs(30);

/// A bound lab server.
pub struct Lab {
    server: Arc<Server>,
    addr: SocketAddr,
    state: Arc<State>,
}

#[derive(Default)]
struct State {
    busy: AtomicUsize,
    maps: MapCache,
}

/// Frees a run's slot when dropped (also when the run panics).
struct Slot(Arc<State>);

impl Drop for Slot {
    fn drop(&mut self) {
        self.0.busy.fetch_sub(1, Ordering::SeqCst);
    }
}

impl Lab {
    /// Binds `host:port` (port 0: any free port).
    pub fn bind(host: IpAddr, port: u16) -> std::io::Result<Lab> {
        let server = Server::http(SocketAddr::new(host, port))
            .map_err(|e| std::io::Error::other(e.to_string()))?;
        let addr = server
            .server_addr()
            .to_ip()
            .ok_or_else(|| std::io::Error::other("not an IP address"))?;
        Ok(Lab {
            server: Arc::new(server),
            addr,
            state: Arc::default(),
        })
    }

    /// The address bound.
    pub fn addr(&self) -> SocketAddr {
        self.addr
    }

    /// A handle that stops [`Lab::serve`] (for tests).
    pub fn stopper(&self) -> impl Fn() + Send + 'static {
        let s = self.server.clone();
        move || s.unblock()
    }

    /// Serves until stopped: the page on the calling thread, runs on workers.
    pub fn serve(&self) {
        for req in self.server.incoming_requests() {
            self.route(req);
        }
    }

    fn route(&self, req: Request) {
        if self.addr.ip().is_loopback() && !host_is_loopback(&req) {
            let msg = "error: the lab answers only requests addressed to localhost or 127.0.0.1 (a guard against DNS rebinding)";
            return respond_text(req, 403, msg);
        }
        let path = req.url().split('?').next().unwrap_or("").to_string();
        match (req.method(), path.as_str()) {
            (Method::Get | Method::Head, "/" | "/index.html") => {
                let r = Response::from_string(super::assets::page())
                    .with_header(header("Content-Type", "text/html; charset=utf-8"))
                    .with_header(header("Cache-Control", "no-store"));
                let _ = req.respond(r);
            }
            (Method::Get, "/api/scenes") => {
                let r = Response::from_string(api::scenes().to_string())
                    .with_header(header("Content-Type", "application/json"));
                let _ = req.respond(r);
            }
            (Method::Get, "/favicon.ico") => {
                let _ = req.respond(Response::empty(204));
            }
            (Method::Post, "/api/run") => self.work(req, Kind::Run),
            (Method::Post, "/api/map") => self.work(req, Kind::Map),
            (_, "/api/run" | "/api/map") => {
                respond_text(req, 405, "error: use POST with a JSON body of parameters")
            }
            _ => respond_text(req, 404, "error: no such page: the lab is at /"),
        }
    }

    /// Hands a run or a map to a worker thread, if a slot is free.
    fn work(&self, req: Request, kind: Kind) {
        let busy = self.state.busy.fetch_add(1, Ordering::SeqCst);
        let slot = Slot(self.state.clone());
        if busy >= MAX_RUNS {
            drop(slot);
            let msg = format!("error: the lab is busy ({MAX_RUNS} runs at once); try again");
            return respond_text(req, 503, &msg);
        }
        let spawned = std::thread::Builder::new()
            .name("lab-worker".into())
            .spawn(move || answer(req, kind, slot));
        // a failed spawn drops the request (its connection closes) and frees the slot
        drop(spawned);
    }
}

#[derive(Clone, Copy)]
enum Kind {
    Run,
    Map,
}

/// A worker: reads the body, validates, computes on a thread of its own and answers
/// within [`TIMEOUT`].
fn answer(mut req: Request, kind: Kind, slot: Slot) {
    let body = match read_body(&mut req) {
        Ok(b) => b,
        Err(e) => return respond_error(req, &e),
    };
    let run = match api::parse_run(&body) {
        Ok(r) => r,
        Err(e) => return respond_error(req, &e),
    };
    let (tx, rx) = mpsc::channel::<Value>();
    let state = slot.0.clone();
    let spawned = std::thread::Builder::new()
        .name("lab-run".into())
        .spawn(move || {
            let _slot = slot; // held until the computation ends, even past the timeout
            let v = match kind {
                Kind::Run => super::simulate::run(&run),
                Kind::Map => {
                    let mut v = (*state.maps.get(&run)).clone();
                    v["seq"] = run.seq.into();
                    v
                }
            };
            let _ = tx.send(v);
        });
    if spawned.is_err() {
        return respond_error(req, &api::internal("no thread for the run"));
    }
    match rx.recv_timeout(TIMEOUT) {
        Ok(v) => {
            let r = Response::from_string(v.to_string())
                .with_header(header("Content-Type", "application/json"))
                .with_header(header("Cache-Control", "no-store"));
            let _ = req.respond(r);
        }
        Err(mpsc::RecvTimeoutError::Timeout) => {
            let msg = format!(
                "error: the run took longer than the lab's limit of {} s: shorten --duration-s or loosen --rtol",
                TIMEOUT.as_secs()
            );
            respond_text(req, 503, &msg)
        }
        Err(mpsc::RecvTimeoutError::Disconnected) => {
            respond_error(req, &api::internal("the run stopped without an answer"))
        }
    }
}

/// The body, at most [`api::MAX_BODY_BYTES`] (a longer one is refused unread if it
/// says its length, else after reading one byte past the limit).
fn read_body(req: &mut Request) -> Result<Vec<u8>, ApiError> {
    if let Some(n) = req.body_length() {
        if n > api::MAX_BODY_BYTES {
            return Err(api::too_large(n));
        }
    }
    let mut body = Vec::new();
    req.as_reader()
        .take(api::MAX_BODY_BYTES as u64 + 1)
        .read_to_end(&mut body)
        .map_err(|e| ApiError::bad(format!("error: cannot read the request body: {e}")))?;
    if body.len() > api::MAX_BODY_BYTES {
        return Err(api::too_large(body.len()));
    }
    Ok(body)
}

/// Whether the request's Host header names a loopback address (or is absent).
fn host_is_loopback(req: &Request) -> bool {
    let Some(h) = req.headers().iter().find(|h| h.field.equiv("Host")) else {
        return true;
    };
    let host = h.value.as_str();
    let name = if let Some(rest) = host.strip_prefix('[') {
        rest.split(']').next().unwrap_or("")
    } else {
        host.split(':').next().unwrap_or("")
    };
    name.eq_ignore_ascii_case("localhost")
        || name.parse::<IpAddr>().is_ok_and(|ip| ip.is_loopback())
}

fn header(name: &str, value: &str) -> Header {
    Header::from_bytes(name.as_bytes(), value.as_bytes()).expect("a valid ASCII header")
}

fn respond_error(req: Request, e: &ApiError) {
    respond_text(req, e.status, &e.reason)
}

/// A JSON answer `{"error": reason}` with `status`.
fn respond_text(req: Request, status: u16, reason: &str) {
    let body = serde_json::json!({ "error": reason }).to_string();
    let r = Response::from_string(body)
        .with_status_code(status)
        .with_header(header("Content-Type", "application/json"))
        .with_header(header("Cache-Control", "no-store"));
    let _ = req.respond(r);
}

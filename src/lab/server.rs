//! The lab's HTTP server: std only ([`super::http`] reads each request with explicit
//! bounds; the README's note on crates says why no library). One thread accepts
//! connections; each connection has a thread of its own (at most [`MAX_CONNECTIONS`]),
//! so a client that pipelines requests and never reads the answers, or sends its body
//! a byte at a time, holds only its own connection, and only until a deadline. Every
//! run and map goes to a worker thread. Every request is bounded: its header block, URL
//! and body ([`super::http`], [`super::api::MAX_BODY_BYTES`]), the work (the CLI's budget
//! and the lab's drive cycles, checked before any run), the number of runs at once
//! ([`MAX_RUNS`], a slot taken only once the whole body has arrived) and the wait for an
//! answer ([`TIMEOUT`]). No thread but the caller's writes to stdout or stderr.

use super::api::{self, ApiError};
use super::http::{self, Conn, Deadlines, Next, Refusal, Request, JSON};
use super::map::MapCache;
use serde_json::Value;
use std::net::{IpAddr, Ipv4Addr, Ipv6Addr, SocketAddr, TcpListener, TcpStream};
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::sync::{mpsc, Arc};
use std::time::Duration;

/// Most runs and maps computed at once (with [`super::api::MAX_CYCLES`] and the frames
/// and events a run keeps, a bound on the lab's memory: docs/lab.md gives the measured
/// peak); a request beyond is answered 503 at once.
pub const MAX_RUNS: usize = 4;
/// Longest wait for a run's answer; the run is answered 503 then (it finishes in the
/// background, bounded by the work checks, and its slot is freed when it ends).
pub const TIMEOUT: Duration = Duration::from_secs(30);
/// Most connections served at once (one thread each); one beyond is answered 503 and
/// closed. A browser opens about six.
pub const MAX_CONNECTIONS: usize = 64;
/// Stack of a connection's thread: it parses, routes and writes (runs have their own).
const CONNECTION_STACK_BYTES: usize = 1024 * 1024;

/// A bound lab server.
pub struct Lab {
    listener: TcpListener,
    addr: SocketAddr,
    state: Arc<State>,
    deadlines: Deadlines,
}

#[derive(Default)]
struct State {
    busy: AtomicUsize,
    connections: AtomicUsize,
    stop: AtomicBool,
    maps: MapCache,
}

/// Frees a run's slot when dropped (also when the run panics).
struct Slot(Arc<State>);

impl Drop for Slot {
    fn drop(&mut self) {
        self.0.busy.fetch_sub(1, Ordering::SeqCst);
    }
}

/// Counts a connection until dropped.
struct Connection(Arc<State>);

impl Drop for Connection {
    fn drop(&mut self) {
        self.0.connections.fetch_sub(1, Ordering::SeqCst);
    }
}

impl Lab {
    /// Binds `host:port` (port 0: any free port).
    pub fn bind(host: IpAddr, port: u16) -> std::io::Result<Lab> {
        let listener = TcpListener::bind(SocketAddr::new(host, port))?;
        let addr = listener.local_addr()?;
        Ok(Lab {
            listener,
            addr,
            state: Arc::default(),
            deadlines: Deadlines::default(),
        })
    }

    /// The same lab with other deadlines (tests shorten them).
    pub fn with_deadlines(mut self, deadlines: Deadlines) -> Lab {
        self.deadlines = deadlines;
        self
    }

    /// The address bound.
    pub fn addr(&self) -> SocketAddr {
        self.addr
    }

    /// A handle that stops [`Lab::serve`] (for tests): it sets the flag and wakes the
    /// accepting thread with a connection of its own. Open connections end on their own
    /// deadlines.
    pub fn stopper(&self) -> impl Fn() + Send + 'static {
        let state = self.state.clone();
        let mut wake = self.addr;
        if wake.ip().is_unspecified() {
            wake.set_ip(match wake.ip() {
                IpAddr::V4(_) => IpAddr::V4(Ipv4Addr::LOCALHOST),
                IpAddr::V6(_) => IpAddr::V6(Ipv6Addr::LOCALHOST),
            });
        }
        move || {
            state.stop.store(true, Ordering::SeqCst);
            let _ = TcpStream::connect_timeout(&wake, Duration::from_secs(1));
        }
    }

    /// Serves until stopped: accepts on the calling thread, one thread per connection.
    pub fn serve(&self) {
        for stream in self.listener.incoming() {
            if self.state.stop.load(Ordering::SeqCst) {
                break;
            }
            match stream {
                Ok(s) => self.accept(s),
                // out of file descriptors or the like: wait, rather than spin
                Err(_) => std::thread::sleep(Duration::from_millis(20)),
            }
        }
    }

    fn accept(&self, stream: TcpStream) {
        let open = self.state.connections.fetch_add(1, Ordering::SeqCst);
        let counted = Connection(self.state.clone());
        let Ok(conn) = Conn::new(stream, self.deadlines) else {
            return;
        };
        if open >= MAX_CONNECTIONS {
            let msg =
                format!("the lab serves at most {MAX_CONNECTIONS} connections at once; try again");
            let r = Refusal {
                status: 503,
                reason: format!("error: {msg}"),
            };
            // a small answer on a fresh connection: the socket's buffer takes it at once
            return conn.refuse_at_once(&r);
        }
        let loopback = self.addr.ip().is_loopback();
        // a failed spawn drops the connection (it closes) and its count
        let _ = std::thread::Builder::new()
            .name("lab-connection".into())
            .stack_size(CONNECTION_STACK_BYTES)
            .spawn(move || serve_connection(conn, loopback, &counted));
    }
}

/// One connection's requests, in order, until the client closes, a deadline passes or a
/// request is refused.
fn serve_connection(mut conn: Conn, loopback: bool, counted: &Connection) {
    loop {
        let too_large = |n: u64| api::too_large(usize::try_from(n).unwrap_or(usize::MAX)).reason;
        match conn.next_request(api::MAX_BODY_BYTES, too_large) {
            Next::Closed => return,
            Next::Refused(r) => return conn.refuse_and_close(&r),
            Next::Request(req) => {
                let keep = req.keep_alive;
                let (status, ctype, body) = route(&req, loopback, &counted.0);
                let head_only = req.method == "HEAD";
                if conn.respond(status, ctype, &body, head_only, keep).is_err() || !keep {
                    return;
                }
            }
        }
    }
}

type Answer = (u16, &'static str, Vec<u8>);

fn text(status: u16, reason: &str) -> Answer {
    (status, JSON, http::error_json(reason))
}

fn json(v: &Value) -> Answer {
    (200, JSON, v.to_string().into_bytes())
}

fn route(req: &Request, loopback: bool, state: &Arc<State>) -> Answer {
    if loopback && !host_is_loopback(req.host.as_deref()) {
        let msg = "error: the lab answers only requests addressed to localhost or 127.0.0.1 (a guard against DNS rebinding)";
        return text(403, msg);
    }
    match (req.method.as_str(), req.path.as_str()) {
        ("GET" | "HEAD", "/" | "/index.html") => (
            200,
            "text/html; charset=utf-8",
            super::assets::page().as_bytes().to_vec(),
        ),
        ("GET", "/api/scenes") => json(&api::scenes()),
        ("GET", "/favicon.ico") => (204, "text/plain", Vec::new()),
        ("POST", "/api/run") => work(&req.body, Kind::Run, state),
        ("POST", "/api/map") => work(&req.body, Kind::Map, state),
        (_, "/api/run" | "/api/map") => text(405, "error: use POST with a JSON body of parameters"),
        _ => text(404, "error: no such page: the lab is at /"),
    }
}

#[derive(Clone, Copy)]
enum Kind {
    Run,
    Map,
}

/// Validates a whole body, takes a run slot if one is free, computes on a worker thread
/// and answers within [`TIMEOUT`].
fn work(body: &[u8], kind: Kind, state: &Arc<State>) -> Answer {
    let run = match api::parse_run(body) {
        Ok(r) => r,
        Err(e) => return error(&e),
    };
    let busy = state.busy.fetch_add(1, Ordering::SeqCst);
    let slot = Slot(state.clone());
    if busy >= MAX_RUNS {
        drop(slot);
        let msg = format!("error: the lab is busy ({MAX_RUNS} runs at once); try again");
        return text(503, &msg);
    }
    let (tx, rx) = mpsc::channel::<Value>();
    let state = state.clone();
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
        return error(&api::internal("no thread for the run"));
    }
    match rx.recv_timeout(TIMEOUT) {
        Ok(v) => json(&v),
        Err(mpsc::RecvTimeoutError::Timeout) => {
            let msg = format!(
                "error: the run took longer than the lab's limit of {} s: shorten --duration-s or loosen --rtol",
                TIMEOUT.as_secs()
            );
            text(503, &msg)
        }
        Err(mpsc::RecvTimeoutError::Disconnected) => {
            error(&api::internal("the run stopped without an answer"))
        }
    }
}

fn error(e: &ApiError) -> Answer {
    text(e.status, &e.reason)
}

/// Whether a Host header names a loopback address (or is absent: HTTP/1.0).
fn host_is_loopback(host: Option<&str>) -> bool {
    let Some(host) = host else {
        return true;
    };
    let name = if let Some(rest) = host.strip_prefix('[') {
        rest.split(']').next().unwrap_or("")
    } else {
        host.split(':').next().unwrap_or("")
    };
    name.eq_ignore_ascii_case("localhost")
        || name.parse::<IpAddr>().is_ok_and(|ip| ip.is_loopback())
}

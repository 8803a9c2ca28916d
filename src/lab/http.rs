//! The lab's HTTP/1.1, std only (issue 28): one connection's requests, read with explicit
//! bounds before anything is allocated, and its answers.
//!
//! Bounds, each answered with a status, a one-line JSON reason and `Connection: close`:
//! a request line longer than [`MAX_URL_BYTES`] (414), a header block longer than
//! [`MAX_HEAD_BYTES`] or with more than [`MAX_HEADERS`] lines (431), an announced body
//! longer than the caller's limit, refused before a byte of it is read or allocated (413),
//! a header block or body that has not arrived within [`HEAD_DEADLINE`] or
//! [`BODY_DEADLINE`] (408), a malformed request line, a header line without a colon, a
//! folded header, two `Host` or two different `Content-Length` headers, an HTTP/1.1 request
//! without `Host` (400), an HTTP version other than 1.0 and 1.1 (505), a
//! `Transfer-Encoding` (501: the lab's bodies are small and always sent with a length).
//! Every read and write has a timeout, so a client that sends or reads nothing holds only
//! its own connection's thread, and only for a bounded time.

use std::io::{self, Read, Write};
use std::net::{Shutdown, TcpStream};
use std::time::{Duration, Instant};

/// Longest request line (method, target and version; bytes): a 414 beyond.
pub const MAX_URL_BYTES: usize = 2 * 1024;
/// Longest header block, request line included (bytes): a 431 beyond.
pub const MAX_HEAD_BYTES: usize = 16 * 1024;
/// Most header lines: a 431 beyond.
pub const MAX_HEADERS: usize = 64;
/// Longest wait for a whole header block once its first byte arrived: a 408 after.
pub const HEAD_DEADLINE: Duration = Duration::from_secs(10);
/// Longest wait for the first byte of the next request on a kept-alive connection (the
/// connection is closed silently after it).
pub const IDLE_TIMEOUT: Duration = Duration::from_secs(10);
/// Longest wait for a whole body once its header block arrived: a 408 after.
pub const BODY_DEADLINE: Duration = Duration::from_secs(10);
/// Longest wait for one write of an answer to be taken by the client (the connection
/// is dropped after it: a client that never reads holds only its own thread).
pub const WRITE_TIMEOUT: Duration = Duration::from_secs(10);

/// The deadlines of a connection (the constants above; tests shorten them).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Deadlines {
    /// See [`HEAD_DEADLINE`].
    pub head: Duration,
    /// See [`IDLE_TIMEOUT`].
    pub idle: Duration,
    /// See [`BODY_DEADLINE`].
    pub body: Duration,
    /// See [`WRITE_TIMEOUT`].
    pub write: Duration,
}

impl Default for Deadlines {
    fn default() -> Self {
        Deadlines {
            head: HEAD_DEADLINE,
            idle: IDLE_TIMEOUT,
            body: BODY_DEADLINE,
            write: WRITE_TIMEOUT,
        }
    }
}

/// One request, whole: its body has arrived.
#[derive(Debug, Clone)]
pub struct Request {
    /// `GET`, `POST`, ... (as sent: methods are case-sensitive).
    pub method: String,
    /// The target's path, without the query.
    pub path: String,
    /// The `Host` header, if any (at most one was sent).
    pub host: Option<String>,
    /// The body (at most the caller's limit).
    pub body: Vec<u8>,
    /// Whether the connection stays open after the answer.
    pub keep_alive: bool,
}

/// A request refused before it was read whole: answered, then the connection is closed.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Refusal {
    /// HTTP status.
    pub status: u16,
    /// One line, starting `error: `.
    pub reason: String,
}

fn refuse(status: u16, reason: impl Into<String>) -> Refusal {
    Refusal {
        status,
        reason: format!("error: {}", reason.into()),
    }
}

/// What a connection holds next.
#[derive(Debug)]
pub enum Next {
    /// A whole request.
    Request(Request),
    /// The client closed the connection, or sent nothing within [`IDLE_TIMEOUT`].
    Closed,
    /// A request to refuse (then close).
    Refused(Refusal),
}

/// One client connection: the stream and the bytes read but not yet used (the start of
/// a pipelined request).
pub struct Conn {
    stream: TcpStream,
    buf: Vec<u8>,
    deadlines: Deadlines,
}

/// Reads into `buf` until `deadline`: `Ok(0)` at the end of the stream, a `TimedOut`
/// error once the deadline has passed.
fn read_until(stream: &mut TcpStream, buf: &mut [u8], deadline: Instant) -> io::Result<usize> {
    loop {
        let left = deadline.saturating_duration_since(Instant::now());
        if left.is_zero() {
            return Err(io::ErrorKind::TimedOut.into());
        }
        stream.set_read_timeout(Some(left))?;
        match stream.read(buf) {
            Err(e) if e.kind() == io::ErrorKind::Interrupted => continue,
            Err(e) if e.kind() == io::ErrorKind::WouldBlock => {
                return Err(io::ErrorKind::TimedOut.into())
            }
            r => return r,
        }
    }
}

impl Conn {
    /// A connection with `deadlines`.
    pub fn new(stream: TcpStream, deadlines: Deadlines) -> io::Result<Conn> {
        stream.set_write_timeout(Some(deadlines.write))?;
        stream.set_nodelay(true)?;
        Ok(Conn {
            stream,
            buf: Vec::new(),
            deadlines,
        })
    }

    /// The next request, its body at most `max_body` bytes (the caller's 413 reason is
    /// `too_large(announced length)`).
    pub fn next_request(&mut self, max_body: usize, too_large: fn(u64) -> String) -> Next {
        let head = match self.read_head() {
            Ok(Some(h)) => h,
            Ok(None) => return Next::Closed,
            Err(r) => return Next::Refused(r),
        };
        let parsed = match parse_head(&head) {
            Ok(p) => p,
            Err(r) => return Next::Refused(r),
        };
        if parsed.content_length > max_body as u64 {
            return Next::Refused(Refusal {
                status: 413,
                reason: too_large(parsed.content_length),
            });
        }
        if parsed.expect_continue {
            let _ = self.stream.write_all(b"HTTP/1.1 100 Continue\r\n\r\n");
        }
        match self.read_body(parsed.content_length as usize) {
            Ok(Some(body)) => Next::Request(Request {
                method: parsed.method,
                path: parsed.path,
                host: parsed.host,
                body,
                keep_alive: parsed.keep_alive,
            }),
            Ok(None) => Next::Closed,
            Err(r) => Next::Refused(r),
        }
    }

    /// The header block (without its blank line), `None` if the client closed or sent
    /// nothing before the idle timeout.
    fn read_head(&mut self) -> Result<Option<Vec<u8>>, Refusal> {
        let mut chunk = [0u8; 4096];
        let mut deadline = Instant::now() + self.deadlines.idle;
        let mut started = false;
        loop {
            // empty lines before a request line are ignored (RFC 9112 2.2)
            let skip = self.buf.iter().take_while(|b| matches!(b, b'\r' | b'\n'));
            let skip = skip.count();
            self.buf.drain(..skip);
            if !started && !self.buf.is_empty() {
                started = true;
                deadline = Instant::now() + self.deadlines.head;
            }
            if let Some((end, next)) = head_end(&self.buf) {
                let head = self.buf[..end].to_vec();
                self.buf.drain(..next);
                return Ok(Some(head));
            }
            let line_open = !self.buf.contains(&b'\n');
            if !line_open {
                // a malformed request line is refused at once, not after the deadline
                let end = self.buf.iter().position(|&b| b == b'\n').unwrap_or(0);
                let line = String::from_utf8_lossy(&self.buf[..end]);
                parse_request_line(line.strip_suffix('\r').unwrap_or(&line))?;
            }
            if line_open && self.buf.len() > MAX_URL_BYTES {
                return Err(refuse(
                    414,
                    format!(
                        "the request line is longer than the lab's limit of {MAX_URL_BYTES} bytes"
                    ),
                ));
            }
            if self.buf.len() > MAX_HEAD_BYTES {
                return Err(head_too_large());
            }
            match read_until(&mut self.stream, &mut chunk, deadline) {
                Ok(0) => return Ok(None),
                Ok(n) => self.buf.extend_from_slice(&chunk[..n]),
                Err(e) if e.kind() == io::ErrorKind::TimedOut && started => {
                    return Err(refuse(
                        408,
                        format!(
                            "the request's header block did not arrive within {} s",
                            self.deadlines.head.as_secs_f64()
                        ),
                    ))
                }
                Err(_) => return Ok(None),
            }
        }
    }

    /// A body of `len` bytes (at most the caller's limit, checked before), `None` if the
    /// client closed first.
    fn read_body(&mut self, len: usize) -> Result<Option<Vec<u8>>, Refusal> {
        let deadline = Instant::now() + self.deadlines.body;
        let mut body = Vec::with_capacity(len);
        let have = self.buf.len().min(len);
        body.extend(self.buf.drain(..have));
        let mut chunk = [0u8; 4096];
        while body.len() < len {
            let want = (len - body.len()).min(chunk.len());
            match read_until(&mut self.stream, &mut chunk[..want], deadline) {
                Ok(0) => return Ok(None),
                Ok(n) => body.extend_from_slice(&chunk[..n]),
                Err(e) if e.kind() == io::ErrorKind::TimedOut => {
                    return Err(refuse(
                        408,
                        format!(
                            "the request body did not arrive within {} s ({} of {len} bytes)",
                            self.deadlines.body.as_secs_f64(),
                            body.len()
                        ),
                    ))
                }
                Err(_) => return Ok(None),
            }
        }
        Ok(Some(body))
    }

    /// Answers `status` with `body`; `head_only` leaves the body out (HEAD). An error
    /// means the client is gone or does not read: the caller closes.
    pub fn respond(
        &mut self,
        status: u16,
        content_type: &str,
        body: &[u8],
        head_only: bool,
        keep_alive: bool,
    ) -> io::Result<()> {
        let head = format!(
            "HTTP/1.1 {status} {}\r\nContent-Type: {content_type}\r\nContent-Length: {}\r\nCache-Control: no-store\r\nConnection: {}\r\n\r\n",
            reason_phrase(status),
            body.len(),
            if keep_alive { "keep-alive" } else { "close" }
        );
        self.stream.write_all(head.as_bytes())?;
        if !head_only {
            self.stream.write_all(body)?;
        }
        self.stream.flush()
    }

    /// Answers a refusal as JSON `{"error": reason}` and closes the connection: the
    /// answer is sent, the sending side shut, and what the client still sends is read and
    /// dropped for a moment (at most [`LINGER_BYTES`]) so that the close does not reset
    /// the connection before the client has read the answer.
    pub fn refuse_and_close(mut self, r: &Refusal) {
        let _ = self.respond(r.status, JSON, &error_json(&r.reason), false, false);
        let _ = self.stream.shutdown(Shutdown::Write);
        let deadline = Instant::now() + LINGER;
        let mut chunk = [0u8; 4096];
        let mut drained = 0;
        while drained < LINGER_BYTES {
            match read_until(&mut self.stream, &mut chunk, deadline) {
                Ok(0) | Err(_) => break,
                Ok(n) => drained += n,
            }
        }
    }

    /// Answers a refusal and closes without waiting (the accepting thread's answer to a
    /// connection beyond the limit): what the client has sent so far is dropped unread.
    pub fn refuse_at_once(mut self, r: &Refusal) {
        let _ = self
            .stream
            .set_write_timeout(Some(Duration::from_millis(100)));
        let _ = self.respond(r.status, JSON, &error_json(&r.reason), false, false);
        let _ = self.stream.shutdown(Shutdown::Write);
        if self.stream.set_nonblocking(true).is_ok() {
            let (mut chunk, mut drained) = ([0u8; 4096], 0);
            while drained < LINGER_BYTES {
                match self.stream.read(&mut chunk) {
                    Ok(n) if n > 0 => drained += n,
                    _ => break,
                }
            }
        }
    }
}

/// How long a refused connection's further input is read and dropped.
const LINGER: Duration = Duration::from_millis(500);
/// Most bytes read and dropped after a refusal.
pub const LINGER_BYTES: usize = 1 << 20;

/// The content type of the lab's JSON answers.
pub const JSON: &str = "application/json";

/// `{"error": reason}` as bytes.
pub fn error_json(reason: &str) -> Vec<u8> {
    serde_json::json!({ "error": reason })
        .to_string()
        .into_bytes()
}

fn head_too_large() -> Refusal {
    refuse(
        431,
        format!("the request's header block is longer than the lab's limit of {MAX_HEAD_BYTES} bytes or {MAX_HEADERS} lines"),
    )
}

/// The end of the header block in `buf` and the start of what follows it (a blank line:
/// CRLF CRLF, or bare LF LF, which RFC 9112 allows a server to accept).
fn head_end(buf: &[u8]) -> Option<(usize, usize)> {
    let mut i = 0;
    while let Some(k) = buf[i..].iter().position(|&b| b == b'\n') {
        let nl = i + k;
        let rest = &buf[nl + 1..];
        if rest.starts_with(b"\r\n") {
            return Some((nl + 1, nl + 3));
        }
        if rest.starts_with(b"\n") {
            return Some((nl + 1, nl + 2));
        }
        i = nl + 1;
    }
    None
}

/// A parsed header block.
#[derive(Debug, PartialEq)]
struct Head {
    method: String,
    path: String,
    host: Option<String>,
    content_length: u64,
    keep_alive: bool,
    expect_continue: bool,
}

/// At most 40 characters of `s`, control characters escaped, for one-line reasons.
pub(crate) fn clip(s: &str) -> String {
    let mut out: String = s
        .chars()
        .take(40)
        .collect::<String>()
        .escape_debug()
        .to_string();
    if s.chars().count() > 40 {
        out.push_str("...");
    }
    out
}

fn is_token(s: &str) -> bool {
    !s.is_empty()
        && s.bytes()
            .all(|b| b.is_ascii_alphanumeric() || b"!#$%&'*+-.^_`|~".contains(&b))
}

/// Parses a header block (request line and header lines, no blank line).
fn parse_head(head: &[u8]) -> Result<Head, Refusal> {
    let text = std::str::from_utf8(head)
        .map_err(|_| refuse(400, "the request's header block is not UTF-8 text"))?;
    let mut lines = text.split('\n').map(|l| l.strip_suffix('\r').unwrap_or(l));
    let line = lines.next().unwrap_or("");
    let (method, target, http11) = parse_request_line(line)?;
    let mut h = Head {
        method,
        path: target.split('?').next().unwrap_or("").to_string(),
        host: None,
        content_length: 0,
        keep_alive: http11,
        expect_continue: false,
    };
    let mut length_seen = false;
    for (count, line) in lines.filter(|l| !l.is_empty()).enumerate() {
        if count >= MAX_HEADERS {
            return Err(head_too_large());
        }
        header_line(line, &mut h, &mut length_seen)?;
    }
    if http11 && h.host.is_none() {
        return Err(refuse(400, "an HTTP/1.1 request needs a Host header"));
    }
    Ok(h)
}

/// The request line `METHOD /target HTTP/1.x`: (method, target, whether HTTP/1.1).
fn parse_request_line(line: &str) -> Result<(String, String, bool), Refusal> {
    let malformed = || {
        refuse(
            400,
            format!(
                "malformed request line \"{}\": expected METHOD /path HTTP/1.1",
                clip(line)
            ),
        )
    };
    let parts: Vec<&str> = line.split(' ').collect();
    let [method, target, version] = parts[..] else {
        return Err(malformed());
    };
    if !is_token(method) || !target.starts_with('/') {
        return Err(malformed());
    }
    if line.len() > MAX_URL_BYTES {
        return Err(refuse(
            414,
            format!("the request line is longer than the lab's limit of {MAX_URL_BYTES} bytes"),
        ));
    }
    if target.bytes().any(|b| b <= b' ' || b == 0x7f) {
        return Err(malformed());
    }
    let http11 = match version {
        "HTTP/1.1" => true,
        "HTTP/1.0" => false,
        v if v.len() == 8
            && v.starts_with("HTTP/")
            && v.as_bytes()[5].is_ascii_digit()
            && v.as_bytes()[6] == b'.'
            && v.as_bytes()[7].is_ascii_digit() =>
        {
            return Err(refuse(
                505,
                format!("HTTP version {} is not supported: use HTTP/1.1", clip(v)),
            ))
        }
        _ => return Err(malformed()),
    };
    Ok((method.to_string(), target.to_string(), http11))
}

/// One header line into `h`.
fn header_line(line: &str, h: &mut Head, length_seen: &mut bool) -> Result<(), Refusal> {
    if line.starts_with([' ', '\t']) {
        return Err(refuse(
            400,
            format!("folded header line \"{}\" (obsolete)", clip(line)),
        ));
    }
    let Some((name, value)) = line.split_once(':') else {
        return Err(refuse(
            400,
            format!("header line without a colon: \"{}\"", clip(line)),
        ));
    };
    if !is_token(name) {
        return Err(refuse(
            400,
            format!("malformed header name \"{}\"", clip(name)),
        ));
    }
    let value = value.trim_matches([' ', '\t']);
    if value.chars().any(|c| c.is_control() && c != '\t') {
        return Err(refuse(
            400,
            format!("control character in the header {}", clip(name)),
        ));
    }
    match name.to_ascii_lowercase().as_str() {
        "host" if h.host.is_some() => Err(refuse(400, "two Host headers")),
        "host" => {
            h.host = Some(value.to_string());
            Ok(())
        }
        "content-length" => {
            if value.is_empty() || !value.bytes().all(|b| b.is_ascii_digit()) {
                let why = format!("malformed Content-Length \"{}\"", clip(value));
                return Err(refuse(400, why));
            }
            // a length beyond u64 is as refused as any beyond the limit (413)
            let n = value.parse::<u64>().unwrap_or(u64::MAX);
            if *length_seen && n != h.content_length {
                return Err(refuse(400, "two different Content-Length headers"));
            }
            *length_seen = true;
            h.content_length = n;
            Ok(())
        }
        "transfer-encoding" => Err(refuse(
            501,
            "Transfer-Encoding is not supported: send the body with a Content-Length",
        )),
        "connection" => {
            let v = value.to_ascii_lowercase();
            if v.split(',').any(|t| t.trim() == "close") {
                h.keep_alive = false;
            }
            Ok(())
        }
        "expect" => {
            if !value.eq_ignore_ascii_case("100-continue") {
                return Err(Refusal {
                    status: 417,
                    reason: format!("error: unsupported Expect \"{}\"", clip(value)),
                });
            }
            h.expect_continue = true;
            Ok(())
        }
        _ => Ok(()),
    }
}

/// The reason phrase of the statuses the lab sends.
pub fn reason_phrase(status: u16) -> &'static str {
    match status {
        200 => "OK",
        204 => "No Content",
        400 => "Bad Request",
        403 => "Forbidden",
        404 => "Not Found",
        405 => "Method Not Allowed",
        408 => "Request Timeout",
        413 => "Content Too Large",
        414 => "URI Too Long",
        417 => "Expectation Failed",
        431 => "Request Header Fields Too Large",
        500 => "Internal Server Error",
        501 => "Not Implemented",
        503 => "Service Unavailable",
        505 => "HTTP Version Not Supported",
        _ => "Status",
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn status(head: &str) -> Result<Head, u16> {
        parse_head(head.as_bytes()).map_err(|r| {
            assert!(r.reason.starts_with("error: ") && !r.reason.contains('\n'));
            r.status
        })
    }

    #[test]
    fn heads_parse_or_get_their_status() {
        let ok =
            status("POST /api/run?x=1 HTTP/1.1\r\nHost: localhost\r\nContent-Length: 12").unwrap();
        assert_eq!(
            (ok.method.as_str(), ok.path.as_str(), ok.content_length),
            ("POST", "/api/run", 12)
        );
        assert!(ok.keep_alive);
        let huge = status("GET / HTTP/1.1\r\nHost: a\r\nContent-Length: 99999999999999999999");
        assert_eq!(huge.unwrap().content_length, u64::MAX);
        let close = status("GET / HTTP/1.1\r\nHost: a\r\nConnection: Close").unwrap();
        assert!(!close.keep_alive);
        assert!(!status("GET / HTTP/1.0").unwrap().keep_alive);
        for (head, code) in [
            ("GARBAGE", 400),
            ("GET", 400),
            ("GET HTTP/1.1", 400),
            ("GET  / HTTP/1.1", 400),
            ("GET x HTTP/1.1", 400),
            ("GET / HTTP/9.9", 505),
            ("GET / HTTP/1.1x", 400),
            ("GET / HTTP/1.1\r\nHost: a\r\nNoColon", 400),
            ("GET / HTTP/1.1\r\nHost: a\r\n folded", 400),
            ("GET / HTTP/1.1\r\nHost: a\r\nHost: b", 400),
            ("GET / HTTP/1.1\r\nhost: a\r\nHOST: a", 400),
            ("GET / HTTP/1.1", 400),
            ("GET / HTTP/1.1\r\nHost: a\r\nContent-Length: -1", 400),
            ("GET / HTTP/1.1\r\nHost: a\r\nContent-Length: 1e3", 400),
            ("GET / HTTP/1.1\r\nHost: a\r\nContent-Length: ", 400),
            (
                "GET / HTTP/1.1\r\nHost: a\r\nContent-Length: 1\r\nContent-Length: 2",
                400,
            ),
            (
                "POST / HTTP/1.1\r\nHost: a\r\nTransfer-Encoding: chunked",
                501,
            ),
            ("GET / HTTP/1.1\r\nHost: a\r\nBad Name: x", 400),
        ] {
            assert_eq!(status(head).err(), Some(code), "{head:?}");
        }
        let many = format!("GET / HTTP/1.0{}", "\r\nX: y".repeat(MAX_HEADERS + 1));
        assert_eq!(status(&many).err(), Some(431));
        let long = format!("GET /{} HTTP/1.0", "a".repeat(MAX_URL_BYTES));
        assert_eq!(status(&long).err(), Some(414));
    }

    #[test]
    fn the_head_ends_at_the_first_blank_line() {
        assert_eq!(head_end(b"GET / HTTP/1.0\r\n\r\nrest"), Some((16, 18)));
        assert_eq!(head_end(b"GET / HTTP/1.0\n\nrest"), Some((15, 16)));
        assert_eq!(head_end(b"GET / HTTP/1.0\r\nHost: a\r\n"), None);
    }
}

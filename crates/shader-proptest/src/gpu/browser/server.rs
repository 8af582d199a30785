//! A small HTTP/1.1 server on the loopback interface: pages and binary batches for Chromium. One
//! thread accepts, one thread per connection answers its requests in turn (Chromium keeps
//! connections open); a request is a method, a path and a body, an answer a status, a type and a
//! body.

use crate::gpu::error::Error;
use std::io::{BufRead, BufReader, Write};
use std::net::{SocketAddr, TcpListener, TcpStream};
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::Arc;
use std::thread::JoinHandle;
use std::time::Duration;

/// Longest wait for the next request on an open connection before it is closed.
const IDLE_CONNECTION: Duration = Duration::from_secs(120);

/// Largest request body accepted (a batch of results is a few megabytes).
const MAX_BODY: usize = 1 << 30;

/// An HTTP request: `GET /page.html`, `POST /output/3` with its body.
#[derive(Debug)]
pub struct Request {
    /// `GET`, `POST`, ...
    pub method: String,
    /// The path, query included, as sent: `/index.html`.
    pub path: String,
    /// The body (empty for a `GET`).
    pub body: Vec<u8>,
}

/// An answer to a [`Request`].
#[derive(Debug)]
pub struct Response {
    /// 200, 404, ...
    pub status: u16,
    /// The `Content-Type`.
    pub content_type: &'static str,
    /// The body.
    pub body: Vec<u8>,
}

impl Response {
    /// 200 with `body` of `content_type`.
    pub fn ok(content_type: &'static str, body: impl Into<Vec<u8>>) -> Response {
        Response {
            status: 200,
            content_type,
            body: body.into(),
        }
    }

    /// 204: nothing to send.
    pub fn no_content() -> Response {
        Response {
            status: 204,
            content_type: "text/plain",
            body: Vec::new(),
        }
    }

    /// 404, naming `path`.
    pub fn not_found(path: &str) -> Response {
        Response {
            status: 404,
            content_type: "text/plain",
            body: format!("nothing at {path}\n").into_bytes(),
        }
    }
}

/// Answers requests: called on the connections' threads.
pub type Handler = dyn Fn(Request) -> Response + Send + Sync;

/// An HTTP server on `127.0.0.1` that answers with a [`Handler`]; it stops accepting when dropped.
///
/// ```
/// use shader_proptest::{LoopbackServer, Response};
///
/// let server = LoopbackServer::start(0, |request| Response::ok("text/plain", request.path))?;
/// assert!(server.url("/hello").starts_with("http://127.0.0.1:"));
/// # Ok::<(), shader_proptest::Error>(())
/// ```
pub struct LoopbackServer {
    address: SocketAddr,
    stopping: Arc<AtomicBool>,
    acceptor: Option<JoinHandle<()>>,
}

impl LoopbackServer {
    /// Listens on `127.0.0.1:port` (0: a free port) and answers every request with `handler`.
    pub fn start(
        port: u16,
        handler: impl Fn(Request) -> Response + Send + Sync + 'static,
    ) -> Result<LoopbackServer, Error> {
        let listener = TcpListener::bind(("127.0.0.1", port))
            .map_err(|error| Error::Setup(format!("listening on 127.0.0.1:{port}: {error}")))?;
        let address = listener
            .local_addr()
            .map_err(|error| Error::Setup(format!("the listening address: {error}")))?;
        let stopping = Arc::new(AtomicBool::new(false));
        let handler: Arc<Handler> = Arc::new(handler);
        let acceptor = {
            let stopping = Arc::clone(&stopping);
            std::thread::spawn(move || accept(&listener, &stopping, &handler))
        };
        Ok(LoopbackServer {
            address,
            stopping,
            acceptor: Some(acceptor),
        })
    }

    /// The address of `path` on this server: `http://127.0.0.1:<port><path>`.
    pub fn url(&self, path: &str) -> String {
        format!("http://{}{path}", self.address)
    }

    /// The port it listens on.
    pub fn port(&self) -> u16 {
        self.address.port()
    }
}

impl Drop for LoopbackServer {
    fn drop(&mut self) {
        self.stopping.store(true, Ordering::Relaxed);
        // A connection of its own wakes the accepting thread, which then sees `stopping`.
        let _ = TcpStream::connect(self.address);
        if let Some(acceptor) = self.acceptor.take() {
            let _ = acceptor.join();
        }
    }
}

/// Accepts connections until `stopping`, each answered on a thread of its own.
fn accept(listener: &TcpListener, stopping: &AtomicBool, handler: &Arc<Handler>) {
    for stream in listener.incoming() {
        if stopping.load(Ordering::Relaxed) {
            break;
        }
        let Ok(stream) = stream else { continue };
        let handler = Arc::clone(handler);
        std::thread::spawn(move || serve(stream, handler.as_ref()));
    }
}

/// Answers the requests of one connection until it closes, is idle too long or sends something
/// that is not HTTP.
fn serve(stream: TcpStream, handler: &Handler) {
    // Without TCP_NODELAY a response of more than one segment can wait for a delayed
    // acknowledgement (40 ms on Linux).
    if stream.set_read_timeout(Some(IDLE_CONNECTION)).is_err() || stream.set_nodelay(true).is_err() {
        return;
    }
    let Ok(mut writer) = stream.try_clone() else {
        return;
    };
    let mut reader = BufReader::new(stream);
    while let Some(request) = read_request(&mut reader) {
        let response = handler(request);
        if write_response(&mut writer, &response).is_err() {
            break;
        }
    }
}

/// The next request on a connection, or `None` at its end or on anything malformed.
fn read_request(reader: &mut impl BufRead) -> Option<Request> {
    let mut line = String::new();
    if reader.read_line(&mut line).ok()? == 0 {
        return None;
    }
    let mut parts = line.split_whitespace();
    let (method, path) = (parts.next()?.to_string(), parts.next()?.to_string());
    let mut length = 0;
    loop {
        line.clear();
        reader.read_line(&mut line).ok()?;
        let header = line.trim_end();
        if header.is_empty() {
            break;
        }
        if let Some((name, value)) = header.split_once(':') {
            if name.eq_ignore_ascii_case("content-length") {
                length = value.trim().parse().ok().filter(|&length| length <= MAX_BODY)?;
            }
        }
    }
    let mut body = vec![0; length];
    reader.read_exact(&mut body).ok()?;
    Some(Request { method, path, body })
}

/// Writes `response` with its length in one write; the connection stays open for the next
/// request.
fn write_response(writer: &mut impl Write, response: &Response) -> std::io::Result<()> {
    let reason = match response.status {
        200 => "OK",
        204 => "No Content",
        404 => "Not Found",
        _ => "Error",
    };
    let head = format!(
        "HTTP/1.1 {} {reason}\r\nContent-Type: {}\r\nContent-Length: {}\r\nCache-Control: no-store\r\n\r\n",
        response.status,
        response.content_type,
        response.body.len()
    );
    let mut message = Vec::with_capacity(head.len() + response.body.len());
    message.extend_from_slice(head.as_bytes());
    message.extend_from_slice(&response.body);
    writer.write_all(&message)
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::io::Read;

    /// A request with a body is read whole; the next one follows on the same connection.
    #[test]
    fn requests_follow_each_other_on_a_connection() {
        let text =
            b"POST /output/1 HTTP/1.1\r\nHost: x\r\nContent-Length: 4\r\n\r\nabcdGET / HTTP/1.1\r\n\r\n";
        let mut reader = BufReader::new(&text[..]);
        let post = read_request(&mut reader).expect("a POST");
        assert_eq!(
            (post.method.as_str(), post.path.as_str(), &post.body[..]),
            ("POST", "/output/1", &b"abcd"[..])
        );
        let get = read_request(&mut reader).expect("a GET");
        assert_eq!(
            (get.method.as_str(), get.path.as_str(), get.body.len()),
            ("GET", "/", 0)
        );
        assert!(read_request(&mut reader).is_none());
    }

    /// A served request gets the handler's answer, with its length.
    #[test]
    fn a_request_is_answered() {
        let server =
            LoopbackServer::start(0, |request| Response::ok("text/plain", request.path)).expect("a server");
        let mut stream = TcpStream::connect(("127.0.0.1", server.port())).expect("a connection");
        stream.write_all(b"GET /hello HTTP/1.1\r\n\r\n").expect("sent");
        let mut answer = vec![0; 256];
        let read = stream.read(&mut answer).expect("an answer");
        let answer = String::from_utf8_lossy(&answer[..read]);
        assert!(answer.starts_with("HTTP/1.1 200 OK\r\n"), "{answer}");
        assert!(
            answer.ends_with("Content-Length: 6\r\nCache-Control: no-store\r\n\r\n/hello"),
            "{answer}"
        );
    }
}

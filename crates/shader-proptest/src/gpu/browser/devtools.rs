//! The Chrome DevTools protocol over Chromium's debugging pipe (`--remote-debugging-pipe`):
//! Chromium reads commands on its file descriptor 3 and writes answers and events on 4, each
//! message one JSON object ended by a NUL byte. A command is `{"id", "method", "params"}`, with a
//! `"sessionId"` when it goes to a page attached in flat mode; its answer carries the same `"id"`
//! and a `"result"` or an `"error"`; an event carries a `"method"` and no `"id"`.
//!
//! One thread reads the pipe and hands each answer to the call that waits for it, and each event
//! of a page's session to that page's queue; every call waits at most its timeout.

use serde_json::{json, Value};
use std::collections::HashMap;
use std::io::{BufRead, BufReader, PipeReader, PipeWriter, Write};
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::mpsc::{channel, Receiver, RecvTimeoutError, Sender};
use std::sync::{Arc, Mutex};
use std::time::Duration;

/// Where the reader thread hands what it reads.
#[derive(Default)]
struct Routes {
    /// The calls waiting for an answer, by id.
    answers: HashMap<u64, Sender<Result<Value, String>>>,
    /// The event queues of the sessions that asked for theirs, by session id.
    events: HashMap<String, Sender<Value>>,
    /// Set when the pipe has closed: why.
    closed: Option<String>,
}

/// A DevTools connection over a pipe pair; shared by the browser and its pages.
pub(super) struct DevTools {
    commands: Mutex<PipeWriter>,
    next_id: AtomicU64,
    routes: Arc<Mutex<Routes>>,
}

impl DevTools {
    /// Starts reading `messages` (what Chromium writes) on a thread of its own; commands go to
    /// `commands` (what Chromium reads).
    pub(super) fn new(commands: PipeWriter, messages: PipeReader) -> DevTools {
        let routes = Arc::new(Mutex::new(Routes::default()));
        let for_reader = Arc::clone(&routes);
        std::thread::spawn(move || read_messages(messages, &for_reader));
        DevTools {
            commands: Mutex::new(commands),
            next_id: AtomicU64::new(1),
            routes,
        }
    }

    /// The result of `method` with `params`, sent to the page of `session` (the browser itself
    /// when `None`); an error with Chromium's message, or when no answer came within `timeout`.
    pub(super) fn call(
        &self,
        session: Option<&str>,
        method: &str,
        params: Value,
        timeout: Duration,
    ) -> Result<Value, String> {
        let id = self.next_id.fetch_add(1, Ordering::Relaxed);
        let (sender, answer) = channel();
        {
            let mut routes = lock(&self.routes);
            if let Some(why) = &routes.closed {
                return Err(why.clone());
            }
            routes.answers.insert(id, sender);
        }
        let mut command = json!({ "id": id, "method": method, "params": params });
        if let Some(session) = session {
            command["sessionId"] = Value::from(session);
        }
        let mut bytes = command.to_string().into_bytes();
        bytes.push(0);
        let written = lock(&self.commands).write_all(&bytes);
        if let Err(error) = written {
            lock(&self.routes).answers.remove(&id);
            return Err(format!(
                "Chromium's DevTools pipe closed before {method} was sent: {error}"
            ));
        }
        match answer.recv_timeout(timeout) {
            Ok(result) => result,
            Err(RecvTimeoutError::Timeout) => {
                lock(&self.routes).answers.remove(&id);
                Err(format!(
                    "no answer to {method} within {:.1} s",
                    timeout.as_secs_f64()
                ))
            }
            Err(RecvTimeoutError::Disconnected) => Err(self.closed_reason()),
        }
    }

    /// From now on, the events of the page of `session`, in the order Chromium sent them.
    pub(super) fn events(&self, session: &str) -> Receiver<Value> {
        let (sender, events) = channel();
        lock(&self.routes).events.insert(session.to_string(), sender);
        events
    }

    /// Why the pipe closed, or that it did.
    fn closed_reason(&self) -> String {
        lock(&self.routes)
            .closed
            .clone()
            .unwrap_or_else(|| "Chromium closed its DevTools pipe".to_string())
    }
}

/// Locks `mutex`; a panic elsewhere while holding it leaves the routes usable.
fn lock<T>(mutex: &Mutex<T>) -> std::sync::MutexGuard<'_, T> {
    mutex.lock().unwrap_or_else(|poisoned| poisoned.into_inner())
}

/// Reads NUL-ended messages from `messages` until the pipe closes, routing each; then fails every
/// waiting call.
fn read_messages(messages: PipeReader, routes: &Mutex<Routes>) {
    let mut reader = BufReader::new(messages);
    let mut message = Vec::new();
    let why = loop {
        message.clear();
        match reader.read_until(0, &mut message) {
            Ok(0) => break "Chromium closed its DevTools pipe".to_string(),
            Ok(_) => {
                if message.last() == Some(&0) {
                    message.pop();
                }
                match serde_json::from_slice::<Value>(&message) {
                    Ok(value) => route(value, &mut lock(routes)),
                    Err(error) => break format!("Chromium wrote a message that is not JSON: {error}"),
                }
            }
            Err(error) => break format!("reading Chromium's DevTools pipe failed: {error}"),
        }
    };
    let mut routes = lock(routes);
    routes.closed = Some(why);
    // Dropping the senders wakes every waiting call and ends every event queue.
    routes.answers.clear();
    routes.events.clear();
}

/// Hands one message to the call or the event queue it is for; drops what nobody waits for.
fn route(message: Value, routes: &mut Routes) {
    if let Some(id) = message["id"].as_u64() {
        if let Some(sender) = routes.answers.remove(&id) {
            let result = match message.get("error") {
                Some(error) => Err(format!(
                    "Chromium answered: {}",
                    error["message"].as_str().unwrap_or("an error without a message")
                )),
                None => Ok(message["result"].clone()),
            };
            // The caller is gone only where it timed out.
            let _ = sender.send(result);
        }
        return;
    }
    if let Some(session) = message["sessionId"].as_str() {
        let delivered = routes
            .events
            .get(session)
            .is_some_and(|queue| queue.send(message.clone()).is_ok());
        if !delivered {
            routes.events.remove(session);
        }
    }
}

/// The bytes of standard base64 `text` (RFC 4648, with padding), as DevTools sends binary data.
pub(super) fn decode_base64(text: &str) -> Result<Vec<u8>, String> {
    let digit = |byte: u8| -> Result<u32, String> {
        Ok(match byte {
            b'A'..=b'Z' => byte - b'A',
            b'a'..=b'z' => byte - b'a' + 26,
            b'0'..=b'9' => byte - b'0' + 52,
            b'+' => 62,
            b'/' => 63,
            _ => return Err(format!("{:?} is not a base64 digit", byte as char)),
        }
        .into())
    };
    let text = text.trim_end_matches('=').as_bytes();
    let mut bytes = Vec::with_capacity(text.len() * 3 / 4);
    for group in text.chunks(4) {
        let mut bits = 0u32;
        for (index, &byte) in group.iter().enumerate() {
            bits |= digit(byte)? << (18 - 6 * index);
        }
        let whole = match group.len() {
            4 => 3,
            3 => 2,
            2 => 1,
            _ => return Err("base64 text of a length that no bytes give".to_string()),
        };
        bytes.extend(&bits.to_be_bytes()[1..=whole]);
    }
    Ok(bytes)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// RFC 4648's test vectors, section 10.
    #[test]
    fn base64_decodes_the_rfc_vectors() {
        for (text, bytes) in [
            ("", ""),
            ("Zg==", "f"),
            ("Zm8=", "fo"),
            ("Zm9v", "foo"),
            ("Zm9vYg==", "foob"),
            ("Zm9vYmE=", "fooba"),
            ("Zm9vYmFy", "foobar"),
        ] {
            assert_eq!(decode_base64(text).as_deref(), Ok(bytes.as_bytes()), "{text}");
        }
        assert!(decode_base64("Zm9v!").is_err());
        assert!(decode_base64("Z").is_err());
    }

    /// An answer reaches its call, an event its session's queue, and a closed pipe fails the call.
    #[test]
    fn answers_and_events_are_routed() {
        let (our_reader, their_writer) = std::io::pipe().expect("a pipe");
        let (their_reader, our_writer) = std::io::pipe().expect("a pipe");
        let devtools = DevTools::new(our_writer, our_reader);
        let events = devtools.events("page");
        let echo = std::thread::spawn(move || {
            let mut commands = BufReader::new(their_reader);
            let mut writer = their_writer;
            let mut command = Vec::new();
            commands.read_until(0, &mut command).expect("a command");
            command.pop();
            let command: Value = serde_json::from_slice(&command).expect("JSON");
            let event = json!({ "method": "Page.loadEventFired", "sessionId": "page", "params": {} });
            let answer = json!({ "id": command["id"], "result": { "method": command["method"] } });
            for message in [event, answer] {
                writer
                    .write_all(&[message.to_string().as_bytes(), &[0]].concat())
                    .expect("written");
            }
        });
        let result = devtools
            .call(Some("page"), "Page.enable", json!({}), Duration::from_secs(5))
            .expect("an answer");
        assert_eq!(result["method"], "Page.enable");
        let event = events.recv_timeout(Duration::from_secs(5)).expect("an event");
        assert_eq!(event["method"], "Page.loadEventFired");
        echo.join().expect("the echo ended");
        let closed = devtools.call(None, "Browser.getVersion", json!({}), Duration::from_secs(5));
        assert!(closed.is_err_and(|why| why.contains("closed")));
    }
}

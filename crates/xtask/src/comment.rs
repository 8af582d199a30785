//! Rust doc comments as shader comments: the first paragraph, with rustdoc links and code spans
//! turned into plain text and the crate's names turned into the shaders' names.

use crate::rust_items::{Kind, RustItems};

/// Longest generated comment line, the indentation and comment marker included.
const LINE_WIDTH: usize = 100;

/// The first paragraph of `docs` in shader spelling, wrapped to `LINE_WIDTH` after `prefix`
/// (indentation and comment marker, e.g. `"    // "`). No lines for an empty doc comment.
pub fn lines(docs: &[String], prefix: &str, names: &RustItems) -> Vec<String> {
    let paragraph: Vec<&str> = docs
        .iter()
        .map(|line| line.trim())
        .take_while(|line| !line.is_empty())
        .collect();
    let text = plain_text(&paragraph.join(" "), names, false);
    wrap(&text, prefix)
}

/// `[`x`]`, `[`x`](target)` and `[text](target)` become their text; a code span becomes its
/// contents, renamed when it names a shared item or public function.
fn plain_text(text: &str, names: &RustItems, in_link: bool) -> String {
    let mut out = String::new();
    let mut rest = text;
    while let Some(start) = rest.find(['[', '`']) {
        out.push_str(&rest[..start]);
        let tail = &rest[start..];
        if let Some(inner) = tail.strip_prefix('`') {
            let Some(end) = inner.find('`') else {
                out.push_str(tail);
                return out;
            };
            out.push_str(&shader_names(&inner[..end], names, in_link));
            rest = &inner[end + 1..];
        } else {
            let Some(end) = tail.find(']') else {
                out.push_str(tail);
                return out;
            };
            let label = &tail[1..end];
            let after = &tail[end + 1..];
            rest = skip_link_target(after);
            // A bracket that is no link (an interval such as `[0, 1]`) keeps its brackets.
            if rest.len() == after.len() && !label.starts_with('`') {
                out.push('[');
                out.push_str(&plain_text(label, names, in_link));
                out.push(']');
            } else {
                out.push_str(&plain_text(label, names, true));
            }
        }
    }
    out.push_str(rest);
    out
}

/// The text after a link's `(target)` or `[reference]`, or `text` itself when none follows.
fn skip_link_target(text: &str) -> &str {
    for (open, close) in [('(', ')'), ('[', ']')] {
        if let Some(inner) = text.strip_prefix(open) {
            if let Some(end) = inner.find(close) {
                return &inner[end + 1..];
            }
        }
    }
    text
}

/// The shader spelling of a code span: each name in it (a path counts by its last segment) gets
/// `Rf` before a shared struct, `RF_` before a shared constant, and `rf_` before a public function
/// where the span is a link or a path (a plain `normal_spread_angle` may be a parameter).
fn shader_names(code: &str, names: &RustItems, in_link: bool) -> String {
    let mut out = String::new();
    let mut word = String::new();
    for c in code.chars().chain(std::iter::once(' ')) {
        if c.is_alphanumeric() || c == '_' || c == ':' {
            word.push(c);
        } else {
            out.push_str(&shader_name(&word, names, in_link));
            word.clear();
            out.push(c);
        }
    }
    out.pop();
    out
}

/// A path is written from its first shared item on, with `.` between segments: `crate::wireframe::
/// WireframeSettings::stipple` becomes `RfWireframeSettings.stipple`, and an enum's variant its
/// constant: `Mode::Cone` becomes `RT_MODE_CONE`.
fn shader_name(word: &str, names: &RustItems, in_link: bool) -> String {
    let segments: Vec<&str> = word.split("::").collect();
    for (index, segment) in segments.iter().enumerate() {
        let rest = &segments[index + 1..];
        let renamed = match names.items.get(*segment) {
            Some(
                item @ crate::rust_items::Item {
                    kind: Kind::Enum { variants },
                    ..
                },
            ) => {
                match rest
                    .first()
                    .and_then(|next| variants.iter().find(|v| v.name == *next))
                {
                    Some(variant) => return variant.shader_name.clone(),
                    None => Some(item.shader_name.clone()),
                }
            }
            Some(item) if !matches!(item.kind, Kind::Unreadable(_)) => Some(item.shader_name.clone()),
            _ if in_link || segments.len() > 1 => names.functions.get(*segment).cloned(),
            _ => None,
        };
        if let Some(first) = renamed {
            return std::iter::once(first)
                .chain(rest.iter().map(|s| format!(".{s}")))
                .collect();
        }
    }
    word.to_string()
}

/// Greedy word wrap; a word longer than the line stands on its own line.
fn wrap(text: &str, prefix: &str) -> Vec<String> {
    let mut lines = Vec::new();
    let mut line = String::new();
    for word in text.split_whitespace() {
        if !line.is_empty() && prefix.len() + line.len() + 1 + word.len() > LINE_WIDTH {
            lines.push(format!("{prefix}{line}"));
            line.clear();
        }
        if !line.is_empty() {
            line.push(' ');
        }
        line.push_str(word);
    }
    if !line.is_empty() {
        lines.push(format!("{prefix}{line}"));
    }
    lines
}

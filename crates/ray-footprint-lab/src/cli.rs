//! What the lab's command-line programs (the `verify`, `gallery` and `quality` examples and the
//! benches) share: answering `--help`, reporting a bad option, and reading a positive count.

use std::process::exit;

/// The options `parsed` from the command line, before the program opens anything. An empty error
/// message asks for help: prints `usage` (starting `usage: ` and the program's name) and exits with
/// status 0. Any other error: prints it and `usage` to stderr and exits with status 2.
pub fn options_or_exit<T>(parsed: Result<T, String>, usage: &str) -> T {
    parsed.unwrap_or_else(|message| {
        if message.is_empty() {
            println!("{usage}");
            exit(0)
        }
        eprintln!("error: {message}\n{usage}");
        exit(2)
    })
}

/// `value` of the option `flag` as a positive integer, or the message that names both.
pub fn positive_count(flag: &str, value: &str) -> Result<usize, String> {
    match value.parse::<usize>() {
        Ok(n) if n > 0 => Ok(n),
        _ => Err(format!("{flag} must be a positive integer, got '{value}'")),
    }
}

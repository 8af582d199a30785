//! What the lab's command-line programs (the `verify` example and the benches) share: reporting a
//! bad option, and reading a positive count.

use std::process::exit;

/// The options `parsed` from the command line; on an error, prints it and `usage` (the program's
/// name and options) to stderr and exits with status 2, before the program opens anything.
pub fn options_or_exit<T>(parsed: Result<T, String>, usage: &str) -> T {
    parsed.unwrap_or_else(|message| {
        eprintln!("error: {message}\nusage: {usage}");
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

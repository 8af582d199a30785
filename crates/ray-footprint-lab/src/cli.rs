//! What the lab's command-line programs (the `verify`, `gallery`, `quality`, `cost_quality`,
//! `path_footprint` and `path_image` examples and the benches) share: answering `--help`,
//! reporting a bad option, reading a command line's flags, a positive count, level-of-detail
//! biases, a seed and an image size, and the command that reruns an example.

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

/// The options of a benchmark's or an example's command line `args`, each a flag and its value, in
/// order. `--bench`, which `cargo bench` passes to every benchmark, is skipped; `--help` or `-h`
/// gives the empty message that asks for help ([`options_or_exit`]); a flag without a value, the
/// message naming it.
pub fn command_options(mut args: impl Iterator<Item = String>) -> Result<Vec<(String, String)>, String> {
    let mut options = Vec::new();
    while let Some(flag) = args.next() {
        match flag.as_str() {
            "--bench" => continue,
            "--help" | "-h" => return Err(String::new()),
            _ => {}
        }
        let value = args.next().ok_or_else(|| format!("{flag} needs a value"))?;
        options.push((flag, value));
    }
    Ok(options)
}

/// `value` of the option `flag` as an integer of at least `min`, or the message that names both.
pub fn count_at_least(flag: &str, value: &str, min: usize) -> Result<usize, String> {
    match positive_count(flag, value)? {
        count if count >= min => Ok(count),
        count => Err(format!("{flag} must be at least {min}, got {count}")),
    }
}

/// `value` of the option `flag` (`--spread`) as whether a render of `n` samples per pixel starts
/// its paths from one sample's cone (`sample`) rather than the pixel's (`pixel`), or the message
/// that names both.
pub fn sample_spread(flag: &str, value: &str) -> Result<bool, String> {
    match value {
        "pixel" => Ok(false),
        "sample" => Ok(true),
        _ => Err(format!("{flag} must be pixel or sample, got '{value}'")),
    }
}

/// `value` of the option `flag` (`--biases`) as its comma-separated level-of-detail biases, each a
/// finite number of mip levels, or the message that names the option and the first item that is
/// not.
pub fn lod_biases(flag: &str, value: &str) -> Result<Vec<f32>, String> {
    value
        .split(',')
        .map(|item| match item.trim().parse::<f32>() {
            Ok(bias) if bias.is_finite() => Ok(bias),
            _ => Err(format!(
                "{flag} {value}: '{item}' is not a finite number of mip levels"
            )),
        })
        .collect()
}

/// `value` of the option `flag` as a seed (any `u64`), or the message that names both.
pub fn seed(flag: &str, value: &str) -> Result<u64, String> {
    value
        .parse()
        .map_err(|_| format!("{flag} must be an integer, got '{value}'"))
}

/// `value` of the option `flag` as an image size `WIDTHxHEIGHT`, both positive, or the message
/// that names both.
pub fn image_size(flag: &str, value: &str) -> Result<(u32, u32), String> {
    let error = || format!("{flag} must be WIDTHxHEIGHT, got '{value}'");
    let (width, height) = value.split_once('x').ok_or_else(error)?;
    let side = |text: &str| text.parse::<u32>().ok().filter(|&n| n > 0).ok_or_else(error);
    Ok((side(width)?, side(height)?))
}

/// The command that reruns the example `name` of this crate with the arguments it was given:
/// `cargo run --release -p ray-footprint-lab --example NAME[ -- ARGS]`.
pub fn example_command(name: &str) -> String {
    let arguments: Vec<String> = std::env::args().skip(1).collect();
    let tail = if arguments.is_empty() {
        String::new()
    } else {
        format!(" -- {}", arguments.join(" "))
    };
    format!("cargo run --release -p ray-footprint-lab --example {name}{tail}")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn image_sizes_biases_and_seeds_are_read_or_named() {
        assert_eq!(image_size("--size", "640x360"), Ok((640, 360)));
        for bad in ["640", "0x360", "640x", "x360", "-1x2"] {
            assert_eq!(
                image_size("--size", bad),
                Err(format!("--size must be WIDTHxHEIGHT, got '{bad}'"))
            );
        }
        assert_eq!(lod_biases("--biases", "-20, 0.5,20"), Ok(vec![-20.0, 0.5, 20.0]));
        for (bad, item) in [("1,x", "x"), ("inf", "inf"), ("1,,2", "")] {
            assert_eq!(
                lod_biases("--biases", bad),
                Err(format!(
                    "--biases {bad}: '{item}' is not a finite number of mip levels"
                ))
            );
        }
        assert_eq!(seed("--seed", "7"), Ok(7));
        assert_eq!(
            seed("--seed", "-7"),
            Err("--seed must be an integer, got '-7'".to_string())
        );
    }
}

//! The generated tables of the root crate's pages: the degenerate inputs of every function
//! (`src/degenerate.md`, [`degenerate_table`]) and how each function is proven (`src/proven.md`,
//! [`proven_table`]). `tests/records.rs` and `tests/references.rs` hold the pages to them.

use crate::record::Function;
use ray_footprint::shaders::Module;
use shader_proptest::{Language, RunConfig};
use std::fmt::Write as _;

/// The degenerate table of `src/degenerate.md`: every record's rows ([`crate::degenerate`]) as
/// markdown, one section per module, the functions in module order.
pub fn degenerate_table(records: &[Box<dyn Function>]) -> String {
    let mut out = String::new();
    for &module in Module::ALL {
        writeln!(out, "\n### `{}`\n", module.stem()).expect("a String");
        out.push_str("| function | degenerate input | documented output |\n| --- | --- | --- |\n");
        for record in records.iter().filter(|record| record.module() == module) {
            record.degenerate_markdown(&mut out);
        }
    }
    out
}

/// The markdown table of `src/proven.md`: per function, its agreement checks (languages and cases
/// per language), its references (kind and description), its degenerate rows and the bug a check
/// or reference found, one section per module.
pub fn proven_table(records: &[Box<dyn Function>]) -> String {
    let cases = RunConfig::default().cases;
    let languages: Vec<&str> = Language::ALL.iter().map(|language| language.name()).collect();
    let mut out = String::new();
    for &module in Module::ALL {
        let agreement = format!(
            "{}: {} cases each{}",
            languages.join(", "),
            thousands(cases),
            if module.needs_f64() {
                " (needs `shaderFloat64`)"
            } else {
                ""
            }
        );
        writeln!(out, "\n### `{}`\n", module.stem()).expect("a String");
        out.push_str("| function | agreement | references | degenerate rows | found |\n| --- | --- | --- | --- | --- |\n");
        for record in records.iter().filter(|record| record.module() == module) {
            let references: Vec<String> = record
                .references()
                .iter()
                .map(|(kind, description)| format!("{}: {description}", kind.name()))
                .collect();
            writeln!(
                out,
                "| `{}` | {agreement} | {} | {} | {} |",
                record.name(),
                references.join("<br>").replace('|', "\\|"),
                record.degenerate_rows(),
                record.found().unwrap_or("").replace('|', "\\|")
            )
            .expect("a String");
        }
    }
    out
}

/// `n` with commas between groups of three digits.
fn thousands(n: usize) -> String {
    let digits = n.to_string();
    let mut out = String::new();
    for (index, digit) in digits.chars().enumerate() {
        if index > 0 && (digits.len() - index).is_multiple_of(3) {
            out.push(',');
        }
        out.push(digit);
    }
    out
}

#[cfg(test)]
mod tests {
    use super::thousands;

    #[test]
    fn thousands_are_grouped() {
        assert_eq!(thousands(100_000), "100,000");
        assert_eq!(thousands(999), "999");
    }
}

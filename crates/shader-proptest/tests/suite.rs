//! `run_checks` on a suite that holds one function in several languages: the entries of one check
//! run together on the same cases, each judged on its own, with one seed for the whole run.

use shader_proptest::{run_checks, Check, Error, FunctionCheck, Gpu, Outcome, Report, RunConfig, Shader};

/// `halve` in three languages, the GLSL one wrong for `x > 0.5`, the Slang one not compiling.
fn shaders() -> [Shader; 3] {
    [
        Shader::wgsl("fn halve(x: f32) -> f32 { return x * 0.5; }"),
        Shader::glsl("float halve(float x) { return x > 0.5 ? x * 0.25 : x * 0.5; }"),
        Shader::slang("float halve(float x) { return x * ; }"),
    ]
}

#[test]
fn entries_of_one_check_run_on_the_same_cases_and_end_apart() {
    let gpu = Gpu::new().unwrap_or_else(|error| panic!("{error}"));
    let half = FunctionCheck::new("halve", || (-1.0f32..1.0,), |(x,): (f32,)| x * 0.5);
    let checks: Vec<(&dyn Check, Shader)> = shaders()
        .into_iter()
        .map(|shader| (&half as &dyn Check, shader))
        .collect();
    let config = RunConfig {
        cases: 20_000,
        batch: 4096,
        seed: None,
        ..RunConfig::default()
    };
    let mut results: Vec<(usize, Result<Report, Error>)> = Vec::new();
    run_checks(&gpu, &checks, &config, 2, |index, result| {
        results.push((index, result))
    })
    .unwrap_or_else(|error| panic!("{error}"));
    assert_eq!(
        results.iter().map(|(index, _)| *index).collect::<Vec<_>>(),
        [0, 1, 2]
    );
    let [(_, wgsl), (_, glsl), (_, slang)] = <[_; 3]>::try_from(results).expect("three results");
    let (wgsl, glsl) = (wgsl.expect("WGSL runs"), glsl.expect("GLSL runs"));
    assert!(matches!(slang, Err(Error::Compile(_))), "{slang:?}");
    wgsl.assert_passed();
    assert_eq!(wgsl.cases, config.cases);
    let Outcome::Failed(failure) = &glsl.outcome else {
        panic!("the wrong GLSL passed:\n{glsl}");
    };
    // The seed the run drew is every report's, so that one variable replays the whole suite.
    assert_eq!(wgsl.seed, glsl.seed);
    // Shrinking moves the case towards 0 while it still fails: it stops just above 0.5.
    let shrunk: f32 = failure
        .input
        .trim_matches(|c| c == '(' || c == ')' || c == ',')
        .parse()
        .expect("one float");
    assert!(shrunk > 0.5 && shrunk < 0.5001, "{}", failure.input);
}

/// Groups run two at a time and still report in the order of the suite; an entry of a check that
/// is not next to its others makes a group of its own.
#[test]
fn groups_report_in_order() {
    let gpu = Gpu::new().unwrap_or_else(|error| panic!("{error}"));
    let halve = FunctionCheck::new("halve", || (-1.0f32..1.0,), |(x,): (f32,)| x * 0.5);
    let twice = FunctionCheck::new("twice", || (-1.0f32..1.0,), |(x,): (f32,)| x * 2.0);
    let checks: [(&dyn Check, Shader); 5] = [
        (
            &halve,
            Shader::wgsl("fn halve(x: f32) -> f32 { return x * 0.5; }"),
        ),
        (&halve, Shader::glsl("float halve(float x) { return x * 0.5; }")),
        (
            &twice,
            Shader::wgsl("fn twice(x: f32) -> f32 { return x * 2.0; }"),
        ),
        (&twice, Shader::glsl("float twice(float x) { return x * 2.0; }")),
        (
            &halve,
            Shader::wgsl("fn halve(x: f32) -> f32 { return x * 0.5; }"),
        ),
    ];
    let config = RunConfig {
        cases: 20_000,
        batch: 2048,
        ..RunConfig::default()
    };
    let mut reports = Vec::new();
    run_checks(&gpu, &checks, &config, 2, |index, result| {
        reports.push((index, result.unwrap_or_else(|error| panic!("{error}"))));
    })
    .unwrap_or_else(|error| panic!("{error}"));
    let order: Vec<(usize, &str)> = reports
        .iter()
        .map(|(index, report)| (*index, report.function.as_str()))
        .collect();
    assert_eq!(
        order,
        [
            (0, "halve"),
            (1, "halve"),
            (2, "twice"),
            (3, "twice"),
            (4, "halve")
        ]
    );
    for (_, report) in &reports {
        report.assert_passed();
        assert_eq!(report.cases, config.cases);
    }
}

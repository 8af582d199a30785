//! The same checks in headless Chromium's WebGPU (feature `browser`): a right WGSL function
//! passes, a wrong one fails and shrinks as on the Vulkan path, a kernel Tint rejects, a shader
//! that needs 64-bit floats, a GLSL shader, a missing Chromium, one that never answers
//! and a page that never answers each end with what happened.

use shader_proptest::{
    BrowserDevice, Chromium, ChromiumOptions, Error, FunctionCheck, LoopbackServer, Outcome, Response,
    RunConfig, Shader, Tolerance,
};
use std::time::{Duration, Instant};

const FALLOFF: &str = "fn falloff(d: f32, r0: f32, r1: f32) -> f32 { return 1.0 - smoothstep(r0, r1, d); }";

/// The falloff of the WGSL above, with `smoothstep`'s formula.
fn falloff((d, r0, r1): (f32, f32, f32)) -> f32 {
    let t = ((d - r0) / (r1 - r0)).clamp(0.0, 1.0);
    1.0 - t * t * (3.0 - 2.0 * t)
}

/// The falloff check on d in 0..10, r0 in 0..1, r1 in 1.5..5. Vulkan and WebGPU let `smoothstep`
/// be computed with its own roundings: a handful of ULP of 1 is an absolute 1e-6.
fn check() -> FunctionCheck<(f32, f32, f32), f32> {
    FunctionCheck::new("falloff", || (0.0f32..10.0, 0.0f32..1.0, 1.5f32..5.0), falloff)
        .tolerance(Tolerance::Absolute(1.0e-6))
}

fn config() -> RunConfig {
    RunConfig {
        cases: 20_000,
        seed: Some(5),
        ..RunConfig::default()
    }
}

fn device() -> BrowserDevice {
    BrowserDevice::new().unwrap_or_else(|error| panic!("{error}\non Debian 12 run `scripts/setup.sh`"))
}

#[test]
fn a_wgsl_check_runs_in_the_browser() {
    let device = device();
    let report = check()
        .run_browser(&device, &Shader::wgsl(FALLOFF), &config())
        .unwrap_or_else(|error| panic!("{error}"));
    println!("{report}");
    assert!(report.device.contains("through Chromium"), "{}", report.device);
    assert!(report.device.ends_with("WebGPU"), "{}", report.device);
    assert_eq!(report.cases, 20_000);
    report.assert_passed();
}

#[test]
fn a_wrong_function_fails_and_shrinks_in_the_browser() {
    let device = device();
    let broken = Shader::wgsl(FALLOFF.replace("r1, d)", "r1 + 1.0, d)"));
    let report = check()
        .run_browser(&device, &broken, &config())
        .unwrap_or_else(|error| panic!("{error}"));
    let Outcome::Failed(failure) = &report.outcome else {
        panic!("the broken falloff passed: {report}")
    };
    println!("{report}");
    assert!(failure.input.ends_with(", 0.0, 1.5)"), "{}", failure.input);
}

/// A kernel that naga compiles and Tint rejects (a barrier in control flow that depends on the
/// argument, which WGSL's uniformity analysis forbids) fails the preparation with Tint's error.
#[test]
fn a_kernel_tint_rejects_is_a_compile_error() {
    let device = device();
    let shader = Shader::wgsl("fn gated(x: f32) -> f32 { if x > 0.5 { workgroupBarrier(); } return x; }");
    let check = FunctionCheck::new("gated", || (0.0f32..1.0,), |(x,): (f32,)| x);
    match check.run_browser(&device, &shader, &config()) {
        Err(Error::Compile(message)) => {
            assert!(message.contains("Tint error"), "{message}");
            assert!(message.contains("uniform control flow"), "{message}");
        }
        Err(other) => panic!("expected Tint's compile error, got {other}"),
        Ok(report) => panic!("expected Tint to reject the kernel, got {report}"),
    }
}

/// A shader that needs 64-bit floats (here inside an f32 function) is reported as not run, with
/// WebGPU's reason.
#[test]
fn a_shader_needing_f64_is_not_run() {
    let device = device();
    let shader = Shader::wgsl("fn twice(x: f32) -> f32 { return f32(2.0 * f64(x)); }")
        .requires(shader_proptest::Feature::ShaderFloat64);
    let check = FunctionCheck::new("twice", || (0.0f32..1.0,), |(x,): (f32,)| 2.0 * x);
    let report = check
        .run_browser(&device, &shader, &config())
        .unwrap_or_else(|error| panic!("{error}"));
    assert!(!report.passed(), "{report}");
    match &report.outcome {
        Outcome::NotRun(reason) => assert_eq!(reason, "WebGPU has no 64-bit floats"),
        _ => panic!("expected not run: {report}"),
    }
}

#[test]
fn glsl_is_refused() {
    let device = device();
    let glsl =
        Shader::glsl("float falloff(float d, float r0, float r1) { return 1.0 - smoothstep(r0, r1, d); }");
    match check().run_browser(&device, &glsl, &config()) {
        Err(Error::Setup(message)) => assert!(message.contains("WebGPU takes WGSL"), "{message}"),
        Err(other) => panic!("expected a setup error, got {other}"),
        Ok(report) => panic!("expected a refusal, got {report}"),
    }
}

/// An executable that is not there is a setup error naming the path and what to install, at once.
#[test]
fn a_missing_chromium_is_named_with_what_to_install() {
    let options = ChromiumOptions {
        executable: Some("/nonexistent/chromium".into()),
        ..ChromiumOptions::default()
    };
    let started = Instant::now();
    match BrowserDevice::with_options(&options) {
        Err(Error::Setup(message)) => {
            assert!(
                message.contains("no Chromium at /nonexistent/chromium"),
                "{message}"
            );
            assert!(message.contains("apt-get install chromium"), "{message}");
        }
        Err(other) => panic!("expected a setup error, got {other}"),
        Ok(_) => panic!("a Chromium started from /nonexistent/chromium"),
    }
    assert!(started.elapsed() < Duration::from_secs(1));
}

/// An executable that runs but never answers on the DevTools pipe fails after the start timeout,
/// however long the timeout for pages is.
#[test]
fn a_chromium_that_never_answers_times_out() {
    let silent = std::env::temp_dir().join(format!("shader-proptest-silent-{}", std::process::id()));
    std::fs::write(&silent, "#!/bin/sh\nexec sleep 30\n").expect("a script");
    std::fs::set_permissions(&silent, std::os::unix::fs::PermissionsExt::from_mode(0o755)).expect("mode");
    let start_timeout = Duration::from_secs(1);
    let options = ChromiumOptions {
        executable: Some(silent.clone()),
        start_timeout,
        timeout: Duration::from_secs(60),
    };
    let started = Instant::now();
    let launched = Chromium::launch(&options);
    let waited = started.elapsed();
    std::fs::remove_file(&silent).expect("the script removed");
    match launched {
        Err(Error::Browser(message)) => {
            assert!(
                message.contains("did not answer over its DevTools pipe within 1.0 s"),
                "{message}"
            )
        }
        Err(other) => panic!("expected a browser error, got {other}"),
        Ok(_) => panic!("a script that only sleeps started as Chromium"),
    }
    assert!(
        waited >= start_timeout && waited < 10 * start_timeout,
        "waited {waited:?}"
    );
}

/// A page whose script never answers fails after the timeout, naming the script.
#[test]
fn a_page_that_never_answers_times_out() {
    let timeout = Duration::from_secs(2);
    let options = ChromiumOptions {
        timeout,
        ..ChromiumOptions::default()
    };
    let server = LoopbackServer::start(0, |_| Response::ok("text/html", "<p>a page</p>")).expect("a server");
    let chromium = Chromium::launch(&options).unwrap_or_else(|error| panic!("{error}"));
    let page = chromium
        .open(&server.url("/"))
        .unwrap_or_else(|error| panic!("{error}"));
    let started = Instant::now();
    match page.evaluate("new Promise(() => {})") {
        Err(Error::Browser(message)) => assert!(message.contains("did not answer"), "{message}"),
        Err(other) => panic!("expected a browser error, got {other}"),
        Ok(value) => panic!("a promise that never resolves answered {value}"),
    }
    let waited = started.elapsed();
    assert!(waited >= timeout && waited < 3 * timeout, "waited {waited:?}");
}

/// A page whose server never answers fails to open after the timeout.
#[test]
fn a_page_that_never_loads_times_out() {
    let timeout = Duration::from_secs(2);
    let options = ChromiumOptions {
        timeout,
        ..ChromiumOptions::default()
    };
    let server = LoopbackServer::start(0, |_| {
        std::thread::sleep(Duration::from_secs(20));
        Response::no_content()
    })
    .expect("a server");
    let chromium = Chromium::launch(&options).unwrap_or_else(|error| panic!("{error}"));
    let started = Instant::now();
    match chromium.open(&server.url("/")) {
        Err(Error::Browser(message)) => assert!(message.contains("loading"), "{message}"),
        Err(other) => panic!("expected a browser error, got {other}"),
        Ok(_) => panic!("a page that never arrives opened"),
    }
    assert!(started.elapsed() < 3 * timeout, "waited {:?}", started.elapsed());
}

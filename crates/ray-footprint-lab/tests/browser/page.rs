//! The demo page in headless Chromium: each mode renders with no WebGPU message, and its
//! screenshot is compared with FLIP against the same shader, texture, camera and mode rendered by
//! the lab through wgpu on lavapipe (naga and lavapipe against Tint and SwiftShader).

use super::browser_options;
use ray_footprint_lab::demo::{render_with_wgpu, serve, DemoMode, IMAGE_SIZE, PAGE_PATH};
use ray_footprint_lab::figure::write_png;
use ray_footprint_lab::quality::image::Image;
use ray_footprint_lab::quality::metrics::flip;
use shader_proptest::{BrowserPage, Chromium};

/// Largest mean FLIP between the page's screenshot and lavapipe's image, per mode, in
/// [`DemoMode::ALL`]'s order.
///
/// Where the shader names the mip level (`textureSampleLevel`: mip 0, cone, wireframe) the two
/// implementations measured 0.0026 to 0.0042 apart, from their trilinear filters' rounding; 0.01
/// keeps a margin and stays under a tenth of the nearest other mode (0.137 between mip 0 and cone
/// on lavapipe), so a page that shows the wrong mode, texture or camera fails. The anisotropic
/// mode samples with gradients (`textureSampleGrad`), whose footprint filter each implementation
/// chooses: lavapipe's image is its cone image (it filters the ellipse's major axis
/// isotropically) and SwiftShader's is sharper at grazing angles, 0.04 apart; 0.05 is under half
/// the distance from the cone to mip 0, the nearest mode of another footprint.
const MAX_FLIP: [f64; 4] = [0.01, 0.01, 0.05, 0.01];

/// The canvas as the page shows it, from a screenshot.
fn canvas_image(page: &BrowserPage) -> Image {
    // The canvas scrolled to the viewport's top, where all of it shows; its place there.
    let rect = page
        .evaluate(
            "(canvas => { canvas.scrollIntoView(); const { x, y } = canvas.getBoundingClientRect(); \
             return [x, y, window.devicePixelRatio]; })(document.getElementById('image'))",
        )
        .unwrap_or_else(|error| panic!("{error}"));
    let [left, top, ratio] = [0, 1, 2].map(|i| rect[i].as_f64().expect("a number"));
    assert_eq!(
        ratio, 1.0,
        "the screenshot's pixels are the canvas's only at a device pixel ratio of 1"
    );
    let [left, top] = [left, top].map(|at| at.round() as usize);
    let png = page.screenshot().unwrap_or_else(|error| panic!("{error}"));
    let decoder = png::Decoder::new(std::io::Cursor::new(png));
    let mut reader = decoder.read_info().expect("a PNG");
    let mut pixels = vec![0; reader.output_buffer_size().expect("a size")];
    let info = reader.next_frame(&mut pixels).expect("a frame");
    let channels = info.color_type.samples();
    let [width, height] = IMAGE_SIZE;
    assert!(
        left + width as usize <= info.width as usize && top + height as usize <= info.height as usize,
        "the canvas ({width} x {height} at {left}, {top}) is not all in the {} x {} screenshot",
        info.width,
        info.height
    );
    let pixels = (0..height as usize)
        .flat_map(|y| (0..width as usize).map(move |x| (x, y)))
        .map(|(x, y)| {
            let at = ((top + y) * info.width as usize + left + x) * channels;
            [0, 1, 2].map(|c| f32::from(pixels[at + c]) / 255.0)
        })
        .collect();
    Image {
        width,
        height,
        pixels,
    }
}

#[test]
fn each_mode_matches_lavapipe() {
    let server = serve(0).unwrap_or_else(|error| panic!("{error}"));
    let chromium = Chromium::launch(&browser_options()).unwrap_or_else(|error| panic!("{error}"));
    let page = chromium
        .open(&server.url(PAGE_PATH))
        .unwrap_or_else(|error| panic!("{error}"));
    println!(
        "the page in {}, against lavapipe through wgpu (mean FLIP, at most)",
        chromium.version()
    );
    let folder = std::path::Path::new(env!("CARGO_TARGET_TMPDIR")).join("demo");
    std::fs::create_dir_all(&folder).expect("a folder for the images");
    println!(
        "each mode's images: {}/<mode>_{{chromium,lavapipe}}.png",
        folder.display()
    );
    let mut images = Vec::new();
    let mut over = Vec::new();
    for (mode, max) in DemoMode::ALL.into_iter().zip(MAX_FLIP) {
        let messages = page
            .evaluate(&format!("demo.render('{}')", mode.name()))
            .unwrap_or_else(|error| panic!("{}: {error}", mode.name()));
        assert!(
            messages.as_array().is_some_and(Vec::is_empty),
            "WebGPU messages in mode {}: {messages}",
            mode.name()
        );
        let browser = canvas_image(&page);
        let lavapipe = render_with_wgpu(mode).unwrap_or_else(|error| panic!("{}: {error}", mode.name()));
        for (image, name) in [(&browser, "chromium"), (&lavapipe, "lavapipe")] {
            let path = folder.join(format!("{}_{name}.png", mode.name()));
            write_png(&path, &image.to_rgba()).unwrap_or_else(|error| panic!("{}: {error}", path.display()));
        }
        let mean = flip(&lavapipe, &browser).expect("same sizes").mean();
        println!("{:<18} {mean:.4} (at most {max})", mode.name());
        if mean > max {
            over.push(format!("{}: {mean:.4} > {max}", mode.name()));
        }
        images.push((browser, lavapipe));
    }
    let between = |a: &Image, b: &Image| flip(a, b).expect("same sizes").mean();
    let [cone, anisotropic] = [1, 2].map(|i| &images[i]);
    println!(
        "cone against anisotropic cone: {:.4} in the page, {:.4} on lavapipe",
        between(&cone.0, &anisotropic.0),
        between(&cone.1, &anisotropic.1)
    );
    assert!(
        over.is_empty(),
        "the page differs from lavapipe: {}",
        over.join(", ")
    );
}

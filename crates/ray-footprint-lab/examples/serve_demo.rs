//! Serves the WebGPU demo page (`web/`) and the crate's WGSL modules on loopback, until stopped:
//! `cargo run -p ray-footprint-lab --features browser --example serve_demo [-- --port N]`, then
//! open the printed address in a browser with WebGPU.

use ray_footprint_lab::demo::{serve, PAGE_PATH};

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let arguments: Vec<String> = std::env::args().skip(1).collect();
    let port = match arguments.as_slice() {
        [] => 8080,
        [flag, port] if flag == "--port" => port
            .parse()
            .map_err(|_| format!("--port {port:?}: expected a port number (0 to 65535)"))?,
        other => return Err(format!("unexpected arguments {other:?}; usage: serve_demo [--port N]").into()),
    };
    let server = serve(port)?;
    println!("the demo: {}", server.url(PAGE_PATH));
    println!("serving 127.0.0.1 only; Ctrl-C stops it");
    loop {
        std::thread::park();
    }
}

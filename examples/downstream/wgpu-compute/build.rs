//! Links `src/shaders/lod.wesl` with ray-footprint's WESL package, as wesl's documentation says:
//! the package added to the compiler, the shader compiled into `OUT_DIR/lod.wgsl`.

fn main() {
    let mut compiler = wesl::Wesl::new("src/shaders");
    compiler.add_package(&ray_footprint::wesl::PACKAGE);
    compiler.build_artifact(&"package::lod".parse().expect("a module path"), "lod");
}

// The user's kernel with the modules pasted in front (ray_footprint::wgpu::shader_with_modules):
// texture LOD and world footprint of a pinhole camera's ray cone hitting a ground plane.
@group(0) @binding(0) var<storage, read> cases: array<vec4<f32>>; // t, fov_y, image height, |cos|
@group(0) @binding(1) var<storage, read_write> results: array<vec2<f32>>; // footprint, LOD

@compute @workgroup_size(64)
fn main(@builtin(global_invocation_id) id: vec3<u32>) {
    if id.x >= arrayLength(&results) {
        return;
    }
    let input = cases[id.x];
    let cone = rf_pinhole_ray_cone(rf_pixel_spread_angle(input.y, input.z));
    let direction = vec3<f32>(sqrt(1.0 - input.w * input.w), -input.w, 0.0);
    let normal = vec3<f32>(0.0, 1.0, 0.0);
    let footprint = rf_world_footprint(cone, input.x, normal, direction);
    let lod = rf_texture_lod(0.0, rf_width_at(cone, input.x), vec2<f32>(1024.0), normal, direction);
    results[id.x] = vec2<f32>(footprint, lod);
}

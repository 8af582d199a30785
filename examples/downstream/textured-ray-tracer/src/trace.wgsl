// A small ray tracer in one compute shader: every pixel's rays (n x n per pixel, on a grid) tested
// against every triangle of the scene, the closest hit textured. The lines marked `cone LOD`
// are what texture LOD from ray cones adds to a tracer that samples mip 0.

struct Frame {
    origin: vec4<f32>,
    // The image plane, as in "Ray Tracing in One Weekend": its lower left corner and its two spans.
    lower_left: vec4<f32>,
    horizontal: vec4<f32>,
    vertical: vec4<f32>,
    size: vec2<u32>,
    // Rays per pixel along each axis.
    samples: u32,
    // 0: sample mip 0; 1: sample at the ray cone's level of detail.
    cone_lod: u32,
}

@group(0) @binding(0) var<uniform> frame: Frame;
@group(0) @binding(1) var<storage, read> positions: array<vec4<f32>>;
@group(0) @binding(2) var<storage, read> uvs: array<vec2<f32>>;
@group(0) @binding(3) var albedo: texture_2d<f32>;
@group(0) @binding(4) var albedo_sampler: sampler;
@group(0) @binding(5) var<storage, read_write> colours: array<vec4<f32>>;

const SKY: vec3<f32> = vec3<f32>(0.55, 0.7, 0.9);

// (t, u, v) of the ray's hit with triangle p0 p1 p2 (Moller-Trumbore), t < 0 where it misses.
fn intersect(origin: vec3<f32>, direction: vec3<f32>, p0: vec3<f32>, p1: vec3<f32>, p2: vec3<f32>) -> vec3<f32> {
    let e1 = p1 - p0;
    let e2 = p2 - p0;
    let q = cross(direction, e2);
    let determinant = dot(e1, q);
    if abs(determinant) < 1e-12 {
        return vec3<f32>(-1.0, 0.0, 0.0);
    }
    let s = (origin - p0) / determinant;
    let u = dot(s, q);
    let r = cross(s, e1);
    let v = dot(direction, r);
    if u < 0.0 || v < 0.0 || u + v > 1.0 {
        return vec3<f32>(-1.0, 0.0, 0.0);
    }
    return vec3<f32>(dot(e2, r), u, v);
}

// The colour the ray sees: the closest triangle's texture, or the sky.
fn shade(origin: vec3<f32>, direction: vec3<f32>) -> vec3<f32> {
    var closest = vec3<f32>(1e30, 0.0, 0.0);
    var triangle = 0xffffffffu;
    for (var i = 0u; i < arrayLength(&positions) / 3u; i++) {
        let hit = intersect(origin, direction, positions[3u * i].xyz, positions[3u * i + 1u].xyz, positions[3u * i + 2u].xyz);
        if hit.x > 0.0 && hit.x < closest.x {
            closest = hit;
            triangle = i;
        }
    }
    if triangle == 0xffffffffu {
        return SKY;
    }
    let uv0 = uvs[3u * triangle];
    let uv1 = uvs[3u * triangle + 1u];
    let uv2 = uvs[3u * triangle + 2u];
    let uv = (1.0 - closest.y - closest.z) * uv0 + closest.y * uv1 + closest.z * uv2;
    let p0 = positions[3u * triangle].xyz; // cone LOD
    let p1 = positions[3u * triangle + 1u].xyz; // cone LOD
    let p2 = positions[3u * triangle + 2u].xyz; // cone LOD
    let centre = frame.lower_left.xyz + 0.5 * (frame.horizontal.xyz + frame.vertical.xyz); // cone LOD
    let spread = rf_pixel_spread_angle_from_image_plane(length(frame.vertical.xyz), length(centre - frame.origin.xyz), f32(frame.size.y)); // cone LOD
    let lod = rf_hit_texture_lod(rf_pinhole_ray_cone(spread), direction, closest.x, p0, p1, p2, uv0, uv1, uv2, vec2<f32>(textureDimensions(albedo))); // cone LOD
    return textureSampleLevel(albedo, albedo_sampler, uv, select(0.0, lod, frame.cone_lod != 0u)).rgb; // cone LOD
}

@compute @workgroup_size(8, 8)
fn main(@builtin(global_invocation_id) id: vec3<u32>) {
    if id.x >= frame.size.x || id.y >= frame.size.y {
        return;
    }
    let n = frame.samples;
    var sum = vec3<f32>(0.0);
    for (var sy = 0u; sy < n; sy++) {
        for (var sx = 0u; sx < n; sx++) {
            let s = (f32(id.x) + (f32(sx) + 0.5) / f32(n)) / f32(frame.size.x);
            let t = 1.0 - (f32(id.y) + (f32(sy) + 0.5) / f32(n)) / f32(frame.size.y);
            let aim = frame.lower_left.xyz + s * frame.horizontal.xyz + t * frame.vertical.xyz;
            sum += shade(frame.origin.xyz, normalize(aim - frame.origin.xyz));
        }
    }
    colours[id.y * frame.size.x + id.x] = vec4<f32>(sum / f32(n * n), 1.0);
}

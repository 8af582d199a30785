// The browser demo's scene, rendered by compute: a textured ground plane (y = 0) under a mirror
// sphere, one invocation per pixel, in one of four modes. Placed after ray_cone.wgsl,
// ray_diff.wgsl and wireframe.wgsl, as the crate ships them; the page (index.html) and the lab
// (src/demo.rs, through wgpu) run this same text.
//
// Entry points: texture_level0 writes the ground texture's level 0, texture_downsample each next
// level from the one above (a 2 x 2 box filter), render the image.

struct DemoParams {
    // MODE_MIP0, MODE_CONE, MODE_ANISOTROPIC or MODE_WIREFRAME.
    mode: u32,
    pad0: u32,
    pad1: u32,
    pad2: u32,
}

@group(0) @binding(0) var<uniform> params: DemoParams;
@group(0) @binding(1) var ground_texture: texture_2d<f32>;
@group(0) @binding(2) var ground_sampler: sampler;
@group(0) @binding(3) var image: texture_storage_2d<rgba8unorm, write>;
@group(0) @binding(4) var level_out: texture_storage_2d<rgba8unorm, write>;
@group(0) @binding(5) var level_in: texture_2d<f32>;

// Mip 0 everywhere: what a ray tracer samples without a footprint.
const MODE_MIP0: u32 = 0u;
// The ray cone's LOD (rf_texture_lod), carried through the mirror with its curvature.
const MODE_CONE: u32 = 1u;
// The cone's elliptical footprint as textureSampleGrad gradients (rf_anisotropic_cone_gradients).
const MODE_ANISOTROPIC: u32 = 2u;
// MODE_CONE with the ground's triangles drawn anti-aliased (rf_process_wireframe).
const MODE_WIREFRAME: u32 = 3u;

const EYE: vec3<f32> = vec3<f32>(0.0, 1.1, 5.5);
const LOOK_AT: vec3<f32> = vec3<f32>(0.0, 0.7, 0.0);
// Vertical field of view, radians.
const FOV_Y: f32 = 0.9;
const SPHERE_CENTRE: vec3<f32> = vec3<f32>(0.0, 1.0, 0.0);
const SPHERE_RADIUS: f32 = 1.0;
// The mirror's reflectance.
const MIRROR: vec3<f32> = vec3<f32>(0.85, 0.85, 0.9);
// World units per repeat of the ground texture.
const TEXTURE_TILE: f32 = 2.0;
// The ground's triangles: squares of this side split along their diagonal.
const CELL: f32 = 1.0;
const SKY: vec3<f32> = vec3<f32>(0.62, 0.75, 0.92);
const WIRE: vec3<f32> = vec3<f32>(0.05, 0.05, 0.08);
// No hit.
const FAR: f32 = 1.0e30;

// Level 0 of the ground texture: 32-texel squares of two colours, each a 4-texel checker of two
// shades of its colour.
@compute @workgroup_size(8, 8)
fn texture_level0(@builtin(global_invocation_id) id: vec3<u32>) {
    if any(id.xy >= textureDimensions(level_out)) {
        return;
    }
    let large = ((id.x / 32u) + (id.y / 32u)) % 2u;
    let small = ((id.x / 4u) + (id.y / 4u)) % 2u;
    let colour = select(vec3<f32>(0.85, 0.55, 0.2), vec3<f32>(0.2, 0.45, 0.8), large == 1u);
    let shade = select(1.0, 0.55, small == 1u);
    textureStore(level_out, id.xy, vec4<f32>(colour * shade, 1.0));
}

// The next level: each texel the mean of the 2 x 2 texels above it.
@compute @workgroup_size(8, 8)
fn texture_downsample(@builtin(global_invocation_id) id: vec3<u32>) {
    if any(id.xy >= textureDimensions(level_out)) {
        return;
    }
    let above = 2u * id.xy;
    let sum = textureLoad(level_in, above, 0) + textureLoad(level_in, above + vec2<u32>(1u, 0u), 0)
        + textureLoad(level_in, above + vec2<u32>(0u, 1u), 0) + textureLoad(level_in, above + vec2<u32>(1u, 1u), 0);
    textureStore(level_out, id.xy, 0.25 * sum);
}

// Distance along the ray to the sphere's front, or FAR.
fn hit_sphere(origin: vec3<f32>, direction: vec3<f32>) -> f32 {
    let offset = origin - SPHERE_CENTRE;
    let b = dot(offset, direction);
    let c = dot(offset, offset) - SPHERE_RADIUS * SPHERE_RADIUS;
    let discriminant = b * b - c;
    let t = -b - sqrt(max(discriminant, 0.0));
    return select(FAR, t, discriminant >= 0.0 && t > 1.0e-4);
}

// Distance along the ray to the ground, or FAR.
fn hit_ground(origin: vec3<f32>, direction: vec3<f32>) -> f32 {
    let t = -origin.y / direction.y;
    return select(FAR, t, direction.y < 0.0 && t > 0.0);
}

// The ground's triangle under a point: its vertices (world) and barycentrics.
struct GroundTriangle {
    p0: vec3<f32>,
    p1: vec3<f32>,
    p2: vec3<f32>,
    barycentrics: vec3<f32>,
}

fn ground_triangle(point: vec3<f32>) -> GroundTriangle {
    let corner = floor(point.xz / CELL);
    let local = point.xz / CELL - corner;
    let p0 = vec3<f32>(corner.x, 0.0, corner.y) * CELL;
    let p2 = vec3<f32>(corner.x + 1.0, 0.0, corner.y + 1.0) * CELL;
    if local.x >= local.y {
        let p1 = vec3<f32>(corner.x + 1.0, 0.0, corner.y) * CELL;
        return GroundTriangle(p0, p1, p2, vec3<f32>(1.0 - local.x, local.x - local.y, local.y));
    }
    let p1 = vec3<f32>(corner.x, 0.0, corner.y + 1.0) * CELL;
    return GroundTriangle(p0, p1, p2, vec3<f32>(1.0 - local.y, local.y - local.x, local.x));
}

// Texture coordinates of a ground point.
fn ground_uv(point: vec3<f32>) -> vec2<f32> {
    return point.xz / TEXTURE_TILE;
}

// The ground's colour where a ray with `cone` at its origin meets it at distance t.
fn shade_ground(point: vec3<f32>, t: f32, cone: RfRayCone, direction: vec3<f32>) -> vec3<f32> {
    let normal = vec3<f32>(0.0, 1.0, 0.0);
    let triangle = ground_triangle(point);
    let uv = ground_uv(point);
    let uv0 = ground_uv(triangle.p0);
    let uv1 = ground_uv(triangle.p1);
    let uv2 = ground_uv(triangle.p2);
    let width = rf_width_at(cone, t);
    if params.mode == MODE_MIP0 {
        return textureSampleLevel(ground_texture, ground_sampler, uv, 0.0).rgb;
    }
    if params.mode == MODE_ANISOTROPIC {
        let gradients = rf_anisotropic_cone_gradients(width, direction, triangle.p0, triangle.p1, triangle.p2, uv0, uv1, uv2);
        return textureSampleGrad(ground_texture, ground_sampler, uv, gradients.dx, gradients.dy).rgb;
    }
    let base_lod = rf_triangle_base_lod(triangle.p0, triangle.p1, triangle.p2, uv0, uv1, uv2);
    let size = vec2<f32>(textureDimensions(ground_texture));
    let lod = rf_texture_lod(base_lod, width, size, normal, direction);
    let colour = textureSampleLevel(ground_texture, ground_sampler, uv, lod).rgb;
    if params.mode != MODE_WIREFRAME {
        return colour;
    }
    let footprint = rf_world_footprint(cone, t, normal, direction);
    let deltas = rf_cone_barycentric_deltas(footprint, triangle.p0, triangle.p1, triangle.p2);
    let coverage = rf_process_wireframe(RF_WIREFRAME_DEFAULT, triangle.barycentrics, deltas);
    return mix(colour, WIRE, coverage);
}

// The colour seen along a primary ray: the ground, the sky, or either in the mirror sphere, whose
// curvature widens the reflected cone (rf_curvature_spread_angle, curvature 1 / radius).
fn trace(direction: vec3<f32>, primary_cone: RfRayCone) -> vec3<f32> {
    var origin = EYE;
    var ray = direction;
    var cone = primary_cone;
    var weight = vec3<f32>(1.0);
    let t_sphere = hit_sphere(origin, ray);
    if t_sphere < hit_ground(origin, ray) {
        let point = origin + t_sphere * ray;
        let normal = (point - SPHERE_CENTRE) / SPHERE_RADIUS;
        let spread = rf_curvature_spread_angle(1.0 / SPHERE_RADIUS, rf_width_at(cone, t_sphere), normal, ray);
        cone = rf_propagate(cone, t_sphere, spread);
        origin = point;
        ray = reflect(ray, normal);
        weight = MIRROR;
    }
    let t_ground = hit_ground(origin, ray);
    if t_ground == FAR {
        return weight * SKY;
    }
    return weight * shade_ground(origin + t_ground * ray, t_ground, cone, ray);
}

@compute @workgroup_size(8, 8)
fn render(@builtin(global_invocation_id) id: vec3<u32>) {
    let size = textureDimensions(image);
    if any(id.xy >= size) {
        return;
    }
    let forward = normalize(LOOK_AT - EYE);
    let right = normalize(cross(forward, vec3<f32>(0.0, 1.0, 0.0)));
    let up = cross(right, forward);
    let half_height = tan(0.5 * FOV_Y);
    let pixel = (vec2<f32>(id.xy) + 0.5) / vec2<f32>(size) * 2.0 - 1.0;
    let aspect = f32(size.x) / f32(size.y);
    let direction = normalize(forward + pixel.x * half_height * aspect * right - pixel.y * half_height * up);
    let cone = rf_pinhole_ray_cone_for_ray(rf_pixel_spread_angle(FOV_Y, f32(size.y)), direction, forward);
    textureStore(image, id.xy, vec4<f32>(trace(direction, cone), 1.0));
}

// ray-footprint ray-tracing renderer, WGSL path: a compute shader that traces each pixel's primary
// ray with a ray query (naga's `wgpu_ray_query`) over the renderer's acceleration structures and
// records the same per-pixel values as the GLSL closest-hit shader (rt_common.glsl), computed with
// the WGSL ray_cone, ray_diff and wireframe modules. naga gives no barycentrics to a WGSL
// closest-hit shader yet; a ray query's committed intersection has them.
//
// The renderer compiles `enable wgpu_ray_query;`, then shaders/wgsl/ray_cone.wgsl, ray_diff.wgsl
// and wireframe.wgsl, then this file.

// Floats per vertex: position xyz, u, normal xyz, v (VERTEX_FLOATS in scene.rs).
const RT_VERTEX_FLOATS: u32 = 8u;
// Farthest hit distance.
const RT_MAX_DISTANCE: f32 = 1.0e4;
// Materials and the mesh table (the twins of rt_common.glsl's).
const RT_MATERIAL_MIRROR: u32 = 1u;
const RT_MATERIAL_GLASS: u32 = 2u;
const RT_MESH_TABLE_WORDS: u32 = 4u;

// Push constants (Rust mirror: ray_footprint_lab::rt::abi::RtPushConstants, 96 bytes).
struct RtPushConstants {
    eye: vec3<f32>,
    tan_half_fov_y: f32,
    right: vec3<f32>,
    aspect: f32,
    up: vec3<f32>,
    texture_size: f32,
    forward: vec3<f32>,
    mode: u32,
    cone: RfRayConePushConstants,
    width: u32,
    height: u32,
    pixel_offset: vec2<f32>,
    flags: u32,
    pad: u32,
}

// The ray-differential, re-intersection and wireframe values of a primary hit (Rust mirror:
// ray_footprint_lab::rt::abi::RtDiffRecord, 176 bytes; the field docs are there).
struct RtDiffRecord {
    eye_d_direction_dx: vec3<f32>,
    lod: f32,
    eye_d_direction_dy: vec3<f32>,
    offset_lod: f32,
    barycentric_dx: vec2<f32>,
    barycentric_dy: vec2<f32>,
    uv_dx: vec2<f32>,
    uv_dy: vec2<f32>,
    neighbour_right: vec3<f32>,
    coverage: f32,
    neighbour_below: vec3<f32>,
    pad0: u32,
    offset_dx: vec3<f32>,
    pad1: u32,
    offset_dy: vec3<f32>,
    pad2: u32,
    offset_uv_dx: vec2<f32>,
    offset_uv_dy: vec2<f32>,
    deltas: vec3<f32>,
    pad3: u32,
    cone_deltas: vec3<f32>,
    pad4: u32,
}

// What a primary hit measured (Rust mirror: ray_footprint_lab::rt::abi::RtPixelRecord, 320 bytes).
struct RtPixelRecord {
    normal: vec3<f32>,
    t: f32,
    direction: vec3<f32>,
    instance: u32,
    barycentrics: vec2<f32>,
    primitive: u32,
    hit: u32,
    cone: RfRayCone,
    width: f32,
    footprint: f32,
    texel_density: f32,
    base_lod: f32,
    lod: f32,
    gradient: f32,
    curvature: f32,
    curvature_spread: f32,
    reflected: RfRayCone,
    diff: RtDiffRecord,
    roughness_spread: f32,
    eta: f32,
    normal_spread: f32,
    total_internal_reflection: u32,
    refracted: RfRayCone,
    cone_uv_dx: vec2<f32>,
    cone_uv_dy: vec2<f32>,
    pad: vec2<u32>,
}

// Per-frame uniforms (Rust mirror: ray_footprint_lab::rt::abi::RtUniforms, 176 bytes): inverse view and
// projection matrices, wireframe colour and settings.
struct RtUniforms {
    view_inv: mat4x4<f32>,
    proj_inv: mat4x4<f32>,
    wireframe: RfWireframePushConstants,
}

// A triangle's vertices.
struct RtTriangle {
    p: array<vec3<f32>, 3>,
    n: array<vec3<f32>, 3>,
    uv: array<vec2<f32>, 3>,
}

var<immediate> pc: RtPushConstants;
@group(0) @binding(0) var rt_scene: acceleration_structure;
@group(0) @binding(1) var<storage, read> rt_vertices: array<f32>;
@group(0) @binding(2) var<storage, read> rt_indices: array<u32>;
@group(0) @binding(3) var<storage, read> rt_meshes: array<u32>;
@group(0) @binding(4) var<storage, read_write> rt_records: array<RtPixelRecord>;
@group(0) @binding(7) var<uniform> rt_frame: RtUniforms;

// Triangle `primitive` of mesh `mesh`, from the vertex, index and mesh-table buffers.
fn rt_triangle(mesh: u32, primitive: u32) -> RtTriangle {
    let first_index = rt_meshes[RT_MESH_TABLE_WORDS * mesh] + 3u * primitive;
    let first_vertex = rt_meshes[RT_MESH_TABLE_WORDS * mesh + 1u];
    var tri: RtTriangle;
    for (var k = 0u; k < 3u; k++) {
        let f = (first_vertex + rt_indices[first_index + k]) * RT_VERTEX_FLOATS;
        tri.p[k] = vec3<f32>(rt_vertices[f], rt_vertices[f + 1u], rt_vertices[f + 2u]);
        tri.n[k] = vec3<f32>(rt_vertices[f + 4u], rt_vertices[f + 5u], rt_vertices[f + 6u]);
        tri.uv[k] = vec2<f32>(rt_vertices[f + 3u], rt_vertices[f + 7u]);
    }
    return tri;
}

// Barycentric weights (1 - u - v, u, v).
fn rt_weights(barycentrics: vec2<f32>) -> vec3<f32> {
    return vec3<f32>(1.0 - barycentrics.x - barycentrics.y, barycentrics.x, barycentrics.y);
}

// Unit direction of the primary ray through `pixel`, offset from its centre by pc.pixel_offset.
fn rt_primary_direction(pixel: vec2<u32>) -> vec3<f32> {
    let c = 2.0 * (vec2<f32>(pixel) + 0.5 + pc.pixel_offset) / vec2<f32>(f32(pc.width), f32(pc.height)) - 1.0;
    return normalize(pc.forward + c.x * pc.aspect * pc.tan_half_fov_y * pc.right
        - c.y * pc.tan_half_fov_y * pc.up);
}

// Every ray-cone value of a hit on a mesh of material `material` with parameter `parameter`, the
// material's values and the anisotropic cone gradients (the twin of rt_measure in rt_common.glsl;
// the ray-differential values are rt_measure_diff's).
fn rt_measure(tri: RtTriangle, material: u32, parameter: f32, barycentrics: vec2<f32>, t: f32, direction: vec3<f32>,
        cone: RfRayCone) -> RtPixelRecord {
    let w = rt_weights(barycentrics);
    let normal = normalize(w.x * tri.n[0] + w.y * tri.n[1] + w.z * tri.n[2]);
    let width = rf_width_at(cone, t);
    let footprint = rf_world_footprint(cone, t, normal, direction);
    let density = rf_texel_density(tri.p[0], tri.p[1], tri.p[2], tri.uv[0], tri.uv[1], tri.uv[2]);
    let base_lod = rf_triangle_base_lod(tri.p[0], tri.p[1], tri.p[2], tri.uv[0], tri.uv[1], tri.uv[2]);
    let lod = rf_texture_lod(base_lod, width, vec2<f32>(pc.texture_size), normal, direction);
    let gradient = rf_texture_gradient(footprint * density, pc.cone.tex_grad_scale);
    let curvature = rf_triangle_curvature(tri.p[0], tri.p[1], tri.p[2], tri.n[0], tri.n[1], tri.n[2]);
    let spread = rf_curvature_spread_angle(curvature, width, normal, direction);
    let roughness_spread = select(0.0, rf_roughness_spread_angle(parameter), material == RT_MATERIAL_MIRROR);
    var record = RtPixelRecord();
    record.normal = normal;
    record.t = t;
    record.direction = direction;
    record.barycentrics = barycentrics;
    record.hit = 1u;
    record.cone = cone;
    record.width = width;
    record.footprint = footprint;
    record.texel_density = density;
    record.base_lod = base_lod;
    record.lod = lod;
    record.gradient = gradient;
    record.curvature = curvature;
    record.curvature_spread = spread;
    record.reflected = rf_propagate(cone, t, spread + 2.0 * roughness_spread);
    record.roughness_spread = roughness_spread;
    if material == RT_MATERIAL_GLASS {
        record.eta = select(parameter, 1.0 / parameter, dot(normal, direction) < 0.0);
        record.normal_spread = curvature * footprint;
        let refracted = rf_refract_ray_cone(rf_propagate(cone, t, 0.0), normal, direction, record.normal_spread,
            record.eta);
        record.total_internal_reflection = select(0u, 1u, refracted.total_internal_reflection);
        record.refracted = refracted.cone;
    }
    let cone_uv = rf_anisotropic_cone_gradients(width, direction, tri.p[0], tri.p[1], tri.p[2], tri.uv[0], tri.uv[1],
        tri.uv[2]);
    record.cone_uv_dx = cone_uv.dx;
    record.cone_uv_dy = cone_uv.dy;
    return record;
}

// The isotropic LOD (RTG Eq. 1-2) of UV gradients scaled to texels (the size is a power of two).
fn rt_texel_lod(uv: RfDerivatives2) -> f32 {
    return rf_lod_isotropic(RfDerivatives2(uv.dx * pc.texture_size, uv.dy * pc.texture_size));
}

// The ray-differential and wireframe values of a primary hit (the twin of rt_measure_diff in
// rt_common.glsl).
fn rt_measure_diff(tri: RtTriangle, barycentrics: vec2<f32>, t: f32, origin: vec3<f32>, direction: vec3<f32>,
        world_to_object: mat4x4<f32>, pixel: vec2<u32>, footprint: f32) -> RtDiffRecord {
    let xy = vec2<f32>(pixel) + pc.pixel_offset;
    let size = vec2<f32>(f32(pc.width), f32(pc.height));
    let eye = rf_eye_ray_diff_from_matrices(xy, size, rt_frame.view_inv, rt_frame.proj_inv);
    let bary = rf_barycentric_derivatives(eye, direction, t, tri.p[0], tri.p[1], tri.p[2]);
    let uv = rf_texture_derivatives(bary, tri.uv[0], tri.uv[1], tri.uv[2]);
    let next = rf_pixel_directions(xy, size, rt_frame.view_inv, rt_frame.proj_inv);
    let w = rt_weights(barycentrics);
    let offsets = rf_barycentric_offsets(world_to_object, origin, tri.p[0], tri.p[1], tri.p[2], next.right,
        next.below, w);
    let offset_uv = rf_uv_gradients_from_offsets(offsets, tri.uv[0], tri.uv[1], tri.uv[2]);
    let deltas = rf_barycentric_deltas(world_to_object, origin, tri.p[0], tri.p[1], tri.p[2], next.right,
        next.below, w);
    let coverage = rf_process_wireframe(rf_unpack_wireframe_settings(rt_frame.wireframe.settings), w, deltas);
    return RtDiffRecord(eye.d_direction_dx, rt_texel_lod(uv), eye.d_direction_dy, rt_texel_lod(offset_uv),
        bary.dx, bary.dy, uv.dx, uv.dy, next.right, coverage, next.below, 0u, offsets.dx, 0u, offsets.dy, 0u,
        offset_uv.dx, offset_uv.dy, deltas, 0u, rf_cone_barycentric_deltas(footprint, tri.p[0], tri.p[1], tri.p[2]),
        0u);
}

// A 4x3 matrix as a 4x4 one with the last row (0, 0, 0, 1), like GLSL's mat4(mat4x3).
fn rt_mat4(m: mat4x3<f32>) -> mat4x4<f32> {
    return mat4x4<f32>(vec4<f32>(m[0], 0.0), vec4<f32>(m[1], 0.0), vec4<f32>(m[2], 0.0), vec4<f32>(m[3], 1.0));
}

@compute @workgroup_size(8, 8)
fn main(@builtin(global_invocation_id) id: vec3<u32>) {
    if id.x >= pc.width || id.y >= pc.height {
        return;
    }
    let direction = rt_primary_direction(id.xy);
    let cone = rf_pinhole_ray_cone_for_ray(pc.cone.pixel_spread_angle, direction, pc.forward);
    var query: ray_query;
    rayQueryInitialize(&query, rt_scene, RayDesc(RAY_FLAG_FORCE_OPAQUE, 0xffu, 0.0, RT_MAX_DISTANCE, pc.eye, direction));
    while rayQueryProceed(&query) {}
    let hit = rayQueryGetCommittedIntersection(&query);
    var record = RtPixelRecord();
    record.direction = direction;
    record.cone = cone;
    if hit.kind == RAY_QUERY_INTERSECTION_TRIANGLE {
        let mesh = hit.instance_custom_data;
        let tri = rt_triangle(mesh, hit.primitive_index);
        let material = rt_meshes[RT_MESH_TABLE_WORDS * mesh + 2u];
        let parameter = bitcast<f32>(rt_meshes[RT_MESH_TABLE_WORDS * mesh + 3u]);
        record = rt_measure(tri, material, parameter, hit.barycentrics, hit.t, direction, cone);
        record.instance = hit.instance_custom_data;
        record.primitive = hit.primitive_index;
        record.diff = rt_measure_diff(tri, hit.barycentrics, hit.t, pc.eye, direction, rt_mat4(hit.world_to_object),
            id.xy, record.footprint);
    }
    rt_records[id.y * pc.width + id.x] = record;
}

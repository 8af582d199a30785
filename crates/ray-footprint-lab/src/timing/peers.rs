//! The peers' original functions beside the library's: which function of which peer file stands
//! against which library function, and the adapter that calls it with the library function's
//! parameters and result ([`PEERS`]). The peers' code is never part of this repository: it is
//! read at run time from a directory the user names, where each peer's file is found by its name
//! ([`PeerSource::find`]), and the items an adapter needs are cut out of it ([`extract`]).
//!
//! The adapters are ours: each takes the library function's arguments, builds what the peer's
//! function takes (a peer's struct, an array of vertices, a matrix in the peer's convention, a
//! face normal the library function computes inside), calls it, and returns the library
//! function's result type, so both run in the same timing loop
//! ([`super::function::timing_source`]).
//!
//! Five peers also have a *guarded* adapter ([`Peer::guarded_adapter`]): the same cut items,
//! called with the library's guards for degenerate input added around them (clamps of the
//! arguments before the call, arguments scaled so that no square overflows or underflows, a
//! select after it), so that where the defined behaviour is what a function costs, the peer with
//! that behaviour added shows it. Where a guard sits inside the peer's function, the guarded
//! kernel edits the cut items ([`Peer::guards_inside`], [`add_guards_inside`]): the peer's own
//! text, replaced by the same text with the guard added.

use std::path::{Path, PathBuf};

/// A peer's file.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PeerSource {
    /// Falcor's `Source/Falcor/Rendering/Materials/TexLODHelpers.slang` (NVIDIA): ray cones and
    /// ray differentials.
    FalcorTexLod,
    /// nvpro's `wireframe.h.slang` (`nvpro_core2/nvshaders`), or the copy of its functions in the
    /// vk_raytracing_tutorial_KHR's `raytrace_tutorial/20_wireframe/shaders/wireframe_helpers.h.slang`.
    NvproWireframe,
    /// The vk_raytracing_tutorial_KHR's ray-cone helpers,
    /// `raytrace_tutorial/19_ray_differentials/shaders/rtraydifferentials.slang`.
    TutorialRayCones,
}

impl PeerSource {
    /// The file names the source goes by, in order of preference.
    pub fn file_names(self) -> &'static [&'static str] {
        match self {
            PeerSource::FalcorTexLod => &["TexLODHelpers.slang"],
            PeerSource::NvproWireframe => &["wireframe.h.slang", "wireframe_helpers.h.slang"],
            PeerSource::TutorialRayCones => &["rtraydifferentials.slang"],
        }
    }

    /// A short name for tables.
    pub fn name(self) -> &'static str {
        match self {
            PeerSource::FalcorTexLod => "Falcor TexLODHelpers",
            PeerSource::NvproWireframe => "nvpro wireframe",
            PeerSource::TutorialRayCones => "vk_raytracing_tutorial ray cones",
        }
    }

    /// The first file under `dir` (searched depth first, in name order) with one of the source's
    /// names, or `None`.
    pub fn find(self, dir: &Path) -> Option<PathBuf> {
        self.file_names().iter().find_map(|name| find_file(dir, name))
    }
}

/// The first file called `name` under `dir`, depth first in name order; hidden folders skipped.
fn find_file(dir: &Path, name: &str) -> Option<PathBuf> {
    let mut entries: Vec<PathBuf> = std::fs::read_dir(dir).ok()?.flatten().map(|e| e.path()).collect();
    entries.sort();
    for path in &entries {
        if path.is_file() && path.file_name().is_some_and(|n| n == name) {
            return Some(path.clone());
        }
    }
    entries
        .iter()
        .filter(|path| {
            path.is_dir()
                && !path
                    .file_name()
                    .is_some_and(|n| n.to_string_lossy().starts_with('.'))
        })
        .find_map(|path| find_file(path, name))
}

/// A peer's function set against a library function.
#[derive(Clone, Copy, Debug)]
pub struct Peer {
    /// The library function (shader name).
    pub function: &'static str,
    /// The peer's file.
    pub source: PeerSource,
    /// The peer's items the adapter needs, each by how its declaration starts (white space
    /// folded): every declaration that starts so is taken, overloads included.
    pub items: &'static [&'static str],
    /// The adapter: `peer_<function>`, with the library function's parameters and result.
    pub adapter: &'static str,
    /// The guarded adapter, where there is one: `guarded_peer_<function>`, with the library
    /// function's parameters and result, calling the same items with the library function's
    /// guards added around them.
    pub guarded_adapter: Option<&'static str>,
    /// The library's guards that sit inside the peer's functions, added there for the guarded
    /// kernel: each `(peer's text, guarded text)` replaces the peer's text, which must occur once
    /// in the cut items ([`add_guards_inside`]).
    pub guards_inside: &'static [(&'static str, &'static str)],
}

/// Which of a peer's adapters a kernel calls.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum AdapterKind {
    /// [`Peer::adapter`]: the peer's original as it is.
    Plain,
    /// [`Peer::guarded_adapter`]: the peer's original with the library's guards added.
    Guarded,
}

impl AdapterKind {
    /// The adapter's name for the library function `function`.
    pub fn name(self, function: &str) -> String {
        match self {
            AdapterKind::Plain => format!("peer_{function}"),
            AdapterKind::Guarded => format!("guarded_peer_{function}"),
        }
    }
}

impl Peer {
    /// The adapter of `kind`, or `None` where the peer has no such adapter.
    pub fn adapter_of(&self, kind: AdapterKind) -> Option<&'static str> {
        match kind {
            AdapterKind::Plain => Some(self.adapter),
            AdapterKind::Guarded => self.guarded_adapter,
        }
    }
}

/// What each peer's original is timed against. An adapter's name is `peer_` and the library
/// function's, a guarded adapter's `guarded_peer_` and the library function's
/// ([`AdapterKind::name`]).
pub const PEERS: &[Peer] = &[
    Peer {
        function: "rf_propagate",
        source: PeerSource::FalcorTexLod,
        items: &["struct RayCone"],
        adapter: "RfRayCone peer_rf_propagate(RfRayCone cone, float t, float surface_spread_angle) {
    RayCone propagated = RayCone(cone.width, cone.spread_angle).propagateDistance(t).addToSpreadAngle(surface_spread_angle);
    return RfRayCone(propagated.getWidth(), propagated.getSpreadAngle());
}",
        guarded_adapter: None,
        guards_inside: &[],
    },
    Peer {
        function: "rf_curvature_spread_angle",
        source: PeerSource::FalcorTexLod,
        items: &["float computeSpreadAngleFromCurvatureIso("],
        adapter: "float peer_rf_curvature_spread_angle(float curvature, float width, float3 normal, float3 direction) {
    return computeSpreadAngleFromCurvatureIso(curvature, width, direction, normal);
}",
        guarded_adapter: None,
        guards_inside: &[],
    },
    Peer {
        function: "rf_world_footprint",
        source: PeerSource::TutorialRayCones,
        items: &["struct RayCone", "float rayConeWorldFootprint("],
        adapter: "float peer_rf_world_footprint(RfRayCone cone, float t, float3 normal, float3 direction) {
    RayCone peer = { cone.width, cone.spread_angle };
    return rayConeWorldFootprint(peer, t, normal, -direction);
}",
        guarded_adapter: None,
        guards_inside: &[],
    },
    Peer {
        function: "rf_texel_density",
        source: PeerSource::TutorialRayCones,
        items: &["float triangleTexelDensity("],
        adapter: "float peer_rf_texel_density(float3 p0, float3 p1, float3 p2, float2 uv0, float2 uv1, float2 uv2) {
    return triangleTexelDensity(p0, p1, p2, uv0, uv1, uv2);
}",
        // Ours scales the cross product by its largest component before `length`; here the cross
        // product is taken once more in the adapter for that scale (the peer takes it inside) and
        // one edge passed divided by it, so the peer's |cross| is within 1 to sqrt(3), and the
        // result scaled back by 1 / sqrt(scale). A world triangle whose cross product is below
        // RF_MIN_SQUARED_MAGNITUDE in every component passes a unit triangle, so its area counts
        // as RF_MIN_SQUARED_MAGNITUDE, as ours clamps it. Not addable from outside: the peer
        // clamps the UV area to at least 1e-20 (ours takes its root as it is, 0 for a degenerate
        // UV triangle).
        guarded_adapter: Some(
            "float guarded_peer_rf_texel_density(float3 p0, float3 p1, float3 p2, float2 uv0, float2 uv1, float2 uv2) {
    float3 edge01 = p1 - p0;
    float3 edge02 = p2 - p0;
    float3 normal = cross(edge01, edge02);
    float largest = max(max(abs(normal.x), abs(normal.y)), abs(normal.z));
    float scale = max(largest, RF_MIN_SQUARED_MAGNITUDE);
    bool flat = largest < RF_MIN_SQUARED_MAGNITUDE;
    float3 scaled01 = flat ? float3(1.0, 0.0, 0.0) : edge01 / scale;
    float3 scaled02 = flat ? float3(0.0, 1.0, 0.0) : edge02;
    return triangleTexelDensity(float3(0.0), scaled01, scaled02, uv0, uv1, uv2) * rsqrt(scale);
}",
        ),
        guards_inside: &[],
    },
    Peer {
        function: "rf_triangle_base_lod",
        source: PeerSource::FalcorTexLod,
        items: &["float computeRayConeTriangleLODValue(float3"],
        adapter: "float peer_rf_triangle_base_lod(float3 p0, float3 p1, float3 p2, float2 uv0, float2 uv1, float2 uv2) {
    float3 vertices[3] = { p0, p1, p2 };
    float2 txcoords[3] = { uv0, uv1, uv2 };
    return computeRayConeTriangleLODValue(vertices, txcoords, float3x3(1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0));
}",
        // The world edges as for rf_texel_density (one divided by the largest component of their
        // cross product, a unit triangle where that is below RF_MIN_SQUARED_MAGNITUDE), half the
        // scale's logarithm taken back out; the UV area computed in the adapter too, and a UV
        // triangle of area RF_MIN_SQUARED_MAGNITUDE passed where it is smaller, so the peer's
        // log2(Ta / Pa) is of a finite, nonzero quotient: ours clamps both areas to at least
        // RF_MIN_SQUARED_MAGNITUDE. The peer's quotient stays (its single logarithm); with both
        // areas kept in range it neither overflows nor underflows.
        guarded_adapter: Some(
            "float guarded_peer_rf_triangle_base_lod(float3 p0, float3 p1, float3 p2, float2 uv0, float2 uv1, float2 uv2) {
    float3 edge01 = p1 - p0;
    float3 edge02 = p2 - p0;
    float3 normal = cross(edge01, edge02);
    float largest = max(max(abs(normal.x), abs(normal.y)), abs(normal.z));
    float scale = max(largest, RF_MIN_SQUARED_MAGNITUDE);
    bool flat = largest < RF_MIN_SQUARED_MAGNITUDE;
    float3 vertices[3] = { float3(0.0), flat ? float3(1.0, 0.0, 0.0) : edge01 / scale,
        flat ? float3(0.0, 1.0, 0.0) : edge02 };
    float2 uv_edge1 = uv1 - uv0;
    float2 uv_edge2 = uv2 - uv0;
    bool uv_flat = abs(uv_edge1.x * uv_edge2.y - uv_edge1.y * uv_edge2.x) < RF_MIN_SQUARED_MAGNITUDE;
    float2 txcoords[3] = { float2(0.0), uv_flat ? float2(1.0e-18, 0.0) : uv_edge1,
        uv_flat ? float2(0.0, 1.0e-18) : uv_edge2 };
    return computeRayConeTriangleLODValue(vertices, txcoords, float3x3(1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0))
        - 0.5 * log2(scale);
}",
        ),
        guards_inside: &[],
    },
    // Falcor's computeLOD leaves out the texture's size, which its texture sampler adds as
    // 0.5 log2(width height): the adapter adds it as that sampler does.
    Peer {
        function: "rf_texture_lod",
        source: PeerSource::FalcorTexLod,
        items: &["struct RayCone"],
        adapter: "float peer_rf_texture_lod(float base_lod, float width, float2 texture_size, float3 normal, float3 direction) {
    return RayCone(width, 0.0).computeLOD(base_lod, direction, normal) + 0.5 * log2(texture_size.x * texture_size.y);
}",
        // |width| clamped to at least RF_MIN_MAGNITUDE and |n.d| to at least RF_MIN_COS before the
        // call (the cosine taken in the adapter and handed to the peer as a direction along a unit
        // normal, so the peer's dot is that cosine), the texture size to at least 1 and its two
        // logarithms taken apart, as ours does. Not addable from outside: the peer's quotient
        // |width| / |n.d| (ours takes the two logarithms apart), which overflows for widths past
        // about 3e34.
        guarded_adapter: Some(
            "float guarded_peer_rf_texture_lod(float base_lod, float width, float2 texture_size, float3 normal, float3 direction) {
    float cosine = max(abs(dot(normal, direction)), RF_MIN_COS);
    float2 size = max(texture_size, 1.0);
    return RayCone(max(abs(width), RF_MIN_MAGNITUDE), 0.0).computeLOD(base_lod, float3(cosine, 0.0, 0.0),
        float3(1.0, 0.0, 0.0)) + 0.5 * (log2(size.x) + log2(size.y));
}",
        ),
        guards_inside: &[],
    },
    Peer {
        function: "rf_refract_ray_cone",
        source: PeerSource::FalcorTexLod,
        items: &[
            "struct RayCone",
            "bool refractWithTIR(",
            "void rotate2DPlusMinus(",
            "float2 orthogonal(",
            "void computeRayConeForRefraction(",
            "bool refractRayCone(",
        ],
        adapter: "RfRefractedRayCone peer_rf_refract_ray_cone(RfRayCone cone, float3 normal, float3 direction,
        float normal_spread_angle, float eta) {
    RayCone refracted = RayCone(cone.width, cone.spread_angle);
    float3 refracted_direction;
    bool transmitted = refractRayCone(refracted, float3(0.0), direction, float3(0.0), normal, normal_spread_angle, eta,
        refracted_direction);
    return RfRefractedRayCone(RfRayCone(refracted.getWidth(), refracted.getSpreadAngle()), !transmitted);
}",
        // eta clamped to at least 0; the normal turned to face the ray and the normal spread's sign
        // with it, the spread clamped to +-RF_MAX_NORMAL_SPREAD; the cone's spread clamped so
        // that no boundary ray turns past RF_MAX_INCIDENCE_ANGLE (ours' rf_incidence_sin_cos and
        // rf_refraction_half_spread, called in the adapter); on total internal reflection the
        // reflected cone selected after the call (the peer leaves the cone as it was). Not
        // addable from outside: the peer's divisions by the boundary rays' cosines (ours keeps
        // each divisor at least RF_MIN_COS), its acos of a dot product that rounding can push
        // past 1, and its branches, on total internal reflection for the central ray and each
        // boundary ray.
        guarded_adapter: Some(
            "RfRefractedRayCone guarded_peer_rf_refract_ray_cone(RfRayCone cone, float3 normal, float3 direction,
        float normal_spread_angle, float eta) {
    float cosine = dot(normal, direction);
    float3 facing_normal = cosine > 0.0 ? -normal : normal;
    float facing_spread = cosine > 0.0 ? -normal_spread_angle : normal_spread_angle;
    float half_spread = rf_refraction_half_spread(cone.spread_angle, rf_incidence_sin_cos(normal, direction, cosine));
    RayCone refracted = RayCone(cone.width, 2.0 * half_spread);
    float3 refracted_direction;
    bool transmitted = refractRayCone(refracted, float3(0.0), direction, float3(0.0), facing_normal,
        clamp(facing_spread, -RF_MAX_NORMAL_SPREAD, RF_MAX_NORMAL_SPREAD), max(eta, 0.0), refracted_direction);
    RfRayCone leaving = transmitted ? RfRayCone(refracted.getWidth(), refracted.getSpreadAngle())
        : RfRayCone(cone.width, cone.spread_angle + 2.0 * facing_spread);
    return RfRefractedRayCone(leaving, !transmitted);
}",
        ),
        guards_inside: &[],
    },
    Peer {
        function: "rf_pixel_directions",
        source: PeerSource::NvproWireframe,
        items: &["void computeDifferentials("],
        adapter: "RfNeighbourDirections peer_rf_pixel_directions(float2 pixel, float2 image_size, float4x4 view_inv,
        float4x4 proj_inv) {
    float3 right;
    float3 below;
    computeDifferentials(pixel, image_size, transpose(view_inv), transpose(proj_inv), right, below);
    return RfNeighbourDirections(right, below);
}",
        guarded_adapter: None,
        guards_inside: &[],
    },
    Peer {
        function: "rf_barycentric_derivatives",
        source: PeerSource::FalcorTexLod,
        items: &["struct RayDiff", "void computeBarycentricDifferentials("],
        adapter: "RfDerivatives2 peer_rf_barycentric_derivatives(RfRayDiff diff, float3 direction, float t, float3 p0,
        float3 p1, float3 p2) {
    float3 edge01 = p1 - p0;
    float3 edge02 = p2 - p0;
    float3 face_normal = normalize(cross(edge01, edge02));
    RayDiff at_hit = RayDiff(diff.d_origin_dx, diff.d_origin_dy, diff.d_direction_dx, diff.d_direction_dy)
        .propagate(float3(0.0), direction, t, face_normal);
    float2 dx;
    float2 dy;
    computeBarycentricDifferentials(at_hit, direction, edge01, edge02, face_normal, dx, dy);
    return RfDerivatives2(dx, dy);
}",
        guarded_adapter: None,
        guards_inside: &[],
    },
    Peer {
        function: "rf_texture_derivatives",
        source: PeerSource::FalcorTexLod,
        items: &["void interpolateDifferentials("],
        adapter: "RfDerivatives2 peer_rf_texture_derivatives(RfDerivatives2 barycentric, float2 t0, float2 t1, float2 t2) {
    float2 values[3] = { t0, t1, t2 };
    float2 dx;
    float2 dy;
    interpolateDifferentials(barycentric.dx, barycentric.dy, values, dx, dy);
    return RfDerivatives2(dx, dy);
}",
        guarded_adapter: None,
        guards_inside: &[],
    },
    Peer {
        function: "rf_normal_derivatives",
        source: PeerSource::FalcorTexLod,
        items: &["struct RayDiff", "void interpolateDifferentials(", "void computeNormalDifferentials("],
        adapter: "RfDerivatives3 peer_rf_normal_derivatives(float3 n0, float3 n1, float3 n2, float2 barycentrics,
        RfDerivatives2 barycentric) {
    float3 normals[3] = { n0, n1, n2 };
    float3 interpolated = (1.0 - barycentrics.x - barycentrics.y) * n0 + barycentrics.x * n1 + barycentrics.y * n2;
    float3 dx;
    float3 dy;
    computeNormalDifferentials(RayDiff(float3(0.0), float3(0.0), float3(0.0), float3(0.0)), interpolated,
        barycentric.dx, barycentric.dy, normals, dx, dy);
    return RfDerivatives3(dx, dy);
}",
        guarded_adapter: None,
        guards_inside: &[],
    },
    Peer {
        function: "rf_barycentric_deltas",
        source: PeerSource::NvproWireframe,
        items: &["float3 intersectRayTriangle(", "float3 computeDerivative("],
        adapter: "float3 peer_rf_barycentric_deltas(float4x4 world_to_object, float3 world_origin, float3 p0, float3 p1,
        float3 p2, float3 direction_x, float3 direction_y, float3 hit_barycentrics) {
    float4x4 rows = transpose(world_to_object);
    float4x3 peer_matrix = float4x3(rows[0].xyz, rows[1].xyz, rows[2].xyz, rows[3].xyz);
    float3 object_origin = mul(float4(world_origin, 1.0), peer_matrix);
    float3 positions[3] = { p0, p1, p2 };
    return computeDerivative(peer_matrix, world_origin, object_origin, positions, direction_x, direction_y,
        hit_barycentrics);
}",
        guarded_adapter: None,
        guards_inside: &[],
    },
    Peer {
        function: "rf_anisotropic_cone_gradients",
        source: PeerSource::FalcorTexLod,
        items: &["void computeAnisotropicEllipseAxes("],
        adapter: "RfDerivatives2 peer_rf_anisotropic_cone_gradients(float width, float3 direction, float3 p0, float3 p1,
        float3 p2, float2 uv0, float2 uv1, float2 uv2) {
    float3 positions[3] = { p0, p1, p2 };
    float2 txcoords[3] = { uv0, uv1, uv2 };
    float3 face_normal = normalize(cross(p1 - p0, p2 - p0));
    float2 dx;
    float2 dy;
    computeAnisotropicEllipseAxes(p0, face_normal, direction, 0.5 * width, positions, txcoords, uv0, dx, dy);
    return RfDerivatives2(dx, dy);
}",
        guarded_adapter: None,
        guards_inside: &[],
    },
    Peer {
        function: "rf_process_wireframe",
        source: PeerSource::NvproWireframe,
        items: &[
            "struct WireframeSettings",
            "float edgePosition(",
            "float edgeThickness(",
            "float stipple(",
            "float getLineWidth(",
            "float processWireframe(",
        ],
        adapter: "float peer_rf_process_wireframe(RfWireframeSettings settings, float3 barycentrics, float3 deltas) {
    WireframeSettings peer = { settings.thickness, settings.thickness_var, settings.smoothing, settings.stipple,
        settings.stipple_length, float(settings.stipple_repeats) };
    return processWireframe(peer, barycentrics, deltas);
}",
        // The thickness and the thickness variation clamped to [0, RF_MAX_LINE_THICKNESS] and the
        // smoothing so that the ramp width (thickness times smoothing) stays within it, which
        // keeps the peer's products finite; ours' screen-space switch (|deltas|, or ones); the
        // stipple pattern, the peer's own `stipple` with ours' clamps of its arguments (repeats at
        // least 1, length and edge position in [0, 1]) and a solid line for repeats <= 0,
        // evaluated always and selected, the peer's branch around it switched off. Inside the
        // peer's functions (`guards_inside`): ours' hard step where the ramp width is at most
        // RF_MIN_LINE_RAMP, selected beside the peer's smoothstep; the smoothstep taken from the
        // ramp's start over its width, as ours divides, so that a ramp narrower than half an ulp
        // of its start (whose two edges round to one, where the peer's smoothstep is undefined)
        // still ramps; and the clamps of the edge position and of 1 - sin(e pi) in the thickness
        // variation.
        guarded_adapter: Some(
            "float guarded_peer_rf_process_wireframe(RfWireframeSettings settings, float3 barycentrics, float3 deltas) {
    float thickness = clamp(settings.thickness, 0.0, RF_MAX_LINE_THICKNESS);
    float smoothing = clamp(settings.smoothing, 0.0, RF_MAX_LINE_THICKNESS / max(thickness, RF_MIN_LINE_RAMP));
    WireframeSettings peer = { thickness, clamp(settings.thickness_var, 0.0, RF_MAX_LINE_THICKNESS), smoothing, false,
        settings.stipple_length, float(settings.stipple_repeats) };
    float coverage = processWireframe(peer, barycentrics, settings.screen_space ? abs(deltas) : float3(1.0));
    float dashes = stipple(float(max(settings.stipple_repeats, 1)), clamp(settings.stipple_length, 0.0, 1.0),
        clamp(edgePosition(barycentrics), 0.0, 1.0));
    float pattern = settings.stipple_repeats > 0 ? dashes : 1.0;
    return coverage * (settings.stipple ? pattern : 1.0);
}",
        ),
        guards_inside: &[
            (
                "smoothstep(deltas * (thickness), deltas * (thickness + smoothing), barys)",
                "select(deltas * smoothing > RF_MIN_LINE_RAMP, smoothstep(0.0, max(deltas * smoothing, RF_MIN_LINE_RAMP), barys - deltas * (thickness)), step(deltas * (thickness), barys))",
            ),
            (
                "(1.0 - sin(edgePos * M_PI))",
                "clamp(1.0 - sin(clamp(edgePos, 0.0, 1.0) * M_PI), 0.0, 1.0)",
            ),
        ],
    },
];

/// `items` (an [`extract`]ion) with each of `edits`' peer's text replaced by its guarded text.
/// Fails naming the first text that does not occur exactly once.
pub fn add_guards_inside(items: &str, edits: &[(&str, &str)]) -> Result<String, String> {
    let mut guarded = items.to_string();
    for (peer_text, guarded_text) in edits {
        match guarded.matches(peer_text).count() {
            1 => guarded = guarded.replacen(peer_text, guarded_text, 1),
            count => {
                return Err(format!(
                    "'{peer_text}' occurs {count} times, not once, where a guard goes"
                ))
            }
        }
    }
    Ok(guarded)
}

/// What an extraction needs beside the items: pi, which the peers take from a header of their
/// own (`M_PI`).
const PRELUDE: &str = "#ifndef M_PI\n#define M_PI 3.14159265358979323846\n#endif\n";

/// The `#define` lines of `source` and every declaration in it that starts with one of `items`
/// (white space folded), each to its matching closing brace (a struct with its `;`), in the order
/// of `items` and, for overloads, of the source; comments removed. Fails naming the first item
/// that nothing starts with, or one whose braces do not close.
pub fn extract(source: &str, items: &[&str]) -> Result<String, String> {
    let code = without_comments(source);
    let mut out = String::from(PRELUDE);
    for line in code
        .lines()
        .filter(|line| line.trim_start().starts_with("#define"))
    {
        out.push_str(line.trim());
        out.push('\n');
    }
    for item in items {
        let prefix = fold_spaces(item);
        let starts: Vec<usize> = line_starts(&code)
            .filter(|&at| {
                fold_spaces(&code[at..code[at..].find('\n').map_or(code.len(), |end| at + end)])
                    .starts_with(&prefix)
            })
            .collect();
        if starts.is_empty() {
            return Err(format!("no declaration starts with '{item}'"));
        }
        for start in starts {
            out.push_str(
                declaration(&code, start).ok_or_else(|| format!("'{item}': its braces do not close"))?,
            );
            out.push('\n');
        }
    }
    Ok(out)
}

/// The byte offsets of each line's first character.
fn line_starts(text: &str) -> impl Iterator<Item = usize> + '_ {
    std::iter::once(0).chain(text.match_indices('\n').map(|(at, _)| at + 1))
}

/// `text` with every run of white space one space, trimmed.
fn fold_spaces(text: &str) -> String {
    text.split_whitespace().collect::<Vec<_>>().join(" ")
}

/// The declaration starting at `start`: to the brace that closes its first `{`, with a `;` that
/// follows it.
fn declaration(code: &str, start: usize) -> Option<&str> {
    let open = start + code[start..].find('{')?;
    let mut depth = 0;
    for (offset, c) in code[open..].char_indices() {
        match c {
            '{' => depth += 1,
            '}' => {
                depth -= 1;
                if depth == 0 {
                    let end = open + offset + 1;
                    let semicolon = code[end..].trim_start().starts_with(';');
                    let end = if semicolon {
                        end + code[end..].find(';')? + 1
                    } else {
                        end
                    };
                    return Some(&code[start..end]);
                }
            }
            _ => {}
        }
    }
    None
}

/// `source` without `//` and `/* */` comments (the peers' shaders have no strings that hold them).
fn without_comments(source: &str) -> String {
    let mut out = String::with_capacity(source.len());
    let mut rest = source;
    while let Some(at) = rest.find('/') {
        out.push_str(&rest[..at]);
        let tail = &rest[at..];
        if tail.starts_with("//") {
            rest = tail.find('\n').map_or("", |end| &tail[end..]);
        } else if let Some(body) = tail.strip_prefix("/*") {
            rest = body.find("*/").map_or("", |end| &body[end + 2..]);
        } else {
            out.push('/');
            rest = &tail[1..];
        }
    }
    out.push_str(rest);
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    const PEER_FILE: &str = "#include \"other.slang\"\n\
        #define MODE 2 // the mode\n\
        /** A cone. { not a brace } */\n\
        struct Cone\n{\n    float width;\n    float width_at(float t) { return width + t; }\n};\n\
        float twice(float x) { return 2.0 * x; } // twice\n\
        float twice(float2 x) { return 2.0 * x.x; }\n\
        [shader(\"raygeneration\")]\nvoid main() { }\n";

    #[test]
    fn extracts_the_items_and_the_defines() {
        let extracted = extract(PEER_FILE, &["struct Cone", "float twice("]).unwrap();
        assert!(extracted.contains("#define MODE 2\n"));
        assert!(extracted.contains(
            "struct Cone\n{\n    float width;\n    float width_at(float t) { return width + t; }\n};"
        ));
        assert!(extracted.contains("float twice(float x) { return 2.0 * x; }"));
        assert!(extracted.contains("float twice(float2 x) { return 2.0 * x.x; }"));
        assert!(
            !extracted.contains("main") && !extracted.contains("include") && !extracted.contains("brace")
        );
    }

    #[test]
    fn guards_replace_the_peers_text_once() {
        let extracted = extract(PEER_FILE, &["float twice("]).unwrap();
        let guarded = add_guards_inside(&extracted, &[("2.0 * x.x", "2.0 * max(x.x, 0.0)")]).unwrap();
        assert!(guarded.contains("float twice(float2 x) { return 2.0 * max(x.x, 0.0); }"));
        assert!(guarded.contains("float twice(float x) { return 2.0 * x; }"));
        let missing = add_guards_inside(&extracted, &[("3.0 * x", "0.0")]).unwrap_err();
        assert_eq!(missing, "'3.0 * x' occurs 0 times, not once, where a guard goes");
        let twice = add_guards_inside(&extracted, &[("return 2.0", "return 0.0")]).unwrap_err();
        assert_eq!(twice, "'return 2.0' occurs 2 times, not once, where a guard goes");
    }

    #[test]
    fn a_missing_item_is_named() {
        let error = extract(PEER_FILE, &["float thrice("]).unwrap_err();
        assert_eq!(error, "no declaration starts with 'float thrice('");
    }

    #[test]
    fn every_adapter_is_named_for_its_function_and_kind() {
        for peer in PEERS {
            for kind in [AdapterKind::Plain, AdapterKind::Guarded] {
                let Some(adapter) = peer.adapter_of(kind) else {
                    continue;
                };
                let name = format!(" {}(", kind.name(peer.function));
                assert!(
                    adapter.contains(&name),
                    "{}: the {kind:?} adapter is not {name}",
                    peer.function
                );
            }
        }
    }

    #[test]
    fn the_five_functions_slower_than_their_peers_have_guarded_adapters() {
        let guarded: Vec<&str> = PEERS
            .iter()
            .filter(|peer| peer.guarded_adapter.is_some())
            .map(|peer| peer.function)
            .collect();
        assert_eq!(
            guarded,
            [
                "rf_texel_density",
                "rf_triangle_base_lod",
                "rf_texture_lod",
                "rf_refract_ray_cone",
                "rf_process_wireframe"
            ]
        );
    }
}

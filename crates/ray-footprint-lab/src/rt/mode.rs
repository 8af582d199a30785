//! Render modes: how the closest-hit shader picks a texture level of detail.

use std::fmt;

/// A render mode. `cargo xtask codegen` writes each discriminant into the shaders as a constant
/// named `RT_MODE_` and the mode's name in capitals: RT_MODE_CONE_CURVATURE for ConeCurvature.
///
/// Every mode traces the same primary rays and records the same per-pixel values
/// ([`crate::rt::abi::RtPixelRecord`]); the mode decides how the texture is sampled, whether a
/// reflection off a mirror widens its cone by the surface curvature and roughness, whether glass
/// refracts the cone (and its second section), whether a reflected or refracted ray carries a ray
/// differential, and whether the wireframe is drawn. Every mode but the path tracers reflects
/// and refracts the same rays; the path tracers (`PathMip0` to `PathBias`) scatter from every
/// surface, and trace the same paths as each other. The ray-differential modes carry the differential through mirrors and glass (Igehy's
/// reflection and refraction); the re-intersection of `BaryGradients` needs a primary hit: what
/// the mirror reflects is sampled at the ray-cone LOD in it. The cone modes other than `ConeRefraction` and `ConeSections` carry the
/// cone through glass as if the glass were not there.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[repr(u32)]
pub enum Mode {
    /// Always mip 0: aliases wherever a pixel covers more than a texel.
    Mip0 = 0,
    /// Isotropic ray-cone LOD (RTG Eq. 34); reflections treat the sphere as a planar mirror.
    Cone = 1,
    /// Ray-cone LOD; reflections widen (or narrow) the cone by the curvature the triangle's
    /// principal curvatures agree on (`rf_isotropic_curvature` of the shape operator fitted to its
    /// vertex normals, Rusinkiewicz 2004; JCGT 2021's spread): the lesser in magnitude when both
    /// have one sign, 0 on a saddle, where the beam converges one way and diverges the other.
    ConeCurvature = 2,
    /// `textureGrad` with the ray-cone gradient times `tex_grad_scale` (0: mip 0, 1: matching, >1: blurred).
    TexGradScale = 3,
    /// Ray-cone LOD into a texture whose mip levels are flat colours (RTG Fig. 20-9/20-10).
    MipLevels = 4,
    /// `textureGrad` with anisotropic UV gradients from the ray differentials (Igehy; RTG
    /// Eq. 8-21), times `tex_grad_scale`; reflections carry the differential.
    RayDiff = 5,
    /// `textureGrad` with anisotropic UV gradients from the neighbour pixels' rays re-intersected
    /// with the hit triangle's plane (signed barycentric offsets), times `tex_grad_scale`.
    BaryGradients = 6,
    /// Ray-cone LOD under an anti-aliased wireframe (per-pixel barycentric deltas by
    /// re-intersection; the closed-form cone deltas in reflections).
    Wireframe = 7,
    /// `textureLod` at the isotropic LOD of the ray-differential texel gradients (RTG Eq. 1-2:
    /// the chapter's RayDiffs); reflections carry the differential.
    RayDiffIsotropic = 8,
    /// Ray-cone LOD as `ConeCurvature`; glass refracts the cone (`rf_refract_ray_cone`, RTG II
    /// ch. 10), the normal's turn across the footprint from the curvature; total internal
    /// reflection gives the reflected cone.
    ConeRefraction = 9,
    /// Ray-cone LOD as `ConeCurvature`; a rough mirror widens the reflected cone by twice
    /// `rf_roughness_spread_angle` of its roughness (JCGT 2021).
    ConeRoughness = 10,
    /// `textureGrad` with the gradients of the cone's elliptical footprint
    /// (`rf_anisotropic_cone_gradients`, JCGT 2021), times `tex_grad_scale`; reflections as
    /// `ConeCurvature`. The ellipse is the round cone cut by the surface at the hit, so it cannot be
    /// carried through a curved mirror: a reflection off a surface whose normal curvature differs
    /// with direction (a cylinder, a saddle) gives the beam widths and spreads that differ across
    /// it, about axes of their own, which the cone's two numbers (8 bytes) cannot hold. Across the
    /// ray the beam is `W + t S` (pixel offsets to offsets, and to turns, two 2 x 2 maps) and a
    /// reflection adds the shape operator's turn of `W` to `S`; following the ellipse alone,
    /// `(W + t S)(W + t S)^T`, needs `W W^T`, `S S^T` and the whole of `W S^T`, 10 numbers. Either
    /// way it takes 8 or 10 numbers and the frame's angle about the ray (36 to 44 bytes): a ray
    /// differential in a frame of its own, against Igehy's 12 numbers (48 bytes), not a cone.
    ConeAnisotropic = 11,
    /// Ray-cone LOD as `ConeCurvature`, with the OptiX Toolkit's curvature estimate in place of the
    /// fitted shape operator's: the triangle's edge curvature of least magnitude when
    /// the three agree in sign, 0 when they do not (its `ray_cone.h`, `minTriangleCurvature`).
    ConeMinCurvature = 12,
    /// Ray-cone LOD as `ConeRefraction`, the beam carried as two sections: glass refracts the
    /// cone in the plane of incidence as `ConeRefraction` does and the section across it by
    /// Coddington's sagittal equation (`rf_refract_sagittal_cone`), and the ray carries that
    /// section's axis; a surface is filtered at the round cone whose footprint is as long as the
    /// longer axis of the sections' ellipse on it (`rf_two_section_width`). RTG II's cone alone
    /// spreads both ways as in the plane of incidence, which off the normal is too wide.
    ConeSections = 13,
    /// A path tracer at level 0: every surface scatters the ray on up to the bounce limit, a
    /// textured surface as a Lambertian one (a direction from its cosine lobe, new random numbers
    /// at every bounce), a mirror about a GGX normal of its roughness, glass as in the other
    /// modes; each textured vertex is sampled at mip 0, what Unreal, Bevy Solari and pbrt-v4's GPU
    /// path do past the first hit.
    PathMip0 = 14,
    /// The path tracer of `PathMip0`, each textured vertex sampled at the ray-cone LOD of the
    /// arriving cone, the cone leaving every vertex `rf_scatter_ray_cone`'s for the lobe drawn
    /// (the hit triangle's isotropic curvature), glass refracting it as `ConeRefraction`.
    PathCone = 15,
    /// The path tracer of `PathMip0` at the ray-cone LOD, every vertex a curved mirror whatever
    /// the lobe drawn: the cone leaves with the curvature's spread (JCGT 2021) and no scattering
    /// term; glass carries the cone on as if it were not there.
    PathCurvature = 16,
    /// `PathCurvature` plus twice `rf_roughness_spread_angle` of the lobe's roughness at every
    /// scattering vertex (JCGT 2021 section 3, Falcor's `roughnessToSpread`), a Lambertian surface
    /// read as roughness 1.
    PathRoughness = 17,
    /// The path tracer at the ray-cone LOD with RTXPT's rule: no curvature term, and at every
    /// scattering vertex that is not a delta lobe (GGX alpha below 0.0064) the spread grows by
    /// 0.3 times the whole angle of the spherical cap of solid angle `1 / pdf` of the direction
    /// drawn, clamped to 2 pi (`ComputeRayConeSpreadAngleExpansionByScatterPDF`).
    PathRtxpt = 18,
    /// The path tracer at the ray-cone LOD with the OptiX Toolkit's rule (`ray_cone.h`): its
    /// `reflect` (twice the curvature times the width while the angle is below 0.25), then
    /// `scatterBsdf`, `0.25 min(1, 1 / (pi f_s))` with `f_s` the BSDF value of the direction
    /// drawn, the cone set to the diffuse angle 0.25 once it reaches it.
    PathOptix = 19,
    /// `PathCurvature` with one global level-of-detail bias, `RtPushConstants::lod_bias` mip
    /// levels, added to the LOD of every textured vertex past the first hit: what Falcor's path
    /// tracer does at secondary hits (one `lodBias` for all of them). By default -3 levels, the
    /// best of the sweep `path_image_gpu --biases` prints.
    PathBias = 20,
}

/// The level-of-detail bias of [`Mode::PathBias`] that the renderer's push constants carry by
/// default, in mip levels: the lowest image error of the sweep `path_image_gpu --size 960x540
/// --seed 7 --biases -12,-8,-6,-4,-3,-2,-1,-0.25,0,1` on an H200, where -4 to -2 are within 0.5%
/// of each other (the lab README, "The GPU modes' image error").
pub const PATH_LOD_BIAS: f32 = -3.0;

impl Mode {
    /// Every mode, in gallery order.
    pub const ALL: [Mode; 21] = [
        Mode::Mip0,
        Mode::Cone,
        Mode::ConeCurvature,
        Mode::ConeMinCurvature,
        Mode::TexGradScale,
        Mode::MipLevels,
        Mode::RayDiff,
        Mode::RayDiffIsotropic,
        Mode::BaryGradients,
        Mode::Wireframe,
        Mode::ConeRefraction,
        Mode::ConeSections,
        Mode::ConeRoughness,
        Mode::ConeAnisotropic,
        Mode::PathMip0,
        Mode::PathCone,
        Mode::PathCurvature,
        Mode::PathRoughness,
        Mode::PathRtxpt,
        Mode::PathOptix,
        Mode::PathBias,
    ];

    /// The discriminant: the value of the mode's `RT_MODE_*` constant in the shaders.
    pub fn id(self) -> u32 {
        self as u32
    }

    /// The command-line and file name.
    pub fn name(self) -> &'static str {
        match self {
            Mode::Mip0 => "mip0",
            Mode::Cone => "cone",
            Mode::ConeCurvature => "cone_curvature",
            Mode::TexGradScale => "tex_grad_scale",
            Mode::MipLevels => "mip_levels",
            Mode::RayDiff => "ray_diff",
            Mode::BaryGradients => "bary_gradients",
            Mode::Wireframe => "wireframe",
            Mode::RayDiffIsotropic => "ray_diff_isotropic",
            Mode::ConeRefraction => "cone_refraction",
            Mode::ConeRoughness => "cone_roughness",
            Mode::ConeAnisotropic => "cone_anisotropic",
            Mode::ConeMinCurvature => "cone_min_curvature",
            Mode::ConeSections => "cone_sections",
            Mode::PathMip0 => "path_mip0",
            Mode::PathCone => "path_cone",
            Mode::PathCurvature => "path_curvature",
            Mode::PathRoughness => "path_roughness",
            Mode::PathRtxpt => "path_rtxpt",
            Mode::PathOptix => "path_optix",
            Mode::PathBias => "path_bias",
        }
    }

    /// One line saying what the mode shows.
    pub fn description(self) -> &'static str {
        match self {
            Mode::Mip0 => "mip 0 everywhere (aliases at grazing angles)",
            Mode::Cone => "isotropic ray-cone LOD, reflections as off a planar mirror",
            Mode::ConeCurvature => "isotropic ray-cone LOD, reflected cones widened by curvature",
            Mode::TexGradScale => "textureGrad with the ray-cone gradient times tex_grad_scale",
            Mode::MipLevels => "ray-cone LOD into a texture with one colour per mip level",
            Mode::RayDiff => "textureGrad with anisotropic ray-differential gradients",
            Mode::BaryGradients => "textureGrad with gradients from re-intersected neighbour rays",
            Mode::Wireframe => "ray-cone LOD under an anti-aliased wireframe",
            Mode::RayDiffIsotropic => "textureLod at the isotropic ray-differential LOD",
            Mode::ConeRefraction => "as cone_curvature, glass refracting the cone",
            Mode::ConeRoughness => "as cone_curvature, rough mirrors widening the reflected cone",
            Mode::ConeAnisotropic => "textureGrad with the cone's elliptical footprint",
            Mode::ConeMinCurvature => "as cone_curvature, the OptiX Toolkit's least edge curvature",
            Mode::ConeSections => "as cone_refraction, glass refracting the beam's two sections",
            Mode::PathMip0 => "path tracer, every textured vertex at mip 0",
            Mode::PathCone => "path tracer, rf_scatter_ray_cone at every vertex, its LOD at each",
            Mode::PathCurvature => "path tracer, every vertex a curved mirror (no scattering term)",
            Mode::PathRoughness => "path tracer, curvature and twice the roughness spread (JCGT 2021)",
            Mode::PathRtxpt => "path tracer, RTXPT's spread from the direction's pdf",
            Mode::PathOptix => "path tracer, the OptiX Toolkit's reflect and scatterBsdf",
            Mode::PathBias => "path tracer, path_curvature's LOD plus a global bias past the first hit",
        }
    }

    /// Whether the mode traces paths: every surface scatters the ray on, as `PathMip0` does.
    pub fn traces_paths(self) -> bool {
        matches!(
            self,
            Mode::PathMip0
                | Mode::PathCone
                | Mode::PathCurvature
                | Mode::PathRoughness
                | Mode::PathRtxpt
                | Mode::PathOptix
                | Mode::PathBias
        )
    }

    /// The mode called `name`, or `None`.
    pub fn from_name(name: &str) -> Option<Mode> {
        Mode::ALL.into_iter().find(|mode| mode.name() == name)
    }
}

impl fmt::Display for Mode {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.pad(self.name())
    }
}

impl Mode {
    /// What the payload of the mode's colour-only shaders carries beyond the colour and the bounce
    /// depth: the ray cone in the modes that read it (every mode but the two at mip 0 and the
    /// ray-differential modes: the level of detail, or in the gradient modes that of what the mirror reflects), the
    /// sagittal section and its axis in `ConeSections`, and the ray differential in the
    /// ray-differential modes, which carry it through mirrors and glass and never read the cone.
    pub fn payload(self) -> Payload {
        let differential = matches!(self, Mode::RayDiff | Mode::RayDiffIsotropic);
        Payload {
            cone: !matches!(self, Mode::Mip0 | Mode::PathMip0) && !differential,
            sagittal: self == Mode::ConeSections,
            differential,
        }
    }

    /// The `#define`s (name, value) the colour-only shaders are compiled with in this mode.
    pub fn colour_defines(self) -> Vec<(&'static str, String)> {
        let payload = self.payload();
        let mut defines = vec![("RT_COLOUR_MODE", format!("{}u", self.id()))];
        if payload.cone {
            defines.push(("RT_PAYLOAD_CONE", String::new()));
        }
        if payload.sagittal {
            defines.push(("RT_PAYLOAD_SAGITTAL", String::new()));
        }
        if payload.differential {
            defines.push(("RT_PAYLOAD_DIFF", String::new()));
        }
        defines
    }
}

/// What a mode's colour-only payload carries beyond the colour and the bounce depth (16 bytes):
/// mip 0's payload is 16 bytes, a cone mode's 24, `cone_sections`' 36, a ray-differential
/// mode's 64.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Payload {
    /// The ray cone (8 bytes).
    pub cone: bool,
    /// The sagittal section and its axis (12 bytes: the section's cone, and the axis in two
    /// 16-bit snorms of its octahedral projection).
    pub sagittal: bool,
    /// The ray differential: origin and direction changes per pixel step, without the pads of
    /// `RfRayDiff` (48 bytes).
    pub differential: bool,
}

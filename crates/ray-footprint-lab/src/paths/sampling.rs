//! What a path draws at a vertex: its random numbers, the shading frame they are read in, the
//! direction they pick (Lambert's cosine lobe, or a GGX microfacet normal from the distribution of
//! normals and the reflection about it), and the pdf and BSDF value of that direction.
//!
//! Sources: Walter, Marschner, Li and Torrance, "Microfacet Models for Refraction through Rough
//! Surfaces", EGSR 2007, cited as "Walter Eq. N" (GGX: D Eq. 33, G1 Eq. 34, sampling Eq. 35-36,
//! the reflection's Jacobian Eq. 14, the BRDF Eq. 20).

use super::scene::{Material, DIFFUSE_ALBEDO};
use glam::DVec3;
use std::f64::consts::PI;

/// Random numbers a vertex draws: the lobe choice, then two for the direction.
pub const NUMBERS_PER_VERTEX: usize = 3;

/// A SplitMix64 sequence (Steele, Lea and Flood, "Fast Splittable Pseudorandom Number Generators",
/// OOPSLA 2014): the stream of one path's one bounce, so that the path traced from a neighbouring
/// image position draws the same numbers at the same vertex.
#[derive(Clone, Copy, Debug)]
pub struct Stream {
    state: u64,
}

/// SplitMix64's output function of a state.
fn mix64(state: u64) -> u64 {
    let mut z = state;
    z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
    z ^ (z >> 31)
}

/// SplitMix64's increment, the golden ratio in 64 bits.
const GOLDEN_GAMMA: u64 = 0x9e37_79b9_7f4a_7c15;

impl Stream {
    /// The stream of path `path`'s bounce `bounce` (0: its image position; `k >= 1`: vertex `k`)
    /// under `seed`: its state is the three keys mixed in turn.
    pub fn new(seed: u64, path: u64, bounce: u32) -> Stream {
        let keyed = mix64(mix64(seed.wrapping_add(GOLDEN_GAMMA)) ^ path.wrapping_mul(GOLDEN_GAMMA));
        Stream {
            state: mix64(keyed ^ u64::from(bounce).wrapping_mul(0xd1b5_4a32_d192_ed03)),
        }
    }

    /// The next number, uniform in `[0, 1)` with 53 random bits.
    pub fn next_f64(&mut self) -> f64 {
        self.state = self.state.wrapping_add(GOLDEN_GAMMA);
        (mix64(self.state) >> 11) as f64 * (1.0 / (1u64 << 53) as f64)
    }
}

/// The [`NUMBERS_PER_VERTEX`] numbers path `path` draws at vertex `vertex` (1 to 4).
pub fn vertex_numbers(seed: u64, path: u64, vertex: u32) -> [f64; NUMBERS_PER_VERTEX] {
    let mut stream = Stream::new(seed, path, vertex);
    [stream.next_f64(), stream.next_f64(), stream.next_f64()]
}

/// The image position of path `path`: uniform over `[0, width) x [0, height)`.
pub fn pixel_position(seed: u64, path: u64, width: f64, height: f64) -> (f64, f64) {
    let mut stream = Stream::new(seed, path, 0);
    (stream.next_f64() * width, stream.next_f64() * height)
}

/// A shading frame: `tangent`, `bitangent`, `normal`, right-handed and orthonormal.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Frame {
    /// First tangent axis.
    pub tangent: DVec3,
    /// Second tangent axis, `normal x tangent`.
    pub bitangent: DVec3,
    /// The unit normal.
    pub normal: DVec3,
}

impl Frame {
    /// The world direction of the frame's local `(x, y, z)`.
    pub fn to_world(&self, local: DVec3) -> DVec3 {
        local.x * self.tangent + local.y * self.bitangent + local.z * self.normal
    }
}

/// The frame of the unit `normal` built by Gram-Schmidt against the fixed unit `axis`:
/// `tangent = unit(axis - normal (normal . axis))`, `bitangent = normal x tangent`. With one axis
/// per surface, the frame turns with the normal as a rigid body wherever the normal stays away
/// from `+-axis` (a smooth function of the normal there), so the directions read in it move
/// smoothly across the surface.
pub fn shading_frame(normal: DVec3, axis: DVec3) -> Frame {
    let tangent = (axis - normal * normal.dot(axis)).normalize();
    Frame {
        tangent,
        bitangent: normal.cross(tangent),
        normal,
    }
}

/// The lobe a vertex sampled.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Lobe {
    /// Lambert's cosine lobe: a direction read in the frame alone.
    Diffuse,
    /// A GGX lobe of perceptual roughness `roughness`: the incoming direction reflected about a
    /// microfacet normal read in the frame.
    Glossy {
        /// Perceptual roughness (GGX `alpha = roughness^2`).
        roughness: f64,
    },
}

/// Cosine-weighted direction in the frame (Malley's method): `r = sqrt(u1)`, `phi = 2 pi u2`,
/// `(r cos phi, r sin phi, sqrt(1 - u1))`; its pdf is `cos theta / pi`.
pub fn cosine_direction(u1: f64, u2: f64) -> DVec3 {
    let radius = u1.sqrt();
    let angle = 2.0 * PI * u2;
    DVec3::new(
        radius * angle.cos(),
        radius * angle.sin(),
        (1.0 - u1).max(0.0).sqrt(),
    )
}

/// A GGX microfacet normal in the frame from its distribution of normals (Walter Eq. 35-36):
/// `theta_m = atan(alpha sqrt(u1 / (1 - u1)))`, `phi_m = 2 pi u2`. Its pdf over normals is
/// `D(m) cos theta_m`.
pub fn ggx_normal(alpha: f64, u1: f64, u2: f64) -> DVec3 {
    let tan_theta = alpha * (u1 / (1.0 - u1)).sqrt();
    let cos_theta = 1.0 / (1.0 + tan_theta * tan_theta).sqrt();
    let sin_theta = tan_theta * cos_theta;
    let angle = 2.0 * PI * u2;
    DVec3::new(sin_theta * angle.cos(), sin_theta * angle.sin(), cos_theta)
}

/// GGX's distribution of normals (Walter Eq. 33) at `cos_m = m . n > 0`:
/// `D = alpha^2 / (pi ((alpha^2 - 1) cos_m^2 + 1)^2)`, the same as
/// `alpha^2 / (pi cos_m^4 (alpha^2 + tan^2 theta_m)^2)`.
pub fn ggx_distribution(alpha: f64, cos_m: f64) -> f64 {
    let alpha2 = alpha * alpha;
    let denominator = (alpha2 - 1.0) * cos_m * cos_m + 1.0;
    alpha2 / (PI * denominator * denominator)
}

/// Smith's GGX masking term (Walter Eq. 34) for a direction at `cos_v = v . n > 0`:
/// `G1 = 2 / (1 + sqrt(1 + alpha^2 tan^2 theta_v))`.
pub fn smith_g1(alpha: f64, cos_v: f64) -> f64 {
    let tan2 = (1.0 - cos_v * cos_v).max(0.0) / (cos_v * cos_v);
    2.0 / (1.0 + (1.0 + alpha * alpha * tan2).sqrt())
}

/// The direction a material sends the ray `incoming` (unit, arriving at the vertex) to, from the
/// vertex's numbers `[lobe, u1, u2]`, in `frame` (whose normal faces the incoming side), with the
/// lobe it took; `None` where the reflection about a GGX normal goes below the surface (the path
/// ends there).
pub fn sample_material(
    material: Material,
    frame: &Frame,
    incoming: DVec3,
    numbers: [f64; NUMBERS_PER_VERTEX],
) -> Option<(Lobe, DVec3)> {
    let [choice, u1, u2] = numbers;
    let lobe = match material {
        Material::Lambert => Lobe::Diffuse,
        Material::Conductor { roughness } => Lobe::Glossy { roughness },
        Material::Coated {
            roughness,
            coat_weight,
        } => {
            if choice < coat_weight {
                Lobe::Glossy { roughness }
            } else {
                Lobe::Diffuse
            }
        }
    };
    let direction = match lobe {
        Lobe::Diffuse => frame.to_world(cosine_direction(u1, u2)),
        Lobe::Glossy { roughness } => {
            let microfacet = frame.to_world(ggx_normal(roughness * roughness, u1, u2));
            incoming - 2.0 * incoming.dot(microfacet) * microfacet
        }
    };
    (direction.dot(frame.normal) > 0.0).then_some((lobe, direction))
}

/// A GGX lobe's pdf (solid angle) and BSDF value for the unit `to_light = -incoming` and
/// `outgoing` around the unit `normal`: with the half vector `m`, `pdf = D(m) cos_m / (4 |o . m|)`
/// (Walter Eq. 14 and 35-36) and `f = D(m) G1(i) G1(o) / (4 cos_i cos_o)` (Walter Eq. 20 with
/// Fresnel 1 and the separable Smith term). A mirror (`alpha = 0`) gives infinity for both.
fn ggx_pdf_and_bsdf(alpha: f64, normal: DVec3, to_light: DVec3, outgoing: DVec3) -> (f64, f64) {
    if alpha == 0.0 {
        return (f64::INFINITY, f64::INFINITY);
    }
    let half = (to_light + outgoing).normalize();
    let (cos_m, cos_in, cos_out) = (half.dot(normal), to_light.dot(normal), outgoing.dot(normal));
    if cos_m <= 0.0 || cos_in <= 0.0 || cos_out <= 0.0 {
        return (0.0, 0.0);
    }
    let distribution = ggx_distribution(alpha, cos_m);
    let pdf = distribution * cos_m / (4.0 * outgoing.dot(half).abs());
    let masking = smith_g1(alpha, cos_in) * smith_g1(alpha, cos_out);
    (pdf, distribution * masking / (4.0 * cos_in * cos_out))
}

/// The material's pdf (solid angle, over both lobes of a coat) and BSDF value (no cosine) for the
/// ray `incoming` leaving along `outgoing`, around the unit `normal` facing the incoming side:
/// Lambert `cos_o / pi` and `albedo / pi`; a coat `c x (GGX) + (1 - c) x (Lambert)` for both.
pub fn pdf_and_bsdf(material: Material, normal: DVec3, incoming: DVec3, outgoing: DVec3) -> (f64, f64) {
    let lambert = (outgoing.dot(normal).max(0.0) / PI, DIFFUSE_ALBEDO / PI);
    match material {
        Material::Lambert => lambert,
        Material::Conductor { roughness } => {
            ggx_pdf_and_bsdf(roughness * roughness, normal, -incoming, outgoing)
        }
        Material::Coated {
            roughness,
            coat_weight,
        } => {
            let coat = ggx_pdf_and_bsdf(roughness * roughness, normal, -incoming, outgoing);
            let base = 1.0 - coat_weight;
            (
                coat_weight * coat.0 + base * lambert.0,
                coat_weight * coat.1 + base * lambert.1,
            )
        }
    }
}

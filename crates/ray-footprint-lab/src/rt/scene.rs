//! The scenes, built in code: a large textured ground plane, a mirror sphere and a dense torus
//! (the gallery); a mirror saddle in a room; glass and rough spheres over the plane.
//!
//! Meshes are in world space (every instance transform is the identity), so the Rust side can
//! look up the exact vertices a hit refers to and recompute what the shaders computed.

use super::abi::{RtPushConstants, RtUniforms};
use super::mode::PATH_LOD_BIAS;
use glam::{Mat4, Vec2, Vec3, Vec4};
use ray_footprint::abi::{RayConePushConstants, WireframePushConstants};
use ray_footprint::ray_cone;
use ray_footprint::wireframe::WireframeSettings;
use std::f32::consts::{PI, TAU};

/// Floats per vertex in the vertex buffer: position xyz, u, normal xyz, v (the shaders' layout).
pub const VERTEX_FLOATS: usize = 8;

/// A mesh vertex.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Vertex {
    /// World-space position.
    pub position: Vec3,
    /// Unit vertex normal.
    pub normal: Vec3,
    /// Texture coordinates (the sampler repeats).
    pub uv: Vec2,
}

/// The material id ([`Material::id`]) of [`Material::Textured`].
pub const MATERIAL_TEXTURED: u32 = 0;
/// The material id ([`Material::id`]) of [`Material::Mirror`].
pub const MATERIAL_MIRROR: u32 = 1;
/// The material id ([`Material::id`]) of [`Material::Glass`].
pub const MATERIAL_GLASS: u32 = 2;

/// How a mesh is shaded. [`Material::id`] is one of the `MATERIAL_*` constants, which `cargo xtask
/// codegen` writes into the shaders as `RT_MATERIAL_*`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Material {
    /// Samples the texture at the mode's level of detail.
    Textured,
    /// A mirror: reflects primary rays (what it reflects is shaded as textured), carrying the
    /// propagated cone; reflects 90% of the light.
    Mirror {
        /// Perceptual roughness in `[0, 1]` (0: a perfect mirror). The `cone_roughness` mode widens
        /// the reflected cone by `2 * rf_roughness_spread_angle(roughness)`; under
        /// [`FLAG_GLOSSY_LOBE`](crate::rt::abi::FLAG_GLOSSY_LOBE) the reflection samples the GGX
        /// lobe of `alpha = roughness^2`.
        roughness: f32,
    },
    /// Clear glass: refracts every ray that reaches it up to the renderer's bounce limit (total
    /// internal reflection reflects it), passing all of the light on.
    Glass {
        /// Index of refraction (the medium outside is 1).
        index_of_refraction: f32,
    },
}

impl Material {
    /// A perfect mirror.
    pub const MIRROR: Material = Material::Mirror { roughness: 0.0 };

    /// The `MATERIAL_*` constant of the material's kind (`RT_MATERIAL_*` in the shaders).
    pub fn id(self) -> u32 {
        match self {
            Material::Textured => MATERIAL_TEXTURED,
            Material::Mirror { .. } => MATERIAL_MIRROR,
            Material::Glass { .. } => MATERIAL_GLASS,
        }
    }

    /// The material's parameter as the shaders read it: the roughness of a mirror, the index of
    /// refraction of glass, 0 for a textured surface.
    pub fn parameter(self) -> f32 {
        match self {
            Material::Textured => 0.0,
            Material::Mirror { roughness } => roughness,
            Material::Glass { index_of_refraction } => index_of_refraction,
        }
    }

    /// Whether the parameter is one the shaders take: a mirror's roughness finite in `[0, 1]`,
    /// glass's index of refraction finite and above 0 (the shaders divide by it); the field and
    /// its value where it is not.
    pub fn validate(self) -> Result<(), String> {
        match self {
            Material::Mirror { roughness } if !(0.0..=1.0).contains(&roughness) => {
                Err(format!("roughness {roughness} is not in [0, 1]"))
            }
            Material::Glass { index_of_refraction }
                if !(index_of_refraction.is_finite() && index_of_refraction > 0.0) =>
            {
                Err(format!(
                    "index_of_refraction {index_of_refraction} is not a finite number above 0"
                ))
            }
            _ => Ok(()),
        }
    }
}

/// Words per mesh in the shaders' mesh table ([`Scene::mesh_table`]).
pub const MESH_TABLE_WORDS: usize = 4;

/// An indexed triangle mesh.
#[derive(Clone, Debug)]
pub struct Mesh {
    /// What the mesh is, for messages.
    pub name: &'static str,
    /// Vertices.
    pub vertices: Vec<Vertex>,
    /// Three indices per triangle, into `vertices`.
    pub indices: Vec<u32>,
    /// How it is shaded.
    pub material: Material,
}

impl Mesh {
    /// Number of triangles.
    pub fn triangle_count(&self) -> usize {
        self.indices.len() / 3
    }

    /// The three vertices of triangle `primitive`.
    pub fn triangle(&self, primitive: u32) -> [Vertex; 3] {
        let first = 3 * primitive as usize;
        [0, 1, 2].map(|k| self.vertices[self.indices[first + k] as usize])
    }
}

/// A square in the plane y = 0, `2 * half_size` wide, normal +y, its texture repeating every
/// `repeat` world units.
pub fn ground_plane(half_size: f32, repeat: f32) -> Mesh {
    let corners = [(-1.0, -1.0), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)];
    let vertices = corners
        .iter()
        .map(|&(x, z)| {
            let position = Vec3::new(x * half_size, 0.0, z * half_size);
            Vertex {
                position,
                normal: Vec3::Y,
                uv: Vec2::new(position.x, position.z) / repeat,
            }
        })
        .collect();
    Mesh {
        name: "ground plane",
        vertices,
        indices: vec![0, 2, 1, 0, 3, 2],
        material: Material::Textured,
    }
}

/// Which diagonal splits each quad of a grid into its two triangles.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Diagonals {
    /// Every quad along the same diagonal, from the row's next vertex to the next row's vertex.
    Parallel,
    /// Neighbouring quads along crossing diagonals, as a checkerboard: a triangle's edges run
    /// along both diagonal directions across the grid, not only one.
    Alternating,
}

/// Triangles of a `rows` x `columns` grid of quads over `(rows + 1) * (columns + 1)` vertices,
/// split along `diagonals`, leaving out the triangles `skip` names (by row and whether it is the
/// quad's first triangle).
fn grid_indices(rows: u32, columns: u32, diagonals: Diagonals, skip: impl Fn(u32, bool) -> bool) -> Vec<u32> {
    let mut indices = Vec::new();
    for row in 0..rows {
        for column in 0..columns {
            let a = row * (columns + 1) + column;
            let b = a + columns + 1;
            let crossing = diagonals == Diagonals::Alternating && (row + column) % 2 == 1;
            let [first, second] = if crossing {
                [[a, b, b + 1], [a, b + 1, a + 1]]
            } else {
                [[a, b, a + 1], [a + 1, b, b + 1]]
            };
            if !skip(row, true) {
                indices.extend(first);
            }
            if !skip(row, false) {
                indices.extend(second);
            }
        }
    }
    indices
}

/// A latitude-longitude sphere with exact vertex normals and no zero-area triangles at the poles.
pub fn uv_sphere(centre: Vec3, radius: f32, rings: u32, segments: u32) -> Mesh {
    let mut vertices = Vec::new();
    for ring in 0..=rings {
        let theta = PI * ring as f32 / rings as f32;
        for segment in 0..=segments {
            let phi = TAU * segment as f32 / segments as f32;
            let normal = Vec3::new(theta.sin() * phi.cos(), theta.cos(), theta.sin() * phi.sin());
            vertices.push(Vertex {
                position: centre + radius * normal,
                normal,
                uv: Vec2::new(
                    4.0 * segment as f32 / segments as f32,
                    2.0 * ring as f32 / rings as f32,
                ),
            });
        }
    }
    let pole = |row: u32, first: bool| (row == 0 && first) || (row == rings - 1 && !first);
    Mesh {
        name: "sphere",
        vertices,
        indices: grid_indices(rings, segments, Diagonals::Parallel, pole),
        material: Material::MIRROR,
    }
}

/// A torus around the z axis through `centre`: tube radius `minor` around a circle of radius
/// `major`, `rings` x `segments` quads (two triangles each).
pub fn torus(centre: Vec3, major: f32, minor: f32, rings: u32, segments: u32) -> Mesh {
    let mut vertices = Vec::new();
    for ring in 0..=rings {
        let u = TAU * ring as f32 / rings as f32;
        let axis = Vec3::new(u.cos(), u.sin(), 0.0);
        for segment in 0..=segments {
            let v = TAU * segment as f32 / segments as f32;
            let normal = v.cos() * axis + v.sin() * Vec3::Z;
            vertices.push(Vertex {
                position: centre + major * axis + minor * normal,
                normal,
                uv: Vec2::new(
                    8.0 * ring as f32 / rings as f32,
                    2.0 * segment as f32 / segments as f32,
                ),
            });
        }
    }
    Mesh {
        name: "torus",
        vertices,
        indices: grid_indices(rings, segments, Diagonals::Parallel, |_, _| false),
        material: Material::Textured,
    }
}

/// A mirror hyperbolic paraboloid, the saddle `y = centre.y + curvature * x * z` with x and z
/// measured from the centre over a square of half side `half_size`: `quads` x `quads` quads (two
/// triangles each, split along `diagonals`) with exact vertex normals, proportional to
/// `(-curvature * z, 1, -curvature * x)`. Its mean curvature is 0 at the centre and its Gaussian
/// curvature negative everywhere (a saddle).
pub fn hyperbolic_paraboloid(
    centre: Vec3,
    half_size: f32,
    curvature: f32,
    quads: u32,
    diagonals: Diagonals,
) -> Mesh {
    let mut vertices = Vec::new();
    for row in 0..=quads {
        let z = half_size * (2.0 * row as f32 / quads as f32 - 1.0);
        for column in 0..=quads {
            let x = half_size * (2.0 * column as f32 / quads as f32 - 1.0);
            vertices.push(Vertex {
                position: centre + Vec3::new(x, curvature * x * z, z),
                normal: Vec3::new(-curvature * z, 1.0, -curvature * x).normalize(),
                uv: Vec2::new(x, z) / (2.0 * half_size) + 0.5,
            });
        }
    }
    Mesh {
        name: "hyperbolic paraboloid",
        vertices,
        indices: grid_indices(quads, quads, diagonals, |_, _| false),
        material: Material::MIRROR,
    }
}

/// The inside of a box from `min` to `max`: floor, ceiling and four walls, normals pointing in,
/// the texture repeating every `repeat` world units on each face.
pub fn room(min: Vec3, max: Vec3, repeat: f32) -> Mesh {
    // Each face: the axis of its normal, the side (min or max), and the two axes it spans.
    let faces = [
        (1, 0, 0, 2),
        (1, 1, 0, 2),
        (0, 0, 2, 1),
        (0, 1, 2, 1),
        (2, 0, 0, 1),
        (2, 1, 0, 1),
    ];
    let (mut vertices, mut indices) = (Vec::new(), Vec::new());
    for (normal_axis, side, u_axis, v_axis) in faces {
        let first = vertices.len() as u32;
        for (a, b) in [(0, 0), (1, 0), (1, 1), (0, 1)] {
            let mut position = min;
            position[normal_axis] = if side == 0 {
                min[normal_axis]
            } else {
                max[normal_axis]
            };
            position[u_axis] = if a == 0 { min[u_axis] } else { max[u_axis] };
            position[v_axis] = if b == 0 { min[v_axis] } else { max[v_axis] };
            let mut normal = Vec3::ZERO;
            normal[normal_axis] = if side == 0 { 1.0 } else { -1.0 };
            let uv = Vec2::new(position[u_axis], position[v_axis]) / repeat;
            vertices.push(Vertex { position, normal, uv });
        }
        indices.extend([first, first + 1, first + 2, first, first + 2, first + 3]);
    }
    Mesh {
        name: "room",
        vertices,
        indices,
        material: Material::Textured,
    }
}

/// The meshes of a scene; mesh `i` is TLAS instance `i` with instance custom index `i`.
#[derive(Clone, Debug)]
pub struct Scene {
    /// The meshes.
    pub meshes: Vec<Mesh>,
}

impl Scene {
    /// The gallery scene: a 400 x 400 ground plane whose texture repeats every 8 units, a mirror
    /// sphere of radius 1 (3,968 triangles) and a torus of 16,384
    /// triangles standing on the ground.
    pub fn gallery() -> Scene {
        Scene {
            meshes: vec![
                ground_plane(200.0, 8.0),
                uv_sphere(Vec3::new(1.3, 1.0, -1.5), 1.0, 32, 64),
                torus(Vec3::new(-1.5, 1.15, -2.5), 0.8, 0.3, 128, 64),
            ],
        }
    }

    /// The hyperbolic-paraboloid reflector of RTG ch. 20 (Fig. 20-10 and 20-11) in a textured
    /// room: a 4 x 4 saddle (`y = 1.2 + 0.35 x z`, 128 x 128 quads split along parallel
    /// diagonals, 32,768 triangles, exact normals) in a 12 x 6 x 12 room whose texture repeats
    /// every 3 units.
    pub fn paraboloid() -> Scene {
        Scene::paraboloid_split(Diagonals::Parallel)
    }

    /// [`Scene::paraboloid`] with its quads split along alternating diagonals: the same surface
    /// and normals at the vertices, other triangles, so that what a curvature estimate makes of
    /// one triangulation shows apart from what the method does.
    pub fn paraboloid_alternating() -> Scene {
        Scene::paraboloid_split(Diagonals::Alternating)
    }

    /// The paraboloid scene with the reflector's quads split along `diagonals`.
    fn paraboloid_split(diagonals: Diagonals) -> Scene {
        Scene {
            meshes: vec![
                room(Vec3::new(-6.0, 0.0, -6.0), Vec3::new(6.0, 6.0, 6.0), 8.0),
                hyperbolic_paraboloid(Vec3::new(0.0, 1.2, 0.0), 2.0, 0.35, 128, diagonals),
            ],
        }
    }

    /// The materials scene: the gallery's ground plane with a glass sphere of radius 1 (index of
    /// refraction [`GLASS_INDEX`], 3,968 triangles) standing left of the view axis and a rough
    /// mirror sphere (roughness [`ROUGHNESS`]) where the gallery's mirror stands.
    pub fn materials() -> Scene {
        let glass = Mesh {
            name: "glass sphere",
            material: Material::Glass {
                index_of_refraction: GLASS_INDEX,
            },
            ..uv_sphere(GLASS_CENTRE, GLASS_RADIUS, 32, 64)
        };
        let rough = Mesh {
            name: "rough sphere",
            material: Material::Mirror { roughness: ROUGHNESS },
            ..uv_sphere(Vec3::new(1.3, 1.0, -1.5), 1.0, 32, 64)
        };
        Scene {
            meshes: vec![ground_plane(200.0, 8.0), glass, rough],
        }
    }

    /// Every vertex of every mesh, [`VERTEX_FLOATS`] floats each, mesh after mesh.
    pub fn vertex_floats(&self) -> Vec<f32> {
        let vertices = self.meshes.iter().flat_map(|mesh| &mesh.vertices);
        vertices
            .flat_map(|v| {
                let (p, n) = (v.position, v.normal);
                [p.x, p.y, p.z, v.uv.x, n.x, n.y, n.z, v.uv.y]
            })
            .collect()
    }

    /// Every index of every mesh (relative to its mesh's first vertex), mesh after mesh.
    pub fn indices(&self) -> Vec<u32> {
        self.meshes
            .iter()
            .flat_map(|mesh| mesh.indices.iter().copied())
            .collect()
    }

    /// Per mesh, [`MESH_TABLE_WORDS`] words: its first index, its first vertex, its [`Material`]'s
    /// id and the bits of its parameter (the shaders' mesh table).
    pub fn mesh_table(&self) -> Vec<u32> {
        let (mut first_index, mut first_vertex) = (0, 0);
        let mut table = Vec::new();
        for mesh in &self.meshes {
            let material = mesh.material;
            table.extend([
                first_index,
                first_vertex,
                material.id(),
                material.parameter().to_bits(),
            ]);
            first_index += mesh.indices.len() as u32;
            first_vertex += mesh.vertices.len() as u32;
        }
        table
    }
}

/// Index of refraction of the glass sphere of [`Scene::materials`]: crown glass.
pub const GLASS_INDEX: f32 = 1.5;
/// Centre of the glass sphere of [`Scene::materials`].
pub const GLASS_CENTRE: Vec3 = Vec3::new(-1.3, 1.0, -1.5);
/// Radius of the glass sphere of [`Scene::materials`].
pub const GLASS_RADIUS: f32 = 1.0;
/// Roughness of the rough sphere of [`Scene::materials`]: a glossy reflection about 15 degrees
/// wide (`2 * rf_roughness_spread_angle(0.3)` = 0.256 rad).
pub const ROUGHNESS: f32 = 0.3;

#[cfg(test)]
mod tests {
    use super::{hyperbolic_paraboloid, Diagonals, Material, Mesh};
    use glam::Vec3;

    /// The quads' diagonals of a grid mesh: each triangle's edge whose ends differ in both row and
    /// column, as (lower index, higher index), sorted.
    fn diagonals(mesh: &Mesh, columns: u32) -> Vec<(u32, u32)> {
        let mut found: Vec<(u32, u32)> = mesh
            .indices
            .chunks(3)
            .flat_map(|t| [(t[0], t[1]), (t[1], t[2]), (t[2], t[0])])
            .map(|(i, j)| (i.min(j), i.max(j)))
            .filter(|&(i, j)| {
                i / (columns + 1) != j / (columns + 1) && i % (columns + 1) != j % (columns + 1)
            })
            .collect();
        found.sort_unstable();
        found.dedup();
        found
    }

    /// Both triangulations of the saddle cover the same quads with two triangles each, wound so
    /// that every face normal points the way of its vertex normals (up); with parallel diagonals
    /// every quad is split from its top-right to its bottom-left corner, with alternating ones
    /// half of them the other way, as a checkerboard.
    #[test]
    fn the_paraboloid_splits_its_quads_along_the_chosen_diagonals() {
        let quads = 4;
        let centre = Vec3::new(0.0, 1.2, 0.0);
        let parallel = hyperbolic_paraboloid(centre, 2.0, 0.35, quads, Diagonals::Parallel);
        let alternating = hyperbolic_paraboloid(centre, 2.0, 0.35, quads, Diagonals::Alternating);
        for mesh in [&parallel, &alternating] {
            assert_eq!(mesh.indices.len(), (quads * quads * 6) as usize);
            for t in mesh.indices.chunks(3) {
                let [p0, p1, p2] = [t[0], t[1], t[2]].map(|i| mesh.vertices[i as usize].position);
                let face = (p1 - p0).cross(p2 - p0);
                let normal = mesh.vertices[t[0] as usize].normal;
                assert!(
                    face.dot(normal) > 0.0,
                    "{t:?}: face {face}, vertex normal {normal}"
                );
            }
        }
        let rising = |&(i, j): &(u32, u32)| j - i == quads; // from (row, column + 1) to (row + 1, column)
        let parallel_diagonals = diagonals(&parallel, quads);
        let alternating_diagonals = diagonals(&alternating, quads);
        assert_eq!(parallel_diagonals.len(), (quads * quads) as usize);
        assert!(parallel_diagonals.iter().all(rising));
        assert_eq!(alternating_diagonals.len(), (quads * quads) as usize);
        assert_eq!(
            alternating_diagonals.iter().filter(|d| rising(d)).count(),
            (quads * quads / 2) as usize
        );
    }

    #[test]
    fn materials_out_of_range_name_the_field_and_value() {
        let bad = [
            (Material::Mirror { roughness: f32::NAN }, "roughness NaN"),
            (Material::Mirror { roughness: -0.1 }, "roughness -0.1"),
            (Material::Mirror { roughness: 1.5 }, "roughness 1.5"),
            (
                Material::Glass {
                    index_of_refraction: 0.0,
                },
                "index_of_refraction 0",
            ),
            (
                Material::Glass {
                    index_of_refraction: f32::INFINITY,
                },
                "index_of_refraction inf",
            ),
        ];
        for (material, start) in bad {
            let message = material.validate().expect_err("out of range");
            assert!(message.starts_with(start), "{material:?}: {message}");
        }
        let good = [
            Material::Textured,
            Material::MIRROR,
            Material::Mirror { roughness: 1.0 },
            Material::Glass {
                index_of_refraction: 1.5,
            },
        ];
        assert!(good.iter().all(|material| material.validate().is_ok()));
    }
}

/// Colour of the wireframe lines (RGBA): orange, visible on both checker colours.
pub const WIRE_COLOUR: Vec4 = Vec4::new(1.0, 0.45, 0.05, 1.0);

/// Near and far planes of the projection in [`Camera::uniforms`]. Only its inverse's directions
/// are used, which do not depend on them.
const CLIP_PLANES: (f32, f32) = (0.01, 1000.0);

/// A pinhole camera.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Camera {
    /// Position.
    pub eye: Vec3,
    /// A point it looks at.
    pub target: Vec3,
    /// Vertical field of view in radians.
    pub fov_y: f32,
}

impl Camera {
    /// Eye height 1 over the ground plane, looking almost level, so the plane recedes to a
    /// grazing horizon; the sphere and the torus stand in front.
    pub fn ground() -> Camera {
        Camera {
            eye: Vec3::new(0.0, 1.0, 4.0),
            target: Vec3::new(0.0, 0.55, -6.0),
            fov_y: 50f32.to_radians(),
        }
    }

    /// Close to the mirror sphere, which fills most of the view and reflects the ground plane
    /// out to its horizon.
    pub fn reflection() -> Camera {
        Camera {
            eye: Vec3::new(1.3, 1.35, 1.2),
            target: Vec3::new(1.3, 0.95, -1.5),
            fov_y: 45f32.to_radians(),
        }
    }

    /// A narrow view of the top of the torus, its silhouette against the ground and the sky in
    /// the upper part: its quads are about 30 pixels wide in a 480 x 270 image (the wireframe view).
    pub fn torus() -> Camera {
        Camera {
            eye: Vec3::new(-1.1, 2.25, -1.65),
            target: Vec3::new(-1.5, 2.17, -2.5),
            fov_y: 16f32.to_radians(),
        }
    }

    /// Above and in front of the hyperbolic paraboloid of [`Scene::paraboloid`], looking down at
    /// it: the saddle fills the middle of the view and reflects the room's walls and ceiling.
    pub fn paraboloid() -> Camera {
        Camera {
            eye: Vec3::new(2.9, 4.6, 2.9),
            target: Vec3::new(0.0, 1.0, 0.0),
            fov_y: 45f32.to_radians(),
        }
    }

    /// Close to the glass sphere of [`Scene::materials`], which fills most of the view: through
    /// it the ground plane behind, upside down.
    pub fn glass() -> Camera {
        Camera {
            eye: Vec3::new(-1.3, 1.35, 1.2),
            target: Vec3::new(-1.3, 0.95, -1.5),
            fov_y: 45f32.to_radians(),
        }
    }

    /// Both spheres of [`Scene::materials`] side by side over the ground plane.
    pub fn materials() -> Camera {
        Camera {
            eye: Vec3::new(0.0, 1.6, 3.6),
            target: Vec3::new(0.0, 0.8, -1.5),
            fov_y: 45f32.to_radians(),
        }
    }

    /// The orthonormal basis: forward (viewing direction), right (= forward x +y) and up.
    fn basis(&self) -> (Vec3, Vec3, Vec3) {
        let forward = (self.target - self.eye).normalize();
        let right = forward.cross(Vec3::Y).normalize();
        (forward, right, right.cross(forward))
    }

    /// The renderer's push constants for this camera: orthonormal basis (right = forward x +y),
    /// and the exact pixel spread angle (RTG Eq. 30) for an image `height` pixels tall.
    pub fn push_constants(
        &self,
        mode: u32,
        tex_grad_scale: f32,
        view: (u32, u32),
        texture_size: u32,
    ) -> RtPushConstants {
        let (width, height) = view;
        let (forward, right, up) = self.basis();
        RtPushConstants {
            eye: self.eye,
            tan_half_fov_y: (0.5 * self.fov_y).tan(),
            right,
            aspect: width as f32 / height as f32,
            up,
            texture_size: texture_size as f32,
            forward,
            mode,
            cone: RayConePushConstants {
                tex_grad_scale,
                pixel_spread_angle: ray_cone::pixel_spread_angle(self.fov_y, height as f32),
            },
            width,
            height,
            pixel_offset: Vec2::ZERO,
            flags: 0,
            lod_bias: PATH_LOD_BIAS,
        }
    }

    /// The renderer's per-frame uniforms for this camera on a `view` = (width, height) image:
    /// the camera-to-world matrix of the same basis (the view axis points back to the camera),
    /// the inverse of a Vulkan-style (y-down) perspective projection with the same field of view
    /// and aspect ratio, so the matrix functions of `ray_diff` see the rays the renderer traces;
    /// and the wireframe `settings` in [`WIRE_COLOUR`].
    pub fn uniforms(&self, view: (u32, u32), settings: WireframeSettings) -> RtUniforms {
        let (forward, right, up) = self.basis();
        let view_inv = Mat4::from_cols(
            right.extend(0.0),
            up.extend(0.0),
            (-forward).extend(0.0),
            self.eye.extend(1.0),
        );
        let aspect = view.0 as f32 / view.1 as f32;
        let (near, far) = CLIP_PLANES;
        let projection = glam::camera::rh::proj::vulkan::perspective(self.fov_y, aspect, near, far);
        RtUniforms {
            view_inv,
            proj_inv: projection.inverse(),
            wireframe: WireframePushConstants {
                colour: WIRE_COLOUR,
                settings: settings.pack(),
            },
        }
    }
}

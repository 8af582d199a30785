//! Analytic scenes for the path measurement: infinite planes and spheres (whole, or a cap of one),
//! each with a material and the fixed axis its shading frame is built against, and the pinhole
//! camera that looks at them.
//!
//! Stored normals and curvatures follow `ray_footprint::ray_cone::curvature_spread_angle`: a
//! curvature is positive where the surface bends away from the side its stored normals point to,
//! so a sphere with outward normals has `1 / R` and the same sphere with inward normals `-1 / R`
//! (stored normal and curvature flip together); a plane has 0.

use glam::DVec3;

/// Vertical field of view of every scene's camera, in degrees.
pub const FOV_Y_DEGREES: f64 = 60.0;

/// The albedo of every Lambert surface (it only enters the BSDF value the OptiX Toolkit's rule
/// reads, whose `min(1, 1 / (pi f_s))` is 1 for any Lambert albedo up to 1).
pub const DIFFUSE_ALBEDO: f64 = 0.8;

/// A pinhole camera: an image `width` x `height` pixels with the vertical field of view
/// `2 atan(tan_half_fov_y)`, pixel positions continuous from `(0, 0)` at the top left corner.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Camera {
    /// The eye.
    pub position: DVec3,
    /// Unit viewing direction (the view axis).
    pub forward: DVec3,
    /// Unit direction of increasing `x` on the image.
    pub right: DVec3,
    /// Unit direction of decreasing `y` on the image.
    pub up: DVec3,
    /// `tan(fov_y / 2)`.
    pub tan_half_fov_y: f64,
    /// Image width in pixels.
    pub width: f64,
    /// Image height in pixels.
    pub height: f64,
}

impl Camera {
    /// The camera at `position` looking at `target`, its image's up as close to `up_hint` as the
    /// view allows, with the vertical field of view [`FOV_Y_DEGREES`] and `size = (width, height)`
    /// pixels.
    pub fn looking_at(position: DVec3, target: DVec3, up_hint: DVec3, size: (u32, u32)) -> Camera {
        let forward = (target - position).normalize();
        let right = forward.cross(up_hint).normalize();
        Camera {
            position,
            forward,
            right,
            up: right.cross(forward),
            tan_half_fov_y: (0.5 * FOV_Y_DEGREES.to_radians()).tan(),
            width: f64::from(size.0),
            height: f64::from(size.1),
        }
    }

    /// The vertical field of view in radians.
    pub fn fov_y(&self) -> f64 {
        2.0 * self.tan_half_fov_y.atan()
    }

    /// The direction through the image position `(x, y)` before normalisation:
    /// `forward + u right + v up` with `u = (2 x / W - 1) (W / H) tan(fov_y / 2)` and
    /// `v = (1 - 2 y / H) tan(fov_y / 2)`, so that one pixel step moves it by
    /// `2 tan(fov_y / 2) / H` along `right` or `-up`.
    pub fn unnormalized_direction(&self, x: f64, y: f64) -> DVec3 {
        let across = (2.0 * x / self.width - 1.0) * (self.width / self.height) * self.tan_half_fov_y;
        let upward = (1.0 - 2.0 * y / self.height) * self.tan_half_fov_y;
        self.forward + across * self.right + upward * self.up
    }

    /// The unit direction through the image position `(x, y)`.
    pub fn direction(&self, x: f64, y: f64) -> DVec3 {
        self.unnormalized_direction(x, y).normalize()
    }

    /// `2 tan(fov_y / 2) / H`: how far one pixel step moves [`Camera::unnormalized_direction`].
    pub fn pixel_tan(&self) -> f64 {
        2.0 * self.tan_half_fov_y / self.height
    }
}

/// The part of a sphere a [`Shape::Sphere`] keeps: the points `p` with
/// `dot(p - centre, axis) >= min_cos * radius`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Cap {
    /// Unit axis of the cap, from the centre.
    pub axis: DVec3,
    /// Cosine of the cap's half angle.
    pub min_cos: f64,
}

/// An analytic surface.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Shape {
    /// An infinite plane through `point`; `normal` (unit) is its stored normal.
    Plane {
        /// A point of the plane.
        point: DVec3,
        /// The stored unit normal.
        normal: DVec3,
    },
    /// A sphere, or a cap of one. Its stored normals point outward, or inward with `inward`.
    Sphere {
        /// The centre.
        centre: DVec3,
        /// The radius.
        radius: f64,
        /// Whether the stored normals point inward (then the curvature is `-1 / radius`).
        inward: bool,
        /// The part kept, or the whole sphere.
        cap: Option<Cap>,
    },
}

impl Shape {
    /// Distance along the unit `direction` from `origin` to the shape's nearest point ahead, or
    /// `None`. `leaving` says the ray starts on this shape: a plane is then never met again, and a
    /// sphere's root at the origin (within `1e-9` radii) is skipped.
    pub fn distance(&self, origin: DVec3, direction: DVec3, leaving: bool) -> Option<f64> {
        match *self {
            Shape::Plane { point, normal } => plane_distance(point, normal, origin, direction, leaving),
            Shape::Sphere {
                centre, radius, cap, ..
            } => sphere_distance(centre, radius, cap, origin, direction, leaving),
        }
    }

    /// The stored unit normal at the point `p` of the shape.
    pub fn normal_at(&self, p: DVec3) -> DVec3 {
        match *self {
            Shape::Plane { normal, .. } => normal,
            Shape::Sphere {
                centre,
                radius,
                inward,
                ..
            } => {
                let outward = (p - centre) / radius;
                if inward {
                    -outward
                } else {
                    outward
                }
            }
        }
    }

    /// The curvature that goes with the stored normals: 0 for a plane, `1 / R` for a sphere with
    /// outward normals, `-1 / R` with inward ones.
    pub fn curvature(&self) -> f64 {
        match *self {
            Shape::Plane { .. } => 0.0,
            Shape::Sphere { radius, inward, .. } => {
                if inward {
                    -1.0 / radius
                } else {
                    1.0 / radius
                }
            }
        }
    }
}

/// `t = dot(point - origin, normal) / dot(direction, normal)` where positive.
fn plane_distance(
    point: DVec3,
    normal: DVec3,
    origin: DVec3,
    direction: DVec3,
    leaving: bool,
) -> Option<f64> {
    let facing = direction.dot(normal);
    if leaving || facing == 0.0 {
        return None;
    }
    let t = (point - origin).dot(normal) / facing;
    (t > 0.0).then_some(t)
}

/// The nearer root of `|origin + t direction - centre| = radius` beyond the start (`1e-9` radii
/// when `leaving`) whose point lies on the cap, else the farther one.
fn sphere_distance(
    centre: DVec3,
    radius: f64,
    cap: Option<Cap>,
    origin: DVec3,
    direction: DVec3,
    leaving: bool,
) -> Option<f64> {
    let offset = origin - centre;
    let half_b = offset.dot(direction);
    let discriminant = half_b * half_b - (offset.length_squared() - radius * radius);
    if discriminant < 0.0 {
        return None;
    }
    let root = discriminant.sqrt();
    let start = if leaving { 1e-9 * radius } else { 0.0 };
    let on_cap =
        |t: f64| cap.is_none_or(|cap| (offset + t * direction).dot(cap.axis) >= cap.min_cos * radius);
    [-half_b - root, -half_b + root]
        .into_iter()
        .find(|&t| t > start && on_cap(t))
}

/// What a surface scatters with.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Material {
    /// Lambert's diffuse reflector of albedo [`DIFFUSE_ALBEDO`].
    Lambert,
    /// A GGX conductor (Fresnel 1) of perceptual roughness `roughness`, `alpha = roughness^2`;
    /// roughness 0 is a mirror.
    Conductor {
        /// Perceptual roughness.
        roughness: f64,
    },
    /// A GGX coat of perceptual roughness `roughness` over a Lambert base: the coat's lobe is
    /// sampled with probability `coat_weight`, the base's otherwise, and the BSDF is
    /// `coat_weight f_ggx + (1 - coat_weight) f_lambert`.
    Coated {
        /// Perceptual roughness of the coat.
        roughness: f64,
        /// Probability (and weight) of the coat's lobe.
        coat_weight: f64,
    },
}

/// A shape with its material and the fixed world axis its shading frame is built against.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Surface {
    /// The geometry.
    pub shape: Shape,
    /// The material.
    pub material: Material,
    /// The unit world axis the tangent is taken from by Gram-Schmidt ([`super::sampling::shading_frame`]):
    /// one per surface, so that the frame turns smoothly with the normal across it. A plane takes
    /// the world axis least aligned with its normal; a sphere takes one whose poles (where the
    /// frame is undefined) lie where the camera sees the sphere edge on or not at all.
    pub frame_axis: DVec3,
}

impl Surface {
    /// An infinite plane through `point` with the stored unit normal `normal`.
    pub fn plane(point: DVec3, normal: DVec3, material: Material) -> Surface {
        Surface {
            shape: Shape::Plane {
                point,
                normal: normal.normalize(),
            },
            material,
            frame_axis: least_aligned_axis(normal),
        }
    }

    /// A whole sphere, stored normals outward or `inward`, its frame built against `frame_axis`.
    pub fn sphere(
        centre: DVec3,
        radius: f64,
        inward: bool,
        material: Material,
        frame_axis: DVec3,
    ) -> Surface {
        Surface {
            shape: Shape::Sphere {
                centre,
                radius,
                inward,
                cap: None,
            },
            material,
            frame_axis: frame_axis.normalize(),
        }
    }

    /// This sphere cut to the cap around the unit `axis` with the half angle `half_angle_degrees`.
    pub fn with_cap(mut self, axis: DVec3, half_angle_degrees: f64) -> Surface {
        if let Shape::Sphere { cap, .. } = &mut self.shape {
            *cap = Some(Cap {
                axis: axis.normalize(),
                min_cos: half_angle_degrees.to_radians().cos(),
            });
        }
        self
    }
}

/// Metres one repeat of the texture spans on every surface (texture coordinates in repeats).
pub const TEXTURE_REPEAT_METRES: f64 = 2.0;

impl Surface {
    /// The texture coordinates `(u, v)` of the point `p` of the surface, in texture repeats
    /// (wrapped by the sampler), about [`TEXTURE_REPEAT_METRES`] metres per repeat: on a plane the
    /// planar projection `((p - point) . t, (p - point) . b) / repeat` onto its frame
    /// (`t` from `frame_axis` by Gram-Schmidt, `b = n x t`); on a sphere the spherical angles about
    /// `frame_axis` as pole, `u = n_u phi / (2 pi)`, `v = n_v theta / pi` with
    /// `n_u = round(2 pi R / repeat)` and `n_v = round(pi R / repeat)` (at least 1) whole repeats,
    /// so that the density is `1 / repeat` per metre along a meridian and on the equator.
    pub fn texture_coordinates(&self, p: DVec3) -> (f64, f64) {
        match self.shape {
            Shape::Plane { point, normal } => {
                let tangent = (self.frame_axis - normal * normal.dot(self.frame_axis)).normalize();
                let offset = p - point;
                let repeats = |axis: DVec3| offset.dot(axis) / TEXTURE_REPEAT_METRES;
                (repeats(tangent), repeats(normal.cross(tangent)))
            }
            Shape::Sphere { centre, radius, .. } => {
                let pole = self.frame_axis;
                let first =
                    (least_aligned_axis(pole) - pole * pole.dot(least_aligned_axis(pole))).normalize();
                let local = (p - centre) / radius;
                let phi = local.dot(pole.cross(first)).atan2(local.dot(first));
                let theta = local.dot(pole).clamp(-1.0, 1.0).acos();
                let whole = |arc: f64| (arc * radius / TEXTURE_REPEAT_METRES).round().max(1.0);
                let tau = std::f64::consts::TAU;
                (
                    whole(tau) * phi / tau,
                    whole(std::f64::consts::PI) * theta / std::f64::consts::PI,
                )
            }
        }
    }
}

/// The world axis (x, y or z) with the smallest `|component|` of `normal`.
fn least_aligned_axis(normal: DVec3) -> DVec3 {
    let size = normal.abs();
    if size.x <= size.y && size.x <= size.z {
        DVec3::X
    } else if size.y <= size.z {
        DVec3::Y
    } else {
        DVec3::Z
    }
}

/// The closest surface a ray meets.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Hit {
    /// Index of the surface in [`Scene::surfaces`].
    pub surface: usize,
    /// Distance along the unit direction.
    pub distance: f64,
}

/// A scene: its surfaces and where its camera stands.
#[derive(Clone, Debug, PartialEq)]
pub struct Scene {
    /// Short name.
    pub name: &'static str,
    /// One line on what it holds.
    pub description: &'static str,
    /// The eye.
    pub eye: DVec3,
    /// The point the camera looks at.
    pub target: DVec3,
    /// The image's up, as nearly as the view allows.
    pub up_hint: DVec3,
    /// The surfaces.
    pub surfaces: Vec<Surface>,
}

impl Scene {
    /// The scene's camera for an image of `size = (width, height)` pixels.
    pub fn camera(&self, size: (u32, u32)) -> Camera {
        Camera::looking_at(self.eye, self.target, self.up_hint, size)
    }

    /// The nearest surface along the unit `direction` from `origin`; `leaving` names the surface
    /// the ray starts on.
    pub fn closest_hit(&self, origin: DVec3, direction: DVec3, leaving: Option<usize>) -> Option<Hit> {
        let mut closest: Option<Hit> = None;
        for (index, surface) in self.surfaces.iter().enumerate() {
            let Some(distance) = surface.shape.distance(origin, direction, leaving == Some(index)) else {
                continue;
            };
            if closest.is_none_or(|hit| distance < hit.distance) {
                closest = Some(Hit {
                    surface: index,
                    distance,
                });
            }
        }
        closest
    }
}

/// The measured scenes, in the order the report prints them.
pub fn scenes() -> Vec<Scene> {
    vec![
        glossy_floor(),
        concave_mirror(),
        diffuse_corner(),
        glossy_sphere(),
        rough_room(),
        mixed(),
        roughness_sweep(),
        facing_mirrors(),
        glossy_dome(),
        small_mirror_ball(),
    ]
}

/// The scenes a command line's `--scene` names: every scene for `all`, else the one named, or the
/// message that names the unknown scene.
pub fn scenes_named(name: &str) -> Result<Vec<Scene>, String> {
    if name == "all" {
        return Ok(scenes());
    }
    let scene = scenes().into_iter().find(|scene| scene.name == name);
    Ok(vec![scene.ok_or_else(|| format!("unknown scene '{name}'"))?])
}

/// Shorthand for a point or direction.
fn v(x: f64, y: f64, z: f64) -> DVec3 {
    DVec3::new(x, y, z)
}

/// The frame axis of a ball seen from `eye`: horizontal and across the line of sight to its
/// `centre`, so that the poles of its frame lie on its left and right silhouette.
fn silhouette_axis(eye: DVec3, centre: DVec3) -> DVec3 {
    (centre - eye).cross(DVec3::Y).normalize()
}

/// A GGX floor (r = 0.2) under a camera pitched 37 degrees down, so that it fills the view, and a
/// diffuse wall 14 m ahead that only its reflection shows.
fn glossy_floor() -> Scene {
    Scene {
        name: "glossy_floor",
        description: "GGX floor (r = 0.2) reflecting a diffuse wall that is seen only in the floor",
        eye: v(0.0, 1.5, 0.0),
        target: v(0.0, 0.0, -2.0),
        up_hint: DVec3::Y,
        surfaces: vec![
            Surface::plane(DVec3::ZERO, DVec3::Y, Material::Conductor { roughness: 0.2 }),
            Surface::plane(v(0.0, 0.0, -14.0), DVec3::Z, Material::Lambert),
        ],
    }
}

/// A spherical bowl of radius 4 (a 50-degree cap, GGX r = 0.05) seen from inside, 5 m ahead,
/// stored normals inward (curvature -1/4); it images the diffuse wall behind the camera, with a
/// diffuse floor below.
fn concave_mirror() -> Scene {
    let bowl = Surface::sphere(
        v(0.0, 1.5, 0.0),
        4.0,
        true,
        Material::Conductor { roughness: 0.05 },
        DVec3::X,
    )
    .with_cap(-DVec3::Z, 50.0);
    Scene {
        name: "concave_mirror",
        description: "concave glossy bowl (GGX r = 0.05, R = 4, inward normals) imaging the diffuse \
                      wall behind the camera",
        eye: v(0.0, 1.5, 1.0),
        target: v(0.0, 1.5, -4.0),
        up_hint: DVec3::Y,
        surfaces: vec![
            bowl,
            Surface::plane(v(0.0, -1.0, 0.0), DVec3::Y, Material::Lambert),
            Surface::plane(v(0.0, 0.0, 3.0), -DVec3::Z, Material::Lambert),
        ],
    }
}

/// Three diffuse planes meeting in a corner, looked into.
fn diffuse_corner() -> Scene {
    Scene {
        name: "diffuse_corner",
        description: "three diffuse planes (floor and two walls) meeting in a corner",
        eye: v(2.0, 1.6, 3.0),
        target: v(-1.0, 0.6, -2.0),
        up_hint: DVec3::Y,
        surfaces: vec![
            Surface::plane(DVec3::ZERO, DVec3::Y, Material::Lambert),
            Surface::plane(v(-2.0, 0.0, 0.0), DVec3::X, Material::Lambert),
            Surface::plane(v(0.0, 0.0, -3.0), DVec3::Z, Material::Lambert),
        ],
    }
}

/// A convex GGX ball (r = 0.15, R = 1) on a diffuse floor before a diffuse wall.
fn glossy_sphere() -> Scene {
    let (eye, centre) = (v(0.0, 1.4, 1.0), v(0.0, 1.0, -3.0));
    Scene {
        name: "glossy_sphere",
        description: "convex GGX sphere (r = 0.15, R = 1) on a diffuse floor, diffuse wall behind",
        eye,
        target: v(0.0, 0.9, -3.0),
        up_hint: DVec3::Y,
        surfaces: vec![
            Surface::sphere(
                centre,
                1.0,
                false,
                Material::Conductor { roughness: 0.15 },
                silhouette_axis(eye, centre),
            ),
            Surface::plane(DVec3::ZERO, DVec3::Y, Material::Lambert),
            Surface::plane(v(0.0, 0.0, -6.0), DVec3::Z, Material::Lambert),
        ],
    }
}

/// A closed box room 6 x 3 x 8 m, every face a GGX conductor of roughness 0.5.
fn rough_room() -> Scene {
    let rough = Material::Conductor { roughness: 0.5 };
    Scene {
        name: "rough_room",
        description: "closed room (6 x 3 x 8 m), every face a rough GGX conductor (r = 0.5)",
        eye: v(0.0, 1.5, 1.5),
        target: v(0.5, 1.2, -6.0),
        up_hint: DVec3::Y,
        surfaces: vec![
            Surface::plane(DVec3::ZERO, DVec3::Y, rough),
            Surface::plane(v(0.0, 3.0, 0.0), -DVec3::Y, rough),
            Surface::plane(v(-3.0, 0.0, 0.0), DVec3::X, rough),
            Surface::plane(v(3.0, 0.0, 0.0), -DVec3::X, rough),
            Surface::plane(v(0.0, 0.0, -6.0), DVec3::Z, rough),
            Surface::plane(v(0.0, 0.0, 2.0), -DVec3::Z, rough),
        ],
    }
}

/// Every material at once: a coated floor and back wall, a near-mirror side wall, a glossy and a
/// diffuse ball.
fn mixed() -> Scene {
    let eye = v(0.0, 1.5, 1.5);
    let (glossy_centre, diffuse_centre) = (v(-1.0, 0.8, -3.0), v(1.2, 0.6, -2.5));
    Scene {
        name: "mixed",
        description: "coated floor (r = 0.1 over Lambert) and wall (r = 0.25), near-mirror side wall \
                      (r = 0.05), GGX ball (r = 0.3), diffuse ball",
        eye,
        target: v(0.0, 0.8, -3.0),
        up_hint: DVec3::Y,
        surfaces: vec![
            Surface::plane(
                DVec3::ZERO,
                DVec3::Y,
                Material::Coated {
                    roughness: 0.1,
                    coat_weight: 0.4,
                },
            ),
            Surface::plane(
                v(0.0, 0.0, -6.0),
                DVec3::Z,
                Material::Coated {
                    roughness: 0.25,
                    coat_weight: 0.5,
                },
            ),
            Surface::plane(
                v(-3.5, 0.0, 0.0),
                DVec3::X,
                Material::Conductor { roughness: 0.05 },
            ),
            Surface::sphere(
                glossy_centre,
                0.8,
                false,
                Material::Conductor { roughness: 0.3 },
                silhouette_axis(eye, glossy_centre),
            ),
            Surface::sphere(
                diffuse_centre,
                0.6,
                false,
                Material::Lambert,
                silhouette_axis(eye, diffuse_centre),
            ),
        ],
    }
}

/// Four GGX balls of roughness 0.05, 0.1, 0.3 and 0.6 in a row on a diffuse floor before a diffuse
/// wall.
fn roughness_sweep() -> Scene {
    let eye = v(0.0, 1.3, 1.5);
    let mut surfaces: Vec<Surface> = [0.05, 0.1, 0.3, 0.6]
        .into_iter()
        .enumerate()
        .map(|(i, roughness)| {
            let centre = v(-2.4 + 1.6 * i as f64, 0.7, -3.5);
            let material = Material::Conductor { roughness };
            Surface::sphere(centre, 0.7, false, material, silhouette_axis(eye, centre))
        })
        .collect();
    surfaces.push(Surface::plane(DVec3::ZERO, DVec3::Y, Material::Lambert));
    surfaces.push(Surface::plane(v(0.0, 0.0, -7.0), DVec3::Z, Material::Lambert));
    Scene {
        name: "roughness_sweep",
        description:
            "four convex GGX spheres (r = 0.05, 0.1, 0.3, 0.6) on a diffuse floor, diffuse wall behind",
        eye,
        target: v(0.0, 0.7, -3.5),
        up_hint: DVec3::Y,
        surfaces,
    }
}

/// Two GGX walls (r = 0.1) 3 m apart facing each other over a diffuse floor, a diffuse wall at the
/// end of the corridor; the camera looks into the left wall at a slant, so that paths cross the
/// corridor several times before they meet the texture of the floor or the end wall. Each wall is
/// a disc of radius 6 m centred on the floor, a cap of a sphere of radius 1000 m (curvature 1e-3,
/// nearly flat), so that light comes in from above: two infinite planes would close the corridor.
fn facing_mirrors() -> Scene {
    let glossy = Material::Conductor { roughness: 0.1 };
    let wall = |side: f64| {
        let centre = v(side * (1.5 + WALL_RADIUS), 0.0, -4.0);
        Surface::sphere(centre, WALL_RADIUS, false, glossy, DVec3::Y)
            .with_cap(v(-side, 0.0, 0.0), (6.0 / WALL_RADIUS).asin().to_degrees())
    };
    Scene {
        name: "facing_mirrors",
        description: "two facing GGX walls (r = 0.1, discs of radius 6 m) 3 m apart over a diffuse \
                      floor, diffuse wall at the corridor's end: several glossy bounces before the texture",
        eye: v(0.8, 1.6, 2.0),
        target: v(-1.5, 1.2, -2.5),
        up_hint: DVec3::Y,
        surfaces: vec![
            wall(-1.0),
            wall(1.0),
            Surface::plane(DVec3::ZERO, DVec3::Y, Material::Lambert),
            Surface::plane(v(0.0, 0.0, -12.0), DVec3::Z, Material::Lambert),
        ],
    }
}

/// The radius of the spheres whose caps make [`facing_mirrors`]' nearly flat walls.
const WALL_RADIUS: f64 = 1000.0;

/// A GGX dome (r = 0.2, R = 4, inward normals: curvature -1/4) over a diffuse floor, seen from
/// inside: an 80-degree cap around +Y whose frame poles (on the X axis) lie outside it.
fn glossy_dome() -> Scene {
    let dome = Surface::sphere(
        DVec3::ZERO,
        4.0,
        true,
        Material::Conductor { roughness: 0.2 },
        DVec3::X,
    )
    .with_cap(DVec3::Y, 80.0);
    Scene {
        name: "glossy_dome",
        description: "inside a concave GGX dome (r = 0.2, R = 4, inward normals) over a diffuse floor",
        eye: v(0.0, 1.5, 2.0),
        target: v(0.0, 2.8, -2.0),
        up_hint: DVec3::Y,
        surfaces: vec![dome, Surface::plane(DVec3::ZERO, DVec3::Y, Material::Lambert)],
    }
}

/// A small convex near-mirror (GGX r = 0.05, R = 0.5) on a diffuse floor before a diffuse wall:
/// the strongest positive curvature, which spreads the cone most.
fn small_mirror_ball() -> Scene {
    let (eye, centre) = (v(0.0, 1.0, 0.0), v(0.0, 0.5, -2.0));
    Scene {
        name: "small_mirror_ball",
        description: "small convex near-mirror ball (GGX r = 0.05, R = 0.5) on a diffuse floor, diffuse \
                      wall behind",
        eye,
        target: centre,
        up_hint: DVec3::Y,
        surfaces: vec![
            Surface::sphere(
                centre,
                0.5,
                false,
                Material::Conductor { roughness: 0.05 },
                silhouette_axis(eye, centre),
            ),
            Surface::plane(DVec3::ZERO, DVec3::Y, Material::Lambert),
            Surface::plane(v(0.0, 0.0, -5.0), DVec3::Z, Material::Lambert),
        ],
    }
}

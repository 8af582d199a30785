//! The lab's scenes, built in code, and the methods each is rendered with.

use crate::rt::abi::{RtPixelRecord, FLAG_GLOSSY_LOBE};
use crate::rt::{checker, two_scale_checker, Camera, MipChain, Mode, Scene, CHECKER_SQUARE, TEXTURE_SIZE};
use glam::Vec3;
use ray_footprint::wireframe::WireframeSettings;

/// Fine checker square of the ground plane's two-scale texture, in texels: level 3 averages it
/// away.
pub const FINE_CHECKER_SQUARE: u32 = 4;
/// Distance from the eye beyond which the ground plane's pixels form the plane scene's mask.
pub const PLANE_MASK_DISTANCE: f32 = 3.0;
/// Vertical field of view of the corners scene, degrees: 100 vertical is about 121 across a 3:2
/// image, and the image's corners lie about 65 degrees off the view axis.
pub const CORNERS_FOV_Y_DEGREES: f32 = 100.0;
/// Angle off the view axis beyond which the corners scene's ground-plane pixels form its mask,
/// degrees.
pub const CORNERS_MASK_DEGREES: f32 = 45.0;

/// What a scene measures.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Measure {
    /// Texture filtering: every texture-filtering mode against mip 0 supersampled.
    Texture,
    /// Wireframe coverage: the anti-aliased lines of a preset against the same lines drawn
    /// hard and supersampled, and drawn hard at one sample per pixel.
    Wireframe {
        /// The preset's name.
        preset: &'static str,
        /// Its settings.
        settings: WireframeSettings,
    },
}

/// The pixels a scene's second PSNR is taken over, from the primary hits of a frame.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Mask {
    /// Pixels whose primary ray hits mesh `mesh` (an index into the scene's meshes).
    Mesh(u32),
    /// Pixels whose primary ray hits mesh `mesh` farther than `distance` from the eye.
    MeshBeyond {
        /// The mesh.
        mesh: u32,
        /// Distance from the eye.
        distance: f32,
    },
    /// Pixels whose primary ray hits mesh `mesh` and leaves the eye more than `degrees` off the
    /// view axis `axis` (unit length).
    MeshOffAxis {
        /// The mesh.
        mesh: u32,
        /// The camera's view axis.
        axis: Vec3,
        /// Least angle between the ray and the axis, degrees.
        degrees: f32,
    },
}

impl Mask {
    /// Whether the pixel of `record` is in the mask.
    pub fn contains(&self, record: &RtPixelRecord) -> bool {
        match *self {
            Mask::Mesh(mesh) => record.hit == 1 && record.instance == mesh,
            Mask::MeshBeyond { mesh, distance } => {
                record.hit == 1 && record.instance == mesh && record.t > distance
            }
            Mask::MeshOffAxis { mesh, axis, degrees } => {
                let cosine = record.direction.normalize_or_zero().dot(axis);
                record.hit == 1 && record.instance == mesh && cosine < degrees.to_radians().cos()
            }
        }
    }

    /// What the mask holds, in words.
    pub fn describe(&self, scene: &Scene) -> String {
        let name = |mesh: u32| scene.meshes.get(mesh as usize).map_or("?", |m| m.name);
        match *self {
            Mask::Mesh(mesh) => format!("the {}", name(mesh)),
            Mask::MeshBeyond { mesh, distance } => format!("the {} beyond {distance} units", name(mesh)),
            Mask::MeshOffAxis { mesh, degrees, .. } => {
                format!("the {} more than {degrees} degrees off the view axis", name(mesh))
            }
        }
    }
}

/// A scene of the lab: geometry, texture, view, mask and what it measures.
#[derive(Clone, Debug)]
pub struct LabScene {
    /// Short name (file names, table rows).
    pub name: &'static str,
    /// One line saying what it shows.
    pub description: &'static str,
    /// The meshes.
    pub scene: Scene,
    /// The texture of every textured mesh.
    pub texture: MipChain,
    /// The view.
    pub camera: Camera,
    /// The pixels that matter.
    pub mask: Mask,
    /// What it measures.
    pub measure: Measure,
    /// The part shown in the side-by-side crops: left, top, width and height as fractions of
    /// the image.
    pub crop: [f32; 4],
    /// The push constants' flags of the ground truth's samples: [`FLAG_GLOSSY_LOBE`] on the rough
    /// reflector, whose ground truth integrates the mirror's glossy lobe; 0 elsewhere.
    pub truth_flags: u32,
}

impl LabScene {
    /// The ground plane at grazing angles under a high-frequency texture: the gallery's checker
    /// with a checker of [`FINE_CHECKER_SQUARE`] texels in every square
    /// ([`two_scale_checker`]); mask: the plane beyond [`PLANE_MASK_DISTANCE`].
    pub fn plane() -> LabScene {
        LabScene {
            name: "plane",
            description: "ground plane at grazing angles, 32- and 4-texel checkers",
            scene: Scene::gallery(),
            texture: two_scale_checker(TEXTURE_SIZE, CHECKER_SQUARE, FINE_CHECKER_SQUARE),
            camera: Camera::ground(),
            mask: Mask::MeshBeyond {
                mesh: 0,
                distance: PLANE_MASK_DISTANCE,
            },
            measure: Measure::Texture,
            crop: [0.0, 0.48, 0.5, 0.4],
            truth_flags: 0,
        }
    }

    /// The ground plane under a wide view ([`CORNERS_FOV_Y_DEGREES`]), the plane scene's texture;
    /// mask: the plane more than [`CORNERS_MASK_DEGREES`] off the view axis, where each primary
    /// ray's own cone (`pinhole_ray_cone_for_ray`) is narrower than the centre pixel's.
    pub fn corners() -> LabScene {
        let camera = Camera {
            eye: Vec3::new(0.0, 1.5, 4.0),
            target: Vec3::new(0.0, 0.0, -2.0),
            fov_y: CORNERS_FOV_Y_DEGREES.to_radians(),
        };
        LabScene {
            name: "corners",
            description: "ground plane under a 100-degree view, the plane's checkers",
            scene: Scene::gallery(),
            texture: two_scale_checker(TEXTURE_SIZE, CHECKER_SQUARE, FINE_CHECKER_SQUARE),
            camera,
            mask: Mask::MeshOffAxis {
                mesh: 0,
                axis: (camera.target - camera.eye).normalize(),
                degrees: CORNERS_MASK_DEGREES,
            },
            measure: Measure::Texture,
            crop: [0.0, 0.6, 0.4, 0.4],
            truth_flags: 0,
        }
    }

    /// The mirror hyperbolic paraboloid in a textured room (RTG ch. 20's saddle reflector);
    /// mask: the reflector.
    pub fn paraboloid() -> LabScene {
        LabScene {
            name: "paraboloid",
            description: "hyperbolic-paraboloid mirror in a checkered room",
            scene: Scene::paraboloid(),
            texture: checker(TEXTURE_SIZE, CHECKER_SQUARE),
            camera: Camera::paraboloid(),
            mask: Mask::Mesh(1),
            measure: Measure::Texture,
            crop: [0.25, 0.25, 0.5, 0.5],
            truth_flags: 0,
        }
    }

    /// [`LabScene::paraboloid`] with the reflector's quads split along alternating diagonals
    /// ([`Scene::paraboloid_alternating`]): the same surface, other triangles for the curvature
    /// estimates to read; mask: the reflector.
    pub fn paraboloid_alternating() -> LabScene {
        LabScene {
            name: "paraboloid_alternating",
            description: "the same mirror, its quads split along alternating diagonals",
            scene: Scene::paraboloid_alternating(),
            ..LabScene::paraboloid()
        }
    }

    /// The gallery's mirror sphere close up, reflecting the ground plane to its horizon; mask:
    /// the sphere.
    pub fn sphere() -> LabScene {
        LabScene {
            name: "sphere",
            description: "mirror sphere reflecting the ground plane",
            scene: Scene::gallery(),
            texture: checker(TEXTURE_SIZE, CHECKER_SQUARE),
            camera: Camera::reflection(),
            mask: Mask::Mesh(1),
            measure: Measure::Texture,
            crop: [0.25, 0.35, 0.5, 0.5],
            truth_flags: 0,
        }
    }

    /// The glass sphere of [`Scene::materials`] close up, the ground plane seen through it upside
    /// down: what the refracted texture's level of detail does; mask: the glass sphere.
    pub fn glass() -> LabScene {
        LabScene {
            name: "glass",
            description: "glass sphere (index 1.5) showing the ground plane through it",
            scene: Scene::materials(),
            texture: checker(TEXTURE_SIZE, CHECKER_SQUARE),
            camera: Camera::glass(),
            mask: Mask::Mesh(1),
            measure: Measure::Texture,
            crop: [0.25, 0.35, 0.5, 0.5],
            truth_flags: 0,
        }
    }

    /// The rough mirror sphere of [`Scene::materials`] close up (where the gallery's mirror
    /// stands, seen as the sphere scene sees that), reflecting the ground plane; its ground truth
    /// integrates the mirror's GGX lobe ([`FLAG_GLOSSY_LOBE`]), the methods reflect about the
    /// shading normal; mask: the rough sphere.
    pub fn rough() -> LabScene {
        LabScene {
            name: "rough",
            description: "rough mirror sphere (roughness 0.3) reflecting the ground plane",
            scene: Scene::materials(),
            texture: checker(TEXTURE_SIZE, CHECKER_SQUARE),
            camera: Camera::reflection(),
            mask: Mask::Mesh(2),
            measure: Measure::Texture,
            crop: [0.25, 0.35, 0.5, 0.5],
            truth_flags: FLAG_GLOSSY_LOBE,
        }
    }

    /// The gallery's dense torus close up under the default wireframe preset; mask: the torus.
    pub fn torus() -> LabScene {
        LabScene {
            name: "torus",
            description: "dense torus under the default wireframe",
            scene: Scene::gallery(),
            texture: checker(TEXTURE_SIZE, CHECKER_SQUARE),
            camera: Camera::torus(),
            mask: Mask::Mesh(2),
            measure: Measure::Wireframe {
                preset: WireframeSettings::PRESETS[0].0,
                settings: WireframeSettings::PRESETS[0].1,
            },
            crop: [0.25, 0.25, 0.5, 0.5],
            truth_flags: 0,
        }
    }

    /// Every scene of the lab, in table order.
    pub fn all() -> Vec<LabScene> {
        vec![
            LabScene::plane(),
            LabScene::corners(),
            LabScene::paraboloid(),
            LabScene::paraboloid_alternating(),
            LabScene::sphere(),
            LabScene::glass(),
            LabScene::rough(),
            LabScene::torus(),
        ]
    }

    /// The methods rendered at one sample per pixel, the baseline first: mip 0 and every
    /// texture-filtering mode of [`Mode::ALL`]; on the wireframe scene, the hard lines and the
    /// preset's anti-aliased lines.
    pub fn methods(&self) -> Vec<Method> {
        match self.measure {
            Measure::Texture => {
                let others = Mode::ALL
                    .into_iter()
                    .filter(|&mode| mode != Mode::Mip0 && not_a_texture_method(mode).is_none());
                std::iter::once(Mode::Mip0)
                    .chain(others)
                    .map(Method::texture)
                    .collect()
            }
            Measure::Wireframe { settings, .. } => vec![
                Method {
                    name: String::from("wireframe_hard"),
                    mode: Mode::Wireframe,
                    settings: hard_lines(settings),
                    flags: 0,
                },
                Method {
                    name: String::from("wireframe"),
                    mode: Mode::Wireframe,
                    settings,
                    flags: 0,
                },
            ],
        }
    }

    /// How the ground truth renders each of its samples: mip 0 under the scene's
    /// [`LabScene::truth_flags`]; for the wireframe, the hard lines.
    pub fn truth_method(&self) -> Method {
        match self.measure {
            Measure::Texture => Method {
                flags: self.truth_flags,
                ..Method::texture(Mode::Mip0)
            },
            Measure::Wireframe { .. } => self.methods().swap_remove(0),
        }
    }
}

/// Why `mode` is not compared with the texture scenes' ground truth, or `None` for the modes
/// that filter the colour texture: every mode but the mip-level visualisation, the wireframe and
/// the path tracers. A mode added later gets a row unless it is listed here.
pub fn not_a_texture_method(mode: Mode) -> Option<&'static str> {
    match mode {
        Mode::MipLevels => Some("shows the mip levels in a texture of its own"),
        Mode::Wireframe => Some("draws lines over the texture: measured on the torus"),
        _ if mode.traces_paths() => Some(
            "path traces another image (diffuse bounces, one random path a sample): measured against \
             per-vertex truth by the example path_footprint",
        ),
        _ => None,
    }
}

/// The same lines as `settings` without anti-aliasing: smoothing 0, and the line's edge in the
/// middle of the preset's smoothing ramp, where an anti-aliased pixel is half covered. The ramp
/// runs from `0.5 * thickness * v` to `0.5 * thickness * v + thickness * smoothing` pixels from
/// the edge (`v` the thickness factor), so the hard line's thickness is
/// `thickness * (v + smoothing) / v`. For presets whose thickness factor is the same along the
/// edge (`thickness_var.x == thickness_var.y`, as the lab's preset); others keep the factor at the
/// edge middle.
pub fn hard_lines(settings: WireframeSettings) -> WireframeSettings {
    let factor = settings.thickness_var.x.max(f32::MIN_POSITIVE);
    WireframeSettings {
        thickness: settings.thickness * (factor + settings.smoothing) / factor,
        smoothing: 0.0,
        ..settings
    }
}

/// How a row of the table is rendered: mode, wireframe settings and the name it goes by.
#[derive(Clone, Debug, PartialEq)]
pub struct Method {
    /// Name in the table (the mode's name, or a wireframe variant's).
    pub name: String,
    /// The render mode.
    pub mode: Mode,
    /// The wireframe settings (drawn in the wireframe mode only).
    pub settings: WireframeSettings,
    /// The push constants' flags (`FLAG_*`): 0 for every method, [`LabScene::truth_flags`] for
    /// a ground truth.
    pub flags: u32,
}

impl Method {
    /// `mode` on the texture, under the default wireframe settings (drawn in no texture mode),
    /// without flags.
    pub fn texture(mode: Mode) -> Method {
        Method {
            name: mode.name().to_string(),
            mode,
            settings: WireframeSettings::default(),
            flags: 0,
        }
    }
}

use glam::Vec3;

/// What kind of light, with the fields only that kind has.
#[derive(Clone, Debug, PartialEq)]
pub enum LightKind {
    Directional,
    Point,
    /// `beam_width`/`cut_off_angle` in radians (VRML97 §6.44); `drop_off_rate`
    /// is Inventor's SpotLight exponent (0..1, used as `cos^(128·rate)`) —
    /// when it is non-zero it replaces the VRML beam-width ramp.
    Spot {
        beam_width: f32,
        cut_off_angle: f32,
        drop_off_rate: f32,
    },
}

/// A light; lives on a node, so its location/direction are in that node's
/// coordinate system.
#[derive(Clone, Debug, PartialEq)]
pub struct Light {
    pub kind: LightKind,
    pub on: bool,
    pub intensity: f32,
    pub ambient_intensity: f32,
    pub color: Vec3,
    pub location: Vec3,
    pub direction: Vec3,
    /// VRML97 attenuation (constant, linear, quadratic).
    pub attenuation: Vec3,
    /// VRML97 radius: beyond it a point/spot light contributes nothing.
    pub radius: f32,
    /// VRML97 DirectionalLight scoping: light only the siblings' subtrees
    /// (the parent's descendants). Inventor lights are global here too when false.
    pub scoped: bool,
}

impl Light {
    pub fn new(kind: LightKind) -> Self {
        Light {
            kind,
            on: true,
            intensity: 1.0,
            ambient_intensity: 0.0,
            color: Vec3::ONE,
            location: Vec3::ZERO,
            direction: Vec3::new(0.0, 0.0, -1.0),
            attenuation: Vec3::new(1.0, 0.0, 0.0),
            radius: 100.0,
            scoped: false,
        }
    }

    /// A VRML97 SpotLight with its default beam (1.570796) and cut-off (0.785398).
    pub fn spot() -> Self {
        Light::new(LightKind::Spot {
            beam_width: std::f32::consts::FRAC_PI_2,
            cut_off_angle: std::f32::consts::FRAC_PI_4,
            drop_off_rate: 0.0,
        })
    }
}

#[derive(Clone, Debug, PartialEq)]
pub enum CameraKind {
    /// `height_angle` is the full vertical field of view in radians
    /// (VRML97 fieldOfView applies to the smaller window dimension; see render).
    Perspective { height_angle: f32 },
    /// `height` is the view volume's height in world units.
    Orthographic { height: f32 },
}

/// A camera / viewpoint, in the coordinate system of the node that holds it.
#[derive(Clone, Debug, PartialEq)]
pub struct Camera {
    pub kind: CameraKind,
    pub position: glam::Vec3,
    pub orientation: glam::Quat,
    /// Description / viewpoint name shown in lists and used by `--viewpoint`.
    pub description: String,
    /// True for VRML97 Viewpoint: fieldOfView is for the smaller dimension.
    pub fov_smaller_side: bool,
    /// Inventor focalDistance / orbit distance (used by the editor to orbit).
    pub focal_distance: f32,
    pub near: Option<f32>,
    pub far: Option<f32>,
}

impl Default for Camera {
    /// The VRML97 Viewpoint defaults.
    fn default() -> Self {
        Camera {
            kind: CameraKind::Perspective {
                height_angle: std::f32::consts::FRAC_PI_4,
            },
            position: glam::Vec3::new(0.0, 0.0, 10.0),
            orientation: glam::Quat::IDENTITY,
            description: String::new(),
            fov_smaller_side: true,
            focal_distance: 10.0,
            near: None,
            far: None,
        }
    }
}

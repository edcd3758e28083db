//! A VRML97 Background (ISO/IEC 14772-1 §6.5): a sky sphere and a ground
//! sphere of colour bands at infinity, and a panorama cube of six images
//! inside them.

use super::ImageId;
use glam::Vec3;

/// The six panorama faces, in the order of [`Background::panorama`].
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Face {
    Back,
    Bottom,
    Front,
    Left,
    Right,
    Top,
}

impl Face {
    pub const ALL: [Face; 6] = [
        Face::Back,
        Face::Bottom,
        Face::Front,
        Face::Left,
        Face::Right,
        Face::Top,
    ];
    /// The VRML97 field naming this face's image (`backUrl` …).
    pub fn field(self) -> &'static str {
        match self {
            Face::Back => "backUrl",
            Face::Bottom => "bottomUrl",
            Face::Front => "frontUrl",
            Face::Left => "leftUrl",
            Face::Right => "rightUrl",
            Face::Top => "topUrl",
        }
    }
}

/// Sky and ground colours are linear 0..1 RGB; angles are radians from the
/// zenith (sky) or the nadir (ground), increasing. `sky_color[0]` is at the
/// zenith and `sky_color[i]` at `sky_angle[i-1]`; below the last angle the
/// last colour holds. The ground is drawn over the sky up to its last angle
/// only.
#[derive(Clone, Debug, PartialEq)]
pub struct Background {
    pub sky_color: Vec<Vec3>,
    pub sky_angle: Vec<f32>,
    pub ground_color: Vec<Vec3>,
    pub ground_angle: Vec<f32>,
    /// Images for back (+Z), bottom (−Y), front (−Z), left (−X), right
    /// (+X), top (+Y), in [`Face::ALL`] order (the field order). Each is
    /// upright seen from inside: the side faces with +Y up, the top with +Z
    /// up, the bottom with −Z up (as view3dscene shows them).
    pub panorama: [Option<ImageId>; 6],
}

impl Default for Background {
    /// The VRML97 defaults: black sky, no ground, no panorama.
    fn default() -> Self {
        Background {
            sky_color: vec![Vec3::ZERO],
            sky_angle: Vec::new(),
            ground_color: Vec::new(),
            ground_angle: Vec::new(),
            panorama: [None; 6],
        }
    }
}

impl Background {
    /// Whether it is one flat colour (drawn like the plain background).
    pub fn is_flat(&self) -> bool {
        self.sky_color.len() <= 1
            && self.ground_visible_bands() == 0
            && self.panorama.iter().all(Option::is_none)
    }

    fn ground_visible_bands(&self) -> usize {
        self.ground_angle
            .len()
            .min(self.ground_color.len().saturating_sub(1))
    }

    /// The colour of a flat fill: the first sky colour.
    pub fn flat_color(&self) -> Vec3 {
        self.sky_color.first().copied().unwrap_or(Vec3::ZERO)
    }
}

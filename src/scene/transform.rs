use glam::{Mat4, Quat, Vec3};

/// A VRML97 Transform: `P' = T · C · R · SR · S · SR⁻¹ · C⁻¹ · P`
/// (ISO/IEC 14772-1 §6.52), optionally preceded by a raw matrix
/// (Inventor MatrixTransform) as `extra · (T · C · …)`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Transform {
    pub translation: Vec3,
    pub rotation: Quat,
    pub scale: Vec3,
    pub scale_orientation: Quat,
    pub center: Vec3,
    pub extra: Option<Mat4>,
}

impl Default for Transform {
    fn default() -> Self {
        Transform {
            translation: Vec3::ZERO,
            rotation: Quat::IDENTITY,
            scale: Vec3::ONE,
            scale_orientation: Quat::IDENTITY,
            center: Vec3::ZERO,
            extra: None,
        }
    }
}

impl Transform {
    pub fn from_translation(t: Vec3) -> Self {
        Transform {
            translation: t,
            ..Default::default()
        }
    }

    /// The local matrix of this transform.
    pub fn matrix(&self) -> Mat4 {
        let t = Mat4::from_translation(self.translation + self.center);
        let r = Mat4::from_quat(self.rotation);
        let m = if self.scale_orientation == Quat::IDENTITY {
            t * r * Mat4::from_scale(self.scale)
        } else {
            let sr = Mat4::from_quat(self.scale_orientation);
            t * r * sr * Mat4::from_scale(self.scale) * sr.inverse()
        };
        let m = if self.center == Vec3::ZERO {
            m
        } else {
            m * Mat4::from_translation(-self.center)
        };
        match self.extra {
            Some(e) => e * m,
            None => m,
        }
    }

    pub fn is_identity(&self) -> bool {
        *self == Transform::default()
    }
}

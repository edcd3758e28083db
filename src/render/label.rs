//! Inventor `Text2` labels: screen-aligned at a constant pixel size.
//!
//! The Inventor Mentor (ch. 7, "Text2") and Coin's `SoText2` draw a Text2
//! string as a bitmap at the projected position of its local origin: it
//! always faces the viewer and is `Font.size` pixels high whatever the
//! distance, rotation or scale. The reader builds the label's triangles in
//! scene units with `TextSpec::units_per_pixel` local units per pixel (so
//! writers and the editor see a plausible size); here the shape's matrix
//! is replaced, per view and picture size, by one that puts the local
//! origin where the world matrix puts it, turns the label's x/y plane to
//! the screen's and scales one pixel of the label to one pixel of the
//! picture at the origin's depth. Glyphs stay geometry (lit, picked,
//! depth-tested at the anchor's depth).

use super::View;
use glam::{Mat4, Vec3, Vec4};

/// The matrix that draws a label mesh with `units_per_pixel` local units
/// per pixel, anchored at `world`'s origin, facing the viewer at a
/// constant pixel size in a picture `height` pixels high. `None` when the
/// anchor is behind the eye or the matrices are degenerate (nothing to
/// draw, as Coin draws no label whose origin is clipped).
pub fn label_matrix(world: Mat4, view: &View, height: u32, units_per_pixel: f32) -> Option<Mat4> {
    let anchor = view.view * world * Vec4::new(0.0, 0.0, 0.0, 1.0);
    let clip = view.proj * anchor;
    let y_scale = view.proj.y_axis.y;
    if !(clip.w > 0.0 && y_scale.abs() > 0.0 && units_per_pixel > 0.0 && height > 0) {
        return None;
    }
    // Eye-space units per picture pixel at the anchor: the view volume is
    // 2·w / y_scale high there (w = depth for a perspective camera, 1 for
    // an orthographic one).
    let per_pixel = 2.0 * clip.w / (y_scale.abs() * height as f32);
    let s = per_pixel / units_per_pixel;
    let m = view.view.inverse()
        * Mat4::from_translation(anchor.truncate() / anchor.w)
        * Mat4::from_scale(Vec3::new(s, s, s));
    m.is_finite().then_some(m)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::{Camera, CameraKind};
    use glam::Quat;

    fn project(view: &View, w: u32, h: u32, p: Vec3) -> (f32, f32) {
        let c = view.proj * view.view * p.extend(1.0);
        let n = c.truncate() / c.w;
        ((n.x + 1.0) * 0.5 * w as f32, (1.0 - n.y) * 0.5 * h as f32)
    }

    /// A label 2 units per pixel spans the same pixels near and far, and
    /// turns with the camera: one local unit along x is half a pixel to
    /// the right on screen, along y half a pixel up, from any view.
    #[test]
    fn labels_keep_their_pixel_size_and_face_the_viewer() {
        let (w, h) = (320, 240);
        for (pos, turn) in [
            (Vec3::new(0.0, 0.0, 10.0), 0.0),
            (Vec3::new(0.0, 0.0, 100.0), 0.0),
            (Vec3::new(3.0, 1.0, 20.0), 0.7),
        ] {
            let cam = Camera {
                kind: CameraKind::Perspective { height_angle: 0.8 },
                position: pos,
                orientation: Quat::from_rotation_y(turn),
                ..Camera::default()
            };
            let view = View::from_camera(&cam, Mat4::IDENTITY, w as f32 / h as f32);
            // The anchor 5 units in front of the camera, in a rotated,
            // scaled group: neither changes the label.
            let ahead =
                pos + Quat::from_rotation_y(turn) * Vec3::new(0.0, 0.0, -5.0 - pos.z / 10.0);
            let world = Mat4::from_scale_rotation_translation(
                Vec3::splat(3.0),
                Quat::from_rotation_z(0.4),
                ahead,
            );
            let m = label_matrix(world, &view, h, 2.0).unwrap();
            let (ax, ay) = project(&view, w, h, m.transform_point3(Vec3::ZERO));
            let (bx, by) = project(&view, w, h, world.transform_point3(Vec3::ZERO));
            assert!((ax - bx).abs() < 1e-3 && (ay - by).abs() < 1e-3);
            let (xx, xy) = project(&view, w, h, m.transform_point3(Vec3::new(20.0, 0.0, 0.0)));
            assert!(
                (xx - ax - 10.0).abs() < 1e-2 && (xy - ay).abs() < 1e-2,
                "{xx} {xy}"
            );
            let (yx, yy) = project(&view, w, h, m.transform_point3(Vec3::new(0.0, 20.0, 0.0)));
            assert!(
                (yx - ax).abs() < 1e-2 && (ay - yy - 10.0).abs() < 1e-2,
                "{yx} {yy}"
            );
        }
    }

    #[test]
    fn orthographic_and_behind_the_eye() {
        let cam = Camera {
            kind: CameraKind::Orthographic { height: 12.0 },
            position: Vec3::new(0.0, 0.0, 10.0),
            ..Camera::default()
        };
        let view = View::from_camera(&cam, Mat4::IDENTITY, 4.0 / 3.0);
        let m = label_matrix(Mat4::IDENTITY, &view, 240, 1.0).unwrap();
        // 12 units over 240 pixels: one pixel is 0.05 units.
        let one = m.transform_point3(Vec3::X) - m.transform_point3(Vec3::ZERO);
        assert!((one.length() - 0.05).abs() < 1e-6, "{one}");
        let behind = Mat4::from_translation(Vec3::new(0.0, 0.0, 20.0));
        let persp = Camera {
            position: Vec3::new(0.0, 0.0, 10.0),
            ..Camera::default()
        };
        let view = View::from_camera(&persp, Mat4::IDENTITY, 1.0);
        assert!(label_matrix(behind, &view, 240, 1.0).is_none());
        assert!(label_matrix(Mat4::IDENTITY, &view, 240, 0.0).is_none());
    }
}

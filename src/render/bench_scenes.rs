//! Scenes the benchmarks draw (`animed bench` and `cargo bench`), built in
//! code so both measure exactly the same work.

use crate::scene::{
    Camera, CameraKind, Light, LightKind, Material, Mesh, Node, NodeKind, Scene, Shape, Transform,
};
use glam::Vec3;

/// The three lights of the per-pixel benchmark: directional, point, spot.
pub fn three_lights(s: &mut Scene) {
    let mut sun = Light::new(LightKind::Directional);
    sun.direction = Vec3::new(-0.3, -0.4, -1.0);
    sun.intensity = 0.5;
    let mut lamp = Light::new(LightKind::Point);
    lamp.location = Vec3::new(-1.0, 0.5, 3.0);
    lamp.intensity = 0.5;
    lamp.attenuation = Vec3::new(1.0, 0.1, 0.0);
    let mut spot = Light::new(LightKind::Spot {
        beam_width: 0.3,
        cut_off_angle: 0.6,
        drop_off_rate: 0.0,
    });
    spot.location = Vec3::new(0.5, 0.0, 3.0);
    spot.direction = Vec3::new(0.0, 0.0, -1.0);
    for l in [sun, lamp, spot] {
        s.add_node(None, Node::new("light", NodeKind::Light(l)));
    }
}

fn shiny() -> Material {
    Material {
        diffuse: Vec3::new(0.6, 0.5, 0.4),
        specular: Vec3::splat(0.6),
        shininess: 0.3,
        ..Material::default()
    }
}

fn ortho_camera(s: &mut Scene) {
    let cam = Camera {
        kind: CameraKind::Orthographic { height: 2.0 },
        position: Vec3::new(0.0, 0.0, 5.0),
        ..Camera::default()
    };
    s.add_node(None, Node::new("cam", NodeKind::Camera(cam)));
}

/// `layers` screen-filling quads (for `aspect` = width/height) stacked in
/// depth and listed back to front (the worst order for overdraw), lit by
/// [`three_lights`] with a specular material, seen by an orthographic camera.
pub fn layers(layers: usize, aspect: f32) -> Scene {
    let mut s = Scene::new();
    ortho_camera(&mut s);
    stacked(s, layers, (aspect * 1.01, 1.01))
}

/// One [`layers`] quad seen by a perspective camera tilted 50° from it
/// (the quad is made large enough to fill the view): what
/// `layers_textured` samples at one level pair everywhere, this samples
/// from magnified at the bottom of the screen to about level 3 at the top,
/// with 1/w varying over every triangle.
pub fn layer_tilted() -> Scene {
    let mut s = Scene::new();
    let cam = Camera {
        position: Vec3::new(0.0, -1.6, 1.2),
        orientation: glam::Quat::from_rotation_x(50f32.to_radians()),
        ..Camera::default()
    };
    s.add_node(None, Node::new("cam", NodeKind::Camera(cam)));
    stacked(s, 1, (4.0, 4.0))
}

/// [`layer_tilted`] with [`layers_textured`]'s texture and coordinates.
pub fn layer_tilted_textured() -> Scene {
    checkered(layer_tilted(), 2.0)
}

/// `s` with [`three_lights`], the specular material and `layers` quads of
/// half-size `half` facing +z, stacked back to front.
fn stacked(mut s: Scene, layers: usize, half: (f32, f32)) -> Scene {
    three_lights(&mut s);
    let material = s.add_material(shiny());
    let (hw, hh) = half;
    for k in 0..layers {
        let z = -((layers - k) as f32) * 0.1;
        let mesh = Mesh {
            positions: vec![
                Vec3::new(-hw, -hh, z),
                Vec3::new(hw, -hh, z),
                Vec3::new(hw, hh, z),
                Vec3::new(-hw, hh, z),
            ],
            normals: vec![Vec3::new(0.1, 0.2, 1.0).normalize(); 4],
            triangles: vec![[0, 1, 2], [0, 2, 3]],
            solid: true,
            ..Mesh::default()
        };
        let mesh = s.add_mesh(mesh);
        s.add_node(
            None,
            Node::new(
                format!("layer{k}"),
                NodeKind::Shape(Shape { mesh, material }),
            ),
        );
    }
    s
}

/// A 256×256 RGB checker of 32-texel squares (benchmark texture).
fn checker_image(s: &mut Scene) -> Option<crate::scene::ImageId> {
    let texels: Vec<[u8; 4]> = (0..256 * 256)
        .map(|i| {
            let (x, y) = (i % 256, i / 256);
            if (x / 32 + y / 32) % 2 == 0 {
                [230, 220, 200, 255]
            } else {
                [60, 70, 90, 255]
            }
        })
        .collect();
    crate::scene::Image::new(
        "checker",
        crate::scene::ImageSource::Inline,
        256,
        256,
        3,
        texels,
    )
    .and_then(|img| s.add_image(img))
    .ok()
}

/// [`layers`] with the checker texture on the material, repeated 4 times
/// over the screen height: about 1.4 texels per pixel at 1280×720, so
/// sampling blends two mip levels (trilinear) everywhere.
pub fn layers_textured(layers_count: usize, aspect: f32) -> Scene {
    checkered(layers(layers_count, aspect), 2.0)
}

/// [`small_triangles`] with texture coordinates across the grid and a
/// 256×256 checker texture on the material (trilinear-sampled).
pub fn small_triangles_textured(count: usize, aspect: f32) -> Scene {
    checkered(small_triangles(count, aspect), 4.0)
}

/// `s` with the checker texture on every material and texture
/// coordinates `scale`·(x, y) on every mesh.
fn checkered(mut s: Scene, scale: f32) -> Scene {
    if let Some(image) = checker_image(&mut s) {
        for m in &mut s.materials {
            m.texture = Some(crate::scene::Texture::new(image));
        }
        for mesh in &mut s.meshes {
            mesh.texcoords = mesh
                .positions
                .iter()
                .map(|p| glam::Vec2::new(p.x * scale, p.y * scale))
                .collect();
        }
    }
    s
}

/// About `count` small triangles (a grid of quads, two each) covering the
/// screen once, one mesh, lit by [`three_lights`].
pub fn small_triangles(count: usize, aspect: f32) -> Scene {
    let mut s = Scene::new();
    ortho_camera(&mut s);
    three_lights(&mut s);
    let quads = (count / 2).max(1);
    // cols / rows ≈ aspect, cols · rows ≈ quads.
    let rows = ((quads as f32 / aspect).sqrt().round() as usize).max(1);
    let cols = quads.div_ceil(rows);
    let mut m = Mesh {
        solid: true,
        ..Mesh::default()
    };
    for r in 0..=rows {
        for c in 0..=cols {
            let x = -aspect + 2.0 * aspect * c as f32 / cols as f32;
            let y = -1.0 + 2.0 * r as f32 / rows as f32;
            // A gentle bump so normals vary.
            let z = 0.05 * libm::sinf(x * 7.0) * libm::cosf(y * 5.0);
            m.positions.push(Vec3::new(x, y, z));
            m.normals.push(
                Vec3::new(-0.35 * libm::cosf(x * 7.0), 0.25 * libm::sinf(y * 5.0), 1.0).normalize(),
            );
        }
    }
    let stride = cols as u32 + 1;
    for r in 0..rows as u32 {
        for c in 0..cols as u32 {
            let a = r * stride + c;
            m.triangles.push([a, a + 1, a + stride + 1]);
            m.triangles.push([a, a + stride + 1, a + stride]);
        }
    }
    let mesh = s.add_mesh(m);
    let material = s.add_material(shiny());
    s.add_node(
        None,
        Node::new("grid", NodeKind::Shape(Shape { mesh, material }))
            .with_transform(Transform::default()),
    );
    s
}

//! What a Phong-only writer (.iv, .wrl, .x3d) cannot carry, said as
//! warnings instead of dropped silently: a material's emissive texture map
//! (glTF's emissiveTexture; VRML97, X3D 3 and Inventor have none), and for
//! VRML97/X3D the Inventor DrawStyle widths a shape draws its lines and
//! points with (those formats leave widths to the browser).

use crate::scene::{NodeKind, Scene};

/// One warning per kind of loss, naming how many and the first one.
pub fn dropped_parts(scene: &Scene, has_widths: bool) -> Vec<String> {
    let mut out = Vec::new();
    let emissive: Vec<&str> = scene
        .materials
        .iter()
        .filter(|m| m.emissive_texture.is_some())
        .map(|m| m.name.as_str())
        .collect();
    if let Some(first) = emissive.first() {
        out.push(format!(
            "{} material(s) have an emissive texture map, which this format cannot hold: \
             not written (their emissive colour is), first `{first}`",
            emissive.len()
        ));
    }
    if !has_widths {
        let wide: Vec<&str> = scene
            .nodes
            .iter()
            .filter(|n| matches!(n.kind, NodeKind::Shape(_)))
            .filter(|n| n.line_width != 0.0 || n.point_size != 0.0)
            .map(|n| n.name.as_str())
            .collect();
        if let Some(first) = wide.first() {
            out.push(format!(
                "{} shape(s) have a line width or point size (Inventor DrawStyle), which \
                 this format cannot hold: drawn 1 pixel wide elsewhere, first `{first}`",
                wide.len()
            ));
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::{Material, Node, Shape, Texture};

    #[test]
    fn emissive_maps_and_widths_are_named() {
        let mut s = Scene::new();
        let mesh = s.add_mesh(crate::scene::Mesh::default());
        let material = s.add_material(Material {
            name: "Glow".into(),
            emissive_texture: Some(Texture::new(crate::scene::ImageId(0))),
            ..Material::default()
        });
        let mut n = Node::new("Wire", NodeKind::Shape(Shape { mesh, material }));
        n.line_width = 2.0;
        s.add_node(None, n);
        let w = dropped_parts(&s, false);
        assert_eq!(w.len(), 2);
        assert!(
            w[0].contains("emissive texture") && w[0].contains("`Glow`"),
            "{w:?}"
        );
        assert!(
            w[1].contains("line width") && w[1].contains("`Wire`"),
            "{w:?}"
        );
        // Inventor keeps widths (DrawStyle): only the map is lost.
        assert_eq!(dropped_parts(&s, true).len(), 1);
    }
}

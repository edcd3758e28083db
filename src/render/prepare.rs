//! From a posed scene to screen-space primitives: gather the visible shapes
//! with their material and lights, transform vertices, clip, project, cull,
//! and snap to the fixed-point grid. Everything here is per primitive and
//! order-preserving, so it can run in parallel without changing the result.

use super::background::Painter;
use super::clip::{self, ClipVert, ATTRS, A_NORMAL};
use super::geometry::Geometry;
use super::in_place::extend_in_place;
use super::label::label_matrix;
use super::shade::{ShadeMaterial, WorldLight};
use super::stroke_faces;
use super::texture::Sampler;
use super::tri_gradients::Gradients;
use super::{RenderOptions, View};
use crate::anim::Pose;
use crate::scene::{Material, Mesh, NodeId, NodeKind, RenderStyle, Scene};
use glam::{Mat3, Mat4, Vec3, Vec4};
use rayon::prelude::*;

/// Sub-pixel bits of the fixed-point screen coordinates.
pub const SUBPIXEL_BITS: u32 = 8;
pub const SUBPIXEL: i64 = 1 << SUBPIXEL_BITS;
/// Screen coordinates stay within ±2^20 pixels (guard band), so edge
/// function products fit easily in i64.
const MAX_SCREEN: f32 = (1 << 20) as f32;

/// One drawn shape: what every pixel of it needs besides its attributes.
#[derive(Clone, Debug)]
pub struct Item {
    /// `NodeId.0 + 1` for the id buffer.
    pub id: u32,
    pub material: ShadeMaterial,
    pub lights: Vec<WorldLight>,
    /// Lines/points without normals, or an unlit material: colour is used
    /// as is.
    pub unlit: bool,
    /// Drawn in the Lines or Points style and not solid: its lines and
    /// points stand for a two-sided surface's edges and corners, lit on the
    /// side that faces the eye as the filled surface is (`raster::facing`).
    /// A solid surface draws only its front faces' edges and corners
    /// (`stroke_faces`), and they, like line and point sets drawn as
    /// themselves, are lit by the normal as given.
    pub surface_strokes: bool,
    /// The shading pass computes texture coordinates and their derivatives
    /// for this item and runs its texture steps (`surface::shade_lanes`;
    /// its tiles shade in the loop compiled with them). Set it when the
    /// material has a texture or an emissive map and the mesh has texture
    /// coordinates (the vertices then carry them in `clip::A_UV`).
    /// Untextured items never pay for it.
    pub textured: bool,
    /// The texture of a textured item.
    pub texture: Option<Sampler>,
    /// The emissive map of a textured item (glTF emissiveTexture), sampled
    /// at the same texture coordinates; its material's emissive colour is
    /// then zero and comes from here, per pixel.
    pub emissive: Option<EmissiveMap>,
}

/// An emissive map: `factor × texel` is the emitted colour, added to the
/// lit colour before anything clamps it (glTF 2.0 §3.9.3 and Appendix B:
/// the emission is a term of the sum, like VRML97's O_E).
#[derive(Clone, Debug)]
pub struct EmissiveMap {
    pub map: Sampler,
    /// The material's emissive colour (animated ones too).
    pub factor: Vec3,
}

/// Index of the 1/w plane in [`Tri::base`] (after the attributes).
pub const INV_W: usize = ATTRS;
/// Planes per triangle: every attribute divided by w, then 1/w.
pub const PLANES: usize = ATTRS + 1;

/// A screen-space triangle, oriented so its edge functions are positive
/// inside (see `raster`).
///
/// Attributes are stored as planes over the screen-space barycentric
/// weights b1, b2 of vertices 1 and 2: `value/w = base + b1·d1 + b2·d2`
/// (value/w and 1/w are affine in screen space), so a pixel needs two
/// multiply-adds per attribute and one division for 1/w.
#[derive(Clone, Copy, Debug)]
pub struct Tri {
    /// Fixed-point (SUBPIXEL) screen coordinates, y down.
    pub x: [i64; 3],
    pub y: [i64; 3],
    /// Window depth 0..1 (linear in screen space).
    pub z: [f32; 3],
    /// Attribute planes (see above); normals already face the viewer for
    /// triangles seen from behind (two-sided lighting).
    pub base: [f32; PLANES],
    pub d1: [f32; PLANES],
    pub d2: [f32; PLANES],
    pub item: u32,
    /// Pixel bounding box, inclusive min, exclusive max, clamped to the frame.
    pub bbox: [i32; 4],
    /// The texture planes' screen gradients, set for textured items only
    /// (zero otherwise: untextured triangles never pay the division).
    pub grad: Gradients,
}

impl Tri {
    /// Window depth at screen-space weights b1, b2 (the depth pass's
    /// arithmetic, one pixel).
    #[inline]
    pub fn depth_at(&self, b1: f32, b2: f32) -> f32 {
        self.z[0] + b1 * (self.z[1] - self.z[0]) + b2 * (self.z[2] - self.z[0])
    }

    /// Twice the signed area in SUBPIXEL² units (positive: see [`Tri`]).
    #[inline]
    pub fn area(&self) -> i64 {
        (self.x[1] - self.x[0]) * (self.y[2] - self.y[0])
            - (self.y[1] - self.y[0]) * (self.x[2] - self.x[0])
    }

    /// The edge function opposite vertex `k` at the fixed-point point
    /// (`px`, `py`), biased by the top-left rule (a point exactly on an
    /// edge is inside only for a top or a left edge: for this orientation
    /// horizontal going right, or going up), and its steps per pixel in x
    /// and y. Exact integers, so the rasteriser stepping it across a tile
    /// and a lone evaluation at one sample agree to the bit.
    #[inline]
    pub fn edge(&self, k: usize, px: i64, py: i64) -> (i64, i64, i64) {
        let (a, b) = ((k + 1) % 3, (k + 2) % 3);
        let (dx, dy) = (self.x[b] - self.x[a], self.y[b] - self.y[a]);
        let top_left = (dy == 0 && dx > 0) || dy < 0;
        let bias = if top_left { 0 } else { -1 };
        let e = dx * (py - self.y[a]) - dy * (px - self.x[a]) + bias;
        (e, -dy * SUBPIXEL, dx * SUBPIXEL)
    }

    /// The screen-space weights of vertices 1 and 2 at the sample `off`
    /// (SUBPIXEL units from the centre) of pixel (`x`, `y`): the very bits
    /// the depth pass computes there (`edge as f32 · (1 / area as f32)`),
    /// for samples whose weights it does not keep.
    #[inline]
    pub fn weights_at(&self, x: i32, y: i32, off: (i64, i64)) -> (f32, f32) {
        let px = x as i64 * SUBPIXEL + SUBPIXEL / 2 + off.0;
        let py = y as i64 * SUBPIXEL + SUBPIXEL / 2 + off.1;
        let inv_area = 1.0 / self.area() as f32;
        (
            self.edge(1, px, py).0 as f32 * inv_area,
            self.edge(2, px, py).0 as f32 * inv_area,
        )
    }

    /// Perspective-correct attributes at screen-space weights b1, b2 (the
    /// same arithmetic as the shading pass, one lane).
    #[inline]
    pub fn attrs_at(&self, b1: f32, b2: f32) -> [f32; ATTRS] {
        let plane = |j: usize| self.base[j] + b1 * self.d1[j] + b2 * self.d2[j];
        let s = 1.0 / plane(INV_W);
        std::array::from_fn(|j| plane(j) * s)
    }
}

/// What binning reads of an opaque triangle: its pixel box and whether
/// its item is textured. Kept in a list of its own beside the triangles
/// (`Prepared::opaque_boxes`), 10 bytes where binning otherwise reads two
/// cache lines of every 248-byte [`Tri`] just after set-up wrote them (a
/// memory-bound 5 % of a 100k-triangle frame).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TriBox {
    /// [`Tri::bbox`] (clamped to the frame, which is at most
    /// `MAX_SIDE` = 2¹⁴ pixels a side).
    pub bbox: [u16; 4],
    pub textured: bool,
}

impl TriBox {
    /// The box of a triangle whose [`Tri::bbox`] is `bbox`.
    pub fn of_box(bbox: &[i32; 4], textured: bool) -> TriBox {
        TriBox {
            bbox: bbox.map(|v| v.clamp(0, u16::MAX as i32) as u16),
            textured,
        }
    }
}

/// A screen-space line segment.
#[derive(Clone, Debug)]
pub struct Line {
    pub x: [f32; 2],
    pub y: [f32; 2],
    pub z: [f32; 2],
    pub inv_w: [f32; 2],
    pub attr: [[f32; ATTRS]; 2],
    pub item: u32,
    /// Width in whole pixels (≥ 1; see [`stroke_pixels`]).
    pub width: i32,
    pub bbox: [i32; 4],
}

/// A screen-space point (drawn as a small square).
#[derive(Clone, Debug)]
pub struct Point {
    /// Screen position of the centre (pixels).
    pub c: [f32; 2],
    pub z: f32,
    pub attr: [f32; ATTRS],
    pub item: u32,
    /// Side of its square in whole pixels (≥ 1; see [`stroke_pixels`]).
    pub size: i32,
    pub bbox: [i32; 4],
}

/// The widest line and largest point drawn, in pixels (a hostile
/// lineWidth cannot make one primitive cover the whole picture many times).
pub const MAX_STROKE: i32 = 64;

/// A node's line width or point size in whole pixels: OpenGL rounds a
/// non-antialiased width to the nearest integer and draws 0 as 1 (OpenGL
/// 2.1 §3.3.1, §3.4.2), and Coin leaves OpenGL's default of 1 when the
/// DrawStyle says 0.
pub fn stroke_pixels(w: f32) -> i32 {
    if w.is_finite() && w > 0.0 {
        (w.round() as i32).clamp(1, MAX_STROKE)
    } else {
        1
    }
}

/// Everything the tiles draw, in drawing order. Kept between frames (see
/// `render::render_into`) so its buffers are not allocated and faulted in
/// again for every frame.
#[derive(Default)]
pub struct Prepared {
    pub items: Vec<Item>,
    pub opaque: Vec<Tri>,
    /// Each opaque triangle's box, for binning (see [`TriBox`]).
    pub opaque_boxes: Vec<TriBox>,
    /// Sorted back to front.
    pub transparent: Vec<Tri>,
    pub lines: Vec<Line>,
    pub points: Vec<Point>,
    /// The scene's gradient/panorama background, when drawn.
    pub sky: Option<Painter>,
    /// Working buffers of `prepare`: transformed vertices of the current
    /// mesh.
    verts: Vec<ClipVert>,
    /// The current mesh's vertices in screen space (see [`ScreenVert`]).
    screen_verts: Vec<ScreenVert>,
}

struct Screen {
    w: f32,
    h: f32,
    guard: f32,
    /// Multisampling: lines and points reach a little further.
    aa: bool,
}

impl Screen {
    /// Clip space → (screen x, screen y, depth, 1/w).
    fn project(&self, c: Vec4) -> (f32, f32, f32, f32) {
        let iw = 1.0 / c.w;
        (
            (c.x * iw * 0.5 + 0.5) * self.w,
            (0.5 - c.y * iw * 0.5) * self.h,
            c.z * iw * 0.5 + 0.5,
            iw,
        )
    }
}

/// Prepares a frame's primitives into `out` (emptied first).
pub fn prepare(scene: &Scene, pose: &Pose, view: &View, opts: &RenderOptions, out: &mut Prepared) {
    let screen = Screen {
        w: opts.width as f32,
        h: opts.height as f32,
        guard: MAX_SCREEN / opts.width.max(opts.height).max(1) as f32,
        aa: opts.samples() > 1,
    };
    let view_proj = view.proj * view.view;
    let lights = gather_lights(scene, pose);
    let headlight = opts
        .headlight
        .then(|| WorldLight::headlight(view.forward()));
    // Inventor's global ambient (`Settings::ambient`): a light that only
    // has its ambient term (I_ia = 1, colour = the ambient).
    let global_ambient = (scene.settings.ambient != Vec3::ZERO)
        .then(|| {
            let mut l = crate::scene::Light::new(crate::scene::LightKind::Directional);
            (l.intensity, l.ambient_intensity, l.color) = (0.0, 1.0, scene.settings.ambient);
            WorldLight::new(&l, Mat4::IDENTITY)
        })
        .flatten();

    out.items.clear();
    out.opaque.clear();
    out.opaque_boxes.clear();
    out.transparent.clear();
    out.lines.clear();
    out.points.clear();
    out.sky = None;
    if opts.sky {
        if let Some(bg) = &scene.settings.sky {
            out.sky = Painter::new(scene, bg, view.view, view.proj, opts.width, opts.height);
        }
    }
    let mut verts = std::mem::take(&mut out.verts);
    for node_id in scene.walk() {
        let i = node_id.0 as usize;
        let node = &scene.nodes[i];
        let NodeKind::Shape(shape) = &node.kind else {
            continue;
        };
        if !pose.visible.get(i).copied().unwrap_or(node.visible) {
            continue;
        }
        let style = opts.style_override.unwrap_or(node.style);
        if style == RenderStyle::Hidden {
            continue;
        }
        let Some(mesh) = scene.meshes.get(shape.mesh.0 as usize) else {
            continue;
        };
        let default_material = Material::default();
        let material = pose
            .materials
            .get(shape.material.0 as usize)
            .or_else(|| scene.materials.get(shape.material.0 as usize))
            .unwrap_or(&default_material);
        let mut world = pose.world.get(i).copied().unwrap_or(Mat4::IDENTITY);
        // An Inventor Text2 faces the viewer at a constant pixel size.
        if let Some(t) = mesh.text.as_deref().filter(|t| t.units_per_pixel > 0.0) {
            match label_matrix(world, view, opts.height, t.units_per_pixel) {
                Some(m) => world = m,
                None => continue,
            }
        }
        // Morphed/skinned shapes draw the pose's deformed vertices.
        let geo = Geometry::of(mesh, pose, node_id, world);

        let mut item_lights: Vec<WorldLight> = lights
            .iter()
            .filter(|(scope, _)| scope.is_none_or(|s| is_ancestor(scene, s, node_id)))
            .map(|(_, l)| l.clone())
            .collect();
        item_lights.extend(headlight.clone());
        // An Inventor material's ambient term is a constant colour (below).
        if material.ambient_color.is_none() {
            item_lights.extend(global_ambient.clone());
        }
        // An unlit material (lighting off) draws like a mesh without
        // normals: its vertex colours or its emissive colour as they are.
        let has_normals = mesh.normals.len() == mesh.positions.len() && !material.unlit;
        let mut smat = ShadeMaterial::new(material);
        // Inventor's ambient (Coin: OpenGL's material ambient × the light
        // model's ambient; Inventor lights have none): the same colour at
        // every pixel, so it is added as emission is.
        if let Some(a) = material.ambient_color {
            smat.emissive += a * scene.settings.ambient;
        }
        let item = out.items.len() as u32;
        // Textured: the material's texture, when its image exists and the
        // mesh has coordinates for it (lit or not: an unlit mesh's colour
        // stands in for the lit one, see `fragment::shade_group`).
        let has_uv = has_texcoords(mesh);
        let sampler = |t: &crate::scene::Texture| {
            let image = scene.image(t.image)?;
            has_uv.then(|| Sampler::new(t, image))
        };
        let texture = material.texture.as_ref().and_then(sampler);
        let emissive = material.emissive_texture.as_ref().and_then(sampler);
        let emissive = emissive.map(|map| {
            smat.emissive = Vec3::ZERO;
            EmissiveMap {
                map,
                factor: material.emissive,
            }
        });
        let translucent = texture.as_ref().is_some_and(Sampler::translucent);

        transform_vertices(mesh, &geo, view_proj, material, has_normals, &mut verts);
        let stroke = Stroke {
            item,
            line: stroke_pixels(node.line_width),
            point: stroke_pixels(node.point_size),
        };
        match style {
            RenderStyle::Filled => {
                let textured = texture.is_some() || emissive.is_some();
                let setup = Setup {
                    item,
                    screen: &screen,
                    opts,
                    textured,
                };
                project_vertices(&verts, &screen, &mut out.screen_verts);
                let v = (&verts[..], &out.screen_verts[..]);
                if smat.alpha < 1.0 || translucent {
                    let lists = (&mut out.transparent, &mut Vec::new());
                    setup_triangles(mesh, v, &setup, lists, |_| ());
                } else {
                    let lists = (&mut out.opaque, &mut out.opaque_boxes);
                    let side = |bbox: &[i32; 4]| TriBox::of_box(bbox, textured);
                    setup_triangles(mesh, v, &setup, lists, side);
                }
                push_lines(&mut out.lines, &mesh.lines, &verts, stroke, &screen);
                push_points(&mut out.points, &mesh.points, &verts, stroke, &screen);
            }
            RenderStyle::Lines => {
                // The polygons' outlines when the mesh keeps them (no
                // triangulation diagonals), else the triangles' edges.
                let mut edges: Vec<[u32; 2]> = Vec::new();
                if mesh.edges.is_empty() {
                    edges.reserve(mesh.triangles.len() * 3 + mesh.lines.len());
                    for t in &mesh.triangles {
                        edges.extend([[t[0], t[1]], [t[1], t[2]], [t[2], t[0]]]);
                    }
                } else {
                    edges.extend(&mesh.edges);
                }
                edges.extend(&mesh.lines);
                if mesh.solid {
                    edges = stroke_faces::front_edges(&mesh.triangles, &edges, &verts);
                }
                push_lines(&mut out.lines, &edges, &verts, stroke, &screen);
                push_points(&mut out.points, &mesh.points, &verts, stroke, &screen);
            }
            RenderStyle::Points if mesh.solid => {
                let front = stroke_faces::front_corners(&mesh.triangles, &verts);
                push_points(&mut out.points, &front, &verts, stroke, &screen);
            }
            RenderStyle::Points | RenderStyle::Hidden => {
                let all: Vec<u32> = (0..mesh.positions.len() as u32).collect();
                push_points(&mut out.points, &all, &verts, stroke, &screen);
            }
        }
        out.items.push(Item {
            id: node_id.0 + 1,
            material: smat,
            lights: item_lights,
            unlit: !has_normals,
            // A solid surface's strokes are its front faces' (above), lit
            // one-sided as Coin lights them.
            surface_strokes: style != RenderStyle::Filled && !mesh.solid,
            textured: texture.is_some() || emissive.is_some(),
            texture,
            emissive,
        });
    }
    out.verts = verts;
    // Back to front by mean depth; the stable sort keeps scene order on ties.
    out.transparent
        .sort_by(|a, b| mean(&b.z).total_cmp(&mean(&a.z)));
}

fn mean(z: &[f32; 3]) -> f32 {
    (z[0] + z[1] + z[2]) / 3.0
}

/// Lights in world space with their scope: `Some(parent)` for a scoped
/// DirectionalLight (lights only `parent`'s descendants), `None` = global.
fn gather_lights(scene: &Scene, pose: &Pose) -> Vec<(Option<NodeId>, WorldLight)> {
    let mut out = Vec::new();
    for (id, light) in &pose.lights {
        let i = id.0 as usize;
        // A light under a hidden group (Inventor Switch) does not shine.
        if !pose.visible.get(i).copied().unwrap_or(true) {
            continue;
        }
        let world = pose.world.get(i).copied().unwrap_or(Mat4::IDENTITY);
        if let Some(wl) = WorldLight::new(light, world) {
            let scope = if light.scoped {
                scene.nodes.get(i).and_then(|n| n.parent)
            } else {
                None
            };
            out.push((scope, wl));
        }
    }
    out
}

fn is_ancestor(scene: &Scene, ancestor: NodeId, mut node: NodeId) -> bool {
    // Bounded by the node count so a malformed parent cycle cannot hang.
    for _ in 0..scene.nodes.len() {
        match scene.nodes.get(node.0 as usize).and_then(|n| n.parent) {
            Some(p) if p == ancestor => return true,
            Some(p) => node = p,
            None => return false,
        }
    }
    false
}

/// Whether every vertex has texture coordinates.
fn has_texcoords(mesh: &Mesh) -> bool {
    !mesh.texcoords.is_empty() && mesh.texcoords.len() == mesh.positions.len()
}

/// Object → clip space, plus world position, world normal, colour and
/// texture coordinates.
fn transform_vertices(
    mesh: &Mesh,
    geo: &Geometry,
    view_proj: Mat4,
    material: &Material,
    has_normals: bool,
    out: &mut Vec<ClipVert>,
) {
    let world = geo.world;
    let mvp = view_proj * world;
    let normal_m = Mat3::from_mat4(world).inverse().transpose();
    let has_colors = mesh.colors.len() == mesh.positions.len();
    let has_uv = has_texcoords(mesh);
    // Unlit geometry (lines/points without normals) shows its own colour or
    // the material's emissive colour (VRML97 IndexedLineSet/PointSet).
    let base = if has_normals {
        material.diffuse
    } else {
        material.emissive
    };
    geo.positions
        .par_iter()
        .enumerate()
        .map(|(k, &p)| {
            let wp = world.transform_point3(p);
            let n = if has_normals {
                (normal_m * geo.normals[k]).normalize_or_zero()
            } else {
                Vec3::ZERO
            };
            let c = if has_colors { mesh.colors[k] } else { base };
            let uv = if has_uv {
                mesh.texcoords[k]
            } else {
                glam::Vec2::ZERO
            };
            ClipVert {
                clip: mvp * p.extend(1.0),
                attr: [wp.x, wp.y, wp.z, n.x, n.y, n.z, c.x, c.y, c.z, uv.x, uv.y],
            }
        })
        .collect_into_vec(out);
}

/// What [`setup_triangles`] needs besides the mesh: the item drawn, the
/// screen mapping, the frame size, and whether the item is textured (its
/// triangles then get their `grad`).
struct Setup<'a> {
    item: u32,
    screen: &'a Screen,
    opts: &'a RenderOptions,
    textured: bool,
}

/// Sets up the triangles of `mesh` from its vertices in clip space and in
/// screen space (`verts`, the same vertices), appending them to the first
/// list in the mesh's order and `side` of each box to the second: chunks of
/// the mesh in parallel, each writing its triangles straight into their
/// place (`in_place`), after a first pass that only counts them.
fn setup_triangles<U: Copy + Send>(
    mesh: &Mesh,
    verts: (&[ClipVert], &[ScreenVert]),
    setup: &Setup,
    lists: (&mut Vec<Tri>, &mut Vec<U>),
    side: impl Fn(&[i32; 4]) -> U + Sync,
) {
    let Setup {
        item,
        screen,
        opts,
        textured,
    } = *setup;
    let mesh_setup = MeshSetup {
        verts,
        screen,
        cull: mesh.solid,
        size: (opts.width as i32, opts.height as i32),
    };
    let tri_flags = (item, textured);
    const CHUNK: usize = 4096;
    let chunks: Vec<&[[u32; 3]]> = mesh.triangles.chunks(CHUNK).collect();
    extend_in_place(
        lists,
        &chunks,
        |chunk| mesh_setup.count(chunk),
        |chunk, sink| {
            mesh_setup.make(chunk, |v, drawn| {
                // SAFETY: `write_triangle` writes every field.
                unsafe { sink.push_with(|slot| side(&write_triangle(v, drawn, tri_flags, slot))) }
            })
        },
    );
}

/// One mesh's set-up: its vertices (in clip and screen space), the
/// screen, whether back faces are culled, and the frame size.
struct MeshSetup<'a> {
    verts: (&'a [ClipVert], &'a [ScreenVert]),
    screen: &'a Screen,
    cull: bool,
    size: (i32, i32),
}

impl MeshSetup<'_> {
    /// How many triangles [`MeshSetup::make`] makes of `tris`, from the
    /// tests alone.
    fn count(&self, tris: &[[u32; 3]]) -> usize {
        let (w, h) = self.size;
        let mut n = 0;
        for t in tris {
            let drawn = |v: [&ScreenVert; 3]| drawn_box(v, self.cull, w, h);
            each_triangle(t, self.verts, self.screen, drawn, |_| n += 1);
        }
        n
    }

    /// The drawn screen triangles of `tris` (vertex indices), in order:
    /// their corners and what [`drawn_box`] says of them, for `emit` to
    /// write (`write_triangle`) where they go.
    fn make(&self, tris: &[[u32; 3]], mut emit: impl FnMut([&ScreenVert; 3], Drawn)) {
        let (w, h) = self.size;
        for t in tris {
            let drawn = |v: [&ScreenVert; 3]| {
                let d = drawn_box(v, self.cull, w, h)?;
                emit(v, d);
                Some(())
            };
            each_triangle(t, self.verts, self.screen, drawn, |()| ());
        }
    }
}

/// What `make` makes of each screen triangle that the mesh triangle `t`
/// (vertex indices into `verts`) gives, passed to `emit`: itself when it
/// is inside every clip plane, nothing when it is outside one, else the
/// fan of its clipped polygon. Counting and setting up triangles walk the
/// same cases.
#[inline(always)]
fn each_triangle<T>(
    t: &[u32; 3],
    (verts, screen_verts): (&[ClipVert], &[ScreenVert]),
    screen: &Screen,
    mut make: impl FnMut([&ScreenVert; 3]) -> Option<T>,
    mut emit: impl FnMut(T),
) {
    if t.iter()
        .any(|&i| i as usize >= verts.len().min(screen_verts.len()))
    {
        return;
    }
    let sv = t.map(|i| &screen_verts[i as usize]);
    let sides = sv[0].sides & sv[1].sides & sv[2].sides;
    if sides >> 8 != 0 {
        // Every vertex outside one plane.
        return;
    }
    if sides & clip::INSIDE_ALL == clip::INSIDE_ALL {
        if let Some(x) = make(sv) {
            emit(x);
        }
        return;
    }
    // Fan the (convex) clipped polygon.
    let tri = t.map(|i| verts[i as usize]);
    let poly = clip::clip_polygon(&tri, screen.guard);
    let poly: Vec<ScreenVert> = poly.iter().map(|v| ScreenVert::of(v, screen)).collect();
    for k in 1..poly.len().saturating_sub(1) {
        if let Some(x) = make([&poly[0], &poly[k], &poly[k + 1]]) {
            emit(x);
        }
    }
}

/// A vertex in screen space, worked out once per vertex for the
/// triangles sharing it (about six in a mesh) rather than once per
/// triangle corner: the very operations `screen_triangle` made per corner,
/// so the same bits.
#[derive(Clone, Copy, Debug, Default)]
pub struct ScreenVert {
    /// Fixed-point (SUBPIXEL) screen position, y down.
    x: i64,
    y: i64,
    /// Window depth.
    z: f32,
    /// Every attribute divided by w, then 1/w: the vertex's values of the
    /// triangle planes (see [`Tri`]).
    planes: [f32; PLANES],
    /// Which sides of the clip planes it is on (`clip::sides`).
    sides: u16,
    /// Its projection is finite (else no triangle through it is drawn).
    finite: bool,
}

impl ScreenVert {
    /// Projects `v` through `screen`.
    fn of(v: &ClipVert, screen: &Screen) -> ScreenVert {
        let (sx, sy, sz, iw) = screen.project(v.clip);
        let mut planes = [iw; PLANES];
        for (p, a) in planes.iter_mut().zip(v.attr) {
            *p = a * iw;
        }
        ScreenVert {
            x: round_i64(sx * SUBPIXEL as f32),
            y: round_i64(sy * SUBPIXEL as f32),
            z: sz,
            planes,
            sides: clip::sides(v.clip, screen.guard),
            finite: sx.is_finite() && sy.is_finite() && sz.is_finite(),
        }
    }
}

/// Every vertex of a mesh in screen space, in parallel.
fn project_vertices(verts: &[ClipVert], screen: &Screen, out: &mut Vec<ScreenVert>) {
    verts
        .par_iter()
        .map(|v| ScreenVert::of(v, screen))
        .collect_into_vec(out);
}

/// What [`drawn_box`] finds of a drawn triangle: its area (twice,
/// signed) and its pixel box.
type Drawn = (i64, [i32; 4]);

/// The area (twice, signed) and pixel box of the triangle through three
/// projected vertices when it is drawn; `None` when it is degenerate,
/// culled as a back face (`cull`), not finite or outside the `w`×`h`
/// frame: the tests set-up makes before [`write_triangle`] writes a
/// triangle, and which counting asks alone.
#[inline(always)]
fn drawn_box(v: [&ScreenVert; 3], cull: bool, w: i32, h: i32) -> Option<Drawn> {
    if !v.iter().all(|v| v.finite) {
        return None;
    }
    let x = v.map(|v| v.x);
    let y = v.map(|v| v.y);
    let area = (x[1] - x[0]) * (y[2] - y[0]) - (y[1] - y[0]) * (x[2] - x[0]);
    // Counter-clockwise in the picture (y up) is negative here (y down).
    if area == 0 || (area > 0 && cull) {
        return None;
    }
    let px = |f: i64| (f >> SUBPIXEL_BITS) as i32;
    let bbox = [
        px(x[0].min(x[1]).min(x[2])).max(0),
        px(y[0].min(y[1]).min(y[2])).max(0),
        (px(x[0].max(x[1]).max(x[2])) + 1).min(w),
        (px(y[0].max(y[1]).max(y[2])) + 1).min(h),
    ];
    if bbox[0] >= bbox[2] || bbox[1] >= bbox[3] {
        return None;
    }
    Some((area, bbox))
}

/// The screen triangle through three projected vertices, oriented (see
/// [`Tri`]), with its planes and, when `textured`, its gradients; `None`
/// when [`drawn_box`] says it is not drawn. Set-up writes its triangles
/// in place instead (`write_triangle`).
#[cfg(test)]
fn screen_triangle(
    v: [&ScreenVert; 3],
    item: u32,
    (cull, textured): (bool, bool),
    w: i32,
    h: i32,
) -> Option<Tri> {
    let drawn = drawn_box(v, cull, w, h)?;
    let mut t = std::mem::MaybeUninit::uninit();
    write_triangle(v, drawn, (item, textured), &mut t);
    // SAFETY: `write_triangle` wrote every field.
    Some(unsafe { t.assume_init() })
}

/// Writes the drawn (`drawn_box`) triangle through three projected
/// vertices into `out`, field by field, oriented (see [`Tri`]), with its
/// planes and, when `textured`, its gradients; returns its box. Field by
/// field and inlined, so set-up writes the 248 bytes straight into their
/// slot: built on the stack, they were copied by 64-byte loads just after
/// narrower stores wrote them, which stalls every load (see
/// `in_place::Sink::push_with`).
#[inline(always)]
fn write_triangle(
    v: [&ScreenVert; 3],
    (area, bbox): Drawn,
    (item, textured): (u32, bool),
    out: &mut std::mem::MaybeUninit<Tri>,
) -> [i32; 4] {
    let mut x = v.map(|v| v.x);
    let mut y = v.map(|v| v.y);
    let mut z = v.map(|v| v.z);
    let back = area > 0;
    let mut at = v.map(|v| v.planes);
    if back {
        // Two-sided lighting: light the side we see (n/w negated is the
        // negated normal over w, bit for bit).
        for a in &mut at {
            for n in &mut a[A_NORMAL..A_NORMAL + 3] {
                *n = -*n;
            }
        }
    }
    if area < 0 {
        x.swap(1, 2);
        y.swap(1, 2);
        z.swap(1, 2);
        at.swap(1, 2);
    }
    let base = at[0];
    let d1 = std::array::from_fn(|j| at[1][j] - at[0][j]);
    let d2 = std::array::from_fn(|j| at[2][j] - at[0][j]);
    // Textured triangles get their screen gradients as they are set up
    // (not in a second pass over megabytes of triangles).
    let grad = if textured {
        Gradients::of(&x, &y, &d1, &d2)
    } else {
        Gradients::default()
    };
    // Every field of `Tri` is written below, one by one: this pattern has
    // no `..`, so a field added to `Tri` stops it compiling until the
    // field is written here too (else it would be left uninitialised).
    let _all_fields = |t: &Tri| {
        let Tri {
            x: _,
            y: _,
            z: _,
            base: _,
            d1: _,
            d2: _,
            item: _,
            bbox: _,
            grad: _,
        } = t;
    };
    let t = out.as_mut_ptr();
    // SAFETY: `t` points to one (uninitialised) `Tri`; each field is
    // written once through a raw pointer, never through a reference.
    unsafe {
        (&raw mut (*t).x).write(x);
        (&raw mut (*t).y).write(y);
        (&raw mut (*t).z).write(z);
        (&raw mut (*t).base).write(base);
        (&raw mut (*t).d1).write(d1);
        (&raw mut (*t).d2).write(d2);
        (&raw mut (*t).item).write(item);
        (&raw mut (*t).bbox).write(bbox);
        (&raw mut (*t).grad).write(grad);
    }
    bbox
}

/// `x.round() as i64` (half away from zero, saturating) without the call
/// to libm's `roundf` that `round` becomes on x86-64's baseline: six per
/// triangle were 2.5 % of a 100k-triangle frame. Truncate, then step away
/// from zero when the remainder is at least a half; `x − trunc(x)` is
/// exact in f32 (Sterbenz), so the result is `round`'s. Values too big for
/// that (and NaN) take `round` itself.
#[inline]
pub fn round_i64(x: f32) -> i64 {
    if x.is_nan() || x.abs() >= (1u64 << 62) as f32 {
        return x.round() as i64;
    }
    let t = x as i64;
    let f = x - t as f32;
    t + (f >= 0.5) as i64 - (f <= -0.5) as i64
}

/// The attribute planes of a triangle (see [`Tri`]) from its corners'
/// attributes and 1/w: what set-up computes from [`ScreenVert`]s, written
/// out for the tests.
#[cfg(test)]
pub fn planes(
    attr: &[[f32; ATTRS]; 3],
    inv_w: &[f32; 3],
) -> ([f32; PLANES], [f32; PLANES], [f32; PLANES]) {
    let mut base = [0.0; PLANES];
    let mut d1 = [0.0; PLANES];
    let mut d2 = [0.0; PLANES];
    for j in 0..PLANES {
        let at = |k: usize| {
            if j == INV_W {
                inv_w[k]
            } else {
                attr[k][j] * inv_w[k]
            }
        };
        base[j] = at(0);
        d1[j] = at(1) - at(0);
        d2[j] = at(2) - at(0);
    }
    (base, d1, d2)
}

/// Which item a line or point belongs to and how wide it is drawn.
#[derive(Clone, Copy)]
struct Stroke {
    item: u32,
    line: i32,
    point: i32,
}

fn push_lines(out: &mut Vec<Line>, edges: &[[u32; 2]], verts: &[ClipVert], k: Stroke, s: &Screen) {
    let n = verts.len();
    for e in edges {
        if e[0] as usize >= n || e[1] as usize >= n {
            continue;
        }
        let Some((a, b)) =
            clip::clip_segment(&verts[e[0] as usize], &verts[e[1] as usize], s.guard)
        else {
            continue;
        };
        let (ax, ay, az, aw) = s.project(a.clip);
        let (bx, by, bz, bw) = s.project(b.clip);
        if ![ax, ay, az, bx, by, bz].iter().all(|v| v.is_finite()) {
            continue;
        }
        // A wide line reaches half its width further each way.
        let reach = 1 + k.line / 2;
        let bbox = [
            (ax.min(bx).floor() as i32 - reach).max(0),
            (ay.min(by).floor() as i32 - reach).max(0),
            (ax.max(bx).ceil() as i32 + reach).min(s.w as i32),
            (ay.max(by).ceil() as i32 + reach).min(s.h as i32),
        ];
        if bbox[0] >= bbox[2] || bbox[1] >= bbox[3] {
            continue;
        }
        out.push(Line {
            x: [ax, bx],
            y: [ay, by],
            z: [az, bz],
            inv_w: [aw, bw],
            attr: [a.attr, b.attr],
            item: k.item,
            width: k.line,
            bbox,
        });
    }
}

fn push_points(out: &mut Vec<Point>, idx: &[u32], verts: &[ClipVert], k: Stroke, s: &Screen) {
    let size = k.point;
    for &i in idx {
        let Some(v) = verts.get(i as usize) else {
            continue;
        };
        let c = v.clip;
        if c.z < -c.w || c.z > c.w || c.w <= 0.0 {
            continue;
        }
        let (x, y, z, _) = s.project(c);
        if !(x.is_finite() && y.is_finite())
            || x < -(size as f32) - 4.0
            || y < -(size as f32) - 4.0
            || x > s.w + size as f32 + 4.0
            || y > s.h + size as f32 + 4.0
        {
            continue;
        }
        // OpenGL's square (2.1 §3.3.1), in our y-down rows: an odd size is
        // centred on the pixel holding the point (row ⌈y⌉−1 is GL's
        // ⌊y_gl⌋), an even one on the nearest pixel corner.
        let (x0, y0) = if size % 2 == 1 {
            let r = (size - 1) / 2;
            (x.floor() as i32 - r, y.ceil() as i32 - 1 - r)
        } else {
            let r = size / 2;
            ((x + 0.5).floor() as i32 - r, (y - 0.5).ceil() as i32 - r)
        };
        let bbox = [
            x0.max(0),
            y0.max(0),
            (x0 + size).min(s.w as i32),
            (y0 + size).min(s.h as i32),
        ];
        if bbox[0] >= bbox[2] || bbox[1] >= bbox[3] {
            continue;
        }
        let bbox = if s.aa {
            // Anti-aliased: the square may touch one more pixel each way.
            [
                (x0 - 1).max(0),
                (y0 - 1).max(0),
                (x0 + size + 1).min(s.w as i32),
                (y0 + size + 1).min(s.h as i32),
            ]
        } else {
            bbox
        };
        out.push(Point {
            c: [x, y],
            z,
            attr: v.attr,
            item: k.item,
            size,
            bbox,
        });
    }
}

/// A triangle with no attributes, corners at pixel positions `pts` and
/// window depths `z`, turned to the positive winding, its box the pixels
/// its corners span (unclamped): what the depth-pass tests draw.
#[cfg(test)]
pub fn test_tri(pts: [(f64, f64); 3], z: [f32; 3]) -> Tri {
    let fx = |v: f64| (v * SUBPIXEL as f64).round() as i64;
    let (base, d1, d2) = planes(&[[0.0; ATTRS]; 3], &[1.0; 3]);
    let mut t = Tri {
        x: pts.map(|p| fx(p.0)),
        y: pts.map(|p| fx(p.1)),
        z,
        base,
        d1,
        d2,
        item: 0,
        bbox: [0; 4],
        grad: Gradients::default(),
    };
    if t.area() < 0 {
        t.x.swap(1, 2);
        t.y.swap(1, 2);
        t.z.swap(1, 2);
    }
    let px = |f: i64| (f >> 8) as i32;
    t.bbox = [
        px(*t.x.iter().min().unwrap()),
        px(*t.y.iter().min().unwrap()),
        px(*t.x.iter().max().unwrap()) + 1,
        px(*t.y.iter().max().unwrap()) + 1,
    ];
    t
}

#[cfg(test)]
mod round_tests {
    use super::round_i64;

    /// `round_i64` is `round() as i64` on halves, near-halves, both signs,
    /// the edges of exact integers (2²³, 2²⁴), huge values and NaN.
    #[test]
    fn round_i64_matches_round() {
        let mut xs = vec![
            0.0f32,
            -0.0,
            0.5,
            -0.5,
            1.5,
            -1.5,
            2.5,
            -2.5,
            1e30,
            -1e30,
            f32::NAN,
        ];
        xs.extend([
            f32::INFINITY,
            f32::NEG_INFINITY,
            f32::MAX,
            f32::MIN,
            4.6e18,
            -4.6e18,
            9.3e18,
        ]);
        for e in [1.0f32, 8388608.0, 16777216.0] {
            for k in -40..40 {
                let x = e + k as f32 * 0.25;
                xs.extend([
                    x,
                    -x,
                    x.next_up(),
                    x.next_down(),
                    -x.next_up(),
                    -x.next_down(),
                ]);
            }
        }
        // Every 997th bit pattern: all exponents, signs and fractions.
        xs.extend((0..u32::MAX / 997).map(|i| f32::from_bits(i * 997)));
        for x in xs {
            assert_eq!(round_i64(x), x.round() as i64, "{x:e} ({:#x})", x.to_bits());
        }
    }
}

#[cfg(test)]
mod screen_vert_tests {
    use super::*;
    use crate::internals::render::test_rng::XorShift;

    /// Triangles set up from vertices projected once ([`ScreenVert`]) have
    /// the bits of the per-corner set-up they replace: each corner
    /// projected and snapped, the seen side's normal, then [`planes`] of
    /// the attributes and 1/w — front and back faces, both windings.
    #[test]
    fn projected_vertices_give_the_per_corner_triangles_bits() {
        let screen = Screen {
            w: 320.0,
            h: 240.0,
            guard: MAX_SCREEN / 320.0,
            aa: false,
        };
        let mut rng = XorShift::new(0x853C_49E6_748F_EA9B);
        let mut next = || rng.unit() as f32 * 2.0 - 1.0;
        let mut checked = [0; 2];
        for _ in 0..5000 {
            let verts: [ClipVert; 3] = std::array::from_fn(|_| {
                let w = 1.0 + next().abs() * 4.0;
                ClipVert {
                    clip: Vec4::new(next() * w, next() * w, next() * w, w),
                    attr: std::array::from_fn(|_| next() * 3.0),
                }
            });
            let sv = verts.map(|v| ScreenVert::of(&v, &screen));
            let got = screen_triangle([&sv[0], &sv[1], &sv[2]], 7, (false, false), 320, 240);
            // The per-corner reference.
            let p = verts.map(|v| screen.project(v.clip));
            let mut x = p.map(|p| round_i64(p.0 * SUBPIXEL as f32));
            let mut y = p.map(|p| round_i64(p.1 * SUBPIXEL as f32));
            let mut z = p.map(|p| p.2);
            let mut inv_w = p.map(|p| p.3);
            let area = (x[1] - x[0]) * (y[2] - y[0]) - (y[1] - y[0]) * (x[2] - x[0]);
            let Some(t) = got else {
                continue;
            };
            let mut attr = verts.map(|v| v.attr);
            if area > 0 {
                for a in &mut attr {
                    for n in &mut a[A_NORMAL..A_NORMAL + 3] {
                        *n = -*n;
                    }
                }
            }
            if area < 0 {
                x.swap(1, 2);
                y.swap(1, 2);
                z.swap(1, 2);
                inv_w.swap(1, 2);
                attr.swap(1, 2);
            }
            let (base, d1, d2) = planes(&attr, &inv_w);
            let bits = |a: &[f32]| a.iter().map(|v| v.to_bits()).collect::<Vec<_>>();
            assert_eq!((t.x, t.y), (x, y));
            assert_eq!(bits(&t.z), bits(&z));
            assert_eq!(bits(&t.base), bits(&base));
            assert_eq!(bits(&t.d1), bits(&d1));
            assert_eq!(bits(&t.d2), bits(&d2));
            checked[(area > 0) as usize] += 1;
        }
        assert!(checked[0] > 500 && checked[1] > 500, "{checked:?}");
    }
}

#[cfg(test)]
mod count_tests {
    use super::*;
    use crate::internals::render::test_rng::XorShift;

    /// Counting a mesh's triangles gives what setting them up makes:
    /// seeded meshes with back faces (culled or not), degenerate and
    /// off-screen triangles, vertices behind the eye and beyond the
    /// guard band (clipped into fans), non-finite vertices and indices
    /// past the end. A miscount would only slow set-up down (the
    /// in-place append falls back to a serial one), so it is checked
    /// here.
    #[test]
    fn counting_agrees_with_setting_up() {
        let opts = RenderOptions {
            width: 320,
            height: 240,
            ..RenderOptions::default()
        };
        let screen = Screen {
            w: 320.0,
            h: 240.0,
            guard: MAX_SCREEN / 320.0,
            aa: false,
        };
        let mut rng = XorShift::new(0x9E37_79B9_7F4A_7C15);
        let mut next = || rng.unit() as f32;
        let (mut made, mut fans, mut dropped) = (0, 0, 0);
        for mesh in 0..40 {
            let verts: Vec<ClipVert> = (0..60)
                .map(|k| {
                    let w = if k % 17 == 3 {
                        -0.5
                    } else {
                        0.2 + next() * 3.0
                    };
                    let far = if k % 13 == 5 { 1e6 } else { 1.5 };
                    let mut clip = Vec4::new(
                        (next() * 2.0 - 1.0) * w * far,
                        (next() * 2.0 - 1.0) * w * 1.5,
                        (next() * 2.2 - 1.1) * w,
                        w,
                    );
                    if k == 7 {
                        clip.x = f32::NAN;
                    }
                    ClipVert {
                        clip,
                        attr: std::array::from_fn(|_| next()),
                    }
                })
                .collect();
            let mut screen_verts = Vec::new();
            project_vertices(&verts, &screen, &mut screen_verts);
            let tris: Vec<[u32; 3]> = (0..300)
                .map(|k| {
                    let mut t = [0, 1, 2].map(|_| (next() * 60.0) as u32 % 60);
                    if k % 50 == 0 {
                        t[1] = 60 + k;
                    }
                    if k % 40 == 1 {
                        t[2] = t[0];
                    }
                    t
                })
                .collect();
            let setup = MeshSetup {
                verts: (&verts, &screen_verts),
                screen: &screen,
                cull: mesh % 2 == 0,
                size: (opts.width as i32, opts.height as i32),
            };
            for part in tris.chunks(37) {
                let mut n = 0;
                setup.make(part, |_, _| n += 1);
                assert_eq!(setup.count(part), n, "mesh {mesh}");
                made += n;
                fans += part
                    .iter()
                    .filter(|t| {
                        let s = t.map(|i| screen_verts.get(i as usize).map_or(0, |v| v.sides));
                        let s = s[0] & s[1] & s[2];
                        s >> 8 == 0 && s & clip::INSIDE_ALL != clip::INSIDE_ALL
                    })
                    .count();
                dropped += part.iter().filter(|t| setup.count(&[**t]) == 0).count();
            }
        }
        assert!(
            made > 2000 && fans > 300 && dropped > 2000,
            "{made} {fans} {dropped}"
        );
    }
}

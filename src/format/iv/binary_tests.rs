//! Tests of the binary Inventor reader: SGI's star in binary against its
//! ASCII twin (converted by SGI's ivcat), and hostile inputs.

use super::{read_binary_nested, read_nested};
use crate::format::Loaded;
use crate::scene::{NodeKind, Scene};
use std::path::Path;

const STAR_BINARY: &[u8] = include_bytes!("../../../tests/data/readers/star.ivb");
const STAR_ASCII: &[u8] = include_bytes!("../../../tests/data/readers/star.iv");

fn binary(bytes: &[u8]) -> Result<Loaded, String> {
    read_binary_nested(bytes, Path::new("b.iv"), 0).map_err(|e| e.to_string())
}

/// A mesh's positions, normals and triangles.
type Geometry = (Vec<glam::Vec3>, Vec<glam::Vec3>, Vec<[u32; 3]>);

/// Every shape's mesh.
fn meshes(s: &Scene) -> Vec<Geometry> {
    s.nodes
        .iter()
        .filter_map(|n| match &n.kind {
            NodeKind::Shape(sh) => {
                let m = &s.meshes[sh.mesh.0 as usize];
                Some((m.positions.clone(), m.normals.clone(), m.triangles.clone()))
            }
            _ => None,
        })
        .collect()
}

#[test]
fn the_binary_star_is_the_scene_of_its_ascii_twin() {
    let b = binary(STAR_BINARY).unwrap();
    let a = read_nested(STAR_ASCII, Path::new("a.iv"), 0, false).unwrap();
    assert!(b.warnings.is_empty(), "{:?}", b.warnings);
    assert_eq!(b.scene.nodes.len(), a.scene.nodes.len());
    let (mb, ma) = (meshes(&b.scene), meshes(&a.scene));
    assert_eq!(mb.len(), 1);
    assert_eq!(mb.len(), ma.len());
    for ((pb, nb, tb), (pa, na, ta)) in mb.iter().zip(&ma) {
        // ivcat printed 6 significant digits; the binary holds the floats.
        assert_eq!(tb, ta);
        assert_eq!(pb.len(), 52);
        for (x, y) in pb.iter().zip(pa).chain(nb.iter().zip(na)) {
            assert!((*x - *y).abs().max_element() < 1e-5, "{x} vs {y}");
        }
    }
}

#[test]
fn a_truncated_file_is_an_error_with_a_byte_offset_at_every_length() {
    let header = STAR_BINARY.iter().position(|&b| b == b'\n').unwrap() + 1;
    for len in header + 1..STAR_BINARY.len() {
        let e = binary(&STAR_BINARY[..len]).map(|_| ()).unwrap_err();
        assert!(e.starts_with("b.iv: byte "), "{len}: {e}");
    }
}

/// A binary file: header, then big-endian words and padded strings.
struct File(Vec<u8>);

impl File {
    /// The header line padded to 24 bytes, as SGI's writer pads it.
    fn new(version: &str) -> File {
        File(format!("#Inventor {version} binary  \n").into_bytes())
    }
    fn word(mut self, w: u32) -> File {
        self.0.extend(w.to_be_bytes());
        self
    }
    fn string(mut self, s: &str) -> File {
        self.0.extend((s.len() as u32).to_be_bytes());
        self.0.extend(s.as_bytes());
        self.0
            .resize(self.0.len() + s.len().next_multiple_of(4) - s.len(), 0);
        self
    }
}

#[test]
fn hostile_counts_names_and_nesting_are_errors_not_allocations() {
    // A Coordinate3 claiming four billion points.
    let huge = File::new("V2.0")
        .string("Coordinate3")
        .word(1)
        .string("point")
        .word(u32::MAX);
    let e = binary(&huge.0).map(|_| ()).unwrap_err();
    assert!(
        e.contains("byte 56: value count 4294967295 is more than the file holds"),
        "{e}"
    );
    // A string longer than the file.
    let long = File::new("V2.0").word(1 << 30);
    let e = binary(&long.0).map(|_| ()).unwrap_err();
    assert!(e.contains("byte 24: string of"), "{e}");
    // A group claiming more children than the file has bytes.
    let kids = File::new("V2.0").string("Separator").word(0).word(1 << 28);
    let e = binary(&kids.0).map(|_| ()).unwrap_err();
    assert!(e.contains("child count"), "{e}");
    // A node type whose fields this reader cannot know.
    let unknown = File::new("V2.0").string("MyNode").word(1).string("x");
    let e = binary(&unknown.0).map(|_| ()).unwrap_err();
    assert!(
        e.contains("'MyNode' is not a node this reader knows"),
        "{e}"
    );
    // Deep nesting: a chain of Groups, one inside the other.
    let mut deep = File::new("V2.0");
    for _ in 0..100_000 {
        deep = deep.string("Group").word(1);
    }
    let e = binary(&deep.0).map(|_| ()).unwrap_err();
    assert!(e.contains("--max-depth"), "{e}");
    // USE of a name never defined.
    let e = binary(&File::new("V2.1").string("USE").string("nope").0)
        .map(|_| ())
        .unwrap_err();
    assert!(e.contains("USE of undefined name 'nope'"), "{e}");
}

#[test]
fn nodes_not_built_in_carry_their_field_types_and_v21_writes_flags() {
    // V2.1: flags word after the type; an extension node describing its
    // one field (NOT_BUILT_IN in the fields word), then a DEF'd cube.
    let f = File::new("V2.1")
        .string("Separator")
        .word(0x02)
        .word(0)
        .word(2)
        .string("MyNode")
        .word(0)
        .word(0x4000 | 1)
        .string("MFFloat")
        .string("weights")
        .string("weights")
        .word(2)
        .word(1.0f32.to_bits())
        .word(2.0f32.to_bits())
        .word(0)
        .string("DEF")
        .string("Box")
        .string("Cube")
        .word(0)
        .word(1)
        .string("width")
        .word(3.0f32.to_bits())
        .word(0);
    let l = binary(&f.0).unwrap();
    let id = l.scene.find_node("Box").expect("the DEF'd cube");
    let NodeKind::Shape(s) = &l.scene.node(id).kind else {
        panic!("not a shape");
    };
    let (lo, hi) = l.scene.meshes[s.mesh.0 as usize].bounds().unwrap();
    assert_eq!((hi - lo).x, 3.0);
}

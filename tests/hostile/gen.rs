//! Generators of hostile inputs: each returns the bytes of a small file
//! that asks a reader for far more than it is (or a deep recursion), so the
//! suite needs no big files in the repository.

use std::io::Write;

/// `n` PROTOs, each instancing the previous one inside a Group: 2n levels
/// deep once expanded, from a file a few dozen bytes per level.
pub fn proto_chain(n: usize) -> Vec<u8> {
    let mut s = String::from("#VRML V2.0 utf8\nPROTO P0 [] { Shape { geometry Box {} } }\n");
    for i in 1..n {
        s += &format!("PROTO P{i} [] {{ Group {{ children P{} {{}} }} }}\n", i - 1);
    }
    s += &format!("P{} {{}}\n", n - 1);
    s.into_bytes()
}

/// `n` Groups nested in the text.
pub fn nested_groups(n: usize) -> Vec<u8> {
    let mut s = String::from("#VRML V2.0 utf8\n");
    for _ in 0..n {
        s += "Group { children [\n";
    }
    s += "Shape { geometry Box {} }\n";
    for _ in 0..n {
        s += "] }\n";
    }
    s.into_bytes()
}

/// Binary Inventor 2.0: `n` Separators one inside the other, a Cube in
/// the innermost (big-endian words; strings padded to a word).
pub fn binary_nested_separators(n: usize) -> Vec<u8> {
    let mut b = b"#Inventor V2.0 binary  \n".to_vec();
    let string = |b: &mut Vec<u8>, s: &str| {
        b.extend((s.len() as u32).to_be_bytes());
        b.extend(s.as_bytes());
        b.resize(b.len() + s.len().next_multiple_of(4) - s.len(), 0);
    };
    for _ in 0..n {
        string(&mut b, "Separator");
        b.extend(0u32.to_be_bytes()); // no fields
        b.extend(1u32.to_be_bytes()); // one child
    }
    string(&mut b, "Cube");
    b.extend(0u32.to_be_bytes());
    b
}

/// An Extrusion of `n` cross-section points along `n` spine points
/// (n² vertices from 5n numbers).
pub fn extrusion(n: usize) -> Vec<u8> {
    let cs: Vec<String> = (0..n).map(|i| format!("{} {}", i % 7, i % 5)).collect();
    let sp: Vec<String> = (0..n).map(|i| format!("0 {i} 0")).collect();
    format!(
        "#VRML V2.0 utf8\nShape {{ geometry Extrusion {{ crossSection [{}] spine [{}] }} }}\n",
        cs.join(" "),
        sp.join(" ")
    )
    .into_bytes()
}

/// An ElevationGrid of n × n heights (n² numbers written as `0`).
pub fn elevation_grid(n: usize) -> Vec<u8> {
    let mut s = format!(
        "#VRML V2.0 utf8\nShape {{ geometry ElevationGrid {{ xDimension {n} zDimension {n} height ["
    );
    s += &"0 ".repeat(n * n);
    s += "] } }\n";
    s.into_bytes()
}

/// DEF/USE doubling: level i holds two USEs of level i-1 (2^levels boxes).
pub fn def_use_doubling(levels: usize) -> Vec<u8> {
    let mut s = String::from("#VRML V2.0 utf8\nDEF A0 Shape { geometry Box {} }\n");
    for i in 1..levels {
        s += &format!(
            "DEF A{i} Group {{ children [ USE A{} USE A{} ] }}\n",
            i - 1,
            i - 1
        );
    }
    s.into_bytes()
}

/// The same doubling through PROTO instancing.
pub fn proto_doubling(levels: usize) -> Vec<u8> {
    let mut s = String::from("#VRML V2.0 utf8\nPROTO P0 [] { Shape { geometry Box {} } }\n");
    for i in 1..levels {
        s += &format!(
            "PROTO P{i} [] {{ Group {{ children [ P{p} {{}} P{p} {{}} ] }} }}\n",
            p = i - 1
        );
    }
    s += &format!("P{} {{}}\n", levels - 1);
    s.into_bytes()
}

/// Gzip of `fields` Coordinate fields of `per_field` zeros each.
pub fn gzip_numbers(fields: usize, per_field: usize) -> Vec<u8> {
    let mut e = flate2::write::GzEncoder::new(Vec::new(), flate2::Compression::fast());
    e.write_all(b"#VRML V2.0 utf8\n").unwrap();
    let chunk = "0 ".repeat(1 << 16);
    for _ in 0..fields {
        e.write_all(b"Shape { geometry PointSet { coord Coordinate { point [")
            .unwrap();
        let mut left = per_field;
        while left > 0 {
            let k = left.min(1 << 16);
            e.write_all(&chunk.as_bytes()[..2 * k]).unwrap();
            left -= k;
        }
        e.write_all(b"] } } }\n").unwrap();
    }
    e.finish().unwrap()
}

/// A gzip bomb: `mib` MiB of spaces after a VRML header.
pub fn gzip_bomb(mib: usize) -> Vec<u8> {
    let mut e = flate2::write::GzEncoder::new(Vec::new(), flate2::Compression::best());
    e.write_all(b"#VRML V2.0 utf8\n").unwrap();
    let block = vec![b' '; 1 << 20];
    for _ in 0..mib {
        e.write_all(&block).unwrap();
    }
    e.finish().unwrap()
}

/// Many small strings: each costs far more memory than its 3 bytes.
pub fn many_strings(n: usize) -> Vec<u8> {
    let mut s = String::from("#VRML V2.0 utf8\nWorldInfo { info [");
    s += &"\"a\" ".repeat(n);
    s += "] }\n";
    s.into_bytes()
}

/// A node with `n` one-number fields (each field costs ~100 bytes).
pub fn many_fields(n: usize) -> Vec<u8> {
    let mut s = String::from("#Inventor V2.1 ascii\nSeparator { Info { ");
    s += &"a 1 ".repeat(n);
    s += "} }\n";
    s.into_bytes()
}

/// An Inline of `target` (a device, FIFO or file).
pub fn inline_of(target: &str) -> Vec<u8> {
    format!("#VRML V2.0 utf8\nInline {{ url \"{target}\" }}\n").into_bytes()
}

/// A file inlining `name` `n` times (each copy counts).
pub fn inline_many(name: &str, n: usize) -> Vec<u8> {
    let mut s = String::from("#VRML V2.0 utf8\n");
    for _ in 0..n {
        s += &format!("Inline {{ url \"{name}\" }}\n");
    }
    s.into_bytes()
}

/// `n` nested Separators, each with a Translation (Inventor).
pub fn nested_separators(n: usize) -> Vec<u8> {
    let mut s = String::from("#Inventor V2.1 ascii\n");
    for _ in 0..n {
        s += "Separator { Translation { translation 0.1 0 0 }\n";
    }
    s += "Cube {}\n";
    s += &"}\n".repeat(n);
    s.into_bytes()
}

/// VRML 1.0 with `n` sibling DEF'd Groups: state leaks from each into the
/// next, so the scene nests n deep though the file nests 3.
pub fn vrml1_sibling_groups(n: usize) -> Vec<u8> {
    let mut s = String::from("#VRML V1.0 ascii\nSeparator {\n");
    for i in 0..n {
        s += &format!("DEF G{i} Group {{ Translation {{ translation 0.1 0 0 }} Cube {{}} }}\n");
    }
    s += "}\n";
    s.into_bytes()
}

/// VRML 1.0 with `n` sibling DEF'd Transforms, each moving what follows.
pub fn vrml1_sibling_transforms(n: usize) -> Vec<u8> {
    let mut s = String::from("#VRML V1.0 ascii\nSeparator {\n");
    for i in 0..n {
        s += &format!("DEF T{i} Transform {{ translation 0.01 0 0 }} Cube {{}}\n");
    }
    s += "}\n";
    s.into_bytes()
}

//! The writer's binary buffer: one buffer, one buffer view per accessor,
//! 4-byte aligned, little-endian — and the accessor JSON that describes
//! each piece.

use serde_json::{json, Value as Json};

/// Accumulates the binary buffer, its views and accessors.
#[derive(Default)]
pub struct Bin {
    pub bytes: Vec<u8>,
    pub views: Vec<Json>,
    pub accessors: Vec<Json>,
}

/// An f32 as the shortest decimal that reads back as the same f32, so the
/// JSON is short and round-trips bit for bit.
pub fn num(x: f32) -> Json {
    if !x.is_finite() {
        return json!(0);
    }
    let s = format!("{x}");
    match s.parse::<f64>() {
        Ok(v) if v == v.trunc() && v.abs() < 1e15 => json!(v as i64),
        Ok(v) => json!(v),
        Err(_) => json!(0),
    }
}

pub fn nums(xs: &[f32]) -> Json {
    Json::Array(xs.iter().map(|&x| num(x)).collect())
}

/// glTF's accessor type name for a component count.
fn type_name(n: usize) -> &'static str {
    match n {
        1 => "SCALAR",
        2 => "VEC2",
        3 => "VEC3",
        4 => "VEC4",
        _ => "MAT4",
    }
}

impl Bin {
    fn view(&mut self, data: &[u8], target: Option<u32>) -> usize {
        while !self.bytes.len().is_multiple_of(4) {
            self.bytes.push(0);
        }
        let mut v = json!({
            "buffer": 0,
            "byteOffset": self.bytes.len(),
            "byteLength": data.len(),
        });
        if let Some(t) = target {
            v["target"] = json!(t);
        }
        self.bytes.extend_from_slice(data);
        self.views.push(v);
        self.views.len() - 1
    }

    /// A buffer view of raw bytes (an embedded image), with no target.
    pub fn raw(&mut self, data: &[u8]) -> usize {
        self.view(data, None)
    }

    /// Float accessor of `n`-component elements. `bounds`: write min/max
    /// (required for POSITION and animation inputs).
    pub fn floats(&mut self, data: &[f32], n: usize, bounds: bool, target: Option<u32>) -> usize {
        let mut bytes = Vec::with_capacity(data.len() * 4);
        for x in data {
            bytes.extend_from_slice(&x.to_le_bytes());
        }
        let view = self.view(&bytes, target);
        let count = data.len() / n.max(1);
        let mut a = json!({
            "bufferView": view,
            "componentType": 5126,
            "count": count,
            "type": type_name(n),
        });
        if bounds && count > 0 {
            let mut lo = vec![f32::INFINITY; n];
            let mut hi = vec![f32::NEG_INFINITY; n];
            for e in data.chunks_exact(n) {
                for c in 0..n {
                    lo[c] = lo[c].min(e[c]);
                    hi[c] = hi[c].max(e[c]);
                }
            }
            a["min"] = nums(&lo);
            a["max"] = nums(&hi);
        }
        self.accessors.push(a);
        self.accessors.len() - 1
    }

    /// Unsigned-short VEC4 vertex attribute (JOINTS_0).
    pub fn joints(&mut self, data: &[[u16; 4]]) -> usize {
        let mut bytes = Vec::with_capacity(data.len() * 8);
        for j in data.iter().flatten() {
            bytes.extend_from_slice(&j.to_le_bytes());
        }
        let view = self.view(&bytes, Some(34962));
        self.accessors.push(json!({
            "bufferView": view,
            "componentType": 5123,
            "count": data.len(),
            "type": "VEC4",
        }));
        self.accessors.len() - 1
    }

    /// Unsigned-int index accessor (element array buffer).
    pub fn indices(&mut self, data: &[u32]) -> usize {
        let mut bytes = Vec::with_capacity(data.len() * 4);
        for x in data {
            bytes.extend_from_slice(&x.to_le_bytes());
        }
        let view = self.view(&bytes, Some(34963));
        self.accessors.push(json!({
            "bufferView": view,
            "componentType": 5125,
            "count": data.len(),
            "type": "SCALAR",
        }));
        self.accessors.len() - 1
    }
}

/// A .glb: header, JSON chunk (space-padded), BIN chunk (zero-padded).
pub fn glb(json: &[u8], bin: &[u8]) -> Vec<u8> {
    let pad = |n: usize| (4 - n % 4) % 4;
    let json_len = json.len() + pad(json.len());
    let bin_len = bin.len() + pad(bin.len());
    let total = 12 + 8 + json_len + if bin.is_empty() { 0 } else { 8 + bin_len };
    let mut out = Vec::with_capacity(total);
    out.extend_from_slice(b"glTF");
    out.extend_from_slice(&2u32.to_le_bytes());
    out.extend_from_slice(&(total as u32).to_le_bytes());
    out.extend_from_slice(&(json_len as u32).to_le_bytes());
    out.extend_from_slice(b"JSON");
    out.extend_from_slice(json);
    out.resize(out.len() + pad(json.len()), b' ');
    if !bin.is_empty() {
        out.extend_from_slice(&(bin_len as u32).to_le_bytes());
        out.extend_from_slice(b"BIN\0");
        out.extend_from_slice(bin);
        out.resize(out.len() + pad(bin.len()), 0);
    }
    out
}

//! Reading accessors (spec §3.6): every component type, normalised
//! integers (§3.11: `max(c / (2ⁿ⁻¹ − 1), −1)` signed, `c / (2ⁿ − 1)`
//! unsigned), byte strides, matrix column padding and sparse substitution.
//! Every read is bounds-checked against its buffer view and buffer, so a
//! hostile file gets an error naming the accessor, never a panic; an
//! accessor without a buffer view (all zeros, maybe sparse) is capped at
//! [`MAX_VIEWLESS`] elements so its `count` cannot allocate without limit.

use super::container::{Buffers, GltfError, Result};
use super::pointer::pointer;
use gltf::accessor::{DataType, Dimensions};
use gltf::Accessor;

/// Largest element count of an accessor that has no buffer view.
pub const MAX_VIEWLESS: usize = 1 << 24;

pub fn components(d: Dimensions) -> usize {
    match d {
        Dimensions::Scalar => 1,
        Dimensions::Vec2 => 2,
        Dimensions::Vec3 => 3,
        Dimensions::Vec4 => 4,
        Dimensions::Mat2 => 4,
        Dimensions::Mat3 => 9,
        Dimensions::Mat4 => 16,
    }
}

fn size_of(t: DataType) -> usize {
    match t {
        DataType::I8 | DataType::U8 => 1,
        DataType::I16 | DataType::U16 => 2,
        DataType::U32 | DataType::F32 => 4,
    }
}

/// Byte offset of component `c` inside an element, and the element size
/// (matrix columns start on 4-byte boundaries, §3.6.2.4).
fn layout(d: Dimensions, t: DataType) -> (Vec<usize>, usize) {
    let size = size_of(t);
    let rows = match d {
        Dimensions::Mat2 => 2,
        Dimensions::Mat3 => 3,
        Dimensions::Mat4 => 4,
        _ => {
            let n = components(d);
            return ((0..n).map(|c| c * size).collect(), n * size);
        }
    };
    let column = (rows * size).div_ceil(4) * 4;
    let offsets = (0..rows * rows)
        .map(|c| (c / rows) * column + (c % rows) * size)
        .collect();
    (offsets, rows * column)
}

/// One component as f32 (normalised when asked).
#[inline]
fn decode(t: DataType, normalized: bool, b: &[u8]) -> f32 {
    match t {
        DataType::F32 => f32::from_le_bytes([b[0], b[1], b[2], b[3]]),
        DataType::U8 if normalized => b[0] as f32 / 255.0,
        DataType::U8 => b[0] as f32,
        DataType::I8 if normalized => (b[0] as i8 as f32 / 127.0).max(-1.0),
        DataType::I8 => b[0] as i8 as f32,
        DataType::U16 => {
            let v = u16::from_le_bytes([b[0], b[1]]) as f32;
            if normalized {
                v / 65535.0
            } else {
                v
            }
        }
        DataType::I16 => {
            let v = i16::from_le_bytes([b[0], b[1]]) as f32;
            if normalized {
                (v / 32767.0).max(-1.0)
            } else {
                v
            }
        }
        DataType::U32 => u32::from_le_bytes([b[0], b[1], b[2], b[3]]) as f32,
    }
}

/// The bytes of buffer view `view` checked against its buffer.
fn view_bytes<'b>(view: &gltf::buffer::View, buffers: &'b Buffers) -> Result<&'b [u8]> {
    let here = pointer(&[&"bufferViews", &view.index()]);
    let data = buffers
        .data
        .get(view.buffer().index())
        .ok_or_else(|| GltfError::at(format!("{here}/buffer"), "no such buffer"))?;
    view.offset()
        .checked_add(view.length())
        .and_then(|end| data.get(view.offset()..end))
        .ok_or_else(|| {
            GltfError::at(
                here,
                format!(
                    "bytes {}..{}+{} are past the end of buffer {} ({} bytes)",
                    view.offset(),
                    view.offset(),
                    view.length(),
                    view.buffer().index(),
                    data.len()
                ),
            )
        })
}

/// Reads `count` elements laid out with `stride` from `bytes` at `offset`.
#[allow(clippy::too_many_arguments)]
fn read_dense(
    here: &str,
    bytes: &[u8],
    offset: usize,
    stride: Option<usize>,
    count: usize,
    d: Dimensions,
    t: DataType,
    normalized: bool,
    out: &mut Vec<f32>,
) -> Result<()> {
    let (comp_offsets, elem) = layout(d, t);
    let stride = stride.unwrap_or(elem);
    if stride < elem {
        return Err(GltfError::at(
            here,
            format!("byte stride {stride} is smaller than an element ({elem} bytes)"),
        ));
    }
    let needed = if count == 0 {
        Some(0)
    } else {
        (count - 1)
            .checked_mul(stride)
            .and_then(|n| n.checked_add(elem))
            .and_then(|n| n.checked_add(offset))
    };
    match needed {
        Some(n) if n <= bytes.len() => {}
        _ => {
            return Err(GltfError::at(
                here,
                format!(
                    "{count} elements of {elem} bytes (stride {stride}) from byte {offset} \
                     run past the end of the buffer view ({} bytes)",
                    bytes.len()
                ),
            ))
        }
    }
    let n = comp_offsets.len();
    out.reserve(count * n);
    let size = size_of(t);
    if t == DataType::F32 && stride == elem && d != Dimensions::Mat2 && d != Dimensions::Mat3 {
        // Tightly packed floats: the common case, one pass.
        let src = &bytes[offset..offset + count * elem];
        out.extend(
            src.chunks_exact(4)
                .map(|b| f32::from_le_bytes([b[0], b[1], b[2], b[3]])),
        );
        return Ok(());
    }
    for i in 0..count {
        let at = offset + i * stride;
        for &c in &comp_offsets {
            out.push(decode(t, normalized, &bytes[at + c..at + c + size]));
        }
    }
    Ok(())
}

/// Reads an accessor as f32 components (`count × components`), applying
/// normalisation and sparse substitution. `here` is the pointer of the
/// place that refers to the accessor, for messages.
pub fn read_f32(acc: &Accessor, buffers: &Buffers) -> Result<Vec<f32>> {
    let here = pointer(&[&"accessors", &acc.index()]);
    let (d, t, count) = (acc.dimensions(), acc.data_type(), acc.count());
    let n = components(d);
    let mut out = Vec::new();
    match acc.view() {
        Some(view) => {
            let bytes = view_bytes(&view, buffers)?;
            read_dense(
                &here,
                bytes,
                acc.offset(),
                view.stride(),
                count,
                d,
                t,
                acc.normalized(),
                &mut out,
            )?;
        }
        None => {
            if count > MAX_VIEWLESS {
                return Err(GltfError::at(
                    format!("{here}/count"),
                    format!("{count} elements without a buffer view (at most {MAX_VIEWLESS})"),
                ));
            }
            out.resize(count * n, 0.0);
        }
    }
    if let Some(sparse) = acc.sparse() {
        let sp = format!("{here}/sparse");
        let k = sparse.count();
        if k > count {
            return Err(GltfError::at(
                format!("{sp}/count"),
                format!("{k} sparse values for {count} elements"),
            ));
        }
        let idx = sparse.indices();
        let it = match idx.index_type() {
            gltf::accessor::sparse::IndexType::U8 => DataType::U8,
            gltf::accessor::sparse::IndexType::U16 => DataType::U16,
            gltf::accessor::sparse::IndexType::U32 => DataType::U32,
        };
        let mut indices = Vec::new();
        read_dense(
            &format!("{sp}/indices"),
            view_bytes(&idx.view(), buffers)?,
            idx.offset(),
            None,
            k,
            Dimensions::Scalar,
            it,
            false,
            &mut indices,
        )?;
        let vals = sparse.values();
        let mut values = Vec::new();
        read_dense(
            &format!("{sp}/values"),
            view_bytes(&vals.view(), buffers)?,
            vals.offset(),
            None,
            k,
            d,
            t,
            acc.normalized(),
            &mut values,
        )?;
        for (j, &i) in indices.iter().enumerate() {
            let i = i as usize;
            if i >= count {
                return Err(GltfError::at(
                    format!("{sp}/indices"),
                    format!("sparse index {i} is not below the count {count}"),
                ));
            }
            out[i * n..(i + 1) * n].copy_from_slice(&values[j * n..(j + 1) * n]);
        }
    }
    Ok(out)
}

/// Reads an accessor of whole numbers (indices): u8, u16 or u32 scalars.
pub fn read_indices(acc: &Accessor, buffers: &Buffers) -> Result<Vec<u32>> {
    let here = pointer(&[&"accessors", &acc.index()]);
    if acc.dimensions() != Dimensions::Scalar
        || !matches!(
            acc.data_type(),
            DataType::U8 | DataType::U16 | DataType::U32
        )
        || acc.normalized()
    {
        return Err(GltfError::at(
            here,
            "indices must be unsigned byte, short or int scalars",
        ));
    }
    // u32 → f32 loses precision above 2²⁴: read exactly instead.
    if acc.data_type() == DataType::U32 && acc.sparse().is_none() {
        let view = acc
            .view()
            .ok_or_else(|| GltfError::at(&here, "indices without a buffer view"))?;
        let bytes = view_bytes(&view, buffers)?;
        let count = acc.count();
        let stride = view.stride().unwrap_or(4).max(4);
        let end = count
            .checked_sub(1)
            .map_or(Some(0), |c| c.checked_mul(stride)?.checked_add(4))
            .and_then(|n| n.checked_add(acc.offset()));
        if !matches!(end, Some(e) if e <= bytes.len()) {
            return Err(GltfError::at(
                here,
                format!("{count} indices run past the end of the buffer view"),
            ));
        }
        return Ok((0..count)
            .map(|i| {
                let at = acc.offset() + i * stride;
                u32::from_le_bytes([bytes[at], bytes[at + 1], bytes[at + 2], bytes[at + 3]])
            })
            .collect());
    }
    Ok(read_f32(acc, buffers)?
        .into_iter()
        .map(|v| v as u32)
        .collect())
}

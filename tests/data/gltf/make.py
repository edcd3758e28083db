#!/usr/bin/env python3
"""Writes the hand-made glTF test files in this folder (run: python3 make.py).

Every number is chosen by hand so the tests can check values exactly:
see tests/format_gltf.rs for what each file exercises.
"""
import base64, json, struct, os

HERE = os.path.dirname(os.path.abspath(__file__))


class Buf:
    def __init__(self):
        self.data = bytearray()
        self.views = []
        self.accessors = []

    def add(self, fmt, values, comp, typ, count, normalized=False, target=None, minmax=None):
        while len(self.data) % 4:
            self.data.append(0)
        raw = struct.pack("<" + fmt * len(values), *values)
        view = {"buffer": 0, "byteOffset": len(self.data), "byteLength": len(raw)}
        if target:
            view["target"] = target
        self.data += raw
        self.views.append(view)
        acc = {"bufferView": len(self.views) - 1, "componentType": comp, "count": count, "type": typ}
        if normalized:
            acc["normalized"] = True
        if minmax:
            acc["min"], acc["max"] = minmax
        self.accessors.append(acc)
        return len(self.accessors) - 1

    def f32(self, values, typ, n, **kw):
        return self.add("f", values, 5126, typ, len(values) // n, **kw)

    def images(self, imgs):
        """Appends encoded images, each in a buffer view; their view indices."""
        views = []
        for img in imgs:
            while len(self.data) % 4:
                self.data.append(0)
            self.views.append({"buffer": 0, "byteOffset": len(self.data), "byteLength": len(img)})
            views.append(len(self.views) - 1)
            self.data += img
        return views

    def uri(self):
        return "data:application/octet-stream;base64," + base64.b64encode(bytes(self.data)).decode()


def bounds(flat, n):
    cols = [flat[i::n] for i in range(n)]
    return [min(c) for c in cols], [max(c) for c in cols]


def write(name, doc, buf=None):
    if buf is not None:
        doc["buffers"] = [{"byteLength": len(buf.data), "uri": buf.uri()}]
        doc["bufferViews"] = buf.views
        doc["accessors"] = buf.accessors
    with open(os.path.join(HERE, name), "w") as f:
        json.dump(doc, f, indent=1)


def glb(name, doc, buf):
    doc["buffers"] = [{"byteLength": len(buf.data)}]
    doc["bufferViews"] = buf.views
    doc["accessors"] = buf.accessors
    js = json.dumps(doc).encode()
    js += b" " * (-len(js) % 4)
    bin_ = bytes(buf.data) + b"\0" * (-len(buf.data) % 4)
    total = 12 + 8 + len(js) + 8 + len(bin_)
    out = struct.pack("<4sII", b"glTF", 2, total)
    out += struct.pack("<I4s", len(js), b"JSON") + js
    out += struct.pack("<I4s", len(bin_), b"BIN\0") + bin_
    with open(os.path.join(HERE, name), "wb") as f:
        f.write(out)


def animated():
    """A box-ish quad 'Box' with two clips, a camera and a point light."""
    b = Buf()
    pos = [-1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0]
    p = b.f32(pos, "VEC3", 3, target=34962, minmax=bounds(pos, 3))
    nrm = b.f32([0, 0, 1] * 4, "VEC3", 3, target=34962)
    idx = b.add("H", [0, 1, 2, 0, 2, 3], 5123, "SCALAR", 6, target=34963)
    # Walk: translation LINEAR 0 s (0,0,0) → 1 s (2,0,0) → 2 s (2,4,0);
    #       rotation STEP 0 s identity, 1 s 90° about z.
    t_in = b.f32([0, 1, 2], "SCALAR", 1, minmax=([0], [2]))
    t_out = b.f32([0, 0, 0, 2, 0, 0, 2, 4, 0], "VEC3", 3)
    r_in = b.f32([0, 1], "SCALAR", 1, minmax=([0], [1]))
    h = 0.7071067811865476
    r_out = b.f32([0, 0, 0, 1, 0, 0, h, h], "VEC4", 4)
    # Spin: scale CUBICSPLINE 0 s → 2 s, value 1 → 3, tangents (in, out)
    # per second; rotation LINEAR 0 → 180° about y in two 90° steps.
    s_in = b.f32([0, 2], "SCALAR", 1, minmax=([0], [2]))
    s_out = b.f32([0, 0, 0, 1, 1, 1, 2, 2, 2, 0, 0, 0, 3, 3, 3, 0, 0, 0], "VEC3", 3)
    y_in = b.f32([0, 1, 2], "SCALAR", 1, minmax=([0], [2]))
    y_out = b.f32([0, 0, 0, 1, 0, h, 0, h, 0, 1, 0, 0], "VEC4", 4)
    doc = {
        "asset": {"version": "2.0", "generator": "tests/data/gltf/make.py"},
        "extensionsUsed": ["KHR_lights_punctual"],
        "extensions": {"KHR_lights_punctual": {"lights": [
            {"type": "point", "color": [1, 0.5, 0.5], "intensity": 100, "range": 20}]}},
        "scene": 0,
        "scenes": [{"nodes": [0, 1, 2]}, {"nodes": [3]}],
        "nodes": [
            {"name": "Box", "mesh": 0, "translation": [0, 0, 0]},
            {"name": "Cam", "camera": 0, "translation": [0, 0, 10]},
            {"name": "Lamp", "translation": [3, 3, 3],
             "extensions": {"KHR_lights_punctual": {"light": 0}}},
            {"name": "Other", "mesh": 0},
        ],
        "cameras": [{"name": "Front", "type": "perspective",
                     "perspective": {"yfov": 0.8, "znear": 0.5, "zfar": 100}}],
        "materials": [{"name": "Red", "pbrMetallicRoughness": {
            "baseColorFactor": [0.5, 0, 0, 1], "metallicFactor": 0, "roughnessFactor": 0.5}}],
        "meshes": [{"name": "Quad", "primitives": [
            {"attributes": {"POSITION": p, "NORMAL": nrm}, "indices": idx, "material": 0}]}],
        "animations": [
            {"name": "Walk", "samplers": [
                {"input": t_in, "output": t_out, "interpolation": "LINEAR"},
                {"input": r_in, "output": r_out, "interpolation": "STEP"}],
             "channels": [
                {"sampler": 0, "target": {"node": 0, "path": "translation"}},
                {"sampler": 1, "target": {"node": 0, "path": "rotation"}}]},
            {"name": "Spin", "samplers": [
                {"input": s_in, "output": s_out, "interpolation": "CUBICSPLINE"},
                {"input": y_in, "output": y_out, "interpolation": "LINEAR"}],
             "channels": [
                {"sampler": 0, "target": {"node": 0, "path": "scale"}},
                {"sampler": 1, "target": {"node": 0, "path": "rotation"}}]},
        ],
    }
    write("animated.gltf", json.loads(json.dumps(doc)), b)
    glb("animated.glb", doc, b)


def topologies():
    """Strips, fans, lines, loops, points; u8-normalised colours; no normals
    (flat normals are computed); a sparse accessor; a matrix node."""
    b = Buf()
    pos = [0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0]
    p = b.f32(pos, "VEC3", 3, target=34962, minmax=bounds(pos, 3))
    col = b.add("B", [255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 255, 255, 255, 255],
                5121, "VEC4", 4, normalized=True, target=34962)
    # Sparse: base all zero (no view), vertex 2 replaced by (0, 2, 0).
    sp_idx = len(b.views)
    b.data += b"\0" * (-len(b.data) % 4)
    b.views.append({"buffer": 0, "byteOffset": len(b.data), "byteLength": 1})
    b.data += bytes([2])
    b.data += b"\0" * (-len(b.data) % 4)
    b.views.append({"buffer": 0, "byteOffset": len(b.data), "byteLength": 12})
    b.data += struct.pack("<3f", 0, 2, 0)
    b.accessors.append({"componentType": 5126, "count": 4, "type": "VEC3", "min": [0, 0, 0], "max": [0, 2, 0],
                        "sparse": {"count": 1, "indices": {"bufferView": sp_idx, "componentType": 5121},
                                   "values": {"bufferView": sp_idx + 1}}})
    sparse = len(b.accessors) - 1
    prims = [{"attributes": {"POSITION": p, "COLOR_0": col}, "mode": m} for m in (0, 1, 2, 3, 5, 6)]
    prims.append({"attributes": {"POSITION": sparse}, "mode": 0})
    doc = {
        "asset": {"version": "2.0"},
        "scenes": [{"nodes": [0]}],
        "nodes": [{"name": "Shapes", "mesh": 0,
                   "matrix": [2, 0, 0, 0, 0, 2, 0, 0, 0, 0, 2, 0, 1, 2, 3, 1]}],
        "meshes": [{"primitives": prims}],
    }
    write("topologies.gltf", doc, b)


def bad_files():
    write("requires_meshopt.gltf", {
        "asset": {"version": "2.0"},
        "extensionsUsed": ["EXT_meshopt_compression"],
        "extensionsRequired": ["EXT_meshopt_compression"],
    })
    b = Buf()
    p = b.f32([0, 0, 0, 1, 0, 0, 0, 1, 0], "VEC3", 3, minmax=([0, 0, 0], [1, 1, 0]))
    b.accessors[p]["count"] = 30  # runs past the end of its view
    write("accessor_overrun.gltf", {
        "asset": {"version": "2.0"},
        "scenes": [{"nodes": [0]}],
        "nodes": [{"mesh": 0}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": p}}]}],
    }, b)



def png(w, h, rows, alpha):
    """A tiny PNG (8-bit RGB or RGBA), rows top first: for the texture tests."""
    import zlib
    raw = b"".join(b"\x00" + bytes(c for px in row for c in px) for row in rows)
    def chunk(t, d):
        return struct.pack(">I", len(d)) + t + d + struct.pack(">I", zlib.crc32(t + d) & 0xFFFFFFFF)
    ihdr = struct.pack(">IIBBBBB", w, h, 8, 6 if alpha else 2, 0, 0, 0)
    return b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", ihdr) + chunk(b"IDAT", zlib.compress(raw)) + chunk(b"IEND", b"")


def textured():
    """Two quads: left, a 2x2 RGB PNG in a buffer view (top-left red,
    top-right green, bottom-left blue, bottom-right white), REPEAT; right,
    tex_2x2.png beside the file (RGBA, left column half transparent),
    CLAMP_TO_EDGE, alphaMode BLEND, KHR_texture_transform taking the right
    half of the image (offset [0.5, 0], scale [0.5, 1])."""
    b = Buf()
    pos, uv = [], []
    for x0 in (-2.2, 0.2):
        pos += [x0, -1, 0, x0 + 2, -1, 0, x0 + 2, 1, 0, x0, 1, 0]
        # glTF uv: origin at the image's top-left, v down.
        uv += [0, 1, 1, 1, 1, 0, 0, 0]
    p = b.f32(pos, "VEC3", 3, target=34962, minmax=bounds(pos, 3))
    t = b.f32(uv, "VEC2", 2, target=34962)
    ia = b.add("H", [0, 1, 2, 0, 2, 3], 5123, "SCALAR", 6, target=34963)
    ib = b.add("H", [4, 5, 6, 4, 6, 7], 5123, "SCALAR", 6, target=34963)
    img = png(2, 2, [[(255, 0, 0), (0, 255, 0)], [(0, 0, 255), (255, 255, 255)]], False)
    while len(b.data) % 4:
        b.data.append(0)
    b.views.append({"buffer": 0, "byteOffset": len(b.data), "byteLength": len(img)})
    b.data += img
    with open(os.path.join(HERE, "tex_2x2.png"), "wb") as f:
        f.write(png(2, 2, [[(255, 255, 0, 128), (0, 255, 255, 255)], [(255, 0, 255, 128), (20, 20, 20, 255)]], True))
    doc = {
        "asset": {"version": "2.0", "generator": "make.py"},
        "extensionsUsed": ["KHR_texture_transform"],
        "scene": 0,
        "scenes": [{"nodes": [0, 1]}],
        "nodes": [{"name": "Left", "mesh": 0}, {"name": "Right", "mesh": 1}],
        "meshes": [
            {"primitives": [{"attributes": {"POSITION": p, "TEXCOORD_0": t}, "indices": ia, "material": 0}]},
            {"primitives": [{"attributes": {"POSITION": p, "TEXCOORD_0": t}, "indices": ib, "material": 1}]},
        ],
        "materials": [
            {"name": "Buffered", "pbrMetallicRoughness": {"baseColorTexture": {"index": 0}, "metallicFactor": 0}},
            {"name": "Beside", "alphaMode": "BLEND", "pbrMetallicRoughness": {
                "baseColorTexture": {"index": 1, "extensions": {"KHR_texture_transform": {"offset": [0.5, 0], "scale": [0.5, 1]}}},
                "metallicFactor": 0}},
        ],
        "samplers": [{"wrapS": 10497, "wrapT": 10497}, {"wrapS": 33071, "wrapT": 33071, "magFilter": 9729}],
        "textures": [{"source": 0, "sampler": 0}, {"source": 1, "sampler": 1}],
        "images": [
            {"bufferView": len(b.views) - 1, "mimeType": "image/png", "name": "buffered"},
            {"uri": "tex_2x2.png"},
        ],
    }
    write("textured.gltf", doc, b)

def sampler_modes():
    """Two quads showing glTF sampler modes (read in tests/render_textures.rs):
    left, a 4x4 RGB texture (each texel its own colour) with magFilter and
    minFilter NEAREST and wrapS MIRRORED_REPEAT, u running 0..2 so the right
    half is the mirror image of the left, hard texel edges; right, a 4x4
    RGBA texture whose alpha is 255 on a plus shape and 0 elsewhere,
    alphaMode MASK (alphaCutoff 0.5), NEAREST: a hard-edged opaque plus."""
    b = Buf()
    pos = [-2.2, -1, 0, -0.2, -1, 0, -0.2, 1, 0, -2.2, 1, 0,
           0.2, -1, 0, 2.2, -1, 0, 2.2, 1, 0, 0.2, 1, 0]
    uv = [0, 1, 2, 1, 2, 0, 0, 0,
          0, 1, 1, 1, 1, 0, 0, 0]
    p = b.f32(pos, "VEC3", 3, target=34962, minmax=bounds(pos, 3))
    t = b.f32(uv, "VEC2", 2, target=34962)
    ia = b.add("H", [0, 1, 2, 0, 2, 3], 5123, "SCALAR", 6, target=34963)
    ib = b.add("H", [4, 5, 6, 4, 6, 7], 5123, "SCALAR", 6, target=34963)
    rgb = [[(60 * x + 20, 60 * y + 20, 200 - 50 * x) for x in range(4)] for y in range(4)]
    plus = [[(230, 200, 40, 255 if x in (1, 2) or y in (1, 2) else 0) for x in range(4)] for y in range(4)]
    imgs = [png(4, 4, rgb, False), png(4, 4, plus, True)]
    views = b.images(imgs)
    doc = {
        "asset": {"version": "2.0", "generator": "make.py"},
        "scene": 0,
        "scenes": [{"nodes": [0, 1]}],
        "nodes": [{"name": "Mirrored", "mesh": 0}, {"name": "Masked", "mesh": 1}],
        "meshes": [
            {"primitives": [{"attributes": {"POSITION": p, "TEXCOORD_0": t}, "indices": ia, "material": 0}]},
            {"primitives": [{"attributes": {"POSITION": p, "TEXCOORD_0": t}, "indices": ib, "material": 1}]},
        ],
        "materials": [
            {"name": "Nearest", "pbrMetallicRoughness": {"baseColorTexture": {"index": 0}, "metallicFactor": 0}},
            {"name": "Plus", "alphaMode": "MASK", "alphaCutoff": 0.5, "doubleSided": True,
             "pbrMetallicRoughness": {"baseColorTexture": {"index": 1}, "metallicFactor": 0}},
        ],
        "samplers": [
            {"wrapS": 33648, "wrapT": 33071, "magFilter": 9728, "minFilter": 9728},
            {"wrapS": 33071, "wrapT": 33071, "magFilter": 9728, "minFilter": 9984},
        ],
        "textures": [{"source": 0, "sampler": 0}, {"source": 1, "sampler": 1}],
        "images": [
            {"bufferView": views[0], "mimeType": "image/png", "name": "colours"},
            {"bufferView": views[1], "mimeType": "image/png", "name": "plus"},
        ],
    }
    write("sampler_modes.gltf", doc, b)


def emissive():
    """Three quads in a dim scene (one directional light of 1 lux, facing
    the quads) for emissive maps (tests/render_textures.rs and
    tests/format_gltf.rs):
    left, a dark grey lit material (base 0.05) with emissiveTexture = a 4x4
    RGB checker of glowing texels (255, 200 - 40y, 40 + 60x) and black
    ones, NEAREST, emissiveFactor [1, 1, 1];
    middle, a 2x2 grey checker baseColorTexture lit by the light, plus the
    same emissive texture repeated twice across the quad
    (KHR_texture_transform scale [2, 2]) with emissiveFactor [0.2, 0.6, 1];
    right, KHR_materials_unlit with the glowing checker as its base colour
    texture and baseColorFactor [1, 0.5, 0.5, 1]."""
    b = Buf()
    pos, uv = [], []
    for x0 in (-3.3, -1.0, 1.3):
        pos += [x0, -1, 0, x0 + 2, -1, 0, x0 + 2, 1, 0, x0, 1, 0]
        uv += [0, 1, 1, 1, 1, 0, 0, 0]
    n = [0, 0, 1] * 12
    p = b.f32(pos, "VEC3", 3, target=34962, minmax=bounds(pos, 3))
    nn = b.f32(n, "VEC3", 3, target=34962)
    t = b.f32(uv, "VEC2", 2, target=34962)
    idx = [b.add("H", [k, k + 1, k + 2, k, k + 2, k + 3], 5123, "SCALAR", 6, target=34963) for k in (0, 4, 8)]
    glow = [[(255, 200 - 40 * y, 40 + 60 * x) if (x + y) % 2 == 0 else (0, 0, 0) for x in range(4)] for y in range(4)]
    grey = [[(200, 200, 200), (90, 90, 90)], [(90, 90, 90), (200, 200, 200)]]
    imgs = [png(4, 4, glow, False), png(2, 2, grey, False)]
    views = b.images(imgs)
    prim = lambda k, m: {"attributes": {"POSITION": p, "NORMAL": nn, "TEXCOORD_0": t}, "indices": idx[k], "material": m}
    doc = {
        "asset": {"version": "2.0", "generator": "make.py"},
        "extensionsUsed": ["KHR_texture_transform", "KHR_materials_unlit", "KHR_lights_punctual"],
        "extensions": {"KHR_lights_punctual": {"lights": [{"type": "directional", "intensity": 1.0}]}},
        "scene": 0,
        "scenes": [{"nodes": [0, 1, 2, 3]}],
        "nodes": [
            {"name": "Glow", "mesh": 0},
            {"name": "Lit", "mesh": 1},
            {"name": "Unlit", "mesh": 2},
            {"name": "Sun", "extensions": {"KHR_lights_punctual": {"light": 0}}},
        ],
        "meshes": [{"primitives": [prim(k, k)]} for k in range(3)],
        "materials": [
            {"name": "GlowMap", "emissiveTexture": {"index": 0}, "emissiveFactor": [1, 1, 1],
             "pbrMetallicRoughness": {"baseColorFactor": [0.05, 0.05, 0.05, 1], "metallicFactor": 0}},
            {"name": "LitAndGlow", "emissiveFactor": [0.2, 0.6, 1],
             "emissiveTexture": {"index": 0, "extensions": {"KHR_texture_transform": {"scale": [2, 2]}}},
             "pbrMetallicRoughness": {"baseColorTexture": {"index": 1}, "metallicFactor": 0}},
            {"name": "UnlitMap", "extensions": {"KHR_materials_unlit": {}},
             "pbrMetallicRoughness": {"baseColorTexture": {"index": 0}, "baseColorFactor": [1, 0.5, 0.5, 1]}},
        ],
        "samplers": [{"wrapS": 10497, "wrapT": 10497, "magFilter": 9728, "minFilter": 9728}],
        "textures": [{"source": 0, "sampler": 0}, {"source": 1, "sampler": 0}],
        "images": [
            {"bufferView": views[0], "mimeType": "image/png", "name": "glow"},
            {"bufferView": views[1], "mimeType": "image/png", "name": "grey"},
        ],
    }
    write("emissive.gltf", doc, b)


if __name__ == "__main__":
    emissive()
    sampler_modes()
    textured()
    animated()
    topologies()
    bad_files()

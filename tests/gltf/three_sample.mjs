// Samples what three.js plays: loads a .gltf/.glb with GLTFLoader under
// node, plays one clip with AnimationMixer at the given times and prints
// every glTF node's local translation, rotation (x y z w) and scale as
// JSON: [{"time": t, "nodes": {"INDEX": {"name": "glTF name", "t": [...],
// "r": [...], "s": [...]}}}] (three.js renames nodes; the glTF name is
// taken from the file's JSON through the parser's associations).
// Usage: node three_sample.mjs FILE CLIP_INDEX T1,T2,...
import { createRequire } from 'module';
import fs from 'fs';
import path from 'path';
import { pathToFileURL } from 'url';
const npm = process.env.NPM_DIR || '.';
const three = await import(pathToFileURL(path.join(npm, 'node_modules/three/build/three.module.js')));
const { GLTFLoader } = await import(pathToFileURL(path.join(npm, 'node_modules/three/examples/jsm/loaders/GLTFLoader.js')));

// FileLoader reports progress with a DOM event node does not have.
globalThis.ProgressEvent ??= class extends Event {
  constructor(type, init = {}) { super(type); Object.assign(this, init); }
};
// External files through a small fetch shim for file: URLs.
const realFetch = globalThis.fetch;
globalThis.fetch = async (url, opts) => {
  const u = typeof url === 'string' ? url : (url.url ?? String(url));
  if (u.startsWith('file://')) {
    const data = fs.readFileSync(new URL(u));
    return new Response(data);
  }
  return realFetch(url, opts);
};

const [file, clipArg, timesArg] = process.argv.slice(2);
const bytes = fs.readFileSync(file);
const loader = new GLTFLoader();
const dir = pathToFileURL(path.dirname(path.resolve(file)) + '/').href;
const gltf = await new Promise((resolve, reject) =>
  loader.parse(bytes.buffer.slice(bytes.byteOffset, bytes.byteOffset + bytes.byteLength), dir, resolve, reject));
const scene = gltf.scene;
const mixer = new three.AnimationMixer(scene);
const clip = gltf.animations[Number(clipArg || 0)];
if (clip) mixer.clipAction(clip).play();
const out = [];
for (const t of (timesArg || '0').split(',').map(Number)) {
  mixer.setTime(t);
  scene.updateMatrixWorld(true);
  const nodes = {};
  scene.traverse((o) => {
    const assoc = gltf.parser.associations.get(o);
    if (!assoc || assoc.nodes === undefined || o === scene) return;
    const name = gltf.parser.json.nodes[assoc.nodes].name || '';
    if (!name) return;
    nodes[assoc.nodes] = {
      name,
      t: o.position.toArray(),
      r: o.quaternion.toArray(),
      s: o.scale.toArray(),
    };
  });
  out.push({ time: t, nodes });
}
console.log(JSON.stringify(out));

// Samples what three.js plays: loads a .gltf/.glb with GLTFLoader under
// node, plays one clip with AnimationMixer at the given times and prints
// every glTF node's local translation, rotation (x y z w) and scale as
// JSON: [{"time": t, "nodes": {"INDEX": {"name": "glTF name", "t": [...],
// "r": [...], "s": [...]}}}] (three.js renames nodes; the glTF name is
// taken from the file's JSON through the parser's associations).
// Usage: node three_sample.mjs FILE CLIP_INDEX T1,T2,...
import { loadPlaying } from './three_load.mjs';

const [file, clipArg, timesArg] = process.argv.slice(2);
const { gltf, scene, mixer } = await loadPlaying(file, clipArg);
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

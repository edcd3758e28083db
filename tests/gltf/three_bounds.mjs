// Deformed mesh bounds as three.js plays them: loads a .gltf/.glb with
// GLTFLoader under node, plays one clip with AnimationMixer and prints, per
// time, every mesh's world-space axis-aligned bounds after morph targets and
// skinning (Mesh.getVertexPosition applies both), in the form
// `animed sample --bounds --json` prints:
// [{"time": t, "meshes": [{"name": "...", "min": [x,y,z], "max": [x,y,z]}]}]
// A mesh is named by its nearest ancestor glTF node with a name.
// Usage: NPM_DIR=... node three_bounds.mjs FILE CLIP_INDEX T1,T2,...
import { three, loadPlaying } from './three_load.mjs';

const [file, clipArg, timesArg] = process.argv.slice(2);
const { gltf, scene, mixer } = await loadPlaying(file, clipArg);

function nameOf(o) {
  for (let p = o; p && p !== scene; p = p.parent) {
    const a = gltf.parser.associations.get(p);
    if (a && a.nodes !== undefined) {
      const n = gltf.parser.json.nodes[a.nodes].name || '';
      if (n) return n;
    }
  }
  return '';
}

const out = [];
const v = new three.Vector3();
for (const t of (timesArg || '0').split(',').map(Number)) {
  mixer.setTime(t);
  scene.updateMatrixWorld(true);
  const meshes = [];
  scene.traverse((o) => {
    if (!o.isMesh || !o.visible) return;
    const pos = o.geometry.attributes.position;
    const min = [Infinity, Infinity, Infinity], max = [-Infinity, -Infinity, -Infinity];
    for (let i = 0; i < pos.count; i++) {
      o.getVertexPosition(i, v);
      v.applyMatrix4(o.matrixWorld);
      const a = v.toArray();
      for (let k = 0; k < 3; k++) { min[k] = Math.min(min[k], a[k]); max[k] = Math.max(max[k], a[k]); }
    }
    meshes.push({ name: nameOf(o), min, max });
  });
  out.push({ time: t, meshes });
}
console.log(JSON.stringify(out));

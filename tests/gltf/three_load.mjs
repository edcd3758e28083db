// What three_sample.mjs and three_bounds.mjs share: three.js and its
// GLTFLoader from NPM_DIR, the two shims node needs (ProgressEvent, fetch of
// file: URLs for external buffers and images), and one clip playing on the
// loaded scene.
// Usage: const { three, gltf, scene, mixer } = await loadPlaying(FILE, CLIP_INDEX);
import fs from 'fs';
import path from 'path';
import { pathToFileURL } from 'url';

const npm = process.env.NPM_DIR || '.';
export const three = await import(pathToFileURL(path.join(npm, 'node_modules/three/build/three.module.js')));
const { GLTFLoader } = await import(pathToFileURL(path.join(npm, 'node_modules/three/examples/jsm/loaders/GLTFLoader.js')));

// FileLoader reports progress with a DOM event node does not have.
globalThis.ProgressEvent ??= class extends Event {
  constructor(type, init = {}) { super(type); Object.assign(this, init); }
};
// External files through a small fetch shim for file: URLs.
const realFetch = globalThis.fetch;
globalThis.fetch = async (url, opts) => {
  const u = typeof url === 'string' ? url : (url.url ?? String(url));
  if (u.startsWith('file://')) return new Response(fs.readFileSync(new URL(u)));
  return realFetch(url, opts);
};

/// Loads FILE (.gltf/.glb) and plays clip CLIP_INDEX (if the file has it).
export async function loadPlaying(file, clipArg) {
  const bytes = fs.readFileSync(file);
  const loader = new GLTFLoader();
  const dir = pathToFileURL(path.dirname(path.resolve(file)) + '/').href;
  const gltf = await new Promise((resolve, reject) =>
    loader.parse(bytes.buffer.slice(bytes.byteOffset, bytes.byteOffset + bytes.byteLength), dir, resolve, reject));
  const scene = gltf.scene;
  const mixer = new three.AnimationMixer(scene);
  const clip = gltf.animations[Number(clipArg || 0)];
  if (clip) mixer.clipAction(clip).play();
  return { gltf, scene, mixer };
}

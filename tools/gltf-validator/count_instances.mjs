// Loads a glTF/GLB file with three.js's GLTFLoader (as a web viewer would) and prints, as
// one JSON line, how many trees it placed: the instances of its InstancedMeshes (EXT_mesh_
// gpu_instancing; a mesh of several primitives is a Group of InstancedMeshes sharing the
// instances, counted once), the plain meshes, and the instances' ids (_ID).
// Usage: node tools/gltf-validator/count_instances.mjs FILE
import { readFile } from 'node:fs/promises';
import { GLTFLoader } from 'three/examples/jsm/loaders/GLTFLoader.js';

const file = process.argv[2];
const bytes = await readFile(file);
const loader = new GLTFLoader();
// Node has no image decoder: textures are left out; geometry and instancing are what count.
loader.register((parser) => {
  parser.loadTexture = async () => null;
  return { name: 'ecoforest_no_textures' };
});
const gltf = await loader.parseAsync(
  bytes.buffer.slice(bytes.byteOffset, bytes.byteOffset + bytes.byteLength), '');
let instances = 0, meshes = 0;
const ids = [];
const counted = new Set();  // the nodes whose instances were counted
gltf.scene.traverse((object) => {
  if (object.isInstancedMesh) {
    const node = object.parent.isGroup && object.parent !== gltf.scene ? object.parent : object;
    if (counted.has(node)) return;
    counted.add(node);
    instances += object.count;
    const id = object.geometry.getAttribute('_ID');
    if (id) for (let i = 0; i < id.count; ++i) ids.push(id.getX(i));
  } else if (object.isMesh) {
    meshes += 1;
  }
});
console.log(JSON.stringify({ instances, meshes, ids }));

// view.mjs - the structure in three.js: the .glb phyllo-export --gltf
// wrote, parsed in memory by GLTFLoader (an InstancedMesh an organ
// object and material), turned with OrbitControls, drawn on demand.
import * as THREE from 'three';
import { GLTFLoader } from 'three/addons/loaders/GLTFLoader.js';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';

export const BACKGROUND = 0xc6d3dc;

export class View {
  constructor(parent) {
    this.parent = parent;
    this.renderer = new THREE.WebGLRenderer({ antialias: true,
      preserveDrawingBuffer: true });
    this.renderer.setPixelRatio(window.devicePixelRatio);
    // No status read back after each shader: a wait for the GPU.
    this.renderer.debug.checkShaderErrors = false;
    parent.appendChild(this.renderer.domElement);
    this.scene = new THREE.Scene();
    this.scene.background = new THREE.Color(BACKGROUND);
    this.scene.add(new THREE.HemisphereLight(0xffffff, 0x554433, 1.6));
    const sun = new THREE.DirectionalLight(0xffffff, 2.2);
    sun.position.set(-2, 4, -1);
    this.scene.add(sun);
    this.camera = new THREE.PerspectiveCamera(42, 1, 0.001, 1000);
    this.controls = new OrbitControls(this.camera, this.renderer.domElement);
    this.controls.addEventListener('change', () => this.render());
    this.loader = new GLTFLoader();
    this.shown = null;
    this.instances = 0;
    new ResizeObserver(() => this.resize()).observe(parent);
    this.resize();
  }

  resize() {
    const w = Math.max(1, this.parent.clientWidth);
    const h = Math.max(1, this.parent.clientHeight);
    this.renderer.setSize(w, h);
    this.camera.aspect = w / h;
    this.camera.updateProjectionMatrix();
    this.render();
  }

  render() {
    this.renderer.render(this.scene, this.camera);
  }

  // Look at the structure from in front and above (our Z up is glTF's
  // Y), as the README's pictures do.
  frame(object) {
    const box = new THREE.Box3().setFromObject(object);
    if (box.isEmpty())
      return;
    const sphere = box.getBoundingSphere(new THREE.Sphere());
    const r = Math.max(sphere.radius, 1e-6);
    const dir = new THREE.Vector3(0, 4, 3.5).normalize();
    this.camera.near = r / 100;
    this.camera.far = r * 100;
    this.camera.position.copy(sphere.center).addScaledVector(dir,
      r / Math.sin(THREE.MathUtils.degToRad(21)) * 0.85);
    this.controls.target.copy(sphere.center);
    this.camera.updateProjectionMatrix();
    this.controls.update();
  }

  /*
   * Show the .glb in bytes (a Uint8Array) in place of what was shown;
   * reframe: look at it afresh (a new scene), else keep the view.
   * Resolves once drawn.
   */
  async show(bytes, reframe) {
    const buffer = bytes.byteOffset === 0 &&
      bytes.byteLength === bytes.buffer.byteLength ? bytes.buffer :
      bytes.slice().buffer;
    const gltf = await this.loader.parseAsync(buffer, '');
    this.clear();
    this.shown = gltf.scene;
    this.scene.add(this.shown);
    this.instances = countInstances(this.shown);
    if (reframe)
      this.frame(this.shown);
    this.render();
  }

  clear() {
    if (this.shown === null)
      return;
    this.scene.remove(this.shown);
    this.shown.traverse(o => {
      if (o.geometry)
        o.geometry.dispose();
      if (o.material)
        [].concat(o.material).forEach(m => m.dispose());
      if (o.isInstancedMesh)
        o.dispose();
    });
    this.shown = null;
    this.instances = 0;
  }
}

/*
 * The organs drawn: each organ object's instance count once, though
 * GLTFLoader makes a mesh of several materials a Group of InstancedMeshes,
 * one a material (a mesh of one is its InstancedMesh, under the
 * structure's node, an Object3D).
 */
export function countInstances(root) {
  const counted = new Set();
  let n = 0;
  root.traverse(o => {
    if (!o.isInstancedMesh)
      return;
    const object = o.parent !== root && o.parent.isGroup ? o.parent : o;
    if (counted.has(object))
      return;
    counted.add(object);
    n += o.count;
  });
  return n;
}

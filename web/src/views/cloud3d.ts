// PointCloud2 in 3D with three.js: one preallocated BufferGeometry that grows only when a
// bigger cloud arrives, colour by intensity or height, an orbit camera. A new cloud only
// replaces the buffers' contents; rendering happens on the next animation frame, once,
// however many clouds arrived in between (the subscription is latest-only anyway).

import * as THREE from "three";
import { OrbitControls } from "three/examples/jsm/controls/OrbitControls.js";
import { type Cloud, stampMs, unpackCloud } from "../messages";
import { probe } from "../probe";

export type ColourBy = "height" | "intensity";

/** Blue (low) to red (high), precomputed: a table lookup per point, not a colour conversion. */
const RAMP_STEPS = 256;
const RAMP = (() => {
  const t = new Float32Array(RAMP_STEPS * 3);
  const c = new THREE.Color();
  for (let i = 0; i < RAMP_STEPS; i++) {
    c.setHSL(0.66 * (1 - i / (RAMP_STEPS - 1)), 0.9, 0.55);
    t.set([c.r, c.g, c.b], i * 3);
  }
  return t;
})();

export class CloudView {
  private renderer: THREE.WebGLRenderer;
  private scene = new THREE.Scene();
  private camera: THREE.PerspectiveCamera;
  private controls: OrbitControls;
  private geometry = new THREE.BufferGeometry();
  private points: THREE.Points;
  private capacity = 0;
  private cloud: Cloud | undefined;
  private dirty = true;
  private raf = 0;
  private ro: ResizeObserver;
  colourBy: ColourBy = "height";
  /** Called after each render that showed a new cloud, with that cloud's header stamp (ms). */
  onShown: ((stampMs: number | null) => void) | null = null;
  private pending = false;
  private pendingStamp: number | null = null;
  lastCount = 0;

  constructor(private parent: HTMLElement) {
    this.renderer = new THREE.WebGLRenderer({ antialias: false, preserveDrawingBuffer: true });
    this.renderer.setPixelRatio(Math.min(window.devicePixelRatio || 1, 2));
    this.renderer.setClearColor(0x0b1016);
    parent.appendChild(this.renderer.domElement);
    this.camera = new THREE.PerspectiveCamera(60, 1, 0.05, 200);
    // ROS is z-up.
    this.camera.up.set(0, 0, 1);
    this.camera.position.set(-8, -8, 7);
    this.controls = new OrbitControls(this.camera, this.renderer.domElement);
    this.controls.addEventListener("change", () => (this.dirty = true));
    this.points = new THREE.Points(this.geometry, new THREE.PointsMaterial({ size: 0.06, vertexColors: true }));
    this.points.frustumCulled = false;
    this.scene.add(this.points);
    const grid = new THREE.GridHelper(20, 20, 0x3b4a5a, 0x1c2631);
    grid.rotation.x = Math.PI / 2;
    this.scene.add(grid, new THREE.AxesHelper(1));
    this.ro = new ResizeObserver(() => this.resize());
    this.ro.observe(parent);
    const loop = () => {
      if (this.dirty) this.render();
      this.raf = requestAnimationFrame(loop);
    };
    this.raf = requestAnimationFrame(loop);
  }

  private resize() {
    const w = this.parent.clientWidth, h = Math.max(200, this.parent.clientHeight - 4);
    this.renderer.setSize(w, h, true);
    this.camera.aspect = w / h;
    this.camera.updateProjectionMatrix();
    this.dirty = true;
  }

  /** Takes a decoded PointCloud2 message; returns the number of points. */
  show(msg: any): number {
    const t0 = performance.now();
    this.cloud = unpackCloud(msg, this.cloud);
    const n = this.cloud.count;
    if (n > this.capacity) {
      this.capacity = Math.max(n, Math.ceil(this.capacity * 1.5));
      this.geometry.setAttribute("position", new THREE.BufferAttribute(new Float32Array(this.capacity * 3), 3));
      this.geometry.setAttribute("color", new THREE.BufferAttribute(new Float32Array(this.capacity * 3), 3));
    }
    const pos = this.geometry.getAttribute("position") as THREE.BufferAttribute;
    const col = this.geometry.getAttribute("color") as THREE.BufferAttribute;
    (pos.array as Float32Array).set(this.cloud.positions.subarray(0, n * 3));
    this.colour(this.cloud, col.array as Float32Array, n);
    pos.needsUpdate = true;
    col.needsUpdate = true;
    this.geometry.setDrawRange(0, n);
    this.lastCount = n;
    this.pending = true;
    this.pendingStamp = stampMs(msg.header);
    probe.busyMs.cloudUnpack += performance.now() - t0;
    this.dirty = true;
    return n;
  }

  private colour(c: Cloud, out: Float32Array, n: number) {
    const byI = this.colourBy === "intensity" && n > 0 && !Number.isNaN(c.intensity[0]);
    let lo = Infinity, hi = -Infinity;
    for (let i = 0; i < n; i++) {
      const v = byI ? c.intensity[i] : c.positions[i * 3 + 2];
      if (v < lo) lo = v;
      if (v > hi) hi = v;
    }
    const k = (RAMP_STEPS - 1) / (hi > lo ? hi - lo : 1);
    for (let i = 0; i < n; i++) {
      const j = Math.round(((byI ? c.intensity[i] : c.positions[i * 3 + 2]) - lo) * k) * 3;
      out[i * 3] = RAMP[j];
      out[i * 3 + 1] = RAMP[j + 1];
      out[i * 3 + 2] = RAMP[j + 2];
    }
  }

  private render() {
    this.dirty = false;
    const t0 = performance.now();
    this.renderer.render(this.scene, this.camera);
    // WebGL is asynchronous: this counts the CPU side of the draw (buffer uploads).
    probe.busyMs.cloudRender += performance.now() - t0;
    if (this.pending && this.onShown) this.onShown(this.pendingStamp);
    this.pending = false;
  }

  destroy() {
    cancelAnimationFrame(this.raf);
    this.ro.disconnect();
    this.controls.dispose();
    this.geometry.dispose();
    (this.points.material as THREE.Material).dispose();
    this.renderer.dispose();
    this.renderer.domElement.remove();
  }
}

// The browser side of ncverify's HTML report (src/render/html_report.cpp writes the page):
// one interactive 3D view per direction of measurement, drawn with three.js from the mesh
// the page embeds. Bundled with three.js by esbuild at build time and inlined into every
// report, so the page needs nothing from the network (its Content-Security-Policy forbids it).
import {
  BufferAttribute,
  BufferGeometry,
  CanvasTexture,
  Color,
  DirectionalLight,
  HemisphereLight,
  Mesh,
  MeshLambertMaterial,
  PerspectiveCamera,
  Points,
  PointsMaterial,
  Raycaster,
  SRGBColorSpace,
  Scene,
  Vector2,
  Vector3,
  WebGLRenderer,
} from 'three';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';

// The report's state, for people debugging a page and for the end-to-end test.
const state = { ready: false, views: [] };
window.ncvReport = state;

function decodeBase64(text) {
  const binary = atob(text.trim());
  const bytes = new Uint8Array(binary.length);
  for (let i = 0; i < binary.length; ++i) bytes[i] = binary.charCodeAt(i);
  return bytes.buffer;
}

// The mesh section: positions (float32 x 3, relative to data.center), values (float32),
// regions (uint32), triangle corners (uint32 x 3), colours (uint8 x 3, sRGB).
function readMesh(data) {
  const buffer = decodeBase64(document.getElementById(data.meshId).textContent);
  const v = data.vertexCount;
  const f = data.triangleCount;
  let at = 0;
  const take = (Type, count) => {
    const array = new Type(buffer, at, count);
    at += count * Type.BYTES_PER_ELEMENT;
    return array;
  };
  const positions = take(Float32Array, 3 * v);
  const values = take(Float32Array, v);
  const regions = take(Uint32Array, v);
  const indices = take(Uint32Array, 3 * f);
  const colorBytes = take(Uint8Array, 3 * v);
  return { positions, values, regions, indices, colorBytes };
}

function linearColors(bytes) {
  const colors = new Float32Array(bytes.length);
  const c = new Color();
  for (let i = 0; i < bytes.length; i += 3) {
    c.setRGB(bytes[i] / 255, bytes[i + 1] / 255, bytes[i + 2] / 255, SRGBColorSpace);
    colors[i] = c.r;
    colors[i + 1] = c.g;
    colors[i + 2] = c.b;
  }
  return colors;
}

// A round marker with a dark rim, drawn once into a canvas.
function markerTexture() {
  const canvas = document.createElement('canvas');
  canvas.width = canvas.height = 64;
  const g = canvas.getContext('2d');
  g.beginPath();
  g.arc(32, 32, 26, 0, 2 * Math.PI);
  g.fillStyle = '#ffffff';
  g.fill();
  g.lineWidth = 8;
  g.strokeStyle = '#111111';
  g.stroke();
  const texture = new CanvasTexture(canvas);
  texture.colorSpace = SRGBColorSpace;
  return texture;
}

function markerPoints(points, color, size, texture) {
  const geometry = new BufferGeometry();
  geometry.setAttribute('position', new BufferAttribute(new Float32Array(points.flat()), 3));
  const material = new PointsMaterial({
    color: new Color(color),
    size,
    sizeAttenuation: false,
    map: texture,
    transparent: true,
    alphaTest: 0.5,
    depthTest: false,
  });
  const markers = new Points(geometry, material);
  markers.renderOrder = 10;
  return markers;
}

function formatLength(value, data) {
  if (!Number.isFinite(value)) return 'no sample';
  const scale = 10 ** data.decimals;
  if (Math.round(Math.abs(value) * scale) === 0) return '0';
  return value.toFixed(data.decimals);
}

function formatPoint(p, data) {
  return '(' + p.map((x) => formatLength(x, data)).join(', ') + ')';
}

class ErrorView {
  constructor(section, data) {
    this.section = section;
    this.data = data;
    this.holder = section.querySelector('.ncv-canvas');
    this.readout = section.querySelector('.ncv-readout');
    this.mesh = readMesh(data);
    this.center = new Vector3(...data.center);
    this.setUpScene();
    this.setUpMarkers();
    this.setUpInteraction();
    this.resize();
    this.home();
  }

  setUpScene() {
    this.renderer = new WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
    this.renderer.setPixelRatio(window.devicePixelRatio || 1);
    this.holder.appendChild(this.renderer.domElement);
    this.scene = new Scene();
    this.scene.background = new Color('#eef1f4');
    this.camera = new PerspectiveCamera(35, 1, 0.001, 1000);
    // Light from the sky and from the eye: every face the camera sees is lit, so the
    // colours keep their hue whichever way the part is turned.
    this.scene.add(new HemisphereLight(0xffffff, 0x9a9a9a, 1.7));
    this.headlight = new DirectionalLight(0xffffff, 1.4);
    this.camera.add(this.headlight);
    this.scene.add(this.camera);

    const geometry = new BufferGeometry();
    geometry.setAttribute('position', new BufferAttribute(this.mesh.positions, 3));
    geometry.setAttribute('color', new BufferAttribute(linearColors(this.mesh.colorBytes), 3));
    geometry.setIndex(new BufferAttribute(this.mesh.indices, 1));
    geometry.computeBoundingSphere();
    geometry.computeBoundingBox();
    const material = new MeshLambertMaterial({ vertexColors: true, flatShading: true, side: 2 });
    this.surface = new Mesh(geometry, material);
    this.scene.add(this.surface);
    this.radius = geometry.boundingSphere.radius || 1;
    this.camera.near = this.radius / 1000;
    this.camera.far = this.radius * 100;
    this.controls = new OrbitControls(this.camera, this.renderer.domElement);
    this.controls.enableDamping = false;
    this.controls.addEventListener('change', () => this.render());
  }

  local(p) {
    return [p[0] - this.center.x, p[1] - this.center.y, p[2] - this.center.z];
  }

  setUpMarkers() {
    const texture = markerTexture();
    const excess = this.data.regions.filter((r) => r.kind === 'excess');
    const gouge = this.data.regions.filter((r) => r.kind === 'gouge');
    for (const [list, color] of [[excess, '#ff2d00'], [gouge, '#1e5bff']]) {
      if (list.length) this.scene.add(markerPoints(list.map((r) => this.local(r.at)), color, 11, texture));
    }
    for (const worst of this.data.worst) {
      this.scene.add(markerPoints([this.local(worst.at)], '#ffe100', 18, texture));
    }
  }

  setUpInteraction() {
    this.raycaster = new Raycaster();
    this.pointer = new Vector2();
    const canvas = this.renderer.domElement;
    canvas.addEventListener('pointermove', (e) => this.pick(e));
    canvas.addEventListener('click', (e) => this.pick(e));
    window.addEventListener('resize', () => {
      this.resize();
      this.render();
    });
    this.section.querySelector('.ncv-home')?.addEventListener('click', () => this.home());
    for (const row of this.section.querySelectorAll('tr[data-region]')) {
      row.addEventListener('click', () => this.showRegion(Number(row.dataset.region), row));
      row.addEventListener('keydown', (e) => {
        if (e.key === 'Enter' || e.key === ' ') this.showRegion(Number(row.dataset.region), row);
      });
    }
    for (const button of this.section.querySelectorAll('button[data-worst]')) {
      button.addEventListener('click', () => this.showWorst(Number(button.dataset.worst)));
    }
  }

  resize() {
    const width = this.holder.clientWidth || 640;
    const height = this.holder.clientHeight || 480;
    this.renderer.setSize(width, height, false);
    this.renderer.domElement.style.width = width + 'px';
    this.renderer.domElement.style.height = height + 'px';
    this.camera.aspect = width / height;
    this.camera.updateProjectionMatrix();
  }

  render() {
    this.renderer.render(this.scene, this.camera);
  }

  // Looks at target from the current direction (or from the given one) at distance.
  look(target, distance, direction) {
    const from = direction || this.camera.position.clone().sub(this.controls.target).normalize();
    this.controls.target.copy(target);
    this.camera.position.copy(target.clone().add(from.multiplyScalar(distance)));
    this.camera.up.set(0, 0, 1);
    this.controls.update();
    this.render();
  }

  // The whole part from above, in front and to the side, +Z up as CAM software shows it.
  home() {
    const direction = new Vector3(0.55, -0.95, 0.9).normalize();
    const distance = this.radius / Math.sin((this.camera.fov * Math.PI) / 360) * 1.05;
    this.look(new Vector3(0, 0, 0), distance, direction);
  }

  showRegion(id, row) {
    const region = this.data.regions[id - 1];
    if (!region) return;
    for (const other of this.section.querySelectorAll('tr.ncv-chosen')) other.classList.remove('ncv-chosen');
    row?.classList.add('ncv-chosen');
    const lo = new Vector3(...this.local(region.boxMin));
    const hi = new Vector3(...this.local(region.boxMax));
    const size = Math.max(hi.clone().sub(lo).length(), this.radius / 12);
    this.look(new Vector3(...this.local(region.at)), size * 2.5);
    this.say(`region ${id} (${region.kind}): extreme ${formatLength(region.extreme, this.data)} ` +
      `${this.data.units} at ${formatPoint(region.at, this.data)}`);
  }

  showWorst(k) {
    const worst = this.data.worst[k];
    this.look(new Vector3(...this.local(worst.at)), this.radius / 4);
    this.say(`${worst.label} ${formatLength(worst.value, this.data)} ${this.data.units} at ` +
      formatPoint(worst.at, this.data));
  }

  say(text) {
    this.readout.textContent = text;
  }

  // The error under the pointer: interpolated over the displayed triangle from its
  // corners' samples.
  pick(event) {
    const rect = this.renderer.domElement.getBoundingClientRect();
    this.pointer.set(((event.clientX - rect.left) / rect.width) * 2 - 1,
      -((event.clientY - rect.top) / rect.height) * 2 + 1);
    this.raycaster.setFromCamera(this.pointer, this.camera);
    const hit = this.raycaster.intersectObject(this.surface, false)[0];
    if (!hit || !hit.face) return;
    const { a, b, c } = hit.face;
    const bary = hit.barycoord || new Vector3(1 / 3, 1 / 3, 1 / 3);
    const values = this.mesh.values;
    const value = values[a] * bary.x + values[b] * bary.y + values[c] * bary.z;
    const nearest = [a, b, c][[bary.x, bary.y, bary.z].indexOf(Math.max(bary.x, bary.y, bary.z))];
    const region = this.mesh.regions[nearest];
    const p = hit.point;
    const at = [p.x + this.center.x, p.y + this.center.y, p.z + this.center.z];
    let text = `error ${formatLength(value, this.data)} ${this.data.units} at ${formatPoint(at, this.data)}`;
    if (region) text += ` \u2014 region ${region} (${this.data.regions[region - 1].kind})`;
    this.say(text);
  }
}

function start() {
  for (const section of document.querySelectorAll('section.ncv-direction')) {
    const data = JSON.parse(document.getElementById(section.dataset.view).textContent);
    const view = new ErrorView(section, data);
    state.views.push({
      title: data.title,
      triangles: data.triangleCount,
      regions: data.regions.length,
      canvas: view.renderer.domElement,
    });
  }
  state.ready = true;
  document.body.dataset.ready = 'true';
}

if (document.readyState === 'loading') {
  document.addEventListener('DOMContentLoaded', start);
} else {
  start();
}

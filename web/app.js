// The live view's page: polls the server's latest frame (/state), draws every rod as a tube
// with three.js, and sends the sliders' values (/control). What the page measured is on
// document.body.dataset (frames drawn, drawn frames per second, slider-to-frame latency) for
// the end-to-end test.
"use strict";

const stats = { drawn: 0, fps: 0, latencyMs: null };
let config = null;
let pending = null;  // {version, sentAt}: a control sent, until a frame shows it

const el = (id) => document.getElementById(id);
const scene = new THREE.Scene();
const camera = new THREE.PerspectiveCamera(45, 1, 1e-4, 1e4);
const renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
renderer.setClearColor(0xf4f5f7);
el("scene").appendChild(renderer.domElement);
scene.add(new THREE.AmbientLight(0xffffff, 0.55));
const sun = new THREE.DirectionalLight(0xffffff, 0.9);
sun.position.set(1, -2, 3);
scene.add(sun);
const material = new THREE.MeshStandardMaterial({ color: 0x3b6fb6, roughness: 0.5 });
let tubes = [];
let framed = false;

function resize() {
  const box = el("scene").getBoundingClientRect();
  renderer.setSize(box.width, box.height);
  camera.aspect = box.width / Math.max(box.height, 1);
  camera.updateProjectionMatrix();
}
window.addEventListener("resize", resize);
resize();

let drawRadius = null;  // the tube's radius on screen: the section's, or L/120 for thin rods
function frameCamera(points) {
  const box = new THREE.Box3().setFromPoints(points);
  const size = Math.max(box.getSize(new THREE.Vector3()).length(), 1e-3);
  const centre = box.getCenter(new THREE.Vector3());
  let length = 0;
  for (let i = 1; i < points.length; i++) length += points[i].distanceTo(points[i - 1]);
  drawRadius = Math.max(config ? config.radius : 0, length / 120);
  const grid = new THREE.GridHelper(2 * size, 20, 0xb0b4bc, 0xd8dbe0);
  grid.rotation.x = Math.PI / 2;  // in the world's x-y plane, z up
  grid.position.set(centre.x, centre.y, box.min.z);
  scene.add(grid, new THREE.AxesHelper(0.25 * size));
  camera.up.set(0, 0, 1);
  camera.position.copy(centre).add(new THREE.Vector3(0.2 * size, -1.8 * size, 0.6 * size));
  camera.lookAt(centre);
  framed = true;
}

function draw(state) {
  for (const t of tubes) { scene.remove(t); t.geometry.dispose(); }
  tubes = [];
  for (const rod of state.rods || []) {
    if (rod.length < 2) continue;
    const points = rod.map((p) => new THREE.Vector3(p[0], p[1], p[2]));
    if (!framed) frameCamera(points);
    const curve = new THREE.CatmullRomCurve3(points);
    const mesh = new THREE.Mesh(new THREE.TubeGeometry(curve, 4 * points.length, drawRadius, 12), material);
    scene.add(mesh);
    tubes.push(mesh);
  }
  renderer.render(scene, camera);
  stats.drawn += 1;
  document.body.dataset.framesDrawn = String(stats.drawn);
}

function readout(state) {
  const tip = state.tip ? state.tip.map((v) => v.toFixed(5)).join(", ") : "–";
  const ratio = state.real_time_ratio == null ? "– (statics)" : state.real_time_ratio.toFixed(2) + "×";
  el("readout").textContent =
    `status      ${state.status}\nt           ${state.t.toFixed(3)} s\n` +
    `real time   ${ratio}\ntip         [${tip}] m\nframes/s    ${stats.fps.toFixed(0)}\n` +
    `latency     ${stats.latencyMs == null ? "–" : stats.latencyMs.toFixed(0) + " ms"}`;
  document.body.dataset.status = state.status;
  document.body.dataset.tip = JSON.stringify(state.tip);
}

async function setControl(name, value) {
  try {
    const sentAt = performance.now();
    const r = await fetch("/control", { method: "POST", body: JSON.stringify({ name, value }) });
    const body = await r.json();
    if (!r.ok) { el("message").textContent = body.error; return false; }
    el("message").textContent = "";
    pending = { version: body.control_version, sentAt };
    return true;
  } catch (e) {
    el("message").textContent = `the server did not answer (${e})`;
    return false;
  }
}
window.cosseratSetControl = setControl;

function buildControls() {
  const box = el("controls");
  for (const c of config.controls) {
    const row = document.createElement("div");
    row.className = "row";
    const label = document.createElement("label");
    const input = document.createElement("input");
    input.type = "range";
    input.id = "control-" + c.name;
    input.min = c.min; input.max = c.max; input.step = (c.max - c.min) / 200; input.value = c.value;
    // The label shows the value in force: the file's until the slider moves (the slider itself
    // snaps to its 200 steps), and 0 for a step's round-off residue near zero.
    const show = (v) => {
      const shown = Math.abs(v) < 1e-9 * (c.max - c.min) ? 0 : v;
      label.textContent = `${c.label}: ${Number(shown).toPrecision(3)} ${c.unit}`;
    };
    input.addEventListener("input", () => { show(Number(input.value)); setControl(c.name, Number(input.value)); });
    show(c.value);
    row.append(label, input);
    box.append(row);
  }
  el("notes").textContent = (config.notes || []).join("\n");
}

// Dragging the tip: a spring of config.drag_stiffness (N/m) pulls it toward the pointer, in the
// plane through the tip facing the camera; the tip-force sliders follow, and go back to their
// values when the pointer is released.
let lastState = null, drag = null;
const pointer = new THREE.Vector2(), raycaster = new THREE.Raycaster();
function tipOnScreen() {
  if (!lastState || !lastState.tip) return null;
  const p = new THREE.Vector3(...lastState.tip).project(camera);
  const box = renderer.domElement.getBoundingClientRect();
  return { x: box.left + (p.x + 1) / 2 * box.width, y: box.top + (1 - p.y) / 2 * box.height };
}
function setSlider(name, value) {
  const input = document.getElementById("control-" + name);
  if (!input) return;
  input.value = value;
  input.dispatchEvent(new Event("input"));
}
window.cosseratTipOnScreen = tipOnScreen;
// Where the tip was drawn over the last 0.3 s: a swinging tip (2 m/s is over 1000 px/s) is
// caught where the eye saw it, not only where the newest frame put it.
const recentTips = [];
function rememberTip() {
  const tip = tipOnScreen(), now = performance.now();
  if (tip) recentTips.push({ at: now, ...tip });
  while (recentTips.length && now - recentTips[0].at > 300) recentTips.shift();
}
renderer.domElement.addEventListener("pointerdown", (e) => {
  const near = recentTips.some((t) => Math.hypot(e.clientX - t.x, e.clientY - t.y) <= 25);
  if (!lastState || !config || !config.drag_stiffness || !near) return;
  const names = ["tip_force_x", "tip_force_y", "tip_force_z"];
  if (!names.every((n) => document.getElementById("control-" + n))) return;
  const normal = camera.getWorldDirection(new THREE.Vector3());
  drag = { plane: new THREE.Plane().setFromNormalAndCoplanarPoint(normal, new THREE.Vector3(...lastState.tip)),
           saved: names.map((n) => Number(document.getElementById("control-" + n).value)), names };
  renderer.domElement.setPointerCapture(e.pointerId);
});
renderer.domElement.addEventListener("pointermove", (e) => {
  if (!drag) return;
  const box = renderer.domElement.getBoundingClientRect();
  pointer.set(((e.clientX - box.left) / box.width) * 2 - 1, -((e.clientY - box.top) / box.height) * 2 + 1);
  raycaster.setFromCamera(pointer, camera);
  const target = new THREE.Vector3();
  if (!raycaster.ray.intersectPlane(drag.plane, target)) return;
  const pull = target.sub(new THREE.Vector3(...lastState.tip)).multiplyScalar(config.drag_stiffness);
  drag.names.forEach((n, i) => {
    const c = config.controls.find((c) => c.name === n);
    setSlider(n, Math.min(c.max, Math.max(c.min, drag.saved[i] + pull.getComponent(i))));
  });
});
renderer.domElement.addEventListener("pointerup", () => {
  if (!drag) return;
  drag.names.forEach((n, i) => setSlider(n, drag.saved[i]));
  drag = null;
});

let busy = false;
async function poll() {
  if (!busy) {
    busy = true;
    try {
      const state = await (await fetch("/state")).json();
      if (state.error) el("error").textContent = state.error;
      if (pending && state.control_version >= pending.version) {
        stats.latencyMs = performance.now() - pending.sentAt;
        document.body.dataset.latencyMs = stats.latencyMs.toFixed(1);
        pending = null;
      }
      lastState = state;
      rememberTip();
      draw(state);
      readout(state);
    } catch (e) {
      el("message").textContent = `lost the server (${e})`;
    }
    busy = false;
  }
  requestAnimationFrame(poll);
}

let lastCount = 0, lastTime = performance.now();
setInterval(() => {
  const now = performance.now();
  stats.fps = (1000 * (stats.drawn - lastCount)) / (now - lastTime);
  document.body.dataset.fps = stats.fps.toFixed(1);
  lastCount = stats.drawn; lastTime = now;
}, 1000);

(async () => {
  try {
    config = await (await fetch("/config")).json();
  } catch (e) {
    el("error").textContent = `no server (${e})`;
    return;
  }
  el("problem").textContent = `${config.problem} — ${config.mode}`;
  if (config.error) {
    el("error").textContent = config.error;
    document.body.dataset.status = "error";
    return;
  }
  buildControls();
  requestAnimationFrame(poll);
})();

// The SDI digital twin page: scene, design review, commissioning preview, execution monitor.
// All state comes from the server (the run's view and its event stream); the page keeps only
// what it draws. `window.sdiTwin` exposes the scene state for end-to-end tests.
import * as THREE from "three";
import { OrbitControls } from "three/addons/controls/OrbitControls.js";
import { TransformControls } from "three/addons/controls/TransformControls.js";

const $ = (id) => document.getElementById(id);
const TAB = sessionStorage.getItem("sdi-tab") || Math.random().toString(36).slice(2, 12);
sessionStorage.setItem("sdi-tab", TAB);
const COLOURS = {
  proposed: 0x9fb3c8, violating: 0xd32f2f, verified: 0x64b5f6, placed: 0x43a047,
  disturbed: 0xff9800, selected: 0xffd54f, pending: 0xbdbdbd,
};

const T = {
  tab: TAB, runId: null, view: null, scene: null, timeline: null, selected: null,
  partIds: [], partStates: {}, placed: {}, toPlace: [], clock: 0, playing: false, deltaPoints: [],
  samples: {}, execClock: 0, lastSeq: 0, frames: 0, ready: false, busyRefresh: false,
};
window.sdiTwin = T;
T.edit = (op) => edit(op);

// ---------------------------------------------------------------------------- three.js scene
const container = $("view");
const renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
renderer.setPixelRatio(1);
container.appendChild(renderer.domElement);
const scene3 = new THREE.Scene();
scene3.background = new THREE.Color(0xeef1f4);
const camera = new THREE.PerspectiveCamera(40, 1, 0.01, 20);
camera.up.set(0, 0, 1);
camera.position.set(0.62, -0.62, 1.3);
const orbit = new OrbitControls(camera, renderer.domElement);
orbit.target.set(0.5, 0.3, 0.05);
orbit.update();
scene3.add(new THREE.HemisphereLight(0xffffff, 0x888888, 2.0));
const sun = new THREE.DirectionalLight(0xffffff, 1.5);
sun.position.set(1, -1, 2);
scene3.add(sun);

function resize() {
  const w = container.clientWidth, h = container.clientHeight;
  renderer.setSize(w, h);
  camera.aspect = w / Math.max(1, h);
  camera.updateProjectionMatrix();
}
window.addEventListener("resize", resize);
resize();

const gizmo = new TransformControls(camera, renderer.domElement);
gizmo.setSize(0.7);
const gizmoTarget = new THREE.Object3D();
scene3.add(gizmoTarget);
scene3.add(gizmo.getHelper());
gizmo.addEventListener("dragging-changed", (e) => {
  orbit.enabled = !e.value;
  if (!e.value && T.selected) {
    const p = gizmoTarget.position;
    edit({ op: "move", id: T.selected, position: [p.x, p.y, p.z], free: !!T.shift });
  }
});

function matrixOf(m16) {
  const m = new THREE.Matrix4();
  m.set(...m16);
  return m;
}

function box(size, colour, opacity = 1) {
  const mat = new THREE.MeshStandardMaterial({ color: colour, transparent: opacity < 1, opacity });
  return new THREE.Mesh(new THREE.BoxGeometry(...size), mat);
}

function drawFixed(s) {
  const table = box(s.table.half.map((v) => 2 * v), 0xd7ccc8);
  table.position.set(...s.table.centre);
  scene3.add(table);
  const lo = s.workspace.lower, hi = s.workspace.upper;
  const ws = new THREE.Box3(new THREE.Vector3(...lo), new THREE.Vector3(...hi));
  scene3.add(new THREE.Box3Helper(ws, 0x1565c0));
  for (const a of s.supply_areas) {
    const pad = box([a.x[1] - a.x[0], a.y[1] - a.y[0], 0.002], 0xffe082);
    pad.position.set((a.x[0] + a.x[1]) / 2, (a.y[0] + a.y[1]) / 2, 0.001);
    scene3.add(pad);
  }
  T.robots = {};
  T.ghosts = {};
  for (const r of s.robots) {
    T.robots[r.name] = buildRobot(r, 1.0);
    T.ghosts[r.name] = buildRobot(r, 0.25);
    T.ghosts[r.name].root.visible = false;
    setJoints(T.robots[r.name], r.home);
  }
}

// A robot from its URDF chain: one group per joint, visuals hung off each link.
function buildRobot(r, opacity) {
  const root = new THREE.Group();
  root.matrixAutoUpdate = false;
  root.matrix.copy(matrixOf(r.T_world_base));
  scene3.add(root);
  const joints = [];
  const addVisuals = (link, group) => {
    for (const v of r.visuals[link] || []) {
      let geom;
      if (v.kind === "box") geom = new THREE.BoxGeometry(...v.size);
      else if (v.kind === "cylinder") {
        geom = new THREE.CylinderGeometry(v.radius, v.radius, v.length, 20);
        geom.rotateX(Math.PI / 2); // URDF cylinders run along z, three.js along y
      } else geom = new THREE.SphereGeometry(v.radius, 16, 12);
      const c = v.colour || [0.8, 0.8, 0.8, 1];
      const mat = new THREE.MeshStandardMaterial({
        color: new THREE.Color(c[0], c[1], c[2]), transparent: opacity < 1, opacity,
        depthWrite: opacity >= 1,
      });
      const mesh = new THREE.Mesh(geom, mat);
      mesh.matrixAutoUpdate = false;
      mesh.matrix.copy(matrixOf(v.origin));
      group.add(mesh);
    }
  };
  addVisuals(r.base_link, root);
  let parent = root;
  for (const j of r.chain) {
    const origin = new THREE.Group();
    origin.matrixAutoUpdate = false;
    origin.matrix.copy(matrixOf(j.origin));
    const moving = new THREE.Group();
    origin.add(moving);
    parent.add(origin);
    addVisuals(j.child, moving);
    if (j.type === "revolute") joints.push({ group: moving, axis: new THREE.Vector3(...j.axis) });
    parent = moving;
  }
  return { root, joints, name: r.name };
}

function setJoints(robot, q) {
  robot.joints.forEach((j, i) => j.group.quaternion.setFromAxisAngle(j.axis, q[i] || 0));
}

// ------------------------------------------------------------------------------ the parts
// One InstancedMesh for every part: a picked instance id names the part.
let parts = null;
const MAX_PARTS = 2048;
function ensureParts() {
  if (parts) return;
  const geom = new THREE.BoxGeometry(1, 1, 1);
  const mat = new THREE.MeshStandardMaterial({ color: 0xffffff });
  parts = new THREE.InstancedMesh(geom, mat, MAX_PARTS);
  parts.count = 0;
  parts.instanceMatrix.setUsage(THREE.DynamicDrawUsage);
  scene3.add(parts);
  T.partsMesh = parts;
}

let labels = [];
function drawParts(list, states) {
  ensureParts();
  T.partList = list;
  T.partIds = list.map((p) => p.id);
  T.partStates = {};
  const m = new THREE.Matrix4(), q = new THREE.Quaternion(), z = new THREE.Vector3(0, 0, 1);
  list.forEach((p, i) => {
    q.setFromAxisAngle(z, (p.yaw_deg || 0) * Math.PI / 180);
    const hidden = states[p.id] === "hidden";
    m.compose(new THREE.Vector3(...p.position), q,
      // drawn 3 % smaller, so neighbouring parts read as separate parts
      hidden ? new THREE.Vector3(1e-6, 1e-6, 1e-6) : new THREE.Vector3(...p.size).multiplyScalar(0.97));
    parts.setMatrixAt(i, m);
    const state = p.id === T.selected && states[p.id] !== "violating" ? "selected" : states[p.id] || "proposed";
    T.partStates[p.id] = states[p.id] || "proposed";
    parts.setColorAt(i, new THREE.Color(COLOURS[state] || COLOURS.proposed));
  });
  parts.count = list.length;
  parts.instanceMatrix.needsUpdate = true;
  if (parts.instanceColor) parts.instanceColor.needsUpdate = true;
  parts.computeBoundingSphere();
  drawLabels(list, states);
}

// Labels: each violating part names its broken constraints (always); with "order labels",
// every part shows its place in the assembly order and its id.
function drawLabels(list, states) {
  for (const l of labels) scene3.remove(l);
  labels = [];
  T.labels = {};
  const broken = {};
  const shown = T.replay ? T.replay.design?.violations || [] : reviewing(T.view) ? T.view.review.violations : [];
  for (const v of shown) {
    for (const id of v.objects) (broken[id] = broken[id] || new Set()).add(v.constraint);
  }
  const order = (T.view && (T.view.review?.sequence || T.view.sequence)) || T.partIds;
  list.forEach((p) => {
    if (states[p.id] === "hidden") return;
    let text = $("labels").checked ? `${order.indexOf(p.id) + 1} · ${p.id}` : "";
    if (broken[p.id]) text = `${text ? text + " · " : ""}${[...broken[p.id]].join(", ")}`;
    if (!text) return;
    T.labels[p.id] = text;
    const c = document.createElement("canvas");
    c.width = 256; c.height = 40;
    const g = c.getContext("2d");
    g.font = "bold 24px sans-serif"; g.textAlign = "center";
    const w = Math.min(256, g.measureText(text).width + 12);
    g.fillStyle = "rgba(255,255,255,0.85)";
    g.fillRect(128 - w / 2, 4, w, 34);
    g.fillStyle = broken[p.id] ? "#b71c1c" : "#222";
    g.fillText(text, 128, 30);
    const sprite = new THREE.Sprite(new THREE.SpriteMaterial({ map: new THREE.CanvasTexture(c), depthTest: false }));
    sprite.scale.set(0.24, 0.0375, 1);
    sprite.position.set(p.position[0], p.position[1], p.position[2] + p.size[2] / 2 + 0.03);
    scene3.add(sprite);
    labels.push(sprite);
  });
}

// ------------------------------------------------------------------------------ server calls
async function api(path, body) {
  const opts = body === undefined ? {} : {
    method: "POST", headers: { "content-type": "application/json" }, body: JSON.stringify(body),
  };
  const r = await fetch(path, opts);
  const data = await r.json();
  if (!r.ok) {
    showError(data.field ? `${data.field}: ${data.error}` : data.error);
    throw new Error(data.error);
  }
  showError(null);
  return data;
}

// A button's action: a refused request is shown by `api` (the error line), not thrown further.
const safe = (fn) => async (...args) => {
  try { await fn(...args); } catch (e) { if (!T.lastError) showError(String(e)); }
};

function showError(text) {
  $("error").hidden = !text;
  $("error").textContent = text || "";
  T.lastError = text || null;
}

// Views asked for, numbered: answers can arrive out of order (an event's refresh sent before an
// edit may answer after it), and an older answer must not replace a newer one on screen.
let viewAsked = 0;

async function edit(op) {
  if (!T.runId) return;
  const asked = ++viewAsked;
  try {
    const review = await api(`/api/runs/${T.runId}/edit`, { tab: TAB, op });
    if (asked !== viewAsked) return; // a later view is coming (or came): it has this edit
    T.view.review = review;
    render();
  } catch (e) {
    render(); // a refused edit: back to the server's layout
  }
}

// ------------------------------------------------------------------------------ run view
async function openRun(runId) {
  if (T.ws) T.ws.close();
  T.runId = runId;
  T.timeline = null; T.placed = {}; T.deltaPoints = []; T.samples = {}; T.selected = null;
  T.execClock = 0; T.lastSeq = 0; T.replaying = false; T.replay = null; T.editFailed = false;
  $("replay-panel").hidden = true;
  history.replaceState(null, "", `#${runId}`);
  await refresh();
  connect();
  await refreshRuns();
}

function connect() {
  const proto = location.protocol === "https:" ? "wss" : "ws";
  const ws = new WebSocket(`${proto}://${location.host}/ws/runs/${T.runId}?tab=${TAB}&after=0`);
  T.ws = ws;
  ws.onmessage = (msg) => {
    const data = JSON.parse(msg.data);
    if (data.type === "events") onEvents(data.events, false);
  };
  ws.onclose = () => { if (T.ws === ws) setTimeout(() => T.ws === ws && connect(), 1000); };
}
setInterval(() => { if (T.ws && T.ws.readyState === 1) T.ws.send(JSON.stringify({ tab: TAB })); }, 5000);

const REFRESH_ON = new Set(["stopped", "twin_idle", "twin_edit", "twin_error", "record", "execution"]);
function onEvents(events, replay) {
  let refreshNeeded = false;
  for (const e of events) {
    T.lastSeq = Math.max(T.lastSeq, e.seq);
    if (e.type === "samples") addSamples(e.payload);
    else if (e.type === "step_done") T.toPlace.push(e.payload); // shown when the clock gets there
    else if (e.type === "execution_started") {
      T.placed = {}; T.samples = {}; T.deltaPoints = []; T.execClock = 0; T.executing = true;
      T.toPlace = [];
      for (const p of e.payload.already_placed || []) placePart(p);
    } else if (e.type === "execution") T.executing = false;
    if (!replay && REFRESH_ON.has(e.type)) refreshNeeded = true;
  }
  if (refreshNeeded) refresh();
  else drawScene();
}

async function refresh() {
  if (!T.runId) return;
  const asked = ++viewAsked;
  const view = await api(`/api/runs/${T.runId}`);
  if (asked !== viewAsked) return; // a later view is on its way
  const changed = !T.view || T.view.status !== view.status || T.view.busy !== view.busy ||
    T.view.waiting_for?.kind !== view.waiting_for?.kind;
  T.view = view;
  if (changed) refreshRuns();
  const kind = view.waiting_for?.kind;
  const confirming = kind === "pre_execute" || kind === "resume_execution";
  // the record on screen: the one awaiting approval, else the one approved (and executed)
  const wanted = confirming ? view.waiting_for.record_hash : view.approved_hash;
  if (wanted && (!T.timeline || T.timeline.record_hash !== wanted)) {
    try { T.timeline = await api(`/api/runs/${T.runId}/timeline`); } catch (e) { T.timeline = null; }
    setupSlider();
  }
  render();
  T.ready = true;
}

async function refreshRuns() {
  const runs = await api("/api/runs");
  const ul = $("runs");
  ul.innerHTML = "";
  for (const r of runs) {
    const li = document.createElement("li");
    li.textContent = `${r.run_id} · ${r.busy ? r.busy + "…" : r.waiting_for || r.status} · ${(r.command || "").slice(0, 40)}`;
    li.dataset.run = r.run_id;
    if (r.run_id === T.runId) li.className = "current";
    li.onclick = () => openRun(r.run_id);
    ul.appendChild(li);
  }
  T.runs = runs;
}

// The editor is open at a design review, and at a failure report once the operator asked to
// edit the failed layout.
function reviewing(v) {
  return !!(v && v.review && !v.busy && (v.waiting_for?.kind !== "failure_report" || T.editFailed));
}

function phaseText(v) {
  if (v.busy) return `working: ${v.busy}…`;
  const k = v.waiting_for?.kind;
  if (k === "design_review") return "touch point 1 — design review";
  if (k === "recovery_review") return "touch point 1 — a recovery changed the shape: review it";
  if (k === "edit_review") return "touch point 1 — the edit breaks constraints: choose";
  if (k === "pre_execute") return "touch point 2 — approve the commissioning record";
  if (k === "resume_execution") return "execution was interrupted — approve to continue";
  if (k === "failure_report") return "touch point 3 — failure report";
  return `run ${v.status}`;
}

function render() {
  const v = T.view;
  if (!v) return;
  T.phase = v.busy ? "busy" : v.waiting_for?.kind || v.status;
  $("phase").textContent = `${v.run_id}: ${phaseText(v)}`;
  if (v.error) showError(v.error);
  // reading
  const rd = v.reading;
  $("reading-panel").hidden = !rd && !(v.notes || []).length;
  const ul = $("reading");
  ul.innerHTML = "";
  for (const s of rd?.structures || []) addLi(ul, s);
  for (const r of rd?.relations || []) addLi(ul, r);
  const read = new Set(rd?.notes || []);
  for (const n of read) addLi(ul, n, "note");
  if (rd?.ignored?.length) addLi(ul, `ignored: ${rd.ignored.join(", ")}`, "note");
  // the run's own notes (a recovery, a replan) under their own heading; the reading's notes
  // are repeated in the run's for every review, so each is shown once
  const run = $("run-notes");
  run.innerHTML = "";
  for (const n of new Set((v.notes || []).filter((n) => !read.has(n)))) addLi(run, n, "note");
  $("run-notes-title").hidden = !run.children.length;
  // panels
  const kind = v.waiting_for?.kind;
  if (kind !== "failure_report") T.editFailed = false;
  const review = reviewing(v);
  $("review-panel").hidden = !review;
  const failing = kind === "failure_report";
  $("reject-box").hidden = failing;
  $("back-to-report").hidden = !failing;
  $("editing-failed").hidden = !failing;
  $("accept").textContent = failing ? "Send the edited layout" : "Accept design";
  const replanned = v.waiting_for?.replanned;
  $("replanned").hidden = !replanned;
  $("replanned").textContent = replanned || "";
  const confirming = ["pre_execute", "resume_execution"].includes(v.waiting_for?.kind) && !v.busy;
  $("preview-panel").hidden = !(T.timeline && (confirming || v.approved_hash));
  $("confirm-buttons").hidden = !confirming;
  $("revise").hidden = v.waiting_for?.kind !== "pre_execute";
  $("monitor-panel").hidden = !(v.approved_hash || T.executing);
  $("failure-panel").hidden = !failing || !!v.busy || !!T.editFailed;
  $("plan").disabled = false;
  if (review) renderReview(v.review);
  const rec = v.waiting_for?.recovery;
  $("recovery").hidden = !rec;
  $("recovery").textContent = rec ? `recovery: ${rec.summary || JSON.stringify(rec)}` : "";
  const er = v.waiting_for?.kind === "edit_review" && !v.busy;
  $("edit-review-panel").hidden = !er;
  if (er) {
    const w = v.waiting_for;
    $("edit-review").textContent = (w.violations || []).map((x) => `[${x.constraint}] ${x.message}`).join("; ") +
      (w.repair ? ` — repair: ${w.repair.summary}` : " — no repair keeps it");
    $("edit-repair").disabled = !w.repair;
  }
  if (T.timeline) renderRecord();
  if (failing) renderFailure(v);
  renderExec();
  drawScene();
}

// Touch point 3: the failure and the orchestrator's options (its recovery skills, retry, a
// human edit of the failed layout, abort).
function renderFailure(v) {
  const f = v.failure || {};
  const w = v.waiting_for;
  $("failure").textContent = `${f.error_type || "failure"} in ${f.phase || "?"}: ${f.message || ""}`;
  $("failure-refused").hidden = !w.refused;
  $("failure-refused").textContent = w.refused || "";
  $("edit-failed").disabled = !v.review;
  const skills = w.skills || [];
  const key = skills.map((k) => k.name).join();
  if ($("skills").dataset.key === key) return;
  $("skills").dataset.key = key;
  $("skills").innerHTML = "";
  for (const k of skills) {
    const b = document.createElement("button");
    b.id = `skill-${k.name}`;
    b.textContent = k.name;
    b.title = k.does;
    b.onclick = safe(async () => {
      await api(`/api/runs/${T.runId}/failure`, { tab: TAB, action: "recover", skill: k.name });
      await refresh();
    });
    const row = document.createElement("div");
    row.append(b, ` ${k.does}`);
    $("skills").appendChild(row);
  }
}

function addLi(ul, text, cls) {
  const li = document.createElement("li");
  li.textContent = text;
  if (cls) li.className = cls;
  ul.appendChild(li);
}

function renderReview(r) {
  $("undo").disabled = !r.can_undo;
  $("redo").disabled = !r.can_redo;
  const failing = T.view.waiting_for?.kind === "failure_report";
  $("accept").disabled = !r.passed || (failing && !r.edits.length);
  const sel = T.selected && r.parts.find((p) => p.id === T.selected);
  $("selected").textContent = sel
    ? `${sel.id} at (${sel.position.map((x) => x.toFixed(3)).join(", ")}), yaw ${sel.yaw_deg}°, order ${(r.sequence || []).indexOf(sel.id) + 1}`
    : "click a part to select it; drag it to move (Shift: free, no snap)";
  const ul = $("violations");
  ul.innerHTML = "";
  if (!r.violations.length) addLi(ul, "none — the Inspector passes this layout", "ok");
  r.violations.forEach((v, k) => {
    const li = document.createElement("li");
    li.textContent = `[${v.constraint}] ${v.message} — ${v.hint}`;
    if (v.suggestion) {
      const b = document.createElement("button");
      b.textContent = "apply";
      b.className = "hint";
      b.onclick = () => edit({ op: "hint", index: k });
      li.appendChild(b);
    }
    ul.appendChild(li);
  });
}

// The scene for the current phase: review layout, preview at the slider, or as built.
function drawScene() {
  const v = T.view;
  if (!v || !T.scene) return;
  const states = {};
  let list = [];
  const R = T.replay;
  if (R && R.layout) { // a replay: the design in force at its step, or the record's parts
    list = R.layout;
    const executing = R.steps[R.k]?.kind === "execution";
    const violating = new Set((R.design?.violations || []).flatMap((x) => x.objects || []));
    for (const p of list) {
      if (executing) states[p.id] = T.placed[p.id] || "pending";
      else states[p.id] = violating.has(p.id) ? "violating" : "verified";
    }
  } else if (reviewing(v)) {
    list = v.review.parts;
    for (const p of list) states[p.id] = p.state;
  } else if (v.layout) {
    list = v.layout;
    const violating = new Set((v.violations || []).flatMap((x) => x.objects || []));
    // the preview builds up as its clock runs; once its record ran, unbuilt parts are pending
    const ran = !!(v.execution && T.timeline && v.execution.record_hash === T.timeline.record_hash);
    const built = T.executing || ran || Object.keys(T.placed).length;
    const showTimeline = T.timeline && !built;
    for (const p of list) {
      if (T.placed[p.id]) states[p.id] = T.placed[p.id];
      else if (showTimeline) states[p.id] = partShownAt(p.id, T.clock) ? "verified" : "hidden";
      else if (built) states[p.id] = "pending";
      else states[p.id] = violating.has(p.id) ? "violating" : "verified";
    }
  }
  drawParts(list, states);
  const ghostsOn = !!T.timeline && !reviewing(v) && (!R || R.steps[R.k]?.kind === "execution");
  for (const name in T.ghosts) T.ghosts[name].root.visible = ghostsOn;
  if (T.timeline) {
    for (const name in T.timeline.robots) {
      const q = planAt(name, T.clock);
      if (q) setJoints(T.ghosts[name], q);
    }
  }
  if (!R && reviewing(v) && $("use-gizmo").checked && T.selected && list.find((p) => p.id === T.selected)) {
    const p = list.find((p) => p.id === T.selected);
    if (!gizmo.dragging) gizmoTarget.position.set(...p.position);
    if (!gizmo.object) gizmo.attach(gizmoTarget);
  } else if (gizmo.object) gizmo.detach();
}

function partShownAt(id, t) {
  const s = T.timeline.steps.find((x) => x.part_id === id);
  return !s || s.release === null || t >= s.release;
}

// ------------------------------------------------------------------------------ picking, drag
const raycaster = new THREE.Raycaster();
function pick(ev) {
  const rect = renderer.domElement.getBoundingClientRect();
  const ndc = new THREE.Vector2(((ev.clientX - rect.left) / rect.width) * 2 - 1,
    -((ev.clientY - rect.top) / rect.height) * 2 + 1);
  raycaster.setFromCamera(ndc, camera);
  return raycaster;
}

let drag = null;
renderer.domElement.addEventListener("pointerdown", (ev) => {
  T.shift = ev.shiftKey;
  if (!reviewing(T.view) || T.replay || $("use-gizmo").checked) return;
  const hit = parts && pick(ev).intersectObject(parts)[0];
  if (!hit) return;
  const id = T.partIds[hit.instanceId];
  T.selected = id;
  const p = T.view.review.parts.find((x) => x.id === id);
  drag = { id, z: p.position[2], plane: hit.point.z, start: [...p.position], moved: false,
           offset: [hit.point.x - p.position[0], hit.point.y - p.position[1]] };
  orbit.enabled = false;
  render();
});
renderer.domElement.addEventListener("pointermove", (ev) => {
  if (!drag) return;
  const plane = new THREE.Plane(new THREE.Vector3(0, 0, 1), -drag.plane);
  const point = new THREE.Vector3();
  if (!pick(ev).ray.intersectPlane(plane, point)) return;
  const p = T.view.review.parts.find((x) => x.id === drag.id);
  p.position = [point.x - drag.offset[0], point.y - drag.offset[1], drag.z];
  drag.moved = true;
  drawScene();
});
renderer.domElement.addEventListener("pointerup", (ev) => {
  orbit.enabled = true;
  if (!drag) return;
  const d = drag;
  drag = null;
  if (!d.moved) return;
  const p = T.view.review.parts.find((x) => x.id === d.id);
  edit({ op: "move", id: d.id, position: p.position, free: ev.shiftKey });
});

// ------------------------------------------------------------------------------ review buttons
const needSel = (fn) => () => { if (T.selected) fn(T.selected); };
$("rotate-left").onclick = needSel((id) => edit({ op: "rotate", id, by_deg: -90 }));
$("rotate-right").onclick = needSel((id) => edit({ op: "rotate", id, by_deg: 90 }));
$("delete").onclick = needSel((id) => { T.selected = null; edit({ op: "remove", id }); });
function insertAt() {
  const r = T.view.review;
  const sel = T.selected && r.parts.find((p) => p.id === T.selected);
  if (sel) return [sel.position[0], sel.position[1], sel.position[2] + sel.size[2]];
  const lo = T.scene.workspace.lower, hi = T.scene.workspace.upper;
  return [(lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2, 0.025];
}
$("insert-cube").onclick = () => edit({ op: "insert", part: "cube", position: insertAt() });
$("insert-beam").onclick = () => edit({ op: "insert", part: "beam", position: insertAt() });
function reorder(delta) {
  const seq = T.view.review.sequence || T.partIds;
  const k = seq.indexOf(T.selected);
  if (k < 0) return;
  if (delta < 0 && k > 0) edit({ op: "reorder", id: T.selected, before: seq[k - 1] });
  if (delta > 0 && k < seq.length - 1) edit({ op: "reorder", id: T.selected, before: seq[k + 2] ?? null });
}
$("earlier").onclick = () => reorder(-1);
$("later").onclick = () => reorder(1);
$("undo").onclick = () => edit({ op: "undo" });
$("redo").onclick = () => edit({ op: "redo" });
$("labels").onchange = () => drawScene();
$("use-gizmo").onchange = () => drawScene();
window.addEventListener("keydown", (ev) => {
  if (ev.target.tagName === "TEXTAREA" || ev.target.tagName === "INPUT") return;
  if ((ev.ctrlKey || ev.metaKey) && ev.key === "z") edit({ op: "undo" });
  if ((ev.ctrlKey || ev.metaKey) && ev.key === "y") edit({ op: "redo" });
  if (ev.key === "Delete" && T.selected) $("delete").click();
});
$("accept").onclick = safe(async () => {
  await api(`/api/runs/${T.runId}/accept`, { tab: TAB, layout_hash: T.view.review.layout_hash });
  T.selected = null;
  await refresh();
});
$("reject").onclick = safe(async () => {
  await api(`/api/runs/${T.runId}/reject`, { tab: TAB, reason: $("reason").value });
  $("reason").value = "";
  T.selected = null;
  await refresh();
});
$("review-abort").onclick = safe(async () => {
  await api(`/api/runs/${T.runId}/abort`, { tab: TAB });
  await refresh();
});
$("edit-failed").onclick = () => { T.editFailed = true; T.selected = null; render(); };
$("back-to-report").onclick = () => { T.editFailed = false; T.selected = null; render(); };
$("command-form").onsubmit = async (ev) => {
  ev.preventDefault();
  $("plan").disabled = true;
  try {
    const { run_id } = await api("/api/runs", { command: $("command").value });
    await openRun(run_id);
  } finally { $("plan").disabled = false; }
};

// ------------------------------------------------------------------------------ preview
function planAt(name, t) {
  const r = T.timeline?.robots[name];
  if (!r || !r.t.length) return null;
  let lo = 0, hi = r.t.length - 1;
  if (t <= r.t[0]) return r.q[0];
  if (t >= r.t[hi]) return r.q[hi];
  while (hi - lo > 1) { const mid = (lo + hi) >> 1; if (r.t[mid] <= t) lo = mid; else hi = mid; }
  const a = (t - r.t[lo]) / (r.t[hi] - r.t[lo]);
  return r.q[lo].map((v, i) => v + a * (r.q[hi][i] - v));
}

function setupSlider() {
  if (!T.timeline) return;
  $("slider").max = T.timeline.makespan_s;
  $("slider").value = 0;
  T.clock = 0;
}
$("slider").oninput = () => { T.clock = parseFloat($("slider").value); T.playing = false; drawScene(); renderRecord(); };
$("play").onclick = () => { T.playing = !T.playing; if (T.clock >= T.timeline.makespan_s) T.clock = 0; };

function renderRecord() {
  const tl = T.timeline, v = T.view;
  const p = v.planning || {};
  $("record").textContent = `record ${tl.record_hash.slice(0, 12)} · ${tl.steps.length} steps · makespan ${tl.makespan_s.toFixed(1)} s` +
    (p.steps_per_robot ? ` · ${Object.entries(p.steps_per_robot).map(([r, n]) => `${r}: ${n}`).join(", ")}` : "");
  $("clock").textContent = `${T.clock.toFixed(1)} / ${tl.makespan_s.toFixed(1)} s`;
  $("play").textContent = T.playing ? "❚❚ Pause" : "▶ Play";
  $("slider").value = T.clock;
  drawGantt();
}

function drawGantt() {
  const tl = T.timeline, c = $("gantt"), g = c.getContext("2d");
  const robots = Object.keys(tl.robots);
  g.clearRect(0, 0, c.width, c.height);
  const x = (t) => 60 + (c.width - 65) * t / Math.max(1e-6, tl.makespan_s);
  const rowH = (c.height - 10) / Math.max(1, robots.length);
  robots.forEach((r, i) => {
    g.fillStyle = "#333"; g.font = "11px sans-serif";
    g.fillText(r, 2, 5 + rowH * i + rowH / 2 + 4);
    for (const s of tl.steps.filter((s) => s.robot === r)) {
      if (s.start == null) continue;
      g.fillStyle = i ? "#ef8354" : "#4f8fc0";
      g.fillRect(x(s.start), 5 + rowH * i + 3, Math.max(1, x(s.end) - x(s.start) - 1), rowH - 6);
    }
  });
  g.strokeStyle = "#d32f2f";
  g.beginPath(); g.moveTo(x(T.clock), 0); g.lineTo(x(T.clock), c.height); g.stroke();
}

$("approve").onclick = async () => {
  await api(`/api/runs/${T.runId}/confirm`, { tab: TAB, action: "approve", record_hash: T.view.waiting_for.record_hash });
  await refresh();
};
$("revise").onclick = async () => { await api(`/api/runs/${T.runId}/confirm`, { tab: TAB, action: "revise" }); T.timeline = null; await refresh(); };
$("abort").onclick = async () => { await api(`/api/runs/${T.runId}/confirm`, { tab: TAB, action: "abort" }); await refresh(); };
for (const a of ["repair", "undo", "replan", "reject"]) {
  $(`edit-${a}`).onclick = async () => { await api(`/api/runs/${T.runId}/edit-review`, { tab: TAB, action: a }); await refresh(); };
}
$("retry").onclick = async () => { await api(`/api/runs/${T.runId}/failure`, { tab: TAB, action: "retry" }); await refresh(); };
$("fail-abort").onclick = async () => { await api(`/api/runs/${T.runId}/failure`, { tab: TAB, action: "abort" }); await refresh(); };

// ------------------------------------------------------------------------------ execution
function addSamples(payload) {
  for (const [name, rows] of Object.entries(payload.q || {})) {
    (T.samples[name] = T.samples[name] || []).push(...rows);
    for (const row of rows) {
      const plan = planAt(name, row[0]);
      if (!plan) continue;
      const d = Math.sqrt(plan.reduce((s, v, i) => s + (v - row[i + 1]) ** 2, 0));
      T.deltaPoints.push([row[0], d, name]);
    }
  }
  if (payload.delta_max_rad != null) T.deltaMax = payload.delta_max_rad;
}

function placePart(p) {
  const step = T.timeline?.steps.find((s) => s.part_id === p.part_id);
  let state = "placed";
  if (step && p.pose) {
    const tgt = step.target;
    const err = Math.hypot(p.pose[0] - tgt[0][3], p.pose[1] - tgt[1][3], p.pose[2] - tgt[2][3]);
    if (err > T.scene.placed_tolerance_m) state = "disturbed";
  }
  T.placed[p.part_id] = state;
}

function renderExec() {
  const step = T.replay?.steps[T.replay.k];
  const ex = step ? (step.kind === "execution" ? step.report : null) : T.view?.execution;
  const n = Object.values(T.placed).filter((s) => s === "placed").length;
  let text = T.executing ? "executing… " : "";
  text += `${n} part(s) placed within ${(T.scene?.placed_tolerance_m || 0) * 1000} mm`;
  if (ex) text += ` · ${ex.status} · V_traj ${ex.v_traj} · δ ${ex.delta_rad} rad (ε ${ex.epsilon_rad})`;
  $("exec-status").textContent = text;
  T.vTraj = ex?.v_traj || null;
  if (T.replay) renderReplay();
  drawDelta();
}

function drawDelta() {
  const c = $("delta"), g = c.getContext("2d");
  g.clearRect(0, 0, c.width, c.height);
  const eps = T.scene?.epsilon_rad || 0.05;
  const tmax = T.timeline?.makespan_s || Math.max(1, ...T.deltaPoints.map((p) => p[0]));
  const ymax = eps * 1.5;
  const x = (t) => 5 + (c.width - 10) * t / tmax, y = (d) => c.height - 5 - (c.height - 10) * Math.min(d, ymax) / ymax;
  g.strokeStyle = "#d32f2f"; g.setLineDash([4, 3]);
  g.beginPath(); g.moveTo(0, y(eps)); g.lineTo(c.width, y(eps)); g.stroke(); g.setLineDash([]);
  g.fillStyle = "#555"; g.font = "10px sans-serif"; g.fillText(`ε = ${eps} rad`, c.width - 70, y(eps) - 3);
  g.fillStyle = "#1565c0";
  for (const [t, d] of T.deltaPoints) g.fillRect(x(t), y(d), 2, 2);
  g.strokeStyle = "#333"; g.beginPath(); g.moveTo(x(T.execClock), 0); g.lineTo(x(T.execClock), c.height); g.stroke();
}

// Play Q_exec samples in order; a view that falls behind plays faster to catch up.
function stepExecution(dt) {
  let latest = 0;
  for (const rows of Object.values(T.samples)) if (rows.length) latest = Math.max(latest, rows[rows.length - 1][0]);
  if (latest <= T.execClock) return;
  const behind = latest - T.execClock;
  T.execClock = Math.min(latest, T.execClock + dt * Math.max(1, behind / 2));
  for (const [name, rows] of Object.entries(T.samples)) {
    let k = rows.length - 1;
    while (k > 0 && rows[k][0] > T.execClock) k--;
    if (rows[k]) setJoints(T.robots[name], rows[k].slice(1));
    const q = planAt(name, T.execClock);
    if (q) setJoints(T.ghosts[name], q);
  }
  T.clock = T.execClock;
  const due = T.toPlace.filter((p) => p.t == null || p.t <= T.execClock);
  if (due.length) {
    T.toPlace = T.toPlace.filter((p) => !due.includes(p));
    for (const p of due) placePart(p);
    drawScene();
    renderExec();
  }
  if (T.timeline) renderRecord();
  drawDelta();
}

// ------------------------------------------------------------------------------ replay
// A finished run told again from its event stream (GET /replay): the design versions shown at
// review with each answer, the record planned and its approval, then the execution with δ.
$("replay").onclick = async () => {
  const r = await api(`/api/runs/${T.runId}/replay`);
  T.replay = { steps: r.steps, k: -1, layout: null, design: null };
  $("replay-panel").hidden = false;
  const ol = $("replay-steps");
  ol.innerHTML = "";
  r.steps.forEach((step, k) => {
    const li = document.createElement("li");
    li.textContent = describeStep(step);
    li.onclick = () => replayTo(k);
    ol.appendChild(li);
  });
  await replayTo(0);
};
$("replay-prev").onclick = () => T.replay && replayTo(T.replay.k - 1);
$("replay-next").onclick = () => T.replay && replayTo(T.replay.k + 1);
$("replay-close").onclick = () => {
  T.replay = null; T.placed = {}; T.samples = {}; T.deltaPoints = []; T.toPlace = [];
  $("replay-panel").hidden = true;
  refresh();
};

function describeStep(s) {
  const h = (x) => (x || "?").slice(0, 12);
  if (s.kind === "design") {
    const said = s.replanned || s.recovery?.summary || s.refused || "";
    return `design v${s.version} (${s.waiting_for}) · ${s.parts.length} parts${said ? " · " + said : ""}`;
  }
  if (s.kind === "decision") {
    return `${s.at}: ${s.action}${s.skill ? " " + s.skill : ""}${s.reason ? ` "${s.reason}"` : ""}` +
      `${s.edits ? ` (${s.edits.length} edit(s))` : ""} by ${s.by || "?"}`;
  }
  if (s.kind === "record") return `record ${h(s.record_hash)} planned · ${s.steps} steps · makespan ${s.makespan_s} s`;
  if (s.kind === "approval") return `approved record ${h(s.record_hash)} by ${s.by || "?"}`;
  const r = s.report || {};
  return `execution of ${h(s.record_hash)}: ${r.status || "interrupted"} · V_traj ${r.v_traj} · δ ${r.delta_rad} rad (ε ${r.epsilon_rad})`;
}

function recordParts(tl) {
  return tl.steps.map((s) => ({
    id: s.part_id, size: s.size, position: [s.target[0][3], s.target[1][3], s.target[2][3]],
    yaw_deg: Math.atan2(s.target[1][0], s.target[0][0]) * 180 / Math.PI,
  }));
}

async function replayTo(k) {
  const R = T.replay;
  if (!R || k < 0 || k >= R.steps.length) return;
  R.k = k;
  const s = R.steps[k];
  R.design = null;
  for (let i = k; i >= 0; i--) if (R.steps[i].kind === "design") { R.design = R.steps[i]; break; }
  R.layout = R.design ? R.design.parts : null;
  T.placed = {}; T.samples = {}; T.deltaPoints = []; T.execClock = 0; T.toPlace = [];
  T.executing = false;
  if (s.kind === "execution") {
    if (!T.timeline || T.timeline.record_hash !== s.record_hash) {
      T.timeline = await api(`/api/runs/${T.runId}/timeline?record=${s.record_hash}`);
      setupSlider();
    }
    R.layout = recordParts(T.timeline); // exactly the parts of the record executed
    for (const p of s.already_placed || []) placePart(p);
    T.placedAtReplayStart = Object.keys(T.placed).length; // parts come back as the clock runs
    T.replaying = true;
    for (const e of s.events) {
      if (e.type === "samples") addSamples(e.payload);
      else if (e.type === "step_done") T.toPlace.push(e.payload);
    }
  }
  renderExec();
  drawScene();
}

function renderReplay() {
  const R = T.replay;
  if (!R || R.k < 0) return;
  $("replay-step").textContent = `${R.k + 1} / ${R.steps.length}: ${describeStep(R.steps[R.k])}`;
  [...$("replay-steps").children].forEach((li, i) => { li.className = i === R.k ? "current" : ""; });
  $("replay-prev").disabled = R.k <= 0;
  $("replay-next").disabled = R.k >= R.steps.length - 1;
}

// ------------------------------------------------------------------------------ main loop
let last = performance.now();
function frame(now) {
  const dt = Math.min(0.1, (now - last) / 1000);
  last = now;
  if (T.playing && T.timeline) {
    T.clock = Math.min(T.timeline.makespan_s, T.clock + dt * parseFloat($("speed").value));
    if (T.clock >= T.timeline.makespan_s) T.playing = false;
    drawScene();
    renderRecord();
  }
  if (Object.keys(T.samples).length) stepExecution(dt);
  renderer.render(scene3, camera);
  T.frames++;
  requestAnimationFrame(frame);
}

// Screen position of a world point (tests drag parts with the real mouse).
T.screenOf = (p) => {
  const v = new THREE.Vector3(...p).project(camera);
  const rect = renderer.domElement.getBoundingClientRect();
  return [rect.left + (v.x + 1) / 2 * rect.width, rect.top + (1 - v.y) / 2 * rect.height];
};

async function main() {
  T.scene = await api("/api/scene");
  drawFixed(T.scene);
  requestAnimationFrame(frame);
  await refreshRuns();
  const first = location.hash.slice(1) || (T.runs[0] && T.runs[0].run_id);
  if (first) await openRun(first);
  T.ready = true;
  setInterval(refreshRuns, 5000);
  window.addEventListener("hashchange", () => {
    const id = location.hash.slice(1);
    if (id && id !== T.runId) openRun(id);
  });
}
main();

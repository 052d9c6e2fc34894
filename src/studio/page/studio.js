// The studio page (issue 37): the rig in 3D (three.js r111, Debian's libjs-three), a gizmo and
// numeric fields per mount, and the numbers the server computes after every change. Every
// call carries the session's token, read from this page's own address.
'use strict';

const token = new URLSearchParams(location.search).get('token') || '';
const $ = (id) => document.getElementById(id);
const DEG = Math.PI / 180;

const studio = {
  state: null,          // the last /api/state reply
  numbers: null,        // the numbers shown
  selected: null,       // selected mount id
  pivots: new Map(),    // mount id -> Object3D at the mount's pose (the gizmo moves it)
  inFlight: false,      // one pose request at a time while dragging
  queued: null,         // the newest pose waiting for the request in flight
  dragging: false,
  lastLatencyMs: null,  // from a pose change to the redrawn numbers (read by the browser test)
  lastServerMs: null,
  rasterLatenciesMs: [],  // every raster-path update while dragging: change -> numbers drawn
  updates: 0,           // redraws of the numbers so far (the browser test waits on it)
};
window.studio = studio;

async function api(method, name, body) {
  const response = await fetch('/api/' + name, {
    method,
    headers: {'X-Studio-Token': token, 'Content-Type': 'application/json'},
    body: body === undefined ? undefined : JSON.stringify(body),
  });
  const type = response.headers.get('Content-Type') || '';
  const reply = type.startsWith('application/json') ? await response.json() : await response.text();
  if (!response.ok) throw {status: response.status, reply};
  return reply;
}

function showErrors(error) {
  const box = $('errors');
  if (!error) { box.hidden = true; box.textContent = ''; return; }
  const reply = error.reply !== undefined ? error.reply : error;
  let text;
  if (reply && Array.isArray(reply.error)) text = reply.error.map((d) => d.message).join('\n');
  else if (reply && reply.error) text = String(reply.error);
  else text = String(reply && reply.message ? reply.message : reply);
  box.textContent = text;
  box.hidden = false;
}

// ---------------------------------------------------------------- 3D view
const view = {};

function setUpView() {
  const host = $('view3d');
  // No multisampling and per-vertex (Lambert) shading: a frame of the TurtleBot 4 (59k
  // triangles) took 200 ms with them on a machine without a GPU (SwiftShader).
  view.renderer = new THREE.WebGLRenderer({antialias: false, preserveDrawingBuffer: true});
  view.renderer.setPixelRatio(window.devicePixelRatio || 1);
  host.appendChild(view.renderer.domElement);
  view.scene = new THREE.Scene();
  view.scene.background = new THREE.Color(0xf4f6f8);
  view.camera = new THREE.PerspectiveCamera(45, 1, 0.01, 100);
  view.camera.position.set(2.2, 1.8, 2.2);
  view.scene.add(new THREE.HemisphereLight(0xffffff, 0x888888, 0.9));
  const sun = new THREE.DirectionalLight(0xffffff, 0.5);
  sun.position.set(3, 5, 2);
  view.scene.add(sun);
  view.orbit = new THREE.OrbitControls(view.camera, view.renderer.domElement);
  view.gizmo = new THREE.TransformControls(view.camera, view.renderer.domElement);
  view.gizmo.setSize(0.8);
  view.gizmo.addEventListener('dragging-changed', (event) => {
    view.orbit.enabled = !event.value;
    setDragging(event.value);
    if (!event.value && studio.selected) sendPose(studio.selected, true);  // the exact path
  });
  view.gizmo.addEventListener('objectChange', () => {
    if (!studio.selected) return;
    fillFields(poseOfPivot(studio.pivots.get(studio.selected)));
    if (studio.dragging) sendPose(studio.selected, false);  // the raster path while dragging
  });
  view.scene.add(view.gizmo);
  document.querySelectorAll('input[name=gizmo]').forEach((radio) =>
    radio.addEventListener('change', () => view.gizmo.setMode(radio.value)));
  view.orbit.addEventListener('change', requestRender);
  view.gizmo.addEventListener('change', requestRender);
  window.addEventListener('resize', resize);
  resize();
}

// While a mount is dragged the 3D view renders at half resolution (a quarter of the pixels):
// on a machine without a GPU a full frame of the TurtleBot 4 costs more than the numbers do.
function setDragging(on) {
  studio.dragging = on;
  view.renderer.setPixelRatio((window.devicePixelRatio || 1) * (on ? 0.5 : 1));
  resize();
}

// Frames are drawn when something changed, not continuously: the numbers' requests keep the
// processor (a software WebGL one, without a GPU) to themselves while a mount is dragged.
let renderPending = false;
function requestRender() {
  if (renderPending) return;
  renderPending = true;
  requestAnimationFrame(() => {
    renderPending = false;
    view.renderer.render(view.scene, view.camera);
  });
}

function resize() {
  const host = $('view3d');
  const width = host.clientWidth, height = host.clientHeight || 500;
  view.renderer.setSize(width, height);
  view.camera.aspect = width / height;
  view.camera.updateProjectionMatrix();
  requestRender();
}

// The robot frame (REP-103, z up) inside the glTF's root node; pivots hang from it.
function robotFrame() { return view.root; }

function setPivotPose(pivot, xyz, rpyDeg) {
  pivot.position.set(xyz[0], xyz[1], xyz[2]);
  // URDF's rpy: R = Rz(yaw) Ry(pitch) Rx(roll), three.js's Euler order 'ZYX'.
  pivot.rotation.set(rpyDeg[0] * DEG, rpyDeg[1] * DEG, rpyDeg[2] * DEG, 'ZYX');
  pivot.updateMatrix();
  pivot.updateMatrixWorld(true);
  requestRender();
}

function poseOfPivot(pivot) {
  const euler = new THREE.Euler().setFromQuaternion(pivot.quaternion, 'ZYX');
  const round = (v, digits) => Number(v.toFixed(digits));
  return {
    xyz: [round(pivot.position.x, 4), round(pivot.position.y, 4), round(pivot.position.z, 4)],
    rpy_deg: [round(euler.x / DEG, 2), round(euler.y / DEG, 2), round(euler.z / DEG, 2)],
  };
}

async function loadScene() {
  if (view.gltfRoot) view.scene.remove(view.gltfRoot);
  view.gizmo.detach();
  studio.pivots.clear();
  const text = await api('GET', 'scene.gltf');
  const gltf = await new Promise((resolve, reject) =>
    new THREE.GLTFLoader().parse(typeof text === 'string' ? text : JSON.stringify(text), '', resolve, reject));
  view.gltfRoot = gltf.scene;
  view.gltfRoot.traverse((node) => {
    if (!node.isMesh) return;
    // Lambert shades per vertex: the file has no normals (three.js shaded it flat).
    if (!node.geometry.attributes.normal) node.geometry.computeVertexNormals();
    const pbr = node.material;
    node.material = new THREE.MeshLambertMaterial({
      color: pbr.color, transparent: pbr.transparent, opacity: pbr.opacity,
      depthWrite: !pbr.transparent, side: pbr.side});
    pbr.dispose();
  });
  view.scene.add(view.gltfRoot);
  view.root = gltf.scene.children[0];  // the base link's node: its children are in the robot frame
  view.gltfRoot.updateMatrixWorld(true);
  addAreaToPerceive();
  // The whole area to perceive in view: the camera d * 1.6 away, looking down on the robot.
  const d = studio.state.rig.distance_m;
  view.camera.position.set(1.1 * d, 1.0 * d, 1.1 * d);
  view.orbit.target.set(0, 0, 0);
  view.orbit.update();
  for (const mount of studio.state.numbers.mounts) attachPivot(mount);
  requestRender();
}

// Each mount's FOV volume hangs from a pivot at the mount's pose, so the gizmo carries it.
function attachPivot(mount) {
  const pivot = new THREE.Object3D();
  pivot.name = 'pivot:' + mount.id;
  robotFrame().add(pivot);
  setPivotPose(pivot, mount.xyz, mount.rpy_deg);
  const volume = robotFrame().getObjectByName(mount.id);
  if (volume) {
    robotFrame().remove(volume);
    const holder = new THREE.Object3D();  // the robot frame as seen from the pivot
    holder.matrixAutoUpdate = false;
    holder.matrix.getInverse(pivot.matrix);
    holder.add(volume);
    pivot.add(holder);
    pivot.userData.holder = holder;
  }
  const axes = new THREE.AxesHelper(0.12);
  pivot.add(axes);
  studio.pivots.set(mount.id, pivot);
}

function addAreaToPerceive() {
  const rig = studio.state.rig;
  const ring = new THREE.Mesh(
    new THREE.RingGeometry(rig.body_radius_m, rig.distance_m, 96),
    new THREE.MeshBasicMaterial({color: 0x3070c0, transparent: true, opacity: 0.08, side: THREE.DoubleSide}));
  robotFrame().add(ring);  // the floor: z = 0 in the robot frame
  const fence = new THREE.Mesh(
    new THREE.CylinderGeometry(rig.distance_m, rig.distance_m, rig.area_top_m, 96, 1, true),
    new THREE.MeshBasicMaterial({color: 0x3070c0, wireframe: true, transparent: true, opacity: 0.15}));
  fence.rotation.x = Math.PI / 2;  // the cylinder's axis along z
  fence.position.z = rig.area_top_m / 2;
  robotFrame().add(fence);
}

// After the exact path: the moved mount's volume cut by the body again, from the server.
async function refreshVolume(mountId) {
  const pivot = studio.pivots.get(mountId);
  if (!pivot) return;
  const fov = await api('GET', 'fov?mount=' + encodeURIComponent(mountId));
  let volume = pivot.userData.holder ? pivot.userData.holder.children[0] : null;
  const geometry = new THREE.BufferGeometry();
  geometry.setAttribute('position', new THREE.Float32BufferAttribute(fov.positions, 3));
  geometry.setIndex(fov.indices);
  geometry.computeVertexNormals();
  if (!volume) {
    volume = new THREE.Mesh(geometry, new THREE.MeshLambertMaterial(
      {color: 0x2a9d8f, transparent: true, opacity: 0.35, depthWrite: false}));
    volume.name = mountId;
    pivot.userData.holder = new THREE.Object3D();
    pivot.userData.holder.matrixAutoUpdate = false;
    pivot.userData.holder.add(volume);
    pivot.add(pivot.userData.holder);
  } else {
    volume.geometry.dispose();
    volume.geometry = geometry;
    volume.position.set(0, 0, 0);
    volume.quaternion.set(0, 0, 0, 1);
    volume.scale.set(1, 1, 1);
  }
  showHousing(pivot, fov);
  pivot.updateMatrix();
  pivot.userData.holder.matrix.getInverse(pivot.matrix);
  requestRender();
}

// The mount's datasheet housing beside its volume (robot frame, like the volume): grey, or
// red while it cuts into the body or another housing, with check's reason under the panel.
function showHousing(pivot, fov) {
  const holder = pivot.userData.holder;
  let housing = holder.children.find((child) => child.name === 'housing');
  if (housing) { holder.remove(housing); housing.geometry.dispose(); }
  studio.clashes = studio.clashes || new Map();
  studio.clashes.delete(fov.mount);
  if (fov.housing) {
    const geometry = new THREE.BufferGeometry();
    geometry.setAttribute('position', new THREE.Float32BufferAttribute(fov.housing.positions, 3));
    geometry.setIndex(fov.housing.indices);
    geometry.computeVertexNormals();
    housing = new THREE.Mesh(geometry, new THREE.MeshLambertMaterial(
      {color: fov.clash ? 0xd62828 : 0x707070}));
    housing.name = 'housing';
    holder.add(housing);
    if (fov.clash) studio.clashes.set(fov.mount, fov.clash);
  }
  const box = $('clash');
  box.textContent = [...studio.clashes.values()].join('\n');
  box.hidden = studio.clashes.size === 0;
}

// A pose reply's B2 verdict for the moved mount, live while it is dragged: its housing turns
// red (or back to grey) and the reason shows under the panel.
function showClash(mountId, text) {
  studio.clashes = studio.clashes || new Map();
  if (text) studio.clashes.set(mountId, text); else studio.clashes.delete(mountId);
  const pivot = studio.pivots.get(mountId);
  const housing = pivot && pivot.userData.holder.children.find((child) => child.name === 'housing');
  if (housing) { housing.material.color.setHex(text ? 0xd62828 : 0x707070); requestRender(); }
  const box = $('clash');
  box.textContent = [...studio.clashes.values()].join('\n');
  box.hidden = studio.clashes.size === 0;
}

// Where a mount's move arrow along x can be gripped on screen (viewport pixels) and the
// screen direction of +x there: for automation (the browser test drags it). The picker of
// TransformControls r111 spans 0.1 to 1.1 of the gizmo's size along the axis, in world axes
// (robot x is world x: the root turns about x only).
window.studioGrip = function (mountId) {
  const pivot = studio.pivots.get(mountId);
  const origin = new THREE.Vector3().setFromMatrixPosition(pivot.matrixWorld);
  const camera = view.camera;
  const size = origin.distanceTo(camera.position) *
    Math.min(1.9 * Math.tan(Math.PI * camera.fov / 360) / camera.zoom, 7) * view.gizmo.size / 7;
  const rect = view.renderer.domElement.getBoundingClientRect();
  const screen = (offset) => {
    const p = origin.clone().add(new THREE.Vector3(offset * size, 0, 0)).project(camera);
    return [rect.left + (p.x + 1) / 2 * rect.width, rect.top + (1 - p.y) / 2 * rect.height];
  };
  const grip = screen(0.6), further = screen(1.0);
  const length = Math.hypot(further[0] - grip[0], further[1] - grip[1]) || 1;
  return {grip, direction: [(further[0] - grip[0]) / length, (further[1] - grip[1]) / length]};
};

// ---------------------------------------------------------------- edits
function fieldsPose() {
  const n = (id) => Number($(id).value);
  return {xyz: [n('x'), n('y'), n('z')], rpy_deg: [n('roll'), n('pitch'), n('yaw')]};
}

// Shown to a micrometre and a microdegree: a pose read back from a rotation matrix carries
// noise in its last digits (-19.999999999999996), which the fields would send back on a change.
function fillFields(pose) {
  const shown = (v) => Number(v.toFixed(6));
  ['x', 'y', 'z'].forEach((id, i) => { $(id).value = shown(pose.xyz[i]); });
  ['roll', 'pitch', 'yaw'].forEach((id, i) => { $(id).value = shown(pose.rpy_deg[i]); });
}

// Pose changes: while dragging only the newest waits, so the numbers follow the gizmo.
function sendPose(mountId, exact, pose) {
  const request = {mount: mountId, exact, started: performance.now(),
                   pose: pose || poseOfPivot(studio.pivots.get(mountId))};
  if (studio.inFlight) { studio.queued = request; return; }
  runPose(request);
}

async function runPose(request) {
  studio.inFlight = true;
  try {
    const numbers = await api('POST', 'pose',
      {mount: request.mount, xyz: request.pose.xyz, rpy_deg: request.pose.rpy_deg, exact: request.exact});
    showErrors(null);
    showNumbers(numbers);
    if (numbers.clash) showClash(numbers.clash.mount, numbers.clash.text);
    studio.lastServerMs = numbers.seconds * 1000;
    studio.lastLatencyMs = performance.now() - request.started;
    if (!request.exact) studio.rasterLatenciesMs.push(studio.lastLatencyMs);
    if (request.exact) await refreshVolume(request.mount);
  } catch (error) {
    showErrors(error);
    restorePivots();  // refused: back to the last valid pose
  } finally {
    studio.inFlight = false;
    const next = studio.queued;
    studio.queued = null;
    if (next) runPose(next);
  }
}

function restorePivots() {
  if (!studio.numbers) return;
  for (const mount of studio.numbers.mounts) {
    const pivot = studio.pivots.get(mount.id);
    if (pivot) setPivotPose(pivot, mount.xyz, mount.rpy_deg);
    if (mount.id === studio.selected) fillFields(mount);
  }
}

function onFieldChange() {
  if (!studio.selected) return;
  const pose = fieldsPose();
  setPivotPose(studio.pivots.get(studio.selected), pose.xyz, pose.rpy_deg);
  sendPose(studio.selected, true, pose);
}

async function select(mountId) {
  studio.selected = mountId;
  const mount = studio.numbers.mounts.find((m) => m.id === mountId);
  if (!mount) { view.gizmo.detach(); return; }
  $('mounts').value = mountId;
  fillFields(mount);
  view.gizmo.attach(studio.pivots.get(mountId));
  $('link-note').hidden = !mount.urdf_link;
  $('link-note').textContent = mount.urdf_link
    ? 'Placed by the description\'s link ' + mount.urdf_link + '. Moved here, it is saved as xyz and rpy_deg: move the link in the description too.'
    : '';
  await fillSensors(mount.sensor, mount.mode);
}

// The sensor list through `rigdesign sensors`' own filters (the server applies them); the
// selected mount's sensor stays in the list even when the filters leave it out.
let sensorQuery = 0;
async function fillSensors(sensorId, modeId) {
  const params = new URLSearchParams();
  const add = (key, id) => { const v = $(id).value.trim(); if (v) params.set(key, v); };
  add('search', 'sensor-filter');
  add('technology', 'filter-technology');
  add('min_range', 'filter-range');
  add('min_rate', 'filter-rate');
  add('min_fov_deg', 'filter-fov');
  add('max_price', 'filter-price');
  const query = ++sensorQuery;
  let found;
  try { found = (await api('GET', 'sensors?' + params.toString())).sensors; } catch (error) { showErrors(error); return; }
  if (query !== sensorQuery) return;  // a newer filter's answer is coming
  studio.matching = new Map(found.map((s) => [s.id, s.modes]));
  const sensorSelect = $('sensor');
  sensorSelect.innerHTML = '';
  const listed = found.map((s) => s.id);
  if (sensorId && !listed.includes(sensorId)) listed.unshift(sensorId);
  for (const id of listed) {
    const s = studio.state.sensors.find((x) => x.id === id);
    const note = studio.matching.has(id) ? '' : ', filtered out';
    sensorSelect.add(new Option(id + ' (' + s.technology + ', ' + s.price_usd + ' USD' + note + ')', id));
  }
  $('filter-count').textContent = found.length + ' of ' + studio.state.sensors.length + ' sensors match';
  if (sensorId) sensorSelect.value = sensorId;
  fillModes(modeId);
}

function fillModes(modeId) {
  const sensor = studio.state.sensors.find((s) => s.id === $('sensor').value);
  const modeSelect = $('mode');
  modeSelect.innerHTML = '';
  if (!sensor) return;
  const modes = (studio.matching && studio.matching.get(sensor.id)) || sensor.modes;
  for (const m of modes) modeSelect.add(new Option(m, m));
  if (modeId && sensor.modes.includes(modeId)) {
    if (!modes.includes(modeId)) modeSelect.add(new Option(modeId + ' (filtered out)', modeId));
    modeSelect.value = modeId;
  }
}

async function edit(name, body) {
  try {
    const reply = await api('POST', name, body);
    showErrors(null);
    return reply;
  } catch (error) {
    showErrors(error);
    return null;
  }
}

async function applySensor() {
  if (!studio.selected) return;
  const numbers = await edit('sensor', {mount: studio.selected, sensor: $('sensor').value, mode: $('mode').value});
  if (numbers) { showNumbers(numbers); await refreshVolume(studio.selected); }
}

async function addMount() {
  const pose = fieldsPose();
  const state = await edit('add', {sensor: $('sensor').value, mode: $('mode').value, xyz: pose.xyz, rpy_deg: pose.rpy_deg});
  if (state) { await showState(state); await select(state.added); }
}

async function removeMount() {
  if (!studio.selected) return;
  const state = await edit('remove', {mount: studio.selected});
  if (state) { studio.selected = null; await showState(state); }
}

async function save() {
  const state = await edit('save', {});
  if (!state) return;
  await showState(state);  // keeps the selected mount
  // Last, once the page shows the saved rig: what waits for the report sees it settled.
  $('check').textContent = 'check exit code ' + state.check.exit_code + '\n' + state.check.report;
}

async function reload() {
  const state = await edit('reload', {});
  if (state) { studio.selected = null; await showState(state); }
}

// ---------------------------------------------------------------- numbers
function percent(v) { return v === null || v === undefined ? '-' : (100 * v).toFixed(1) + ' %'; }

// As `metrics` prints them: ray spacing R and noise N in millimetres, other lengths in metres.
function formatValue(value, unit, metric) {
  if (value === null || value === undefined) return '-';
  if (unit === 'm' && (metric === 'R' || metric === 'N')) return (value * 1000).toFixed(1) + ' mm';
  if (unit === '') return percent(value);
  return Number(value.toPrecision(4)) + ' ' + unit;
}

function showNumbers(numbers) {
  studio.numbers = numbers;
  $('path').textContent = (numbers.exact ? 'exact path' : 'raster path') + ', ' +
    (numbers.seconds * 1000).toFixed(1) + ' ms on the server';
  $('dirty').textContent = numbers.dirty ? 'unsaved edits' : '';
  $('save').disabled = !numbers.dirty;
  drawCurves(numbers);
  drawVerdicts(numbers);
  drawResultant(numbers);
  // The list is rebuilt only when a mount's name, sensor or mode changed (not on a move).
  const labels = numbers.mounts.map((m) => m.id + ': ' + m.sensor + ' / ' + m.mode);
  const list = $('mounts');
  if (labels.join('\n') !== Array.from(list.options).map((o) => o.text).join('\n')) {
    const keep = studio.selected;
    list.innerHTML = '';
    numbers.mounts.forEach((m, i) => list.add(new Option(labels[i], m.id)));
    if (keep) list.value = keep;
  }
  studio.updates += 1;
  if (!studio.dragging) loadSection();
}

// SC complete and floor against the azimuth, forward in the middle, with the sectors'
// required levels drawn over their spans.
function drawCurves(numbers) {
  const canvas = $('curves'), g = canvas.getContext('2d');
  const W = canvas.width, H = canvas.height, left = 40, right = 10, top = 10, bottom = 28;
  const x = (deg) => left + ((((deg + 180) % 360) + 360) % 360) / 360 * (W - left - right);
  const y = (share) => top + (1 - share) * (H - top - bottom);
  g.clearRect(0, 0, W, H);
  g.font = '11px sans-serif';
  g.strokeStyle = '#ccc'; g.fillStyle = '#555';
  for (let s = 0; s <= 1.0001; s += 0.25) {
    g.beginPath(); g.moveTo(left, y(s)); g.lineTo(W - right, y(s)); g.stroke();
    g.fillText((s * 100).toFixed(0) + '%', 4, y(s) + 4);
  }
  for (let d = -180; d <= 180; d += 45) g.fillText(String(d), x(d === 180 ? 179.99 : d) - 8, H - 10);
  g.fillText('azimuth [deg], 0 = forward, + = left', W / 2 - 90, H - 0);
  // A sector as at most two spans on the axis (it may wrap past 180 degrees); each span one
  // rectangle and one path per required level: a few draw calls however wide the sector.
  const spans = (from, to) => {
    const start = ((((from + 180) % 360) + 360) % 360) - 180, end = start + (to - from);
    return end <= 180 ? [[start, end]] : [[start, 180], [-180, end - 360]];
  };
  const px = (deg) => left + (deg + 180) / 360 * (W - left - right);
  const bounds = numbers.sector_bounds || [];
  numbers.coverage.sectors.forEach((sector, i) => {
    const b = bounds[i];
    if (!b) return;
    g.fillStyle = sector.pass ? 'rgba(40,160,60,0.10)' : 'rgba(200,30,30,0.12)';
    for (const [from, to] of spans(b.from_deg, b.to_deg)) {
      g.fillRect(px(from), top, px(to) - px(from), H - top - bottom);
      g.setLineDash([4, 3]);
      for (const [share, colour] of [[sector.required_complete, '#1f4e9c'], [sector.required_floor, '#c05a00']]) {
        g.strokeStyle = colour;
        g.beginPath(); g.moveTo(px(from), y(share)); g.lineTo(px(to), y(share)); g.stroke();
      }
      g.setLineDash([]);
    }
  });
  const thetas = numbers.coverage.curve_theta_deg;
  const curve = (key, colour) => {
    g.strokeStyle = colour; g.lineWidth = 1.5;
    const values = numbers.coverage[key];
    const points = thetas.map((theta, i) => [((theta + 180) % 360) - 180, values[i]]).sort((a, b) => a[0] - b[0]);
    g.beginPath();
    points.forEach(([deg, share], i) => { if (i === 0) g.moveTo(x(deg), y(share)); else g.lineTo(x(deg), y(share)); });
    g.stroke(); g.lineWidth = 1;
  };
  curve('curve_complete', '#1f4e9c');
  curve('curve_floor', '#c05a00');
  g.fillStyle = '#1f4e9c'; g.fillText('SC complete', left + 6, top + 12);
  g.fillStyle = '#c05a00'; g.fillText('SC floor', left + 90, top + 12);
}

function drawVerdicts(numbers) {
  const body = $('verdicts').tBodies[0];
  body.innerHTML = '';
  for (const r of numbers.requirements) {
    const row = body.insertRow();
    row.dataset.id = r.id;
    const cells = [r.id, r.title, r.verdict, formatValue(r.actual, r.unit, r.metric),
                   formatValue(r.required, r.unit, r.metric),
                   r.margin === null ? '-' : formatValue(r.margin, r.unit, r.metric), (r.limiting_mounts || []).join(', ')];
    cells.forEach((text, i) => {
      const cell = row.insertCell();
      cell.textContent = text;
      if (i === 2) cell.className = r.verdict === 'pass' ? 'pass' : r.verdict === 'fail' ? 'fail' : '';
    });
    row.title = r.explanation;
  }
}

function drawResultant(numbers) {
  const res = numbers.metrics.resultant;
  const light = Object.entries(res.L).map(([k, v]) => k + ' ' + (v.immune ? 'yes' : 'no (' + v.failing_mounts.join(', ') + ')')).join('; ');
  $('resultant').innerHTML = '';
  const lines = [
    'F = ' + Number(res.F.value.toPrecision(4)) + ' Hz (slowest: ' + res.F.limiting_mounts.join(', ') + ')',
    'R = ' + (res.R.value * 1000).toFixed(1) + ' mm (coarsest: ' + res.R.limiting_mounts.join(', ') + ')',
    'N = ' + (res.N.value * 1000).toFixed(1) + ' mm (noisiest: ' + res.N.limiting_mounts.join(', ') + ')',
    'L: ' + light,
    'C_s = ' + res.sensor_cost_usd.toFixed(0) + ' USD, B = ' + (res.bandwidth_bytes_per_s / 1e6).toFixed(2) +
      ' MB/s, U_p = ' + res.driver_cpu_cores.toFixed(2) + ' cores',
  ];
  for (const line of lines) { const div = document.createElement('div'); div.textContent = line; $('resultant').appendChild(div); }
}

async function loadSection() {
  const azimuth = Number($('azimuth').value);
  $('azimuth-value').textContent = azimuth;
  let section;
  try { section = await api('GET', 'section?theta_deg=' + azimuth); } catch (error) { return; }
  const canvas = $('section'), g = canvas.getContext('2d');
  const W = canvas.width, H = canvas.height, pad = 20;
  const span = Math.max(section.d_m, 0.1), top = Math.max(section.h_m * 1.6, 0.3);
  const scale = Math.min((W - 2 * pad) / span, (H - 2 * pad) / top);
  const px = (rho) => pad + rho * scale, py = (z) => H - pad - z * scale;
  g.clearRect(0, 0, W, H);
  g.fillStyle = 'rgba(60,60,60,0.25)';
  g.fillRect(px(0), py(section.h_m), section.r_m * scale, section.h_m * scale);  // the body
  g.strokeStyle = '#3070c0';
  g.strokeRect(px(section.r_m), py(section.h_m), (section.d_m - section.r_m) * scale, section.h_m * scale);
  const colours = ['#2a9d8f', '#e76f51', '#8e44ad', '#f4a261', '#264653', '#e9c46a'];
  section.mounts.forEach((mount, i) => {
    g.fillStyle = colours[i % colours.length] + '66';
    for (const polygon of mount.polygons) {
      g.beginPath();
      polygon.forEach(([rho, z], k) => { if (k === 0) g.moveTo(px(rho), py(z)); else g.lineTo(px(rho), py(z)); });
      g.closePath(); g.fill();
    }
    g.fillStyle = colours[i % colours.length];
    for (const [low, high] of mount.floor) g.fillRect(px(low), py(0) + 2 + 3 * i, (high - low) * scale, 3);
    g.fillText(mount.id, W - 110, 14 + 12 * i);
  });
  g.fillStyle = '#222';
  g.fillText('SC complete ' + percent(section.complete) + ', floor ' + percent(section.floor) + ' at ' + azimuth + ' deg', pad, 12);
}

// ---------------------------------------------------------------- start
async function showState(state) {
  studio.state = state;
  $('rig-file').textContent = state.rig_file;
  if (!state.loaded) {
    showErrors({error: state.diagnostics});
    $('rig-name').textContent = '(the rig did not load: mend the file, then Reload)';
    return;
  }
  $('rig-name').textContent = state.rig.name;
  const technologies = $('filter-technology');
  if (technologies.options.length === 1) {
    for (const t of [...new Set(state.sensors.map((s) => s.technology))].sort()) technologies.add(new Option(t, t));
  }
  showNumbers(state.numbers);
  await fillSensors(null, null);
  await loadScene();
  const keep = state.numbers.mounts.find((m) => m.id === studio.selected);
  if (keep) await select(keep.id);
  else if (state.numbers.mounts.length) await select(state.numbers.mounts[0].id);
}

async function start() {
  setUpView();
  ['x', 'y', 'z', 'roll', 'pitch', 'yaw'].forEach((id) => $(id).addEventListener('change', onFieldChange));
  $('mounts').addEventListener('change', () => select($('mounts').value));
  $('sensor').addEventListener('change', () => fillModes(null));
  for (const id of ['sensor-filter', 'filter-technology', 'filter-range', 'filter-rate', 'filter-fov', 'filter-price'])
    $(id).addEventListener('input', () => fillSensors($('sensor').value, $('mode').value));
  $('apply-sensor').addEventListener('click', applySensor);
  $('add-mount').addEventListener('click', addMount);
  $('remove-mount').addEventListener('click', removeMount);
  $('save').addEventListener('click', save);
  $('reload').addEventListener('click', reload);
  $('azimuth').addEventListener('input', loadSection);
  try {
    await showState(await api('GET', 'state'));
    $('status').textContent = 'ready';
  } catch (error) {
    showErrors(error);
  }
}

start();

// The page of `silva view`: a free camera over the world Silva renders, frames fetched one at a
// time (half resolution while moving, full when still), the menu's config edits, capture and map.
'use strict';

const $ = (id) => document.getElementById(id);
const canvas = $('view');
const ctx2d = canvas.getContext('2d');

// What tests and the console can read.
const silva = window.silva = {
  pose: { x: 0, y: 0, z: 0, yaw: 0, pitch: 0 },
  walk: true, view: 'rgb', ground: 0, generation: -1, framesDrawn: 0, fullFrames: 0,
  lastError: '', lastCapture: null, state: null, follow: null, placed: null,
};

// The launch token silva view printed in the URL (kept for reloads of this tab): the server accepts settings
// changes and captures only with it, so no other web page can make them.
const token = new URLSearchParams(location.search).get('token') || sessionStorage.getItem('silva-token') || '';
sessionStorage.setItem('silva-token', token);
const postHeaders = { 'Content-Type': 'application/json', 'X-Silva-Token': token };

const keys = new Set();
let config = null;          // the world's config (from /state)
let overrides = [];         // the page's own `key=value` list (free keys)
let inFlight = false;
let shownKey = '';          // what the canvas shows: pose + view + size
let lastMove = 0;           // time of the last pose change (ms)
let frameTimes = [];

function poseKey(p) {
  return [p.x, p.y, silva.walk ? 'w' : p.z, p.yaw, p.pitch].map((v) => (typeof v === 'number' ? v.toFixed(3) : v)).join(',');
}

// ---- frames ---------------------------------------------------------------------------------
// What a frame of the current pose and view at width `w` shows.
const frameKey = (w) => poseKey(silva.pose) + '|' + silva.view + '|' + w + '|' + silva.generation;
// Whether the canvas shows the full frame of this very pose and view, read live (a view or pose
// changed a moment ago is never 'still' on the old picture).
Object.defineProperty(silva, 'still', { get: () => shownKey === frameKey(canvas.width) });

async function requestFrame() {
  if (inFlight || !silva.state) return;
  const moving = performance.now() - lastMove < 250;
  const full = !moving;
  const w = full ? canvas.width : canvas.width / 2, h = full ? canvas.height : canvas.height / 2;
  const key = frameKey(w);
  if (key === shownKey) return;
  const p = silva.pose;
  const q = new URLSearchParams({ x: p.x, y: p.y, z: p.z, yaw: p.yaw, pitch: p.pitch, walk: silva.walk ? 1 : 0,
    view: silva.view, w, h });
  if (silva.walk && silva.placed) { q.set('fx', silva.placed.x); q.set('fy', silva.placed.y); }  // collide with solids
  inFlight = true;
  try {
    const res = await fetch('frame?' + q);
    if (res.status === 503) { await sleep(50); return; }          // dropped: the server is busy
    if (!res.ok) { showError((await res.json()).error); return; }
    const placed = JSON.parse(res.headers.get('X-Silva-Pose'));
    const bitmap = await createImageBitmap(await res.blob());
    ctx2d.drawImage(bitmap, 0, 0, canvas.width, canvas.height);
    silva.framesDrawn++;
    if (full) silva.fullFrames++;
    if (silva.walk) silva.pose.z = placed.z;
    if (placed.blocked) { silva.pose.x = placed.x; silva.pose.y = placed.y; }
    silva.placed = placed;
    silva.ground = placed.ground;
    if (placed.generation !== silva.generation) { silva.generation = placed.generation; refreshState(); }
    shownKey = key.slice(0, key.lastIndexOf('|') + 1) + placed.generation;
    frameTimes.push(performance.now());
    frameTimes = frameTimes.filter((t) => t > performance.now() - 2000);
    $('fps').textContent = (frameTimes.length / 2).toFixed(1) + ' frames/s, ' + placed.ms.toFixed(0) + ' ms';
    drawMap();
  } catch (e) {
    await sleep(200);                                              // server restarting or gone
  } finally {
    inFlight = false;
  }
}

const sleep = (ms) => new Promise((r) => setTimeout(r, ms));

// ---- movement -------------------------------------------------------------------------------
let lastTick = performance.now();
function tick(now) {
  const dt = Math.min(0.1, (now - lastTick) / 1000);
  lastTick = now;
  const p = silva.pose;
  const speed = (silva.walk ? 3 : 15) * (keys.has('shift') ? 4 : 1);
  const yaw = p.yaw * Math.PI / 180;
  let fwd = 0, left = 0, up = 0;
  if (keys.has('w')) fwd += 1;
  if (keys.has('s')) fwd -= 1;
  if (keys.has('a')) left += 1;
  if (keys.has('d')) left -= 1;
  if (keys.has('e')) up += 1;
  if (keys.has('q')) up -= 1;
  if (fwd || left || (up && !silva.walk)) {
    silva.follow = null;
    p.x += (Math.cos(yaw) * fwd - Math.sin(yaw) * left) * speed * dt;
    p.y += (Math.sin(yaw) * fwd + Math.cos(yaw) * left) * speed * dt;
    if (!silva.walk) p.z += up * speed * dt;
    lastMove = now;
  }
  if (silva.follow) followTrail(dt, now);
  requestFrame();
  requestAnimationFrame(tick);
}

// Autopilot preview: walk the trail's centre line at 1.4 m/s, looking along it.
function followTrail(dt, now) {
  const f = silva.follow;
  f.s = Math.min(f.s + 1.4 * dt * (keys.has('shift') ? 4 : 1), f.points.length - 1);
  const i = Math.floor(f.s), t = f.s - i, a = f.points[i], b = f.points[Math.min(i + 1, f.points.length - 1)];
  silva.pose.x = a[0] + (b[0] - a[0]) * t;
  silva.pose.y = a[1] + (b[1] - a[1]) * t;
  silva.pose.yaw = a[3];
  silva.pose.pitch = 0;
  lastMove = now;
  if (f.s >= f.points.length - 1) silva.follow = null;
}

function moved() { lastMove = performance.now(); }

canvas.addEventListener('keydown', (e) => {
  const k = e.key.toLowerCase();
  if (e.repeat) return;
  if ('wasdqe'.includes(k) || k === 'shift') keys.add(k);
  else if (k === 'f') setWalk(!silva.walk);
  else if (k === 't') aerial();
  else if (k === 'p') follow();
  else if (k === 'c') capture();
  else if ('12345'.includes(k)) setView(['rgb', 'semantic', 'instance', 'depth', 'normal'][+k - 1]);
  else return;
  e.preventDefault();
});
canvas.addEventListener('keyup', (e) => keys.delete(e.key.toLowerCase()));
canvas.addEventListener('blur', () => keys.clear());

let drag = null;
canvas.addEventListener('mousedown', (e) => { drag = { x: e.clientX, y: e.clientY }; canvas.focus(); });
window.addEventListener('mouseup', () => { drag = null; });
canvas.addEventListener('mousemove', (e) => {
  if (drag) {
    silva.pose.yaw -= (e.clientX - drag.x) * 0.2;
    silva.pose.pitch = Math.max(-89, Math.min(89, silva.pose.pitch - (e.clientY - drag.y) * 0.2));
    drag = { x: e.clientX, y: e.clientY };
    silva.follow = null;
    moved();
  } else {
    probe(e);
  }
});
canvas.addEventListener('mouseleave', () => { $('overlay').style.display = 'none'; });

// ---- overlay: class, instance and depth under the cursor --------------------------------------
let probing = false;
async function probe(e) {
  if (probing || !silva.still) return;
  probing = true;
  const r = canvas.getBoundingClientRect();
  const u = (e.clientX - r.left) / r.width, v = (e.clientY - r.top) / r.height;
  try {
    const info = await (await fetch('probe?' + new URLSearchParams({ u, v }))).json();
    const o = $('overlay');
    o.textContent = info.hit ? `${info.class} (id ${info.class_id})\ninstance ${info.instance_id || '—'}\n` +
      `depth ${info.depth_m.toFixed(2)} m` : 'sky';
    o.style.left = (e.clientX - r.left + 14) + 'px';
    o.style.top = (e.clientY - r.top + 14) + 'px';
    o.style.display = 'block';
  } catch (err) { /* the overlay waits for the next move */ }
  probing = false;
}

// ---- modes ---------------------------------------------------------------------------------
function setView(v) {
  silva.view = v;
  document.querySelectorAll('#views button').forEach((b) => b.classList.toggle('on', b.dataset.view === v));
}
document.querySelectorAll('#views button').forEach((b) => b.addEventListener('click', () => setView(b.dataset.view)));

function setWalk(walk) {
  silva.walk = walk;
  if (walk) silva.pose.pitch = Math.max(-60, Math.min(60, silva.pose.pitch));
  $('walk').textContent = walk ? 'Walk' : 'Fly';
  moved();
}
$('walk').addEventListener('click', () => setWalk(!silva.walk));

// Height (m) of the canopy the aerial view flies over: captures measure camera.aerial_height from the
// crowns under the camera; the page, which does not know them, from a mature stand's top.
const kViewCanopyTop = 30;

function aerial() {
  if (!config) return;
  const high = !silva.walk && silva.pose.z > silva.ground + kViewCanopyTop / 2;
  if (high) { setWalk(true); silva.pose.pitch = 0; return; }
  setWalk(false);
  silva.pose.z = silva.ground + kViewCanopyTop + config.camera.aerial_height;
  silva.pose.pitch = config.camera.aerial_pitch_deg;
  moved();
}
$('aerial').addEventListener('click', aerial);

async function follow() {
  if (silva.follow) { silva.follow = null; return; }
  const points = await (await fetch('trail')).json();
  if (!points.length) { showError('no trail to follow (trail.enabled = false)'); return; }
  // Start at the trail point nearest the camera.
  let best = 0;
  points.forEach((q, i) => {
    const d = (q[0] - silva.pose.x) ** 2 + (q[1] - silva.pose.y) ** 2;
    if (d < (points[best][0] - silva.pose.x) ** 2 + (points[best][1] - silva.pose.y) ** 2) best = i;
  });
  setWalk(true);
  silva.follow = { points, s: best };
}
$('follow').addEventListener('click', follow);

// ---- capture and export -----------------------------------------------------------------------
async function capture() {
  const p = silva.pose;
  const res = await fetch('capture', { method: 'POST', headers: postHeaders,
    body: JSON.stringify({ x: p.x, y: p.y, z: p.z, yaw: p.yaw, pitch: p.pitch, walk: silva.walk }) });
  const body = await res.json();
  if (!res.ok) { showError(body.error); return; }
  silva.lastCapture = body;
  $('captured').textContent = `frame ${body.frame} → ${body.camera_file}`;
}
$('capture').addEventListener('click', capture);

// ---- the menu: config edits --------------------------------------------------------------------
function showError(text) {
  silva.lastError = text || '';
  $('error').textContent = silva.lastError;
}

// The menu's keys, every one: the world after Apply is the command's config plus exactly what the page shows.
function menuOverrides() {
  const list = [];
  if (!config) return list;
  const value = (id, key) => { const v = $(id).value; if (v !== '') list.push(`${key}=${v}`); };
  value('density', 'vegetation.density');
  value('elevation', 'terrain.max_elevation');
  list.push(`trail.enabled=${$('trail').checked}`, `vegetation.ground=${$('ground').checked}`);
  value('time', 'lighting.time_of_day');
  value('weather', 'lighting.weather');
  return list;
}

function renderOverrides() {
  const ul = $('overrides');
  ul.replaceChildren(...overrides.map((o, i) => {
    const li = document.createElement('li');
    li.textContent = o;
    li.title = 'click to remove';
    li.addEventListener('click', () => { overrides.splice(i, 1); renderOverrides(); });
    return li;
  }));
}

$('key-add').addEventListener('click', () => {
  const v = $('key').value.trim();
  if (v) { overrides.push(v); $('key').value = ''; renderOverrides(); }
});

async function apply() {
  const all = [...overrides, ...menuOverrides()];
  const pending = $('key').value.trim();
  if (pending) all.push(pending);
  const res = await fetch('config', { method: 'POST', headers: postHeaders,
    body: JSON.stringify({ seed: $('seed').value.trim(), overrides: all }) });
  if (!res.ok) { showError((await res.json()).error); return; }
  showError('');
  if (pending) { overrides.push(pending); $('key').value = ''; renderOverrides(); }
  refreshState();
}
const menuKeys = ['vegetation.density', 'terrain.max_elevation', 'trail.enabled', 'vegetation.ground',
  'lighting.time_of_day', 'lighting.weather'];
const isMenuKey = (o) => menuKeys.includes(o.split('=')[0]);
$('apply').addEventListener('click', apply);
$('seed').addEventListener('keydown', (e) => { if (e.key === 'Enter') apply(); });
$('seed-random').addEventListener('click', () => { $('seed').value = String(Math.floor(Math.random() * 1e10)); apply(); });
$('seed-copy').addEventListener('click', () => navigator.clipboard && navigator.clipboard.writeText($('seed').value));

// ---- state polling ------------------------------------------------------------------------------
let firstState = true;
let menuGeneration = -1;   // the world whose config the menu fields show
async function refreshState() {
  try {
    const s = await (await fetch('state')).json();
    silva.state = s;
    config = s.config;
    $('status').textContent = s.building ? 'building the world…' : `seed ${s.seed}`;
    if (s.error) showError(s.error);
    if (firstState) {
      firstState = false;
      silva.pose.x = s.start.x; silva.pose.y = s.start.y; silva.pose.yaw = s.start.yaw;
      overrides = s.edits.overrides.filter((o) => !isMenuKey(o));
      renderOverrides();
    }
    silva.generation = s.generation;
    if (silva.fullFrames > 0) loadMap();  // after the first frame: building the map takes a core
    if (menuGeneration === s.generation) return;  // the menu shows this world already (or edits to it)
    menuGeneration = s.generation;
    $('seed').value = String(s.seed);
    $('density').value = config.vegetation.density;
    $('elevation').value = config.terrain.max_elevation;
    $('trail').checked = config.trail.enabled;
    $('ground').checked = config.vegetation.ground;
    for (const [id, v] of [['time', config.lighting.time_of_day], ['weather', config.lighting.weather]]) {
      if (![...$(id).options].some((o) => o.value === v)) $(id).add(new Option(v, v));  // a preset of the config's own
      $(id).value = v;
    }
  } catch (e) { /* next poll */ }
}
setInterval(refreshState, 1000);

// ---- the top-down class map ------------------------------------------------------------------------
let map = null;
let mapGeneration = -2;
async function loadMap() {
  if (mapGeneration === silva.generation) return;
  mapGeneration = silva.generation;
  try {
    const res = await fetch('map');
    if (!res.ok) { mapGeneration = -2; return; }
    map = { placement: JSON.parse(res.headers.get('X-Silva-Map')), image: await createImageBitmap(await res.blob()) };
    drawMap();
  } catch (e) { mapGeneration = -2; }
}

function drawMap() {
  const m = $('map'), c = m.getContext('2d');
  if (!map) return;
  c.drawImage(map.image, 0, 0, m.width, m.height);
  const pl = map.placement, sx = m.width / pl.width, sy = m.height / pl.height;
  const px = (silva.pose.x - pl.x0) / pl.metres_per_pixel * sx, py = (pl.y1 - silva.pose.y) / pl.metres_per_pixel * sy;
  const yaw = silva.pose.yaw * Math.PI / 180;
  c.strokeStyle = '#f33'; c.fillStyle = '#f33'; c.lineWidth = 2;
  c.beginPath(); c.arc(px, py, 4, 0, 2 * Math.PI); c.fill();
  c.beginPath(); c.moveTo(px, py); c.lineTo(px + 12 * Math.cos(yaw), py - 12 * Math.sin(yaw)); c.stroke();
}

$('map').addEventListener('click', (e) => {
  if (!map) return;
  const r = $('map').getBoundingClientRect(), pl = map.placement;
  silva.pose.x = pl.x0 + (e.clientX - r.left) / r.width * pl.width * pl.metres_per_pixel;
  silva.pose.y = pl.y1 - (e.clientY - r.top) / r.height * pl.height * pl.metres_per_pixel;
  silva.follow = null;
  silva.placed = null;  // a teleport is no step: nothing to collide with on the way
  setWalk(true);
  moved();
});

refreshState();
requestAnimationFrame(tick);

// The page of `expmap view`: loads the mesh, places the source where the
// pointer hits the surface, asks the server for maps and draws them, one
// view or two side by side on one camera.

import * as THREE from 'three';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';
import { MapClient } from './map_client.js';
import { ViewPane } from './view_pane.js';
import { readState, stateQuery, writeState } from './url_state.js';

const $ = (id) => document.getElementById(id);

async function getJson(url) {
  const response = await fetch(url);
  const body = await response.json();
  if (!response.ok) throw new Error(body.error || `HTTP ${response.status}`);
  return body;
}

function format(x, digits = 3) { return Number(x).toPrecision(digits); }
function grouped(k) { return Number(k).toLocaleString('en-US'); }
function bytes(mib) {
  const b = mib * 1024 * 1024;
  return b < 1e9 ? `${(b / 1e6).toFixed(0)} MB` : `${(b / 1e9).toFixed(1)} GB`;
}
function ms(x) { return x < 10 ? x.toFixed(2) : x.toFixed(0); }

// Whether WebGL draws on the processor (SwiftShader, llvmpipe: headless
// browsers, machines without a GPU driver); there multisampling would cost
// more than the rest of a frame.
function softwareRendering() {
  const gl = document.createElement('canvas').getContext('webgl2');
  if (!gl) return false;
  const info = gl.getExtension('WEBGL_debug_renderer_info');
  const name = String(gl.getParameter(info ? info.UNMASKED_RENDERER_WEBGL : gl.RENDERER));
  gl.getExtension('WEBGL_lose_context')?.loseContext();
  return /swiftshader|llvmpipe|software/i.test(name);
}

// The mesh, read as it arrives: a mesh of millions of vertices is a
// hundred MB of JSON, so the status line says how far the reading is.
async function loadMesh(counts) {
  const response = await fetch('api/mesh');
  if (!response.ok) throw new Error(`the mesh: HTTP ${response.status}`);
  const reader = response.body.getReader();
  const chunks = [];
  let received = 0;
  for (;;) {
    const { done, value } = await reader.read();
    if (done) break;
    chunks.push(value);
    received += value.length;
    $('status').textContent = `loading the mesh (${grouped(counts.vertex_count)} vertices, ` +
      `${grouped(counts.face_count)} faces): ${(received / 1e6).toFixed(1)} MB so far`;
  }
  $('status').textContent = 'reading the mesh';
  const text = await new Blob(chunks).text();
  $('status').textContent = '';
  return JSON.parse(text);
}

async function main() {
  const status = await getJson('api/status');
  const mesh = await loadMesh(status.mesh);
  const methods = status.methods;
  const heat = methods.find((m) => m.takes_time_factor);
  // DGPC first: it factors no matrix, so the first map comes at once.
  const first = methods.find((m) => m.name === 'dgpc') || methods[0];
  const state = readState(location.search, {
    point: null, method: first.name, fraction: 0.05, radius: null,
    m: heat ? heat.default_m : null, compare: '',
  });

  // The mesh, shared by the views.
  const base = new THREE.BufferGeometry();
  base.setAttribute('position', new THREE.Float32BufferAttribute(mesh.vertices, 3));
  base.setIndex(mesh.faces);
  base.computeVertexNormals();
  base.computeBoundingSphere();
  const { center, radius } = base.boundingSphere;

  const canvas = $('canvas');
  const renderer = new THREE.WebGLRenderer({ canvas, antialias: !softwareRendering() });
  renderer.setPixelRatio(window.devicePixelRatio);
  renderer.setScissorTest(true);
  const camera = new THREE.PerspectiveCamera(35, 1, radius / 100, radius * 100);
  // From the outside of the source given in the address (else from +z):
  // a shared view opens on its decal.
  const outward = new THREE.Vector3(0, 0, 1);
  if (state.point && new THREE.Vector3(...state.point).distanceTo(center) > 1e-6 * radius)
    outward.subVectors(new THREE.Vector3(...state.point), center).normalize();
  camera.position.copy(center).addScaledVector(outward, 2.8 * radius);

  const panes = [0, 1].map(() => new ViewPane(base, mesh.faces, radius / 120));
  const comparing = () => Boolean(state.compare);
  const methodOf = (k) => (k === 0 ? state.method : state.compare);

  // Controls, filled from the server's method list.
  for (const select of [$('method'), $('compare')])
    for (const m of methods) select.add(new Option(m.label, m.name));
  const syncControls = () => {
    $('method').value = state.method;
    $('compare').value = state.compare || '';
    $('patch-kind').value = state.radius ? 'radius' : 'fraction';
    $('patch-size').value = state.radius || state.fraction;
    $('m').value = state.m ?? '';
    $('m-label').style.display = [state.method, state.compare].includes(heat && heat.name) ? '' : 'none';
    $('info-1').style.display = comparing() ? 'block' : 'none';
  };

  // The largest map a method gives here, shown before it is asked for
  // where it is small enough to matter (the exact method's).
  const limitLine = (name) => {
    const m = methods.find((x) => x.name === name);
    if (!m || !m.max_region_faces) return '';
    const fraction = m.max_patch_vertices / mesh.vertex_count;
    return `maps of up to ${grouped(m.max_region_faces)} submesh faces here (up to ${bytes(m.max_map_mib)}),\n` +
      `at most ${grouped(m.max_patch_vertices)} patch vertices` +
      (fraction < status.limits.max_fraction ? ` (fraction ≤ ${format(Math.floor(fraction * 1e4) / 1e4)})` : '') +
      '; larger: expmap compute';
  };
  const info = (k, lines, error) => {
    $(`info-${k}`).innerHTML = '';
    const label = methods.find((m) => m.name === methodOf(k))?.label || methodOf(k);
    const limit = limitLine(methodOf(k));
    $(`info-${k}`).append(label + (limit ? '\n' + limit : '') + (lines ? '\n' + lines : ''));
    if (error) {
      const e = document.createElement('div');
      e.className = 'error';
      e.textContent = error;
      $(`info-${k}`).append(e);
    }
  };
  let framesDrawn = 0, frameQueued = false;
  const clients = [0, 1].map((k) => new MapClient((map, roundTrip) => {
    panes[k].show(map);
    requestDraw();
    const rMax = map.r.reduce((a, b) => Math.max(a, b), 0);
    const rate = panes[k].rate();
    info(k, `${map.vertices.length} vertices, ${map.triangles} triangles\n` +
      `fold-free radius ${format(map.fold_free_radius)} of ${format(rMax)}` +
      (map.flipped ? `, ${map.flipped} flipped (red)` : ', none flipped') + '\n' +
      `query ${ms(map.query_ms)} ms, round trip ${ms(roundTrip)} ms` +
      (rate ? `\n${rate.toFixed(1)} maps/s` : ''));
  }, (error) => { panes[k].clear(); requestDraw(); info(k, '', error); },
  (message) => info(k, 'waiting: ' + message.replace(/; retry.*$/, ''))));

  const query = (k) => {
    const q = { ...state, method: methodOf(k), compare: '' };
    if (q.method !== (heat && heat.name)) q.m = null;
    return stateQuery(q);
  };
  const update = () => {
    writeState(state);
    syncControls();
    if (!state.point) {
      for (const k of [0, 1]) info(k, 'click the surface to place the source');
      return;
    }
    // A view without a map yet says so (the status line below says what
    // the server is busy with, a precomputation on a large mesh).
    for (const k of comparing() ? [0, 1] : [0]) {
      if (!panes[k].lastMap) info(k, 'waiting for the map');
      clients[k].request(query(k));
    }
  };

  const patchChanged = () => { panes.forEach((p) => p.resetScale()); update(); };
  // A new method's box says what it is (and its limit) at once, before its
  // first map, which may take a while (a precomputation, an exact map).
  $('method').onchange = (e) => {
    state.method = e.target.value;
    if (state.point) info(0, 'waiting for the map');
    update();
  };
  $('compare').onchange = (e) => {
    state.compare = e.target.value;
    panes[1].clear();
    resize();
    if (state.point && state.compare) info(1, 'waiting for the map');
    update();
  };
  $('patch-kind').onchange = (e) => {
    const size = Number($('patch-size').value);
    if (e.target.value === 'radius') { state.radius = size > 0 && size <= radius ? size : radius / 10; state.fraction = null; }
    else { state.fraction = size > 0 && size <= 1 ? size : 0.05; state.radius = null; }
    patchChanged();
  };
  $('patch-size').onchange = (e) => {
    const size = Number(e.target.value);
    if (!(size > 0)) return syncControls();
    if (state.radius) state.radius = size; else state.fraction = size;
    patchChanged();
  };
  $('m').onchange = (e) => {
    const m = Number(e.target.value);
    if (m > 0) state.m = m;
    update();
  };

  // The pointer: on the surface it moves the source, elsewhere (or with
  // Alt) the camera. This listener comes before the controls' own, so it
  // can turn them off for a drag that starts on the surface.
  const raycaster = new THREE.Raycaster();
  const viewportOf = (x) => (comparing() && x >= canvas.clientWidth / 2 ? 1 : 0);
  const pick = (clientX, clientY) => {
    const rect = canvas.getBoundingClientRect();
    const x = clientX - rect.left, y = clientY - rect.top;
    const k = viewportOf(x);
    const w = comparing() ? rect.width / 2 : rect.width;
    const ndc = new THREE.Vector2(((x - k * w) / w) * 2 - 1, -(y / rect.height) * 2 + 1);
    raycaster.setFromCamera(ndc, camera);
    const hit = raycaster.intersectObject(panes[k].surface, false)[0];
    return hit ? hit.point.toArray() : null;
  };
  let dragging = false, moveQueued = null;
  canvas.addEventListener('pointerdown', (e) => {
    if (e.button !== 0 || e.altKey) return;
    const point = pick(e.clientX, e.clientY);
    if (!point) return;
    dragging = true;
    controls.enabled = false;
    state.point = point;
    update();
  });
  window.addEventListener('pointermove', (e) => {
    if (!dragging) return;
    // One pick per frame, of the latest position.
    if (!moveQueued) requestAnimationFrame(() => {
      const point = pick(moveQueued.clientX, moveQueued.clientY);
      moveQueued = null;
      if (point) { state.point = point; update(); }
    });
    moveQueued = { clientX: e.clientX, clientY: e.clientY };
  });
  window.addEventListener('pointerup', () => { dragging = false; controls.enabled = true; });
  const controls = new OrbitControls(camera, canvas);
  controls.target.copy(center);
  controls.update();

  // An image dropped on the page becomes the decal's texture.
  window.addEventListener('dragover', (e) => e.preventDefault());
  window.addEventListener('drop', (e) => {
    e.preventDefault();
    const file = e.dataTransfer.files[0];
    if (!file || !file.type.startsWith('image/')) return;
    new THREE.TextureLoader().load(URL.createObjectURL(file), (texture) => {
      texture.colorSpace = THREE.SRGBColorSpace;
      panes.forEach((p) => p.setImage(texture));
      requestDraw();
    });
  });

  // Precomputations in progress, polled while any runs.
  const pollStatus = async () => {
    const s = await getJson('api/status').catch(() => null);
    const running = s ? s.precomputations.filter((p) => p.state === 'running') : [];
    $('status').textContent = running.map((p) =>
      `precomputing ${p.method}${p.m ? ` (m = ${p.m})` : ''}: ${p.step || 'starting'}` +
      `${p.fraction > 0 ? `, about ${Math.floor(100 * p.fraction)}% done` : ''}, ` +
      `${p.seconds.toFixed(1)} s so far`).join(' · ');
    setTimeout(pollStatus, running.length ? 300 : 1500);
  };
  pollStatus();

  function resize() {
    const w = canvas.clientWidth, h = canvas.clientHeight;
    renderer.setSize(w, h, false);
    camera.aspect = (comparing() ? w / 2 : w) / h;
    camera.updateProjectionMatrix();
    requestDraw();
  }
  window.addEventListener('resize', resize);
  resize();

  // Drawn on demand (a new map, the camera moved, a resize): the page costs
  // nothing while nothing changes, and dragging leaves the processor to the
  // maps.
  function draw() {
    frameQueued = false;
    const w = canvas.clientWidth, h = canvas.clientHeight;
    const views = comparing() ? 2 : 1;
    for (let k = 0; k < views; ++k) {
      renderer.setViewport(k * w / views, 0, w / views, h);
      renderer.setScissor(k * w / views, 0, w / views, h);
      renderer.render(panes[k].scene, camera);
    }
    framesDrawn += 1;
  }
  function requestDraw() {
    if (!frameQueued) requestAnimationFrame(draw);
    frameQueued = true;
  }
  controls.addEventListener('change', requestDraw);
  requestDraw();

  // For scripts (the browser test, the rate measurement): what is drawn,
  // and where a point of space is on the screen.
  window.expmapViewer = {
    state,
    mapsDrawn: () => panes.map((p) => p.mapsDrawn),
    framesDrawn: () => framesDrawn,
    lastMap: (k) => panes[k].lastMap,
    rate: (k) => panes[k].rate(),
    screenOf: (k, xyz) => {
      const rect = canvas.getBoundingClientRect();
      const w = comparing() ? rect.width / 2 : rect.width;
      const p = new THREE.Vector3(...xyz).project(camera);
      return { x: rect.left + k * w + (p.x + 1) / 2 * w, y: rect.top + (1 - p.y) / 2 * rect.height };
    },
    pick,
  };
  update();
}

main().catch((error) => {
  document.getElementById('status').textContent = 'expmap view: ' + error.message;
  console.error(error);
});

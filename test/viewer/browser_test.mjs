// The viewer in a real browser, end to end: `expmap view` on a free port,
// its API's answers to good and bad requests, its map against the map the
// command line writes, and the page in Debian's Chromium: a URL state is
// drawn with the checkerboard where the source is, a click elsewhere moves
// the source, a drag updates the map, and two methods show side by side.
//
// usage: node browser_test.mjs --expmap PROGRAM --mesh MESH --npm-dir DIR --work DIR

import { execFileSync, spawnSync } from 'node:child_process';
import fs from 'node:fs';
import path from 'node:path';
import { diagonal, frontPoint, get, getJson, launchBrowser, options, startServer } from './browser_session.mjs';

const o = options(process.argv.slice(2), ['expmap', 'mesh', 'npm-dir', 'work']);
let failures = 0, passes = 0;
function check(condition, what) {
  if (condition) ++passes;
  else { ++failures; console.log(`FAIL: ${what}`); }
}

// The command's own errors: one "expmap: error:" line, status 2 for usage
// and 1 for what happens at run time.
for (const [args, status, message] of [
  [['view'], 2, 'no mesh file given'],
  [['view', o.mesh, '--port', '70000'], 2, '--port must be at most 65535'],
  [['view', o.mesh, '--colour', 'red'], 2, "unknown option '--colour'"],
  [['view', path.join(o.work, 'missing.off')], 1, 'cannot open mesh file'],
  [['view', o.mesh, '--host', '256.0.0.1', '--port', '0'], 1, 'cannot listen on 256.0.0.1'],
]) {
  const r = spawnSync(o.expmap, args, { encoding: 'utf8', timeout: 30000 });
  check(r.status === status && r.stderr.startsWith('expmap: error: ') && r.stderr.includes(message) &&
    r.stderr.trim().split('\n').length === 1,
  `expmap ${args.join(' ')}: status ${status}, '${message}' (got ${r.status}: ${r.stderr.trim()})`);
}
check(spawnSync(o.expmap, ['view', '--help'], { encoding: 'utf8' }).stdout.includes('--host H'), 'expmap view --help');

// Bound to another loopback address, the server answers requests addressed
// to that address, and still refuses other host names.
{
  const other = await startServer(o.expmap, o.mesh, '127.0.0.2');
  try {
    const own = await get(other.port, '/api/status', {}, '127.0.0.2');
    check(own.status === 200, `--host 127.0.0.2 answers requests to 127.0.0.2 (got ${own.status} ${own.body.slice(0, 200)})`);
    const foreign = await get(other.port, '/api/status', { Host: `attacker.example:${other.port}` }, '127.0.0.2');
    check(foreign.status === 403 && JSON.parse(foreign.body).error.includes(`127.0.0.2:${other.port}`),
      `--host 127.0.0.2 refuses another host name, naming its own (got ${foreign.status} ${foreign.body})`);
  } finally {
    other.stop();
  }
}

const server = await startServer(o.expmap, o.mesh);
const browser = await launchBrowser(o['npm-dir']).catch((e) => { server.stop(); throw e; });
try {
  const port = server.port;
  const { json: mesh } = await getJson(port, '/api/mesh');
  const { json: status } = await getJson(port, '/api/status');
  check(mesh.vertices.length === 3 * mesh.vertex_count && mesh.faces.length === 3 * mesh.face_count,
    '/api/mesh gives three coordinates per vertex and three corners per face');
  const methodNames = status.methods.map((m) => m.name).join(',');
  check(methodNames === 'heat,dem,dgpc,exact', `/api/status lists the four methods (got ${methodNames})`);
  check(status.mesh.vertex_count === mesh.vertex_count && status.mesh.face_count === mesh.face_count,
    '/api/status gives the mesh\'s size');
  const exactInfo = status.methods.find((m) => m.name === 'exact');
  check(status.methods.every((m) => m.max_patch_vertices > 0) && exactInfo.max_patch_vertices === 20000 &&
    exactInfo.max_region_faces === 40000 && exactInfo.max_map_mib > 0 &&
    status.limits.queries_per_method > 0 && status.limits.waiting_per_method >= 0 &&
    status.limits.max_wait_seconds > 0,
  `/api/status gives each method's limit and the queue's (got ${JSON.stringify(status.limits)}, ${JSON.stringify(exactInfo)})`);

  // Bad requests: HTTP 400 with a message, nothing else.
  const v0 = mesh.vertices.slice(0, 3).join(',');
  const bad = [
    ['/api/map?method=dgpc&fraction=0.02', 'point=X,Y,Z is required'],
    [`/api/map?point=1,2&method=dgpc&fraction=0.02`, 'three comma-separated numbers'],
    [`/api/map?point=${v0}&method=dgpc&fraction=2`, 'fraction must be in'],
    [`/api/map?point=${v0}&method=dgpc&fraction=nan`, 'finite number'],
    [`/api/map?point=${v0}&method=dgpc`, 'exactly one of fraction'],
    [`/api/map?point=${v0}&method=dgpc&fraction=0.02&radius=1`, 'exactly one of fraction'],
    [`/api/map?point=${v0}&method=nope&fraction=0.02`, "unknown method 'nope'"],
    ['/api/map?point=-1e308,0,1e308&method=dgpc&fraction=0.02', 'point must be near the mesh'],
    [`/api/map?point=${v0}&method=dgpc&fraction=0.02&m=10`, 'applies only to method=heat'],
    [`/api/map?point=${v0}&method=dgpc&fraction=0.02&fraction=0.03`, 'more than once'],
    [`/api/map?point=${v0}&method=dgpc&fraction=0.02&x=1`, "unknown parameter 'x'"],
  ];
  for (const [target, message] of bad) {
    const r = await get(port, target);
    let error = '';
    try { error = JSON.parse(r.body).error; } catch { /* checked below */ }
    check(r.status === 400 && error.includes(message), `${target}: HTTP 400 with '${message}' (got ${r.status} ${r.body})`);
  }
  // Every method maps from a point inside a face: no row at r = 0. A first
  // request waits (HTTP 503) while the method is precomputed.
  const inFace = frontPoint(mesh).point;
  for (const m of status.methods) {
    let r = null;
    for (let tries = 0; tries < 300 && (!r || r.status === 503); ++tries) {
      if (r) await new Promise((resolve) => setTimeout(resolve, 200));
      r = await get(port, `/api/map?point=${inFace.join(',')}&method=${m.name}&fraction=0.02`);
    }
    let map = null;
    try { map = JSON.parse(r.body); } catch { /* checked below */ }
    check(r.status === 200 && map.method === m.name && map.vertices.length > 10 &&
      map.r.every((x) => Number.isFinite(x) && x > 0) && map.theta.every(Number.isFinite),
    `/api/map maps from a point inside a face with ${m.name} (got ${r.status} ${r.body.slice(0, 200)})`);
  }

  // Random requests from a pool of odd names and values (seeded, so a
  // failure repeats): each gets a JSON answer, and the server lives on.
  let seed = 38;
  const random = () => ((seed = (seed * 1103515245 + 12345) % 2147483648) / 2147483648);
  const pick = (a) => a[Math.floor(random() * a.length)];
  const names = ['point', 'method', 'fraction', 'radius', 'm', 'x', '', '%00', 'point[]'];
  const values = ['', '0', '-1', '1e-300', '1e308', 'nan', 'inf', '0.05', '0x10', '%FF%FE', '1,2',
    '1,2,3', ',,', v0, `${v0},4`, 'dgpc', 'heat', 'DGPC', '%2e%2e%2f', 'a'.repeat(3000)];
  let oddAnswers = 0;
  for (let i = 0; i < 150; ++i) {
    const query = Array.from({ length: 1 + Math.floor(random() * 5) }, () => `${pick(names)}=${pick(values)}`).join('&');
    const r = await get(port, `/api/map?${query}`);
    let json = null;
    try { json = JSON.parse(r.body); } catch { /* counted below */ }
    if (!json || ![200, 400, 414, 503].includes(r.status) || (r.status !== 200 && typeof json.error !== 'string')) {
      ++oddAnswers;
      console.log(`odd answer to /api/map?${query.slice(0, 200)}: ${r.status} ${r.body.slice(0, 200)}`);
    }
  }
  check(oddAnswers === 0, `150 random requests got JSON answers (${oddAnswers} did not)`);
  check((await get(port, '/api/status')).status === 200, 'the server lives on after them');

  // Only the page's own files; requests addressed to other host names refused.
  for (const target of ['/../CMakeLists.txt', '/%2e%2e/%2e%2e/%2e%2e/CMakeLists.txt', '/..%2f..%2fCMakeCache.txt', '/etc/passwd', '/api/nothing']) {
    const r = await get(port, target);
    check(r.status >= 400 && !r.body.includes('cmake') && !r.body.includes('root:'), `${target} is refused (got ${r.status})`);
  }
  check((await get(port, '/index.html')).status === 200, 'the page is served');
  check((await get(port, '/three/three.module.js')).status === 200, 'three.js is served from the build');
  check((await get(port, '/api/status', { Host: `attacker.example:${port}` })).status === 403,
    'a request for another host name is refused (DNS rebinding)');

  // The API's map from a vertex's position is the command line's map from
  // that vertex.
  const V = Math.floor(mesh.vertex_count / 3);
  const at = mesh.vertices.slice(3 * V, 3 * V + 3);
  const { status: s1, json: api } = await getJson(port, `/api/map?point=${at.join(',')}&method=dgpc&fraction=0.02`);
  const csv = path.join(o.work, 'viewer_cli_map.csv');
  execFileSync(o.expmap, ['compute', o.mesh, '--source', String(V), '--method', 'dgpc', '--fraction', '0.02', '-o', csv]);
  const rows = fs.readFileSync(csv, 'utf8').trim().split('\n').slice(1).map((l) => l.split(',').map(Number));
  check(s1 === 200 && api.source.nearest_vertex === V, `the map from vertex ${V}'s position has that vertex as its source`);
  check(api.vertices.length === rows.length, `the API's patch has the command line's ${rows.length} vertices (got ${api.vertices.length})`);
  const rMax = Math.max(...rows.map((r) => r[1]));
  let worstR = 0, worstTheta = 0;
  const byVertex = new Map(rows.map((r) => [r[0], r]));
  for (let i = 0; i < api.vertices.length; ++i) {
    const row = byVertex.get(api.vertices[i]);
    if (!row) { worstR = Infinity; break; }
    worstR = Math.max(worstR, Math.abs(row[1] - api.r[i]));
    if (row[1] > 1e-3 * rMax) {
      const d = Math.abs(row[2] - api.theta[i]);
      worstTheta = Math.max(worstTheta, Math.min(d, 2 * Math.PI - d));
    }
  }
  check(worstR <= 1e-9 * rMax && worstTheta <= 1e-7,
    `API and command line agree (r to ${worstR.toExponential(2)}, theta to ${worstTheta.toExponential(2)})`);

  // The page.
  const page = await browser.newPage({ viewport: { width: 900, height: 600 } });
  const logs = [];
  page.on('console', (m) => logs.push(m.text()));
  page.on('pageerror', (e) => logs.push(String(e)));
  const drawn = (k) => page.evaluate((k) => window.expmapViewer ? window.expmapViewer.mapsDrawn()[k] : 0, k);
  const waitDrawn = (k, count) => page.waitForFunction(([k, count]) => window.expmapViewer &&
    window.expmapViewer.mapsDrawn()[k] >= count, [k, count], { timeout: 20000 });

  const first = frontPoint(mesh);
  await page.goto(`${server.url}?point=${first.point.join(',')}&method=dgpc&fraction=0.05`);
  await waitDrawn(0, 1);
  // Two frames, so that the drawn map is on the screen.
  await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
  const source = await page.evaluate((p) => window.expmapViewer.screenOf(0, p), first.point);
  const shot = await page.screenshot();
  const counts = await page.evaluate(async ({ png, x, y }) => {
    const image = new Image();
    image.src = 'data:image/png;base64,' + png;
    await image.decode();
    const c = document.createElement('canvas');
    c.width = image.width;
    c.height = image.height;
    const g = c.getContext('2d');
    g.drawImage(image, 0, 0);
    const half = 40, d = g.getImageData(Math.round(x) - half, Math.round(y) - half, 2 * half, 2 * half).data;
    let yellow = 0, blue = 0;
    for (let i = 0; i < d.length; i += 4) {
      const [r, gr, b] = [d[i], d[i + 1], d[i + 2]];
      if (r > 120 && gr > 90 && b < 0.6 * gr) ++yellow;
      if (b > r + 50 && b > gr + 20) ++blue;
    }
    return { yellow, blue };
  }, { png: shot.toString('base64'), x: source.x, y: source.y });
  check(counts.yellow > 50 && counts.blue > 50,
    `the checkerboard is drawn around the source (${counts.yellow} yellow, ${counts.blue} blue pixels)`);
  fs.writeFileSync(path.join(o.work, 'viewer_first.png'), shot);

  // A click on another point of the surface moves the source there.
  const second = frontPoint(mesh, first.point, 0.15 * diagonal(mesh));
  const target = await page.evaluate((p) => window.expmapViewer.screenOf(0, p), second.point);
  const hit = await page.evaluate(({ x, y }) => window.expmapViewer.pick(x, y), target);
  check(hit !== null, 'the second point is on the surface as the page shows it');
  const before = await drawn(0);
  const firstMap = await page.evaluate(() => window.expmapViewer.lastMap(0));
  await page.mouse.click(target.x, target.y);
  await waitDrawn(0, before + 1);
  const secondMap = await page.evaluate(() => window.expmapViewer.lastMap(0));
  const moved = Math.hypot(...[0, 1, 2].map((d) => secondMap.source.position[d] - firstMap.source.position[d]));
  check(moved > 0.1 * diagonal(mesh) && secondMap.vertices[0] !== firstMap.vertices[0],
    `the click moved the source (by ${moved.toPrecision(3)}) and the map changed`);
  check(hit && Math.hypot(...[0, 1, 2].map((d) => secondMap.source.position[d] - hit[d])) < 1e-3 * diagonal(mesh),
    `the source is where the pointer hit the surface (${JSON.stringify(hit)} vs ${JSON.stringify(secondMap.source.position)})`);
  check(new URL(page.url()).searchParams.get('point') !== first.point.join(','), 'the address follows the source');

  // A drag updates the map while the pointer moves.
  const start = await drawn(0);
  await page.mouse.move(target.x, target.y);
  await page.mouse.down();
  for (let i = 1; i <= 10; ++i) {
    await page.mouse.move(target.x + 3 * i, target.y + 2 * i);
    await page.waitForTimeout(60);
  }
  await page.mouse.up();
  await page.waitForTimeout(300);
  check((await drawn(0)) >= start + 2, `dragging drew ${(await drawn(0)) - start} maps`);

  // The exact method's limit shows before any map of it is asked for.
  await page.goto(`${server.url}?method=exact&fraction=0.05`);
  await page.waitForFunction(() => document.getElementById('info-0').textContent.includes('submesh faces here'),
    null, { timeout: 20000 });
  const limitText = await page.evaluate(() => document.getElementById('info-0').textContent);
  check(limitText.includes('maps of up to 40,000 submesh faces here') && limitText.includes('expmap compute'),
    `the page shows the exact method's limit before a map (${limitText})`);

  // Two methods side by side on one camera.
  await page.goto(`${server.url}?point=${first.point.join(',')}&method=dgpc&fraction=0.05&compare=dgpc`);
  await waitDrawn(0, 1);
  await waitDrawn(1, 1);
  const both = await page.evaluate(() => [0, 1].map((k) => window.expmapViewer.lastMap(k).vertices.length));
  check(both[0] === both[1] && both[0] > 0, `both views drew the same DGPC map (${both})`);
  check(!logs.some((l) => /error/i.test(l)), `no errors in the page's console (${logs.join(' | ')})`);
} catch (e) {
  ++failures;
  console.log(`FAIL: ${e.stack || e}`);
} finally {
  await browser.close();
  server.stop();
}
console.log(`${passes} passed, ${failures} failed`);
process.exit(failures ? 1 : 0);

// Maps per second while dragging the source across the surface in the page
// (server, transfer and drawing, as a user sees them): the pointer circles
// the front-most point of the mesh for a few seconds with the button down,
// and the page counts the maps it draws.
//
// usage: node drag_rate.mjs --expmap PROGRAM --mesh MESH --npm-dir DIR
//        [--method dgpc] [--fraction 0.02] [--m T] [--seconds 8]

import { frontPoint, getJson, launchBrowser, options, startServer } from './browser_session.mjs';

const o = { method: 'dgpc', fraction: '0.02', seconds: '8', ...options(process.argv.slice(2), ['expmap', 'mesh', 'npm-dir']) };
const server = await startServer(o.expmap, o.mesh);
const browser = await launchBrowser(o['npm-dir']);
try {
  const { json: mesh } = await getJson(server.port, '/api/mesh');
  const start = frontPoint(mesh);
  // The server alone: sequential requests from points of the surface near
  // the start (first one, with the precomputation, not counted).
  const query = (p) => `/api/map?point=${p.join(',')}&method=${o.method}&fraction=${o.fraction}${o.m ? `&m=${o.m}` : ''}`;
  const first = await getJson(server.port, query(start.point));
  if (first.status !== 200) throw new Error(`/api/map: ${JSON.stringify(first.json)}`);
  const ring = [];
  for (let i = 0; i < 40; ++i) ring.push(mesh.vertices.slice(3 * ((start.vertex + 97 * i) % mesh.vertex_count), 3 * ((start.vertex + 97 * i) % mesh.vertex_count) + 3));
  const t1 = Date.now();
  let queryMs = 0;
  for (const p of ring) queryMs += (await getJson(server.port, query(p))).json.query_ms;
  const apiSeconds = (Date.now() - t1) / 1000;
  console.log(`server alone: ${(ring.length / apiSeconds).toFixed(1)} maps/s over HTTP, ` +
    `mean query ${(queryMs / ring.length).toFixed(2)} ms`);

  const page = await browser.newPage({ viewport: { width: 900, height: 600 } });
  const m = o.m ? `&m=${o.m}` : '';
  await page.goto(`${server.url}?point=${start.point.join(',')}&method=${o.method}&fraction=${o.fraction}${m}`);
  // The first map includes the precomputation: wait for it (up to 5 minutes).
  await page.waitForFunction(() => window.expmapViewer && window.expmapViewer.mapsDrawn()[0] >= 1, null, { timeout: 300000 });
  const centre = await page.evaluate((p) => window.expmapViewer.screenOf(0, p), start.point);
  await page.mouse.move(centre.x, centre.y);
  await page.mouse.down();
  const before = await page.evaluate(() => window.expmapViewer.mapsDrawn()[0]);
  const t0 = Date.now();
  let moves = 0;
  while (Date.now() - t0 < 1000 * Number(o.seconds)) {
    const a = (Date.now() - t0) / 1000 * 2 * Math.PI / 4;  // a turn every 4 s
    await page.mouse.move(centre.x + 25 * Math.cos(a), centre.y + 25 * Math.sin(a));
    ++moves;
    await page.waitForTimeout(5);
  }
  const seconds = (Date.now() - t0) / 1000;
  await page.mouse.up();
  const after = await page.evaluate(() => window.expmapViewer.mapsDrawn()[0]);
  const map = await page.evaluate(() => window.expmapViewer.lastMap(0));
  console.log(`${o.mesh}: ${mesh.vertex_count} vertices; ${o.method}, fraction ${o.fraction}` +
    `${o.m ? `, m ${o.m}` : ''}: ${map.vertices.length} patch vertices, query ${map.query_ms.toFixed(2)} ms`);
  console.log(`dragging (browser input): ${after - before} maps in ${seconds.toFixed(1)} s = ` +
    `${((after - before) / seconds).toFixed(1)} maps/s (${moves} pointer moves)`);

  // The same circle driven from inside the page, a pointer event every 8 ms
  // (a 120 Hz mouse): the rate the page reaches when input is not the limit.
  const inPage = await page.evaluate(async ({ x, y, seconds }) => {
    const canvas = document.getElementById('canvas');
    const event = (type, t) => new PointerEvent(type, {
      clientX: x + 25 * Math.cos(t * Math.PI / 2), clientY: y + 25 * Math.sin(t * Math.PI / 2),
      button: 0, buttons: 1, bubbles: true, pointerId: 1, isPrimary: true,
    });
    canvas.dispatchEvent(event('pointerdown', 0));
    const before = window.expmapViewer.mapsDrawn()[0], frames = window.expmapViewer.framesDrawn();
    const t0 = performance.now();
    await new Promise((resolve) => {
      const timer = setInterval(() => {
        const t = (performance.now() - t0) / 1000;
        window.dispatchEvent(event('pointermove', t));
        if (t > seconds) { clearInterval(timer); resolve(); }
      }, 8);
    });
    window.dispatchEvent(event('pointerup', 0));
    const s = (performance.now() - t0) / 1000;
    return { maps: window.expmapViewer.mapsDrawn()[0] - before, frames: window.expmapViewer.framesDrawn() - frames, s };
  }, { x: centre.x, y: centre.y, seconds: Number(o.seconds) });
  console.log(`dragging (in-page events at 120 Hz): ${inPage.maps} maps in ${inPage.s.toFixed(1)} s = ` +
    `${(inPage.maps / inPage.s).toFixed(1)} maps/s, ${(inPage.frames / inPage.s).toFixed(1)} frames/s`);
} finally {
  await browser.close();
  server.stop();
}

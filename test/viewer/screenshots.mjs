// Renders the viewer's pictures for the README and the manual: one view
// with the checkerboard decal, and two methods side by side.
//
// usage: node screenshots.mjs --expmap PROGRAM --mesh MESH --npm-dir DIR --out DIR
//        [--point X,Y,Z] [--method dgpc] [--compare dgpc] [--fraction 0.05]
//        [--name viewer]
// Without --point, the front-most point of the mesh (largest z). Writes
// NAME.png (one view) and NAME_compare.png (two).

import path from 'node:path';
import { frontPoint, getJson, launchBrowser, options, startServer } from './browser_session.mjs';

const o = { method: 'dgpc', compare: 'dgpc', fraction: '0.05', name: 'viewer',
  ...options(process.argv.slice(2), ['expmap', 'mesh', 'npm-dir', 'out']) };
const server = await startServer(o.expmap, o.mesh);
const browser = await launchBrowser(o['npm-dir']);
try {
  const { json: mesh } = await getJson(server.port, '/api/mesh');
  const point = o.point ? o.point.split(',').map(Number) : frontPoint(mesh).point;
  const page = await browser.newPage({ viewport: { width: 720, height: 480 } });
  const shots = [
    [`${o.name}.png`, `method=${o.method}`, 1],
    [`${o.name}_compare.png`, `method=${o.method}&compare=${o.compare}`, 2],
  ];
  for (const [file, methods, views] of shots) {
    await page.goto(`${server.url}?point=${point.join(',')}&${methods}&fraction=${o.fraction}`);
    await page.waitForFunction((views) => window.expmapViewer &&
      window.expmapViewer.mapsDrawn().slice(0, views).every((n) => n >= 1), views, { timeout: 300000 });
    await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
    await page.screenshot({ path: path.join(o.out, file) });
    console.log(`wrote ${path.join(o.out, file)}`);
  }
} finally {
  await browser.close();
  server.stop();
}

// What the browser test and the drag-rate measurement share: `expmap view`
// on a free port, Debian's Chromium driven by playwright-core, and plain
// HTTP requests to the server.

import { spawn } from 'node:child_process';
import http from 'node:http';
import path from 'node:path';
import { pathToFileURL } from 'node:url';

export const chromiumPath = process.env.EXPMAP_CHROMIUM || '/usr/bin/chromium';

// Named options --name value from the command line.
export function options(argv, required) {
  const o = {};
  for (let i = 0; i < argv.length; i += 2) {
    if (!argv[i].startsWith('--') || i + 1 >= argv.length) throw new Error(`bad argument '${argv[i]}'`);
    o[argv[i].slice(2)] = argv[i + 1];
  }
  for (const name of required) if (!(name in o)) throw new Error(`--${name} is required`);
  return o;
}

// Starts `expmap view MESH --port 0 --host HOST` (an IPv4 address);
// resolves to { url, port, stop() } once it prints its address.
export function startServer(expmap, mesh, host = '127.0.0.1') {
  return new Promise((resolve, reject) => {
    const child = spawn(expmap, ['view', mesh, '--port', '0', '--host', host], { stdio: ['ignore', 'pipe', 'pipe'] });
    let out = '', err = '';
    const timer = setTimeout(() => { child.kill(); reject(new Error('the server did not start in 60 s')); }, 60000);
    child.stdout.on('data', (d) => {
      out += d;
      const m = out.match(new RegExp(`viewer: +(http://${host.replaceAll('.', '\\.')}:(\\d+)/)`));
      if (m) {
        clearTimeout(timer);
        resolve({ url: m[1], port: Number(m[2]), stop: () => child.kill(), output: () => out + err });
      }
    });
    child.stderr.on('data', (d) => { err += d; });
    child.on('exit', (code) => {
      clearTimeout(timer);
      reject(new Error(`expmap view exited with ${code}: ${out}${err}`));
    });
  });
}

// GET `target` (a path) from the server at `host`, with optional headers;
// resolves to { status, headers, body } with the body as text.
export function get(port, target, headers = {}, host = '127.0.0.1') {
  return new Promise((resolve, reject) => {
    const req = http.request({ host, port, path: target, headers: { Host: `${host}:${port}`, ...headers } },
      (res) => {
        let body = '';
        res.setEncoding('utf8');
        res.on('data', (d) => { body += d; });
        res.on('end', () => resolve({ status: res.statusCode, headers: res.headers, body }));
      });
    req.on('error', reject);
    req.end();
  });
}

export async function getJson(port, target) {
  const r = await get(port, target);
  return { status: r.status, json: JSON.parse(r.body) };
}

// Chromium headless, drawing WebGL in software (SwiftShader).
export async function launchBrowser(npmDir) {
  const entry = path.join(npmDir, 'node_modules', 'playwright-core', 'index.mjs');
  const { chromium } = await import(pathToFileURL(entry).href);
  return chromium.launch({
    executablePath: chromiumPath,
    args: ['--headless=new', '--enable-unsafe-swiftshader', '--use-angle=swiftshader', '--no-sandbox'],
  });
}

// The front-most vertex (largest z, the camera looks down -z) and a point
// inside one of its faces near it, as the page's first view shows them.
export function frontPoint(mesh, exclude = null, minDistance = 0) {
  const x = mesh.vertices, n = mesh.vertex_count;
  let best = -1;
  for (let v = 0; v < n; ++v) {
    if (exclude && Math.hypot(x[3 * v] - exclude[0], x[3 * v + 1] - exclude[1], x[3 * v + 2] - exclude[2]) < minDistance)
      continue;
    if (best < 0 || x[3 * v + 2] > x[3 * best + 2]) best = v;
  }
  const f = Math.floor(mesh.faces.indexOf(best) / 3);  // a face with the vertex as a corner
  const corners = mesh.faces.slice(3 * f, 3 * f + 3);
  const w = corners.map((c) => (c === best ? 0.6 : 0.2));
  const point = [0, 1, 2].map((d) => corners.reduce((s, c, k) => s + w[k] * x[3 * c + d], 0));
  return { vertex: best, point };
}

export function diagonal(mesh) {
  const lo = [Infinity, Infinity, Infinity], hi = [-Infinity, -Infinity, -Infinity];
  for (let i = 0; i < mesh.vertices.length; ++i) {
    lo[i % 3] = Math.min(lo[i % 3], mesh.vertices[i]);
    hi[i % 3] = Math.max(hi[i % 3], mesh.vertices[i]);
  }
  return Math.hypot(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]);
}

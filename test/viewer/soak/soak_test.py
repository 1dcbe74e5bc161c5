#!/usr/bin/env python3
# Copyright (c) 2026 expmap contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""`expmap view` under a long, mixed, partly concurrent load on a mesh of more
than 100,000 vertices: every request is answered (200, 400, 413 or 503), the
server lives, its resident memory (read from /proc, not from the server)
stays under the bound doc/viewer.md states and ends close to where it
started once every method was precomputed.

usage: soak_test.py --expmap PROGRAM --mesh MESH --examples DIR
"""

import argparse
import concurrent.futures
import math
import os
import random
import subprocess
import sys
import threading
import time

MIB = 1024 * 1024


def parse_args():
    p = argparse.ArgumentParser()
    p.add_argument('--expmap', required=True)
    p.add_argument('--mesh', required=True)
    p.add_argument('--examples', required=True, help='the folder of viewer_client.py')
    p.add_argument('--seed', type=int, default=49)
    return p.parse_args()


class Server:
    """`expmap view MESH --port 0`, and its resident memory from /proc."""

    def __init__(self, expmap, mesh):
        self.process = subprocess.Popen([expmap, 'view', mesh, '--port', '0'], stdout=subprocess.PIPE,
                                        stderr=subprocess.STDOUT, text=True)
        self.url = None
        self.output = []
        while self.url is None:
            line = self.process.stdout.readline()
            if not line:
                raise RuntimeError('expmap view ended: ' + ''.join(self.output))
            self.output.append(line)
            if line.startswith('viewer:'):
                self.url = line.split()[-1].rstrip('/')
        threading.Thread(target=lambda: [self.output.append(l) for l in self.process.stdout], daemon=True).start()

    def memory(self, field='VmRSS'):
        """`field` of /proc/PID/status in MiB."""
        with open(f'/proc/{self.process.pid}/status') as f:
            for line in f:
                if line.startswith(field + ':'):
                    return int(line.split()[1]) / 1024
        raise RuntimeError(f'no {field} for the server')

    def alive(self):
        return self.process.poll() is None

    def stop(self):
        self.process.kill()
        self.process.wait()


def main():
    a = parse_args()
    sys.path.insert(0, a.examples)
    import viewer_client as client  # the documented client, tested here too

    failures = []

    def check(condition, what):
        print(('ok:   ' if condition else 'FAIL: ') + what, flush=True)
        if not condition:
            failures.append(what)

    started = time.monotonic()
    server = Server(a.expmap, a.mesh)
    try:
        status, _, mesh = client.request(server.url, '/api/mesh')
        _, _, info = client.request(server.url, '/api/status')
        n = mesh['vertex_count']
        check(n >= 100000, f'the mesh has at least 100,000 vertices ({n})')
        limit = {m['name']: m['max_patch_vertices'] for m in info['methods']}
        exact = next(m for m in info['methods'] if m['name'] == 'exact')
        exact_mib = exact['max_map_mib']
        max_fraction = info['limits']['max_fraction']
        xyz = mesh['vertices']
        lo = [min(xyz[d::3]) for d in range(3)]
        hi = [max(xyz[d::3]) for d in range(3)]
        diagonal = math.dist(lo, hi)
        rng = random.Random(a.seed)

        def point():
            v = rng.randrange(n)
            return xyz[3 * v:3 * v + 3]

        def query(method, point_, fraction=None, radius=None, m=None):
            q = {'point': ','.join(repr(x) for x in point_), 'method': method}
            if fraction is not None:
                q['fraction'] = repr(fraction)
            if radius is not None:
                q['radius'] = repr(radius)
            if m is not None:
                q['m'] = repr(m)
            return q

        # The working set: every method precomputed (heat at two time
        # factors) and one map of each, then the memory the server holds.
        fixed = query('dgpc', xyz[0:3], fraction=0.01)
        for method, m in [('dgpc', None), ('dem', None), ('exact', None), ('heat', None), ('heat', 20.0)]:
            client.get_map(server.url, point(), method, fraction=0.001, m=m)
        first = client.get_map(server.url, xyz[0:3], 'dgpc', fraction=0.01)
        time.sleep(1)
        start_rss = server.memory()
        warmed = time.monotonic()
        print(f'working set after precomputing: {start_rss:.0f} MiB ({warmed - started:.1f} s)', flush=True)

        # Every request sent from here on: (what it was, expected statuses,
        # HTTP status, body), from any thread.
        answers = []
        lock = threading.Lock()
        peak_seen = [start_rss]
        stop_sampling = threading.Event()

        def sample():
            while not stop_sampling.wait(0.05):
                try:
                    rss = server.memory()
                except (OSError, RuntimeError):
                    return
                peak_seen[0] = max(peak_seen[0], rss)

        sampler = threading.Thread(target=sample, daemon=True)
        sampler.start()

        def send(spec):
            kind, q, expected = spec
            status, headers, body = client.request(server.url, '/api/map', q)
            with lock:
                answers.append((kind, q, expected, status, headers, body))
            return status

        def mixed(count):
            """`count` requests of every kind, seeded: small and large maps of
            every method, exact maps near its limit, too large and bad ones."""
            specs = []
            for _ in range(count):
                r = rng.random()
                method = rng.choice(['heat', 'dem', 'dgpc', 'exact'])
                m = rng.choice([None, 20.0]) if method == 'heat' else None
                if r < 0.65:  # small, as the page asks while dragging
                    if rng.random() < 0.5:
                        q = query(method, point(), fraction=rng.uniform(0.0005, 0.01), m=m)
                    else:
                        q = query(method, point(), radius=rng.uniform(0.002, 0.02) * diagonal, m=m)
                    specs.append(('small ' + method, q, {200}))
                elif r < 0.75:  # large, up to the fraction limit
                    method = rng.choice(['heat', 'dem', 'dgpc'])
                    specs.append(('large ' + method, query(method, point(), fraction=rng.uniform(0.05, max_fraction)), {200}))
                elif r < 0.85:  # exact, a medium patch
                    specs.append(('exact', query('exact', point(), fraction=rng.uniform(0.002, 0.02)), {200}))
                elif r < 0.92:  # beyond the exact method's limits: its patch, or its submesh
                    kind = rng.randrange(3)
                    if kind == 0:
                        q = query('exact', point(), fraction=rng.uniform(1.1 * limit['exact'] / n, max_fraction))
                    elif kind == 1:
                        q = query('exact', point(), radius=rng.uniform(0.3, 1.0) * diagonal)
                    else:  # within the patch limit, but a submesh of 2.2 faces a vertex or more
                        q = query('exact', point(), fraction=0.975 * limit['exact'] / n)
                    specs.append(('too large', q, {413}))
                else:  # malformed
                    q = rng.choice([query(method, point(), fraction=0.0), query('nope', point(), fraction=0.01),
                                    query(method, [x + 3 * diagonal for x in point()], fraction=0.01),
                                    {'point': '1,2', 'method': method, 'fraction': '0.01'}])
                    specs.append(('bad', q, {400}))
            return specs

        def run(specs, clients):
            with concurrent.futures.ThreadPoolExecutor(clients) as pool:
                list(pool.map(send, specs))

        # 1. 300 mixed requests from four clients at once.
        run(mixed(300), 4)
        phase = time.monotonic()
        print(f'  300 mixed: {phase - warmed:.1f} s', flush=True)
        # 2. Two exact maps near the limit at once (13,000 patch vertices,
        #    submeshes of about 30,000 to 40,000 faces, or refused where the
        #    surface folds back): the most memory the server lets queries
        #    take.
        near_limit = 13000 / n
        run([('exact near its limit', query('exact', point(), fraction=near_limit), {200, 413})
             for _ in range(2)], 2)
        print(f'  2 exact near the limit: {time.monotonic() - phase:.1f} s, answered ' +
              ', '.join(str(ans[3]) for ans in answers[-2:]), flush=True)
        phase = time.monotonic()
        # 3. A burst: 24 heat requests at once, more than run and wait; the
        #    rest are turned away (503 with Retry-After) and then fetched with
        #    the documented client, which retries.
        burst = [('burst', query('heat', point(), fraction=0.02), {200, 503}) for _ in range(24)]
        run(burst, 24)
        refused = [ans[1] for ans in answers[-24:] if ans[3] == 503]
        retried = [client.get_map(server.url, [float(x) for x in q['point'].split(',')], 'heat', fraction=0.02)
                   for q in refused]
        print(f'  the burst: {time.monotonic() - phase:.1f} s', flush=True)
        phase = time.monotonic()
        # 4. 200 more mixed requests from two clients.
        run(mixed(200), 2)
        print(f'  200 mixed: {time.monotonic() - phase:.1f} s', flush=True)
        stop_sampling.set()
        sampler.join()
        ran = time.monotonic() - warmed

        last = client.get_map(server.url, xyz[0:3], 'dgpc', fraction=0.01)
        time.sleep(1)
        end_rss = server.memory()
        peak = server.memory('VmHWM')

        # Every request got an answer of the documented kind.
        by_status = {}
        for kind, q, expected, status, headers, body in answers:
            by_status[status] = by_status.get(status, 0) + 1
        print(f'{len(answers)} requests in {ran:.1f} s: ' +
              ', '.join(f'{count} x {status}' for status, count in sorted(by_status.items())), flush=True)
        check(len(answers) >= 500, f'at least 500 requests ({len(answers)})')
        odd = [(kind, status, body) for kind, q, expected, status, headers, body in answers if status not in expected]
        for kind, status, body in odd[:10]:
            print(f'  unexpected: {kind} -> {status} {str(body)[:300]}')
        check(not odd, f'every request got its expected status ({len(odd)} did not)')
        check(all(s in (200, 400, 413, 503) for s in by_status), 'only 200, 400, 413 and 503')
        check(all(isinstance(body.get('error'), str) and body['error'] for kind, q, e, status, h, body in answers
                  if status != 200), 'every refusal says why')
        too_large = [(q, body) for kind, q, e, status, h, body in answers if status == 413]
        maxima = {'patch_vertices': limit['exact'], 'region_faces': exact['max_region_faces']}
        check(all(body['limit']['maximum'] == maxima[body['limit']['quantity']] and
                  body['limit']['asked'] > body['limit']['maximum'] and 'expmap compute' in body['error']
                  for q, body in too_large), f'{len(too_large)} too large requests name the limit and expmap compute')
        check(any(body['limit']['quantity'] == 'region_faces' for q, body in too_large),
              'some were refused for their submesh')
        check(all(h.get('Retry-After', '').isdigit() and int(h['Retry-After']) >= 1
                  for k, q, e, status, h, b in answers if status == 503), 'every 503 has a Retry-After')
        check(0 < len(refused) < 24 and len(retried) == len(refused),
              f'the burst: {24 - len(refused)} served at once or in turn, {len(refused)} turned away, '
              'all served when retried')
        # The maps are what was asked for: a fraction patch has its share of
        # the mesh's vertices (a point source is no vertex of its own).
        sizes_wrong = 0
        for kind, q, e, status, h, body in answers:
            if status == 200 and 'fraction' in q:
                if len(body['vertices']) != math.ceil(float(q['fraction']) * n):
                    sizes_wrong += 1
            if status == 200:
                check_limit = len(body['vertices']) <= limit[body['method']]
                if not check_limit:
                    sizes_wrong += 1
        check(sizes_wrong == 0, f'every map has the size asked for, within its limit ({sizes_wrong} not)')
        check(last['r'] == first['r'] and last['theta'] == first['theta'],
              'the same request gives the same map before and after')

        # The server lives, and its memory is bounded.
        check(server.alive() and client.request(server.url, '/api/status')[0] == 200, 'the server lives')
        bound = start_rss + 2 * exact_mib + 512
        print(f'resident memory: {start_rss:.0f} MiB at the start, peak {peak:.0f} MiB '
              f'(sampled {peak_seen[0]:.0f} MiB), {end_rss:.0f} MiB at the end', flush=True)
        check(peak <= bound, f'peak {peak:.0f} MiB within the working set + two exact maps at the limit '
                             f'+ 512 MiB ({bound:.0f} MiB)')
        margin = max(64, 0.1 * start_rss)
        check(end_rss <= start_rss + margin,
              f'ends within {margin:.0f} MiB of the working set ({end_rss - start_rss:+.0f} MiB)')
    finally:
        server.stop()
    print(f'{len(failures)} failed ({time.monotonic() - started:.0f} s in all)')
    return 1 if failures else 0


if __name__ == '__main__':
    sys.exit(main())

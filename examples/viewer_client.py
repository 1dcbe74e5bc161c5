#!/usr/bin/env python3
# Copyright (c) 2026 expmap contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Maps many points through the JSON API of `expmap view`, as a script does.

The server runs a few queries per method at once and lets a few more wait
their turn; beyond that, and while a method is precomputed, it answers
HTTP 503 with a Retry-After header (seconds). A client that sends several
requests at once must wait that long and ask again: `get_map()` does, with
a little random spread so that clients turned away together do not come
back together. Any other error is final: 400 (a bad parameter), 413 (a
patch beyond the method's limit: ask for a smaller one, or run
`expmap compute`), 422 (the computation failed).

    build/tools/expmap view data/meshes/armadillo.off --port 8765 &
    python3 examples/viewer_client.py http://127.0.0.1:8765 --method heat \\
        --fraction 0.02 --maps 40 --clients 8

Only the standard library; the functions can be imported.
"""

import argparse
import concurrent.futures
import json
import random
import time
import urllib.error
import urllib.parse
import urllib.request


class ViewerError(Exception):
    """An answer other than a map: its HTTP status and the server's message."""

    def __init__(self, status, message):
        super().__init__(f'HTTP {status}: {message}')
        self.status = status
        self.message = message


def request(base_url, path, params=None, timeout=300):
    """One GET: (status, headers, parsed JSON body)."""
    url = base_url.rstrip('/') + path + ('?' + urllib.parse.urlencode(params) if params else '')
    try:
        with urllib.request.urlopen(url, timeout=timeout) as response:
            return response.status, response.headers, json.load(response)
    except urllib.error.HTTPError as e:
        body = e.read()
        try:
            parsed = json.loads(body)
        except ValueError:
            parsed = {'error': body.decode('utf-8', 'replace')}
        return e.code, e.headers, parsed


def get_map(base_url, point, method, fraction=None, radius=None, m=None, max_wait=600):
    """The map around the surface point nearest to `point` (x, y, z): the
    JSON of GET /api/map. Waits as the server asks (HTTP 503, Retry-After)
    for at most `max_wait` seconds in all; raises ViewerError for any other
    error, or a 503 that lasts longer."""
    params = {'point': ','.join(repr(float(x)) for x in point), 'method': method}
    if fraction is not None:
        params['fraction'] = repr(fraction)
    if radius is not None:
        params['radius'] = repr(radius)
    if m is not None:
        params['m'] = repr(m)
    deadline = time.monotonic() + max_wait
    while True:
        status, headers, body = request(base_url, '/api/map', params)
        if status == 200:
            return body
        if status != 503:
            raise ViewerError(status, body.get('error', ''))
        wait = float(headers.get('Retry-After', '1')) * random.uniform(1.0, 1.5)
        if time.monotonic() + wait > deadline:
            raise ViewerError(status, body.get('error', ''))
        time.sleep(wait)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n\n')[0])
    parser.add_argument('url', help='the address expmap view prints, e.g. http://127.0.0.1:8765')
    parser.add_argument('--method', default='heat')
    parser.add_argument('--fraction', type=float, default=0.02)
    parser.add_argument('--maps', type=int, default=40, help='maps around random vertices')
    parser.add_argument('--clients', type=int, default=8, help='requests at once')
    parser.add_argument('--seed', type=int, default=1)
    a = parser.parse_args()

    status, _, mesh = request(a.url, '/api/mesh')
    if status != 200:
        raise SystemExit(f'cannot read the mesh: HTTP {status}')
    rng = random.Random(a.seed)
    xyz = mesh['vertices']
    points = [xyz[3 * v:3 * v + 3] for v in (rng.randrange(mesh['vertex_count']) for _ in range(a.maps))]
    start = time.monotonic()
    with concurrent.futures.ThreadPoolExecutor(a.clients) as pool:
        maps = list(pool.map(lambda p: get_map(a.url, p, a.method, fraction=a.fraction), points))
    seconds = time.monotonic() - start
    sizes = [len(m['vertices']) for m in maps]
    print(f'{len(maps)} maps ({a.method}, fraction {a.fraction}) from {a.clients} clients in '
          f'{seconds:.1f} s: {sum(sizes) / len(sizes):.0f} patch vertices on average')


if __name__ == '__main__':
    main()

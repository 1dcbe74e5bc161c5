// The view's state in the page's address, so that a view can be shared and
// reloaded: ?point=X,Y,Z&method=heat&fraction=0.05&m=10&compare=dgpc
// (radius=R instead of fraction=F for a patch of a geodesic radius).

export function readState(search, defaults) {
  const q = new URLSearchParams(search);
  const state = { ...defaults };
  const point = q.get('point');
  if (point) {
    const xyz = point.split(',').map(Number);
    if (xyz.length === 3 && xyz.every(Number.isFinite)) state.point = xyz;
  }
  for (const key of ['method', 'compare']) if (q.has(key)) state[key] = q.get(key);
  for (const key of ['fraction', 'radius', 'm']) {
    const x = Number(q.get(key));
    if (q.has(key) && Number.isFinite(x) && x > 0) state[key] = x;
  }
  if (q.has('radius') && !q.has('fraction')) state.fraction = null;
  if (q.has('fraction')) state.radius = null;
  return state;
}

// Seven significant digits: a point of the surface, to well below an edge.
export function stateQuery(state) {
  const parts = [];
  if (state.point) parts.push('point=' + state.point.map((x) => Number(x.toPrecision(7))).join(','));
  parts.push('method=' + encodeURIComponent(state.method));
  if (state.radius) parts.push('radius=' + state.radius);
  else parts.push('fraction=' + state.fraction);
  if (state.m && [state.method, state.compare].includes('heat')) parts.push('m=' + state.m);
  if (state.compare) parts.push('compare=' + encodeURIComponent(state.compare));
  return '?' + parts.join('&');
}

export function writeState(state) {
  history.replaceState(null, '', stateQuery(state));
}

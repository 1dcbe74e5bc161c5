// Map requests of one view, at most one in flight: while one is answered,
// only the newest of the requests made meanwhile waits, so dragging never
// queues up stale maps.

export class MapClient {
  // onWaiting(message): the server asked to retry (HTTP 503), saying what
  // it waits for (a precomputation and its step, or other queries).
  constructor(onMap, onError, onWaiting = () => {}) {
    this.onMap = onMap;
    this.onError = onError;
    this.onWaiting = onWaiting;
    this.pending = null;
    this.inFlight = false;
  }

  request(query) {
    this.pending = query;
    if (!this.inFlight) this.next();
  }

  async next() {
    const query = this.pending;
    this.pending = null;
    if (!query) return;
    this.inFlight = true;
    const start = performance.now();
    try {
      const response = await fetch('api/map' + query);
      const body = await response.json();
      if (response.status === 503) {
        // Precomputing, or the server's queries of this method and its
        // queue are all taken: ask again shortly (sooner than Retry-After,
        // which is for scripts: the page polls the progress meanwhile),
        // unless a newer request came meanwhile.
        this.onWaiting(body.error || 'the server is busy');
        if (!this.pending) this.pending = query;
        await new Promise((resolve) => setTimeout(resolve, 250));
      } else if (!response.ok) {
        this.onError(body.error || `HTTP ${response.status}`);
      } else {
        this.onMap(body, performance.now() - start);
      }
    } catch (error) {
      this.onError(String(error));
    }
    this.inFlight = false;
    this.next();
  }
}

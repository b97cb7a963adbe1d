// Terrain tiles go through a custom MapLibre protocol, "timed://<url>", so that we can read the
// Server-Timing header (eval = evaluating h(p) for the tile, encode = PNG encoding) that
// MapLibre's own loader never exposes. The handler is a plain fetch: the browser's HTTP cache
// and the server's ETags work as usual.

const PROTOCOL = 'timed';
const KEEP = 200; // recent tiles kept for the averages

/** The URL MapLibre should request instead of `url` (use it in transformRequest). */
export const timedUrl = (url) => `${PROTOCOL}://${url}`;

/** {eval, encode} in ms from a header such as "eval;dur=3.2, encode;dur=1.1". */
export function parseServerTiming(header) {
  const out = {};
  for (const metric of (header ?? '').split(',')) {
    const [name, ...params] = metric.trim().split(';');
    const dur = params.map((p) => p.trim()).find((p) => p.startsWith('dur='));
    if (name && dur) out[name] = Number(dur.slice(4));
  }
  return out;
}

/** Rolling statistics of the tiles fetched so far. */
export class TileTimings {
  count = 0;
  recent = [];

  add(sample) {
    this.count += 1;
    this.recent.push(sample);
    if (this.recent.length > KEEP) this.recent.shift();
  }

  summary() {
    const mean = (key) => {
      const values = this.recent.map((s) => s[key]).filter(Number.isFinite);
      return values.length ? values.reduce((a, b) => a + b, 0) / values.length : NaN;
    };
    return { count: this.count, eval: mean('eval'), encode: mean('encode'), fetch: mean('fetch') };
  }
}

/** Registers the "timed" protocol; every tile fetched through it is added to `timings`. */
export function registerTimedProtocol(maplibregl, timings) {
  maplibregl.addProtocol(PROTOCOL, async (params, abortController) => {
    const url = params.url.slice(PROTOCOL.length + 3);
    const start = performance.now();
    const response = await fetch(url, { signal: abortController.signal });
    if (!response.ok) throw new Error(`tile ${url}: HTTP ${response.status}`);
    const data = await response.arrayBuffer();
    timings.add({ fetch: performance.now() - start, ...parseServerTiming(response.headers.get('Server-Timing')) });
    return { data };
  });
}

/** Writes the summary into `element`, at most a few times per second. */
export function showTimings(element, timings) {
  const format = (ms) => (Number.isFinite(ms) ? `${ms.toFixed(1)} ms` : '—');
  const render = () => {
    const s = timings.summary();
    element.textContent = s.count === 0 ? 'no tiles yet'
      : `${s.count} tiles · mean of last ${Math.min(s.count, KEEP)}:\n` +
        `evaluate ${format(s.eval)} · encode ${format(s.encode)}\nround trip ${format(s.fetch)}`;
  };
  render();
  return setInterval(render, 300);
}

/**
 * Adds to `timings` every resource the page fetched (by any loader, e.g. CesiumJS's own
 * XMLHttpRequests) whose URL matches `pattern`, with its Server-Timing, through the Resource
 * Timing API (same-origin, so serverTiming is readable). Returns the PerformanceObserver.
 */
export function observeResourceTimings(pattern, timings) {
  const observer = new PerformanceObserver((list) => {
    for (const entry of list.getEntries()) {
      if (!pattern.test(entry.name)) continue;
      const server = Object.fromEntries((entry.serverTiming ?? []).map((t) => [t.name, t.duration]));
      timings.add({ fetch: entry.duration, ...server });
    }
  });
  observer.observe({ type: 'resource', buffered: true });
  // The observer sees every entry; the buffer is only for late observers, so keep it from filling.
  performance.addEventListener('resourcetimingbufferfull', () => performance.clearResourceTimings());
  return observer;
}

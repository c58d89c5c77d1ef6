// Renders the image in the page with the same tracer as `promyk render`
// (promyk_render_rows, web_export/wasm/API.md). A page opened from file://
// has no SharedArrayBuffer, so no wasm threads: instead several workers,
// each started from a blob URL (the CSP allows `worker-src blob:`) with its
// own instance of the one compiled module, take chunks of rows in turn. A
// new render supersedes the one under way: its chunks not yet started are
// dropped, so the page stays responsive while a large w renders.

// The worker's code: the module's glue is put before it in the same blob.
// It refers to nothing outside itself (it is sent as text).
function promykRenderWorker() {
  /* global createPromyk */
  let M = null;
  let opened = null; // the key of the scene this instance has open
  const withText = (text, use) => {
    const size = M.lengthBytesUTF8(text) + 1;
    const at = M._malloc(size);
    try {
      M.stringToUTF8(text, at, size);
      return use(at);
    } finally {
      M._free(at);
    }
  };
  const checked = (text) => {
    const value = JSON.parse(text);
    if (value && typeof value === 'object' && 'error' in value) throw new Error(String(value.error));
    return value;
  };
  self.onmessage = async (event) => {
    const m = event.data;
    if (m.type === 'init') {
      M = await createPromyk({
        // The module compiled once by the page; only an instance here.
        instantiateWasm(imports, done) {
          WebAssembly.instantiate(m.module, imports).then((instance) => done(instance, m.module));
          return {};
        },
      });
      self.postMessage({ type: 'ready' });
      return;
    }
    const started = performance.now();
    try {
      if (opened !== m.sceneKey) {
        opened = null;
        withText(m.scene, (a) => withText(m.file, (b) =>
          checked(M.ccall('promyk_open_scene', 'string', ['number', 'number', 'number'], [a, b, m.w]))));
        opened = m.sceneKey;
      }
      if (m.mapKind) {
        // A map's values (the precision lab): one double a pixel.
        const v = withText(m.mapKind, (k) => withText(JSON.stringify(m.settings), (s) =>
          checked(M.ccall('promyk_map_values', 'string', ['number', 'number', 'number', 'number'], [k, m.first, m.count, s]))));
        const values = M.HEAPU8.slice(v.values, v.values + v.values_bytes);
        const ms = performance.now() - started;
        self.postMessage({ type: 'rows', job: m.job, first: m.first, count: m.count, values, ms }, [values.buffer]);
        return;
      }
      const r = withText(JSON.stringify(m.settings), (s) =>
        checked(M.ccall('promyk_render_rows', 'string', ['number', 'number', 'number'], [m.first, m.count, s])));
      const image = M.HEAPU8.slice(r.image, r.image + r.image_bytes);
      const branch = M.HEAPU8.slice(r.branch, r.branch + r.branch_bytes);
      const ms = performance.now() - started; // this chunk's time in the tracer
      self.postMessage({ type: 'rows', job: m.job, first: m.first, count: m.count, channels: r.channels, image, branch, ms },
        [image.buffer, branch.buffer]);
    } catch (error) {
      self.postMessage({ type: 'error', job: m.job, message: error && error.message ? error.message : String(error) });
    }
  };
}

// Pixels per chunk: a double chunk takes milliseconds, a quad one (software
// binary128, about 100 times slower) about as long, so a superseded render
// is dropped quickly in every type.
// A map's pixel (the precision lab) costs about a quad one: the error map's
// reference is quad, the digits-lost map traces the pixel.
function chunkRows(w, settings, mapKind) {
  const budget = (settings.real === 'quad' || mapKind ? 256 : 16384) / Math.max(1, settings.spp || 1);
  return Math.max(1, Math.min(w, Math.floor(budget / w)));
}

export class RenderPool {
  // glue: the module's JavaScript (createPromyk); module: the compiled
  // WebAssembly.Module; count: how many workers.
  constructor(glue, module, count) {
    this.count = count;
    const source = `${glue}\n;(${promykRenderWorker.toString()})();\n`;
    this.url = URL.createObjectURL(new Blob([source], { type: 'text/javascript' }));
    this.workers = [];
    this.job = null;
    this.jobs = 0;
    this.ready = Promise.all(Array.from({ length: count }, () => new Promise((resolve, reject) => {
      const worker = new Worker(this.url);
      const slot = { worker, busy: false };
      worker.onerror = (event) => reject(new Error(event.message || 'worker failed'));
      worker.onmessage = (event) => {
        if (event.data.type === 'ready') {
          worker.onmessage = (e) => this.received(slot, e.data);
          this.workers.push(slot);
          resolve();
        }
      };
      worker.postMessage({ type: 'init', module });
    })));
  }

  // Renders `scene` (its text, as --scene reads it) at w with settings
  // {real, formula, spp}; resolves to {w, channels, image, map} (map: the
  // branch category of each pixel), or to null when a later render
  // superseded it (tracerMs: the workers' time in the tracer, summed over
  // the chunks). onProgress(rowsDone, w) after each chunk.
  // With `mapKind` ("error" or "digits-lost": the precision lab) it computes
  // that map's values instead and resolves to {w, values} (a Float64Array of
  // w·w stored values, render/maps.hpp), superseding and superseded as a render.
  async render({ scene, file, w, settings, mapKind = '' }, onProgress = () => {}) {
    const number = ++this.jobs;
    if (this.job) this.job.finish(null); // superseded
    // Once the workers are up, the chunks go out before this returns: the
    // workers compute while the page draws the rest of the edit.
    if (!this.started) {
      await this.ready;
      this.started = true;
      if (number !== this.jobs) return null;
    }
    return new Promise((resolve, reject) => {
      const rows = chunkRows(w, settings, mapKind);
      const chunks = [];
      for (let first = 0; first < w; first += rows) chunks.push([first, Math.min(rows, w - first)]);
      const job = {
        number, scene, file, w, settings, mapKind, values: mapKind ? new Float64Array(w * w) : null, chunks, done: 0, channels: 0, image: null,
        map: new Uint8Array(w * w), sceneKey: `${number}`, tracerMs: 0,
        finish: (value, error) => {
          if (this.job === job) this.job = null;
          if (error) reject(error);
          else resolve(value);
        },
        onProgress,
      };
      this.job = job;
      for (const slot of this.workers) this.feed(slot);
    });
  }

  // Drops the render under way (its promise resolves to null).
  cancel() {
    ++this.jobs;
    if (this.job) this.job.finish(null);
  }

  // Gives an idle worker the current job's next chunk.
  feed(slot) {
    const job = this.job;
    if (slot.busy || !job || !job.chunks.length) return;
    const [first, count] = job.chunks.shift();
    slot.busy = true;
    slot.worker.postMessage({
      type: 'rows', job: job.number, sceneKey: job.sceneKey, scene: job.scene, file: job.file, w: job.w,
      settings: job.settings, mapKind: job.mapKind, first, count,
    });
  }

  received(slot, message) {
    slot.busy = false;
    const job = this.job;
    if (job && message.job === job.number) {
      if (message.type === 'error') {
        job.finish(null, new Error(message.message));
      } else if (job.values) {
        job.values.set(new Float64Array(message.values.buffer), message.first * job.w);
        job.done += message.count;
        job.tracerMs += message.ms;
        job.onProgress(job.done, job.w);
        if (job.done === job.w) job.finish({ w: job.w, values: job.values, tracerMs: job.tracerMs });
      } else {
        if (!job.image) {
          job.channels = message.channels;
          job.image = new Uint8Array(job.w * job.w * message.channels);
        }
        job.image.set(message.image, message.first * job.w * job.channels);
        job.map.set(message.branch, message.first * job.w);
        job.done += message.count;
        job.tracerMs += message.ms;
        job.onProgress(job.done, job.w);
        if (job.done === job.w) job.finish({ w: job.w, channels: job.channels, image: job.image, map: job.map, tracerMs: job.tracerMs });
      }
    }
    this.feed(slot);
  }
}

// The rendered image, pixels crisp at any zoom, with the branch atlas as an
// overlay (the colours of `render --map branch`, plus a pattern per category
// so the atlas reads without colour), the traced pixels of a trace file
// marked, and the selected pixel framed. Hover tells (i, j), the grey level
// and the branch; a click or the arrow keys select.

// One pattern per category (BranchCategory order: miss, dark, lit, shadowed,
// non-finite, tangent, behind the eye), so the atlas reads without colour.
// A pattern is a tile of screen pixels repeated over the category's area
// (drawn at screen resolution, anchored to the image's corner), so it reads
// at every zoom, a pixel 1 screen pixel wide or 64; the legend shows the same
// tiles. Ink is black on light colours, white on dark ones.
export const patterns = ['none', 'dots', 'slash', 'cross', 'dash', 'bar', 'backslash'];
export const tileSize = 8;

function inked(pattern, x, y) {
  const n = tileSize;
  switch (pattern) {
    case 'dots': return (x % n < 3 && y % n < 3) || ((x + 4) % n < 3 && (y + 4) % n < 3);
    case 'slash': return (x + y) % n === n - 1;
    case 'backslash': return (x - y + n) % n === 0;
    case 'cross': return (x + y) % n === n - 1 || (x - y + n) % n === 0;
    case 'dash': return y % n === 3;
    case 'bar': return x % n === 3;
    default: return false;
  }
}

// The ink colour on a category colour "#RRGGBB": the one that contrasts.
export function inkOn(hex) {
  const v = parseInt(hex.slice(1), 16);
  const luminance = 0.2126 * (v >> 16) + 0.7152 * ((v >> 8) & 255) + 0.0722 * (v & 255);
  return luminance < 110 ? [255, 255, 255] : [0, 0, 0];
}

// A tile of the pattern, as a canvas (transparent where there is no ink).
export function patternTile(pattern, ink) {
  const tile = document.createElement('canvas');
  tile.width = tile.height = tileSize;
  const ctx = tile.getContext('2d');
  const pixels = ctx.createImageData(tileSize, tileSize);
  for (let y = 0; y < tileSize; ++y)
    for (let x = 0; x < tileSize; ++x)
      if (inked(pattern, x, y)) pixels.data.set([...ink, 255], 4 * (y * tileSize + x));
  ctx.putImageData(pixels, 0, 0);
  return tile;
}

// Fills a rectangle of `ctx` with a category's colour and its pattern.
export function drawSwatch(ctx, category, size) {
  ctx.fillStyle = category.hex;
  ctx.fillRect(0, 0, size, size);
  ctx.fillStyle = ctx.createPattern(patternTile(patterns[category.index], inkOn(category.hex)), 'repeat');
  ctx.fillRect(0, 0, size, size);
}

// The zooms offered (whole screen pixels per pixel, so pixels stay crisp).
const zoomSteps = [1, 2, 3, 4, 5, 6, 8, 10, 12, 16, 20, 24, 32, 48, 64];

export class ImageView {
  constructor(canvas, frame, data, { onSelect, onHover }) {
    this.canvas = canvas;
    this.frame = frame; // the box the image must fit in (its width is the panel's)
    this.w = data.w;
    this.channels = data.channels;
    this.image = data.image; // Uint8Array, w·w·channels
    this.map = data.branchMap; // Uint8Array, w·w
    this.onSelect = onSelect;
    this.onHover = onHover;
    // The zoom the reader chose (or the first one, about 512 screen pixels);
    // `zoom` is the one shown: the chosen one, or the largest below it that
    // fits the box now. A box that narrows for a moment (a resize, a
    // full-page screenshot) must not lose the choice.
    this.chosen = Math.floor(512 / this.w);
    this.zoom = 1;
    this.zoomTo(this.chosen);
    this.legend = [];
    this.traced = null; // Set of "i,j"
    this.atlas = false;
    this.overlay = null; // the precision lab's map: a w × w bitmap, drawn over the image and the atlas
    this.selected = null;
    this.base = this.imageBitmap();
    canvas.addEventListener('click', (event) => {
      // A click gives the image the keys (also a click made by a script).
      canvas.focus({ preventScroll: true });
      const pixel = this.pixelAt(event);
      if (pixel) this.onSelect(pixel);
    });
    canvas.addEventListener('mousemove', (event) => this.onHover(this.pixelAt(event)));
    canvas.addEventListener('mouseleave', () => this.onHover(null));
    canvas.addEventListener('keydown', (event) => {
      const moves = { ArrowUp: [-1, 0], ArrowDown: [1, 0], ArrowLeft: [0, -1], ArrowRight: [0, 1] };
      const move = moves[event.key];
      if (!move || event.altKey || event.ctrlKey || event.metaKey) return;
      event.preventDefault();
      event.stopPropagation(); // the arrows move the pixel here, not the step
      const [i, j] = this.selected || [0, 0];
      const next = [Math.min(this.w - 1, Math.max(0, i + move[0])), Math.min(this.w - 1, Math.max(0, j + move[1]))];
      this.onSelect(next);
      this.onHover(next);
    });
  }

  // A new image (the scene panel's render): {w, channels, image, map}.
  setImage({ w, channels, image, map }) {
    const sameSize = w === this.w;
    this.w = w;
    this.channels = channels;
    this.image = image;
    this.map = map;
    if (!sameSize) this.chosen = Math.floor(512 / w);
    this.zoomTo(this.chosen);
    this.base = this.imageBitmap();
    this.setLegend(this.legend);
  }

  // The image's pixels as a bitmap (one 32-bit RGBA word a pixel: fast
  // enough to redo on every edit of the scene).
  imageBitmap() {
    const bitmap = document.createElement('canvas');
    bitmap.width = bitmap.height = this.w;
    const ctx = bitmap.getContext('2d');
    const pixels = ctx.createImageData(this.w, this.w);
    const words = new Uint32Array(pixels.data.buffer);
    const image = this.image;
    const little = new Uint8Array(new Uint16Array([1]).buffer)[0] === 1;
    for (let p = 0; p < words.length; ++p) {
      const c = this.channels === 1 ? p : 3 * p;
      const r = image[c], g = image[this.channels === 1 ? c : c + 1], b = image[this.channels === 1 ? c : c + 2];
      words[p] = little ? (0xff000000 | (b << 16) | (g << 8) | r) >>> 0 : ((r << 24) | (g << 16) | (b << 8) | 0xff) >>> 0;
    }
    ctx.putImageData(pixels, 0, 0);
    return bitmap;
  }

  makeBitmap(rgbOf) {
    const bitmap = document.createElement('canvas');
    bitmap.width = bitmap.height = this.w;
    const ctx = bitmap.getContext('2d');
    const pixels = ctx.createImageData(this.w, this.w);
    for (let p = 0; p < this.w * this.w; ++p) {
      const rgb = rgbOf(p); // null: transparent
      if (rgb) pixels.data.set([rgb[0], rgb[1], rgb[2], 255], 4 * p);
    }
    ctx.putImageData(pixels, 0, 0);
    return bitmap;
  }

  // The precision lab's overlay: `rgb` (3 bytes a pixel, w × w, as
  // `render --map` draws it), or null for none.
  setOverlay(rgb) {
    this.overlay = rgb ? this.makeBitmap((p) => rgb.subarray(3 * p, 3 * p + 3)) : null;
  }

  // The atlas's layers are made when the atlas is first shown (atlasParts).
  setLegend(categories) {
    this.legend = categories;
    this.atlasBitmap = null;
    this.patternLayers = null;
    this.atlasCache = null;
  }

  atlasParts() {
    if (this.atlasBitmap) return;
    const categories = this.legend;
    const byIndex = new Map(categories.map((c) => [c.index, c.rgb]));
    this.atlasBitmap = this.makeBitmap((p) => byIndex.get(this.map[p]) || [0, 0, 0]);
    // Per category with a pattern: a mask of its pixels and its tile.
    this.patternLayers = [];
    for (const category of categories) {
      const pattern = patterns[category.index];
      if (!pattern || pattern === 'none' || !this.map.includes(category.index)) continue;
      const mask = this.makeBitmap((p) => (this.map[p] === category.index ? [0, 0, 0] : null));
      this.patternLayers.push({ mask, tile: patternTile(pattern, inkOn(category.hex)) });
    }
  }

  // The pixel under the mouse, or null.
  pixelAt(event) {
    const box = this.canvas.getBoundingClientRect();
    const j = Math.floor(((event.clientX - box.left) / box.width) * this.w);
    const i = Math.floor(((event.clientY - box.top) / box.height) * this.w);
    return i >= 0 && j >= 0 && i < this.w && j < this.w ? [i, j] : null;
  }

  grey(i, j) {
    const p = i * this.w + j;
    return this.channels === 1 ? String(this.image[p]) : [0, 1, 2].map((c) => this.image[3 * p + c]).join(', ');
  }

  category(i, j) {
    return this.map[i * this.w + j];
  }

  // The first pixel of each category in row order, and how many there are.
  // (Counted in typed arrays: a category is a byte, and a Map per pixel
  // took tens of milliseconds at w = 512 on every edit.)
  tally() {
    const counts = new Uint32Array(256);
    const firsts = new Int32Array(256).fill(-1);
    const map = this.map;
    for (let p = 0; p < map.length; ++p) {
      const c = map[p];
      if (counts[c]++ === 0) firsts[c] = p;
    }
    const first = new Map();
    const count = new Map();
    for (let c = 0; c < 256; ++c) {
      if (!counts[c]) continue;
      first.set(c, [Math.floor(firsts[c] / this.w), firsts[c] % this.w]);
      count.set(c, counts[c]);
    }
    return { first, count };
  }

  // The widest image the box holds (its panel's width less the border).
  room() {
    const panel = this.frame.parentElement;
    const style = getComputedStyle(this.frame);
    const border = parseFloat(style.borderLeftWidth) + parseFloat(style.borderRightWidth);
    return Math.max(1, Math.floor(panel.clientWidth - border));
  }

  // The zooms offered: those whose image fits the box (at least zoom 1,
  // shown scaled down when even that is too wide), none under 96 screen
  // pixels when a larger one fits.
  zoomLevels() {
    const fit = Math.max(1, Math.floor(this.room() / this.w));
    const levels = zoomSteps.filter((z) => z <= fit && this.w * z <= 8192);
    if (!levels.includes(fit) && fit <= 64) levels.push(fit);
    const large = levels.filter((z) => this.w * z >= 96);
    return large.length ? large : [levels[levels.length - 1]];
  }

  // The largest zoom offered not above `zoom` (else the smallest offered).
  zoomTo(zoom) {
    const levels = this.zoomLevels();
    const below = levels.filter((z) => z <= zoom);
    this.zoom = below.length ? below[below.length - 1] : levels[0];
  }

  zoomIn() {
    const next = this.zoomLevels().find((z) => z > this.zoom);
    if (next) this.zoom = this.chosen = next;
  }

  zoomOut() {
    const levels = this.zoomLevels().filter((z) => z < this.zoom);
    if (levels.length) this.zoom = this.chosen = levels[levels.length - 1];
  }

  canZoomIn() {
    return this.zoomLevels().some((z) => z > this.zoom);
  }

  canZoomOut() {
    return this.zoomLevels().some((z) => z < this.zoom);
  }

  // The atlas at this zoom: colours, then each category's pattern over its
  // pixels at screen resolution (made once per zoom and legend).
  atlasLayer(side) {
    if (this.atlasCache && this.atlasCache.side === side) return this.atlasCache.canvas;
    this.atlasParts();
    const layer = document.createElement('canvas');
    layer.width = layer.height = side;
    const ctx = layer.getContext('2d');
    ctx.imageSmoothingEnabled = false;
    ctx.drawImage(this.atlasBitmap, 0, 0, side, side);
    const ink = document.createElement('canvas');
    ink.width = ink.height = side;
    const inkCtx = ink.getContext('2d');
    inkCtx.imageSmoothingEnabled = false;
    for (const { mask, tile } of this.patternLayers) {
      inkCtx.globalCompositeOperation = 'copy';
      inkCtx.drawImage(mask, 0, 0, side, side);
      inkCtx.globalCompositeOperation = 'source-in';
      inkCtx.fillStyle = inkCtx.createPattern(tile, 'repeat');
      inkCtx.fillRect(0, 0, side, side);
      ctx.drawImage(ink, 0, 0);
    }
    this.atlasCache = { side, canvas: layer };
    return layer;
  }

  draw() {
    this.zoomTo(this.chosen); // the box may have narrowed or widened since
    const side = this.w * this.zoom;
    if (this.canvas.width !== side) this.canvas.width = this.canvas.height = side;
    this.canvas.style.width = `${side}px`;
    const ctx = this.canvas.getContext('2d');
    ctx.imageSmoothingEnabled = false;
    ctx.drawImage(this.base, 0, 0, side, side);
    const z = this.zoom;
    // The atlas covers the image (the colours of render --map branch, exactly).
    if (this.atlas && this.legend.length) ctx.drawImage(this.atlasLayer(side), 0, 0);
    if (this.overlay && this.overlay.width === this.w) ctx.drawImage(this.overlay, 0, 0, side, side);
    if (this.traced) {
      // A traced pixel of the trace file: a small magenta corner mark.
      ctx.fillStyle = '#CC79A7';
      const mark = Math.max(1, Math.round(z / 3));
      for (const key of this.traced) {
        const [i, j] = key.split(',').map(Number);
        ctx.fillRect(j * z, i * z, mark, mark);
      }
    }
    if (this.selected) {
      const [i, j] = this.selected;
      const line = Math.max(2, Math.round(z / 6));
      ctx.lineWidth = line;
      ctx.strokeStyle = '#000';
      ctx.strokeRect(j * z - line, i * z - line, z + 2 * line, z + 2 * line);
      ctx.strokeStyle = '#F0E442';
      ctx.lineWidth = Math.max(1, line / 2);
      ctx.strokeRect(j * z - line / 2, i * z - line / 2, z + line, z + line);
    }
  }
}

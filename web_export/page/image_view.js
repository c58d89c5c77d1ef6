// The rendered image, pixels crisp at any zoom, with the branch atlas as an
// overlay (the colours of `render --map branch`, plus a pattern per category
// so the atlas reads without colour), the traced pixels of a trace file
// marked, and the selected pixel framed. Hover tells (i, j), the grey level
// and the branch; a click or the arrow keys select.

// One pattern per category (BranchCategory order: miss, dark, lit, shadowed,
// non-finite, tangent, behind the eye), drawn in a pixel's square.
export const patterns = ['none', 'dot', 'slash', 'cross', 'dash', 'bar', 'backslash'];

export function drawPattern(ctx, pattern, x, y, size) {
  const m = size * 0.2;
  ctx.beginPath();
  switch (pattern) {
    case 'dot':
      ctx.arc(x + size / 2, y + size / 2, size * 0.15, 0, 2 * Math.PI);
      ctx.fill();
      return;
    case 'slash':
      ctx.moveTo(x + m, y + size - m);
      ctx.lineTo(x + size - m, y + m);
      break;
    case 'backslash':
      ctx.moveTo(x + m, y + m);
      ctx.lineTo(x + size - m, y + size - m);
      break;
    case 'cross':
      ctx.moveTo(x + m, y + m);
      ctx.lineTo(x + size - m, y + size - m);
      ctx.moveTo(x + m, y + size - m);
      ctx.lineTo(x + size - m, y + m);
      break;
    case 'dash':
      ctx.moveTo(x + m, y + size / 2);
      ctx.lineTo(x + size - m, y + size / 2);
      break;
    case 'bar':
      ctx.moveTo(x + size / 2, y + m);
      ctx.lineTo(x + size / 2, y + size - m);
      break;
    default:
      return;
  }
  ctx.stroke();
}

export class ImageView {
  constructor(canvas, data, { onSelect, onHover }) {
    this.canvas = canvas;
    this.w = data.w;
    this.channels = data.channels;
    this.image = data.image; // Uint8Array, w·w·channels
    this.map = data.branchMap; // Uint8Array, w·w
    this.onSelect = onSelect;
    this.onHover = onHover;
    this.zoom = Math.max(1, Math.min(64, Math.floor(512 / this.w)));
    this.legend = [];
    this.traced = null; // Set of "i,j"
    this.atlas = false;
    this.selected = null;
    this.base = this.makeBitmap((p) => {
      const c = this.channels;
      return c === 1 ? [this.image[p], this.image[p], this.image[p]] : [this.image[3 * p], this.image[3 * p + 1], this.image[3 * p + 2]];
    });
    canvas.addEventListener('click', (event) => {
      const pixel = this.pixelAt(event);
      if (pixel) this.onSelect(pixel);
    });
    canvas.addEventListener('mousemove', (event) => this.onHover(this.pixelAt(event)));
    canvas.addEventListener('mouseleave', () => this.onHover(null));
    canvas.addEventListener('keydown', (event) => {
      const moves = { ArrowUp: [-1, 0], ArrowDown: [1, 0], ArrowLeft: [0, -1], ArrowRight: [0, 1] };
      const move = moves[event.key];
      if (!move) return;
      event.preventDefault();
      const [i, j] = this.selected || [0, 0];
      const next = [Math.min(this.w - 1, Math.max(0, i + move[0])), Math.min(this.w - 1, Math.max(0, j + move[1]))];
      this.onSelect(next);
      this.onHover(next);
    });
  }

  makeBitmap(rgbOf) {
    const bitmap = document.createElement('canvas');
    bitmap.width = bitmap.height = this.w;
    const ctx = bitmap.getContext('2d');
    const pixels = ctx.createImageData(this.w, this.w);
    for (let p = 0; p < this.w * this.w; ++p) {
      const [r, g, b] = rgbOf(p);
      pixels.data.set([r, g, b, 255], 4 * p);
    }
    ctx.putImageData(pixels, 0, 0);
    return bitmap;
  }

  setLegend(categories) {
    this.legend = categories;
    const byIndex = new Map(categories.map((c) => [c.index, c.rgb]));
    this.atlasBitmap = this.makeBitmap((p) => byIndex.get(this.map[p]) || [0, 0, 0]);
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
  tally() {
    const first = new Map();
    const count = new Map();
    for (let p = 0; p < this.map.length; ++p) {
      const c = this.map[p];
      if (!first.has(c)) first.set(c, [Math.floor(p / this.w), p % this.w]);
      count.set(c, (count.get(c) || 0) + 1);
    }
    return { first, count };
  }

  setZoom(zoom) {
    this.zoom = Math.max(1, Math.min(64, zoom, Math.floor(8192 / this.w)));
  }

  draw() {
    const side = this.w * this.zoom;
    if (this.canvas.width !== side) this.canvas.width = this.canvas.height = side;
    const ctx = this.canvas.getContext('2d');
    ctx.imageSmoothingEnabled = false;
    ctx.drawImage(this.base, 0, 0, side, side);
    const z = this.zoom;
    if (this.atlas && this.atlasBitmap) {
      ctx.globalAlpha = 0.85;
      ctx.drawImage(this.atlasBitmap, 0, 0, side, side);
      ctx.globalAlpha = 1;
      if (z >= 4) {
        ctx.strokeStyle = ctx.fillStyle = 'rgba(0,0,0,0.75)';
        ctx.lineWidth = Math.max(1, z / 8);
        for (let i = 0; i < this.w; ++i)
          for (let j = 0; j < this.w; ++j) drawPattern(ctx, patterns[this.map[i * this.w + j]], j * z, i * z, z);
      }
    }
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

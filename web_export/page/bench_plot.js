// The bench plot (promyk export --bench): per scene, time (ratio to
// double/article at spp 1) against the largest error, both on log axes, one
// mark per result (real type × formula × spp). Hand-drawn SVG: a few dozen
// marks need no library, each mark is an element that takes the keyboard's
// focus and says its numbers (a canvas plot's marks cannot), and nothing
// new is bundled into the offline page.
//
// A value a log axis cannot place still gets its mark, in a strip of its
// own beyond the axis: an error of 0 (the reference itself) left of it, an
// infinite error (null) right of it, an untimed result (ratio null) under it.

const svgNS = 'http://www.w3.org/2000/svg';

function svg(tag, attributes = {}, text = '') {
  const e = document.createElementNS(svgNS, tag);
  for (const [name, value] of Object.entries(attributes)) e.setAttribute(name, String(value));
  if (text) e.textContent = text;
  return e;
}

// Okabe-Ito, and a fill pattern per formula so the plot reads without colour.
const formulaStyle = {
  article: { colour: '#E69F00', fill: 'solid' },
  stable: { colour: '#0072B2', fill: 'hollow' },
  fma: { colour: '#009E73', fill: 'half' },
  geometric: { colour: '#CC79A7', fill: 'dot' },
};
const realShapes = { float: 'circle', double: 'square', 'long-double': 'triangle', quad: 'diamond' };

function shapePath(shape, r) {
  switch (shape) {
    case 'square': return `M${-r},${-r}h${2 * r}v${2 * r}h${-2 * r}z`;
    case 'triangle': return `M0,${-1.2 * r}L${1.1 * r},${0.8 * r}L${-1.1 * r},${0.8 * r}z`;
    case 'diamond': return `M0,${-1.3 * r}L${1.3 * r},0L0,${1.3 * r}L${-1.3 * r},0z`;
    default: return `M${-r},0a${r},${r} 0 1,0 ${2 * r},0a${r},${r} 0 1,0 ${-2 * r},0z`;
  }
}

// A decade's label: 1e−16 (U+2212, as the project writes a minus).
const decade = (k) => (k === 0 ? '1' : `1e${k < 0 ? '\u2212' : ''}${Math.abs(k)}`);

// Whole decades around the finite positive values (at least one).
function decades(values) {
  const logs = values.filter((v) => typeof v === 'number' && v > 0 && Number.isFinite(v)).map(Math.log10);
  if (!logs.length) return [0, 1];
  let low = Math.floor(Math.min(...logs));
  let high = Math.ceil(Math.max(...logs));
  if (high <= low) high = low + 1;
  return [low, high];
}

// One mark's numbers in words (also its accessible name).
export function markText(row, { t, number }) {
  const error = (v) => (v === null ? t('lab_bench_infinite') : number(v));
  return t('lab_bench_mark', {
    scene: row.scene, real: row.real, formula: row.formula, spp: row.spp,
    ratio: row.ratio === null ? t('lab_bench_untimed') : number(row.ratio),
    ns: number(row.ns_per_pixel), max: error(row.max_error), median: error(row.median_error),
    differs: row.branch_differs, non_finite: row.non_finite,
  });
}

function plotScene(scene, rows, words) {
  const { t } = words;
  const width = 640, height = 400;
  const left = 70, right = 12, top = 12, bottom = 56;
  const strip = 48; // the strips beyond the axes: 0, infinite, untimed (room for a decade's number beside)
  const x0 = left + strip, x1 = width - right - strip;
  const y0 = height - bottom - strip, y1 = top;
  const [xLow, xHigh] = decades(rows.map((r) => r.max_error));
  const [yLow, yHigh] = decades(rows.map((r) => r.ratio));
  const x = (v) => (v === null ? width - right - strip / 2 : v === 0 ? left + strip / 2 : x0 + ((Math.log10(v) - xLow) / (xHigh - xLow)) * (x1 - x0));
  const y = (v) => (v === null ? height - bottom - strip / 2 : y0 - ((Math.log10(v) - yLow) / (yHigh - yLow)) * (y0 - y1));

  const plot = svg('svg', { viewBox: `0 0 ${width} ${height}`, class: 'lab-plot', role: 'group', 'aria-label': t('lab_bench_scene', { scene, count: rows.length }) });
  const defs = svg('defs');
  for (const [name, style] of Object.entries(formulaStyle)) {
    if (style.fill !== 'dot') continue;
    const pattern = svg('pattern', { id: `lab-dots-${name}`, width: 3, height: 3, patternUnits: 'userSpaceOnUse' });
    pattern.append(svg('rect', { width: 3, height: 3, fill: '#fff' }), svg('circle', { cx: 1.5, cy: 1.5, r: 1, fill: style.colour }));
    defs.append(pattern);
  }
  for (const [name, style] of Object.entries(formulaStyle)) {
    if (style.fill !== 'half') continue;
    const gradient = svg('linearGradient', { id: `lab-half-${name}` });
    gradient.append(svg('stop', { offset: '50%', 'stop-color': style.colour }), svg('stop', { offset: '50%', 'stop-color': '#fff' }));
    defs.append(gradient);
  }
  plot.append(defs);
  const axes = svg('g', { class: 'lab-axes', 'aria-hidden': 'true' });
  // The whole area, strips included, and the log axes' box inside it.
  axes.append(svg('rect', { x: left, y: y1, width: width - right - left, height: height - bottom - y1, class: 'lab-strips' }));
  axes.append(svg('rect', { x: x0, y: y1, width: x1 - x0, height: y0 - y1, class: 'lab-frame' }));
  // Every decade's grid line; its number only where the numbers do not
  // crowd (every second, fifth... decade), the ends always.
  const labelled = (low, high, room, each) => {
    const step = [1, 2, 3, 5, 10, 20, 50].find((s) => ((high - low) / s) * each <= room) || 100;
    return (k) => (k - low) % step === 0;
  };
  const xLabelled = labelled(xLow, xHigh, x1 - x0, 52);
  const yLabelled = labelled(yLow, yHigh, y0 - y1, 18);
  const below = height - bottom + 14; // the x numbers: under the untimed strip
  for (let k = xLow; k <= xHigh; ++k) {
    const at = x(10 ** k);
    axes.append(svg('line', { x1: at, x2: at, y1, y2: y0, class: 'lab-grid' }));
    // The end numbers lean inwards, clear of the strips' 0 and ∞.
    const anchor = k === xLow ? 'start' : k === xHigh ? 'end' : 'middle';
    if (xLabelled(k)) axes.append(svg('text', { x: at, y: below, 'text-anchor': anchor }, decade(k)));
  }
  for (let k = yLow; k <= yHigh; ++k) {
    const at = y(10 ** k);
    axes.append(svg('line', { x1: x0, x2: x1, y1: at, y2: at, class: 'lab-grid' }));
    if (yLabelled(k)) axes.append(svg('text', { x: left - 6, y: at + 4, 'text-anchor': 'end' }, decade(k)));
  }
  // The strips' names, where a mark in them sits.
  axes.append(svg('text', { x: left + strip / 2, y: below, 'text-anchor': 'middle' }, '0'));
  axes.append(svg('text', { x: width - right - strip / 2, y: below, 'text-anchor': 'middle' }, '∞'));
  axes.append(svg('text', { x: left - 6, y: height - bottom - strip / 2 + 4, 'text-anchor': 'end' }, '—'));
  axes.append(svg('text', { x: (x0 + x1) / 2, y: height - 24, 'text-anchor': 'middle', class: 'lab-axis-title' }, t('lab_bench_axis_x')));
  axes.append(svg('text', { x: (x0 + x1) / 2, y: height - 8, 'text-anchor': 'middle', class: 'lab-axis-note' },
    `0 = ${t('lab_bench_exact')} · ∞ = ${t('lab_bench_infinite')} · — = ${t('lab_bench_untimed')}`));
  const yTitle = svg('text', { x: 14, y: (y0 + y1) / 2, 'text-anchor': 'middle', class: 'lab-axis-title', transform: `rotate(-90 14 ${(y0 + y1) / 2})` }, t('lab_bench_axis_y'));
  axes.append(yTitle);
  plot.append(axes);

  const marks = svg('g', { class: 'lab-marks' });
  rows.forEach((row) => {
    const style = formulaStyle[row.formula] || formulaStyle.article;
    const r = 4 + 1.5 * Math.log2(Math.max(1, row.spp)) / 2;
    const fill = style.fill === 'solid' ? style.colour : style.fill === 'hollow' ? '#fff' : style.fill === 'dot' ? `url(#lab-dots-${row.formula})` : `url(#lab-half-${row.formula})`;
    const text = markText(row, words);
    const mark = svg('g', {
      class: 'lab-mark', tabindex: 0, role: 'img', 'aria-label': text, 'data-row': row.index,
      transform: `translate(${x(row.max_error).toFixed(2)},${y(row.ratio).toFixed(2)})`,
    });
    mark.append(svg('title', {}, text), svg('path', { d: shapePath(realShapes[row.real] || 'circle', r), fill, stroke: style.colour, 'stroke-width': 2 }));
    const say = () => words.readout(text);
    mark.addEventListener('mouseenter', say);
    mark.addEventListener('focus', say);
    marks.append(mark);
  });
  plot.append(marks);
  return plot;
}

// The key: a shape per real type, a colour and a fill per formula.
function key(rows, { t }) {
  const box = document.createElement('div');
  box.className = 'lab-key';
  const note = document.createElement('p');
  note.className = 'note';
  note.textContent = t('lab_bench_shapes');
  box.append(note);
  const add = (label, shape, style) => {
    const item = document.createElement('span');
    item.className = 'lab-key-item';
    const icon = svg('svg', { viewBox: '-9 -9 18 18', width: 18, height: 18, 'aria-hidden': 'true' });
    const fill = style.fill === 'solid' ? style.colour : '#fff';
    icon.append(svg('path', { d: shapePath(shape, 5), fill, stroke: style.colour, 'stroke-width': 2 }));
    item.append(icon, ` ${label}`);
    box.append(item);
  };
  for (const real of [...new Set(rows.map((r) => r.real))]) add(real, realShapes[real] || 'circle', { colour: '#333', fill: 'hollow' });
  for (const formula of [...new Set(rows.map((r) => r.formula))]) add(formula, 'square', formulaStyle[formula] || formulaStyle.article);
  return box;
}

// Every scene's plot into `container`; words: {t, number, readout}.
export function drawBenchPlots(container, bench, words) {
  container.replaceChildren();
  const rows = bench.results.map((row, index) => ({ ...row, index }));
  for (const scene of bench.scenes) {
    const own = rows.filter((r) => r.scene === scene.name);
    const figure = document.createElement('figure');
    figure.className = 'lab-figure';
    const caption = document.createElement('figcaption');
    caption.textContent = words.t('lab_bench_scene', { scene: scene.name, count: own.length });
    figure.append(caption, plotScene(scene.name, own, words), key(own, words));
    // The same numbers as a table, for reading and for a screen reader.
    const details = document.createElement('details');
    const summary = document.createElement('summary');
    summary.textContent = words.t('lab_bench_table');
    const list = document.createElement('ul');
    for (const row of own) {
      const item = document.createElement('li');
      item.textContent = markText(row, words);
      list.append(item);
    }
    details.append(summary, list);
    figure.append(details);
    container.append(figure);
  }
}
